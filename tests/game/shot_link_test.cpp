// Shot links (docs/game.md, "Shot links"): a position and a stroke as link text, read back to
// the same shot, bit for bit; links cut short, altered, of another version or holding an
// impossible position give a message that says so.
#include "game/shot_link.hpp"

#include <gtest/gtest.h>

#include <string>

#include "game/json_field.hpp"
#include "game/random_player.hpp"
#include "physics/simulate.hpp"
#include "session_support.hpp"

namespace game::test {
namespace {

/// A shot from the middle of a random game of `game`: the state after `shots` strokes and the
/// stroke the random player would play next.
SharedShot shot_from_a_game(rules::Game game, int shots) {
    const Config c = config_for(game, 7);
    Session s(c);
    RandomPlayer a(11), b(12);
    play_shots(s, a, b, shots);
    while (s.phase() != Phase::shoot) {
        if (s.phase() == Phase::game_over) s.restart();
        play_shots(s, a, b, 1);
    }
    SharedShot shot{c.game, c.options, c.table, c.params, s.state(), {}};
    shot.stroke = (s.to_act() == A ? a : b).decide(s).stroke;
    return shot;
}

bool same_events(const physics::Shot& x, const physics::Shot& y) {
    if (x.events().size() != y.events().size()) return false;
    for (std::size_t i = 0; i < x.events().size(); ++i) {
        const physics::Event &e = x.events()[i], &f = y.events()[i];
        if (e.time != f.time || e.type != f.type || e.ball_count != f.ball_count) return false;
        for (int k = 0; k < e.ball_count; ++k) {
            const auto &p = e.balls[static_cast<std::size_t>(k)],
                       &q = f.balls[static_cast<std::size_t>(k)];
            if (p.id != q.id || p.pos.x != q.pos.x || p.pos.y != q.pos.y || p.vel.x != q.vel.x ||
                p.vel.y != q.vel.y)
                return false;
        }
    }
    return true;
}

physics::Shot play(const SharedShot& s) {
    return physics::simulate(physics::build_table(s.table), s.params, s.balls(), &s.stroke);
}

TEST(ShotLink, ReadsBackToTheSameShotBitForBit) {
    for (rules::Game game : {rules::Game::eight_ball, rules::Game::nine_ball}) {
        for (int shots : {0, 3, 8}) {
            const SharedShot shot = shot_from_a_game(game, shots);
            const std::string link = shot_link(shot);
            EXPECT_TRUE(link.starts_with("shot=1.")) << link;
            const SharedShot back = read_shot_link(link);
            EXPECT_EQ(shot_link(back), link) << "the link holds every number exactly";
            EXPECT_TRUE(same_events(play(shot), play(back)));
            // As the fragment of the web page's address, with spaces around it from a paste.
            const SharedShot from_address =
                read_shot_link("  http://localhost:8080/#" + link + "\n");
            EXPECT_EQ(shot_link(from_address), link);
        }
    }
}

TEST(ShotLink, ASessionAtTheLinksPositionPlaysThatShot) {
    for (rules::Game game : {rules::Game::eight_ball, rules::Game::nine_ball}) {
        const SharedShot shot = read_shot_link(shot_link(shot_from_a_game(game, 3)));
        Config c = config_for(game, 99);
        c.options = shot.options;
        c.table = shot.table;
        c.params = shot.params;
        Session s = Session::at_position(c, shot.state);
        EXPECT_EQ(s.phase(), Phase::shoot);
        EXPECT_EQ(s.to_act(), shot.state.shooter);
        EXPECT_TRUE(s.history().empty());
        const ShotRecord& r = s.play(shot.stroke);
        EXPECT_EQ(r.before.positions, shot.state.positions);
        ASSERT_NE(s.last_shot(), nullptr);
        EXPECT_TRUE(same_events(*s.last_shot(), play(shot))) << "the very shot of the link";
    }
}

std::string error_of(const std::string& link) {
    try {
        read_shot_link(link);
    } catch (const LoadError& e) {
        return e.what();
    }
    return "(read without error)";
}

TEST(ShotLink, BadLinksSayWhatIsWrong) {
    const std::string link = shot_link(shot_from_a_game(rules::Game::nine_ball, 2));
    EXPECT_NE(error_of("http://localhost:8080/").find("not a shot link"), std::string::npos);
    EXPECT_NE(error_of("shot=1").find("cut short"), std::string::npos);
    EXPECT_NE(error_of(link.substr(0, link.size() - 7)).find("checksum"), std::string::npos);
    std::string changed = link;
    changed[changed.size() / 2] = changed[changed.size() / 2] == 'A' ? 'B' : 'A';
    EXPECT_NE(error_of(changed).find("checksum"), std::string::npos);
    std::string mistyped = link;
    mistyped[mistyped.size() - 5] = '*';
    EXPECT_NE(error_of(mistyped).find("cannot be in a link"), std::string::npos);
    EXPECT_NE(error_of("shot=2" + link.substr(6)).find("version 2"), std::string::npos);
    EXPECT_NE(error_of("shot=1.00000000." + std::string(70000, 'A')).find("too long"),
              std::string::npos);
}

TEST(ShotLink, AnImpossiblePositionIsRefusedByItsField) {
    SharedShot shot = shot_from_a_game(rules::Game::eight_ball, 0);
    shot.state.positions[5] = {3.5, 0.6};  // beyond the 9 ft table's foot rail
    const std::string message = error_of(shot_link(shot));
    EXPECT_TRUE(message.starts_with("link.shot.state.positions")) << message;
}

}  // namespace
}  // namespace game::test
