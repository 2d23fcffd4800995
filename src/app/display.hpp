// Opening SDL's video on a display the player can see, or one clear line saying why not
// (docs/app.md, "Command line": no display).
#pragma once

#include <optional>
#include <string>

namespace app {

/// Starts SDL's video and timer. Empty when a window can be shown; else the one-line message
/// for stderr ("cannot open a window on display :77: ..."), SDL shut down again.
std::optional<std::string> open_video();

}  // namespace app
