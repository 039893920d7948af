// SPDX-License-Identifier: MIT
#include "study.h"

#include "../physical/physical_simulation.h"
#include "../reference/reference.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <iomanip>
#include <limits>
#include <ostream>
#include <sstream>

namespace ab::study {

std::string Method::impactsKey() const
{
    return exact() ? "exact" : std::string(impactModeKey(impacts));
}

std::string Method::label() const
{
    return exact() ? std::string(integratorKey(integrator))
                   : std::string(integratorKey(integrator)) + " " + impactsKey();
}

double defaultTEnd(SceneId scene)
{
    switch (scene) {
    case SceneId::Bounce1d:
        return 600.0; // three impacts, three quarters of the Zeno time (807 steps)
    case SceneId::Box3d:
    case SceneId::TwoBalls:
        return 22.0; // floor bounces, the meeting at 9.8 s, the walls z = 0 (box) at 19.9 s (20.2 s)
    case SceneId::ManyBalls:
        break;
    case SceneId::Street:
        throw InputError("street: there is no closed form for a flood of balls down a street, and its flight is exact "
                         "(event) only; use bounce1d, box3d or two-balls");
    }
    throw InputError("many-balls: there is no closed form for many colliding balls; use bounce1d, box3d or two-balls");
}

std::vector<double> logSweep(double dtMax, double dtMin, int perDecade)
{
    const int n = static_cast<int>(std::lround(std::log10(dtMax / dtMin) * perDecade));
    std::vector<double> dts;
    for (int i = 0; i <= n; ++i) {
        // Twelve significant digits, so a whole decade reads 0.01, not 0.010000000000000002.
        char text[32];
        std::snprintf(text, sizeof text, "%.12g", dtMax * std::pow(10.0, -static_cast<double>(i) / perDecade));
        dts.push_back(std::strtod(text, nullptr));
    }
    return dts;
}

std::vector<Method> allMethods(const RunSpec& spec)
{
    std::vector<Method> methods;
    for (Integrator i : {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4})
        for (ImpactMode m : {ImpactMode::Located, ImpactMode::StepEnd})
            methods.push_back({i, m});
    const bool drag = spec.params.real("b") > 0.0 || spec.params.real("c") > 0.0;
    if (!drag) // the event integrator has no closed form to fly with drag
        methods.push_back({Integrator::Event, ImpactMode::Located});
    return methods;
}

Options defaultOptions(const RunSpec& spec)
{
    Options o(spec);
    o.base.model = ModelKind::Physical;
    o.tEnd = defaultTEnd(spec.scene);
    // Four decades, finest near a million steps: 10 to 0.001 step for bounce1d,
    // 0.3 to 3e-5 s for the scenes in seconds.
    o.dts = spec.scene == SceneId::Bounce1d ? logSweep(10.0, 1e-3, 3) : logSweep(0.3, 3e-5, 3);
    o.methods = allMethods(spec);
    reference::makeReference(o.base, o.tEnd); // refuses parameters without a closed form
    return o;
}

namespace {

double cpuNow()
{
    return static_cast<double>(std::clock()) / CLOCKS_PER_SEC;
}

long long stepsFor(double tEnd, double dt)
{
    return std::max(1LL, static_cast<long long>(std::ceil(tEnd / dt - 1e-9)));
}

class Measurement {
public:
    Measurement(const Options& o, const reference::Reference& ref, const std::vector<double>& refImpacts,
                const std::function<bool()>& cancelled)
        : o_(o), ref_(ref), refImpacts_(refImpacts), cancelled_(cancelled)
    {
    }

    // One row: an untimed run that records the errors, then the timed repeats.
    std::optional<Row> measure(const Method& method, double dt)
    {
        RunSpec spec = o_.base;
        spec.integrator = method.integrator;
        spec.impacts = method.impacts;
        spec.dt = dt;
        Row row;
        row.method = method;
        row.dt = dt;
        row.steps = stepsFor(o_.tEnd, dt);
        const double first = errorsOf(spec, row);
        if (first < 0.0)
            return std::nullopt;
        row.cpuSeconds = timed(spec, row.steps, first);
        if (row.cpuSeconds < 0.0)
            return std::nullopt;
        return row;
    }

private:
    bool stop() const { return cancelled_ && cancelled_(); }

