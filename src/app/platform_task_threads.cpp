// platform::Task on a thread of its own: the desktop, and the web page with threads (Emscripten's
// pthreads, docs/web.md).
#include <chrono>
#include <future>

#include "app/platform.hpp"
#include "app/platform_slices.hpp"

namespace app::platform {

namespace {

class ThreadTask final : public Task {
  public:
    explicit ThreadTask(std::function<void()> work)
        : future_(std::async(std::launch::async, std::move(work))) {}
    // std::async's future waits for its thread when it goes.
    bool done() override {
        return future_.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
    }
    void wait() override { future_.wait(); }

  private:
    std::future<void> future_;
};

}  // namespace

std::unique_ptr<Task> start_task(std::function<void()> work) {
    return std::make_unique<ThreadTask>(std::move(work));
}

PausePoint task_pause_point() {
    return nullptr;
}

void run_task_slice() {
    // The tasks run on their threads.
}

}  // namespace app::platform
