#include "render/headless_context.hpp"

#include <epoxy/egl.h>
#include <epoxy/gl.h>

#include <stdexcept>
#include <string_view>

namespace render {

struct HeadlessContext::Impl {
    EGLDisplay display = EGL_NO_DISPLAY;
    EGLContext context = EGL_NO_CONTEXT;
    EGLSurface surface = EGL_NO_SURFACE;
};

namespace {

[[noreturn]] void fail(std::string_view step) {
    throw std::runtime_error(std::string(step) + " failed (EGL error 0x" + [] {
        char buf[16];
        std::snprintf(buf, sizeof buf, "%04x", static_cast<unsigned>(eglGetError()));
        return std::string(buf);
    }() + "): a headless GL needs Mesa's EGL (libegl-mesa0, libgl1-mesa-dri)");
}

bool has_extension(const char* list, std::string_view name) {
    if (!list) return false;
    std::string_view all(list);
    for (std::size_t pos = 0; (pos = all.find(name, pos)) != std::string_view::npos;
         pos += name.size()) {
        bool starts = pos == 0 || all[pos - 1] == ' ';
        bool ends = pos + name.size() == all.size() || all[pos + name.size()] == ' ';
        if (starts && ends) return true;
    }
    return false;
}

EGLDisplay open_display(bool& surfaceless) {
    const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
    surfaceless = false;
    if (has_extension(client, "EGL_MESA_platform_surfaceless")) {
        EGLDisplay d =
            eglGetPlatformDisplayEXT(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
        if (d != EGL_NO_DISPLAY && eglInitialize(d, nullptr, nullptr)) {
            surfaceless = true;
            return d;
        }
    }
    EGLDisplay d = eglGetDisplay(EGL_DEFAULT_DISPLAY);
    if (d == EGL_NO_DISPLAY || !eglInitialize(d, nullptr, nullptr)) fail("eglInitialize");
    return d;
}

}  // namespace

HeadlessContext::HeadlessContext(HeadlessApi api) : impl_(std::make_unique<Impl>()) {
    bool surfaceless = false;
    impl_->display = open_display(surfaceless);
    const bool es = api == HeadlessApi::gles30;
    if (!eglBindAPI(es ? EGL_OPENGL_ES_API : EGL_OPENGL_API))
        fail(es ? "eglBindAPI(EGL_OPENGL_ES_API)" : "eglBindAPI(EGL_OPENGL_API)");
    const EGLint config_attribs[] = {EGL_SURFACE_TYPE,
                                     surfaceless ? 0 : EGL_PBUFFER_BIT,
                                     EGL_RENDERABLE_TYPE,
                                     es ? EGL_OPENGL_ES3_BIT : EGL_OPENGL_BIT,
                                     EGL_RED_SIZE,
                                     8,
                                     EGL_GREEN_SIZE,
                                     8,
                                     EGL_BLUE_SIZE,
                                     8,
                                     EGL_NONE};
    EGLConfig config = nullptr;
    EGLint count = 0;
    if (!eglChooseConfig(impl_->display, config_attribs, &config, 1, &count) || count < 1)
        fail("eglChooseConfig");
    const EGLint gl_attribs[] = {EGL_CONTEXT_MAJOR_VERSION,
                                 3,
                                 EGL_CONTEXT_MINOR_VERSION,
                                 3,
                                 EGL_CONTEXT_OPENGL_PROFILE_MASK,
                                 EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                                 EGL_NONE};
    const EGLint es_attribs[] = {EGL_CONTEXT_MAJOR_VERSION, 3, EGL_CONTEXT_MINOR_VERSION, 0,
                                 EGL_NONE};
    impl_->context =
        eglCreateContext(impl_->display, config, EGL_NO_CONTEXT, es ? es_attribs : gl_attribs);
    if (impl_->context == EGL_NO_CONTEXT)
        fail(es ? "eglCreateContext (OpenGL ES 3.0)" : "eglCreateContext (OpenGL 3.3 core)");
    if (!surfaceless) {
        const EGLint pbuffer_attribs[] = {EGL_WIDTH, 16, EGL_HEIGHT, 16, EGL_NONE};
        impl_->surface = eglCreatePbufferSurface(impl_->display, config, pbuffer_attribs);
        if (impl_->surface == EGL_NO_SURFACE) fail("eglCreatePbufferSurface");
    }
    if (!eglMakeCurrent(impl_->display, impl_->surface, impl_->surface, impl_->context))
        fail("eglMakeCurrent");
}

HeadlessContext::~HeadlessContext() {
    if (impl_->display == EGL_NO_DISPLAY) return;
    eglMakeCurrent(impl_->display, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    if (impl_->surface != EGL_NO_SURFACE) eglDestroySurface(impl_->display, impl_->surface);
    if (impl_->context != EGL_NO_CONTEXT) eglDestroyContext(impl_->display, impl_->context);
    eglTerminate(impl_->display);
}

std::string HeadlessContext::renderer_name() const {
    const auto* name = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    return name ? name : "";
}

}  // namespace render
