// SPDX-License-Identifier: MIT
// The timing protocol of `amazeballs-cli bench`, shared with the Bullet comparison so
// both are measured the same way: `repeats` runs of the same workload, each from its
// start: `warmup` untimed steps, then `steps` timed ones; the result is the median run's
// wall time per ball and step. The process's CPU
// time is taken over the same blocks: on a busy machine wall time grows with the time the
// process waits for a core, CPU time much less (with several threads it adds theirs up).
#pragma once

#include <sys/resource.h>
#include <time.h>

#include <algorithm>
#include <chrono>
#include <vector>

namespace ab::cli {

struct BallStepTiming {
    double nsPerBallStep = 0.0;    // wall time, median block
    double stepsPerSecond = 0.0;   // 1e9 / (nsPerBallStep N)
    double cpuNsPerBallStep = 0.0; // process CPU time, median block
};

inline double processCpuNanoseconds()
{
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) * 1e9 + static_cast<double>(t.tv_nsec);
}

inline double median(std::vector<double> values)
{
    std::sort(values.begin(), values.end());
    const std::size_t m = values.size() / 2;
    return values.size() % 2 ? values[m] : 0.5 * (values[m - 1] + values[m]);
}

// `start` puts the workload back at its first state, `step` advances all `balls` balls by
// one step, `between` runs after every step (to poll for Ctrl+C: a flag read, negligible
// beside a step of the balls); only the timed steps are timed.
template <typename Start, typename Step, typename Between>
BallStepTiming timeBallSteps(int balls, int warmup, int steps, int repeats, Start&& start, Step&& step,
                             Between&& between)
{
    using Clock = std::chrono::steady_clock;
    std::vector<double> wall, cpu;
    const double ballSteps = static_cast<double>(steps) * balls;
    for (int r = 0; r < repeats; ++r) {
        start();
        for (int i = 0; i < warmup; ++i) {
            step();
            between();
        }
        const double cpuStart = processCpuNanoseconds();
        const auto start = Clock::now();
        for (int i = 0; i < steps; ++i) {
            step();
            between();
        }
        const std::chrono::duration<double, std::nano> elapsed = Clock::now() - start;
        cpu.push_back((processCpuNanoseconds() - cpuStart) / ballSteps);
        wall.push_back(elapsed.count() / ballSteps);
        between();
    }
    BallStepTiming t;
    t.nsPerBallStep = median(wall);
    t.stepsPerSecond = 1e9 / (t.nsPerBallStep * balls);
    t.cpuNsPerBallStep = median(cpu);
    return t;
}

// The process's peak resident memory so far, in MiB (getrusage: ru_maxrss is in KiB on Linux).
inline double peakResidentMiB()
{
    rusage usage{};
    getrusage(RUSAGE_SELF, &usage);
    return static_cast<double>(usage.ru_maxrss) / 1024.0;
}

} // namespace ab::cli
