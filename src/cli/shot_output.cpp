#include "cli/shot_output.hpp"

#include <string>

#include "cli/json_out.hpp"
#include "physics/table.hpp"

namespace cli {

using nlohmann::ordered_json;

ordered_json event_to_json(const physics::Event& event) {
    ordered_json e;
    e["time"] = event.time;
    e["type"] = std::string(physics::to_string(event.type));
    ordered_json ids = ordered_json::array();
    for (int k = 0; k < event.ball_count; ++k) ids.push_back(event.ball(k));
    e["balls"] = std::move(ids);

    switch (event.type) {
        case physics::EventType::transition:
            e["from"] = std::string(physics::to_string(event.from));
            e["to"] = std::string(physics::to_string(event.to));
            break;
        case physics::EventType::ball_ball:
            e["speed"] = event.speed;
            break;
        case physics::EventType::cushion:
            e["speed"] = event.speed;
            if (event.rail >= 0)
                e["cushion"] = std::string(physics::rail_name(event.rail));
            else
                e["pocket_jaw"] = std::string(physics::pocket_name(event.pocket));
            break;
        case physics::EventType::pocket:
            e["pocket"] = std::string(physics::pocket_name(event.pocket));
            break;
        case physics::EventType::strike:
        case physics::EventType::miscue:
        case physics::EventType::off_table:
            break;
    }

    ordered_json pos = ordered_json::array(), vel = ordered_json::array(),
                 spin = ordered_json::array();
    for (std::size_t k = 0; k < event.ball_count; ++k) {
        const physics::EventBall& b = event.balls[k];
        pos.push_back(to_json(b.pos));
        vel.push_back(to_json(b.vel));
        spin.push_back(to_json(b.spin));
    }
    e["pos"] = std::move(pos);
    e["vel"] = std::move(vel);
    e["spin"] = std::move(spin);
    return e;
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
