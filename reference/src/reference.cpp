// rast — the exact reference rasterizer. In the spirit of dEQP's rrRasterizer: one readable file, every
// decision exact, the fill rule as data. The only translation unit that includes CGAL.
#include <rast/reference.h>

#include "depth_plane.h"
#include "exact_depth.h"
#include "pixel_box.h"
#include "validate.h"

#include <CGAL/Cartesian_converter.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Exact_rational.h>
#include <CGAL/Filtered_predicate.h>
#include <CGAL/Interval_nt.h>
#include <CGAL/Simple_cartesian.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
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
    return *this;
}

namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using Point = Epick::Point_2;
using ExactKernel = CGAL::Simple_cartesian<CGAL::Exact_rational>;
using Interval = CGAL::Interval_nt_advanced;  // needs the rounding mode set upward by its user
using IntervalKernel = CGAL::Simple_cartesian<Interval>;

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
// interval arithmetic on the input doubles, and in exact rationals when the interval contains zero.
using FilteredOrientation = CGAL::Filtered_predicate<
    CountedExactOrientation, IntervalKernel::Orientation_2, CGAL::Cartesian_converter<Epick, ExactKernel>,
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
    bool contains(int i) const { return first <= i && i <= last; }
};
constexpr Run kEmptyRun{0, -1};

// The first i in [lo, hi] where `pred` holds, or hi + 1; `pred` must be false, ..., false, true, ...
template <class Pred>
int first_true(int lo, int hi, Pred pred) {
    while (lo <= hi) {
        const int mid = lo + (hi - lo) / 2;
        if (pred(mid))
            hi = mid - 1;
        else
            lo = mid + 1;
    }
    return lo;
}

struct Sample {
    int i, j, s;
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

    // Calls visit(Sample) for every sample in `box` that t covers, in ascending framebuffer order
    // (row j, then column i, then sample s).
    //
    // Why this is exact and cheap: on a sample row (fixed y), the orientation of (from, to, (x, y)) is
    // affine in x with slope -dy: increasing on a left edge, decreasing on a right edge, constant on a
    // horizontal one. The predicates return its exact sign, so each edge's test is a monotone step along
    // the row and the covered columns are one contiguous run (the covered set is convex): the run starts
    // where the last left edge begins to pass and ends where the first right edge stops passing. A
    // binary search finds each end in O(log w) predicate calls; the samples inside need no test at all.
    // A triangle thus costs O(rows * log w) predicate calls plus O(covered samples).
    template <class Visit>
    void for_each_covered(const CcwTriangle& t, const detail::PixelBox& box,
                          std::span<const SamplePoint> pattern, Visit visit) {
        if (box.empty()) return;
        std::array<Run, 16> runs{};  // one per sample of the largest pattern
        const int n = static_cast<int>(pattern.size());
        for (int j = box.j0; j <= box.j1; ++j) {
            int first = box.i1 + 1, last = box.i0 - 1;
            for (int s = 0; s < n; ++s) {
                const double y = j + pattern[s].y;  // exact: pattern offsets are multiples of 1/16
                runs[s] = (y < t.ymin || y > t.ymax) ? kEmptyRun
                                                     : row_run(t, pattern[s].x, y, Run{box.i0, box.i1});
                if (runs[s].empty()) continue;
                first = std::min(first, runs[s].first);
                last = std::max(last, runs[s].last);
            }
            for (int i = first; i <= last; ++i)
                for (int s = 0; s < n; ++s)
                    if (runs[s].contains(i)) visit(Sample{i, j, s, i + pattern[s].x, j + pattern[s].y});
        }
    }

private:
    CGAL::Orientation orientation(const Point& p, const Point& q, const Point& r) {
        ++stats_.orientation_tests;
        return orientation_(p, q, r);
    }

    static Edge edge(const Point& from, const Point& to) { return {from, to, classify(from, to)}; }

    // Whether p is on the covered side of e: strictly left of it, or on it when e is a covered edge.
    bool inside(const Edge& e, const Point& p) {
        const CGAL::Orientation o = orientation(e.from, e.to, p);
        return o == CGAL::LEFT_TURN ||
               (o == CGAL::COLLINEAR && kCoversSamplesOnEdge[static_cast<int>(e.kind)]);
    }