    // Steps the simulation; returns false when cancelled.
    bool stepAll(Simulation& sim, State& s, long long steps, const std::function<void(const State&)>& observe) const
    {
        State next;
        for (long long k = 0; k < steps; ++k) {
            if ((k & 4095) == 0 && stop())
                return false;
            sim.step(s, next);
            std::swap(s, next);
            if (observe)
                observe(s);
        }
        return true;
    }

    // Runs once, comparing every recorded state with the closed form; returns the run's
    // processor time (for the batch size), or -1 when cancelled.
    double errorsOf(const RunSpec& spec, Row& row) const
    {
        auto sim = makeSimulation(spec);
        auto& physics = dynamic_cast<physical::PhysicalSimulation&>(*sim);
        std::vector<physical::Impact> impacts;
        physics.setImpactLog(&impacts);
        State s = sim->start();
        const double e0 = ref_.energy(s.t);
        const auto observe = [&](const State& st) {
            for (int b = 0; b < st.size(); ++b)
                row.maxError = std::max(row.maxError, (st.p.col(b) - ref_.position(b, st.t)).norm());
        };
        const double c0 = cpuNow();
        if (!stepAll(*sim, s, row.steps, observe))
            return -1.0;
        const double seconds = cpuNow() - c0;
        row.relativeError = row.maxError / ref_.lengthScale();
        row.energyError = std::abs(physics.energy(s) - ref_.energy(s.t)) / (e0 != 0.0 ? std::abs(e0) : 1.0);
        row.impacts = s.count;
        const std::size_t k = static_cast<std::size_t>(o_.impactIndex);
        if (k >= 1 && impacts.size() >= k && refImpacts_.size() >= k)
            row.impactTimeError = std::abs(impacts[k - 1].t - refImpacts_[k - 1]);
        return seconds;
    }

    // Median processor time of the stepping loop alone over the repeats; runs shorter
    // than minBatchSeconds are timed in batches (simulations built before the clock).
    double timed(const RunSpec& spec, long long steps, double firstSeconds) const
    {
        const long long batch = std::clamp<long long>(
            static_cast<long long>(std::ceil(o_.minBatchSeconds / std::max(firstSeconds, 1e-7))), 1, 10000);
        const int repeats = firstSeconds > o_.maxSecondsPerRun ? std::min(o_.repeats, 3) : o_.repeats;
        std::vector<double> perRun;
        for (int r = 0; r < std::max(1, repeats); ++r) {
            std::vector<std::unique_ptr<Simulation>> sims;
            std::vector<State> starts;
            for (long long b = 0; b < batch; ++b) {
                sims.push_back(makeSimulation(spec));
                starts.push_back(sims.back()->start());
            }
            const double c0 = cpuNow();
            for (long long b = 0; b < batch; ++b)
                if (!stepAll(*sims[static_cast<std::size_t>(b)], starts[static_cast<std::size_t>(b)], steps, {}))
                    return -1.0;
            perRun.push_back((cpuNow() - c0) / static_cast<double>(batch));
        }
        std::sort(perRun.begin(), perRun.end());
        return perRun[perRun.size() / 2];
    }

