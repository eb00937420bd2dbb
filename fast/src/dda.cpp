// rast — lines by the digital differential analyzer (rast/fast.h): bresenham.cpp's walk, in floating
// point. The ends are the input doubles rounded to the mode's type; the candidate across each column
// (or row) is found by adding the slope once a step, so rounding accumulates along the segment, and the
// ends' diamonds are decided in the same type. Where that lands on the other side of a pixel boundary
// than the exact line, a pixel differs from the reference: rast bench counts how often.
#include <rast/fast.h>

#include "line_diamond.h"

#include <rast/scene_limits.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <string>

namespace rast::fast {

namespace {

template <class T>
struct Point {
    T along, across;
};

// Whether the diamond of pixel (k along, m across) holds p, decided in T.
template <class T>
bool holds(Point<T> p, double k, double m, bool y_major) {
    return detail::diamond_holds<T>(p.along - static_cast<T>(k + 0.5), p.across - static_cast<T>(m + 0.5), T(0.5),
                                    y_major);
}

template <class T>
bool holder(Point<T> p, bool y_major, double& k, double& m) {
    k = std::floor(static_cast<double>(p.along));
    m = std::floor(static_cast<double>(p.across));
    if (holds(p, k, m, y_major)) return true;
    if (y_major && static_cast<double>(p.across) == m && holds(p, k, m - 1, y_major)) {
        m -= 1;
        return true;
    }
    return false;
}

template <class T>
std::vector<std::size_t> walk(const Segment& s, Viewport vp) {
    const T x0 = static_cast<T>(s.v[0].x), y0 = static_cast<T>(s.v[0].y);
    const T x1 = static_cast<T>(s.v[1].x), y1 = static_cast<T>(s.v[1].y);
    std::vector<std::size_t> lit;
    if (x0 == x1 && y0 == y1) return lit;
    const bool y_major = std::abs(y1 - y0) > std::abs(x1 - x0);
    const Point<T> start = y_major ? Point<T>{y0, x0} : Point<T>{x0, y0};
    const Point<T> end = y_major ? Point<T>{y1, x1} : Point<T>{x1, y1};
    const double n_along = y_major ? vp.height : vp.width, n_across = y_major ? vp.width : vp.height;
    const auto keep = [&](double k, double m) {
        if (!(k >= 0 && k < n_along && m >= 0 && m < n_across)) return;
        const auto i = static_cast<std::size_t>(y_major ? m : k), j = static_cast<std::size_t>(y_major ? k : m);
        lit.push_back(j * static_cast<std::size_t>(vp.width) + i);
    };
    double end_k = 0, end_m = 0, start_k = 0, start_m = 0;
    const bool ends_inside = holder(end, y_major, end_k, end_m);
    const bool starts_inside = holder(start, y_major, start_k, start_m);

    const Point<T>& lo = start.along <= end.along ? start : end;
    const Point<T>& hi = start.along <= end.along ? end : start;
    const double first = std::max(std::ceil(static_cast<double>(lo.along) - 0.5), 0.0);
    const double last = std::min(std::floor(static_cast<double>(hi.along) - 0.5), n_along - 1);
    if (first <= last) {
        const T slope = (hi.across - lo.across) / (hi.along - lo.along);
        T across = lo.across + (static_cast<T>(first + 0.5) - lo.along) * slope;
        for (double k = first; k <= last; k += 1) {
            const double m = y_major ? std::ceil(static_cast<double>(across)) - 1 : std::floor(static_cast<double>(across));
            if (!(ends_inside && k == end_k && m == end_m)) keep(k, m);
            across += slope;  // the DDA's step: the rounding of each addition stays
        }
    }
    if (starts_inside && !(ends_inside && start_k == end_k && start_m == end_m)) keep(start_k, start_m);
    std::sort(lit.begin(), lit.end());
    lit.erase(std::unique(lit.begin(), lit.end()), lit.end());
    return lit;
}

}  // namespace

std::vector<std::size_t> dda(const Segment& s, Viewport vp, Precision precision) {
    check_framebuffer(vp, 1, "rast::fast::dda");
    for (const Vertex& v : s.v)
        if (!std::isfinite(v.x) || !std::isfinite(v.y))
            throw std::invalid_argument("rast::fast::dda: an end has a coordinate that is not finite");
    if (precision == Precision::float32) return walk<float>(s, vp);
    if (precision == Precision::float64) return walk<double>(s, vp);
    throw std::invalid_argument("rast::fast::dda: precision " + std::string(name(precision)) +
                                " is not a float mode (bresenham is the fixed-point line)");
}

}  // namespace rast::fast
