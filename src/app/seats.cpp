#include "app/seats.hpp"

#include <stdexcept>

#include "game/random_player.hpp"
#ifdef COOLAABER_HAVE_AI
#include "ai/ai.hpp"
#endif

namespace app {

bool ai_available() {
#ifdef COOLAABER_HAVE_AI
    return true;
#else
    return false;
#endif
}

std::unique_ptr<game::Player> make_computer(const std::string& kind, std::uint64_t seed,
                                            double noise) {
    if (kind == "human") return nullptr;
    if (kind == "random") return std::make_unique<game::RandomPlayer>(seed);
    if (kind.size() == 4 && kind.rfind("ai:", 0) == 0 && kind[3] >= '1' && kind[3] <= '5') {
#ifdef COOLAABER_HAVE_AI
        return std::make_unique<ai::AiPlayer>(kind[3] - '0', seed, noise);
#else
        (void)noise;
        throw std::invalid_argument("player \"" + kind + "\": this build has no AI (src/ai)");
#endif
    }
    throw std::invalid_argument("unknown player \"" + kind +
                                "\" (expected human, random or ai:1 to ai:5)");
}

}  // namespace app
