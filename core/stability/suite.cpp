// SPDX-License-Identifier: MIT
// Running a row of the stability suite and writing the results.
#include "suite.h"

#include "stability_limit.h"

#include <cmath>
#include <cstdio>
#include <ctime>
#include <ostream>

namespace ab::stability {

RunSpec buildSpec(const CaseRow& row)
{
    RunSpec spec(row.scene);
    spec.model = row.model;
    spec.integrator = row.integrator;
    spec.impacts = row.impacts;
    spec.dt = row.dt;
    for (const std::string& a : row.assignments)
        spec.params.parseAssignment(a);
    spec.init = row.init;
    return spec;
}

namespace {

std::string verdictOf(diagnostics::Health h)
{
    switch (h) {
    case diagnostics::Health::Ok:
        return "ok";
    case diagnostics::Health::Warning:
        return "degraded";
    case diagnostics::Health::Failed:
        return "failed";
    }
    return "failed";
}

// Steps the row, checking health on every pair of consecutive final states; stops at
// the first non-finite state.
void simulate(const CaseRow& row, Simulation& sim, RowResult& r, const std::function<bool()>& cancelled)
{
    State s = sim.start();
    diagnostics::HealthCheck health(sim, s);
    std::unique_ptr<Probe> probe = row.probe ? row.probe(sim) : nullptr;
    State next, previous;
    bool first = true;
    auto observe = [&](const State& f) {
        if (!first && health.check(previous, f) == diagnostics::Health::Failed && health.figures().nonfinite)
            return false;
        if (probe)
            probe->observe(f);
        previous = f;
        first = false;
        return true;
    };
    bool stopped = false;
    for (long long i = 0; i < row.steps && !stopped; ++i) {
        if (cancelled && cancelled())
            return;
        sim.step(s, next); // s is final now
        stopped = !observe(s);
        std::swap(s, next);
    }
    if (!stopped)
        observe(s);
    r.figures = health.figures();
    const diagnostics::HealthStatus worst = health.worst();
    r.verdict = verdictOf(worst.level);
    const std::string probeNote = probe ? probe->note() : std::string();
    if (probe)
        r.referenceError = probe->error();
    r.note = probeNote;
    if (worst.level != diagnostics::Health::Ok)
        r.note += (r.note.empty() ? "" : ". ") + worst.line();
}

} // namespace

RowResult runRow(const CaseRow& row, const std::function<bool()>& cancelled)
{
    RowResult r;
    r.caseName = row.caseName;
    r.setting = row.setting;
    r.model = std::string(modelKey(row.model));
    r.integrator = row.model == ModelKind::Report ? "-" : std::string(integratorKey(row.integrator));
    r.dt = row.dt.value_or(defaultDt(row.scene, row.model));
    if (!row.skip.empty()) {
        r.outcome = RowOutcome::Skipped;
        r.note = "not run: " + row.skip;
        return r;
    }
    const std::clock_t start = std::clock();
    std::unique_ptr<Simulation> sim;
    try {
        sim = makeSimulation(buildSpec(row));
    } catch (const InputError& e) {
        const std::string message = e.what();
        if (message.find("not available") != std::string::npos) {
            r.outcome = RowOutcome::NotAvailable;
            r.note = "not available in this build";
            return r;
        }
        r.outcome = RowOutcome::Refused;
        r.verdict = row.expectRefusal ? "ok" : "failed";
        r.note = (row.expectRefusal ? "refused, as it must be: " : "refused unexpectedly: ") + message;
        return r;
    }
    if (row.expectRefusal) {
        r.verdict = "failed";
        r.note = "accepted a value it must refuse";
        return r;
    }
    r.dt = sim->dt();
    simulate(row, *sim, r, cancelled);
    r.cpuSeconds = static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC;
    return r;
}

std::vector<CaseRow> suiteRows(const std::vector<const StabilityCase*>& cases)
{
    std::vector<CaseRow> rows;
    auto add = [&](const StabilityCase& c) {
        for (CaseRow& row : c.rows())
            rows.push_back(std::move(row));
    };
    if (cases.empty())
        for (const StabilityCase& c : stabilityCases())
            add(c);
    for (const StabilityCase* c : cases)
        add(*c);
    return rows;
}

SuiteResult runSuite(const std::vector<CaseRow>& rows,
                     const std::function<void(std::size_t, std::size_t, const RowResult&)>& progress,
                     const std::function<bool()>& cancelled)
{
    SuiteResult result;
    for (const CaseRow& row : rows) {
        if (cancelled && cancelled())
            return result;
        RowResult r = runRow(row, cancelled);
        if (cancelled && cancelled())
            return result; // the row may have stopped part way: its figures would mislead
        result.rows.push_back(std::move(r));
        if (progress)
            progress(result.rows.size(), rows.size(), result.rows.back());
    }
    result.complete = true;
    return result;
}

namespace {

std::string figure(double x)
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", x);
    return buf;
}

std::string optionalFigure(const std::optional<double>& x)
{
    return x ? figure(*x) : std::string();
}

bool ran(const RowResult& r)
{
    return r.outcome == RowOutcome::Ran || r.outcome == RowOutcome::Refused;
}

std::string csvField(const std::string& s)
{
    if (s.find_first_of(",\"\n") == std::string::npos)
        return s;
    std::string q = "\"";
    for (char c : s)
        q += c == '"' ? std::string("\"\"") : std::string(1, c);
    return q + "\"";
}

std::string markdownCell(const std::string& s)
{
    std::string out;
    for (char c : s)
        out += c == '|' ? std::string("\\|") : std::string(1, c);
    return out;
}

} // namespace

