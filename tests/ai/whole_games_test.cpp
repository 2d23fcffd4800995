// Every decision is legal: whole games of the AI against the random player, through
// game::play_game (a decision the session refuses throws game::Refused and fails the test), and
// reproducible from the seeds.
#include <gtest/gtest.h>

#include "ai/ai.hpp"
#include "game/autoplay.hpp"
#include "game/random_player.hpp"
#include "game/session.hpp"

namespace {

game::GameReport play(rules::Game g, int level, std::uint64_t seed, bool ai_breaks,
                      double noise = 1.0) {
    game::Config config;
    config.game = g;
    config.seed = seed;
    game::Session session(config);
    ai::AiPlayer ai_player(level, seed * 3 + 1, noise);
    game::RandomPlayer random(seed * 5 + 2);
    std::array<game::Player*, 2> seats{&ai_player, &random};
    if (!ai_breaks) std::swap(seats[0], seats[1]);
    return game::play_game(session, seats, {}, noise, seed * 7 + 3);
}

TEST(WholeGames, EveryDecisionIsLegalInEightBall) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const int level = static_cast<int>(seed) * 2 - 1;  // 1, 3, 5
        game::GameReport r;
        ASSERT_NO_THROW(r = play(rules::Game::eight_ball, level, seed, seed % 2 == 1)) << seed;
        EXPECT_FALSE(r.capped);
        EXPECT_TRUE(r.winner.has_value());
    }
}

TEST(WholeGames, EveryDecisionIsLegalInNineBall) {
    for (std::uint64_t seed = 1; seed <= 3; ++seed) {
        const int level = static_cast<int>(seed) + 1;  // 2, 3, 4
        game::GameReport r;
        ASSERT_NO_THROW(r = play(rules::Game::nine_ball, level, seed, seed % 2 == 0)) << seed;
        EXPECT_FALSE(r.capped);
        EXPECT_TRUE(r.winner.has_value());
    }
}

TEST(WholeGames, TheAiBeatsTheRandomPlayer) {
    int wins = 0;
    for (std::uint64_t seed = 10; seed < 14; ++seed) {
        const bool ai_breaks = seed % 2 == 0;  // the AI sits at A when it breaks, else at B
        const rules::Player ai_seat = ai_breaks ? rules::Player::A : rules::Player::B;
        if (play(rules::Game::nine_ball, 3, seed, ai_breaks).winner == ai_seat) ++wins;
    }
    EXPECT_GE(wins, 3);
}

TEST(WholeGames, ReproducibleFromTheSeeds) {
    const game::GameReport a = play(rules::Game::eight_ball, 2, 21, true);
    const game::GameReport b = play(rules::Game::eight_ball, 2, 21, true);
    EXPECT_EQ(a.shots, b.shots);
    EXPECT_EQ(a.fouls, b.fouls);
    EXPECT_EQ(a.winner, b.winner);
}

TEST(WholeGames, LevelsStrokeWithTheirOwnNoise) {
    EXPECT_EQ(ai::AiPlayer(1, 1).execution_noise(), 4.0);
    EXPECT_EQ(ai::AiPlayer(5, 1).execution_noise(), 1.0);
    EXPECT_EQ(ai::AiPlayer(3, 1).kind(), "ai:3");
}

}  // namespace
