// SPDX-License-Identifier: MIT
// A fixed team of threads for the phases of an N-ball step. forEach(count, f) calls
// f(item, worker) for every item in [0, count) and returns when all are done; the caller
// works too (as worker 0). forEach(count, f, false) does the items in order on the caller
// alone: a phase too small to pay for waking the others (items that share no data give the
// same results either way).
// 1. Each worker starts on an equal run of the items and, once done, takes items one at
//    a time from the others' runs: work stays where its data was last time, and a worker
//    the system holds back delays the phase by one item, not by its whole share.
// 2. A phase does not wait for a worker that has not joined it: on a busy machine, or a
//    virtual machine whose idle CPU takes long to wake, the workers that are running do
//    all the items. Joining is a handshake (active_, then open_) so that a late worker
//    never touches a phase that has ended.
// 3. Between phases, workers spin (with a pause) for up to 1 ms, then sleep on the atomic
//    (a futex on Linux): a run of steps keeps them awake, an idle simulation lets them
//    sleep. Nothing is allocated per call.
#pragma once

#include <algorithm>
#include <atomic>
#include <chrono>
#include <exception>
#include <mutex>
#include <thread>
#include <type_traits>
#include <vector>
#ifdef __linux__
#include <pthread.h>
#endif

namespace ab::physical {

class WorkerPool {
public:
    explicit WorkerPool(int workers) : runs_(static_cast<std::size_t>(std::max(workers, 1)))
    {
        for (int w = 1; w < workers; ++w)
            threads_.emplace_back([this, w] {
#ifdef __linux__
                pthread_setname_np(pthread_self(), "ab-worker"); // named for profilers and frame timing
#endif
                serve(w);
            });
    }
    ~WorkerPool()
    {
        stop_ = true;
        generation_.fetch_add(1, std::memory_order_seq_cst);
        generation_.notify_all();
        for (std::thread& t : threads_)
            t.join();
    }
    WorkerPool(const WorkerPool&) = delete;
    WorkerPool& operator=(const WorkerPool&) = delete;

    int size() const
    {
        return static_cast<int>(threads_.size()) + 1;
    }

    template <typename F> void forEach(int count, F&& f, bool share = true)
    {
        if (!share || threads_.empty() || count <= 1) {
            for (int item = 0; item < count; ++item)
                f(item, 0);
            return;
        }
        const int workers = size();
        for (int w = 0; w < workers; ++w) {
            runs_[static_cast<std::size_t>(w)].next.store(count * w / workers, std::memory_order_relaxed);
            runs_[static_cast<std::size_t>(w)].end = count * (w + 1) / workers;
        }
        count_ = count;
        job_ = const_cast<void*>(static_cast<const void*>(&f));
        call_ = [](void* job, int item, int w) { (*static_cast<std::remove_reference_t<F>*>(job))(item, w); };
        done_.store(0, std::memory_order_relaxed);
        const int g = generation_.load(std::memory_order_relaxed) + 1;
        open_.store(g, std::memory_order_seq_cst); // publishes the job to those who join g
        generation_.store(g, std::memory_order_seq_cst);
        generation_.notify_all();
        work(0);
        if (spinWhile([&] { return done_.load(std::memory_order_acquire) < count; }))
            for (int d; (d = done_.load(std::memory_order_acquire)) < count;)
                done_.wait(d, std::memory_order_acquire);
        // Closed: a worker that joins now leaves at once; wait for those inside to leave.
        open_.store(-1, std::memory_order_seq_cst);
        while (active_.load(std::memory_order_seq_cst) != 0)
            relax();
        if (error_) {
            std::exception_ptr e = error_;
            error_ = nullptr;
            std::rethrow_exception(e);
        }
    }

private:
    static constexpr auto kSpin = std::chrono::microseconds(1000);

    struct alignas(64) Run { // one cache line each: the items of one worker's run
        std::atomic<int> next{0};
        int end = 0;
    };

    static void relax()
    {
#if defined(__x86_64__) || defined(__i386__)
        __builtin_ia32_pause();
#endif
    }

    // Spins while `keep()` holds, for up to kSpin; true if it still holds then.
    template <typename Keep> static bool spinWhile(Keep&& keep)
    {
        const auto deadline = std::chrono::steady_clock::now() + kSpin;
        for (int i = 1;; ++i) {
            if (!keep())
                return false;
            relax();
            if (i % 256 == 0 && std::chrono::steady_clock::now() > deadline)
                return true;
        }
    }

    // Takes items, own run first, until none is left.
    void work(int w)
    {
        const int workers = size();
        for (int k = 0; k < workers; ++k) {
            Run& r = runs_[static_cast<std::size_t>((w + k) % workers)];
            for (int item = r.next.fetch_add(1, std::memory_order_relaxed); item < r.end;
                 item = r.next.fetch_add(1, std::memory_order_relaxed)) {
                try {
                    call_(job_, item, w);
                } catch (...) {
                    const std::lock_guard<std::mutex> lock(errorMutex_);
                    if (!error_)
                        error_ = std::current_exception();
                }
                if (done_.fetch_add(1, std::memory_order_acq_rel) + 1 == count_)
                    done_.notify_one();
            }
        }
    }

    void serve(int w)
    {
        int seen = 0;
        for (;;) {
            if (spinWhile([&] { return generation_.load(std::memory_order_acquire) == seen; }))
                generation_.wait(seen, std::memory_order_acquire); // returns once it differs
            seen = generation_.load(std::memory_order_acquire);
            if (stop_)
                return;
            active_.fetch_add(1, std::memory_order_seq_cst);
            if (open_.load(std::memory_order_seq_cst) == seen)
                work(w);
            active_.fetch_sub(1, std::memory_order_seq_cst);
        }
    }

    std::vector<Run> runs_;
    std::vector<std::thread> threads_;
    std::atomic<int> generation_{0}; // bumped for each phase (and to stop)
    std::atomic<int> open_{-1};      // the phase workers may still join, or -1
    std::atomic<int> active_{0};     // workers inside a phase
    std::atomic<int> done_{0};       // items finished in this phase
    std::atomic<bool> stop_{false};
    int count_ = 0;
    void* job_ = nullptr;
    void (*call_)(void*, int, int) = nullptr;
    std::mutex errorMutex_;
    std::exception_ptr error_;
};

} // namespace ab::physical
