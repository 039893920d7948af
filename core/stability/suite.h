// SPDX-License-Identifier: MIT
// The stability suite: named cases of stiff and extreme runs, each run for every model and
// integrator it applies to, one row each with the health check's figures and a verdict.
//
// Design:
//  1. A case is a name, a line saying what it shows, and its rows. A row builds its
//     RunSpec lazily, so a value the parameter table refuses (k > 1) is a row whose
//     expected outcome is the refusal.
//  2. A row whose model is not in this build (makeSimulation says "not available") is
//     kept as such, with no figures: when that model lands, the same row runs.
//  3. A row may carry a probe: a closed-form figure of its own (the error of free flight
//     against the parabola, the time of rest against Zeno's sum) beside the health figures.
#pragma once

#include "../diagnostics/health.h"
#include "../simulation.h"

#include <functional>
#include <iosfwd>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ab::stability {

// A figure a row measures against a closed form, fed every final state in order.
class Probe {
public:
    virtual ~Probe() = default;
    virtual void observe(const State& s) = 0;
    virtual std::optional<double> error() const { return std::nullopt; } // reference_error
    virtual std::string note() const { return {}; }
};

struct CaseRow {
    std::string caseName;
    std::string setting; // what this row varies, e.g. "linear, stiffness 1e9, dt omega0 1.6"
    SceneId scene = SceneId::Bounce1d;
    ModelKind model = ModelKind::Report;
    Integrator integrator = Integrator::SymplecticEuler;
    ImpactMode impacts = ImpactMode::Located;
    std::vector<std::string> assignments; // NAME=VALUE, as --set takes them
    std::optional<double> dt;
    std::optional<State> init;
    long long steps = 0;
    bool expectRefusal = false; // a value the parameter table must refuse
    std::string skip;           // not empty: the row is not run, and this says why
    std::function<std::unique_ptr<Probe>(const Simulation&)> probe;
};

// The row's RunSpec; InputError for a refused value.
RunSpec buildSpec(const CaseRow& row);

enum class RowOutcome { Ran, Refused, NotAvailable, Skipped };

struct RowResult {
    std::string caseName;
    std::string model;      // "report" or "physical"
    std::string integrator; // "-" for the report model (one scheme per stage)
    std::string setting;
    RowOutcome outcome = RowOutcome::Ran;
    diagnostics::HealthFigures figures;
    std::string verdict; // ok, degraded or failed (rows that ran or were refused)
    std::string note;
    std::optional<double> referenceError;
    double dt = 0.0;
    double cpuSeconds = 0.0;
};

struct StabilityCase {
    std::string name;
    std::string summary; // what it shows, one line
    std::function<std::vector<CaseRow>()> rows;
};

const std::vector<StabilityCase>& stabilityCases();
const StabilityCase* findCase(const std::string& name);

// Runs one row; `cancelled` is polled between steps (a cancelled row stops where it is).
RowResult runRow(const CaseRow& row, const std::function<bool()>& cancelled = {});

// The rows of the given cases, in order (every case when `cases` is empty).
std::vector<CaseRow> suiteRows(const std::vector<const StabilityCase*>& cases = {});

struct SuiteResult {
    std::vector<RowResult> rows; // the rows that ran to their end, in order
    bool complete = false;       // false when cancelled part way
};

// Runs the rows in order. `progress` (optional) is told after each row; `cancelled`
// (optional) is polled between rows and between steps. A cancelled suite returns the rows
// finished before it (the row it stopped in is dropped) with complete = false.
SuiteResult
runSuite(const std::vector<CaseRow>& rows,
         const std::function<void(std::size_t done, std::size_t total, const RowResult& row)>& progress = {},
         const std::function<bool()>& cancelled = {});

// CSV per the contract: case,model,integrator,max_energy_gain,max_penetration,escaped,
// nonfinite,verdict, then momentum_error,max_overlap,reference_error,steps,cpu_seconds,
// dt,setting,note. Rows that did not run (not available, skipped) are not CSV rows: a
// verdict is only given to a run.
void writeCsv(std::ostream& out, const std::vector<RowResult>& rows);
// A fixed-width table for the terminal, every row included.
void writeTable(std::ostream& out, const std::vector<RowResult>& rows);
// Markdown: the measured stability limits, then every row.
void writeMarkdown(std::ostream& out, const std::vector<RowResult>& rows);
// The stability limits of each integrator, measured against theory, as markdown lines.
void writeLimits(std::ostream& out);

} // namespace ab::stability
