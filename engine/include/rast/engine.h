// rast — one rasterizer behind one interface: the exact reference, or the fast path in one precision and
// thread count. The command line, the properties, `rast replay`, the bench and the fuzzers choose and
// run engines through it, so that each of them takes any engine the others take.
//
// An Engine is a value: copies share what an engine keeps between renders (the fast path's working
// memory), so use one from one thread at a time.
#pragma once

#include <rast/contract.h>
#include <rast/fast.h>
#include <rast/progress.h>
#include <rast/reference.h>
#include <rast/scene.h>

#include <array>
#include <cstddef>
#include <functional>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace rast {

// An engine that could not do its job: a plugin that failed to load, crashed, hung, returned an error or
// wrote ids out of range. Commands end on it with exit status 2; properties pass it on rather than call
// it a failed property, for the engine gave no answer to judge.
struct EngineError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

struct Engine {
    enum class Kind { reference, fast, plugin };

    Kind kind = Kind::reference;
    std::string name;                          // "reference", "fixed8", "float32", a plugin's contract name
    std::string description;                   // for people: "reference (exact)", "fast fixed8, 2 threads"
    std::optional<fast::Precision> precision;  // the fast path's; none for the others
    // What the engine promises (rast/contract.h); none for the float modes, which promise coverage only
    // within their error bound of an edge (edge_error_bound_at).
    std::optional<Contract> contract;
    // The scene's framebuffer, drawn into `fb` (its memory reused when large enough).
    std::function<void(const Scene&, Framebuffer& fb)> draw;
    // The samples (pixel-major, sample index fastest) one triangle covers, alone.
    std::function<std::vector<std::size_t>(const Triangle&, Viewport, int samples)> covered_samples;
    // fast::edge_error_bound_at, the slack each edge function may have at a sample (zero in the fixed
    // modes); empty for the others.
    std::function<std::array<double, 3>(const Triangle&, double x, double y)> edge_error_bound_at;

    Framebuffer render(const Scene& scene) const;
    bool is_reference() const { return kind == Kind::reference; }
    // Exact engines classify every sample exactly on the geometry they rasterize, by the tie rule: the
    // reference, the fixed modes, and a plugin whose contract says ties=top-left with one snapping.
    bool exact() const { return contract && contract->top_left && contract->deterministic(); }
    // Only the reference promises depths bit for bit (the exact depth rounded to nearest); the fast
    // path writes its double plane value, within a few ulps; a plugin returns ids alone, and its
    // depths read NaN.
    bool exact_depth() const { return is_reference(); }
    bool writes_depth() const { return kind != Kind::plugin; }
    // The grid an engine snaps x and y to, 2^-bits of a pixel; none for the others.
    std::optional<int> snap_bits() const { return contract ? contract->snap : std::nullopt; }
};

// The exact reference; `stats`, when given, receives each render's exact-arithmetic counts, and
// `progress` hears how far each render has come.
Engine reference_engine(reference::Stats* stats = nullptr, Progress progress = {});
// The fast path in one precision on `threads` threads (0: all the process may use; the result is the
// same for every count). It keeps a fast::Renderer, whose working memory lasts from render to render.
Engine fast_engine(fast::Precision precision, int threads = 1);
// What the fast path promises in a precision: the fixed modes snap to nearest, ties to even, and keep
// the tie rule and the (z, id) order exactly; none for the float modes.
std::optional<Contract> fast_contract(fast::Precision precision);
// The reference followed by the fast path in every precision mode, one thread each.
std::vector<Engine> all_engines();

}  // namespace rast