    const Options& o_;
    const reference::Reference& ref_;
    const std::vector<double>& refImpacts_;
    std::function<bool()> cancelled_;
};

std::vector<std::string> nonDefaultAssignments(const ParamValues& v)
{
    std::vector<std::string> out;
    for (std::size_t i = 0; i < v.table().size(); ++i)
        if (!v.isDefault(i))
            out.push_back(v.table()[i].key + "=" + formatValue(v.table()[i], v.raw(i)));
    return out;
}

} // namespace

Result runStudy(const Options& options, const std::function<void(std::size_t, std::size_t, const Row&)>& progress,
                const std::function<bool()>& cancelled)
{
    if (!(options.tEnd > 0.0) || !std::isfinite(options.tEnd))
        throw InputError("--t-end: " + formatNumber(options.tEnd) + " must be a positive time");
    for (double dt : options.dts)
        if (!(dt > 0.0) || !std::isfinite(dt))
            throw InputError("--dt: " + formatNumber(dt) + " must be a positive finite step");
    RunSpec base = options.base;
    base.model = ModelKind::Physical;
    const double maxDt = options.dts.empty() ? 0.0 : *std::max_element(options.dts.begin(), options.dts.end());
    const double horizon = options.tEnd + maxDt;
    const auto ref = reference::makeReference(base, horizon);
    const std::vector<double> refImpacts = ref->impactTimes(horizon);
    makeSimulation(base); // refuses bad parameters before the first row

    const SceneInfo& info = sceneInfo(base.scene);
    Result result;
    result.scene = info.key;
    result.reference = ref->description();
    result.timeUnit = info.timeUnit;
    result.lengthUnit = info.lengthUnit;
    result.tEnd = options.tEnd;
    result.lengthScale = ref->lengthScale();
    result.impactIndex = options.impactIndex;
    result.assignments = nonDefaultAssignments(base.params);

    Options o = options;
    o.base = base;
    Measurement m(o, *ref, refImpacts, cancelled);
    const std::size_t total = options.methods.size() * options.dts.size();
    for (double dt : options.dts) {
        for (const Method& method : options.methods) {
            if (cancelled && cancelled())
                return result;
            const auto row = m.measure(method, dt);
            if (!row)
                return result;
            result.rows.push_back(*row);
            if (progress)
                progress(result.rows.size(), total, *row);
        }
    }
    result.complete = true;
    return result;
}

std::optional<double> fittedOrder(const Result& result, const Method& method, double low, double high)
{
    double n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, sxy = 0.0;
    for (const Row& r : result.rows) {
        if (!(r.method == method) || r.relativeError < low || r.relativeError > high)
            continue;
        const double x = std::log(r.dt), y = std::log(r.maxError);
        n += 1.0;
        sx += x;
        sy += y;
        sxx += x * x;
        sxy += x * y;
    }
    const double denominator = n * sxx - sx * sx;
    if (n < 3.0 || denominator <= 0.0)
        return std::nullopt;
    return (n * sxy - sx * sy) / denominator;
}

std::optional<double> cpuToReach(const Result& result, const Method& method, double relative)
{
    std::optional<double> best;
    for (const Row& r : result.rows)
        if (r.method == method && r.relativeError <= relative && (!best || r.cpuSeconds < *best))
            best = r.cpuSeconds;
    return best;
}

namespace {

std::string number(double x, int digits = 3)
{
    std::ostringstream s;
    s << std::setprecision(digits) << x;
    return s.str();
}

std::vector<Method> methodsOf(const Result& r)
{
    std::vector<Method> methods;
    for (const Row& row : r.rows)
        if (std::find(methods.begin(), methods.end(), row.method) == methods.end())
            methods.push_back(row.method);
    return methods;
}

std::vector<double> stepsOf(const Result& r)
{
    std::vector<double> dts;
    for (const Row& row : r.rows)
        if (std::find(dts.begin(), dts.end(), row.dt) == dts.end())
            dts.push_back(row.dt);
    return dts;
}

// One table: a row per step, a column per method, cells from `cell` ("-" when none).
void table(std::ostream& out, const Result& r, const std::string& title,
           const std::function<std::optional<double>(const Row&)>& cell)
{
    const std::vector<Method> methods = methodsOf(r);
    out << "### " << title << "\n\n| dt (" << r.timeUnit << ") |";
    for (const Method& m : methods)
        out << " " << m.label() << " |";
    out << "\n| ---: |";
    for (std::size_t i = 0; i < methods.size(); ++i)
        out << " ---: |";
    out << "\n";
    for (double dt : stepsOf(r)) {
        out << "| " << number(dt) << " |";
        for (const Method& m : methods) {
            std::optional<double> value;
            for (const Row& row : r.rows)
                if (row.method == m && row.dt == dt)
                    value = cell(row);
            out << " " << (value ? number(*value, 2) : std::string("-")) << " |";
        }
        out << "\n";
    }
    out << "\n";
}

} // namespace

void writeCsv(std::ostream& out, const Result& result)
{
    out << "integrator,impacts,dt,max_error,cpu_seconds,relative_error,impact_time_error,energy_error,steps,"
           "impact_count\n";
    for (const Row& r : result.rows) {
        out << integratorKey(r.method.integrator) << "," << r.method.impactsKey() << "," << formatNumber(r.dt) << ","
            << formatNumber(r.maxError) << "," << formatNumber(r.cpuSeconds) << "," << formatNumber(r.relativeError)
            << "," << (r.impactTimeError ? formatNumber(*r.impactTimeError) : std::string()) << ","
            << formatNumber(r.energyError) << "," << r.steps << "," << r.impacts << "\n";
    }
}

void writeMarkdown(std::ostream& out, const Result& r)
{
    out << "## Work-precision: " << r.scene << " (physical model)\n\n";
    out << "Reference: " << r.reference << ". Run to t = " << number(r.tEnd, 6) << " " << r.timeUnit
        << "; parameters: " << (r.assignments.empty() ? std::string("the report's defaults") : std::string());
    for (std::size_t i = 0; i < r.assignments.size(); ++i)
        out << (i ? ", " : "") << "`" << r.assignments[i] << "`";
    out << ". Relative errors are divided by " << number(r.lengthScale, 6) << " " << r.lengthUnit << "."
        << (r.complete ? "" : " **Interrupted: the tables are incomplete.**") << "\n\n";
    table(out, r, "Largest position error over the run (" + r.lengthUnit + ")",
          [](const Row& row) { return std::optional<double>(row.maxError); });
    table(out, r, "Error of the time of impact " + std::to_string(r.impactIndex) + " (" + r.timeUnit + ")",
          [](const Row& row) { return row.impactTimeError; });
    table(out, r, "Energy error at the end, relative to the start energy",
          [](const Row& row) { return std::optional<double>(row.energyError); });
    table(out, r, "CPU time per run (s), median of repeats",
          [](const Row& row) { return std::optional<double>(row.cpuSeconds); });
    out << "### Summary\n\n| method | observed order | CPU to 1e-2 | CPU to 1e-6 | CPU to 1e-10 (relative error) |\n"
           "| --- | ---: | ---: | ---: | ---: |\n";
    for (const Method& m : methodsOf(r)) {
        const auto order = fittedOrder(r, m);
        double worst = 0.0;
        for (const Row& row : r.rows)
            if (row.method == m)
                worst = std::max(worst, row.relativeError);
        // Every error at round-off level (which grows with the number of steps, so there
        // is no order to fit): the method is exact for this motion.
        const std::string fitted = order ? number(*order, 2) : worst < 1e-8 ? "exact" : "-";
        out << "| " << m.label() << " | " << fitted << " |";
        for (double goal : {1e-2, 1e-6, 1e-10}) {
            const auto cpu = cpuToReach(r, m, goal);
            out << " " << (cpu ? number(*cpu, 2) + " s" : std::string("not reached")) << " |";
        }
        out << "\n";
    }
    out << "\nObserved order: least-squares slope of log(error) against log(dt) over the steps whose relative "
           "error lies between 1e-11 and 1e-1 (exact: every error is round-off, below 1e-8). CPU to a tolerance: the "
           "least CPU time of a run whose relative error is at most that.\n";
}

} // namespace ab::study
