// An OpenGL 3.3 core (or OpenGL ES 3.0) context with no display and no window (EGL on Mesa: the
// surfaceless platform, else a pbuffer on the default display), for tests, goldens and the
// benchmark.
#pragma once

#include <memory>
#include <string>

namespace render {

/// Which API the context speaks: desktop OpenGL 3.3 core, or OpenGL ES 3.0 (to check that
/// the shaders compile as GLSL ES 3.00).
enum class HeadlessApi { gl33_core, gles30 };

class HeadlessContext {
  public:
    /// Creates the context and makes it current. Throws std::runtime_error naming the EGL step
    /// that failed (e.g. "eglInitialize failed: install libegl-mesa0 and libgl1-mesa-dri").
    explicit HeadlessContext(HeadlessApi api = HeadlessApi::gl33_core);
    ~HeadlessContext();
    HeadlessContext(const HeadlessContext&) = delete;
    HeadlessContext& operator=(const HeadlessContext&) = delete;

    /// GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)".
    std::string renderer_name() const;

  private:
    struct Impl;
    std::unique_ptr<Impl> impl_;
};

}  // namespace render
