// --screenshot in the browser: there is no offscreen context (EGL) on the web.
#include <cstdio>

#include "app/app.hpp"

namespace app {

int run_screenshot(const AppOptions&) {
    std::fputs("coolaaber: --screenshot is not available in the browser\n", stderr);
    return 2;
}

}  // namespace app
