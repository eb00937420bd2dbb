// rast — the exact reference rasterizer. In the spirit of dEQP's rrRasterizer: one readable file, every
// decision exact, the fill rule as data. The only translation unit that includes CGAL.
#include <rast/reference.h>

#include "bounded_depth.h"
#include "exact_depth.h"
#include "line_pass.h"
#include "pixel_box.h"
#include "validate.h"

#include <rast/filters/orientation.h>

#include <CGAL/Cartesian_converter.h>
#include <CGAL/Exact_kernel_selector.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Filtered_predicate.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <optional>
#include <span>
#include <stdexcept>
#include <utility>
#include <vector>

namespace rast::reference {

Stats& Stats::operator+=(const Stats& o) {
    triangles += o.triangles;
    degenerate_triangles += o.degenerate_triangles;
    orientation_tests += o.orientation_tests;
    orientation_exact += o.orientation_exact;
    samples_covered += o.samples_covered;
    depth_tests += o.depth_tests;
    depth_exact += o.depth_exact;
    depth_nearest_exact += o.depth_nearest_exact;
    return *this;
}

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Epick::Point_2;
// Exact ring arithmetic on doubles, as Epick's own predicates use: the orientation determinant needs
// no division, so no rationals and none of their gcds (CGAL::Mpzf, a multiprecision float, where GMP is).
using ExactSelector = CGAL::Exact_kernel_selector<Epick>;
using ExactKernel = ExactSelector::Exact_kernel_rt;
using IntervalKernel = CGAL::Simple_cartesian<CGAL::Interval_nt_advanced>;

// ---------------------------------------------------------------------------------------------------
// The orientation predicate, with its exact fallbacks counted.

// The exact orientation, counting its calls. The filter below calls it only when interval arithmetic
// cannot decide the sign, so the count is exactly the number of exact fallbacks.
struct CountedExactOrientation {
    using result_type = CGAL::Orientation;
    std::uint64_t* calls;

    CGAL::Orientation operator()(const ExactKernel::Point_2& p, const ExactKernel::Point_2& q,
                                 const ExactKernel::Point_2& r) const {
        ++*calls;
        return ExactKernel::Orientation_2()(p, q, r);
    }
};

// How Epick builds its own predicates (without its static filter): the sign of the determinant in
// interval arithmetic on the input doubles, and in exact arithmetic when the interval contains zero.
using FilteredOrientation = CGAL::Filtered_predicate<
    CountedExactOrientation, IntervalKernel::Orientation_2, ExactSelector::C2E_rt,
    CGAL::Cartesian_converter<Epick, IntervalKernel, CGAL::To_interval<double>>>;

// ---------------------------------------------------------------------------------------------------
// The tie rule, as data.

// Traversing a triangle counter-clockwise (interior on the left), each edge is a left (dy < 0), right
// (dy > 0), top (dy = 0, dx < 0) or bottom (dy = 0, dx > 0) edge. A sample exactly on an edge is
// covered only on left and top edges. A sample on a vertex lies on two edges and must pass both, so
// the per-edge rule already says "both edges through it are covered edges".
enum class EdgeKind { left, right, top, bottom };
constexpr bool kCoversSamplesOnEdge[] = {/* left */ true, /* right */ false, /* top */ true,
                                         /* bottom */ false};

// Comparisons of the input doubles only: no subtraction, so nothing is rounded.
EdgeKind classify(const Point& from, const Point& to) {
    if (to.y() < from.y()) return EdgeKind::left;
    if (to.y() > from.y()) return EdgeKind::right;
    return to.x() < from.x() ? EdgeKind::top : EdgeKind::bottom;
}

struct Edge {
    Point from, to;
    EdgeKind kind;
};

// A triangle of non-zero area, its edges counter-clockwise.
struct CcwTriangle {
    std::array<Edge, 3> edges;
    double ymin, ymax;
};

// The covered pixel columns [first, last] of one sample row.
struct Run {
    int first, last;
    bool empty() const { return first > last; }
    int size() const { return last - first + 1; }
};
constexpr Run kEmptyRun{0, -1};

// The first i in [lo, hi] where `pred` holds, or hi + 1; `pred` must be false, ..., false, true, ....
// The search gallops out from `guess` (steps of 1, 2, 4, ...) and then bisects what is left, so an answer
// d columns from the guess costs O(log d) calls of pred: along a triangle an edge's end moves little
// from one row to the next. Always inlined, into each edge's search: a call cost as much as a predicate.
template <class Pred>
[[gnu::always_inline]] inline int first_true(int lo, int hi, int guess, Pred pred) {
    if (lo > hi) return lo;
    // The answer lies in [below, above]: pred is false before below, and true at above unless above = hi + 1.
    std::int64_t below = lo, above = std::int64_t{hi} + 1;
    const std::int64_t g = std::clamp(guess, lo, hi);
    if (pred(static_cast<int>(g))) {
        above = g;
        for (std::int64_t step = 1; above - step >= lo; step *= 2) {
            if (!pred(static_cast<int>(above - step))) {
                below = above - step + 1;
                break;
            }
            above -= step;
        }
    } else {
        below = g + 1;
        for (std::int64_t step = 1; below - 1 + step <= hi; step *= 2) {
            if (pred(static_cast<int>(below - 1 + step))) {
                above = below - 1 + step;
                break;
            }
            below += step;
        }
    }
    while (below < above) {
        const std::int64_t mid = below + (above - below) / 2;
        if (pred(static_cast<int>(mid)))
            above = mid;
        else
            below = mid + 1;
    }
    return static_cast<int>(below);
}

// A covered sample: where it is stored in the framebuffer, and where it is on the screen.
struct Sample {
    std::size_t index;
    double x, y;
};

// ---------------------------------------------------------------------------------------------------
// Coverage and traversal.

class Rasterizer {
public:
    explicit Rasterizer(Stats& stats)
        : stats_(stats),
          orientation_(CountedExactOrientation{&stats.orientation_exact}, IntervalKernel::Orientation_2()) {}

