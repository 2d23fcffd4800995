// Inside the platform layer: the web loop gives the tasks (platform::Task) their time slice
// before each frame. A no-op where they run on threads (platform_task_threads.cpp).
#pragma once

namespace app::platform {

/// Runs the oldest unfinished task for a few milliseconds (the web page without threads).
void run_task_slice();

}  // namespace app::platform
