// SPDX-License-Identifier: MIT
#include "core_text.h"

#include "core/io/preset.h"
#include "core/scene.h"

#include <QCoreApplication>

#include <algorithm>
#include <cctype>
#include <set>

namespace ab::ui {

QString coreText(std::string_view text)
{
    const std::string source(text);
    return QCoreApplication::translate(coreContext, source.c_str());
}

QString refusalText(const Refusal& r)
{
    std::vector<std::string> args = r.args;
    if (r.detail)
        args.push_back(refusalText(*r.detail).toStdString());
    return QString::fromStdString(fillRefusal(coreText(r.text).toStdString(), args));
}

QString refusalText(const InputError& e)
{
    return e.refusal() ? refusalText(*e.refusal()) : QString::fromUtf8(e.what());
}

std::vector<std::string> coreDisplayedStrings()
{
    std::set<std::string> out;
    auto add = [&out](std::string_view s) {
        // Numbers alone ("2.2.1") read the same in every language.
        if (std::any_of(s.begin(), s.end(), [](char c) { return std::isalpha(static_cast<unsigned char>(c)); }))
            out.emplace(s);
    };
    for (const SceneInfo* s : allScenes()) {
        for (std::string_view text : {s->title, s->reportRef, s->summary, s->timeUnit, s->lengthUnit})
            add(text);
        for (const Equation& e : s->equations)
            add(e.meaning);
        for (const ReportNote& n : s->notes) {
            add(n.where);
            add(n.text);
        }
        for (const ParamSpec& p : s->params) {
            add(p.meaning);
            add(p.equation);
            add(p.unit);
        }
    }
    for (ModelKind m : allModels()) {
        add(modelTitle(m));
        add(modelSummary(m));
    }
    for (Integrator i : allIntegrators())
        add(integratorTitle(i));
    for (const BuiltinPreset& b : builtinPresets()) {
        add(b.preset.name);
        add(b.preset.description);
    }
    for (std::string_view text : refusalTexts())
        add(text);
    return {out.begin(), out.end()};
}

} // namespace ab::ui
