#include <rast/engine.h>

#include <algorithm>
#include <memory>

namespace rast {

Framebuffer Engine::render(const Scene& scene) const {
    Framebuffer fb;
    draw(scene, fb);
    return fb;
}

bool Engine::exact() const { return !precision || snap_bits().has_value(); }

std::optional<int> Engine::snap_bits() const {
    if (!precision) return std::nullopt;
    switch (*precision) {
        case fast::Precision::fixed4: return 4;
        case fast::Precision::fixed8: return 8;
        case fast::Precision::fixed16: return 16;
        case fast::Precision::float32:
        case fast::Precision::float64: return std::nullopt;
    }
    return std::nullopt;
}

Engine reference_engine(reference::Stats* stats, Progress progress) {
    return {"reference", "reference (exact)", std::nullopt,
            [stats, progress](const Scene& s, Framebuffer& fb) { fb = reference::render(s, stats, progress); },
            [](const Triangle& t, Viewport vp, int n) { return reference::covered_samples(t, vp, n); },
            nullptr};
}

namespace {

// What runs: a count above the machine's is not what the user would see in the time taken.
std::string describe_fast(fast::Precision p, int threads) {
    const int limit = fast::max_threads(), runs = threads == 0 ? limit : std::min(threads, limit);
    std::string text = "fast " + std::string(fast::name(p)) + ", " + std::to_string(runs) +
                       (runs == 1 ? " thread" : " threads");
    if (threads == 0) text += " (all)";
    else if (threads > limit) text += " (" + std::to_string(threads) + " asked; the most this machine runs)";
    return text;
}

}  // namespace

Engine fast_engine(fast::Precision p, int threads) {
    auto renderer = std::make_shared<fast::Renderer>();
    const fast::Options options{p, threads};
    return {std::string(fast::name(p)), describe_fast(p, threads), p,
            [renderer, options](const Scene& s, Framebuffer& fb) { renderer->render(s, fb, options); },
            [p](const Triangle& t, Viewport vp, int n) { return fast::covered_samples(t, vp, n, p); },
            [p](const Triangle& t, double x, double y) { return fast::edge_error_bound_at(t, p, x, y); }};
}

std::vector<Engine> all_engines() {
    std::vector<Engine> engines{reference_engine()};
    for (auto p : {fast::Precision::fixed4, fast::Precision::fixed8, fast::Precision::fixed16,
                   fast::Precision::float32, fast::Precision::float64})
        engines.push_back(fast_engine(p));
    return engines;
}

}  // namespace rast
