// Helpers for the session tests: hand-made positions loaded through the save format, and a
// search for a stroke that does what a scenario needs through the real physics (on copies of
// the session, so the search itself changes nothing).
#pragma once

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <string>
#include <utility>
#include <vector>

#include "game/random_player.hpp"
#include "game/session.hpp"
#include "physics/layout.hpp"
#include "physics/table.hpp"
#include "rules/names.hpp"

namespace game::test {

using nlohmann::json;
using rules::Player;
inline constexpr Player A = Player::A;
inline constexpr Player B = Player::B;

// The 9 ft table and the standard ball.
inline constexpr double L = 2.540;
inline constexpr double W = 1.270;
inline constexpr double R = 0.028575;

inline int pocket(physics::PocketId p) {
    return static_cast<int>(p);
}

/// A state in the save format (the `judge` state schema), built field by field.
struct TableState {
    Player shooter = A;
    Player breaker = A;
    std::string shot = "normal";
    json groups = nullptr;               ///< e.g. {{"A", "solids"}, {"B", "stripes"}}
    std::map<int, physics::Vec2> balls;  ///< every ball on the table, the cue ball (0) included
    std::string cue_ball = "on_table";
    json call = nullptr;
    std::array<int, 2> fouls{0, 0};
    std::array<bool, 2> warned{false, false};

    json to_json() const {
        json on_table = json::array(), positions = json::object();
        for (const auto& [id, p] : balls) {
            if (id != 0) on_table.push_back(id);
            positions[std::to_string(id)] = {p.x, p.y};
        }
        return {{"shooter", rules::name(shooter)},
                {"breaker", rules::name(breaker)},
                {"shot", shot},
                {"groups", groups},
                {"on_table", on_table},
                {"cue_ball", cue_ball},
                {"call", call},
                {"fouls_in_row", {{"A", fouls[0]}, {"B", fouls[1]}}},
                {"warned", {{"A", warned[0]}, {"B", warned[1]}}},
                {"positions", positions}};
    }
};

inline Config config_for(rules::Game game, std::uint64_t seed = 1) {
    Config c;
    c.game = game;
    c.seed = seed;
    c.names = {"Ann", "Bob"};
    return c;
}

/// A session whose table is `t` (loaded through from_json): the balls not on the table are
/// listed as pocketed by A.
// Plays with random players, deciding in the test, so a game can be paused anywhere.
inline void play_shots(Session& s, RandomPlayer& a, RandomPlayer& b, int shots) {
    for (int n = 0; n < shots && s.phase() != Phase::game_over;) {
        RandomPlayer& p = s.to_act() == A ? a : b;
        const Decision d = p.decide(s);
        if (d.choice) {
            s.choose(*d.choice);
            continue;
        }
        if (d.cue_pos) s.place_cue_ball(*d.cue_pos);
        s.set_call(d.call);
        if (d.push_out) s.set_push_out(true);
        s.play(d.stroke);
        ++n;
    }
}

inline Session session_with(const Config& config, const TableState& t) {
    json doc = json::parse(Session(config).to_json());
    doc["state"] = t.to_json();
    json pocketed = json::array();
    for (int id = 1; id <= rules::highest_ball(config.game); ++id)
        if (!t.balls.count(id)) pocketed.push_back({{"ball", id}, {"pocket", "SW"}, {"by", "A"}});
    doc["pocketed"] = pocketed;
    return Session::from_json(doc.dump());
}

/// Strokes around a heading: every combination of the heading offsets, speeds and tip heights.
inline std::vector<physics::Stroke> fan(double heading_deg, std::vector<double> offsets_deg,
                                        std::vector<double> speeds, std::vector<double> tops) {
    std::vector<physics::Stroke> out;
    for (double top : tops)
        for (double speed : speeds)
            for (double d : offsets_deg) {
                physics::Stroke s;
                s.speed = speed;
                s.heading_deg = heading_deg + d;
                s.top = top;
                out.push_back(s);
            }
    return out;
}

/// The first candidate stroke whose record satisfies `wanted`, tried on a copy of `s` (after
/// `prepare`, e.g. a call, is applied to the copy).
inline std::optional<physics::Stroke> find_stroke(
    const Session& s, const std::vector<physics::Stroke>& candidates,
    const std::function<bool(const ShotRecord&)>& wanted,
    const std::function<void(Session&)>& prepare = nullptr) {
    for (const physics::Stroke& k : candidates) {
        Session trial = s;
        if (prepare) prepare(trial);
        if (wanted(trial.play(k))) return k;
    }
    return std::nullopt;
}

inline bool down(const ShotRecord& r, int ball) {
    for (const BallDown& d : r.summary.down)
        if (d.ball == ball) return true;
    return false;
}

inline std::optional<int> pocket_of(const ShotRecord& r, int ball) {
    for (const BallDown& d : r.summary.down)
        if (d.ball == ball) return d.pocket;
    return std::nullopt;
}

/// The heading from a to b (unit: deg).
inline double heading(physics::Vec2 a, physics::Vec2 b) {
    return std::atan2(b.y - a.y, b.x - a.x) * 180.0 / 3.14159265358979323846;
}

/// Checks that the session's state is one a table can be in: no ball both on the table and
/// pocketed, every ball of the game in exactly one of them, a position for every ball on the
/// table (and only those), no overlaps, all on the playing surface.
inline void expect_consistent(const Session& s) {
    const rules::GameState& st = s.state();
    std::set<int> seen;
    for (const Pocketed& p : s.pocketed()) {
        EXPECT_FALSE(st.has(p.ball)) << "ball " << p.ball << " is pocketed and on the table";
        EXPECT_TRUE(seen.insert(p.ball).second) << "ball " << p.ball << " pocketed twice";
    }
    for (int id = 1; id <= rules::highest_ball(s.config().game); ++id)
        EXPECT_TRUE(st.has(id) || seen.count(id)) << "ball " << id << " is nowhere";
    for (const auto& [id, p] : st.positions)
        EXPECT_TRUE(id == 0 || st.has(id)) << "ball " << id << " has a position off the table";
    for (int id : st.on_table)
        EXPECT_TRUE(st.positions.count(id)) << "ball " << id << " has no position";
    if (st.cue_ball == rules::CueBall::on_table) {
        EXPECT_TRUE(st.positions.count(0));
    }
    const std::vector<physics::BallState> balls = s.balls();
    std::optional<physics::LayoutError> e =
        physics::validate_layout(s.table(), s.config().params, balls);
    EXPECT_FALSE(e) << "ball " << balls[e ? e->index : 0].id << ": " << (e ? e->message : "");
}

}  // namespace game::test
