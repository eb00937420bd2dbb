// Placing small triangles several at a time in SIMD (runtime dispatch, as kernels.h). Fixed-point ones:
// place_small_fixed (setup.h) one triangle at a time took a fifth of the instructions of a scene of
// 4-pixel triangles, most of them in its branches and in moving coordinates between integer and
// floating-point registers. Here every lane is a triangle and every step is exact: grid units, their
// differences and the pixel ranges are integers below 2^31 held in doubles, scaled by powers of two.
// The float modes' ones: place (setup.h) one at a time took a fifth of a float32 render of 4-pixel
// triangles; in lanes, its steps are the same operations on the same doubles.
#pragma once

#include <rast/scene.h>

#include <cstdint>

namespace rast::fast::detail {

inline constexpr int kPlaceBatch = 8;

// What the placing needs of the Context (setup.h), in doubles: the grid's scale 2^bits and spacing
// 2^-bits, coordinate_limit, the sample offsets' extent in grid units, the viewport's size, and the
// small lane's largest box (kSmallSide).
struct PlaceGrid {
    double scale, unit, limit;
    double sx_min, sx_max, sy_min, sy_max;
    double width, height;
    double small_side;
};

// kPlaceBatch triangles placed, one array per field, each lane what place_small_fixed<Fault::none> makes
// of its triangle: the lane's bit in exactly one of the four masks, and where it is in `small`, the
// fields of its SmallFixed but the id (its corners counter-clockwise in grid units, their depths, its
// pixel bounding box, and in `narrow` whether its edge functions fit in 32 bits, narrow_edges). The
// small and culled lanes' coordinates are finite; a triangle with a depth that is not finite is general.
// `undecided`: the lanes whose coordinate differences make products of 2^53 or more (far ends of a
// triangle clipped to a small box), whose orientation doubles cannot decide exactly; place_small_fixed
// decides them, and may find them small, culled or general.
struct PlacedBatch {
    double z[3][kPlaceBatch];
    std::int32_t x[3][kPlaceBatch], y[3][kPlaceBatch];
    std::int32_t i_lo[kPlaceBatch], i_hi[kPlaceBatch], j_lo[kPlaceBatch], j_hi[kPlaceBatch];
    std::uint32_t small, culled, general, undecided;
    std::uint32_t narrow;  // among the small lanes
};

// Triangles t[0, n), 1 <= n <= kPlaceBatch, into lanes 0 to n - 1 (the lanes past n are in no mask).
void place_small_batch(const Triangle* t, int n, const PlaceGrid& grid, PlacedBatch& out);

// kPlaceBatch triangles of a float mode placed as place<Fault::none> (setup.h; no snapping there) places
// them: a lane's bit in `small` where place finds it small (binning.h's is_small), with its corners
// counter-clockwise and its pixel bounding box, or in `culled` where place finds it covers no sample. The
// winding is the orientation filter's (rast/filters/orientation.h), evaluated as it is: the lanes it
// leaves open, those with a coordinate that is not finite and those whose box is bigger are in neither
// mask, for place itself. The grid is the pixel (PlaceGrid's scale and unit 1, offsets in pixels).
struct FloatPlacedBatch {
    double x[3][kPlaceBatch], y[3][kPlaceBatch], z[3][kPlaceBatch];
    std::int32_t i_lo[kPlaceBatch], i_hi[kPlaceBatch], j_lo[kPlaceBatch], j_hi[kPlaceBatch];
    std::uint32_t small, culled;
};

// Triangles t[0, n), 1 <= n <= kPlaceBatch, into lanes 0 to n - 1 (the lanes past n are in no mask).
void place_float_batch(const Triangle* t, int n, const PlaceGrid& grid, FloatPlacedBatch& out);

}  // namespace rast::fast::detail
