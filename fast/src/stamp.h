// Stamps: the coverage of a batch of small triangles' blocks, each at most kStampSide samples each way,
// as one 64-bit mask per triangle and sample index (SIMD with runtime dispatch, as kernels.h). A tiny
// triangle's edge functions, set up one at a time and stepped sample by sample in scalar code, took
// half of its composing; here the setup runs across the batch's triangles (a lane each), and so does the
// coverage where their blocks are alike (else across one stamp's samples, a lane each); the depth test
// reads the mask's bits.
#pragma once

#include "planes.h"

#include <cstdint>

namespace rast::fast::detail {

inline constexpr int kStampSide = 8;

// What the stamps need of the tile and the context for one sample index: the tile's pixels
// [i0, i1] x [j0, j1], the subpixel bits, and the sample's offset in grid units.
struct StampGrid {
    int i0, i1, j0, j1;
    int bits;
    std::int32_t sx, sy;
};

// The integer edge functions of a batch's blocks (their boxes within the tile) at one sample index, a lane
// per triangle: edge k runs from corner k to corner k + 1, E at the block's first sample (its tie bias
// included, as fixed_edges then fixed_edges_at give it: setup.h, coverage.h), and its steps per column
// and row. A narrow triangle's (narrow_edges, setup.h) are exact; the others' wrap around.
struct StampEdges {
    std::int32_t e[3][kPlaneBatch], dx[3][kPlaneBatch], dy[3][kPlaneBatch];
    std::int32_t width[kPlaneBatch], rows[kPlaneBatch];  // the block's size
};

// The triangles stamp_masks answered, bit k for batch entry k, and how many samples their blocks have in
// all (at one sample index).
struct Stamped {
    std::uint32_t triangles;
    std::uint32_t samples;
};

// Sets up `edges` for every triangle of `batch` (planes.h: counter-clockwise corners in grid units and
// pixel boxes). Of those whose bit is set in `narrow` (narrow_edges, setup.h: their edge functions fit in
// 32 bits over their boxes), answers the ones whose block, their box within the tile, is at most
// kStampSide pixels each way and kScalarSamples pixels in all (the blocks the scalar depth test takes,
// scalar.h), and sets their masks[k]: bit kStampSide r + c for the sample of pixel (i + c, j + r), (i, j)
// the block's first pixel, inside the triangle by the integer edge functions and the tie rule of
// docs/design.md (E >= 0 on an owning edge, E > 0 on the others), for c and r within the block. masks
// holds kPlaneBatch entries; the others' may be overwritten.
Stamped stamp_masks(const PlaneBatch& batch, std::uint32_t narrow, const StampGrid& grid, StampEdges& edges,
                    std::uint64_t* masks);

// Whether stamp_masks finds the masks of `count` stamps, whose blocks are `rows_each` rows in all and at
// most `width` x `rows`, all at once, a lane per triangle over that box, rather than one at a time, a lane
// per sample: unless the box is much larger than the blocks (a few stamps, one of them large). About 16
// instructions a position and 20 a row at once, against 35 a triangle and 15 a row one at a time (AVX2).
inline bool stamps_at_once(int width, int rows, int count, int rows_each) {
    return 16 * rows * width + 20 * rows < 35 * count + 15 * rows_each;
}

}  // namespace rast::fast::detail
