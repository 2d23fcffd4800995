// libFuzzer target for one coolaaber-cli verb (simulate, judge or decide, chosen at build time
// by COOLAABER_FUZZ_VERB): any bytes in, an output document or cli::BadInput out. A crash, a
// sanitizer report, a leak or a hang is a defect (docs/cli.md, "General rules").
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "cli/commands.hpp"
#include "cli/json_in.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    const std::string_view text(reinterpret_cast<const char*>(data), size);
    try {
        (void)cli::run_document(cli::DocumentVerb::COOLAABER_FUZZ_VERB, text);
    } catch (const cli::BadInput&) {
        // The promised answer to bad input.
    }
    return 0;
}