    // The counter-clockwise edges of t, or nothing when t has zero area (it then covers nothing).
    // Winding does not change coverage: a clockwise triangle is the same point set reversed.
    std::optional<CcwTriangle> prepare(const Triangle& t) {
        ++stats_.triangles;
        const Point a(t.v[0].x, t.v[0].y);
        Point b(t.v[1].x, t.v[1].y);
        Point c(t.v[2].x, t.v[2].y);
        switch (orientation(a, b, c)) {
            case CGAL::COLLINEAR: ++stats_.degenerate_triangles; return std::nullopt;
            case CGAL::RIGHT_TURN: std::swap(b, c); break;
            case CGAL::LEFT_TURN: break;
        }
        const auto [ymin, ymax] = std::minmax({a.y(), b.y(), c.y()});
        return CcwTriangle{{edge(a, b), edge(b, c), edge(c, a)}, ymin, ymax};
    }

    // The lecture's inside(tri, x, y): three orientation tests, ties by the edge kinds.
    bool covers(const CcwTriangle& t, const Point& p) {
        return std::ranges::all_of(t.edges, [&](const Edge& e) { return inside(e, p); });
    }

    // Calls visit(j, s, run) with the covered columns of every sample row in `box` that t covers some
    // of: sample s of pixel row j; rows ascending, then samples. Runs, not samples, so that the caller
    // does per row what does not change along it.
    //
    // Why this is exact and cheap: on a sample row (fixed y), the orientation of (from, to, (x, y)) is
    // affine in x with slope -dy: increasing on a left edge, decreasing on a right edge, constant on a
    // horizontal one. The predicates return its exact sign, so each edge's test is a monotone step along
    // the row and the covered columns are one contiguous run (the covered set is convex): the run starts
    // where the last left edge begins to pass and ends where the first right edge stops passing. A
    // search from where the edge ended on the row before finds each end in O(log w) predicate calls,
    // far fewer where edges are steep; the samples inside need no test at all. A triangle thus costs
    // O(rows * log w) predicate calls plus O(covered samples).
    template <class Visit>
    void for_each_run(const CcwTriangle& t, const detail::PixelBox& box, std::span<const SamplePoint> pattern,
                      Visit visit) {
        if (box.empty()) return;
        std::array<int, 3> ends;  // each edge's end on the row before: the next row's first guess
        ends.fill(box.i0 + (box.i1 - box.i0) / 2);
        for (int j = box.j0; j <= box.j1; ++j)
            for (int s = 0; s < static_cast<int>(pattern.size()); ++s) {
                const double y = j + pattern[s].y;  // exact: pattern offsets are multiples of 1/16
                if (y < t.ymin || y > t.ymax) continue;
                const Run run = row_run(t, pattern[s].x, y, Run{box.i0, box.i1}, ends);
                if (!run.empty()) visit(j, s, run);
            }
    }

private:
    // The shared orientation filter (filters/orientation.h) first, CGAL's interval filter and exact
    // predicate where its bound cannot decide.
    CGAL::Orientation orientation(const Point& p, const Point& q, const Point& r) {
        ++stats_.orientation_tests;
        switch (filters::orientation(p.x(), p.y(), q.x(), q.y(), r.x(), r.y()).certain_sign()) {
            case 1: return CGAL::LEFT_TURN;
            case -1: return CGAL::RIGHT_TURN;
            default: return orientation_(p, q, r);
        }
    }

