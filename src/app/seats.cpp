#include "app/seats.hpp"

#include <fmt/format.h>

#include <memory>
#include <optional>
#include <stdexcept>

#include "ai/ai.hpp"
#include "ai/games.hpp"
#include "app/platform.hpp"
#include "game/random_player.hpp"

namespace app {

namespace {

// The level of an "ai:N" seat, else empty.
std::optional<int> ai_level(const std::string& kind) {
    if (kind.size() == 4 && kind.rfind("ai:", 0) == 0 && kind[3] >= '1' && kind[3] <= '5')
        return kind[3] - '0';
    return std::nullopt;
}

game::MatchDecision snooker_decision(const game::SnookerSession& s,
                                     const ai::PlanSettings& settings, std::uint64_t seed) {
    const auto& c = s.config();
    const ai::SnookerPosition pos = ai::snooker_position(s.table(), c.params, c.options, s.state());
    game::MatchDecision d;
    if (s.phase() == game::MatchPhase::choose) {
        d.after_foul = ai::choose_after_foul(pos, *s.last_verdict(), s.before(), settings);
        return d;
    }
    const ai::SnookerPlan plan = ai::plan_snooker(pos, settings, seed);
    d.cue_pos = plan.cue_pos;
    d.nominate = plan.nominated;
    d.stroke = plan.stroke;
    return d;
}

}  // namespace

std::unique_ptr<game::Player> make_computer(const std::string& kind, std::uint64_t seed,
                                            double noise) {
    if (kind == "human") return nullptr;
    if (kind == "random") return std::make_unique<game::RandomPlayer>(seed);
    if (const std::optional<int> level = ai_level(kind))
        return std::make_unique<ai::AiPlayer>(*level, seed, noise, 2, platform::task_pause_point());
    throw std::invalid_argument("unknown player \"" + kind +
                                "\" (expected human, random or ai:1 to ai:5)");
}

std::optional<game::SnookerPlayer> snooker_computer(const std::string& kind, std::uint64_t seed,
                                                    double noise) {
    if (kind == "random") return game::random_snooker_player(seed);
    const std::optional<int> level = ai_level(kind);
    if (!level) return std::nullopt;
    const ai::PlanSettings settings{*level, noise, 2, platform::task_pause_point()};
    auto decisions = std::make_shared<std::uint64_t>(0);  // shared by the copies of `decide`
    return game::SnookerPlayer{[settings, seed, decisions](const game::SnookerSession& s) {
                                   return snooker_decision(s, settings,
                                                           ai::decision_seed(seed, (*decisions)++));
                               },
                               ai::planned_scale({*level, 1.0, 2})};
}

std::optional<game::CaromPlayer> carom_computer(const std::string& kind, std::uint64_t seed,
                                                double noise) {
    if (kind == "random") return game::random_carom_player(seed);
    const std::optional<int> level = ai_level(kind);
    if (!level) return std::nullopt;
    const ai::PlanSettings settings{*level, noise, 2, platform::task_pause_point()};
    auto decisions = std::make_shared<std::uint64_t>(0);
    return game::CaromPlayer{[settings, seed, decisions](const game::CaromSession& s) {
                                 const auto& c = s.config();
                                 game::MatchDecision d;
                                 d.stroke = ai::plan_three_cushion(
                                                {c.options, s.table(), c.params, s.state()},
                                                settings, ai::decision_seed(seed, (*decisions)++))
                                                .stroke;
                                 return d;
                             },
                             ai::planned_scale({*level, 1.0, 2})};
}

std::string seat_words(const std::string& kind) {
    if (kind == "human") return "Human";
    if (kind == "random") return "Computer (random)";
    return "Computer (level " + kind.substr(3) + ")";
}

std::array<std::string, 2> seat_names(const std::array<std::string, 2>& names,
                                      const std::array<std::string, 2>& kinds) {
    std::array<std::string, 2> out = names;
    const bool twins = kinds[0] == kinds[1];
    for (std::size_t i = 0; i < 2; ++i) {
        if (kinds[i] == "human" || names[i] != fmt::format("Player {}", i + 1)) continue;
        out[i] = seat_words(kinds[i]);
        if (twins) out[i].insert(std::string("Computer").size(), fmt::format(" {}", i + 1));
    }
    return out;
}

}  // namespace app
