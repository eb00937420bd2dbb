// rast — the exact visible area of a scene: each pixel cut on its own (visible_pixel.h), rows shared out
// among threads.
#include <rast/visible_area.h>

#include "validate.h"
#include "visible_pixel.h"

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <limits>
#include <map>
#include <mutex>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

namespace rast::reference {

VisibleArea::VisibleArea(Viewport viewport, std::vector<std::size_t> first, std::vector<VisiblePiece> pieces)
    : viewport_(viewport), first_(std::move(first)), pieces_(std::move(pieces)) {
    detail::require_valid(viewport, 1);
    const std::size_t pixels = static_cast<std::size_t>(viewport.width) * static_cast<std::size_t>(viewport.height);
    if (first_.size() != pixels + 1 || first_.front() != 0 || first_.back() != pieces_.size() ||
        !std::is_sorted(first_.begin(), first_.end()))
        throw std::invalid_argument("rast::reference::VisibleArea: the pixel offsets do not match the pieces");
}

std::span<const VisiblePiece> VisibleArea::at(int i, int j) const {
    const std::size_t p = static_cast<std::size_t>(j) * static_cast<std::size_t>(viewport_.width) + static_cast<std::size_t>(i);
    return std::span(pieces_).subspan(first_[p], first_[p + 1] - first_[p]);
}

std::vector<VisiblePiece> visible_in_pixel(const Scene& scene, int i, int j, std::span<const std::size_t> order) {
    detail::require_valid(scene.viewport, 1);
    if (i < 0 || i >= scene.viewport.width || j < 0 || j >= scene.viewport.height)
        throw std::invalid_argument("rast::reference::visible_in_pixel: pixel (" + std::to_string(i) + ", " +
                                    std::to_string(j) + ") is outside the viewport");
    std::vector<detail::Cutter> cutters;
    cutters.reserve(order.size());
    std::vector<bool> named(scene.triangles.size());
    for (const std::size_t id : order) {
        if (id >= scene.triangles.size() || named[id])
            throw std::invalid_argument("rast::reference::visible_in_pixel: triangle " + std::to_string(id) +
                                        (id >= scene.triangles.size() ? " is not in the scene" : " is named twice"));
        named[id] = true;
        detail::require_finite(scene.triangles[id], id);
        if (auto c = detail::make_cutter(scene.triangles[id], id)) cutters.push_back(std::move(*c));
    }
    std::vector<const detail::Cutter*> pointers;
    for (const detail::Cutter& c : cutters) pointers.push_back(&c);
    return detail::visible_in_square(i, j, pointers);
}

Rational resolve_error(std::span<const VisiblePiece> visible, std::span<const std::int32_t> sample_ids) {
    if (sample_ids.empty()) throw std::invalid_argument("rast::reference::resolve_error: a pixel without samples");
    // Owner -> its sample fraction minus its area.
    std::map<std::int64_t, Rational> difference;
    Rational nothing(1);
    for (const VisiblePiece& p : visible) {
        difference[static_cast<std::int64_t>(p.id)] -= p.area;
        nothing -= p.area;
    }
    difference[-1] -= nothing;
    const Rational share(1, static_cast<long>(sample_ids.size()));
    for (const std::int32_t id : sample_ids) difference[id] += share;
    Rational variation(0);
    for (const auto& [owner, d] : difference) variation += abs(d);
    return variation / 2;
}

namespace {

// The pixels k whose open square (k, k + 1) meets the open interval (lo, hi): only those can hold area
// of a triangle that spans [lo, hi]. Clamped to [0, n - 1] in double, before the conversion to int.
std::pair<int, int> open_span(double lo, double hi, int n) {
    const double first = std::max(std::floor(lo), 0.0);
    const double last = std::min(std::ceil(hi) - 1.0, n - 1.0);
    if (first > last) return {0, -1};
    return {static_cast<int>(first), static_cast<int>(last)};
}

// A triangle with its cutter, the pixel rows and columns its box spans, and its plane in doubles: that
// plane only orders the triangles of a pixel roughly front to back, which saves cuts and decides nothing.
struct Candidate {
    detail::Cutter cutter;
    std::pair<int, int> rows, columns;
    double za, zb, zc;
};

// None for a triangle of zero area or one outside the viewport.
std::optional<Candidate> make_candidate(const Triangle& t, std::size_t id, Viewport vp) {
    const auto [xmin, xmax] = std::minmax({t.v[0].x, t.v[1].x, t.v[2].x});
    const auto [ymin, ymax] = std::minmax({t.v[0].y, t.v[1].y, t.v[2].y});
    const auto columns = open_span(xmin, xmax, vp.width), rows = open_span(ymin, ymax, vp.height);
    if (columns.first > columns.second || rows.first > rows.second) return std::nullopt;
    std::optional<detail::Cutter> cutter = detail::make_cutter(t, id);
    if (!cutter) return std::nullopt;
    const double za = cutter->depth.a.convert_to<double>(), zb = cutter->depth.b.convert_to<double>(),
                 zc = cutter->depth.c.convert_to<double>();
    return Candidate{std::move(*cutter), rows, columns, za, zb, zc};
}

// The pieces of row j, pixel after pixel, and how many each pixel has.
struct Row {
    std::vector<std::size_t> count;
    std::vector<VisiblePiece> pieces;
    VisibleStats stats;
};

Row cut_row(int j, int width, const std::vector<const Candidate*>& in_row) {
    Row row;
    row.count.resize(static_cast<std::size_t>(width));
    std::vector<std::pair<double, const detail::Cutter*>> order;
    std::vector<const detail::Cutter*> cutters;
    for (int i = 0; i < width; ++i) {
        order.clear();
        const double x = i + 0.5, y = j + 0.5;
        for (const Candidate* c : in_row) {
            if (c->columns.first > i || i > c->columns.second) continue;
            // Far beyond double's range the rough depth can be NaN; sorting needs an order, so it goes last.
            const double z = c->za * x + c->zb * y + c->zc;
            order.emplace_back(std::isnan(z) ? std::numeric_limits<double>::infinity() : z, &c->cutter);
        }
        if (order.empty()) continue;
        ++row.stats.pixels_cut;
        row.stats.candidates += order.size();
        std::sort(order.begin(), order.end(), [](const auto& p, const auto& q) {
            return p.first < q.first || (p.first == q.first && p.second->id < q.second->id);
        });
        cutters.clear();
        for (const auto& entry : order) cutters.push_back(entry.second);
        std::vector<VisiblePiece> pixel = detail::visible_in_square(i, j, cutters);
        row.count[static_cast<std::size_t>(i)] = pixel.size();
        std::move(pixel.begin(), pixel.end(), std::back_inserter(row.pieces));
    }
    return row;
}

}  // namespace

VisibleArea visible_area(const Scene& scene, const Progress& progress, unsigned threads, VisibleStats* stats) {
    const Viewport vp = scene.viewport;
    detail::require_valid(vp, 1);
    const std::vector<std::int32_t> ids = triangle_ids(scene);
    std::vector<Candidate> candidates;
    candidates.reserve(scene.triangles.size());
    for (std::size_t id = 0; id < scene.triangles.size(); ++id) {
        detail::require_finite(scene.triangles[id], id);
        if (auto c = make_candidate(scene.triangles[id], id, vp)) candidates.push_back(std::move(*c));
    }
    std::vector<std::vector<const Candidate*>> in_row(static_cast<std::size_t>(vp.height));
    for (const Candidate& c : candidates) {
        for (int j = c.rows.first; j <= c.rows.second; ++j) in_row[static_cast<std::size_t>(j)].push_back(&c);
    }

    std::vector<Row> rows(static_cast<std::size_t>(vp.height));
    std::mutex report;
    std::size_t done = 0;
    report_progress(progress, 0, rows.size());
    tbb::task_arena arena(threads == 0 ? tbb::task_arena::automatic : static_cast<int>(threads));
    arena.execute([&] {
        tbb::parallel_for(tbb::blocked_range<int>(0, vp.height, 1), [&](const tbb::blocked_range<int>& range) {
            for (int j = range.begin(); j != range.end(); ++j) {
                rows[static_cast<std::size_t>(j)] = cut_row(j, vp.width, in_row[static_cast<std::size_t>(j)]);
                const std::lock_guard lock(report);
                report_progress(progress, ++done, rows.size(), 1);
            }
        });
    });

    std::vector<std::size_t> first{0};
    std::vector<VisiblePiece> pieces;
    for (Row& row : rows) {
        if (stats) {
            stats->pixels_cut += row.stats.pixels_cut;
            stats->candidates += row.stats.candidates;
        }
        for (const std::size_t n : row.count) first.push_back(first.back() + n);
        std::move(row.pieces.begin(), row.pieces.end(), std::back_inserter(pieces));
    }
    // Cut by their indices, the triangles take their ids in the scene; lines have no area.
    if (!scene.lines.empty())
        for (VisiblePiece& piece : pieces) piece.id = static_cast<std::size_t>(ids[piece.id]);
    return VisibleArea(vp, std::move(first), std::move(pieces));
}

}  // namespace rast::reference
