#include "progress_meter.h"

#include <gtest/gtest.h>

#include <sstream>

namespace rast::cli {
namespace {

// A meter on a clock the test sets by hand.
struct Meter {
    explicit Meter(bool terminal) : meter("render", "triangles", out, terminal, [this] { return now; }) {}
    std::ostringstream out;
    double now = 100;
    ProgressMeter meter;
};

TEST(ProgressMeter, AComputationWithinTwoSecondsSaysNothing) {
    Meter m(false);
    m.meter.update(0, 1000);
    m.now = 101.9;
    m.meter.update(512, 1000);
    m.meter.update(1000, 1000);
    EXPECT_EQ(m.out.str(), "");
}

TEST(ProgressMeter, ALogGetsALineEveryTenSecondsAndTheTimeTaken) {
    Meter m(false);
    m.meter.update(0, 1000);
    m.now = 102.5;
    m.meter.update(256, 1000);  // past two seconds: the first line
    m.now = 110;
    m.meter.update(512, 1000);  // 7.5 s after it: not yet
    m.now = 112.5;
    m.meter.update(768, 1000);
    m.now = 113;
    m.meter.update(1000, 1000);
    EXPECT_EQ(m.out.str(),
              "render:  25% (256 of 1000 triangles), 2.5 s\n"
              "render:  76% (768 of 1000 triangles), 12.5 s\n"
              "render: 100% (1000 of 1000 triangles), 13.0 s\n");
}

TEST(ProgressMeter, ATerminalLineIsRewrittenAndEndedOnce) {
    Meter m(true);
    m.meter.update(0, 3);
    m.now = 103;
    m.meter.update(1, 3);
    m.now = 103.1;  // within a quarter second: skipped
    m.meter.update(2, 3);
    m.now = 104;
    m.meter.update(3, 3);
    EXPECT_EQ(m.out.str(),
              "\rrender:  33% (1 of 3 triangles), 3.0 s\x1b[K"
              "\rrender: 100% (3 of 3 triangles), 4.0 s\x1b[K\n");
}

TEST(ProgressMeter, EachComputationStartsItsOwnClock) {
    Meter m(false);
    m.meter.update(0, 10);
    m.now = 105;
    m.meter.update(5, 10);
    m.meter.update(10, 10);
    m.meter.update(0, 10);  // a second render: quiet for its own first two seconds
    m.now = 106;
    m.meter.update(5, 10);
    m.meter.update(10, 10);
    EXPECT_EQ(m.out.str(),
              "render:  50% (5 of 10 triangles), 5.0 s\n"
              "render: 100% (10 of 10 triangles), 5.0 s\n");
}

TEST(ProgressMeter, AnUnfinishedTerminalLineIsEndedWhenTheMeterGoes) {
    std::ostringstream out;
    double now = 0;
    {
        ProgressMeter meter("render", "triangles", out, true, [&] { return now; });
        meter.update(0, 4);
        now = 3;
        meter.update(2, 4);
    }
    EXPECT_EQ(out.str(), "\rrender:  50% (2 of 4 triangles), 3.0 s\x1b[K\n");
}

}  // namespace
}  // namespace rast::cli
