// The verbs of coolaaber-cli (docs/cli.md). Each takes the parsed input document and
// returns the output document; bad input throws cli::BadInput (cli/json_in.hpp).
#pragma once

#include <array>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "game/json_field.hpp"

namespace cli {

/// `simulate`: a table, parameters, balls (or a rack) and an optional strike → the shot's
/// events, final state, samples, rest time.
nlohmann::ordered_json simulate_command(const nlohmann::json& input);

/// `judge`: a game state and a shot's events → the verdict and the next state.
nlohmann::ordered_json judge_command(const nlohmann::json& input);

/// `judge` of a snooker or three-cushion document (`game` "snooker" or "three_cushion").
nlohmann::ordered_json snooker_judge_document(const game::Field& input);
nlohmann::ordered_json carom_judge_document(const game::Field& input);

/// `decide`: a game's state (and a pending choice) → the AI's stroke, call, ball-in-hand spot,
/// push-out or choice, its expected success, the simulations it ran and the seconds it took.
nlohmann::ordered_json decide_command(const nlohmann::json& input);
/// `decide` of a snooker or three-cushion document: the stroke (and nomination, cue-ball spot),
/// or the choice after a foul.
nlohmann::ordered_json snooker_decide_document(const game::Field& input);
nlohmann::ordered_json carom_decide_document(const game::Field& input);

/// The verbs that read one JSON document.
enum class DocumentVerb { simulate, judge, decide };

/// Runs `verb` on the text of its input document and returns the output document (one line,
/// or indented when `pretty`, with a final newline). Bad input, the document's text included,
/// throws BadInput; it never exits or aborts, so a fuzzer may call it with any bytes.
std::string run_document(DocumentVerb verb, std::string_view text, bool pretty = false);

/// `bench --runs N`: simulates each standard scene `runs` times and reports timings.
inline constexpr std::int64_t default_bench_runs = 2000;
inline constexpr std::int64_t max_bench_runs = 1'000'000;
nlohmann::ordered_json bench_command(std::int64_t runs = default_bench_runs);

/// `match`: plays whole games between two players and returns the summary (docs/game.md).
struct MatchOptions {
    std::string game = "8ball";  ///< --game: "8ball", "9ball", "snooker" or "three_cushion"
    std::string players = "random,random";  ///< --players: two of "random", "ai:LEVEL"
    std::int64_t games = 100;               ///< --games
    std::string seed = "1";                 ///< --seed: 0 to 2^64 - 1
    std::string log;                        ///< --log: a file for one JSON line per shot
    double noise = 1.0;                     ///< --noise: scale of the execution noise
    bool duplicate = false;                 ///< --duplicate: each seed twice, sides swapped
    std::optional<std::int64_t> reds;       ///< --reds: snooker, reds racked (default 15)
    std::optional<std::int64_t> target;     ///< --target: three-cushion, points to win
};
nlohmann::ordered_json match_command(const MatchOptions& options);
/// `match` of snooker frames or three-cushion games between two computer players
/// (games_match.cpp); `seed` and `levels` read by match_command.
nlohmann::ordered_json games_match(const MatchOptions& options, std::uint64_t seed,
                                   const std::array<int, 2>& levels);

}  // namespace cli
