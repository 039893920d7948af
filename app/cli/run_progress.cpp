// SPDX-License-Identifier: MIT
#include "run_progress.h"

#include "../../core/params.h"

#include <cmath>
#include <iostream>
#include <unistd.h>

namespace ab::cli {

RunProgress::RunProgress(std::ostream& err, bool shown, long long total, double tEnd, std::string timeUnit, Clock clock)
    : err_(err), shown_(shown && total > 0), total_(total),
      end_("of " + formatSignificant(tEnd, 4) + " " + std::move(timeUnit)), clock_(std::move(clock)), start_(clock_())
{
}

RunProgress::~RunProgress()
{
    end();
}

bool RunProgress::isTerminal(const std::ostream& stream)
{
    if (&stream == &std::cerr)
        return ::isatty(STDERR_FILENO) == 1;
    if (&stream == &std::cout)
        return ::isatty(STDOUT_FILENO) == 1;
    return false;
}

double RunProgress::steadySeconds()
{
    return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count();
}

std::string RunProgress::clockTime(double seconds)
{
    const long long s = std::isfinite(seconds) ? static_cast<long long>(std::ceil(std::max(seconds, 0.0))) : 0;
    const auto two = [](long long x) { return (x < 10 ? "0" : "") + std::to_string(x); };
    if (s >= 3600)
        return std::to_string(s / 3600) + ":" + two(s / 60 % 60) + ":" + two(s % 60);
    return std::to_string(s / 60) + ":" + two(s % 60);
}

void RunProgress::update(long long done, double t)
{
    if (!shown_ || done <= 0)
        return;
    const double now = clock_(), elapsed = now - start_;
    if (elapsed < kFirstAfter || (lastWrite_ >= 0.0 && now - lastWrite_ < kEvery))
        return;
    lastWrite_ = now;
    // The time left at the pace so far: elapsed (total - done) / done. A street run's steps
    // cost most while its pile settles, so the figure is a guide, not a promise.
    const double left = elapsed * static_cast<double>(total_ - done) / static_cast<double>(done);
    const int percent = static_cast<int>(100 * done / total_);
    std::string line = "run: t = " + formatSignificant(t, 4) + " " + end_ + " (" + std::to_string(percent) +
                       "%), about " + clockTime(left) + " left";
    const std::size_t width = line.size();
    if (width < width_)
        line.append(width_ - width, ' '); // over the end of a longer line before
    err_ << "\r" << line << std::flush;
    width_ = std::max(width_, width);
}

void RunProgress::end()
{
    if (width_ == 0)
        return;
    err_ << "\r" << std::string(width_, ' ') << "\r" << std::flush;
    width_ = 0;
}

} // namespace ab::cli
