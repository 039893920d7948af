// SPDX-License-Identifier: MIT
// The health check's findings and the model's notices in the window's words and
// language: the core hands them over as data (diagnostics::Finding), the command line
// words them in English with its options, the window here with its own controls ("the
// physical model", "impacts located inside the step") and the charts' ball numbers (ball
// 1 is the first).
#pragma once

#include "core/diagnostics/health.h"
#include "core/scene.h"

#include <QCoreApplication>
#include <QString>

namespace ab::ui {

struct FindingText {
    QString what;   // what happened, with its figure, the time and the balls
    QString rule;   // the report's rule behind it, with its appendix; empty when none
    QString remedy; // what to change
    // What happened without its figures in brackets: the status bar's one line.
    QString headline() const { return what.section(QStringLiteral(" ("), 0, 0); }
    QString full() const; // "What (the report's rule). Remedy."
};

class HealthText {
    Q_DECLARE_TR_FUNCTIONS(HealthText)
public:
    static FindingText describe(const diagnostics::HealthStatus& status, const SceneInfo& scene);
    static QString rule(diagnostics::ReportRule rule);
    static QString remedy(const diagnostics::Finding& f, const SceneInfo& scene);
    // The report's counter stopped the motion at `t` (EngineStatus::haltedAt).
    static QString halted(const SceneInfo& scene, const ParamValues& params, double t);

private:
    static QString what(const diagnostics::Finding& f, double t, const SceneInfo& scene);
};

// Three significant figures, as the command line's messages.
QString figure(double x);

} // namespace ab::ui
