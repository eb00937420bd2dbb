// visible_area and msaa_visible_bound: the exact visible area, and supersampling held to it.
#include <rast/reference.h>
#include <rast/visible_area.h>
#include <rast/visible_oracle.h>

#include "checks.h"

#include <algorithm>
#include <numeric>
#include <random>
#include <span>
#include <string>

namespace rast::properties {

namespace {

std::string pixel_name(int i, int j) { return "pixel (" + std::to_string(i) + ", " + std::to_string(j) + ")"; }

std::string describe(std::span<const reference::VisiblePiece> pieces) {
    std::string out;
    for (const auto& p : pieces) out += (out.empty() ? "" : ",") + std::to_string(p.id) + ":" + p.area.str();
    return out.empty() ? "-" : out;
}

std::string describe(const std::vector<std::pair<std::size_t, Rational>>& pieces) {
    std::string out;
    for (const auto& [id, area] : pieces) out += (out.empty() ? "" : ",") + std::to_string(id) + ":" + area.str();
    return out.empty() ? "-" : out;
}

}  // namespace

// The reference's visible areas equal the slab judge's in every pixel; they sum to the area of the union
// (at most 1); where nothing overlaps, to the exact coverage, each triangle keeping its own area; the
// order the triangles are cut in changes nothing; and a triangle holding the pixel in front of all the
// others near it owns all of it.
Outcome visible_area(const Scene& scene, const Engine&) {
    return visible_area_of(scene, [](const Scene& s) { return reference::visible_area(s); });
}

Outcome visible_area_of(const Scene& scene, const std::function<reference::VisibleArea(const Scene&)>& computed) {
    const reference::VisibleArea visible = computed(scene);
    const std::vector<Rational> coverage = reference::coverage_area(scene);
    const Viewport vp = scene.viewport;
    std::vector<std::vector<std::size_t>> orders(3, std::vector<std::size_t>(scene.triangles.size()));
    std::iota(orders[0].begin(), orders[0].end(), std::size_t{0});
    orders[1].assign(orders[0].rbegin(), orders[0].rend());
    orders[2] = orders[0];
    std::shuffle(orders[2].begin(), orders[2].end(), std::mt19937(static_cast<unsigned>(scene.triangles.size())));
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) {
            const auto pieces = visible.at(i, j);
            const SlabPixel judged = visible_by_slabs(scene, i, j);
            const bool same = std::equal(pieces.begin(), pieces.end(), judged.visible.begin(), judged.visible.end(),
                                         [](const auto& p, const auto& q) { return p.id == q.first && p.area == q.second; });
            if (!same)
                return Outcome::fail(pixel_name(i, j) + ": the reference's visible areas are " + describe(pieces) +
                                     ", the slabs give " + describe(judged.visible));
            if (judged.covered > 1)
                return Outcome::fail(pixel_name(i, j) + ": the union of its triangles has area " +
                                     judged.covered.str() + " > 1");
            const Rational& summed = coverage[static_cast<std::size_t>(j) * static_cast<std::size_t>(vp.width) +
                                              static_cast<std::size_t>(i)];
            if (summed == judged.covered) {
                for (const auto& p : pieces)
                    if (p.area != reference::pixel_area(scene.triangles[p.id], i, j))
                        return Outcome::fail(pixel_name(i, j) + ": nothing overlaps there, yet triangle " +
                                             std::to_string(p.id) + " shows " + p.area.str() + " of its area " +
                                             reference::pixel_area(scene.triangles[p.id], i, j).str());
            }
            // Draw order: the triangles cut into the pixel in the scene's order, reversed, and shuffled.
            for (const auto& order : orders) {
                const auto again = reference::visible_in_pixel(scene, i, j, order);
                if (!std::equal(pieces.begin(), pieces.end(), again.begin(), again.end()))
                    return Outcome::fail(pixel_name(i, j) + ": inserting the triangles in another order gives " +
                                         describe(again) + ", not " + describe(pieces));
            }
            if (const auto front = front_cover(scene, i, j);
                front && !(pieces.size() == 1 && pieces[0].id == *front && pieces[0].area == 1))
                return Outcome::fail(pixel_name(i, j) + ": triangle " + std::to_string(*front) +
                                     " holds it in front of all others, yet the visible areas are " + describe(pieces));
        }
    return Outcome::pass();
}

// In every pixel, the total variation distance between the engine's sample fractions per owner and the
// exact visible areas (of the geometry it rasterizes) is at most the cells met by boundaries over N
// (rast/visible_oracle.h says why).
Outcome msaa_visible_bound(const Scene& scene, const Engine& engine) {
    const Scene geometry = rasterized_geometry(engine, scene);
    const reference::VisibleArea visible = reference::visible_area(geometry);
    const Framebuffer image = engine.render(scene);
    const int n = scene.samples;
    const auto [columns, rows] = sample_cells(n);
    const Viewport vp = scene.viewport;
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) {
            const Rational variation = reference::resolve_error(
                visible.at(i, j), std::span(image.ids).subspan(image.index(i, j, 0), static_cast<std::size_t>(n)));
            const int met = cells_met_by_boundaries(geometry, i, j, columns, rows);
            if (variation * n > met)
                return Outcome::fail(pixel_name(i, j) + ": " + engine.name + "'s " + std::to_string(n) +
                                     " samples are " + variation.str() + " from the visible areas " +
                                     describe(visible.at(i, j)) + " in total variation, beyond the bound " +
                                     std::to_string(met) + "/" + std::to_string(n) + " (" + std::to_string(met) +
                                     " of its " + std::to_string(columns * rows) + " cells meet a boundary)");
        }
    return Outcome::pass();
}

}  // namespace rast::properties
