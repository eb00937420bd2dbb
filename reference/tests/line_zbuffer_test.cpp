// Lines in the reference's z-buffer, worked out by hand: a line's depth at a pixel, its samples against
// triangles and other lines in the (z, id) order, and ids shared with triangles in file order.
#include <rast/line.h>
#include <rast/reference.h>

#include <rast/testing/line_scenes.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <stdexcept>
#include <vector>

namespace rast::reference {
namespace {

using rast::testing::backdrop;
using rast::testing::row;
using rast::testing::segment;

TEST(LineDepth, IsZAtThePointNearestTheCentre) {
    // Along a row: the centre's own x. (2.5 - 0.5) / 4 of the way from 0 to 1.
    const Segment along{{Vertex{0.5, 0.5, 0}, Vertex{4.5, 0.5, 1}}};
    EXPECT_EQ(line_depth(along, 2, 0), Rational(1, 2));
    EXPECT_EQ(line_depth(along, 2, 3), Rational(1, 2));  // off the line: the same foot
    // Beyond an end: that end's z.
    EXPECT_EQ(line_depth(along, 7, 0), Rational(1));
    EXPECT_EQ(line_depth(along, -3, 5), Rational(0));
    // A diagonal from (0, 0) to (4, 4): the centre (2.5, 0.5) projects to t = (2.5 * 4 + 0.5 * 4) / 32 = 3/8.
    const Segment diagonal{{Vertex{0, 0, 0}, Vertex{4, 4, 1}}};
    EXPECT_EQ(line_depth(diagonal, 2, 0), Rational(3, 8));
    // Depth 2 to -6: z = 2 - 8 t.
    const Segment falling{{Vertex{0, 0, 2}, Vertex{4, 4, -6}}};
    EXPECT_EQ(line_depth(falling, 2, 0), Rational(-1));
    // No length: the start's z.
    EXPECT_EQ(line_depth(Segment{{Vertex{1, 1, 0.25}, Vertex{1, 1, 9}}}, 0, 0), Rational(1, 4));
}

// A line in front of a triangle shows at its lit pixels; behind it, nowhere.
TEST(LineZBuffer, NearerWinsAgainstATriangle) {
    Scene scene{{5, 3}, 1, {backdrop(0, 0, 0.5)}};
    append_line(scene, segment({0.5, 1.5, 0.25}, {3.5, 1.5, 0.25}));
    Framebuffer fb = render(scene);
    EXPECT_EQ(row(fb, 1), (std::vector<std::int32_t>{1, 1, 1, 0, 0}));
    EXPECT_EQ(row(fb, 0), (std::vector<std::int32_t>{0, 0, 0, 0, 0}));
    EXPECT_EQ(fb.depth[fb.index(1, 1)], 0.25);
    scene.lines[0].segment.v[0].z = scene.lines[0].segment.v[1].z = 0.75;
    fb = render(scene);
    EXPECT_EQ(row(fb, 1), (std::vector<std::int32_t>{0, 0, 0, 0, 0}));
}

// Equal depths: the lower id, so the line wins when it comes first in the file and loses when it comes
// after. The triangle's id follows the line's.
TEST(LineZBuffer, TiesGoToTheLowerIdInFileOrder) {
    Scene first{{4, 1}, 1, {backdrop(0.125, 0, 0)}, {}};
    // z = x / 8 along the row y = 0.5, as the triangle's plane there.
    first.lines.push_back({segment({0.5, 0.5, 0.0625}, {3.5, 0.5, 0.4375}), 0});
    EXPECT_EQ(triangle_ids(first), (std::vector<std::int32_t>{1}));
    EXPECT_EQ(row(render(first), 0), (std::vector<std::int32_t>{0, 0, 0, 1}));
    Scene after = first;
    after.lines[0].id = 1;
    EXPECT_EQ(row(render(after), 0), (std::vector<std::int32_t>{0, 0, 0, 0}));
}

// With four samples, a lit pixel's samples take the line's one depth, z at the pixel centre's foot: the
// triangle z = x has x = 2.375, 2.875, 2.125, 2.625 at pixel (2, 0)'s samples, so the line at z = 2.5
// takes samples 1 and 3.
TEST(LineZBuffer, EverySampleOfALitPixelTakesTheCentresDepth) {
    Scene scene{{4, 1}, 4, {backdrop(1, 0, 0)}};
    append_line(scene, segment({0.5, 0.5, 0.5}, {3.5, 0.5, 3.5}));
    const Framebuffer fb = render(scene);
    EXPECT_EQ(fb.id(2, 0, 0), 0);
    EXPECT_EQ(fb.id(2, 0, 1), 1);
    EXPECT_EQ(fb.id(2, 0, 2), 0);
    EXPECT_EQ(fb.id(2, 0, 3), 1);
    EXPECT_EQ(fb.depth[fb.index(2, 0, 1)], 2.5);
    EXPECT_EQ(fb.depth[fb.index(2, 0, 0)], 2.375);
}

// Two lines: the nearer at each pixel, and on a tie the lower id. The lines cross at pixel (2, 2) and
// are equal there: (2.5, 2.5) is on both, z = 1 for each.
TEST(LineZBuffer, LinesOrderAmongThemselves) {
    Scene scene{{5, 5}, 1, {}};
    append_line(scene, segment({0.5, 2.5, 2}, {4.5, 2.5, 0}));  // z falls along x
    append_line(scene, segment({2.5, 0.5, 0}, {2.5, 4.5, 2}));  // z rises along y
    const Framebuffer fb = render(scene);
    EXPECT_EQ(fb.id(1, 2), 0);
    EXPECT_EQ(fb.id(2, 2), 0);  // the tie
    EXPECT_EQ(fb.id(3, 2), 0);
    EXPECT_EQ(fb.id(2, 1), 1);
    EXPECT_EQ(fb.id(2, 3), 1);
    Scene swapped{{5, 5}, 1, {}};
    append_line(swapped, scene.lines[1].segment);
    append_line(swapped, scene.lines[0].segment);
    const Framebuffer back = render(swapped);
    EXPECT_EQ(back.id(2, 2), 0);  // now the vertical one's
    EXPECT_EQ(back.id(1, 2), 1);
}

TEST(LineZBuffer, RejectsBadLines) {
    Scene scene{{4, 4}, 1, {backdrop(0, 0, 0)}};
    append_line(scene, segment({0, 0, 0}, {1, std::numeric_limits<double>::infinity(), 0}));
    EXPECT_THROW(render(scene), std::invalid_argument);
    scene.lines[0] = {segment({0, 0, 0}, {1, 1, 0}), 2};
    EXPECT_THROW(render(scene), std::invalid_argument);
}

}  // namespace
}  // namespace rast::reference
