// SPDX-License-Identifier: MIT
// What the suite's case files share (cases.cpp, spin_cases.cpp, ...): row builders, probes and the
// integrator lists, and the cases kept in a file of their own.
#pragma once

#include "suite.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace ab::stability {

// Three significant figures for settings and notes.
std::string num(double x);

// A run's energy at its start and at the last state seen: the error a probe reports is the
// relative change, end / start - 1 (none while nothing was seen or the start holds none).
struct EnergyTrack {
    double start = 0.0, end = 0.0;
    bool started = false;

    void add(double e)
    {
        if (!started)
            start = e, started = true;
        end = e;
    }
    std::optional<double> error() const
    {
        return started && start > 0.0 ? std::optional(end / start - 1.0) : std::nullopt;
    }
    double ratio() const { return end / start; }
};

extern const std::vector<Integrator> impulseIntegrators; // every integrator of impulse contacts
extern const std::vector<Integrator> springIntegrators;  // every integrator of the spring floor

// A report-model row of case `name`.
CaseRow reportRow(const std::string& name, const std::string& setting, SceneId scene,
                  std::vector<std::string> assignments, std::optional<double> dt, long long steps);
// One physical row per integrator.
std::vector<CaseRow> physicalRows(const CaseRow& base, const std::vector<Integrator>& integrators);
// Physical rows whose start the model must refuse (the refusal is the outcome checked).
std::vector<CaseRow> refusedPhysicalRows(const CaseRow& base);
void append(std::vector<CaseRow>& to, std::vector<CaseRow> rows);

// Probes of bounce1d and box3d runs (bounce_probes.cpp): free flight against the parabola
// until the first contact; contacts against Zeno's sum (the exact rest time); the energy at
// the end against the start; the largest move in one step, in box sides.
std::unique_ptr<Probe> flightProbe(const Simulation& sim);
std::unique_ptr<Probe> zenoProbe(const Simulation& sim);
std::unique_ptr<Probe> driftProbe(const Simulation& sim);
std::unique_ptr<Probe> jumpProbe(const Simulation& sim);

// Rough balls (docs/spin.md, spin_cases.cpp).
std::vector<CaseRow> spinEnergyDrift();
std::vector<CaseRow> spinLargeMu();
std::vector<CaseRow> spinBackspinWall();

// The street (docs/street.md, street_cases.cpp).
std::vector<CaseRow> streetElastic();
std::vector<CaseRow> streetKerbCrossing();
std::vector<CaseRow> streetAdvert();

} // namespace ab::stability
