// The scene generators produce what bench_scenes.h promises, the same way every time.
#include <rast/bench_scenes.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace rast::bench {
namespace {

double area(const Triangle& t) {
    const Vertex &a = t.v[0], &b = t.v[1], &c = t.v[2];
    return std::abs((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x)) / 2;
}

double distance(const Vertex& a, const Vertex& b) { return std::hypot(a.x - b.x, a.y - b.y); }

double longest_edge(const Triangle& t) {
    return std::max({distance(t.v[0], t.v[1]), distance(t.v[1], t.v[2]), distance(t.v[2], t.v[0])});
}

bool is_multiple_of(double c, double unit) { return std::floor(c / unit) == c / unit; }

TEST(BenchScenes, SameSpecSameSceneOtherSeedOtherScene) {
    const SceneSpec spec{.shape = Shape::small, .triangles = 500, .seed = 7};
    EXPECT_EQ(make_scene(spec).triangles, make_scene(spec).triangles);
    SceneSpec other = spec;
    other.seed = 8;
    EXPECT_NE(make_scene(spec).triangles, make_scene(other).triangles);
}

TEST(BenchScenes, DepthModeDoesNotChangeTheGeometry) {
    const SceneSpec spec{.shape = Shape::needle, .triangles = 100, .depth = Depth::random};
    SceneSpec separated = spec;
    separated.depth = Depth::separated;
    const Scene a = make_scene(spec), b = make_scene(separated);
    ASSERT_EQ(a.triangles.size(), b.triangles.size());
    for (std::size_t k = 0; k < a.triangles.size(); ++k) {
        for (int m = 0; m < 3; ++m) {
            EXPECT_EQ(a.triangles[k].v[m].x, b.triangles[k].v[m].x);
            EXPECT_EQ(a.triangles[k].v[m].y, b.triangles[k].v[m].y);
        }
    }
}

TEST(BenchScenes, RoundShapesFitTheirDiameter) {
    const std::pair<Shape, double> sizes[] = {
        {Shape::tiny, 4}, {Shape::small, 16}, {Shape::medium, 64}, {Shape::large, 256}};
    for (const auto& [shape, across] : sizes) {
        const Scene scene = make_scene({.shape = shape, .triangles = 1000});
        ASSERT_EQ(scene.triangles.size(), 1000u);
        for (const Triangle& t : scene.triangles) {
            EXPECT_LE(longest_edge(t), across) << name(shape);
            EXPECT_GT(area(t), 0) << name(shape);
        }
    }
}

TEST(BenchScenes, NeedlesAreLongAndThin) {
    for (const Triangle& t : make_scene({.shape = Shape::needle, .triangles = 1000}).triangles) {
        const double length = distance(t.v[0], t.v[1]);
        EXPECT_GE(length, 64);
        EXPECT_LE(length, 512);
        const double width = 2 * area(t) / length;  // the apex's distance from the long edge
        EXPECT_GE(width, 0.125 - 1e-9);
        EXPECT_LE(width, 1 + 1e-9);
    }
}

TEST(BenchScenes, HugeTrianglesReachFarBeyondTheViewport) {
    for (const Triangle& t : make_scene({.shape = Shape::huge, .triangles = 1000}).triangles) {
        EXPECT_LE(distance(t.v[0], t.v[1]), std::hypot(8, 8));
        const double far = std::max(std::abs(t.v[2].x), std::abs(t.v[2].y));
        EXPECT_GE(far, 0x1p20 / std::sqrt(2) - 1024);
        EXPECT_LE(far, 0x1p24 + 1024);
    }
}

TEST(BenchScenes, MeshTilesTheViewportExactlyOnce) {
    // 64 x 32 pixels, 64 triangles: cells of sqrt(2 * 64 * 32 / 64) = 8 pixels, 8 x 4 of them.
    const Scene scene = make_scene({.shape = Shape::mesh, .triangles = 64, .viewport = {64, 32}});
    ASSERT_EQ(scene.triangles.size(), 64u);
    double total = 0;
    for (const Triangle& t : scene.triangles) {
        total += area(t);
        for (const Vertex& v : t.v) {
            EXPECT_GE(v.x, 0);
            EXPECT_LE(v.x, 64);
            EXPECT_GE(v.y, 0);
            EXPECT_LE(v.y, 32);
        }
    }
    EXPECT_NEAR(total, 64 * 32, 1e-9);
}

TEST(BenchScenes, FansAreClosedAroundPixelCentres) {
    const Scene scene = make_scene({.shape = Shape::fan, .triangles = 1000});
    EXPECT_LE(scene.triangles.size(), 1000u);
    EXPECT_GT(scene.triangles.size(), 1000u - 8);
    // A fan is a run of triangles around the same centre; its last rim vertex is its first.
    std::size_t first = 0;
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        const Vertex& c = scene.triangles[k].v[0];
        EXPECT_TRUE(is_multiple_of(c.x - 0.5, 1) && is_multiple_of(c.y - 0.5, 1));
        const bool last = k + 1 == scene.triangles.size() || !(scene.triangles[k + 1].v[0].x == c.x &&
                                                               scene.triangles[k + 1].v[0].y == c.y);
        if (!last) {
            EXPECT_EQ(scene.triangles[k].v[2].x, scene.triangles[k + 1].v[1].x);
            continue;
        }
        EXPECT_GE(k + 1 - first, 3u);
        EXPECT_EQ(scene.triangles[k].v[2].x, scene.triangles[first].v[1].x);
        EXPECT_EQ(scene.triangles[k].v[2].y, scene.triangles[first].v[1].y);
        first = k + 1;
    }
}

