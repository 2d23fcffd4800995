// The web platform (platform.hpp): the page's canvas through Emscripten's GLFW with a WebGL 2
// context, Dear ImGui's GLFW and OpenGL ES 3 backends, and the browser's animation frames as the
// loop. The canvas follows the page's size (src/app/web/shell.html lays it out).
#define GLFW_INCLUDE_ES3
#include <GLFW/glfw3.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_opengl3.h>
#include <emscripten.h>
#include <emscripten/html5.h>
#include <imgui.h>

#include <cmath>
#include <string>

#include "app/platform.hpp"
#include "app/platform_slices.hpp"

namespace app::platform {

namespace {

Key key_of(int k) {
    switch (k) {
        case GLFW_KEY_LEFT:
            return Key::left;
        case GLFW_KEY_RIGHT:
            return Key::right;
        case GLFW_KEY_UP:
            return Key::up;
        case GLFW_KEY_DOWN:
            return Key::down;
        case GLFW_KEY_SPACE:
            return Key::space;
        case GLFW_KEY_V:
            return Key::v;
        case GLFW_KEY_S:
            return Key::s;
        case GLFW_KEY_ENTER:
            return Key::enter;
        case GLFW_KEY_P:
            return Key::p;
        case GLFW_KEY_H:
            return Key::h;
        case GLFW_KEY_G:
            return Key::g;
        case GLFW_KEY_O:
            return Key::o;
        case GLFW_KEY_R:
            return Key::r;
        case GLFW_KEY_ESCAPE:
            return Key::escape;
        case GLFW_KEY_F11:
            return Key::f11;
        default:
            return Key::other;
    }
}

// The canvas's pixels: its size on the page (CSS px) times the device's pixels per CSS pixel,
// so that a high-density screen gets a sharp picture.
std::pair<int, int> page_size() {
    double w = 0, h = 0;
    emscripten_get_element_css_size("#canvas", &w, &h);
    const double dpr = emscripten_get_device_pixel_ratio();
    return {std::max(1, static_cast<int>(std::lround(w * dpr))),
            std::max(1, static_cast<int>(std::lround(h * dpr)))};
}

class WebWindow final : public Window {
  public:
    explicit WebWindow(GLFWwindow* window) : window_(window) {
        // Installed before ImGui's, which chain to them (ImGui_ImplGlfw_InitForOpenGL).
        glfwSetWindowUserPointer(window_, this);
        glfwSetCursorPosCallback(window_, [](GLFWwindow* w, double x, double y) {
            Event e = Event::of(Event::Kind::motion);
            e.x = x;
            e.y = y;
            self(w).queue_.push_back(e);
        });
        glfwSetMouseButtonCallback(window_, [](GLFWwindow* w, int button, int action, int) {
            Event e = Event::of(Event::Kind::button);
            glfwGetCursorPos(w, &e.x, &e.y);
            e.button = button == GLFW_MOUSE_BUTTON_LEFT    ? 0
                       : button == GLFW_MOUSE_BUTTON_RIGHT ? 1
                                                           : 2;
            e.down = action == GLFW_PRESS;
            self(w).queue_.push_back(e);
        });
        glfwSetScrollCallback(window_, [](GLFWwindow* w, double, double y) {
            Event e = Event::of(Event::Kind::wheel);
            e.wheel = static_cast<float>(y);
            self(w).queue_.push_back(e);
        });
        glfwSetKeyCallback(window_, [](GLFWwindow* w, int key, int, int action, int mods) {
            Event e = Event::of(action == GLFW_RELEASE ? Event::Kind::other : Event::Kind::key);
            e.key = key_of(key);
            e.shift = (mods & GLFW_MOD_SHIFT) != 0;
            e.ctrl = (mods & GLFW_MOD_CONTROL) != 0;
            self(w).queue_.push_back(e);
        });
        glfwSetCharCallback(window_, [](GLFWwindow* w, unsigned) {
            self(w).queue_.push_back(Event::of(Event::Kind::other));
        });
        listen_to_touch();
    }
    ~WebWindow() override {
        glfwDestroyWindow(window_);
        glfwTerminate();
    }
    WebWindow(const WebWindow&) = delete;
    WebWindow& operator=(const WebWindow&) = delete;

