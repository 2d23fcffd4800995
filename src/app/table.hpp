// The game at the table: a controller and its camera, the panel's state and the settings, as
// one window or one screenshot shows them; what the panel's actions and the keys do to it.
#pragma once

#include <array>
#include <map>
#include <string>

#include "app/camera_rig.hpp"
#include "app/controller.hpp"
#include "app/game_setup.hpp"
#include "app/panel.hpp"
#include "app/platform.hpp"
#include "app/settings.hpp"
#include "render/camera.hpp"

namespace app {

struct Table {
    GameSetup setup;
    Controller controller;
    CameraRig rig;
    PanelState panel;
    render::Camera last_camera;
    Settings saved;  ///< the settings as last written
    bool exit_requested = false;

    explicit Table(GameSetup s);

    /// The shot link line shown in the information bar, until the next shot.
    std::string link_note_shown() const;
    void note_link(std::string text, bool is_error);
    /// Copy shot link: the last shot (or the shot as aimed) as link text on the clipboard.
    void copy_link(platform::Window& window);
    enum class LinkFrom { paste, address };
    /// Opens a shot link: its position and table, and its stroke played at once. A bad link is
    /// reported and the game is left as it was.
    void open_link(const std::string& text, LinkFrom from);
    void paste_link(const platform::Window& window);
    void start_practice(physics::RackType game);
    void save_position();
    void load_position();
    render::Camera camera(float aspect) const;
    /// Keeps the cue-ball view on the cue ball and the aim (frozen while the balls move).
    void follow_cue_ball();
    void set_power(double power);
    void change_view();
    void apply(const PanelActions& a, platform::Window* window);
    /// Writes the settings when they changed (the Sound checkbox, the power, the view...), so
    /// they persist at once and not only on Exit.
    void persist_settings();
    /// Saves an unfinished game where the next run resumes it (a finished one's save is
    /// removed); an error message or empty.
    std::string save_game() const;
    void save_and_close();

  private:
    void start_new_game(const NewGame& choice);
};

/// What the painter's table is built from (a pasted link may bring another table).
std::string table_key(const Controller& c);

/// Where each ball is seen in the table view (the status file's test hook).
std::map<int, std::array<double, 2>> ball_pixels(const Table& t, int width, int height);

/// The keyboard at the table (docs/app.md, "Playing").
void on_key(Table& t, platform::Window& window, const platform::Event& e);

}  // namespace app