TEST(BenchScenes, CentreEdgesLieOnTheHalfPixelLattice) {
    for (const Triangle& t : make_scene({.shape = Shape::centre_edges, .triangles = 1000}).triangles) {
        for (const Vertex& v : t.v) EXPECT_TRUE(is_multiple_of(v.x, 0.5) && is_multiple_of(v.y, 0.5));
        EXPECT_LE(longest_edge(t), std::hypot(16, 16));
    }
}

TEST(BenchScenes, SubnormalEdgesRunAlongTheLeftBorder) {
    const SceneSpec spec{.shape = Shape::subnormal, .triangles = 1000, .viewport = {64, 32}};
    for (const Triangle& t : make_scene(spec).triangles) {
        for (int m = 0; m < 2; ++m) {
            EXPECT_EQ(std::fpclassify(t.v[m].x), FP_SUBNORMAL);
            EXPECT_EQ(t.v[m].y, m == 0 ? 0 : 32);
        }
        EXPECT_GE(t.v[2].x, 1);
        EXPECT_LE(t.v[2].x, 8);
    }
}

TEST(BenchScenes, SliversHaveAlmostNoArea) {
    for (const Triangle& t : make_scene({.shape = Shape::sliver, .triangles = 1000}).triangles) {
        const double length = distance(t.v[0], t.v[1]);
        EXPECT_GE(length, 16);
        EXPECT_LE(length, 256);
        // The apex is at most 2^-9 px off the long edge (plus the rounding of the midpoint).
        EXPECT_LE(2 * area(t) / length, 0x1p-9 + 1e-9);
    }
}

TEST(BenchScenes, GridSnapMovesVerticesOntoMultiplesOf1Over256) {
    const SceneSpec spec{.shape = Shape::needle, .triangles = 1000};
    SceneSpec snapped = spec;
    snapped.on_grid_256 = true;
    const Scene a = make_scene(spec), b = make_scene(snapped);
    for (std::size_t k = 0; k < a.triangles.size(); ++k) {
        for (int m = 0; m < 3; ++m) {
            const Vertex &u = a.triangles[k].v[m], &v = b.triangles[k].v[m];
            EXPECT_TRUE(is_multiple_of(v.x, 0x1p-8) && is_multiple_of(v.y, 0x1p-8));
            EXPECT_LE(std::abs(u.x - v.x), 0x1p-9);
            EXPECT_LE(std::abs(u.y - v.y), 0x1p-9);
            EXPECT_EQ(u.z, v.z);
        }
    }
}

TEST(BenchScenes, SeparatedDepthsGiveEachTriangleItsOwnBand) {
    const Scene scene = make_scene({.shape = Shape::small, .triangles = 1000, .depth = Depth::separated});
    std::vector<int> seen(1000, 0);
    for (const Triangle& t : scene.triangles) {
        const double band = std::floor(t.v[0].z);
        for (const Vertex& v : t.v) {
            EXPECT_GE(v.z, band);
            EXPECT_LT(v.z, band + 0.25);
        }
        ASSERT_GE(band, 0);
        ASSERT_LT(band, 1000);
        ++seen[static_cast<std::size_t>(band)];
    }
    EXPECT_EQ(std::count(seen.begin(), seen.end(), 1), 1000);
}

TEST(BenchScenes, NamesRoundTripAndDescribeIsReadable) {
    for (const Shape s : {Shape::tiny, Shape::small, Shape::medium, Shape::large, Shape::needle,
                          Shape::huge, Shape::mesh, Shape::fan, Shape::centre_edges, Shape::subnormal,
                          Shape::sliver}) {
        EXPECT_EQ(parse_shape(name(s)), s);
    }
    EXPECT_EQ(parse_shape("enormous"), std::nullopt);
    EXPECT_EQ(describe({.shape = Shape::small, .triangles = 10000, .on_grid_256 = true,
                        .depth = Depth::separated, .seed = 1}),
              "small/n:10000/1024x1024/grid256/separated/seed:1");
}

TEST(BenchScenes, RejectsAnEmptyViewport) {
    EXPECT_THROW(make_scene({.viewport = {0, 10}}), std::invalid_argument);
}

}  // namespace
}  // namespace rast::bench
