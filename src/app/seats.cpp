#include "app/seats.hpp"

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

}  // namespace app
