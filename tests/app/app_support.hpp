// Helpers for the app's tests: sessions and controllers on the standard table, and running a
// controller until its shot is over.
#pragma once

#include <map>
#include <nlohmann/json.hpp>

#include "app/controller.hpp"
#include "game/session.hpp"
#include "physics/vec.hpp"

namespace app_test {

inline game::Session new_session(rules::Game game = rules::Game::eight_ball,
                                 std::uint64_t seed = 5) {
    game::Config c;
    c.game = game;
    c.seed = seed;
    c.names = {"Ann", "Bob"};
    return game::Session(c);
}

/// An 8-ball session (Ann to shoot) with the balls at `balls` (0: the cue ball, on the table
/// unless `cue_ball` says it is in hand), loaded through the save format; the balls not listed
/// count as pocketed by Ann.
inline game::Session session_at(const std::map<int, physics::Vec2>& balls,
                                const std::string& cue_ball = "on_table",
                                const std::string& shot = "normal") {
    nlohmann::json doc = nlohmann::json::parse(new_session().to_json());
    nlohmann::json on_table = nlohmann::json::array(), positions = nlohmann::json::object();
    nlohmann::json pocketed = nlohmann::json::array();
    for (int id = 1; id <= 15; ++id)
        if (!balls.count(id)) pocketed.push_back({{"ball", id}, {"pocket", "SW"}, {"by", "A"}});
    for (const auto& [id, p] : balls) {
        if (id != 0) on_table.push_back(id);
        positions[std::to_string(id)] = {p.x, p.y};
    }
    nlohmann::json& st = doc["state"];
    st["shot"] = shot;
    st["on_table"] = on_table;
    st["positions"] = positions;
    st["cue_ball"] = cue_ball;
    doc["pocketed"] = pocketed;
    return game::Session::from_json(doc.dump());
}

inline app::ControllerOptions options(std::string a = "human", std::string b = "human") {
    app::ControllerOptions o;
    o.players = {std::move(a), std::move(b)};
    o.seed = 9;
    o.computer_aim_seconds = 0.0;
    return o;
}

/// Updates in steps of `dt` until nothing moves or thinks (at most `limit` s of updates).
inline void run_until_idle(app::Controller& c, double dt = 1.0 / 30.0, double limit = 120.0) {
    for (double t = 0; t < limit && c.busy(); t += dt) {
        c.wait_for_computer();
        c.update(dt);
    }
}

/// Plays until the game is over (computer seats), at most `max_updates` updates.
inline void play_to_the_end(app::Controller& c, int max_updates = 200000) {
    for (int i = 0; i < max_updates && c.session().phase() != game::Phase::game_over; ++i) {
        c.wait_for_computer();
        c.update(0.05);
    }
}

}  // namespace app_test
