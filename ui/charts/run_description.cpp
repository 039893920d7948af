// SPDX-License-Identifier: MIT
#include "run_description.h"

#include "program_version.h"

#include "ui/i18n/core_text.h"

namespace ab::ui {

namespace {

QString qs(const std::string& s)
{
    return QString::fromStdString(s);
}

std::string unitSuffix(const std::string& unit)
{
    return unit == "1" ? std::string() : " " + unit;
}

unsigned modelMask(ModelKind model)
{
    return model == ModelKind::Report ? ReportModel : PhysicalModel;
}

std::string impactsWords(ImpactMode mode)
{
    return mode == ImpactMode::StepEnd ? "found at the step's end" : "located inside the step";
}

// "physical, integrator rk4, impacts located inside the step, dt 0.01 s"
std::string schemeLine(const RunFacts& run, const SceneInfo& info)
{
    const RunSpec& spec = *run.spec;
    std::string line = "model " + std::string(modelKey(spec.model));
    if (spec.model == ModelKind::Report)
        line += " (the report's own step and impact rules)";
    else
        line += ", integrator " + std::string(integratorKey(spec.integrator)) + ", impacts " +
                std::string(impactModeKey(spec.impacts)) + " (" + impactsWords(spec.impacts) + ")";
    return line + ", dt " + formatNumber(run.dt) + " " + info.timeUnit;
}

} // namespace

QString RunDescription::runLabel(const RunSpec& spec)
{
    return qs(variantLabel(RunVariant{spec.model, spec.integrator, spec.impacts, spec.dt}));
}

QString RunDescription::caption(const RunFacts& run, const RunFacts* comparison, bool closedForm)
{
    const RunSpec& spec = *run.spec;
    const SceneInfo& info = sceneInfo(spec.scene);
    QStringList parts;
    QString scheme = tr("Stage %1 (%2)").arg(info.stage).arg(qs(info.key));
    if (spec.model == ModelKind::Report)
        scheme += tr(", report model (the report's own step and impact rules)");
    else
        scheme +=
            tr(", physical model, integrator %1, impacts %2")
                .arg(coreText(integratorTitle(spec.integrator)),
                     spec.impacts == ImpactMode::StepEnd ? tr("at the step's end") : tr("located inside the step"));
    scheme += tr(", dt = %1 %2").arg(qs(formatStep(run.dt)), coreText(info.timeUnit));
    parts << scheme;
    QStringList changed;
    const unsigned mask = modelMask(spec.model);
    for (std::size_t i = 0; i < info.params.size(); ++i) {
        const ParamSpec& p = info.params[i];
        if (!p.usedBy(mask) || spec.params.isDefault(i))
            continue;
        const QString value = qs(formatValue(p, spec.params.raw(i)) + unitSuffix(p.unit));
        const QString usual = qs(formatValue(p, p.defaultValue));
        changed << (p.reportDefault() ? tr("%1 = %2 (report: %3)") : tr("%1 = %2 (default: %3)"))
                       .arg(qs(p.key), value, usual);
    }
    if (changed.isEmpty())
        parts << (anyReportDefault(info.params) ? tr("the report's constants") : tr("the default constants"));
    else
        parts << changed.join(", ");
    if (spec.init)
        parts << tr("started from a given state");
    if (comparison)
        parts << tr("dotted: %1")
                     .arg(qs(variantLabel(RunVariant{comparison->spec->model, comparison->spec->integrator,
                                                     comparison->spec->impacts, comparison->dt})));
    if (closedForm)
        parts << tr("dashed: closed form");
    return parts.join("; ");
}

std::vector<std::string> RunDescription::comments(const RunFacts& run, const RunFacts* comparison, bool closedForm,
                                                  int ball, int balls, const std::string& what)
{
    const RunSpec& spec = *run.spec;
    const SceneInfo& info = sceneInfo(spec.scene);
    std::vector<std::string> out;
    out.push_back(programName() + " " + programVersion() + ", " + what);
    out.push_back("scene: " + info.key + " (stage " + std::to_string(info.stage) + ": " + info.title + ")");
    out.push_back("run: " + schemeLine(run, info));
    if (spec.model != ModelKind::Report)
        out.push_back("integrator: " + std::string(integratorKey(spec.integrator)) +
                      "; impacts: " + std::string(impactModeKey(spec.impacts)));
    else
        out.push_back("integrator: the report's own step; impacts: the report's rules");
    out.push_back("dt: " + formatNumber(run.dt) + " " + info.timeUnit);
    if (ball >= 0)
        out.push_back("ball: " + std::to_string(ball + 1) + " of " + std::to_string(balls) +
                      " (position and velocity columns; energy and momentum are of all balls)");
    else
        out.push_back("balls: " + std::to_string(balls) + " (the ball column counts from 0, as the contract's CSV)");
    if (spec.scene == SceneId::Street && what == "chart data") // a trajectory has no energy columns
        out.push_back("energy columns: sums over the " + std::to_string(balls) +
                      " balls; the energy chart draws each divided by " + std::to_string(balls) +
                      ", the mean per ball");
    const unsigned mask = modelMask(spec.model);
    for (std::size_t i = 0; i < info.params.size(); ++i) {
        const ParamSpec& p = info.params[i];
        if (!p.usedBy(mask))
            continue;
        std::string line = "constant " + p.key + " = " + formatValue(p, spec.params.raw(i)) + unitSuffix(p.unit);
        const std::string whose = p.reportDefault() ? "the report's" : "the default";
        line += spec.params.isDefault(i) ? " (" + whose + " value)"
                                         : " (" + whose + ": " + formatValue(p, p.defaultValue) + ")";
        out.push_back(line);
    }
    if (spec.init)
        out.push_back("start: a given state (--init), not the constants' start values");
    if (comparison)
        out.push_back("comparison (compare_ columns): " + schemeLine(*comparison, info));
    if (closedForm)
        out.push_back("closed form (_closed_form columns): the textbook motion of the same constants");
    return out;
}

} // namespace ab::ui
