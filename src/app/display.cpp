#include "app/display.hpp"

#include <SDL.h>
#include <fmt/format.h>
#include <unistd.h>

#include <cstdio>
#include <cstdlib>

namespace app {

namespace {

bool set(const char* variable) {
    const char* v = std::getenv(variable);
    return v && *v;
}

// The display named in the environment, for messages (":0", "wayland-0").
std::string display_name() {
    for (const char* v : {"DISPLAY", "WAYLAND_DISPLAY"})
        if (set(v)) return std::getenv(v);
    return "(none)";
}

constexpr const char* no_server =
    "no display server accepted the connection (is it running, and does it let this user in?)";
constexpr const char* what_to_do =
    "check DISPLAY, or run it under a virtual display (xvfb-run -a ./play)";

// Xlib writes its own complaints ("Authorization required, ...") to stderr: they are caught
// while SDL starts and become part of the one message, or are passed on if it starts.
class CaughtStderr {
  public:
    CaughtStderr() {
        std::fflush(stderr);
        file_ = std::tmpfile();
        saved_ = file_ ? ::dup(STDERR_FILENO) : -1;
        if (saved_ >= 0) ::dup2(::fileno(file_), STDERR_FILENO);
    }
    ~CaughtStderr() { release(); }
    CaughtStderr(const CaughtStderr&) = delete;
    CaughtStderr& operator=(const CaughtStderr&) = delete;

    /// Restores stderr; returns what was written meanwhile.
    std::string release() {
        if (saved_ < 0) return {};
        std::fflush(stderr);
        ::dup2(saved_, STDERR_FILENO);
        ::close(saved_);
        saved_ = -1;
        std::string text;
        std::rewind(file_);
        for (int ch; (ch = std::fgetc(file_)) != EOF;) text += static_cast<char>(ch);
        std::fclose(file_);
        return text;
    }

  private:
    std::FILE* file_ = nullptr;
    int saved_ = -1;
};

// The first non-empty line of `text`, without the trailing dot.
std::string first_line(const std::string& text) {
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string::npos) end = text.size();
        std::string line = text.substr(start, end - start);
        while (!line.empty() && (line.back() == '.' || line.back() == ' ')) line.pop_back();
        if (!line.empty()) return line;
        start = end + 1;
    }
    return {};
}

}  // namespace

std::optional<std::string> open_video() {
    if (!set("DISPLAY") && !set("WAYLAND_DISPLAY") && !set("SDL_VIDEODRIVER"))
        return "cannot open a window: no display (DISPLAY and WAYLAND_DISPLAY are not set): run "
               "it in a desktop session, under a virtual display (xvfb-run -a ./play), or render "
               "a picture with --screenshot FILE";
    const std::string display = display_name();
    // With an X display and no Wayland one only X11 is tried: SDL's other drivers would print
    // their own complaints, or fall back to an offscreen window the player never sees.
    const bool x11_only = set("DISPLAY") && !set("WAYLAND_DISPLAY") && !set("SDL_VIDEODRIVER");
    if (x11_only) SDL_SetHint(SDL_HINT_VIDEODRIVER, "x11");
    CaughtStderr caught;
    const bool started = SDL_Init(SDL_INIT_VIDEO | SDL_INIT_TIMER) == 0;
    const std::string said = caught.release();
    if (started) {
        std::fputs(said.c_str(), stderr);
        return std::nullopt;
    }
    if (!x11_only)
        return fmt::format("cannot open a window on display {}: {}", display, SDL_GetError());
    const std::string why = first_line(said);
    return fmt::format("cannot open a window on display {}: {}{}; {}", display, no_server,
                       why.empty() ? "" : " (" + why + ")", what_to_do);
}

}  // namespace app
