// A decision computed beside the frames (platform::Task): the computer player's or Hint's
// thinking, which the frame polls. Like a std::future: dropping or replacing one waits for its
// work to end, so the work may read the session it was started on.
#pragma once

#include <exception>
#include <memory>
#include <optional>
#include <utility>

#include "app/platform.hpp"

namespace app {

template <typename T>
class Thinking {
  public:
    Thinking() = default;

    /// Starts work() beside the frames; its result, or what it throws, comes back by get().
    template <typename F>
    static Thinking start(F work) {
        Thinking t;
        t.outcome_ = std::make_shared<Outcome>();
        t.task_ = platform::start_task([out = t.outcome_, work = std::move(work)]() mutable {
            try {
                out->value.emplace(work());
            } catch (...) {
                out->error = std::current_exception();
            }
        });
        return t;
    }

    /// Whether work was started and its result not taken yet.
    bool valid() const { return task_ != nullptr; }
    /// Whether the result is there (valid() only).
    bool ready() const { return task_->done(); }
    void wait() const { task_->wait(); }
    /// The result, once the work has ended; rethrows what it threw. Not valid() after.
    T get() {
        task_->wait();
        task_.reset();
        const std::shared_ptr<Outcome> out = std::move(outcome_);
        if (out->error) std::rethrow_exception(out->error);
        return std::move(*out->value);
    }

  private:
    struct Outcome {
        std::optional<T> value;
        std::exception_ptr error;
    };
    std::shared_ptr<Outcome> outcome_;
    std::unique_ptr<platform::Task> task_;
};

}  // namespace app
