// SPDX-License-Identifier: MIT
// A line on standard error while a long `run` goes on: the scene time reached, the share of
// the run done and the time left at the pace so far, rewritten in place. A run of the
// advert's 250,000 balls takes minutes a simulated second, and a terminal that shows nothing
// for that long looks hung. Shown only where standard error is a terminal (a script reading
// it still gets the health check's one line and nothing else) and the CSV does not scroll
// on that terminal, first after two seconds, at most twice a second, and wiped when the run
// ends, however it ends.
#pragma once

#include <chrono>
#include <functional>
#include <ostream>
#include <string>

namespace ab::cli {

class RunProgress {
public:
    using Clock = std::function<double()>; // seconds since any fixed moment, never going back

    static constexpr double kFirstAfter = 2.0; // s of wall time before the line appears
    static constexpr double kEvery = 0.5;      // s between two rewrites

    // A run of `total` steps to scene time `tEnd`, in `timeUnit`.
    RunProgress(std::ostream& err, bool shown, long long total, double tEnd, std::string timeUnit,
                Clock clock = steadySeconds);
    ~RunProgress();
    RunProgress(const RunProgress&) = delete;
    RunProgress& operator=(const RunProgress&) = delete;

    // `done` steps taken, the state reached at scene time `t`.
    void update(long long done, double t);
    // Wipes the line (if one was written), so that what follows starts on a clean line.
    void end();

    // True where `stream` is this process's standard output or error and that is a terminal.
    static bool isTerminal(const std::ostream& stream);
    // h:mm:ss, or m:ss under an hour, of a whole number of seconds (rounded up).
    static std::string clockTime(double seconds);

private:
    static double steadySeconds();

    std::ostream& err_;
    bool shown_;
    long long total_;
    std::string end_; // "of 9 s"
    Clock clock_;
    double start_;
    double lastWrite_ = -1.0;
    std::size_t width_ = 0; // of the line on screen
};

} // namespace ab::cli