    static Edge edge(const Point& from, const Point& to) { return {from, to, classify(from, to)}; }

    // Whether p is on the covered side of e: strictly left of it, or on it when e is a covered edge.
    bool inside(const Edge& e, const Point& p) {
        const CGAL::Orientation o = orientation(e.from, e.to, p);
        return o == CGAL::LEFT_TURN ||
               (o == CGAL::COLLINEAR && kCoversSamplesOnEdge[static_cast<int>(e.kind)]);
    }

    // The covered columns of the sample row at height y with horizontal offset sx, within `run`; the
    // search for edge k's end starts at ends[k] and leaves the end found there.
    Run row_run(const CcwTriangle& t, double sx, double y, Run run, std::array<int, 3>& ends) {
        for (int k = 0; k < 3; ++k) {
            const Edge& e = t.edges[k];
            if (run.empty()) break;
            const auto passes = [&](int i) { return inside(e, Point(i + sx, y)); };
            switch (e.kind) {
                case EdgeKind::left: run.first = ends[k] = first_true(run.first, run.last, ends[k], passes); break;
                case EdgeKind::right:
                    ends[k] = first_true(run.first, run.last, ends[k], [&](int i) { return !passes(i); });
                    run.last = ends[k] - 1;
                    break;
                case EdgeKind::top:
                case EdgeKind::bottom:
                    if (!passes(run.first)) run = kEmptyRun;
                    break;
            }
        }
        return run;
    }

    Stats& stats_;
    FilteredOrientation orientation_;
};

// ---------------------------------------------------------------------------------------------------
// Depth: the bounded double-double planes of bounded_depth.h first, exact integer fractions
// (exact_depth.h) where their bounds cannot decide.

// The exact depth planes of a scene's triangles, built when first needed.
class ExactDepths {
public:
    explicit ExactDepths(const std::vector<Triangle>& triangles)
        : triangles_(triangles), planes_(triangles.size()) {}

    const detail::ExactDepth& operator[](std::int32_t id) {
        auto& plane = planes_[static_cast<std::size_t>(id)];
        if (!plane) plane.emplace(triangles_[static_cast<std::size_t>(id)]);
        return *plane;
    }

private:
    const std::vector<Triangle>& triangles_;
    std::vector<std::optional<detail::ExactDepth>> planes_;
};

// The z-buffer with the (z, id) order. It stores each fragment's exact depth rounded to nearest, and
// rounding to nearest is monotone: a rounded depth strictly above the stored one means an exact depth
// strictly above it. Only equal rounded depths need a closer look. A sample holds no triangle exactly
// when its depth is +infinity: a stored depth is that of a point of a triangle, between its vertices'
// depths, so finite. Depths alone then decide every comparison but a tie, and ids are read only there.
class ZBuffer {
    static constexpr double kEmpty = std::numeric_limits<double>::infinity();

public:
    ZBuffer(const Scene& scene, Framebuffer& fb, Stats& stats)
        : triangles_(scene.triangles), fb_(fb), stats_(stats), exact_(scene.triangles) {}

    // Offers the fragment of triangle `id` at sample q; z encloses its depth (none: no bounded plane).
    void offer(std::int32_t id, const Sample& q, const std::optional<detail::Bounded>& z) {
        const double depth = nearest(id, q, z);
        double& stored_depth = fb_.depth[q.index];
        std::int32_t& stored_id = fb_.ids[q.index];
        if (stored_depth != kEmpty) {
            // The (z, id) order: nearer, or as near and earlier.
            ++stats_.depth_tests;
            if (depth > stored_depth) return;
            if (depth == stored_depth) {
                const int order = compare(id, stored_id, q, z);
                if (order > 0 || (order == 0 && stored_id < id)) return;
            }
        }
        stored_id = id;
        stored_depth = depth;
    }

