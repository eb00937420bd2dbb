// The diamond of the diamond-exit rule (docs/design.md) for the fast path's two line walks, Bresenham's
// in grid units and the DDA's in float or double: one statement of which boundary it holds.
#pragma once

namespace rast::fast::detail {

// Whether a pixel's diamond holds the point that lies (da along, dc across) from its centre, the diamond
// being `half` wide from centre to corner: inside, or on its held boundary (the two lower edges and the
// bottom corner; the right corner too for a y-major segment). Along is the segment's major axis. For an
// x-major segment across is y, so "lower" is dc < 0. For a y-major one along is y and across is x:
// "lower" is da < 0, and the right corner is da = 0, dc > 0.
template <class N>
bool diamond_holds(N da, N dc, N half, bool y_major) {
    const N d = (da < 0 ? -da : da) + (dc < 0 ? -dc : dc);
    if (d < half) return true;
    if (d > half) return false;
    if (!y_major) return dc < 0;
    return da < 0 || (da == 0 && dc > 0);
}

}  // namespace rast::fast::detail
