// SPDX-License-Identifier: MIT
// The navigator's section on rotation (docs/spin.md): for a physical run whose balls turn,
// the rough-sphere model's equations (I, S1-S4, S9-S13) with the run's own numbers (the
// moment of inertia, mu g, and for a ball that starts sliding on the floor the moment it
// rolls and how fast); for a report run given friction or spin, the note that the
// report's model has no rotation. Empty where neither applies.
#pragma once

#include "core/simulation.h"

#include <QCoreApplication>
#include <QString>

namespace ab::ui {

class SpinEquations {
    Q_DECLARE_TR_FUNCTIONS(SpinEquations)
public:
    // HTML for the navigator, after the stage's own equations; empty: nothing to say.
    static QString html(const Simulation& sim);

private:
    static QString reportNote(const RunSpec& spec);
    static QString inertiaRow(const RunSpec& spec);
    static QString floorRows(const Simulation& sim);
    static QString impactRows(const RunSpec& spec);
};

} // namespace ab::ui
