// The resolved image against the exact visible area; see aa_error.h.
#include <rast/aa_error.h>

#include <rast/reference.h>

#include <algorithm>
#include <span>

namespace rast::bench {

std::vector<VisibleError> visible_errors(const Scene& scene, const reference::VisibleArea& visible,
                                         std::span<const int> sample_counts) {
    std::vector<VisibleError> result;
    const Viewport vp = scene.viewport;
    for (const int n : sample_counts) {
        Scene at_n = scene;
        at_n.samples = n;
        const Framebuffer fb = reference::render(at_n);
        VisibleError e{n, 0, 0, 0};
        double sum = 0;
        for (int j = 0; j < vp.height; ++j)
            for (int i = 0; i < vp.width; ++i) {
                const auto ids = std::span(fb.ids).subspan(fb.index(i, j, 0), static_cast<std::size_t>(n));
                const auto seen = visible.at(i, j);
                if (seen.empty() && std::all_of(ids.begin(), ids.end(), [](auto id) { return id < 0; })) continue;
                const double error = reference::resolve_error(seen, ids).convert_to<double>();
                ++e.pixels;
                sum += error;
                e.worst = std::max(e.worst, error);
            }
        e.mean = e.pixels == 0 ? 0 : sum / static_cast<double>(e.pixels);
        result.push_back(e);
    }
    return result;
}

}  // namespace rast::bench
