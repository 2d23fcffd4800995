// libFuzzer target for the game's settings file: any bytes in, settings or game::LoadError out
// (docs/app.md).
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "app/settings.hpp"
#include "game/json_field.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::optional<app::Settings> settings;
    try {
        settings = app::settings_from_json(std::string(reinterpret_cast<const char*>(data), size));
    } catch (const game::LoadError&) {
        return 0;
    }
    // What loads must save and load again: an exception escaping here aborts, and the fuzzer
    // reports the input.
    (void)app::settings_from_json(app::settings_to_json(*settings));
    return 0;
}
