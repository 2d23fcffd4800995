// The platform layer: everything that touches the window system, input, the clipboard, timing
// and the main loop. One implementation per platform, chosen by CMake (src/app/CMakeLists.txt):
// platform_desktop.cpp (SDL2) and platform_web.cpp (Emscripten's GLFW, the browser's loop); and
// for the work beside the frames (Task), platform_task_threads.cpp (a thread: the desktop and the
// threaded web page) or platform_task_sliced.cpp (the web page without threads: time slices
// between the browser's frames). The game's frame (app.cpp) sees only this header.
#pragma once

#include <functional>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace app::platform {

/// The keys the table answers (docs/app.md, "Playing").
enum class Key { other, left, right, up, down, space, v, s, enter, p, h, g, o, r, escape, f11 };

/// One input or window event, in the window's pixels.
struct Event {
    /// link: a shot link to open (the web page's address changed to one); other: for ImGui
    enum class Kind { quit, motion, button, wheel, key, resized, link, other };
    Kind kind = Kind::motion;
    double x = 0, y = 0;  ///< motion, button (unit: px)
    int button = 0;       ///< 0 left, 1 right, 2 middle
    bool down = false;    ///< button
    float wheel = 0;      ///< wheel steps, up positive
    Key key = Key::other;
    bool shift = false, ctrl = false;  ///< key, motion
    int width = 0, height = 0;         ///< resized (unit: px), not in fullscreen
    std::string text;                  ///< link

    static Event of(Kind k) {
        Event e;
        e.kind = k;
        return e;
    }
};

/// The game's window with its OpenGL (desktop) or WebGL 2 (web) context, and Dear ImGui's
/// platform and renderer backends once start_imgui is called.
class Window {
  public:
    /// Opens the window; empty, and `why` set to one line for the player, when it cannot.
    static std::unique_ptr<Window> open(int width, int height, bool fullscreen, std::string& why);
    virtual ~Window() = default;

    /// Starts ImGui's backends (the ImGui context exists already); stop_imgui before it goes.
    virtual void start_imgui() = 0;
    virtual void stop_imgui() = 0;
    /// The events since the last call, waiting up to `wait_ms` for one when there are none
    /// (0: no wait; the web never waits, the browser calls the next frame).
    virtual std::vector<Event> events(int wait_ms) = 0;
    /// ImGui's new frame for both backends (before ImGui::NewFrame).
    virtual void new_imgui_frame() = 0;
    virtual void present() = 0;
    /// The drawable's size (unit: px).
    virtual std::pair<int, int> drawable_size() const = 0;
    /// The drawable's pixels per unit of the desktop's mouse (the web: device pixels per CSS
    /// pixel), so that a mouse's move aims alike on any screen.
    virtual double pixels_per_point() const = 0;
    /// The display's dots per inch of the mouse's units, 0 when unknown (the panel's scale
    /// follows it).
    virtual float dpi() const = 0;
    virtual bool fullscreen() const = 0;
    virtual void set_fullscreen(bool on) = 0;
    virtual bool shift_held() const = 0;
    /// The still table view's multisampling (app/painter.hpp).
    virtual int table_samples() const = 0;
    /// The clipboard's text ("" when empty or unreadable).
    virtual std::string clipboard() const = 0;
    /// Puts a shot link (game/shot_link.hpp) on the clipboard: as it is on the desktop, as the
    /// page's address with the link as its fragment on the web. The reason when it could not.
    virtual std::optional<std::string> copy_link(const std::string& link) = 0;
    /// True where the game has no exit to save on (a web page is closed or reloaded at any
    /// time): the game is then saved whenever a shot ends.
    virtual bool saves_as_it_goes() const = 0;
    /// The game's files (settings, saved game) were written: the web keeps them in the
    /// browser's storage (IndexedDB) from here.
    virtual void files_written() = 0;
};

/// Work that runs beside the frames (the computer player's and Hint's thinking): on its own
/// thread, or, in the web page without threads, in slices of a few milliseconds between the
/// browser's frames (it pauses at the AI's pause points, ai/pause.hpp).
class Task {
  public:
    /// Waits for the work to end first (it may use what its starter owns).
    virtual ~Task() = default;
    /// Whether the work has returned.
    virtual bool done() = 0;
    /// Returns once the work has (without threads: runs the rest of it now).
    virtual void wait() = 0;
};

/// Starts `work`, which catches what it throws.
std::unique_ptr<Task> start_task(std::function<void()> work);

/// The pause hook for the AI's settings (ai/pause.hpp, PlanSettings::pause) that lets a task
/// hand the CPU back between slices; null where tasks have threads of their own.
using PausePoint = void (*)();
PausePoint task_pause_point();

/// Calls `frame` until it returns false: a loop on the desktop; on the web, once per animation
/// frame of the browser, returning at once (the page lives on).
void run(std::function<bool()> frame);

}  // namespace app::platform
