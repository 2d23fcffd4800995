// The shot model's heading σ follows the cue: the noise model's heading σ combined with the squirt
// that its side-offset σ causes with the session's cue (physics::Params::cue_endmass).
#include <gtest/gtest.h>

#include <cmath>

#include "ai/internal/ghost_ball.hpp"
#include "game/stroke_noise.hpp"
#include "physics/cue_strike.hpp"

namespace {

physics::Params with_end_mass(double kg) {
    physics::Params p;
    p.cue_endmass = kg;
    return p;
}

TEST(HeadingSigma, OfTheDefaultCueIsTheDocumentedValue) {
    EXPECT_NEAR(ai::heading_sigma_deg(physics::Params{}), 0.210, 0.001);
}

TEST(HeadingSigma, WithoutSquirtIsTheNoiseModels) {
    EXPECT_NEAR(ai::heading_sigma_deg(with_end_mass(1e-9)), game::StrokeNoise{}.heading_deg, 1e-6);
}

// The squirt part is what the strike gives a side offset of one σ, for light and heavy cues.
TEST(HeadingSigma, TheSquirtPartIsTheStrikesSquirtAtOneSigmaOfSideOffset) {
    const game::StrokeNoise sigma;
    double previous = 0.0;
    for (double kg : {0.005, 0.015, 0.03}) {
        const physics::Params p = with_end_mass(kg);
        physics::Stroke st;
        st.speed = 2.0;
        st.side = sigma.offset;
        const double squirt_deg = physics::strike(p, st).squirt_deg;
        const double expected = std::hypot(sigma.heading_deg, squirt_deg);
        EXPECT_NEAR(ai::heading_sigma_deg(p), expected, 1e-4 * expected) << kg << " kg";
        EXPECT_GT(ai::heading_sigma_deg(p), previous) << kg << " kg";
        previous = ai::heading_sigma_deg(p);
    }
}

}  // namespace
