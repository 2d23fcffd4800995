// The document verbs from text to text: what coolaaber-cli runs on its input, and the entry
// point of the fuzz targets.
#include "cli/commands.hpp"
#include "cli/json_in.hpp"
#include "cli/json_out.hpp"

namespace cli {

std::string run_document(DocumentVerb verb, std::string_view text, bool pretty) {
    const nlohmann::json input = parse_document(text);
    nlohmann::ordered_json output;
    switch (verb) {
        case DocumentVerb::simulate:
            output = simulate_command(input);
            break;
        case DocumentVerb::judge:
            output = judge_command(input);
            break;
        case DocumentVerb::decide:
            output = decide_command(input);
            break;
    }
    return write_document(output, pretty);
}

}  // namespace cli