void writeCsv(std::ostream& out, const std::vector<RowResult>& rows)
{
    out << "case,model,integrator,max_energy_gain,max_penetration,escaped,nonfinite,verdict,momentum_error,"
           "max_overlap,reference_error,steps,cpu_seconds,dt,setting,note\n";
    for (const RowResult& r : rows) {
        if (!ran(r))
            continue;
        const diagnostics::HealthFigures& f = r.figures;
        out << r.caseName << ',' << r.model << ',' << r.integrator << ',' << figure(f.maxEnergyGain) << ','
            << figure(f.maxPenetration) << ',' << f.escaped << ',' << (f.nonfinite ? 1 : 0) << ',' << r.verdict << ','
            << optionalFigure(f.maxMomentumError) << ',' << optionalFigure(f.maxOverlap) << ','
            << optionalFigure(r.referenceError) << ',' << f.steps << ',' << figure(r.cpuSeconds) << ',' << figure(r.dt)
            << ',' << csvField(r.setting) << ',' << csvField(r.note) << '\n';
    }
}

void writeTable(std::ostream& out, const std::vector<RowResult>& rows)
{
    char line[512];
    std::snprintf(line, sizeof line, "%-18s %-8s %-17s %-11s %-11s %-4s %-4s %-10s %-8s %-9s %s\n", "case", "model",
                  "integrator", "energy_gain", "penetration", "esc", "nan", "steps", "cpu_s", "verdict", "setting");
    out << line;
    for (const RowResult& r : rows) {
        const diagnostics::HealthFigures& f = r.figures;
        const bool figures = r.outcome == RowOutcome::Ran;
        const std::string verdict = ran(r) ? r.verdict : r.outcome == RowOutcome::Skipped ? "skipped" : "n/a";
        std::snprintf(line, sizeof line, "%-18s %-8s %-17s %-11s %-11s %-4s %-4s %-10s %-8s %-9s %s\n",
                      r.caseName.c_str(), r.model.c_str(), r.integrator.c_str(),
                      figures ? figure(f.maxEnergyGain).c_str() : "", figures ? figure(f.maxPenetration).c_str() : "",
                      figures ? std::to_string(f.escaped).c_str() : "", figures ? (f.nonfinite ? "yes" : "no") : "",
                      figures ? std::to_string(f.steps).c_str() : "", figures ? figure(r.cpuSeconds).c_str() : "",
                      verdict.c_str(), r.setting.c_str());
        out << line;
        if (!r.note.empty() && r.outcome != RowOutcome::NotAvailable)
            out << "    " << r.note << "\n";
    }
}

void writeLimits(std::ostream& out)
{
    out << "| integrator | measured limit of dt omega0 | theory |\n| --- | --- | --- |\n";
    const GrowthCriterion c;
    for (Integrator i : {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4,
                         Integrator::ImplicitEuler, Integrator::ImplicitMidpoint}) {
        const StabilityLimit limit = measureStabilityLimit(i, c);
        const double theory = theoreticalLimit(i);
        out << "| " << integratorKey(i) << " | ";
        if (limit.stableEverywhere) {
            out << "stable up to " << figure(c.hMax) << " (the end of the search)";
        } else if (i == Integrator::Euler) {
            const GrowthCriterion longer{100'000, c.growth, 1e-6, c.hMax, 0.0};
            out << figure(limit.h) << " over " << c.steps << " steps, " << figure(measureStabilityLimit(i, longer).h)
                << " over " << longer.steps << " (sqrt(G^(2/n) - 1): " << figure(expectedMeasuredLimit(i, c)) << " and "
                << figure(expectedMeasuredLimit(i, longer)) << ")";
        } else {
            out << figure(limit.h) << " (" << figure(100.0 * (limit.h - theory) / theory) << "% from theory)";
        }
        out << " | ";
        if (i == Integrator::Euler)
            out << "0: abs(1 + i h) > 1 for every h";
        else if (std::isfinite(theory))
            out << figure(theory);
        else
            out << (i == Integrator::ImplicitEuler ? "none; amplitude x 1/sqrt(1 + h^2) per step (damps)"
                                                   : "none; amplitude x 1 per step (keeps it)");
        out << " |\n";
    }
}

void writeMarkdown(std::ostream& out, const std::vector<RowResult>& rows)
{
    out << "| case | model | integrator | setting | dt | max energy gain | max penetration | escaped | non-finite | "
           "momentum error | reference error | steps | CPU s | verdict | note |\n"
           "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
    for (const RowResult& r : rows) {
        const diagnostics::HealthFigures& f = r.figures;
        const bool figures = r.outcome == RowOutcome::Ran;
        const std::string verdict = ran(r) ? r.verdict : r.outcome == RowOutcome::Skipped ? "skipped" : "n/a";
        out << "| " << r.caseName << " | " << r.model << " | " << r.integrator << " | " << markdownCell(r.setting)
            << " | " << figure(r.dt) << " | " << (figures ? figure(f.maxEnergyGain) : "") << " | "
            << (figures ? figure(f.maxPenetration) : "") << " | " << (figures ? std::to_string(f.escaped) : "") << " | "
            << (figures ? (f.nonfinite ? "yes" : "no") : "") << " | "
            << (figures ? optionalFigure(f.maxMomentumError) : "") << " | "
            << (figures ? optionalFigure(r.referenceError) : "") << " | " << (figures ? std::to_string(f.steps) : "")
            << " | " << (figures ? figure(r.cpuSeconds) : "") << " | " << verdict << " | " << markdownCell(r.note)
            << " |\n";
    }
}

} // namespace ab::stability