    void start_imgui() override {
        ImGui_ImplGlfw_InitForOpenGL(window_, true);
        ImGui_ImplOpenGL3_Init("#version 300 es");
    }
    void stop_imgui() override {
        ImGui_ImplOpenGL3_Shutdown();
        ImGui_ImplGlfw_Shutdown();
    }

    std::vector<Event> events(int) override {
        glfwPollEvents();
        follow_the_page();
        follow_the_address();
        std::vector<Event> out;
        out.swap(queue_);
        return out;
    }

    void new_imgui_frame() override {
        ImGui_ImplOpenGL3_NewFrame();
        ImGui_ImplGlfw_NewFrame();
        // Two frames in the same millisecond (a headless browser's virtual time) give 0.
        ImGuiIO& io = ImGui::GetIO();
        io.DeltaTime = std::max(io.DeltaTime, 1e-4f);
    }
    void present() override { glfwSwapBuffers(window_); }
    std::pair<int, int> drawable_size() const override {
        int w = 0, h = 0;
        glfwGetFramebufferSize(window_, &w, &h);
        return {w, h};
    }
    double pixels_per_point() const override { return emscripten_get_device_pixel_ratio(); }
    // Per CSS pixel (a 96th of an inch), the panel's unit; with a finger for a pointer (a phone,
    // a tablet) as for one and a half times that, its controls big enough to tap.
    float dpi() const override {
        return EM_ASM_INT({ return matchMedia('(pointer: coarse)').matches ? 1 : 0; }) ? 144.0f
                                                                                       : 96.0f;
    }
    bool fullscreen() const override {
        EmscriptenFullscreenChangeEvent s{};
        return emscripten_get_fullscreen_status(&s) == EMSCRIPTEN_RESULT_SUCCESS && s.isFullscreen;
    }
    void set_fullscreen(bool on) override {
        // The browser allows it only in a key or click's handler: deferred until the next one.
        if (on)
            emscripten_request_fullscreen("#canvas", true);
        else
            emscripten_exit_fullscreen();
    }
    bool shift_held() const override {
        return glfwGetKey(window_, GLFW_KEY_LEFT_SHIFT) == GLFW_PRESS ||
               glfwGetKey(window_, GLFW_KEY_RIGHT_SHIFT) == GLFW_PRESS;
    }
    // WebGL 2 cannot blit the renderer's cached table into a multisampled view: one sample
    // keeps the cache, which a software renderer (and a phone) needs for a fluid frame rate.
    int table_samples() const override { return 1; }
    std::string clipboard() const override {
        return {};  // the browser reads the clipboard only asynchronously, with permission
    }
    std::optional<std::string> copy_link(const std::string& link) override {
        EM_ASM(
            {
                var url = location.href.split('#')[0] + '#' + UTF8ToString($0);
                navigator.clipboard.writeText(url).catch(function(e) {
                    console.warn('The shot link was not copied (' + e + '): ' + url);
                });
            },
            link.c_str());
        return std::nullopt;
    }
    bool saves_as_it_goes() const override { return true; }
    void files_written() override {
        EM_ASM({ Module.coolaaberStoreFiles(); });  // src/app/web/files.js
    }

  private:
    // One finger is the left mouse button (aim without striking, drag the ball in hand, press
    // the panel's Strike): Emscripten's GLFW would press it at the last mouse position, so its
    // own touch listeners are replaced.
    void listen_to_touch() {
        EM_ASM({
            var canvas = Module['canvas'];
            canvas.removeEventListener('touchstart', GLFW.onMouseButtonDown, true);
            canvas.removeEventListener('touchmove', GLFW.onMousemove, true);
            canvas.removeEventListener('touchend', GLFW.onMouseButtonUp, true);
            canvas.removeEventListener('touchcancel', GLFW.onMouseButtonUp, true);
        });
        emscripten_set_touchstart_callback("#canvas", this, true, on_touch);
        emscripten_set_touchmove_callback("#canvas", this, true, on_touch);
        emscripten_set_touchend_callback("#canvas", this, true, on_touch);
        emscripten_set_touchcancel_callback("#canvas", this, true, on_touch);
    }

