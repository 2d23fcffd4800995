#include "app/seats.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "ai/ai.hpp"
#include "game/random_player.hpp"

namespace app {

std::unique_ptr<game::Player> make_computer(const std::string& kind, std::uint64_t seed,
                                            double noise) {
    if (kind == "human") return nullptr;
    if (kind == "random") return std::make_unique<game::RandomPlayer>(seed);
    if (kind.size() == 4 && kind.rfind("ai:", 0) == 0 && kind[3] >= '1' && kind[3] <= '5') {
        return std::make_unique<ai::AiPlayer>(kind[3] - '0', seed, noise);
    }
    throw std::invalid_argument("unknown player \"" + kind +
                                "\" (expected human, random or ai:1 to ai:5)");
}

std::optional<game::SnookerPlayer> snooker_computer(const std::string& kind, std::uint64_t seed,
                                                    double /*noise*/) {
    if (kind == "random") return game::random_snooker_player(seed);
    return std::nullopt;  // the AI's snooker player is wired in here
}

std::optional<game::CaromPlayer> carom_computer(const std::string& kind, std::uint64_t seed,
                                                double /*noise*/) {
    if (kind == "random") return game::random_carom_player(seed);
    return std::nullopt;  // the AI's three-cushion player is wired in here
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
