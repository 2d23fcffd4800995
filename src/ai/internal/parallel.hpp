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

namespace ai {

/// Calls this thread's pause hook, if any (ai/pause.hpp): between two steps, never inside one.
void pause_point();

/// Calls f(i) for every i in [0, n), on `workers` threads (the caller's included).
template <typename F>
void parallel_for(std::size_t n, int workers, const F& f) {
    const std::size_t extra =
        workers > 1 ? std::min(static_cast<std::size_t>(workers - 1), n > 0 ? n - 1 : 0) : 0;
    std::atomic<std::size_t> next{0};
    std::exception_ptr error;
    std::mutex error_mutex;
    auto work = [&] {
        for (std::size_t i = next++; i < n; i = next++) {
            try {
                f(i);
            } catch (...) {
                std::lock_guard<std::mutex> lock(error_mutex);
                if (!error) error = std::current_exception();
            }
            pause_point();
        }
    };
    std::vector<std::thread> threads;
    threads.reserve(extra);
    try {
        for (std::size_t t = 0; t < extra; ++t) threads.emplace_back(work);
    } catch (const std::system_error&) {
        // No more threads here (WebAssembly without pthreads): the caller does the rest, and
        // the result is the same.
    }
    work();
    for (std::thread& t : threads) t.join();
    if (error) std::rethrow_exception(error);
}

}  // namespace ai
