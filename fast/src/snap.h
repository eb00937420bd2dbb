// Snapping to the fixed-point grid: round to nearest, ties to even, as Direct3D 11 does.
#pragma once

#include <rast/fast.h>

#include <cmath>
#include <cstdint>

namespace rast::fast::detail {

// N for fixedN, 0 for the float modes.
constexpr int subpixel_bits(Precision p) {
    switch (p) {
        case Precision::fixed4: return 4;
        case Precision::fixed8: return 8;
        case Precision::fixed16: return 16;
        case Precision::float32:
        case Precision::float64: return 0;
    }
    return 0;
}

constexpr bool is_fixed(Precision p) { return subpixel_bits(p) != 0; }

// x rounded to the nearest multiple of 2^-bits. Scaling by a power of two is exact, and a double of
// magnitude >= 2^(52-bits) is already a multiple of 2^-bits (its ulp is at least that), which also
// keeps x·2^bits from overflowing. Below that, adding 2^52 (with x's sign) leaves no fraction bits, so
// the sum is rounded to an integer, ties to even, under the default rounding mode; subtracting it back
// is exact, and copysign keeps the sign of a zero result as std::nearbyint would.
inline double snap_coordinate(double x, int bits) {
    const double scale = static_cast<double>(std::int64_t{1} << bits);  // multiplying by it is exact
    const double scaled = x * scale;
    if (!(std::abs(scaled) < 0x1p52)) return x;
    const double shift = std::copysign(0x1p52, scaled);
    return std::copysign((scaled + shift) - shift, scaled) * (1 / scale);  // 1 / scale: exact, a power of two
}

// x · 2^bits rounded to the nearest integer, ties to even, as snap_coordinate rounds, for
// |x · 2^bits| <= 2^51: adding 1.5 · 2^52 gives a sum in [2^52, 2^53), where the ulp is 1, so the
// addition itself rounds as wanted, and subtracting it back is exact.
inline std::int64_t grid_units(double x, double scale) {
    return static_cast<std::int64_t>((x * scale + 0x1.8p52) - 0x1.8p52);
}

// rast::fast::snap without its input checks: the engine snaps triangles and lines it has already
// checked (the identity in the float modes).
template <class Shape>
Shape snapped(Shape shape, Precision precision) {
    const int bits = subpixel_bits(precision);
    if (bits == 0) return shape;
    for (Vertex& v : shape.v) {
        v.x = snap_coordinate(v.x, bits);
        v.y = snap_coordinate(v.y, bits);
    }
    return shape;
}

}  // namespace rast::fast::detail
