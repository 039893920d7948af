// SPDX-License-Identifier: MIT
// A checked preset as the document of its file (the format: preset.cpp).
#include "preset_document.h"

#include <algorithm>

namespace ab::presetfile {

using json::Document;

namespace {

// Numbers are written as doubles, as the reader makes them.
Document vectorValue(const Eigen::Vector3d& v)
{
    return Document::array({v.x(), v.y(), v.z()});
}

// A parameter the preset's check found in the scene's table.
bool isVector(const SceneInfo& info, const std::string& name)
{
    const ParamSpec* spec = info.findParam(name);
    return spec && spec->kind == ParamKind::Vector;
}

Document viewValue(const PresetView& view)
{
    Document camera = Document::object();
    if (view.cameraYaw)
        camera["yaw"] = *view.cameraYaw;
    if (view.cameraPitch)
        camera["pitch"] = *view.cameraPitch;
    if (view.cameraDistance)
        camera["distance"] = *view.cameraDistance;
    if (view.cameraTarget)
        camera["target"] = vectorValue(*view.cameraTarget);
    Document out = Document::object();
    if (!camera.empty())
        out["camera"] = std::move(camera);
    if (!view.charts.empty())
        out["charts"] = view.charts;
    if (view.selectedBall)
        out["selected_ball"] = static_cast<double>(*view.selectedBall);
    if (view.speed)
        out["speed"] = *view.speed;
    if (view.compare) {
        Document compare = Document::object();
        compare["model"] = std::string(modelKey(view.compare->model));
        compare["integrator"] = std::string(integratorKey(view.compare->integrator));
        compare["impacts"] = std::string(impactModeKey(view.compare->impacts));
        if (view.compare->dt)
            compare["dt"] = *view.compare->dt;
        out["compare"] = std::move(compare);
    }
    return out;
}

} // namespace

Document document(const Preset& p)
{
    const SceneInfo& info = sceneInfo(p.scene);
    Document doc = Document::object();
    doc["format"] = std::string(formatTag);
    doc["version"] = static_cast<double>(Preset::currentVersion);
    doc["name"] = p.name;
    doc["description"] = p.description;
    doc["scene"] = info.key;
    doc["model"] = std::string(modelKey(p.model));
    if (p.integrator)
        doc["integrator"] = std::string(integratorKey(*p.integrator));
    if (p.impacts)
        doc["impacts"] = std::string(impactModeKey(*p.impacts));
    if (p.dt)
        doc["dt"] = *p.dt;
    if (p.steps)
        doc["steps"] = static_cast<double>(*p.steps); // exact: steps <= 4e9 < 2^53
    if (!p.params.empty()) {
        Document params = Document::object();
        for (const auto& [name, value] : p.params)
            params[name] = isVector(info, name) ? vectorValue(value) : Document(value.x());
        doc["params"] = std::move(params);
    }
    Document view = viewValue(p.view);
    if (!view.empty())
        doc["view"] = std::move(view);
    return doc;
}

} // namespace ab::presetfile
