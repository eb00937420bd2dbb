// order_independence: the z-buffer's result is the (z, id) minimum, whatever order the triangles come in.
#include <rast/reference.h>

#include <algorithm>
#include <numeric>

#include "checks.h"
#include "samples.h"

namespace rast::properties {

namespace {

// Every permutation of up to four triangles; beyond that the reversal, two rotations and the
// interleaving (odd positions first), which between them reorder every pair of triangles somewhere.
std::vector<std::vector<std::size_t>> draw_orders(std::size_t n) {
    std::vector<std::size_t> order(n);
    std::iota(order.begin(), order.end(), 0);
    std::vector<std::vector<std::size_t>> orders;
    if (n <= 4) {
        do orders.push_back(order);
        while (std::next_permutation(order.begin(), order.end()));
        return orders;
    }
    orders.push_back(order);
    orders.emplace_back(order.rbegin(), order.rend());
    for (std::size_t by : {std::size_t{1}, n / 2}) {
        auto rotated = order;
        std::rotate(rotated.begin(), rotated.begin() + static_cast<std::ptrdiff_t>(by), rotated.end());
        orders.push_back(rotated);
    }
    std::vector<std::size_t> interleaved;
    for (std::size_t start : {std::size_t{1}, std::size_t{0}})
        for (std::size_t k = start; k < n; k += 2) interleaved.push_back(k);
    orders.push_back(interleaved);
    return orders;
}

}  // namespace

// For every draw order, the rendered ids and depths are those of the (z, id) minimum over the
// triangles' own fragments (each triangle rendered alone), with z compared exactly and ids taken in
// that draw order.
Outcome order_independence(const Scene& scene, const Engine& engine) {
    const std::size_t count = scene.triangles.size();
    const Scene geometry = rasterized_geometry(engine, scene);
    std::vector<Framebuffer> alone;
    for (const Triangle& t : scene.triangles) alone.push_back(engine.render(Scene{scene.viewport, scene.samples, {t}}));

    // Per sample, the triangles covering it, nearest first by exact depth; `tied` marks a triangle
    // at exactly the depth of the one before it.
    struct Fragment {
        std::size_t triangle;
        bool tied;
    };
    const std::size_t samples = sample_count(scene.viewport, scene.samples);
    std::vector<std::vector<Fragment>> nearest_first(samples);
    for (std::size_t index = 0; index < samples; ++index) {
        const Sample at = sample_at(scene.viewport, scene.samples, index);
        std::vector<std::pair<reference::Rational, std::size_t>> depths;
        for (std::size_t k = 0; k < count; ++k)
            if (alone[k].ids[index] == 0) depths.emplace_back(0, k);
        if (depths.size() > 1) {  // exact depths only where there is something to order
            for (auto& [z, k] : depths) z = reference::depth_at(geometry.triangles[k], at.x, at.y);
            std::sort(depths.begin(), depths.end());
        }
        for (std::size_t f = 0; f < depths.size(); ++f)
            nearest_first[index].push_back({depths[f].second, f > 0 && depths[f].first == depths[f - 1].first});
    }

    for (const auto& order : draw_orders(count)) {
        Scene drawn{scene.viewport, scene.samples, {}};
        std::vector<std::size_t> position(count);
        for (std::size_t r = 0; r < count; ++r) {
            drawn.triangles.push_back(scene.triangles[order[r]]);
            position[order[r]] = r;
        }
        Framebuffer expected(scene.viewport, scene.samples);
        for (std::size_t index = 0; index < samples; ++index) {
            const auto& fragments = nearest_first[index];
            if (fragments.empty()) continue;
            std::size_t winner = fragments[0].triangle;
            for (std::size_t f = 1; f < fragments.size() && fragments[f].tied; ++f)
                if (position[fragments[f].triangle] < position[winner]) winner = fragments[f].triangle;
            expected.ids[index] = static_cast<std::int32_t>(position[winner]);
            expected.depth[index] = alone[winner].depth[index];
        }
        std::string name = engine.name + " drawing triangles in the order";
        for (std::size_t k : order) (name += ' ') += std::to_string(k);
        if (auto diff = first_difference(engine.render(drawn), name, expected, "the (z, id) minimum",
                                         engine.writes_depth()))
            return Outcome::fail(*diff);
    }
    return Outcome::pass();
}

}  // namespace rast::properties
