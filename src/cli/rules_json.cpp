#include "cli/rules_json.hpp"

#include "game/state_json.hpp"
#include "rules/names.hpp"

namespace cli {

// The readers and writers are the game module's (game/state_json.hpp): save files and the CLI
// share one schema; the CLI's documents may leave out the optional fields.

rules::Game read_game(const JsonIn& in) {
    return in.name_of<rules::Game>();
}

rules::Options read_options(const JsonIn& in) {
    return game::read_options(in, game::Fields::required);
}

rules::GameState read_state(const JsonIn& in, rules::Game game, const physics::Table& table,
                            const physics::Params& params) {
    return game::read_state(in, {game, table, params}, game::Fields::required);
}

std::vector<physics::Event> read_events(const JsonIn& in, rules::Game game,
                                        const rules::GameState& s) {
    std::vector<physics::Event> events;
    const std::size_t n = in.array_size();
    events.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        events.push_back(game::read_event(in.at(i), game, game::Fields::required, &s));
    return events;
}

nlohmann::ordered_json to_json(const rules::GameState& s) {
    return game::to_json(s);
}

nlohmann::ordered_json to_json(const rules::Options& o) {
    return game::to_json(o);
}

nlohmann::ordered_json to_json(const std::optional<rules::Choice>& c) {
    return game::to_json(c);
}

nlohmann::ordered_json to_json(const rules::Verdict& v) {
    return game::to_json(v);
}

}  // namespace cli
