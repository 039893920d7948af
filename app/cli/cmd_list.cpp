// SPDX-License-Identifier: MIT
// `list`: every scene's parameter table, the models and the integrators, straight from
// the core's tables.
#include "commands.h"

#include "../../core/scene.h"

#include <algorithm>
#include <iomanip>
#include <ostream>

namespace ab::cli {

namespace {

const char* modelsText(unsigned models)
{
    switch (models) {
    case ReportModel:
        return "report";
    case PhysicalModel:
        return "physical";
    default:
        return "both";
    }
}

void listScene(const SceneInfo& s, std::ostream& out)
{
    out << s.key << "  (stage " << s.stage << ": " << s.title << "; report " << s.reportRef << ")\n";
    out << "  time in " << s.timeUnit << ", lengths in " << s.lengthUnit << "; the report's step "
        << formatNumber(s.reportDt) << " " << s.timeUnit << ", " << s.reportSteps
        << " steps; balls: " << (s.ballCount ? std::to_string(s.ballCount) : std::string("n")) << "\n";
    std::size_t wKey = 4, wUnit = 4, wDef = 7, wRange = 5, wEq = 8;
    for (const ParamSpec& p : s.params) {
        wKey = std::max(wKey, p.key.size());
        wUnit = std::max(wUnit, p.unit.size());
        wDef = std::max(wDef, formatValue(p, p.defaultValue).size());
        wRange = std::max(wRange, formatRange(p).size());
        wEq = std::max(wEq, p.equation.size());
    }
    auto row = [&](const std::string& key, const std::string& unit, const std::string& def, const std::string& range,
                   const std::string& eq, const std::string& models, const std::string& meaning) {
        out << "  " << std::left << std::setw(static_cast<int>(wKey)) << key << "  "
            << std::setw(static_cast<int>(wUnit)) << unit << "  " << std::setw(static_cast<int>(wDef)) << def << "  "
            << std::setw(static_cast<int>(wRange)) << range << "  " << std::setw(static_cast<int>(wEq)) << eq << "  "
            << std::setw(8) << models << "  " << meaning << "\n";
    };
    row("name", "unit", "default", "range", "equation", "models", "meaning");
    for (const ParamSpec& p : s.params)
        row(p.key, p.unit, formatValue(p, p.defaultValue), formatRange(p), p.equation, modelsText(p.models),
            p.meaning + (p.kind == ParamKind::Vector ? " [x,y,z]" : ""));
    out << "\n";
}

} // namespace

int listCommand(Parsed&, std::ostream& out, std::ostream&)
{
    out << "Scenes (the report's four stages, in order). Set a parameter with --set NAME=VALUE;\n"
           "vectors as x,y,z. Ranges are inclusive; '(' marks an exclusive lower bound.\n\n";
    for (const SceneInfo* s : allScenes())
        listScene(*s, out);
    out << "Models:\n";
    for (ModelKind m : allModels())
        out << "  " << std::left << std::setw(10) << modelKey(m) << modelSummary(m) << "\n";
    out << "\nIntegrators (physical model):\n";
    for (Integrator i : allIntegrators())
        out << "  " << std::left << std::setw(18) << integratorKey(i) << integratorTitle(i) << "\n";
    out << "\nImpact modes: located (time of impact found inside the step), step-end (as the report)\n"
           "Broadphases (many-balls): grid, all-pairs\n";
    return 0;
}

} // namespace ab::cli
