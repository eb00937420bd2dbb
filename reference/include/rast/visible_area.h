// rast — the exact visible area: the ideal antialiased image of a z-buffered scene.
//
// In each pixel square, the area where each triangle is the z-buffer's winner under the (z, id) order of
// docs/design.md, z the triangle's plane: triangles that interpenetrate split a pixel along the line where
// their planes meet, and coplanar overlaps go to the lower id. Boundaries have no area, so the tie rule
// plays no part. This is what supersampling a z-buffer approximates: the box-filtered visible image.
// Lines have no area: they hide nothing and own none (their ids are skipped).
#pragma once

#include <rast/progress.h>
#include <rast/reference.h>
#include <rast/scene.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rast::reference {

// One triangle's visible area in one pixel.
struct VisiblePiece {
    std::size_t id;
    Rational area;
    bool operator==(const VisiblePiece&) const = default;
};

class VisibleArea {
public:
    // Pixel p's pieces are pieces[first[p]] .. pieces[first[p + 1] - 1], bottom row first. Throws
    // std::invalid_argument for a viewport outside the limits or offsets that do not match the pieces.
    VisibleArea(Viewport viewport, std::vector<std::size_t> first, std::vector<VisiblePiece> pieces);

    Viewport viewport() const { return viewport_; }
    // The visible triangles of pixel (i, j), within the viewport: ids ascending, each with a non-zero area;
    // their areas sum to the area of the union of the triangles inside the pixel.
    std::span<const VisiblePiece> at(int i, int j) const;

private:
    Viewport viewport_;
    std::vector<std::size_t> first_;  // pixel p's pieces are [first_[p], first_[p + 1]), bottom row first
    std::vector<VisiblePiece> pieces_;
};

// The visible areas of pixel (i, j) alone, cutting with the triangles `order` names, in that order (each
// id at most once; a triangle left out is not there). Here a triangle's id is its index in
// Scene::triangles, in `order` and in the pieces alike. visible_area inserts them roughly front to back;
// any order gives the same areas, which a property holds. Throws std::invalid_argument for a pixel
// outside the viewport, an id out of range or named twice, or a coordinate that is not finite.
std::vector<VisiblePiece> visible_in_pixel(const Scene& scene, int i, int j, std::span<const std::size_t> order);

// How far a pixel's samples are from its visible areas: the total variation distance between the
// fraction of the samples each owner holds (`sample_ids`, -1 for none) and the area it sees (nothing seen
// owning what is left). It is the largest error the resolved colour of the pixel can have, when colours
// lie in [0, 1]: the average over samples against the average over the area. Throws
// std::invalid_argument for no samples.
Rational resolve_error(std::span<const VisiblePiece> visible, std::span<const std::int32_t> sample_ids);

// What the cutting had to do: how the cost grows with the triangles that reach a pixel.
struct VisibleStats {
    std::uint64_t pixels_cut = 0;  // pixels that some triangle's box reaches
    std::uint64_t candidates = 0;  // (triangle, pixel) pairs cut, over those pixels
};

// `threads` 0 takes every core; rows are shared out among them. `progress` counts pixel rows (from any
// of those threads, one call at a time).
VisibleArea visible_area(const Scene& scene, const Progress& progress = {}, unsigned threads = 0,
                         VisibleStats* stats = nullptr);

}  // namespace rast::reference
