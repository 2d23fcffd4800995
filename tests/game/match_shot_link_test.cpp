// Shot links of snooker and three-cushion (docs/game.md, "Shot links"): the match just before a
// stroke and the stroke, read back to the same match and the same shot, bit for bit; a link
// holding an impossible match names the field under "link.shot.session".
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "game/json_field.hpp"
#include "game/match_player.hpp"
#include "game/shot_link.hpp"

namespace game {
namespace {

/// A snooker shot after `turns` random turns: the match placed and nominated as the random
/// player wants, and its stroke.
SharedSnookerShot snooker_shot(int turns) {
    SnookerConfig c;
    c.names = {"Ann", "Bob"};
    SnookerSession s(c);
    SnookerPlayer player = random_snooker_player(3);
    for (int t = 0;; ++t) {
        if (s.phase() == MatchPhase::frame_over) s.next_frame();
        const MatchDecision d = player.decide(s);
        if (t >= turns && s.phase() != MatchPhase::choose) {
            if (d.cue_pos) s.place_cue_ball(*d.cue_pos);
            if (s.may_nominate()) s.nominate(d.nominate);
            return {s, d.stroke};
        }
        apply(s, d, d.stroke);
    }
}

SharedCaromShot carom_shot(int strokes) {
    CaromSession s{CaromConfig{}};
    CaromPlayer player = random_carom_player(5);
    for (int t = 0; t < strokes; ++t) {
        if (s.game_over()) s.next_game();
        const MatchDecision d = player.decide(s);
        apply(s, d, d.stroke);
    }
    if (s.game_over()) s.next_game();
    return {s, player.decide(s).stroke};
}

TEST(MatchShotLink, ASnookerShotReadsBackToTheSameMatchAndPlaysTheSameShot) {
    for (int turns : {0, 7, 20}) {
        const SharedSnookerShot shot = snooker_shot(turns);
        const std::string link = shot_link(shot);
        ASSERT_TRUE(link.starts_with("shot=1.")) << link;
        AnyShot any = read_any_shot_link("https://example.org/coolaaber/#" + link);
        ASSERT_TRUE(std::holds_alternative<SharedSnookerShot>(any));
        SharedSnookerShot& back = std::get<SharedSnookerShot>(any);
        EXPECT_EQ(back.before.to_json(), shot.before.to_json());
        SnookerSession reference = shot.before;
        const rules::SnookerVerdict expected = reference.play(shot.stroke);
        const rules::SnookerVerdict got = back.before.play(back.stroke);
        EXPECT_EQ(got.state.positions, expected.state.positions) << "bit for bit";
        EXPECT_EQ(got.state.scores, expected.state.scores);
        EXPECT_EQ(got.foul_points, expected.foul_points);
        EXPECT_EQ(back.before.to_json(), reference.to_json());
    }
}

TEST(MatchShotLink, AThreeCushionShotReadsBackToTheSameGameAndPlaysTheSameShot) {
    for (int strokes : {0, 5, 12}) {
        const SharedCaromShot shot = carom_shot(strokes);
        AnyShot any = read_any_shot_link(shot_link(shot));
        ASSERT_TRUE(std::holds_alternative<SharedCaromShot>(any));
        SharedCaromShot& back = std::get<SharedCaromShot>(any);
        EXPECT_EQ(back.before.to_json(), shot.before.to_json());
        CaromSession reference = shot.before;
        reference.play(shot.stroke);
        back.before.play(back.stroke);
        EXPECT_EQ(back.before.to_json(), reference.to_json()) << "bit for bit";
        EXPECT_EQ(back.before.state().positions, reference.state().positions);
    }
}

TEST(MatchShotLink, APoolReaderRefusesAMatchLinkByName) {
    try {
        read_shot_link(shot_link(carom_shot(0)));
        FAIL() << "read a three-cushion link as pool's";
    } catch (const LoadError& e) {
        EXPECT_EQ(e.path(), "link.shot.game") << e.what();
    }
}

std::string error_of(const std::string& link) {
    try {
        read_any_shot_link(link);
    } catch (const LoadError& e) {
        return e.what();
    }
    return "(read without error)";
}

TEST(MatchShotLink, AnImpossibleMatchIsRefusedByItsFieldUnderTheLink) {
    const SharedSnookerShot shot = snooker_shot(0);
    nlohmann::json doc = {{"game", "snooker"},
                          {"session", nlohmann::json::parse(shot.before.to_json())},
                          {"stroke", {{"speed", 2.0}, {"heading_deg", 0.0}}}};
    EXPECT_EQ(error_of(link_of_payload(doc.dump())).find("link.shot.stroke"), 0u)
        << "a stroke without all its fields: " << error_of(link_of_payload(doc.dump()));
    nlohmann::json session = nlohmann::json::parse(shot.before.to_json());
    session["state"]["positions"]["7"] = {9.0, 0.5};  // off the 12 ft table
    doc["session"] = session;
    doc["stroke"] = {
        {"speed", 2.0}, {"heading_deg", 0.0}, {"side", 0.0}, {"top", 0.0}, {"elevation_deg", 0.0}};
    const std::string message = error_of(link_of_payload(doc.dump()));
    EXPECT_TRUE(message.starts_with("link.shot.session.state.positions")) << message;
    doc["game"] = "snooker_plus";
    EXPECT_NE(error_of(link_of_payload(doc.dump())).find("link.shot.game"), std::string::npos);
}

}  // namespace
}  // namespace game
