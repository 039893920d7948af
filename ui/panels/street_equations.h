// SPDX-License-Identifier: MIT
// The navigator's section on the street (stage 5): its equations St1-St5 with the run's
// own numbers (the acceleration down a block rolling or sliding, whether friction holds
// a ball, the speed at a block's foot, where a ball that leaves a crossing lands, the
// drop of the whole street), and why the report model is not offered.
#pragma once

#include "core/simulation.h"

#include <QCoreApplication>
#include <QString>

namespace ab::ui {

class StreetEquations {
    Q_DECLARE_TR_FUNCTIONS(StreetEquations)
public:
    // HTML for the navigator, after the stage's own equations; empty outside the street.
    static QString html(const RunSpec& spec);
};

} // namespace ab::ui
