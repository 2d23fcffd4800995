// game::CaromSession: whole three-cushion games by a random player through the real physics,
// save/load round trips at every stroke, corrupt saves.
#include "game/carom_session.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "game/json_field.hpp"
#include "game/match_player.hpp"
#include "game/session.hpp"
#include "physics/rack.hpp"

namespace game {
namespace {

using rules::Player;

TEST(CaromSession, RandomPlayersFinishGamesAndEverySaveReadsBack) {
    CaromConfig c;
    c.options = {.target = 2, .equal_innings = true};
    CaromSession s(c);
    CaromPlayer player = random_carom_player(11);
    int strokes = 0;
    for (int game = 0; game < 2; ++game) {
        EXPECT_EQ(s.state().starter, s.starter_of_game(game));
        EXPECT_EQ(s.cue_ball(), physics::carom_ball::white);  // the starter plays the white
        while (!s.game_over() && strokes < 20000) {
            const Player p = *s.to_act();
            const int before = s.state().scores[rules::index(p)];
            const MatchDecision d = player.decide(s);
            apply(s, d, d.stroke);
            const rules::CaromVerdict& v = *s.last_verdict();
            EXPECT_EQ(s.state().scores[rules::index(p)], before + (v.point ? 1 : 0));
            if (!v.game_over) {
                EXPECT_EQ(*v.next_shooter, v.point ? p : rules::other(p));
            }
            ++strokes;
            ASSERT_EQ(CaromSession::from_json(s.to_json()).to_json(), s.to_json());
        }
        ASSERT_TRUE(s.game_over());
        if (s.winner()) {
            EXPECT_GE(s.state().scores[rules::index(*s.winner())], 2);
        }
        EXPECT_FALSE(s.to_act());
        EXPECT_THROW(s.play(physics::Stroke{}), Refused);
        s.next_game();
    }
    EXPECT_EQ(s.game_number(), 2);
    std::printf("two games to 2: %d strokes\n", strokes);
}

TEST(CaromSession, TheYellowIsTheSecondPlayersBallAndTheAverageCountsInnings) {
    CaromSession s(CaromConfig{});
    physics::Stroke k;  // a soft stroke at nothing: no point, the inning passes
    k.heading_deg = 180.0;
    k.speed = 0.5;
    const rules::CaromVerdict& v = s.play(k);
    EXPECT_FALSE(v.point);
    EXPECT_EQ(s.to_act(), Player::B);
    EXPECT_EQ(s.cue_ball(), physics::carom_ball::yellow);
    EXPECT_EQ(s.state().innings, (std::array<int, 2>{1, 1}));
    EXPECT_EQ(s.average(Player::A), 0.0);
}

TEST(CaromSession, CorruptSavesNameTheField) {
    CaromSession s(CaromConfig{});
    const std::string good = s.to_json();
    auto error_of = [](const std::string& text) -> std::string {
        try {
            (void)CaromSession::from_json(text);
        } catch (const LoadError& e) {
            return e.what();
        }
        return "loaded";
    };
    auto with = [&](const std::string& from, const std::string& to) {
        std::string t = good;
        const std::size_t at = t.find(from);
        EXPECT_NE(at, std::string::npos) << from;
        return t.replace(at, from.size(), to);
    };
    EXPECT_NE(error_of(with("\"target\":15", "\"target\":0")).find("carom.config.target"),
              std::string::npos);
    EXPECT_NE(error_of(with("\"game_over\":false", "\"game_over\":true")).find("carom.game_over"),
              std::string::npos);
    EXPECT_NE(error_of(with("\"2\":[", "\"3\":[")).find("carom.state.positions"),
              std::string::npos);
    EXPECT_NE(error_of(with("coolaaber-three-cushion", "x")).find("carom.format"),
              std::string::npos);
}

}  // namespace
}  // namespace game
