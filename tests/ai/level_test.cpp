// The levels' table (level.cpp): what must hold between its entries, whatever their values.
// The search grows with the level, each game's own knobs are off in the other game, every entry
// searches something, and levels out of range are clamped to 1–5. How the entries differ between
// the games and at the end of a rack: rack_end_test.cpp.
#include "ai/internal/level.hpp"

#include <gtest/gtest.h>

#include <array>
#include <string>
#include <vector>

namespace {

using rules::Game;

struct Where {
    Game game;
    bool rack_end;
};
constexpr std::array<Where, 3> everywhere{
    {{Game::eight_ball, false}, {Game::eight_ball, true}, {Game::nine_ball, false}}};

// The knobs that count work: a level above never does less of any.
std::vector<int> counts(const ai::Effort& e) {
    return {e.pot_pairs,  e.speeds,         e.spins,         e.safety_speeds,  e.safety_contacts,
            e.placements, e.sweep_headings, e.centred_kicks, e.break_samples,  e.shortlist,
            e.samples,    e.finalists,      e.polish,        e.deep_finalists, e.deep_samples};
}

TEST(Levels, SearchMoreAndStrokeBetterWithTheLevel) {
    for (const Where& w : everywhere)
        for (int level = ai::min_level; level < ai::max_level; ++level) {
            const std::vector<int> low = counts(ai::effort_for(w.game, level, w.rack_end));
            const std::vector<int> high = counts(ai::effort_for(w.game, level + 1, w.rack_end));
            for (std::size_t k = 0; k < low.size(); ++k)
                EXPECT_LE(low[k], high[k]) << "level " << level << ", knob " << k;
            EXPECT_NE(low, high) << "level " << level;
            EXPECT_GT(ai::noise_multiplier(level), ai::noise_multiplier(level + 1));
        }
    EXPECT_EQ(ai::noise_multiplier(ai::max_level), 1.0);
}

TEST(Levels, EachGamesOwnKnobsAreOffInTheOtherGame) {
    for (int level = ai::min_level; level <= ai::max_level; ++level) {
        const ai::Effort nine = ai::effort_for(Game::nine_ball, level);
        EXPECT_EQ(nine.distinct_leaves, 0.0) << "level " << level;
        EXPECT_EQ(nine.stuck_ball_cost, 0.0) << "level " << level;
        EXPECT_EQ(nine.finalist_rounds, 1) << "level " << level;
        for (bool rack_end : {false, true}) {
            const ai::Effort eight = ai::effort_for(Game::eight_ball, level, rack_end);
            EXPECT_EQ(eight.combinations, 0) << "level " << level;
            EXPECT_FALSE(eight.tuned_breaks) << "level " << level;
            EXPECT_FALSE(eight.fresh_deep_draws) << "level " << level;
            EXPECT_EQ(eight.deep_halvings, 0) << "level " << level;
        }
    }
}

TEST(Levels, EveryEntrySearchesTheStepsItHas) {
    for (const Where& w : everywhere)
        for (int level = ai::min_level; level <= ai::max_level; ++level) {
            const ai::Effort e = ai::effort_for(w.game, level, w.rack_end);
            const std::string at = "level " + std::to_string(level);
            for (int n : {e.pot_pairs, e.speeds, e.spins, e.refine_steps, e.safety_speeds,
                          e.safety_contacts, e.placements, e.sweep_headings, e.break_samples,
                          e.shortlist, e.samples, e.finalists, e.finalist_rounds, e.playout_shots})
                EXPECT_GT(n, 0) << at;
            EXPECT_LE(e.finalists, e.shortlist) << at;
            // The deep finalists come from the finalists and the polished pots' variants (up to 6
            // each: candidates.hpp's pot_variants).
            EXPECT_LE(e.deep_finalists, e.finalists + 6 * e.polish) << at;
            if (e.deep_finalists > 0) {  // the second ply has strokes to play
                EXPECT_GT(e.deep_samples, 0) << at;
                EXPECT_GT(e.next_pairs * e.next_speeds * e.next_spins, 0) << at;
            }
            // The raised cue, the centred pots and the model's σ go together: the engine pots
            // raised, centred strokes as the model does at that σ (model_sigma_test.cpp).
            EXPECT_EQ(e.max_raise_deg > 0.0, e.centred_pots) << at;
            EXPECT_EQ(e.model_sigma_deg > 0.0, e.centred_pots) << at;
        }
}

TEST(Levels, OutOfRangeAreClampedToOneToFive) {
    for (const Where& w : everywhere) {
        EXPECT_EQ(ai::effort_for(w.game, 0, w.rack_end), ai::effort_for(w.game, 1, w.rack_end));
        EXPECT_EQ(ai::effort_for(w.game, -3, w.rack_end), ai::effort_for(w.game, 1, w.rack_end));
        EXPECT_EQ(ai::effort_for(w.game, 9, w.rack_end), ai::effort_for(w.game, 5, w.rack_end));
    }
    EXPECT_EQ(ai::noise_multiplier(0), ai::noise_multiplier(1));
    EXPECT_EQ(ai::noise_multiplier(9), ai::noise_multiplier(5));
}

}  // namespace
