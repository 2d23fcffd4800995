// The verbs of coolaaber-cli (cli-contract.md). Each takes the parsed input document and
// returns the output document; bad input throws cli::BadInput.
#pragma once

#include <nlohmann/json.hpp>

namespace cli {

nlohmann::json simulate_command(const nlohmann::json& input);
nlohmann::json judge_command(const nlohmann::json& input);

}  // namespace cli
