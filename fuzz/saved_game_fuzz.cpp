// libFuzzer target for the saved game: any bytes in, a session or game::LoadError out
// (docs/game.md, "Save and resume").
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
    // What loads must save and load again (resuming relies on it): an exception escaping here
    // aborts, and the fuzzer reports the input.
    (void)game::Session::from_json(session->to_json());
    return 0;
}
