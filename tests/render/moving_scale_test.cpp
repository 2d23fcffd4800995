// The moving camera's frame scale: down in steps while frames are over budget, back up while
// well under it, within its bounds (no GL).
#include "render/moving_scale.hpp"

#include <gtest/gtest.h>

namespace {

TEST(MovingScale, StepsDownWhileSlowAndBackUpWhileFast) {
    render::MovingScale s(0.75f, 0.5f, 20.0);
    EXPECT_EQ(s.scale(), 0.75f);
    for (int i = 0; i < 3; ++i) s.record(30.0);
    EXPECT_LT(s.scale(), 0.75f);
    for (int i = 0; i < 50; ++i) s.record(60.0);
    EXPECT_EQ(s.scale(), 0.5f) << "never below the floor";
    for (int i = 0; i < 50; ++i) s.record(5.0);
    EXPECT_EQ(s.scale(), 0.75f) << "never above the ceiling";
}

TEST(MovingScale, HoldsStillWithinTheBandAndInWholeSixteenths) {
    render::MovingScale s(0.75f, 0.5f, 20.0);
    s.record(21.0);  // a little over: one step
    s.record(21.0);
    const float reached = s.scale();
    EXPECT_EQ(reached, 0.75f - 1.0f / 16.0f);
    // Frames between 70 % of the budget and the budget: no change, no flicker.
    for (int i = 0; i < 40; ++i) s.record(i % 2 ? 15.0 : 19.0);
    EXPECT_EQ(s.scale(), reached);
}

TEST(MovingScale, ALowestAtTheHighestKeepsItFixed) {
    render::MovingScale s(0.75f, 0.75f, 20.0);
    for (int i = 0; i < 20; ++i) s.record(100.0);
    EXPECT_EQ(s.scale(), 0.75f);
}

}  // namespace
