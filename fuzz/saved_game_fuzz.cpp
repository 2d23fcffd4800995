// libFuzzer target for the saved game: any bytes in, a session or game::LoadError out
// (docs/game.md, "Save format").
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "game/json_field.hpp"
#include "game/session.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::optional<game::Session> session;
    try {
        session.emplace(
            game::Session::from_json(std::string(reinterpret_cast<const char*>(data), size)));
    } catch (const game::LoadError&) {
        return 0;
    }
    // What loads must save and load again to the same session (resuming relies on it): an
    // exception escaping here or a trap aborts, and the fuzzer reports the input.
    const std::string saved = session->to_json();
    if (game::Session::from_json(saved).to_json() != saved) __builtin_trap();
    return 0;
}
