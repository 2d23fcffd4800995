// From a shot's events to cues, and their schedule (no OpenAL).
#include "audio/cues.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "render_support.hpp"

namespace audio {
namespace {

using physics::EventType;

bool audible_type(EventType t) {
    return t == EventType::strike || t == EventType::miscue || t == EventType::ball_ball ||
           t == EventType::cushion || t == EventType::pocket;
}

}  // namespace

TEST(Cues, OnePerCollisionStrikeAndPocketAtItsTime) {
    const physics::Shot shot = test::scene_shot("cut");
    const std::vector<Cue> all = cues_for_shot(shot);
    // The ball's run to the return is heard later; every other cue is an event's.
    std::vector<Cue> cues;
    for (const Cue& c : all)
        if (c.kind != SoundKind::ball_return) cues.push_back(c);
    std::size_t audible = 0;
    for (const auto& e : shot.events()) audible += audible_type(e.type);
    ASSERT_EQ(cues.size(), audible);
    ASSERT_EQ(all.size(), audible + 1);  // one ball potted
    const SoundKind want[] = {SoundKind::cue_strike, SoundKind::ball_click, SoundKind::pocket_drop,
                              SoundKind::cushion_thump};
    ASSERT_EQ(cues.size(), 4u);
    for (std::size_t i = 0; i < cues.size(); ++i) {
        const physics::Event& e = shot.events()[cues[i].event];
        EXPECT_EQ(cues[i].time, e.time);
        EXPECT_EQ(cues[i].kind, want[i]) << i;
        EXPECT_GT(cues[i].gain, 0.0f);
        EXPECT_NEAR(cues[i].position.x, e.balls[0].pos.x, 0.06);
        EXPECT_NEAR(cues[i].position.y, e.balls[0].pos.y, 0.06);
    }
    // The pocket's speed is the ball's speed as it fell (its state after the event is at rest).
    EXPECT_GT(cues[2].speed, 0.1);
    for (std::size_t i = 1; i < all.size(); ++i) EXPECT_LE(all[i - 1].time, all[i].time) << i;
}

TEST(Cues, APottedBallRunsToTheReturnAfterItsDrop) {
    const physics::Shot shot = test::scene_shot("cut");
    const CueOptions o;
    const std::vector<Cue> cues = cues_for_shot(shot, o);
    const auto drop = std::find_if(cues.begin(), cues.end(),
                                   [](const Cue& c) { return c.kind == SoundKind::pocket_drop; });
    const auto run = std::find_if(cues.begin(), cues.end(),
                                  [](const Cue& c) { return c.kind == SoundKind::ball_return; });
    ASSERT_NE(drop, cues.end());
    ASSERT_NE(run, cues.end());
    EXPECT_EQ(run->event, drop->event);
    // The drop's own position to the return's, at the channel's speed, after the settling.
    const double d =
        std::hypot(o.ball_return.x - drop->position.x, o.ball_return.y - drop->position.y);
    EXPECT_DOUBLE_EQ(run->time, drop->time + o.return_settle + d / o.return_speed);
    EXPECT_GT(run->time - drop->time, 0.5);
    EXPECT_LT(run->time - drop->time, 3.0);
    EXPECT_EQ(run->position, o.ball_return);
    EXPECT_EQ(run->gain, o.return_gain);
}

TEST(Cues, JawCushionEventsRattle) {
    physics::Params p;
    physics::BallState b;
    b.pos = {2.4, 1.2};
    b.vel = {1.0, 0.0};
    b.motion = physics::Motion::rolling;
    physics::Event jaw;
    jaw.time = 0.1;
    jaw.type = EventType::cushion;
    jaw.speed = 1.0;
    jaw.pocket = 5;
    jaw.balls[0].pos = b.pos;
    physics::Event rail = jaw;
    rail.time = 0.2;
    rail.pocket = -1;
    rail.rail = 1;
    const physics::Shot shot(p, {jaw, rail}, {{physics::Segment{0.0, b}}}, false);
    const auto cues = cues_for_shot(shot);
    ASSERT_EQ(cues.size(), 2u);
    EXPECT_EQ(cues[0].kind, SoundKind::jaw_rattle);
    EXPECT_EQ(cues[1].kind, SoundKind::cushion_thump);
}

TEST(Cues, LoudnessFollowsSpeed) {
    const CueOptions o;
    EXPECT_LT(loudness(0.05, o.ball_ball_full, 1.0), 0.01f);  // a kiss: below −40 dB
    EXPECT_EQ(loudness(9.0, o.ball_ball_full, 1.0), 1.0f);    // a break: full
    EXPECT_EQ(loudness(0.0, o.ball_ball_full, 1.0), 0.0f);
    float last = 0.0f;
    for (double v = 0.1; v < 6.0; v += 0.1) {
        const float g = loudness(v, o.ball_ball_full, 1.0);
        EXPECT_GT(g, last);
        last = g;
    }
    // Faster impacts also sound a little higher.
    const physics::Shot slow = test::scene_shot("cut", 0.8), fast = test::scene_shot("cut", 3.0);
    const auto click = [](const std::vector<Cue>& cues) {
        for (const Cue& c : cues)
            if (c.kind == SoundKind::ball_click) return c;
        return Cue{};
    };
    CueOptions flat;
    flat.pitch_jitter = 0.0;
    const Cue a = click(cues_for_shot(slow, flat)), b = click(cues_for_shot(fast, flat));
    EXPECT_GT(b.gain, a.gain);
    EXPECT_GT(b.pitch, a.pitch);
}

TEST(Cues, RepeatedHitsVaryAndTheDrawIsSeeded) {
    const physics::Shot shot = test::scene_shot("break");
    const auto cues = cues_for_shot(shot);
    const auto again = cues_for_shot(shot);
    ASSERT_EQ(cues.size(), again.size());
    int last[kSoundKindCount] = {-1, -1, -1, -1, -1};
    for (std::size_t i = 0; i < cues.size(); ++i) {
        EXPECT_EQ(cues[i].variant, again[i].variant);
        EXPECT_EQ(cues[i].pitch, again[i].pitch);
        int& l = last[static_cast<int>(cues[i].kind)];
        EXPECT_NE(cues[i].variant, l) << "two " << to_string(cues[i].kind) << " in a row";
        l = cues[i].variant;
    }
}

TEST(CueSchedule, HandsOutEachCueOnceAndStartsOverOnRewind) {
    std::vector<Cue> cues(3);
    cues[0].time = 0.0;
    cues[1].time = 0.5;
    cues[2].time = 1.0;
    CueSchedule s(cues);
    EXPECT_EQ(s.due(0.0).size(), 1u);
    EXPECT_EQ(s.due(0.4).size(), 0u);
    EXPECT_EQ(s.due(0.5).size(), 1u);
    EXPECT_EQ(s.due(2.0).size(), 1u);
    EXPECT_TRUE(s.finished());
    EXPECT_EQ(s.due(0.2).size(), 0u);  // rewound to 0.2: the cue at 0.5 comes again
    const auto d = s.due(0.7);
    ASSERT_EQ(d.size(), 1u);
    EXPECT_EQ(d[0].time, 0.5);
}

}  // namespace audio
