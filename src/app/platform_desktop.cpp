// The desktop platform (platform.hpp): an SDL2 window with an OpenGL 3.3 core context, Dear
// ImGui's SDL and OpenGL 3 backends, and a plain loop.
#include <SDL.h>
#include <backends/imgui_impl_opengl3.h>
#include <backends/imgui_impl_sdl.h>
#include <epoxy/gl.h>
#include <fmt/format.h>

#include "app/display.hpp"
#include "app/platform.hpp"

namespace app::platform {

namespace {

Key key_of(SDL_Keycode k) {
    switch (k) {
        case SDLK_LEFT:
            return Key::left;
        case SDLK_RIGHT:
            return Key::right;
        case SDLK_UP:
            return Key::up;
        case SDLK_DOWN:
            return Key::down;
        case SDLK_SPACE:
            return Key::space;
        case SDLK_v:
            return Key::v;
        case SDLK_s:
            return Key::s;
        case SDLK_RETURN:
            return Key::enter;
        case SDLK_p:
            return Key::p;
        case SDLK_h:
            return Key::h;
        case SDLK_g:
            return Key::g;
        case SDLK_o:
            return Key::o;
        case SDLK_r:
            return Key::r;
        case SDLK_ESCAPE:
            return Key::escape;
        case SDLK_F11:
            return Key::f11;
        default:
            return Key::other;
    }
}

// SDL's event as the game's, if the game answers it.
std::optional<Event> event_of(const SDL_Event& e, SDL_Window* window) {
    Event out;
    switch (e.type) {
        case SDL_QUIT:
            out.kind = Event::Kind::quit;
            return out;
        case SDL_MOUSEMOTION:
            out.kind = Event::Kind::motion;
            out.x = e.motion.x;
            out.y = e.motion.y;
            return out;
        case SDL_MOUSEBUTTONDOWN:
        case SDL_MOUSEBUTTONUP:
            out.kind = Event::Kind::button;
            out.x = e.button.x;
            out.y = e.button.y;
            out.down = e.type == SDL_MOUSEBUTTONDOWN;
            out.button = e.button.button == SDL_BUTTON_LEFT    ? 0
                         : e.button.button == SDL_BUTTON_RIGHT ? 1
                                                               : 2;
            return out;
        case SDL_MOUSEWHEEL:
            out.kind = Event::Kind::wheel;
            out.wheel = static_cast<float>(e.wheel.y);
            return out;
        case SDL_KEYDOWN:
            out.kind = Event::Kind::key;
            out.key = key_of(e.key.keysym.sym);
            out.shift = (e.key.keysym.mod & KMOD_SHIFT) != 0;
            out.ctrl = (e.key.keysym.mod & KMOD_CTRL) != 0;
            return out;
        case SDL_WINDOWEVENT:
            if (e.window.event != SDL_WINDOWEVENT_SIZE_CHANGED ||
                (SDL_GetWindowFlags(window) & SDL_WINDOW_FULLSCREEN_DESKTOP))
                return std::nullopt;
            out.kind = Event::Kind::resized;
            out.width = e.window.data1;
            out.height = e.window.data2;
            return out;
        default:
            return std::nullopt;
    }
}

class SdlWindow final : public Window {
  public:
    SdlWindow(SDL_Window* window, SDL_GLContext gl) : window_(window), gl_(gl) {}
    ~SdlWindow() override {
        SDL_GL_DeleteContext(gl_);
        SDL_DestroyWindow(window_);
        SDL_Quit();
    }
    SdlWindow(const SdlWindow&) = delete;
    SdlWindow& operator=(const SdlWindow&) = delete;

    void start_imgui() override {
        ImGui_ImplSDL2_InitForOpenGL(window_, gl_);
        ImGui_ImplOpenGL3_Init("#version 330 core");
    }
    void stop_imgui() override {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplSDL2_Shutdown();
    }

