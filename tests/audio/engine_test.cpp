// The engine through OpenAL Soft's loopback device (ALC_SOFT_loopback): real mixing, rendered
// into memory, so these run on machines with no sound card.
#include <gtest/gtest.h>

#include <cstdio>

#include "audio/wav.hpp"
#include "render_support.hpp"

namespace audio::test {
namespace {

/// Cue times, with cues closer than `merge` to the previous one joined: the ear (and the
/// onset detector) hears them as one.
std::vector<double> expected_onsets(const std::vector<Cue>& cues, double merge = 0.025) {
    std::vector<double> times;
    for (const Cue& c : cues)
        if (times.empty() || c.time - times.back() >= merge) times.push_back(c.time);
    return times;
}

Cue cue_at(SoundKind kind, physics::Vec3 where, float gain = 0.5f) {
    Cue c;
    c.kind = kind;
    c.gain = gain;
    c.position = where;
    return c;
}

/// The sounds made of several knocks (a drop rattling in the pocket, a run down the return):
/// the onsets after their first, within their length, are theirs.
double knocks_for(SoundKind kind) {
    return kind == SoundKind::pocket_drop ? 0.5 : kind == SoundKind::ball_return ? 1.0 : 0.0;
}

/// Every cue has an onset within 5 ms of its time, and every onset is a cue's or one of the
/// later knocks of a rattling sound.
void expect_onsets_match(const std::vector<Cue>& cues, const std::vector<double>& got) {
    const std::vector<double> want = expected_onsets(cues);
    for (double w : want) {
        const auto near = std::find_if(got.begin(), got.end(),
                                       [&](double g) { return std::abs(g - w) <= 0.005; });
        EXPECT_NE(near, got.end()) << "no onset at the cue at " << w << " s";
        if (near != got.end())
            std::printf("cue %.4f s  onset %.4f s  (%+.2f ms)\n", w, *near, 1e3 * (*near - w));
    }
    for (double g : got) {
        const bool ok = std::any_of(cues.begin(), cues.end(), [&](const Cue& c) {
            return std::abs(g - c.time) <= 0.005 || (g > c.time && g < c.time + knocks_for(c.kind));
        });
        EXPECT_TRUE(ok) << "an onset at " << g << " s belongs to no cue";
    }
}

double last_cue_time(const Engine& e) {
    return e.cues().empty() ? 0.0 : e.cues().back().time;
}

}  // namespace

TEST(Engine, LoopbackOpens) {
    Engine e = Engine::loopback(kRate);
    ASSERT_TRUE(e.active()) << "OpenAL Soft's loopback device (ALC_SOFT_loopback) is needed";
}

TEST(Engine, CutShotHasOneOnsetPerEventWithin5ms) {
    const physics::Shot shot = scene_shot("cut");
    Engine e = Engine::loopback(kRate);
    ASSERT_TRUE(e.active());
    e.start(shot);
    const Stereo s = render_shot(e, shot, last_cue_time(e) + 1.2);
    const std::string wav = output_path("audio_cut_shot.wav");
    EXPECT_TRUE(write_wav(wav, s.samples, 2, kRate)) << wav;
    std::printf("rendered the cut shot to %s\n", wav.c_str());

    // The cut: strike, ball–ball, the object ball drops, the cue ball meets a rail, and the
    // potted ball reaches the return.
    ASSERT_EQ(e.cues().size(), 5u);
    expect_onsets_match(e.cues(), onsets(s));
}

TEST(Engine, ThePocketSoundFollowsItsEventAndTheReturnComesAfter) {
    const physics::Shot shot = scene_shot("cut");
    Engine e = Engine::loopback(kRate);
    e.start(shot);
    const Stereo s = render_shot(e, shot, last_cue_time(e) + 1.2);
    const auto& cues = e.cues();
    const auto of = [&](SoundKind k) {
        return std::find_if(cues.begin(), cues.end(), [k](const Cue& c) { return c.kind == k; });
    };
    ASSERT_NE(of(SoundKind::pocket_drop), cues.end());
    ASSERT_NE(of(SoundKind::ball_return), cues.end());
    const double drop = of(SoundKind::pocket_drop)->time, run = of(SoundKind::ball_return)->time;
    const std::vector<double> got = onsets(s);
    const auto onset_near = [&](double t) {
        return std::any_of(got.begin(), got.end(),
                           [t](double g) { return std::abs(g - t) < 0.005; });
    };
    EXPECT_TRUE(onset_near(drop));
    EXPECT_TRUE(onset_near(run));
    EXPECT_GT(run, drop + 0.5);
    // Between the rattle's end and the run, only the cue ball's cushion and rumble: quieter
    // than the run itself.
    const float run_peak = peak_between(s, run, run + 0.8);
    std::printf("drop at %.3f s (peak %.4f), return at %.3f s (peak %.4f)\n", drop,
                peak_between(s, drop, drop + 0.5), run, run_peak);
    EXPECT_GT(run_peak, 0.005f);
}

TEST(Engine, BankShotHasOneOnsetPerEventWithin5ms) {
    const physics::Shot shot = scene_shot("bank");
    Engine e = Engine::loopback(kRate);
    ASSERT_TRUE(e.active());
    e.start(shot);
    const Stereo s = render_shot(e, shot, last_cue_time(e) + 1.2);
    ASSERT_GE(expected_onsets(e.cues()).size(), 4u);
    expect_onsets_match(e.cues(), onsets(s));
}

TEST(Engine, FasterImpactIsLouder) {
    float peak[2] = {};
    const double speeds[2] = {0.8, 3.0};  // cue-ball speed (unit: m/s)
    for (int k = 0; k < 2; ++k) {
        const physics::Shot shot = scene_shot("cut", speeds[k]);
        Engine e = Engine::loopback(kRate);
        const Stereo s = render_shot(e, shot, 3.0);
        const auto& cues = e.cues();
        const auto click = std::find_if(
            cues.begin(), cues.end(), [](const Cue& c) { return c.kind == SoundKind::ball_click; });
        ASSERT_NE(click, cues.end());
        peak[k] = peak_between(s, click->time, click->time + 0.02);
    }
    std::printf("ball-ball click peak: %.4f (slow) %.4f (fast)\n", peak[0], peak[1]);
    EXPECT_GT(peak[0], 0.0f);
    EXPECT_GT(peak[1], 2.0f * peak[0]);
}

TEST(Engine, SoftKissIsBarelyAudibleAndABreakIsLoud) {
    Engine e = Engine::loopback(kRate);
    const physics::Vec3 centre{1.27, 0.635, 0.028575};
    CueOptions o;
    Cue kiss = cue_at(SoundKind::ball_click, centre, loudness(0.05, o.ball_ball_full, 1.0));
    e.play(kiss);
    const float soft = peak_between(render_for(e, 0.05), 0.0, 0.05);
    Cue brk = cue_at(SoundKind::ball_click, centre, loudness(9.0, o.ball_ball_full, 1.0));
    e.play(brk);
    const float loud = peak_between(render_for(e, 0.05), 0.0, 0.05);
    std::printf("kiss peak %.5f (%.1f dBFS), break peak %.4f (%.1f dBFS)\n", soft,
                20 * std::log10(soft), loud, 20 * std::log10(loud));
    EXPECT_LT(20 * std::log10(soft / loud), -35.0);
    EXPECT_GT(loud, 0.25f);
}

TEST(Engine, PansTowardTheSideOfTheEvent) {
    // The default listener stands behind the head rail looking down the table (+x): north
    // (+y) is on its left, south on its right.
    const double left_right[2] = {1.20, 0.07};
    std::pair<double, double> energy[2];
    for (int k = 0; k < 2; ++k) {
        Engine e = Engine::loopback(kRate);
        e.play(cue_at(SoundKind::cushion_thump, {1.27, left_right[k], 0.03}));
        energy[k] = channel_energy(render_for(e, 0.3));
    }
    std::printf("north event: L %.4g R %.4g; south event: L %.4g R %.4g\n", energy[0].first,
                energy[0].second, energy[1].first, energy[1].second);
    EXPECT_GT(energy[0].first, 2.0 * energy[0].second);
    EXPECT_GT(energy[1].second, 2.0 * energy[1].first);
}

TEST(Engine, ListenerOrientationDecidesTheSide) {
    // Turned round (looking −x from the foot end), north is on the right.
    Engine e = Engine::loopback(kRate);
    Listener l;
    l.position = {3.1, 0.635, 1.2};
    l.forward = {-1.0, 0.0, -0.6};
    e.set_listener(l);
    e.play(cue_at(SoundKind::ball_click, {1.27, 1.2, 0.03}));
    const auto [left, right] = channel_energy(render_for(e, 0.1));
    EXPECT_GT(right, 2.0 * left);
}

TEST(Engine, MutedIsSilent) {
    const physics::Shot shot = scene_shot("cut");
    Engine e = Engine::loopback(kRate);
    e.set_muted(true);
    EXPECT_TRUE(e.muted());
    const Stereo s = render_shot(e, shot, 2.5);
    EXPECT_EQ(peak_between(s, 0.0, 2.5), 0.0f);
}

TEST(Engine, MuteCutsASoundAtOnceAndUnmuteRestores) {
    Engine e = Engine::loopback(kRate);
    e.play(cue_at(SoundKind::pocket_drop, {1.27, 0.635, 0.03}, 1.0f));
    const Stereo before = render_for(e, 0.05);
    EXPECT_GT(peak_between(before, 0.0, 0.05), 0.01f);
    e.set_muted(true);
    const Stereo after = render_for(e, 0.5);
    // OpenAL Soft may fade out over its first mix update; nothing after 5 ms.
    EXPECT_EQ(peak_between(after, 0.005, 0.5), 0.0f);
    e.play(cue_at(SoundKind::ball_click, {1.27, 0.635, 0.03}));  // ignored while muted
    EXPECT_EQ(peak_between(render_for(e, 0.05), 0.0, 0.05), 0.0f);
    e.set_muted(false);
    e.play(cue_at(SoundKind::ball_click, {1.27, 0.635, 0.03}));
    EXPECT_GT(peak_between(render_for(e, 0.05), 0.0, 0.05), 0.01f);
}

TEST(Engine, UnmutingDoesNotReplayCuesThatFellDueWhileMuted) {
    const physics::Shot shot = scene_shot("cut");
    EngineOptions o;
    o.rolling.enabled = false;  // the cues only: a rolling ball is heard again, rightly
    Engine e = Engine::loopback(kRate, o);
    e.start(shot);
    e.set_muted(true);
    e.update(1.0);  // strike, ball–ball and pocket fall due, muted
    e.set_muted(false);
    e.update(1.0);
    EXPECT_EQ(peak_between(render_for(e, 0.1), 0.0, 0.1), 0.0f);
    e.update(1.3);  // the cushion
    EXPECT_GT(peak_between(render_for(e, 0.1), 0.0, 0.1), 0.0f);
}

TEST(Engine, AfterThePlaybackEndsTheReturnStillComesUnlessTheShotWasSkipped) {
    const physics::Shot shot = scene_shot("cut");
    const double end = *shot.rest_time();
    EngineOptions o;
    o.cues.return_settle = 3.0;  // a long way round to the return: it comes after the end
    Engine e = Engine::loopback(kRate, o);
    e.start(shot);
    const double run = last_cue_time(e);
    ASSERT_EQ(e.cues().back().kind, SoundKind::ball_return);
    ASSERT_GT(run, end) << "the return is heard after the balls stop";
    Stereo s;
    s.samples.assign(static_cast<std::size_t>((run + 0.5) * kRate) * 2, 0.0f);
    // The playback's clock runs to its end, then the app's frames advance the sound's.
    for (std::size_t f = 0; f < s.frames(); f += kChunk) {
        const double t = double(f) / kRate;
        if (t < end)
            e.update(t);
        else
            e.advance(double(kChunk) / kRate);
        e.render({s.samples.data() + 2 * f, 2 * std::min<std::size_t>(kChunk, s.frames() - f)});
    }
    EXPECT_FALSE(e.pending());
    const std::vector<double> got = onsets(s);
    EXPECT_TRUE(
        std::any_of(got.begin(), got.end(), [&](double g) { return std::abs(g - run) < 0.005; }));

    // Skipped to its end from 0.1 s: nothing more comes.
    e.start(shot);
    e.update(0.1);
    EXPECT_TRUE(e.pending());
    e.advance(0.03);
    EXPECT_FALSE(e.pending());
    render_for(e, 0.05);
    EXPECT_EQ(peak_between(render_for(e, 0.5), 0.0, 0.5), 0.0f);
}

TEST(Engine, RendersAreDeterministic) {
    const physics::Shot shot = scene_shot("cut");
    Engine a = Engine::loopback(kRate);
    Engine b = Engine::loopback(kRate);
    const Stereo sa = render_shot(a, shot, 1.5);
    const Stereo sb = render_shot(b, shot, 1.5);
    EXPECT_EQ(sa.samples, sb.samples);
}

TEST(Engine, NoDeviceRunsSilentWithOneLineOnStderr) {
    EngineOptions o;
    o.device = "coolaaber: no such audio device";
    testing::internal::CaptureStderr();
    Engine e(o);
    const std::string err = testing::internal::GetCapturedStderr();
    EXPECT_FALSE(e.active());
    EXPECT_EQ(std::count(err.begin(), err.end(), '\n'), 1) << err;
    EXPECT_NE(err.find("running silent"), std::string::npos) << err;

    // Every call is a no-op and quiet.
    testing::internal::CaptureStderr();
    e.set_listener({});
    e.set_muted(true);
    e.set_muted(false);
    e.start(scene_shot("cut"));
    e.update(0.5);
    e.play(cue_at(SoundKind::ball_click, {}));
    e.stop();
    std::vector<float> buffer(96, 1.0f);
    e.render(buffer);
    EXPECT_EQ(testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(*std::max_element(buffer.begin(), buffer.end()), 0.0f);
    EXPECT_EQ(e.cues().size(), 5u);  // the cues are still made: only the device is missing
}

}  // namespace audio::test
