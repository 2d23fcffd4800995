#include "cli/shot_output.hpp"

#include <string>

#include "cli/json_out.hpp"
#include "game/state_json.hpp"
#include "physics/table.hpp"

namespace cli {

using nlohmann::ordered_json;

// The game's writer (game/state_json.hpp): saved games and the CLI write events alike.
ordered_json event_to_json(const physics::Event& event) {
    return game::to_json(event);
}

ordered_json events_to_json(std::span<const physics::Event> events) {
    ordered_json out = ordered_json::array();
    for (const physics::Event& e : events) out.push_back(event_to_json(e));
    return out;
}

namespace {

bool pocketed(const physics::BallState& b) {
    return b.motion == physics::Motion::pocketed;
}

// `final` entry: id, pos (null when pocketed), state, pocket when pocketed.
ordered_json final_ball(const physics::BallState& b) {
    ordered_json j;
    j["id"] = b.id;
    j["pos"] = pocketed(b) ? ordered_json(nullptr) : to_json(b.pos);
    j["state"] = std::string(physics::to_string(b.motion));
    if (pocketed(b)) j["pocket"] = std::string(physics::pocket_name(b.pocket));
    return j;
}

// `samples` ball: id, pos (null when pocketed), vel, spin, state, pocket when pocketed.
ordered_json sample_ball(const physics::BallState& b) {
    ordered_json j;
    j["id"] = b.id;
    j["pos"] = pocketed(b) ? ordered_json(nullptr) : to_json(b.pos);
    j["vel"] = to_json(pocketed(b) ? physics::Vec2{} : b.vel);
    j["spin"] = to_json(pocketed(b) ? physics::Vec3{} : b.spin);
    j["state"] = std::string(physics::to_string(b.motion));
    if (pocketed(b)) j["pocket"] = std::string(physics::pocket_name(b.pocket));
    return j;
}

}  // namespace

ordered_json shot_to_json(const physics::Shot& shot, std::span<const double> sample_times) {
    ordered_json out;
    out["events"] = events_to_json(shot.events());

    ordered_json final_states = ordered_json::array();
    for (const physics::BallState& b : shot.final_states()) final_states.push_back(final_ball(b));
    out["final"] = std::move(final_states);

    ordered_json samples = ordered_json::array();
    for (double t : sample_times) {
        ordered_json balls = ordered_json::array();
        for (const physics::BallState& b : shot.states_at(t)) balls.push_back(sample_ball(b));
        ordered_json sample;
        sample["time"] = t;
        sample["balls"] = std::move(balls);
        samples.push_back(std::move(sample));
    }
    out["samples"] = std::move(samples);

    std::optional<double> rest = shot.rest_time();
    out["rest_time"] = rest ? ordered_json(*rest) : ordered_json(nullptr);
    out["event_count"] = shot.events().size();
    out["truncated"] = shot.truncated();
    return out;
}

}  // namespace cli
