// The generators' scenes do not depend on RapidCheck's size, which it spreads from 0 to max_size over a
// run: drawn at size 0, where inRange and arbitrary integers collapse to their lower end, loose and
// overlapping scenes once lay almost all in the viewport's lower margin and covered no sample.
#include <rast/exact_geometry.h>
#include <rast/property_generators.h>
#include <rast/tri_format.h>

#include <gtest/gtest.h>
#include <rapidcheck.h>

#include <cstdint>
#include <sstream>
#include <string>

namespace {

bool covers_some_sample(const rast::Scene& scene) {
    for (const rast::Triangle& t : scene.triangles)
        for (int j = 0; j < scene.viewport.height; ++j)
            for (int i = 0; i < scene.viewport.width; ++i)
                for (const rast::SamplePoint p : rast::sample_pattern(scene.samples))
                    if (rast::properties::rule_covers(t, i + p.x, j + p.y)) return true;
    return false;
}

// The share of 200 scenes drawn at `size` that cover some sample. At the nominal size, loose scenes
// cover some sample about 88% of the time and overlapping ones 96% (measured over 1010 draws).
double covering_share(const rc::Gen<rast::Scene>& scenes, int size) {
    int covering = 0;
    for (std::uint64_t seed = 1; seed <= 200; ++seed)
        covering += covers_some_sample(scenes(rc::Random(seed), size).value());
    return covering / 200.0;
}

TEST(Generators, ScenesCoverSamplesAtEverySize) {
    for (const int size : {0, 50, 100}) {
        EXPECT_GT(covering_share(rast::gen::loose_triangles(), size), 0.75) << "size " << size;
        EXPECT_GT(covering_share(rast::gen::overlapping_triangles(), size), 0.85) << "size " << size;
    }
}

// A property that fails on any zero-area triangle, over loose scenes of 1 to 7 triangles: the shrunk
// counterexample keeps one triangle, the zero-area one, whatever its place among the others. (Shrinking
// the count alone drops only the last ones: over these seeds it left 2 to 5 triangles.)
TEST(Generators, ShrinkingKeepsOnlyTheTrianglesThatPlayAPart) {
    for (std::uint64_t seed = 1; seed <= 8; ++seed) {
        rc::detail::TestMetadata metadata;
        metadata.id = "Generators/shrinking";
        rc::detail::TestParams params;
        params.seed = seed;
        params.maxSuccess = 2000;
        const auto result = rc::detail::checkTestable(
            [] {
                for (const rast::Triangle& t : (*rast::gen::loose_triangles()).triangles)
                    RC_ASSERT(rast::properties::orientation(t) != 0);
            },
            metadata, params);
        ASSERT_TRUE(result.is<rc::detail::FailureResult>()) << "seed " << seed << ": no zero-area triangle drawn";
        std::string shown;
        for (const auto& [type, value] : result.get<rc::detail::FailureResult>().counterExample) shown += value;
        std::size_t triangles = 0;
        for (std::size_t at = shown.find("\ntri "); at != std::string::npos; at = shown.find("\ntri ", at + 1))
            ++triangles;
        EXPECT_EQ(triangles, 1u) << "seed " << seed << shown;
    }
}

// A failing property shows its scene as .tri text (RapidCheck showed rast::Scene: <???>), which reads back
// as the same scene.
TEST(Generators, AFailingSceneIsShownAsTriText) {
    const rast::Scene scene{{3, 2}, 4, {rast::Triangle{{rast::Vertex{0.5, 0, 1}, {3, 0.25, -2}, {0, 2, 0.1}}}}};
    const std::string shown = rc::toString(scene);
    EXPECT_EQ(shown, "\nviewport 3 2\nsamples 4\ntri  0x1p-1 0x0p+0 0x1p+0  0x1.8p+1 0x1p-2 -0x1p+1  0x0p+0 0x1p+1 "
                     "0x1.999999999999ap-4\n");
    std::istringstream in(shown);
    EXPECT_EQ(rast::read_tri(in, "shown").triangles, scene.triangles);
}

}  // namespace
