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

/// {"phase", "to_act", "moving", "busy", "thinking", "view", "sound", "power", "shots",
/// "game_number",
///  "info": [lines], "last_shot", "refusal", "winner", "heading_deg", "cue_ball", "balls_on_table",
///  "positions": {"id": [x, y]} (exact), "aim_guide_level", "aim_foul", "call": {"ball",
///  "pocket"} or null, "guide_end", "widgets", "frames", "drawn", "link_note", "ball_px": {"id":
///  [x, y]}, "practice", "panel_height", "table_view": [w, h]}
/// What the last frame showed, beside the controller's state.
struct FrameFacts {
    std::map<std::string, std::array<float, 4>> widgets;  ///< PanelState::widgets
    long frames = 0;                  ///< frames drawn so far (for measuring the frame rate)
    bool cue = false;                 ///< the cue stick was drawn
    bool aim_guide = false;           ///< the aim guide was drawn
    bool ball_in_hand = false;        ///< the ball-in-hand marker was drawn
    int marks = 0;                    ///< rings drawn on the cloth (the call, the guide's path end)
    bool aim_illegal = false;         ///< the guide was drawn red (a foul as aimed)
    std::array<int, 2> window{0, 0};  ///< the window's size (unit: px)
    int panel_width = 0;              ///< (unit: px)
    int panel_height = 0;             ///< below the table; 0 at the right (unit: px)
    std::array<int, 2> table_view{0, 0};  ///< the table view at the top left (unit: px)
    std::string link_note;                ///< the shot link line in the information bar, if shown
    std::map<int, std::array<double, 2>> ball_px;  ///< where each ball is seen (unit: px)
};

std::string status_json(const Controller& c, const Settings& s, CameraMode view,
                        const FrameFacts& frame);

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
