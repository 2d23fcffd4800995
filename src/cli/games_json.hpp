// The snooker and three-cushion documents' parts that `judge`, `decide` and `match` share
// (docs/cli.md, "judge: snooker and three-cushion"): options, states and verdicts, read with
// every check of the contract and written in its key order.
#pragma once

#include <nlohmann/json.hpp>

#include "cli/json_in.hpp"
#include "physics/params.hpp"
#include "physics/table.hpp"
#include "rules/snooker.hpp"
#include "rules/three_cushion.hpp"

namespace cli {

rules::SnookerOptions read_snooker_options(const JsonIn& in);
rules::SnookerState read_snooker_state(const JsonIn& in, const physics::Table& table,
                                       const physics::Params& params);
nlohmann::ordered_json snooker_state_json(const rules::SnookerState& s);
nlohmann::ordered_json snooker_verdict_json(const rules::SnookerVerdict& v);

rules::CaromOptions read_carom_options(const JsonIn& in);
rules::CaromState read_carom_state(const JsonIn& in, const rules::CaromOptions& o,
                                   const physics::Table& table, const physics::Params& params);
nlohmann::ordered_json carom_state_json(const rules::CaromState& s);
nlohmann::ordered_json carom_verdict_json(const rules::CaromVerdict& v);

}  // namespace cli
