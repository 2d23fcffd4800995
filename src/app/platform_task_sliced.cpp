// platform::Task without threads (the web page where SharedArrayBuffer is missing, docs/web.md):
// each task is a fiber (Emscripten's, on Asyncify) that runs a slice of a few milliseconds before
// each of the browser's frames and hands the CPU back at the AI's pause points (ai/pause.hpp), so
// the page keeps drawing while the computer thinks.
#include <emscripten/emscripten.h>
#include <emscripten/fiber.h>

#include <algorithm>
#include <cstdlib>
#include <deque>
#include <limits>
#include <vector>

#include "app/platform.hpp"
#include "app/platform_slices.hpp"

namespace app::platform {

namespace {

// 10 ms of each 16.7 ms refresh at 60 Hz: the rest is the frame's, and one with nothing new to
// draw (the computer thinking) takes little of it.
constexpr double kSliceMs = 10.0;
// The threaded page's threads have Emscripten's default of 2 MiB: the same for the fiber.
constexpr std::size_t kCStackBytes = 2 << 20;
constexpr std::size_t kAsyncifyBytes = 1 << 17;  // the paused frames' locals

class SlicedTask;

// The browser's side of the swaps, and the task now running.
struct Slices {
    emscripten_fiber_t browser{};
    std::vector<char> browser_asyncify = std::vector<char>(kAsyncifyBytes);
    bool browser_ready = false;
    std::deque<SlicedTask*> unfinished;  // oldest first
    SlicedTask* running = nullptr;
    double slice_end = 0.0;
};

Slices& slices() {
    static Slices s;
    return s;
}

class SlicedTask final : public Task {
  public:
    explicit SlicedTask(std::function<void()> work)
        : work_(std::move(work)), c_stack_(kCStackBytes), asyncify_(kAsyncifyBytes) {
        emscripten_fiber_init(&fiber_, &SlicedTask::enter, this, c_stack_.data(), c_stack_.size(),
                              asyncify_.data(), asyncify_.size());
        slices().unfinished.push_back(this);
    }
    ~SlicedTask() override { wait(); }

    bool done() override { return done_; }
    void wait() override {
        while (!done_) run_for(std::numeric_limits<double>::infinity());
    }

    /// Runs the work until it ends or pauses after `ms` milliseconds.
    void run_for(double ms) {
        Slices& s = slices();
        if (!s.browser_ready) {
            emscripten_fiber_init_from_current_context(&s.browser, s.browser_asyncify.data(),
                                                       s.browser_asyncify.size());
            s.browser_ready = true;
        }
        s.running = this;
        s.slice_end = emscripten_get_now() + ms;
        emscripten_fiber_swap(&s.browser, &fiber_);
        s.running = nullptr;
        if (done_) std::erase(s.unfinished, this);
    }

    /// The AI's pause point: back to the browser once the slice is spent.
    static void pause() {
        Slices& s = slices();
        if (s.running && emscripten_get_now() >= s.slice_end)
            emscripten_fiber_swap(&s.running->fiber_, &s.browser);
    }

  private:
    static void enter(void* arg) {
        auto* task = static_cast<SlicedTask*>(arg);
        {
            const std::function<void()> work = std::move(task->work_);
            work();
        }
        task->done_ = true;
        // A fiber never returns from its entry: back to the browser, for good.
        emscripten_fiber_swap(&task->fiber_, &slices().browser);
        std::abort();
    }

    std::function<void()> work_;
    std::vector<char> c_stack_, asyncify_;
    emscripten_fiber_t fiber_{};
    bool done_ = false;
};

}  // namespace

PausePoint task_pause_point() {
    return &SlicedTask::pause;
}

std::unique_ptr<Task> start_task(std::function<void()> work) {
    return std::make_unique<SlicedTask>(std::move(work));
}

void run_task_slice() {
    Slices& s = slices();
    if (!s.unfinished.empty()) s.unfinished.front()->run_for(kSliceMs);
}

}  // namespace app::platform
