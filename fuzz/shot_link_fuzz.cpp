// libFuzzer target for shot links (docs/game.md, "Shot links"): any payload bytes, made a link
// with its right checksum so that the fuzzer reaches the readers behind it (pool's position,
// a snooker or three-cushion match), give a shot or game::LoadError.
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

#include "game/json_field.hpp"
#include "game/shot_link.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view payload(reinterpret_cast<const char*>(data), size);
    std::optional<game::AnyShot> shot;
    try {
        shot.emplace(game::read_any_shot_link(game::link_of_payload(payload)));
    } catch (const game::LoadError&) {
        return 0;
    }
    // What reads must write a link that reads to the same link (a shared shot opens as sent).
    const std::string link = game::shot_link(*shot);
    if (game::shot_link(game::read_any_shot_link(link)) != link) __builtin_trap();
    return 0;
}