    static EM_BOOL on_touch(int type, const EmscriptenTouchEvent* t, void* data) {
        auto& me = *static_cast<WebWindow*>(data);
        for (int i = 0; i < t->numTouches; ++i) {
            const EmscriptenTouchPoint& p = t->touches[i];
            if (!p.isChanged) continue;
            const bool start = type == EMSCRIPTEN_EVENT_TOUCHSTART;
            if (start && me.finger_ < 0) me.finger_ = p.identifier;
            if (p.identifier != me.finger_) continue;
            Event e = Event::of(Event::Kind::motion);
            const double dpr = emscripten_get_device_pixel_ratio();  // CSS px to the canvas's
            e.x = static_cast<double>(p.targetX) * dpr;
            e.y = static_cast<double>(p.targetY) * dpr;
            me.queue_.push_back(e);
            if (type == EMSCRIPTEN_EVENT_TOUCHMOVE) continue;
            e.kind = Event::Kind::button;
            e.button = 0;
            e.down = start;
            me.queue_.push_back(e);
            if (!start) me.finger_ = -1;
        }
        return EM_TRUE;  // no mouse events made up from the touch, no scrolling
    }

    static WebWindow& self(GLFWwindow* w) {
        return *static_cast<WebWindow*>(glfwGetWindowUserPointer(w));
    }

    // The canvas's pixels follow its size on the page (a resized or rotated window).
    void follow_the_page() {
        const auto [w, h] = page_size();
        int cw = 0, ch = 0;
        glfwGetWindowSize(window_, &cw, &ch);
        if (w == cw && h == ch) return;
        EM_ASM({ Browser.setCanvasSize($0, $1); }, w, h);
        queue_.push_back(Event::of(Event::Kind::other));
    }

    // A shot link in the page's address (its fragment, "#shot=..."): when the page opens, and
    // when the address changes to another link.
    void follow_the_address() {
        const int size = EM_ASM_INT({ return lengthBytesUTF8(location.hash) + 1; });
        std::string now(static_cast<std::size_t>(size), '\0');
        EM_ASM({ stringToUTF8(location.hash, $0, $1); }, now.data(), size);
        now.resize(now.find('\0'));
        if (now == address_) return;
        address_ = now;
        if (now.rfind("#shot=", 0) != 0) return;
        Event e = Event::of(Event::Kind::link);
        e.text = now;
        queue_.push_back(e);
    }

    GLFWwindow* window_;
    std::vector<Event> queue_;
    std::string address_;
    long finger_ = -1;  ///< the touch that is the mouse
};

}  // namespace

std::unique_ptr<Window> Window::open(int, int, bool, std::string& why) {
    if (!glfwInit()) {
        why = "the browser's window system did not start";
        return nullptr;
    }
    glfwWindowHint(GLFW_CLIENT_API, GLFW_OPENGL_ES_API);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MAJOR, 3);
    glfwWindowHint(GLFW_CONTEXT_VERSION_MINOR, 0);
    const auto [w, h] = page_size();
    GLFWwindow* window = glfwCreateWindow(w, h, "Coolaaber", nullptr, nullptr);
    if (!window) {
        why =
            "WebGL 2 is needed, and this browser does not offer it: turn on hardware "
            "acceleration, or open the page in a current Chrome, Edge, Firefox or Safari";
        glfwTerminate();
        return nullptr;
    }
    glfwMakeContextCurrent(window);
    return std::make_unique<WebWindow>(window);
}

void run(std::function<bool()> frame) {
    // The browser owns the loop: the frame outlives main(), until it returns false.
    auto* owned = new std::function<bool()>(std::move(frame));
    emscripten_set_main_loop_arg(
        [](void* arg) {
            // Without threads the computer thinks here, a slice before each frame.
            run_task_slice();
            auto* f = static_cast<std::function<bool()>*>(arg);
            if ((*f)()) return;
            emscripten_cancel_main_loop();
            delete f;
        },
        owned, 0, false);
}

}  // namespace app::platform
