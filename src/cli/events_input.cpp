#include "cli/events_input.hpp"

#include <fmt/format.h>

#include <charconv>
#include <string>

#include "cli/json_out.hpp"
#include "game/state_json.hpp"
#include "physics/layout.hpp"

namespace cli {

namespace {

int read_ball_id(const JsonIn& f, const BallSet& balls) {
    const std::int64_t id = f.integer();
    if (id < 0 || id > balls.highest)
        f.fail(fmt::format("ball {} does not exist (the balls are 0 to {})", id, balls.highest));
    if (!balls.present(static_cast<int>(id)))
        f.fail(fmt::format("ball {} is not on the table", id));
    return static_cast<int>(id);
}

}  // namespace

std::vector<physics::Event> read_events(const JsonIn& in, const BallSet& balls) {
    std::vector<physics::Event> events;
    const std::size_t n = in.array_size();
    for (std::size_t i = 0; i < n; ++i) {
        JsonIn e = in.at(i);
        if (!e.raw().is_object()) e.fail("expected an event object");
        JsonIn list = e.at("balls");
        const std::size_t count = list.array_size();
        std::vector<int> ids;
        for (std::size_t k = 0; k < count; ++k) ids.push_back(read_ball_id(list.at(k), balls));
        // The rest of the event is checked by the pool reader, with stand-in ids 0 and 1.
        nlohmann::json copy = e.raw();
        nlohmann::json stand_in = nlohmann::json::array();
        for (std::size_t k = 0; k < count && k < 2; ++k) stand_in.push_back(k);
        copy["balls"] = stand_in;
        physics::Event ev = game::read_event(JsonIn(copy, e.path()), rules::Game::eight_ball,
                                             game::Fields::required, nullptr);
        for (std::size_t k = 0; k < count; ++k) ev.balls[k].id = ids[k];
        const bool strike =
            ev.type == physics::EventType::strike || ev.type == physics::EventType::miscue;
        if (strike && ids[0] != 0 && !balls.any_struck)
            list.at(std::size_t{0}).fail("only the cue ball (0) is struck");
        if (ev.type == physics::EventType::pocket && !balls.pockets)
            e.at("type").fail("a carom table has no pockets");
        events.push_back(ev);
    }
    return events;
}

std::map<int, physics::Vec2> read_positions(const JsonIn& in, const BallSet& balls,
                                            const physics::Table& table,
                                            const physics::Params& params) {
    if (!in.raw().is_object())
        in.fail("expected an object of positions by ball id, e.g. {\"0\": [0.5, 0.6]}");
    std::map<int, physics::Vec2> positions;
    std::vector<physics::BallState> layout;
    std::vector<std::string> keys;
    for (const auto& [key, value] : in.raw().items()) {
        JsonIn item = in.at(std::string_view(key));
        int id = -1;
        const auto [end, ec] = std::from_chars(key.data(), key.data() + key.size(), id);
        if (ec != std::errc() || end != key.data() + key.size() || id < 0 || id > balls.highest)
            item.fail(fmt::format("unknown ball \"{}\": the balls are \"0\" to \"{}\"", key,
                                  balls.highest));
        if (!balls.present(id)) item.fail(fmt::format("ball {} is not on the table", id));
        physics::BallState b;
        b.id = id;
        b.pos = game::read_vec2(item);
        positions[id] = b.pos;
        layout.push_back(b);
        keys.push_back(key);
    }
    if (auto e = physics::validate_layout(table, params, layout))
        in.at(std::string_view(keys[e->index])).fail(e->message);
    return positions;
}

std::array<int, 2> read_pair(const JsonIn& in, int lo, int hi) {
    in.require_fields({"A", "B"});
    return {static_cast<int>(in.at("A").integer_in(lo, hi)),
            static_cast<int>(in.at("B").integer_in(lo, hi))};
}

nlohmann::ordered_json pair_to_json(const std::array<int, 2>& v) {
    nlohmann::ordered_json j;
    j["A"] = v[0];
    j["B"] = v[1];
    return j;
}

nlohmann::ordered_json positions_to_json(const std::map<int, physics::Vec2>& positions) {
    nlohmann::ordered_json j = nlohmann::ordered_json::object();
    for (const auto& [id, p] : positions) j[std::to_string(id)] = to_json(p);
    return j;
}

}  // namespace cli
