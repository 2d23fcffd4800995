// libFuzzer target for the game's settings file: any bytes in, settings or game::LoadError out
// (docs/app.md, "Files").
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
    // What loads must save and load again to the same settings: an exception escaping here or
    // a trap aborts, and the fuzzer reports the input.
    if (app::settings_from_json(app::settings_to_json(*settings)) != *settings) __builtin_trap();
    return 0;
}
