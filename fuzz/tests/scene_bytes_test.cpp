// The rasterizer fuzzer's input encoding: decoding by hand-read bytes, and encoding back.
#include "scene_bytes.h"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace rast::fuzz {
namespace {

using Bytes = std::vector<std::uint8_t>;

std::uint64_t bits(double x) { return std::bit_cast<std::uint64_t>(x); }

// 0x7ff0000000000000 (+infinity) and 0x3fb999999999999a (0.1), little-endian.
const Bytes kInfinity = {0, 0, 0, 0, 0, 0, 0xf0, 0x7f};
const Bytes kOneTenth = {0x9a, 0x99, 0x99, 0x99, 0x99, 0x99, 0xb9, 0x3f};

Bytes concat(std::initializer_list<Bytes> parts) {
    Bytes out;
    for (const Bytes& p : parts) out.insert(out.end(), p.begin(), p.end());
    return out;
}

TEST(SceneBytes, EmptyInputIsTheSmallestScene) {
    const Scene s = decode_scene({});
    EXPECT_EQ(s.viewport, (Viewport{1, 1}));
    EXPECT_EQ(s.samples, 1);
    EXPECT_TRUE(s.triangles.empty());
}

TEST(SceneBytes, DecodesEachKindOfCoordinate) {
    // 4 x 2 pixels, 8 samples; x y z of three vertices: specials 0, 1, 2, 12, 14; grid tags 20 (k),
    // 16 (k / 2), 19 (k / 16); a raw +infinity.
    const Bytes bytes = concat({{3, 1, 2, 0, 1, 2, 12, 14, 20, 0xff, 16, 3, 19, 8, 255}, kInfinity});
    const Scene s = decode_scene(bytes);
    EXPECT_EQ(s.viewport, (Viewport{4, 2}));
    EXPECT_EQ(s.samples, 8);
    ASSERT_EQ(s.triangles.size(), 1u);
    const auto& v = s.triangles[0].v;
    EXPECT_EQ(bits(v[0].x), bits(0.0));
    EXPECT_EQ(bits(v[0].y), bits(-0.0));
    EXPECT_EQ(v[0].z, std::numeric_limits<double>::denorm_min());
    EXPECT_EQ(v[1].x, 0x1p60);
    EXPECT_EQ(v[1].y, DBL_MAX);
    EXPECT_EQ(v[1].z, -1.0);
    EXPECT_EQ(v[2].x, 1.5);
    EXPECT_EQ(v[2].y, 0.5);
    EXPECT_EQ(v[2].z, INFINITY);
}

TEST(SceneBytes, SidesWrapAndMissingBytesReadAsZero) {
    // Side bytes 16 and 255: 16 % 16 + 1 = 1 and 57 + (255 - 240) = 72; samples 0b111 -> 16; one tag 12
    // (2^60), then the input ends: the other eight coordinates read tag 0, which is 0.0.
    const Scene s = decode_scene(Bytes{16, 255, 7, 12});
    EXPECT_EQ(s.viewport, (Viewport{1, 72}));
    EXPECT_EQ(s.samples, 16);
    ASSERT_EQ(s.triangles.size(), 1u);
    EXPECT_EQ(s.triangles[0], (Triangle{{{{0x1p60, 0, 0}, {0, 0, 0}, {0, 0, 0}}}}));
}

TEST(SceneBytes, AtMostFourTriangles) {
    Bytes bytes = {0, 0, 0};
    bytes.resize(3 + 5 * 9, 6);  // five triangles of 0.5 (special 6)
    EXPECT_EQ(decode_scene(bytes).triangles.size(), 4u);
}

TEST(SceneBytes, WideSidesStraddleTheTileBorder) {
    EXPECT_EQ(decode_scene(Bytes{239, 240}).viewport, (Viewport{16, 57}));
    Scene s;
    s.viewport = {64, 65};
    EXPECT_EQ(encode_scene(s), (Bytes{247, 248, 0}));
}

TEST(SceneBytes, EncodesWithTheShortestTag) {
    Scene s;
    s.viewport = {4, 2};
    s.samples = 8;
    s.triangles = {Triangle{{{{0.0, -0.0, std::numeric_limits<double>::denorm_min()},
                              {0x1p60, DBL_MAX, -1.0},
                              {1.5, 0.5, 0.1}}}}};
    // -1 is grid tag 20 (k = -1), 1.5 grid tag 16 (k = 3), 0.5 is special 6, 0.1 is raw.
    const Bytes expected = concat({{3, 1, 2, 0, 1, 2, 12, 14, 20, 0xff, 16, 3, 6, 255}, kOneTenth});
    EXPECT_EQ(encode_scene(s), expected);
    const Scene back = decode_scene(expected);
    EXPECT_EQ(back.viewport, s.viewport);
    EXPECT_EQ(back.samples, s.samples);
    EXPECT_EQ(back.triangles, s.triangles);
    EXPECT_EQ(bits(back.triangles[0].v[0].y), bits(-0.0));
}

TEST(SceneBytes, EncodingRejectsWhatTheFuzzerCannotHold) {
    Scene s;
    for (const int side : {0, 17, 56, 73}) {
        s.viewport = {side, 1};
        EXPECT_THROW(encode_scene(s), std::invalid_argument) << side;
    }
    s.viewport = {1, 1};
    s.samples = 2;
    EXPECT_THROW(encode_scene(s), std::invalid_argument);
    s.samples = 1;
    s.triangles.resize(5);
    EXPECT_THROW(encode_scene(s), std::invalid_argument);
}

}  // namespace
}  // namespace rast::fuzz
