// The depth planes of small triangles, several at a time in SIMD with runtime dispatch (as kernels.h): one
// at a time, setting up a small triangle's plane took a sixth of the instructions of a scene of 4-pixel
// triangles (fixed8 and float32 alike). Every lane computes the same operations in the same order, without
// contraction, so a plane does not depend on the instruction set.
//
// narrow_planes' triangles are narrow (narrow_edges, setup.h): on the fixed grid, their corners within 2^15
// grid units of each other. Their differences, and the cross product of two (integers below 2^31 times a
// power of two), are exact in double, so make_plane's operations give the same gradient, and its
// bounds, which are mul, sub and div's (bounded.h) with those inputs' errors zero, come from the depths
// alone: the plane costs a third fewer operations than make_plane's.
#pragma once

#include <cstdint>

namespace rast::fast::detail {

inline constexpr int kPlaneBatch = 8;

// kPlaneBatch narrow triangles, one array per field (lanes load them whole): counter-clockwise corners
// in grid units, their depths and the pixel bounding box. narrow_planes sets a, b and err, the gradient
// and bound of each one's Plane (setup.h) through corner 0.
struct PlaneBatch {
    std::int32_t x[3][kPlaneBatch], y[3][kPlaneBatch];
    double z[3][kPlaneBatch];
    std::int32_t i_lo[kPlaneBatch], i_hi[kPlaneBatch], j_lo[kPlaneBatch], j_hi[kPlaneBatch];
    double a[kPlaneBatch], b[kPlaneBatch], err[kPlaneBatch];
};

// kPlaneBatch triangles as placed (Placed, setup.h: any path, corners in pixels), one array per field:
// counter-clockwise corners, their depths and the pixel bounding box. make_planes sets a, b and err, those
// of make_plane's Plane for each.
struct CornerBatch {
    double x[3][kPlaneBatch], y[3][kPlaneBatch], z[3][kPlaneBatch];
    std::int32_t i_lo[kPlaneBatch], i_hi[kPlaneBatch], j_lo[kPlaneBatch], j_hi[kPlaneBatch];
    double a[kPlaneBatch], b[kPlaneBatch], err[kPlaneBatch];
};

// What a plane needs of the Context (setup.h): the grid's spacing in pixels and the sample offsets' extent.
struct PlaneGrid {
    double unit, ox_min, ox_max, oy_min, oy_max;
};

// All kPlaneBatch entries, each of them filled.
void narrow_planes(PlaneBatch& batch, const PlaneGrid& grid);

// make_plane (setup.h, filters::Sound) on all kPlaneBatch entries, each of them filled: its operations
// (bounded.h's) in lanes, in its order, so its bits. One triangle at a time it took a sixth of a float32
// render of 4-pixel triangles.
void make_planes(CornerBatch& batch, const PlaneGrid& grid);

}  // namespace rast::fast::detail
