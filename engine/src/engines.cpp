#include <rast/engine.h>

#include <algorithm>
#include <memory>

namespace rast {

Framebuffer Engine::render(const Scene& scene) const {
    Framebuffer fb;
    draw(scene, fb);
    return fb;
}

namespace {

// Every sample count, the tie rule and the (z, id) order; snapping to nearest, ties to even, if at all.
Contract exact_contract(std::string name, std::optional<int> snap) {
    Contract c;
    c.name = std::move(name);
    c.snap = snap;
    return c;
}

}  // namespace

Engine reference_engine(reference::Stats* stats, Progress progress) {
    return {Engine::Kind::reference, "reference", "reference (exact)", std::nullopt,
            exact_contract("reference", std::nullopt),
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

std::optional<Contract> fast_contract(fast::Precision p) {
    const std::optional<int> bits = p == fast::Precision::fixed4    ? std::optional(4)
                                    : p == fast::Precision::fixed8  ? std::optional(8)
                                    : p == fast::Precision::fixed16 ? std::optional(16)
                                                                    : std::nullopt;
    if (!bits) return std::nullopt;
    return exact_contract(std::string(fast::name(p)), bits);
}

Engine fast_engine(fast::Precision p, int threads) {
    auto renderer = std::make_shared<fast::Renderer>();
    const fast::Options options{p, threads};
    return {Engine::Kind::fast, std::string(fast::name(p)), describe_fast(p, threads), p, fast_contract(p),
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
