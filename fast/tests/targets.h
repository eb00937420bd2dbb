// Test helper: a test body run on every SIMD target Highway dispatches to on this machine.
#pragma once

#include <gtest/gtest.h>
#include <hwy/targets.h>

#include <cstdint>

namespace rast::fast::testing {

// Calls body() with Highway's dynamic dispatch pinned to each target this build generated and this machine
// runs, the target named in every failure, and stops at a fatal one. However the body ends, the tests after
// it dispatch as usual again: a target left pinned made later tests fail for no fault of their own.
template <class Body>
void on_every_target(Body&& body) {
    struct Unpin {
        ~Unpin() { hwy::SetSupportedTargetsForTest(0); }
    } unpin;
    for (const std::int64_t target : hwy::SupportedAndGeneratedTargets()) {
        hwy::SetSupportedTargetsForTest(target);
        SCOPED_TRACE(hwy::TargetName(target));
        body();
        if (::testing::Test::HasFatalFailure()) return;
    }
}

}  // namespace rast::fast::testing
