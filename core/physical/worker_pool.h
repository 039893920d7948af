// SPDX-License-Identifier: MIT
// A fixed team of threads for the phases of an N-ball step. run(f) calls f(w) once for
// every worker w in [0, size()) — the caller is worker 0 — and returns when all are done,
// so consecutive run() calls are separated by a join. Workers spin briefly, then sleep on
// the atomic (a futex on Linux), so a phase costs microseconds to start, not a thread.
// Nothing is allocated per call.
#pragma once

#include <atomic>
#include <exception>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>

namespace ab::physical {

class WorkerPool {
public:
    explicit WorkerPool(int workers)
    {
        for (int w = 1; w < workers; ++w)
            threads_.emplace_back([this, w] { serve(w); });
    }
    ~WorkerPool()
    {
        stop_ = true;
        generation_.fetch_add(1, std::memory_order_release);
        generation_.notify_all();
        for (std::thread& t : threads_)
            t.join();
    }
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    int size() const { return static_cast<int>(threads_.size()) + 1; }

    template <typename F> void run(F&& f)
    {
        if (threads_.empty()) {
            f(0);
            return;
        }
        job_ = &f;
        call_ = [](void* job, int w) { (*static_cast<std::remove_reference_t<F>*>(job))(w); };
        pending_.store(static_cast<int>(threads_.size()), std::memory_order_relaxed);
        generation_.fetch_add(1, std::memory_order_release);
        generation_.notify_all();
        guarded(0);
        for (int spins = 0;; ++spins) {
            const int left = pending_.load(std::memory_order_acquire);
            if (left == 0)
                break;
            if (spins > kSpins)
                pending_.wait(left, std::memory_order_acquire);
            else
                relax();
        }
        if (error_) {
            std::exception_ptr e = error_;
            error_ = nullptr;
            std::rethrow_exception(e);
        }
    }

private:
    static constexpr int kSpins = 1000; // about 10-40 us of pause before sleeping

    static void relax()
    {
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause();
#endif
    }

    void guarded(int w)
    {
        try {
            call_(job_, w);
        } catch (...) {
            const std::lock_guard<std::mutex> lock(errorMutex_);
            if (!error_)
                error_ = std::current_exception();
        }
    }

    void serve(int w)
    {
        int seen = 0;
        for (;;) {
            for (int spins = 0;; ++spins) {
                const int g = generation_.load(std::memory_order_acquire);
                if (g != seen) {
                    seen = g;
                    break;
                }
                if (spins > kSpins)
                    generation_.wait(g, std::memory_order_acquire);
                else
                    relax();
            }
            if (stop_)
                return;
            guarded(w);
            if (pending_.fetch_sub(1, std::memory_order_acq_rel) == 1)
                pending_.notify_one();
        }
    }

    std::vector<std::thread> threads_;
    std::atomic<int> generation_{0};
    std::atomic<int> pending_{0};
    std::atomic<bool> stop_{false};
    void* job_ = nullptr;
    void (*call_)(void*, int) = nullptr;
    std::mutex errorMutex_;
    std::exception_ptr error_;
};

} // namespace ab::physical
