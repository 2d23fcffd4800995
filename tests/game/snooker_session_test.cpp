// game::SnookerSession: whole frames by a random player through the real physics (every
// choice taken at random), save/load round trips at every stroke, corrupt saves, refusals.
#include "game/snooker_session.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>

#include "game/json_field.hpp"
#include "game/match_player.hpp"
#include "game/session.hpp"
#include "physics/rack.hpp"

namespace game {
namespace {

namespace sb = physics::snooker_ball;
using rules::Player;

// One turn of the random player (game/match_player.hpp): a stroke, or the after-foul choice.
void random_turn(SnookerSession& s, SnookerPlayer& player) {
    const int before = s.state().score(Player::A) + s.state().score(Player::B);
    const bool stroke = s.phase() != MatchPhase::choose;
    const MatchDecision d = player.decide(s);
    apply(s, d, d.stroke);
    if (!stroke) return;
    const rules::SnookerVerdict& v = *s.last_verdict();
    EXPECT_EQ(v.state.score(Player::A) + v.state.score(Player::B),
              before + v.points_scored + v.foul_points);
}

TEST(SnookerSession, RandomPlayersFinishAMatchAndEverySaveReadsBack) {
    SnookerConfig c;
    c.best_of = 3;
    c.names = {"Ann", "Bob"};
    SnookerSession s(c);
    SnookerPlayer player = random_snooker_player(5);
    int turns = 0;
    while (s.phase() != MatchPhase::match_over && turns < 8000) {
        if (s.phase() == MatchPhase::frame_over) {
            ASSERT_TRUE(s.frame_winner());
            s.next_frame();
            EXPECT_EQ(s.state().shooter, s.breaker_of_frame(s.frame_number()));
            continue;
        }
        random_turn(s, player);
        ++turns;
        if (turns % 25 == 0) {
            const SnookerSession back = SnookerSession::from_json(s.to_json());
            ASSERT_EQ(back.to_json(), s.to_json());
        }
    }
    ASSERT_EQ(s.phase(), MatchPhase::match_over) << "after " << turns << " turns";
    const Player w = *s.match_winner();
    EXPECT_EQ(s.frames_won()[rules::index(w)], 2);
    EXPECT_LE(s.frames_won()[rules::index(rules::other(w))], 1);
    EXPECT_FALSE(s.to_act());
    EXPECT_THROW(s.next_frame(), Refused);
    std::printf("best of 3: %d turns, frames %d-%d\n", turns, s.frames_won()[0], s.frames_won()[1]);
}

TEST(SnookerSession, TheBreakIsFromTheDAndRefusalsSayWhy) {
    SnookerSession s(SnookerConfig{});
    EXPECT_EQ(s.phase(), MatchPhase::place_cue_ball);
    EXPECT_THROW(s.play(physics::Stroke{}), Refused);
    const physics::Vec2 d = s.marks().marks.d_centre();
    EXPECT_EQ(*s.check_cue_ball({d.x + 0.2, d.y}), "The cue ball in hand goes in the D.");
    try {
        s.nominate(sb::black);
        FAIL() << "nominated with a red on";
    } catch (const Refused& e) {
        EXPECT_STREQ(e.what(), "There is nothing to nominate: a red is on.");
    }
    s.place_cue_ball({d.x - 0.1, d.y});
    EXPECT_EQ(s.phase(), MatchPhase::shoot);
    s.place_cue_ball({d.x - 0.1, d.y + 0.1});  // moved again before the stroke
    EXPECT_EQ(s.state().positions.at(sb::cue).y, d.y + 0.1);
}

TEST(SnookerSession, AFoulOffersTheChoiceToTheOpponentAndPlayAgainKeepsTheOffender) {
    SnookerSession s(SnookerConfig{});
    const physics::Vec2 d = s.marks().marks.d_centre();
    s.place_cue_ball({d.x - 0.1, d.y});
    physics::Stroke k;  // straight back into the baulk cushion: no ball hit, a foul
    k.heading_deg = 180.0;
    k.speed = 1.0;
    const rules::SnookerVerdict& v = s.play(k);
    ASSERT_TRUE(v.foul);
    EXPECT_EQ(v.foul_points, 4);
    EXPECT_EQ(s.state().score(Player::B), 4);
    ASSERT_EQ(s.phase(), MatchPhase::choose);
    EXPECT_EQ(s.to_act(), Player::B);
    const SnookerSession saved = SnookerSession::from_json(s.to_json());
    EXPECT_EQ(saved.choices(), s.choices());
    s.choose(rules::AfterFoul::play_again);
    EXPECT_EQ(s.phase(), MatchPhase::shoot);
    EXPECT_EQ(s.state().shooter, Player::A);
    EXPECT_EQ(s.state().score(Player::B), 4);
    EXPECT_THROW(s.choose(rules::AfterFoul::play), Refused);
}

TEST(SnookerSession, CorruptSavesNameTheField) {
    SnookerSession s(SnookerConfig{});
    const std::string good = s.to_json();
    auto error_of = [](const std::string& text) -> std::string {
        try {
            (void)SnookerSession::from_json(text);
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
    EXPECT_EQ(error_of("{").rfind("snooker: ", 0), 0u);
    EXPECT_NE(error_of(with("\"best_of\":1", "\"best_of\":2")).find("snooker.config.best_of"),
              std::string::npos);
    EXPECT_NE(
        error_of(with("\"on_table\":[1,", "\"on_table\":[1,1,")).find("snooker.state.on_table[1]"),
        std::string::npos);
    EXPECT_NE(error_of(with("coolaaber-snooker", "coolaaber-session")).find("snooker.format"),
              std::string::npos);
    EXPECT_NE(error_of(with("\"16\":[", "\"16\":[0.001,")).find("snooker.state.positions"),
              std::string::npos);
}

TEST(SnookerSession, SaveFileNeverLeavesHalfAFileAndLoadsBack) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path() / "coolaaber_snooker";
    std::filesystem::create_directories(dir);
    const std::filesystem::path path = dir / "match.json";
    SnookerSession s(SnookerConfig{});
    s.save_file(path);
    EXPECT_EQ(SnookerSession::load_file(path).to_json(), s.to_json());
    std::ofstream(path) << "{\"format\": \"coolaaber-snooker\", \"version\": 1";
    EXPECT_THROW(SnookerSession::load_file(path), LoadError);
    std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace game
