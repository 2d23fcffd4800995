#include "ai/pause.hpp"

#include "ai/internal/parallel.hpp"

namespace ai {

namespace {
// Per thread: the desktop's simulation workers never pause, only the thread that set the hook.
thread_local PauseHook hook = nullptr;
}  // namespace

PauseHook set_pause_hook(PauseHook h) {
    const PauseHook old = hook;
    hook = h;
    return old;
}

void pause_point() {
    if (hook) hook();
}

}  // namespace ai
