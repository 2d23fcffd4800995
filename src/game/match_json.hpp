// What the snooker and three-cushion save files share (docs/game.md, "Snooker and three-cushion
// saves"): the format header, players' names, pairs by player, ball positions checked against
// the table. Used by snooker_session_json.cpp and carom_session_json.cpp.
#pragma once

#include <array>
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>

#include "game/json_field.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"
#include "physics/vec.hpp"
#include "rules/game_state.hpp"

namespace game::match_json {

/// {"format": `format`, "version": 1}, checked: anything else is not such a file.
void write_header(nlohmann::ordered_json& j, std::string_view format);
void check_header(const Field& root, std::string_view format);

nlohmann::ordered_json pair(const std::array<int, 2>& v);
std::array<int, 2> read_pair(const Field& f, int lo, int hi);
std::array<std::string, 2> read_names(const Field& f);
nlohmann::ordered_json names(const std::array<std::string, 2>& n);

nlohmann::ordered_json positions(const std::map<int, physics::Vec2>& p);
/// Positions by ball id ("0" … "21"); `allowed` says which ids may be there; the layout is
/// checked against the table (on the cloth, no overlaps).
std::map<int, physics::Vec2> read_positions(const Field& f, const physics::Table& table,
                                            const physics::Params& params,
                                            const std::function<bool(int)>& allowed);

}  // namespace game::match_json
