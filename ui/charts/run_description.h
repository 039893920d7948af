// SPDX-License-Identifier: MIT
// What a figure and its data say about how they were made: a caption for under the chart
// (scene, model, integrator, impacts, dt and the constants that differ from the
// report's, in the program's language) and the `#` comment lines of the chart-data CSV
// (the program and its version, and every setting and constant with its unit).
#pragma once

#include "core/simulation.h"

#include <QCoreApplication>
#include <QString>

#include <string>
#include <vector>

namespace ab::ui {

// One run as it was computed: its spec and the step it took (the model's default when
// the spec leaves dt unset).
struct RunFacts {
    const RunSpec* spec = nullptr;
    double dt = 0.0;
};

class RunDescription {
    Q_DECLARE_TR_FUNCTIONS(RunDescription)
public:
    // "Stage 2 (box3d), report model (the report's own step and impact rules), dt = 0.01 s;
    // k = 0.8 (report: 0.9); dotted: physical rk4; dashed: closed form".
    static QString caption(const RunFacts& run, const RunFacts* comparison, bool closedForm);
    // The run's short name in legends and captions: "report", "physical rk4".
    static QString runLabel(const RunSpec& spec);
    // The CSV's comment lines, without the leading "# ", in English (a data file's): `what`
    // the file holds ("chart data", "trajectory"); ball is 0-based (written 1-based), and
    // negative for a file of every ball.
    static std::vector<std::string> comments(const RunFacts& run, const RunFacts* comparison, bool closedForm, int ball,
                                             int balls, const std::string& what = "chart data");
};

} // namespace ab::ui
