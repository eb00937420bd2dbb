// rast — the rasterizer fuzzer's input: a byte string decoded into a small scene whose coordinates reach
// the hard cases (+-0, subnormals, DBL_MIN, 2^60, DBL_MAX, ties on pixel centres, non-finite values),
// and the inverse encoding, so that .tri scenes of the corpus seed the fuzzer.
//
// Layout, read from the front; a missing byte reads as 0, so every byte string is a scene:
//   width, height (a side byte b < kWideSideByte is 1 + b % kSmallSide, so most scenes are small and fast;
//   above, the sides kWideSide..kWideSide+15, which straddle the fast path's 64-pixel tile border),
//   samples (low 2 bits: 1, 4, 8, 16),
//   then up to kMaxTriangles triangles while bytes remain, each 9 coordinates x0 y0 z0 x1 ... z2.
// A coordinate is a tag byte, then:
//   tag < kSpecialCount:       kSpecials[tag], no payload;
//   tag < kGridTagEnd:         one signed byte k, the value k * 2^-(tag % 5): pixel centres, edges through
//                              them and vertices on the fixed-point grids;
//   otherwise:                 8 bytes, the double's bit pattern, little-endian (NaN and infinity included).
#pragma once

#include <rast/scene.h>

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace rast::fuzz {

inline constexpr int kSmallSide = 16;
inline constexpr std::uint8_t kWideSideByte = 240;
inline constexpr int kWideSide = 57;
inline constexpr std::size_t kMaxTriangles = 4;
inline constexpr std::uint8_t kSpecialCount = 16;
inline constexpr std::uint8_t kGridTagEnd = 128;
inline constexpr std::uint8_t kRawTag = 255;

Scene decode_scene(std::span<const std::uint8_t> bytes);

// The shortest bytes that decode to `scene`. Throws std::invalid_argument if it cannot be represented:
// a side that is neither 1..kSmallSide nor kWideSide..kWideSide+15, more than kMaxTriangles triangles, or an unsupported sample count.
std::vector<std::uint8_t> encode_scene(const Scene& scene);

}  // namespace rast::fuzz