    // Whether a fragment at q whose exact depth is at least `lower` loses to the stored one, for
    // certain: rounding to nearest is monotone, so its rounded depth is at least lower, a double. Most
    // fragments behind others are turned away here, before their depth is enclosed. An empty sample's
    // +infinity exceeds every lower bound.
    bool certainly_behind(std::size_t index, double lower) const { return lower > fb_.depth[index]; }

private:
    double nearest(std::int32_t id, const Sample& q, const std::optional<detail::Bounded>& z) {
        if (z)
            if (const auto rounded = detail::nearest(*z)) return *rounded;
        ++stats_.depth_nearest_exact;
        return exact_[id].nearest(q.x, q.y);
    }

    // The sign of the depth of `id` minus that of `stored` at q.
    int compare(std::int32_t id, std::int32_t stored, const Sample& q, const std::optional<detail::Bounded>& z) {
        if (z)
            if (const auto other = detail::BoundedPlane::make(triangles_[static_cast<std::size_t>(stored)]))
                if (const int sign = detail::certain_sign_of_difference(*z, other->at(other->row(q.y), q.x)))
                    return sign;
        ++stats_.depth_exact;
        return exact_[id].compare(exact_[stored], q.x, q.y);
    }

    const std::vector<Triangle>& triangles_;
    Framebuffer& fb_;
    Stats& stats_;
    ExactDepths exact_;
};

// offer_run's two builds, on x86-64; other processors get one generic build.
#if defined(__x86_64__)
#define RAST_FMA_CLONES [[gnu::target_clones("default", "fma")]]
#else
#define RAST_FMA_CLONES
#endif

// Offers `count` samples of a run to the z-buffer, q and those after it along the row (x + 1 and
// index + step each), with their depths on `plane`; returns how many it turned away as certainly behind
// (each a depth comparison). Most fragments of a deep scene are, after a lower bound on their depth and
// one load. Compiled twice and chosen when the library loads: for any x86-64, where std::fma is a call
// into libm, and for processors with FMA, where it is one instruction. Both compute the same exactly
// rounded results (-ffp-contract=off keeps the compiler from fusing anything else), but the
// double-double depths are made of FMAs.
RAST_FMA_CLONES std::uint64_t offer_run(ZBuffer& zbuffer, std::int32_t id, const detail::BoundedPlane& plane,
                                        Sample q, int count, std::size_t step) {
    const detail::Bounded row = plane.row(q.y);
    const auto lower = plane.lower(row);
    std::uint64_t behind = 0;
    for (int k = 0; k < count; ++k, q.index += step, q.x += 1) {
        if (zbuffer.certainly_behind(q.index, lower(q.x))) {
            ++behind;
            continue;
        }
        zbuffer.offer(id, q, plane.at(row, q.x));
    }
    return behind;
}

// The order in which render visits the triangles: tile by tile (tiles of 64 x 64 pixels in rows, a
// triangle in the tile of its bounding box's first pixel), ids ascending within a tile. In id order, rast
// bench's 100 000 small triangles land all over a 12 MB framebuffer and the reference waited mostly for
// stored depths; tile by tile, the rows a triangle touches were mostly touched just before, and they
// take about two thirds of the time (micro bench, 380 -> 250 ms). The z-buffer's (z, id) order is total,
// so the framebuffer does not depend on the order of visits; only the counts of depth comparisons and
// exact roundings do. A counting sort: there are fewer tiles than the framebuffer has samples.
std::vector<std::size_t> tile_order(std::span<const detail::PixelBox> boxes, Viewport vp) {
    constexpr std::size_t kTile = 64;
    const std::size_t tiles_x = (static_cast<std::size_t>(vp.width) + kTile - 1) / kTile;
    const std::size_t tiles = tiles_x * ((static_cast<std::size_t>(vp.height) + kTile - 1) / kTile);
    const auto tile_of = [tiles_x](const detail::PixelBox& b) {
        if (b.empty()) return std::size_t{0};
        return static_cast<std::size_t>(b.j0) / kTile * tiles_x + static_cast<std::size_t>(b.i0) / kTile;
    };
    // next[t + 1] counts tile t's triangles; summed, next[t] is where tile t's next one goes.
    std::vector<std::size_t> next(tiles + 1, 0);
    for (const detail::PixelBox& b : boxes) ++next[tile_of(b) + 1];
    std::partial_sum(next.begin(), next.end(), next.begin());
    std::vector<std::size_t> order(boxes.size());
    for (std::size_t k = 0; k < boxes.size(); ++k) order[next[tile_of(boxes[k])]++] = k;
    return order;
}

// A framebuffer without storage: only its index layout.
Framebuffer layout(Viewport vp, int samples) {
    Framebuffer fb;
    fb.viewport = vp;
    fb.samples = samples;
    return fb;
}

}  // namespace

