// The balls' rumble on the cloth: the pure levels (rolling_at) and, through the loopback
// device, an energy envelope that follows the ball's speed and dies when it stops.
#include "audio/rolling.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "render_support.hpp"

namespace audio {
namespace {

/// The cue ball alone, struck down the table at `ball_speed` (unit: m/s): it slides, rolls
/// and stops without reaching a cushion.
physics::Shot lone_roll(double ball_speed = 0.6) {
    const physics::Params p;
    physics::BallState cue;
    cue.pos = {0.3, 0.635};
    physics::Stroke k;
    k.speed = physics::cue_speed_for_ball_speed(p, ball_speed);
    k.heading_deg = 0.0;
    const std::vector<physics::BallState> balls{cue};
    return physics::simulate(physics::build_table(physics::TableSpec{}), p, balls, &k);
}

double speed_at(const physics::Shot& shot, double t) {
    return physics::norm(shot.state_at(0, t).vel);
}

}  // namespace

TEST(Rolling, GainFollowsSpeedAndStopsWithTheBall) {
    const physics::Shot shot = lone_roll();
    ASSERT_TRUE(shot.rest_time().has_value());
    const double rest = *shot.rest_time();
    const RollOptions o;
    EXPECT_EQ(rolling_at(shot, -0.1, o)[0].gain, 0.0f);  // before the strike
    float last = 2.0f;
    for (double t = 0.5; t < rest; t += 0.25) {
        const Roll r = rolling_at(shot, t, o)[0];
        const physics::BallState b = shot.state_at(0, t);
        ASSERT_EQ(b.motion, physics::Motion::rolling) << t;
        EXPECT_FLOAT_EQ(r.gain, loudness(speed_at(shot, t), o.full, 1.0)) << t;
        EXPECT_LT(r.gain, last) << "slowing down, quieter";
        EXPECT_NEAR(r.position.x, b.pos.x, 1e-12);
        last = r.gain;
    }
    // A sliding ball (just after the strike) scrubs louder than rolling at its speed.
    const double slide_t = 0.01;
    ASSERT_EQ(shot.state_at(0, slide_t).motion, physics::Motion::sliding);
    EXPECT_FLOAT_EQ(rolling_at(shot, slide_t, o)[0].gain,
                    loudness(speed_at(shot, slide_t), o.full, 1.0) * float(o.sliding));
    EXPECT_EQ(rolling_at(shot, rest + 0.01, o)[0].gain, 0.0f);
    RollOptions off = o;
    off.enabled = false;
    EXPECT_EQ(rolling_at(shot, 0.5, off)[0].gain, 0.0f);
}

TEST(Rolling, ThePocketedBallFallsSilent) {
    const physics::Shot shot = test::scene_shot("cut");
    const auto drop = std::find_if(shot.events().begin(), shot.events().end(), [](const auto& e) {
        return e.type == physics::EventType::pocket;
    });
    ASSERT_NE(drop, shot.events().end());
    const int ball = drop->ball(0);
    const std::size_t i = *shot.index_of(ball);
    EXPECT_GT(rolling_at(shot, drop->time - 0.01)[i].gain, 0.0f);
    EXPECT_EQ(rolling_at(shot, drop->time + 0.01)[i].gain, 0.0f);
}

// Loopback: with distance attenuation off, the rumble's RMS in 0.25 s windows follows the
// ball's speed (correlation over 0.98), in proportion (RMS per m/s the same, within 15 %, in
// the first and the last third of the roll), and silence follows the stop.
TEST(Rolling, LoopbackEnergyEnvelopeFollowsTheBallsSpeed) {
    const physics::Shot shot = lone_roll();
    const double rest = *shot.rest_time();
    EngineOptions eo;
    eo.rolloff = 0.0;
    Engine e = Engine::loopback(test::kRate, eo);
    ASSERT_TRUE(e.active());
    const test::Stereo s = test::render_shot(e, shot, rest + 0.5);
    std::vector<double> rms, speed;
    const double window = 0.25;
    for (double t = 0.2; t + window < rest - 0.3; t += window) {
        double sum = 0.0;
        const auto a = static_cast<std::size_t>(t * test::kRate);
        const auto b = static_cast<std::size_t>((t + window) * test::kRate);
        for (std::size_t i = a; i < b; ++i) sum += double(s.left(i)) * s.left(i);
        rms.push_back(std::sqrt(sum / double(b - a)));
        speed.push_back(speed_at(shot, t + 0.5 * window));
    }
    ASSERT_GE(rms.size(), 9u);
    const auto mean = [](const std::vector<double>& v, std::size_t a, std::size_t b) {
        double m = 0.0;
        for (std::size_t i = a; i < b; ++i) m += v[i];
        return m / double(b - a);
    };
    const std::size_t n = rms.size(), third = n / 3;
    const double mr = mean(rms, 0, n), ms = mean(speed, 0, n);
    double sxy = 0.0, sxx = 0.0, syy = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
        sxy += (rms[i] - mr) * (speed[i] - ms);
        sxx += (rms[i] - mr) * (rms[i] - mr);
        syy += (speed[i] - ms) * (speed[i] - ms);
    }
    const double correlation = sxy / std::sqrt(sxx * syy);
    const double early = mean(rms, 0, third) / mean(speed, 0, third);
    const double late = mean(rms, n - third, n) / mean(speed, n - third, n);
    std::printf(
        "rumble: %zu windows, RMS %.4g at %.2f m/s to %.4g at %.2f m/s; correlation "
        "%.4f; RMS per m/s %.4g early, %.4g late\n",
        n, rms.front(), speed.front(), rms.back(), speed.back(), correlation, early, late);
    EXPECT_GT(correlation, 0.98);
    EXPECT_NEAR(late / early, 1.0, 0.15);
    EXPECT_LT(test::peak_between(s, rest + 0.05, rest + 0.5), 1e-6f) << "silent once stopped";
}

}  // namespace audio
