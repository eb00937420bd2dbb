// Precision names and input validation.
#include <rast/fast.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

namespace rast::fast {
namespace {

TEST(Api, NamesRoundTrip) {
    for (Precision p : {Precision::fixed4, Precision::fixed8, Precision::fixed16, Precision::float32,
                        Precision::float64})
        EXPECT_EQ(parse_precision(name(p)), p);
    EXPECT_EQ(name(Precision::fixed8), "fixed8");
    EXPECT_EQ(name(Precision::float32), "float32");
    EXPECT_EQ(parse_precision("fixed12"), std::nullopt);
    EXPECT_EQ(parse_precision(""), std::nullopt);
}

TEST(Api, RejectsBadInput) {
    Scene scene;
    scene.viewport = {0, 4};
    EXPECT_THROW(render(scene), std::invalid_argument);
    scene.viewport = {4, 4};
    scene.samples = 3;
    EXPECT_THROW(render(scene), std::invalid_argument);
    scene.samples = 1;
    scene.triangles.push_back({{{{0, 0, 0}, {1, 0, 0}, {0, std::nan(""), 0}}}});
    try {
        render(scene);
        FAIL() << "a NaN coordinate was accepted";
    } catch (const std::invalid_argument& e) {
        EXPECT_NE(std::string(e.what()).find("triangle 0, vertex 2"), std::string::npos) << e.what();
    }
    scene.triangles[0].v[2].y = std::numeric_limits<double>::infinity();
    EXPECT_THROW(render(scene), std::invalid_argument);
    scene.triangles[0].v[2].y = 1;
    EXPECT_THROW(render(scene, {Precision::fixed8, -1}), std::invalid_argument);
    EXPECT_NO_THROW(render(scene, {Precision::fixed8, 0}));
}

}  // namespace
}  // namespace rast::fast
