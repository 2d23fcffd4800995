#include "app/seats.hpp"

#include <stdexcept>

#include "game/random_player.hpp"

namespace app {

std::unique_ptr<game::Player> make_computer(const std::string& kind, std::uint64_t seed) {
    if (kind == "human") return nullptr;
    if (kind == "random") return std::make_unique<game::RandomPlayer>(seed);
    throw std::invalid_argument("unknown player \"" + kind + "\" (expected human or random)");
}

double own_noise_factor(const std::string& kind) {
    (void)kind;
    return 1.0;
}

}  // namespace app