    std::vector<Event> events(int wait_ms) override {
        std::vector<Event> out;
        SDL_Event e;
        bool have = wait_ms > 0 && SDL_WaitEventTimeout(&e, wait_ms) != 0;
        while (have || SDL_PollEvent(&e)) {
            have = false;
            ImGui_ImplSDL2_ProcessEvent(&e);
            // An event the game does not answer still counts: ImGui may have (a redraw).
            out.push_back(event_of(e, window_).value_or(Event::of(Event::Kind::other)));
        }
        return out;
    }

    void new_imgui_frame() override {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplSDL2_NewFrame();
    }
    void present() override { SDL_GL_SwapWindow(window_); }
    std::pair<int, int> drawable_size() const override {
        int w = 0, h = 0;
        SDL_GL_GetDrawableSize(window_, &w, &h);
        return {w, h};
    }
    double pixels_per_point() const override { return 1.0; }  // no SDL_WINDOW_ALLOW_HIGHDPI
    float dpi() const override {
        float dpi = 0.0f;
        return SDL_GetDisplayDPI(0, nullptr, &dpi, nullptr) == 0 ? dpi : 0.0f;
    }
    bool fullscreen() const override {
        return (SDL_GetWindowFlags(window_) & SDL_WINDOW_FULLSCREEN_DESKTOP) != 0;
    }
    void set_fullscreen(bool on) override {
        SDL_SetWindowFullscreen(window_, on ? SDL_WINDOW_FULLSCREEN_DESKTOP : 0);
    }
    bool shift_held() const override { return (SDL_GetModState() & KMOD_SHIFT) != 0; }
    int table_samples() const override { return 4; }
    std::string clipboard() const override {
        char* text = SDL_GetClipboardText();
        std::string out = text ? text : "";
        SDL_free(text);
        return out;
    }
    std::optional<std::string> copy_link(const std::string& link) override {
        if (SDL_SetClipboardText(link.c_str()) != 0) return std::string(SDL_GetError());
        return std::nullopt;
    }
    bool saves_as_it_goes() const override { return false; }  // saved on exit
    void files_written() override {}

  private:
    SDL_Window* window_;
    SDL_GLContext gl_;
};

}  // namespace

std::unique_ptr<Window> Window::open(int width, int height, bool fullscreen, std::string& why) {
    if (const std::optional<std::string> no = open_video()) {
        why = *no;
        return nullptr;
    }
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MAJOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_MINOR_VERSION, 3);
    SDL_GL_SetAttribute(SDL_GL_CONTEXT_PROFILE_MASK, SDL_GL_CONTEXT_PROFILE_CORE);
    SDL_GL_SetAttribute(SDL_GL_DOUBLEBUFFER, 1);
    Uint32 flags = SDL_WINDOW_OPENGL | SDL_WINDOW_RESIZABLE;
    if (fullscreen) flags |= SDL_WINDOW_FULLSCREEN_DESKTOP;
    SDL_Window* window = SDL_CreateWindow("Coolaaber", SDL_WINDOWPOS_CENTERED,
                                          SDL_WINDOWPOS_CENTERED, width, height, flags);
    if (!window) {
        why = std::string("cannot open a window: ") + SDL_GetError();
        SDL_Quit();
        return nullptr;
    }
    SDL_GLContext gl = SDL_GL_CreateContext(window);
    if (!gl || epoxy_gl_version() < 33) {
        why = fmt::format(
            "OpenGL 3.3 is needed, but this display offers {} ({}). Update the graphics driver, "
            "or run with Mesa's software renderer (LIBGL_ALWAYS_SOFTWARE=1).",
            gl ? reinterpret_cast<const char*>(glGetString(GL_VERSION)) : "none", SDL_GetError());
        if (gl) SDL_GL_DeleteContext(gl);
        SDL_DestroyWindow(window);
        SDL_Quit();
        return nullptr;
    }
    SDL_GL_MakeCurrent(window, gl);
    SDL_GL_SetSwapInterval(1);
    return std::make_unique<SdlWindow>(window, gl);
}

void run(std::function<bool()> frame) {
    while (frame()) {
    }
}

}  // namespace app::platform
