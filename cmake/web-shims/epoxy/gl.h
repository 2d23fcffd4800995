// The web build's <epoxy/gl.h> (cmake/web.cmake): WebGL 2 is OpenGL ES 3.0, Emscripten's own
// header; render's sources stay as they are for the desktop's libepoxy.
#pragma once
#include <GLES3/gl3.h>

// GLES has glClearDepthf only, not desktop GL's double-precision glClearDepth.
inline void glClearDepth(double depth) {
    glClearDepthf(static_cast<float>(depth));
}
