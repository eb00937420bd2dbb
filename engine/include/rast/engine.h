// rast — one rasterizer behind one interface: the exact reference, or the fast path in one precision and
// thread count. The command line, the properties, `rast replay`, the bench and the fuzzers choose and
// run engines through it, so that each of them takes any engine the others take.
//
// An Engine is a value: copies share what an engine keeps between renders (the fast path's working
// memory), so use one from one thread at a time.
#pragma once

#include <rast/fast.h>
#include <rast/progress.h>
#include <rast/reference.h>
#include <rast/scene.h>

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rast {

struct Engine {
    std::string name;                          // "reference", "fixed8", "float32", ...
    std::string description;                   // for people: "reference (exact)", "fast fixed8, 2 threads"
    std::optional<fast::Precision> precision;  // none for the reference
    // The scene's framebuffer, drawn into `fb` (its memory reused when large enough).
    std::function<void(const Scene&, Framebuffer& fb)> draw;
    // The samples (pixel-major, sample index fastest) one triangle covers, alone.
    std::function<std::vector<std::size_t>(const Triangle&, Viewport, int samples)> covered_samples;
    // fast::edge_error_bound_at, the slack each edge function may have at a sample (zero in the fixed
    // modes); empty for the reference.
    std::function<std::array<double, 3>(const Triangle&, double x, double y)> edge_error_bound_at;

    Framebuffer render(const Scene& scene) const;
    bool is_reference() const { return !precision; }
    // Exact engines classify every sample exactly on the geometry they rasterize (reference, fixed N).
    bool exact() const;
    // Only the reference promises depths bit for bit (the exact depth rounded to nearest); the fast
    // path writes its double plane value, within a few ulps. Every engine decides the (z, id) order
    // exactly, so the id buffer is exact everywhere.
    bool exact_depth() const { return !precision; }
    // The fixed modes' grid, 2^-bits of a pixel; none for the others.
    std::optional<int> snap_bits() const;
};

// The exact reference; `stats`, when given, receives each render's exact-arithmetic counts, and
// `progress` hears how far each render has come.
Engine reference_engine(reference::Stats* stats = nullptr, Progress progress = {});
// The fast path in one precision on `threads` threads (0: all the process may use; the result is the
// same for every count). It keeps a fast::Renderer, whose working memory lasts from render to render.
Engine fast_engine(fast::Precision precision, int threads = 1);
// The reference followed by the fast path in every precision mode, one thread each.
std::vector<Engine> all_engines();

}  // namespace rast
