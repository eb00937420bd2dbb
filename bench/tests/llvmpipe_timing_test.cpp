#include "llvmpipe_timing.h"

#include <rast/bench_scenes.h>
#include <rast/reference.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <cerrno>
#include <csignal>
#include <memory>
#include <stdexcept>
#include <string>

namespace rast::bench {
namespace {

// Vertices on llvmpipe's 1/256 grid and a depth band per triangle: its ids must be the reference's.
Scene on_grid_scene() {
    return make_scene({.shape = Shape::small, .triangles = 200, .viewport = {96, 64}, .on_grid_256 = true,
                       .depth = Depth::separated, .seed = 7});
}

TEST(LlvmpipeChild, TimesEachDrawAndReadsBackTheScene) {
    const Scene scene = on_grid_scene();
    LlvmpipeChild llvmpipe(scene, 1);
    for (int k = 0; k < 3; ++k) EXPECT_GT(llvmpipe.draw(), 0);
    EXPECT_EQ(llvmpipe.result().ids, reference::render(scene).ids);
}

TEST(LlvmpipeChild, ChildrenOfTwoThreadCountsEndInEitherOrder) {
    // The first child ends while the second, forked after it, is alive: the second must not hold the
    // first's socket open, or the first would never see its end and this would hang.
    const Scene scene = on_grid_scene();
    auto one = std::make_unique<LlvmpipeChild>(scene, 1);
    LlvmpipeChild two(scene, 2);
    one.reset();
    EXPECT_GT(two.draw(), 0);
    EXPECT_EQ(two.result().ids, reference::render(scene).ids);
}

TEST(LlvmpipeChild, EndsWhenItsSocketTakesDescriptorZero) {
    // With standard input closed, the socket pair is descriptors 0 and 3: the child must close the
    // parent's end below 3 as well, or it never sees that end close and this hangs.
    const int saved = dup(0);
    ASSERT_GE(saved, 0);
    close(0);
    {
        const Scene scene = on_grid_scene();
        LlvmpipeChild llvmpipe(scene, 1);
        EXPECT_GT(llvmpipe.draw(), 0);
    }
    ASSERT_EQ(dup2(saved, 0), 0);
    close(saved);
}

TEST(LlvmpipeChild, ThrowsTheChildsMessage) {
    Scene scene = on_grid_scene();
    scene.samples = 4;  // llvmpipe's load() rejects it in the child
    try {
        LlvmpipeChild llvmpipe(scene, 1);
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_NE(std::string(e.what()).find("1 sample per pixel"), std::string::npos) << e.what();
    }
}

TEST(LlvmpipeChild, AChildThatStopsReplyingIsKilled) {
    LlvmpipeChild llvmpipe(on_grid_scene(), 1, 1);
    const pid_t child = llvmpipe.pid();
    ASSERT_EQ(kill(child, SIGSTOP), 0);  // as a child deadlocked in a draw would
    try {
        llvmpipe.draw();
        FAIL() << "expected std::runtime_error";
    } catch (const std::runtime_error& e) {
        EXPECT_EQ(std::string(e.what()), "llvmpipe timing: no reply from the child process in 1 s");
    }
    // Killed and waited for: the process is gone.
    EXPECT_EQ(kill(child, 0), -1);
    EXPECT_EQ(errno, ESRCH);
}

TEST(TimeLlvmpipeDraws, OneTimePerIteration) {
    const Scene scene = on_grid_scene();
    const LlvmpipeDraws draws = time_llvmpipe_draws(scene, 1, 4);
    ASSERT_EQ(draws.seconds.size(), 4u);
    for (const double s : draws.seconds) EXPECT_GT(s, 0);
    EXPECT_EQ(draws.result.ids, reference::render(scene).ids);
}

}  // namespace
}  // namespace rast::bench
