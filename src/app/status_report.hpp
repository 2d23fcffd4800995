// A test hook (--status-file): what the player sees, as JSON, rewritten whenever it changes,
// so end-to-end tests can wait for "the balls stopped" or read the information bar.
#pragma once

#include <array>
#include <filesystem>
#include <map>
#include <string>

#include "app/camera_rig.hpp"
#include "app/controller.hpp"
#include "app/settings.hpp"

namespace app {

/// {"phase", "to_act", "moving", "busy", "view", "sound", "power", "shots", "game_number",
///  "info": [lines], "last_shot", "refusal", "winner", "heading_deg", "cue_ball", "balls_on_table"}
/// `widgets`: where the panel's labelled widgets are (PanelState::widgets), as "widgets";
/// `frames`: frames drawn so far (for measuring the frame rate).
std::string status_json(const Controller& c, const Settings& s, CameraMode view,
                        const std::map<std::string, std::array<float, 4>>& widgets, long frames);

/// Writes `text` to `path` atomically when it differs from the last text written.
class StatusFile {
  public:
    explicit StatusFile(std::filesystem::path path) : path_(std::move(path)) {}
    void write(const std::string& text);

  private:
    std::filesystem::path path_;
    std::string last_;
};

}  // namespace app