    // The covered columns of the sample row at height y with horizontal offset sx, within `run`.
    Run row_run(const CcwTriangle& t, double sx, double y, Run run) {
        for (const Edge& e : t.edges) {
            if (run.empty()) break;
            const auto passes = [&](int i) { return inside(e, Point(i + sx, y)); };
            switch (e.kind) {
                case EdgeKind::left: run.first = first_true(run.first, run.last, passes); break;
                case EdgeKind::right:
                    run.last = first_true(run.first, run.last, [&](int i) { return !passes(i); }) - 1;
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
// Depth: an interval filter first, exact integer fractions (exact_depth.h) when it cannot decide.

// Interval_nt_advanced computes enclosures only while the rounding mode is upward; these two functions
// are the only places it is used, and each sets and restores the mode.
detail::DepthPlane<Interval> interval_plane(const Triangle& t) {
    CGAL::Protect_FPU_rounding<true> upward;
    return detail::depth_plane<Interval>(t);
}

Interval interval_depth(const detail::DepthPlane<Interval>& plane, double x, double y) {
    CGAL::Protect_FPU_rounding<true> upward;
    return plane.at(Interval(x), Interval(y));
}

// Whether every value of a is below every value of b. Non-finite bounds (overflow, or a zero-area
// enclosure of the denominator) decide nothing.
bool certainly_below(const Interval& a, const Interval& b) {
    return std::isfinite(a.sup()) && std::isfinite(b.inf()) && std::isfinite(a.inf()) &&
           std::isfinite(b.sup()) && a.sup() < b.inf();
}

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
    detail::require_valid(vp);
    detail::require_finite(t);
    const auto pattern = sample_pattern(samples);
    Stats stats;
    Rasterizer rasterizer(stats);
    std::vector<std::size_t> indices;
    const auto ccw = rasterizer.prepare(t);
    if (!ccw) return indices;
    const Framebuffer fb = layout(vp, samples);
    rasterizer.for_each_covered(*ccw, detail::pixel_box(t, vp), pattern,
                                [&](const Sample& q) { indices.push_back(fb.index(q.i, q.j, q.s)); });
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

Framebuffer render(const Scene& scene, Stats* stats_out) {
    detail::require_valid(scene.viewport);
    const auto pattern = sample_pattern(scene.samples);
    if (scene.triangles.size() > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw std::invalid_argument("render: too many triangles for 32-bit ids");
    for (std::size_t id = 0; id < scene.triangles.size(); ++id) detail::require_finite(scene.triangles[id], id);

    Stats stats;
    Rasterizer rasterizer(stats);
    ExactDepths exact(scene.triangles);
    Framebuffer fb(scene.viewport, scene.samples);
    std::vector<Interval> stored_depth(fb.ids.size());  // encloses the exact depth of the stored fragment

    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        const Triangle& t = scene.triangles[k];
        const auto id = static_cast<std::int32_t>(k);
        const auto ccw = rasterizer.prepare(t);
        if (!ccw) continue;
        const auto plane = interval_plane(t);
        rasterizer.for_each_covered(*ccw, detail::pixel_box(t, scene.viewport), pattern, [&](const Sample& q) {
            ++stats.samples_covered;
            const std::size_t index = fb.index(q.i, q.j, q.s);
            const Interval z = interval_depth(plane, q.x, q.y);
            const std::int32_t stored = fb.ids[index];
            if (stored != Framebuffer::kNoTriangle) {
                // The (z, id) order: nearer, or as near and earlier.
                ++stats.depth_tests;
                if (certainly_below(stored_depth[index], z)) return;
                if (!certainly_below(z, stored_depth[index])) {
                    ++stats.depth_exact;
                    const int order = exact[id].compare(exact[stored], q.x, q.y);
                    if (order > 0 || (order == 0 && stored < id)) return;
                }
            }
            fb.ids[index] = id;
            stored_depth[index] = z;
        });
    }

    // The stored depths: each winner's exact depth, rounded to nearest.
    for (int j = 0; j < scene.viewport.height; ++j)
        for (int i = 0; i < scene.viewport.width; ++i)
            for (int s = 0; s < scene.samples; ++s) {
                const std::size_t index = fb.index(i, j, s);
                if (fb.ids[index] == Framebuffer::kNoTriangle) continue;
                const SamplePoint& p = pattern[static_cast<std::size_t>(s)];
                fb.depth[index] = exact[fb.ids[index]].nearest(i + p.x, j + p.y);
            }

    if (stats_out) *stats_out = stats;
    return fb;
}

}  // namespace rast::reference