bool covers(const Triangle& t, double x, double y) {
    detail::require_finite(t);
    if (!std::isfinite(x) || !std::isfinite(y)) throw std::invalid_argument("covers: sample is not finite");
    Stats stats;
    Rasterizer rasterizer(stats);
    const auto ccw = rasterizer.prepare(t);
    return ccw && rasterizer.covers(*ccw, Point(x, y));
}

std::vector<std::size_t> covered_samples(const Triangle& t, Viewport vp, int samples) {
    detail::require_valid(vp, samples);
    detail::require_finite(t);
    const auto pattern = sample_pattern(samples);
    Stats stats;
    Rasterizer rasterizer(stats);
    std::vector<std::size_t> indices;
    const auto ccw = rasterizer.prepare(t);
    if (!ccw) return indices;
    const Framebuffer fb = layout(vp, samples);
    rasterizer.for_each_run(*ccw, detail::pixel_box(t, vp), pattern, [&](int j, int s, Run run) {
        for (int i = run.first; i <= run.last; ++i) indices.push_back(fb.index(i, j, s));
    });
    std::ranges::sort(indices);  // the runs of a pixel row's samples interleave in the framebuffer
    return indices;
}

Rational depth_at(const Triangle& t, double x, double y) {
    detail::require_finite(t);
    if (!std::isfinite(x) || !std::isfinite(y)) throw std::invalid_argument("depth_at: point is not finite");
    Stats stats;
    if (!Rasterizer(stats).prepare(t))
        throw std::invalid_argument("depth_at: the triangle has zero area, so no depth plane");
    return detail::ExactDepth(t).at(x, y);
}

Framebuffer render(const Scene& scene, Stats* stats_out, const Progress& progress) {
    detail::require_valid(scene.viewport, scene.samples);
    const auto pattern = sample_pattern(scene.samples);
    const std::vector<std::int32_t> ids = triangle_ids(scene);
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) detail::require_finite(scene.triangles[k], k);
    for (std::size_t k = 0; k < scene.lines.size(); ++k) detail::require_finite(scene.lines[k].segment, k);

    Stats stats;
    Rasterizer rasterizer(stats);
    Framebuffer fb(scene.viewport, scene.samples);
    ZBuffer zbuffer(scene, fb, stats);

    std::vector<detail::PixelBox> boxes;
    boxes.reserve(scene.triangles.size());
    for (const Triangle& t : scene.triangles) boxes.push_back(detail::pixel_box(t, scene.viewport));
    const std::vector<std::size_t> order = tile_order(boxes, scene.viewport);
    report_progress(progress, 0, order.size());
    for (std::size_t n = 0; n < order.size(); ++n) {
        const std::size_t k = order[n];
        const Triangle& t = scene.triangles[k];
        if (const auto ccw = rasterizer.prepare(t)) {
            const auto id = static_cast<std::int32_t>(k);
            std::optional<detail::BoundedPlane> plane;  // made at the first covered run: many tiny triangles have none
            bool plane_made = false;
            rasterizer.for_each_run(*ccw, boxes[k], pattern, [&](int j, int s, Run run) {
                stats.samples_covered += static_cast<std::uint64_t>(run.size());
                if (!plane_made) {
                    plane = detail::BoundedPlane::make(t);
                    plane_made = true;
                }
                // The run's samples, column by column: x = i + sx steps by 1 exactly (multiples of 1/16
                // below 2^31), the framebuffer index by the pattern's size.
                const double y = j + pattern[s].y;
                Sample q{fb.index(run.first, j, s), run.first + pattern[s].x, y};
                const std::size_t step = pattern.size();
                if (!plane) {
                    for (int i = run.first; i <= run.last; ++i, q.index += step, q.x += 1)
                        zbuffer.offer(id, q, std::nullopt);
                    return;
                }
                stats.depth_tests += offer_run(zbuffer, id, *plane, q, run.size(), step);
            });
        }
        report_progress(progress, n + 1, order.size());
    }
    if (!scene.lines.empty()) detail::draw_lines(scene, ids, fb);

    if (stats_out) *stats_out = stats;
    return fb;
}

}  // namespace rast::reference
