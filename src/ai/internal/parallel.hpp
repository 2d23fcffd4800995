// Splitting independent work between threads without changing its result: each index is computed
// by exactly one worker, by a pure function of the index, into its own slot; which worker takes
// which index depends on timing, the results do not.
#pragma once

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

#include "ai/internal/private.hpp"
#include "ai/pause.hpp"

namespace ai {

/// The threads a search shares its work between, and the pause hook it calls between steps.
/// A plain number of threads converts: no pause.
struct Workers {
    Workers(int threads, PauseHook hook = nullptr) : count(threads), pause(hook) {}  // NOLINT
    int count;
    PauseHook pause;
};

/// Calls f(i) for every i in [0, n), on `workers.count` threads (the caller's included). The
/// caller's thread calls the pause hook after each of its steps (never inside one; the others
/// never pause).
template <typename F>
void parallel_for(std::size_t n, Workers workers, const F& f) {
    const std::size_t extra =
        workers.count > 1 ? std::min(static_cast<std::size_t>(workers.count - 1), n > 0 ? n - 1 : 0)
                          : 0;
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto work = [&](bool caller) {
        for (std::size_t i = next++; i < n; i = next++) {
            try {
                f(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_mutex);
                if (!error) error = std::current_exception();
            }
            if (caller && workers.pause) workers.pause();
        }
    };
    std::vector<std::thread> threads;
    threads.reserve(extra);
    try {
        for (std::size_t t = 0; t < extra; ++t) threads.emplace_back(work, false);
    } catch (const std::system_error&) {
        // No more threads here (WebAssembly without pthreads): the caller does the rest, and
        // the result is the same.
    }
    work(true);
    for (std::thread& t : threads) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace ai
