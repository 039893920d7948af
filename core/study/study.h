// SPDX-License-Identifier: MIT
// The work-precision study: every integrator of the physical model (with impacts located
// and at the step's end; event-driven is exact) over a sweep of steps, each run measured
// against the scene's closed form (core/reference) for its error, and timed for its cost.
//  - max_error: the largest distance of any ball from the closed form over the recorded
//    states (every step; for `event` every sampling interval), in the scene's length unit.
//  - impact_time_error: how far the k-th impact (in time order) is from the closed form's.
//  - energy_error: |E - E_exact| at the end of the run, relative to the start energy.
//  - cpu_seconds: processor time of the stepping loop alone (building the simulation,
//    the reference and the errors are outside it; recording states in memory is inside),
//    the median of several repeats, short runs timed in batches.
#pragma once

#include "../simulation.h"

#include <functional>
#include <iosfwd>
#include <optional>
#include <string>
#include <vector>

namespace ab::study {

struct Method {
    Integrator integrator = Integrator::Euler;
    ImpactMode impacts = ImpactMode::Located; // ignored for event

    bool exact() const { return integrator == Integrator::Event; }
    // "located", "step-end" or "exact" (event), as the CSV writes it.
    std::string impactsKey() const;
    // "rk4 located", "event"
    std::string label() const;
    friend bool operator==(const Method&, const Method&) = default;
};

struct Options {
    explicit Options(RunSpec spec) : base(std::move(spec)) {}

    RunSpec base;            // scene and parameters (the model is set to physical)
    double tEnd = 0.0;       // in the scene's time unit
    std::vector<double> dts; // steps to sweep (sampling intervals for event)
    std::vector<Method> methods;
    int repeats = 5;                // timed repeats; the median is reported
    int impactIndex = 3;            // k of the k-th impact time (1 = first)
    double minBatchSeconds = 2e-3;  // runs shorter than this are timed in batches
    double maxSecondsPerRun = 0.05; // three repeats (if more were asked) for runs longer than this
};

// The default study of a scene: its t-end, a sweep from 10 to 1/1000 of the report's step
// (four decades, three steps per decade), all methods that apply (event only without
// drag). Throws InputError when the scene has no closed form for the parameters.
Options defaultOptions(const RunSpec& spec);
double defaultTEnd(SceneId scene);
std::vector<double> logSweep(double dtMax, double dtMin, int perDecade);
std::vector<Method> allMethods(const RunSpec& spec);

struct Row {
    Method method;
    double dt = 0.0;
    long long steps = 0;
    double maxError = 0.0;      // length unit
    double relativeError = 0.0; // maxError / the reference's length scale
    std::optional<double> impactTimeError;
    double energyError = 0.0;
    double cpuSeconds = 0.0;
    long long impacts = 0; // impacts the run counted
};

struct Result {
    std::string scene;
    std::string reference; // one line naming the closed form
    std::string timeUnit, lengthUnit;
    double tEnd = 0.0;
    double lengthScale = 1.0;
    int impactIndex = 3;
    std::vector<std::string> assignments; // the non-default parameters, NAME=VALUE
    std::vector<Row> rows;
    bool complete = false; // false when cancelled part way
};

// Runs the study. `progress` (optional) is told after each row; `cancelled` (optional) is
// polled between runs and every few thousand steps, and a cancelled study returns what it
// has with complete = false. Throws InputError for parameters without a closed form.
Result runStudy(const Options& options,
                const std::function<void(std::size_t done, std::size_t total, const Row& row)>& progress = {},
                const std::function<bool()>& cancelled = {});

// Observed order of convergence: the least-squares slope of log(max_error) against
// log(dt) over the method's rows whose relative error lies in [low, high] (above round-off,
// inside the asymptotic range). Nothing when fewer than three rows qualify.
std::optional<double> fittedOrder(const Result& result, const Method& method, double low = 1e-11, double high = 1e-1);

// The least CPU time at which the method's relative error is at most `relative`.
std::optional<double> cpuToReach(const Result& result, const Method& method, double relative);

// CSV: integrator,impacts,dt,max_error,cpu_seconds,relative_error,impact_time_error,
// energy_error,steps,impact_count (an empty cell where there is no k-th impact).
void writeCsv(std::ostream& out, const Result& result);
// Markdown: the settings, tables of error, impact-time error, energy error and CPU time
// (one row per step, one column per method), and a summary with fitted orders and the
// cost of reaching 1e-2, 1e-6 and 1e-10 relative error.
void writeMarkdown(std::ostream& out, const Result& result);

} // namespace ab::study
