// SPDX-License-Identifier: MIT
// The preset file, version 1. Keys in this order; only format, version, name, scene and
// model are required, and no other key is allowed anywhere:
//
//   {
//     "format": "amazeballs-preset",
//     "version": 1,
//     "name": "One ball in a box, as in the report",   a short title
//     "description": "...",                            one or two sentences (optional)
//     "scene": "box3d",                                bounce1d | box3d | two-balls | many-balls | street
//     "model": "report",                               report | physical
//     "integrator": "rk4",                             any integrator key (optional)
//     "impacts": "located",                            located | step-end (optional)
//     "dt": 0.01,                                      step, > 0, scene time unit (optional)
//     "steps": 6000,                                   run length, whole, 0..4e9 (optional)
//     "params": {"k": 0.8, "p0": [2, 20, 2]},          only the ones set; vectors as [x, y, z],
//                                                      integers integral; checked against the
//                                                      scene's table and its cross-check
//     "view": {                                        what the app shows (optional, all parts)
//       "camera": {"yaw": 30, "pitch": 20, "distance": 600, "target": [150, 100, 150]},
//       "charts": ["position", "velocity"],
//       "selected_ball": 0,
//       "compare": {"model": "physical", "integrator": "rk4", "impacts": "located", "dt": 0.5}
//     }
//   }
//
// Yaw and pitch are in degrees (pitch within [-90, 90]), distance and target in the
// scene's length unit. `view.compare` runs the same scene again beside the first: its
// model is required; integrator and impacts default to symplectic-euler and located, and
// its dt (optional) to the main run's step. A preset is a whole setup: applying it resets what it leaves out
// (integrator, impacts, step, parameters) to the defaults. Every error names the file and
// the field path ("preset foo.json: params.k: ..."); reading never builds a simulation.
#include "preset.h"

#include "atomic_file.h"
#include "embedded_presets.h"
#include "input_file.h"
#include "preset_document.h"
#include "strict_json.h"

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstring>
#include <fstream>
#include <initializer_list>

namespace ab {

namespace {

using json::Document;
using Kind = Document::value_t;

constexpr long long maxSteps = 4'000'000'000LL; // as `run --steps`

// Where a value sits in the document, for messages: the file and a dotted path.
struct Where {
    const std::string& origin;
    std::string path; // e.g. "view.camera.yaw"; empty for the document itself

    Where operator/(std::string_view key) const
    {
        const std::string shownKey = printableInput(key); // a key may hold anything
        return {origin, path.empty() ? shownKey : path + "." + shownKey};
    }
    Where operator[](std::size_t i) const { return {origin, path + "[" + std::to_string(i) + "]"}; }

    [[noreturn]] void fail(const std::string& what) const
    {
        throw InputError(origin + ": " + (path.empty() ? std::string() : path + ": ") + what);
    }
};

std::string joined(const std::vector<std::string>& words)
{
    std::string out;
    for (const std::string& w : words)
        out += (out.empty() ? "" : ", ") + w;
    return out;
}

// ---- Reading: types --------------------------------------------------------------------

// Every number the reader makes is a double; a number of another kind is still a number.
void expectKind(const Document& v, Kind kind, const Where& at)
{
    if (v.type() != kind && !(kind == Kind::number_float && v.is_number()))
        at.fail("expected " + std::string(json::kindName(kind)) + ", found " + std::string(json::kindName(v.type())));
}

const Document::object_t& members(const Document& v)
{
    return v.get_ref<const Document::object_t&>();
}

// The member's value, or nullptr (a linear search, as the keys are few but for hostile text,
// which fails at its first unknown key).
const Document* find(const Document& obj, std::string_view key)
{
    for (const auto& [k, value] : members(obj))
        if (k == key)
            return &value;
    return nullptr;
}

// An object whose keys are all in `known`.
void checkObject(const Document& v, const Where& at, std::initializer_list<std::string_view> known)
{
    expectKind(v, Kind::object, at);
    for (const auto& [key, value] : members(v)) {
        if (std::find(known.begin(), known.end(), key) != known.end())
            continue;
        std::vector<std::string> names(known.begin(), known.end());
        (at / key).fail("unknown key (known here: " + joined(names) + ")");
    }
}

const Document& required(const Document& obj, std::string_view key, const Where& at)
{
    if (const Document* v = find(obj, key))
        return *v;
    at.fail("missing field '" + std::string(key) + "'");
}

const std::string& text(const Document& v, const Where& at)
{
    expectKind(v, Kind::string, at);
    return v.get_ref<const std::string&>();
}

double number(const Document& v, const Where& at)
{
    expectKind(v, Kind::number_float, at);
    return v.get<double>(); // finite: the JSON reader refuses anything else
}

long long whole(const Document& v, const Where& at, double min, double max)
{
    const double x = number(v, at);
    if (x != std::floor(x))
        at.fail(formatNumber(x) + " is not a whole number");
    if (x < min || x > max)
        at.fail(formatNumber(x) + " is outside [" + formatNumber(min) + ", " + formatNumber(max) + "]");
    return static_cast<long long>(x);
}

Eigen::Vector3d vector3(const Document& v, const Where& at)
{
    if (!v.is_array() || v.size() != 3)
        at.fail("expected an array of 3 numbers [x, y, z]");
    Eigen::Vector3d out;
    for (int i = 0; i < 3; ++i)
        out[i] = number(v[static_cast<std::size_t>(i)], at[static_cast<std::size_t>(i)]);
    return out;
}

template <typename E>
E key(const Document& v, const Where& at, std::optional<E> (*parse)(std::string_view), const std::string& choices)
{
    const std::string& k = text(v, at);
    if (const auto e = parse(k))
        return *e;
    at.fail("unknown value '" + printableInput(k) + "' (choose " + choices + ")");
}

std::optional<SceneId> sceneByKey(std::string_view k)
{
    const SceneInfo* info = findScene(k);
    return info ? std::optional<SceneId>(info->id) : std::nullopt;
}

std::string sceneChoices()
{
    std::vector<std::string> keys;
    for (const SceneInfo* s : allScenes())
        keys.push_back(s->key);
    return joined(keys);
}

std::string integratorChoices()
{
    std::vector<std::string> keys;
    for (Integrator i : allIntegrators())
        keys.emplace_back(integratorKey(i));
    return joined(keys);
}

// ---- Reading: the sections -------------------------------------------------------------

// Format and version come first, so a newer file is named as such before any key it adds
// is called unknown.
void readHeader(const Document& doc, const Where& root)
{
    expectKind(doc, Kind::object, root);
    const Document& format = required(doc, "format", root);
    if (!format.is_string() || format.get_ref<const std::string&>() != presetfile::formatTag)
        (root / "format")
            .fail("this is not an Amazeballs preset (expected \"" + std::string(presetfile::formatTag) + "\")");
    const Where at = root / "version";
    const double version = number(required(doc, "version", root), at);
    if (version > Preset::currentVersion)
        at.fail("made by a newer Amazeballs (file version " + formatNumber(version) + "; this program reads version " +
                std::to_string(Preset::currentVersion) + ")");
    if (version != Preset::currentVersion)
        at.fail(formatNumber(version) + " is not a preset version (this program reads version " +
                std::to_string(Preset::currentVersion) + ")");
}

std::vector<std::pair<std::string, Eigen::Vector3d>> readParams(const Document& v, const Where& at,
                                                                const SceneInfo& info)
{
    expectKind(v, Kind::object, at);
    std::vector<std::pair<std::string, Eigen::Vector3d>> params;
    for (const auto& [name, value] : members(v)) {
        const Where here = at / name;
        const ParamSpec* spec = info.findParam(name);
        if (!spec)
            here.fail("unknown parameter of " + info.key + " (known: " + joined(info.paramKeys()) + ")");
        const Eigen::Vector3d x =
            spec->kind == ParamKind::Vector ? vector3(value, here) : Eigen::Vector3d(number(value, here), 0, 0);
        // A double holds every whole number up to 2^53 - 1; beyond, the text was rounded.
        if (spec->kind == ParamKind::Integer && std::abs(x[0]) > 9007199254740991.0)
            here.fail(formatNumber(x[0]) + " is beyond 2^53 - 1 = 9007199254740991, the largest whole number "
                                           "kept exactly");
        params.emplace_back(name, x);
    }
    return params;
}

PresetView readView(const Document& v, const Where& at)
{
    checkObject(v, at, {"camera", "charts", "selected_ball", "compare", "speed"});
    PresetView view;
    if (const Document* camera = find(v, "camera")) {
        const Where c = at / "camera";
        checkObject(*camera, c, {"yaw", "pitch", "distance", "target"});
        if (const Document* x = find(*camera, "yaw"))
            view.cameraYaw = number(*x, c / "yaw");
        if (const Document* x = find(*camera, "pitch"))
            view.cameraPitch = number(*x, c / "pitch");
        if (const Document* x = find(*camera, "distance"))
            view.cameraDistance = number(*x, c / "distance");
        if (const Document* x = find(*camera, "target"))
            view.cameraTarget = vector3(*x, c / "target");
    }
    if (const Document* charts = find(v, "charts")) {
        expectKind(*charts, Kind::array, at / "charts");
        for (std::size_t i = 0; i < charts->size(); ++i)
            view.charts.push_back(text((*charts)[i], (at / "charts")[i]));
    }
    if (const Document* speed = find(v, "speed"))
        view.speed = number(*speed, at / "speed");
    if (const Document* ball = find(v, "selected_ball"))
        view.selectedBall = static_cast<int>(whole(*ball, at / "selected_ball", 0, 1e9));
    if (const Document* compare = find(v, "compare")) {
        const Where c = at / "compare";
        checkObject(*compare, c, {"model", "integrator", "impacts", "dt"});
        RunVariant variant;
        variant.model = key<ModelKind>(required(*compare, "model", c), c / "model", parseModel, "report, physical");
        if (const Document* x = find(*compare, "integrator"))
            variant.integrator = key<Integrator>(*x, c / "integrator", parseIntegrator, integratorChoices());
        if (const Document* x = find(*compare, "impacts"))
            variant.impacts = key<ImpactMode>(*x, c / "impacts", parseImpactMode, "located, step-end");
        if (const Document* x = find(*compare, "dt"))
            variant.dt = number(*x, c / "dt");
        view.compare = variant;
    }
    return view;
}

// ---- Checking values (shared by reading, saving and applying) ---------------------------

// A value for a message; a preset built in code may hold NaN, which is never printed.
std::string shown(double x)
{
    return std::isfinite(x) ? formatNumber(x) : std::string("a non-finite value");
}

bool isChartKey(const std::string& k)
{
    const auto& keys = presetChartKeys();
    return std::find(keys.begin(), keys.end(), k) != keys.end();
}

void checkView(const PresetView& view, const Where& at, long long ballCount)
{
    const Where camera = at / "camera";
    if (view.cameraYaw && !std::isfinite(*view.cameraYaw))
        (camera / "yaw").fail("not a finite number");
    if (view.cameraPitch && !(std::abs(*view.cameraPitch) <= 90.0))
        (camera / "pitch").fail(shown(*view.cameraPitch) + " is outside [-90, 90] degrees");
    if (view.cameraDistance && !(*view.cameraDistance > 0.0 && std::isfinite(*view.cameraDistance)))
        (camera / "distance").fail(shown(*view.cameraDistance) + " must be a positive distance");
    if (view.cameraTarget && !view.cameraTarget->allFinite())
        (camera / "target").fail("not three finite numbers");
    for (std::size_t i = 0; i < view.charts.size(); ++i) {
        const std::string& chart = view.charts[i];
        if (!isChartKey(chart))
            (at / "charts")[i].fail("unknown chart '" + printableInput(chart) + "' (choose " +
                                    joined(presetChartKeys()) + ")");
        if (std::find(view.charts.begin(), view.charts.begin() + static_cast<std::ptrdiff_t>(i), chart) !=
            view.charts.begin() + static_cast<std::ptrdiff_t>(i))
            (at / "charts")[i].fail("'" + printableInput(chart) + "' is listed twice");
    }
    if (view.selectedBall && (*view.selectedBall < 0 || *view.selectedBall >= ballCount))
        (at / "selected_ball")
            .fail(std::to_string(*view.selectedBall) + " is not a ball of this scene (balls 0 to " +
                  std::to_string(ballCount - 1) + ")");
    if (view.speed && !(*view.speed >= 0.1 && *view.speed <= 10.0))
        (at / "speed").fail(shown(*view.speed) + " is outside [0.1, 10] times real time");
    if (view.compare && view.compare->dt && !(*view.compare->dt > 0.0 && std::isfinite(*view.compare->dt)))
        (at / "compare" / "dt").fail(shown(*view.compare->dt) + " must be a positive step");
}

// Checks every value of the preset; returns the scene's parameters with the preset's set.
ParamValues checkPreset(const Preset& p, const std::string& origin)
{
    const Where root{origin, ""};
    const SceneInfo& info = sceneInfo(p.scene);
    if (p.dt && !(*p.dt > 0.0 && std::isfinite(*p.dt)))
        (root / "dt").fail(shown(*p.dt) + " must be a positive step in " + info.timeUnit);
    if (p.steps && (*p.steps < 0 || *p.steps > maxSteps))
        (root / "steps").fail(std::to_string(*p.steps) + " is outside [0, " + std::to_string(maxSteps) + "]");

    ParamValues values = info.defaults();
    std::vector<std::string> seen;
    for (const auto& [name, value] : p.params) {
        const Where at = root / "params" / name;
        if (!values.indexOf(name))
            at.fail("unknown parameter of " + info.key);
        if (std::find(seen.begin(), seen.end(), name) != seen.end())
            at.fail("set twice");
        seen.push_back(name);
        const ParamSpec& spec = values.spec(name);
        if (spec.kind != ParamKind::Vector && (value.y() != 0.0 || value.z() != 0.0))
            at.fail("holds a vector; this parameter is one number");
        if (const auto error = checkValue(spec, value))
            throw InputError(origin + ": params." + *error); // checkValue's text starts with the name
        values.set(name, value);
    }
    if (info.crossCheck) {
        try {
            info.crossCheck(values);
        } catch (const InputError& e) {
            throw InputError(origin + ": params." + e.what()); // the cross-check names the parameter first
        }
    }
    checkView(p.view, root / "view", info.ballCount != 0 ? info.ballCount : values.integer("n"));
    return values;
}

// How messages name a preset that has no file.
std::string presetOrigin(const Preset& p)
{
    return "preset '" + printableInput(p.name) + "'";
}

std::string readPresetFile(const std::string& path)
{
    // A regular file only, its size checked before it is read (input_file.h).
    return readInputFile(path, "preset", json::maxBytes);
}

} // namespace

Preset parsePreset(std::string_view jsonText, const std::string& origin)
{
    const Document doc = json::parse(jsonText, origin);
    const Where root{origin, ""};
    readHeader(doc, root);
    checkObject(doc, root,
                {"format", "version", "name", "description", "scene", "model", "integrator", "impacts", "dt", "steps",
                 "params", "view"});

    Preset p;
    p.name = text(required(doc, "name", root), root / "name");
    if (const Document* v = find(doc, "description"))
        p.description = text(*v, root / "description");
    p.scene = key<SceneId>(required(doc, "scene", root), root / "scene", sceneByKey, sceneChoices());
    p.model = key<ModelKind>(required(doc, "model", root), root / "model", parseModel, "report, physical");
    if (const Document* v = find(doc, "integrator"))
        p.integrator = key<Integrator>(*v, root / "integrator", parseIntegrator, integratorChoices());
    if (const Document* v = find(doc, "impacts"))
        p.impacts = key<ImpactMode>(*v, root / "impacts", parseImpactMode, "located, step-end");
    if (const Document* v = find(doc, "dt"))
        p.dt = number(*v, root / "dt");
    if (const Document* v = find(doc, "steps"))
        p.steps = whole(*v, root / "steps", 0, static_cast<double>(maxSteps));
    if (const Document* v = find(doc, "params"))
        p.params = readParams(*v, root / "params", sceneInfo(p.scene));
    if (const Document* v = find(doc, "view"))
        p.view = readView(*v, root / "view");
    checkPreset(p, origin);
    return p;
}

std::string presetToJson(const Preset& preset)
{
    checkPreset(preset, presetOrigin(preset));
    return json::write(presetfile::document(preset));
}

void savePreset(const std::filesystem::path& path, const Preset& preset)
{
    const std::string origin = "preset " + printableInput(path.string());
    checkPreset(preset, origin);
    const std::string text = presetToJson(preset);
    // Numbers are formatted by the C library; a locale with a decimal comma would make
    // text that is not JSON. Write only what reads back as the same preset.
    bool readsBack = false;
    try {
        readsBack = parsePreset(text, origin) == preset;
    } catch (const InputError&) {
    }
    if (!readsBack)
        throw std::logic_error(origin + ": not saved: the text would not read back as this preset");
    writeFileAtomically(path, [&](std::ostream& out) { out << text; });
}

const std::vector<std::string>& presetChartKeys()
{
    static const std::vector<std::string> keys{"position",   "velocity", "energy",    "momentum", "activity",
                                               "difference", "spin",     "foot-rate", "speeds"};
    return keys;
}

const std::vector<BuiltinPreset>& builtinPresets()
{
    static const std::vector<BuiltinPreset> list = [] {
        std::vector<BuiltinPreset> l;
        for (const embedded::File& f : embedded::presetFiles())
            l.push_back({std::string(f.key), parsePreset(f.text, "built-in preset " + std::string(f.key))});
        // The report's stages in order, each stage's report preset first.
        std::stable_sort(l.begin(), l.end(), [](const BuiltinPreset& a, const BuiltinPreset& b) {
            const auto rank = [](const BuiltinPreset& x) {
                return std::pair(sceneInfo(x.preset.scene).stage, !x.key.ends_with("-report"));
            };
            return rank(a) < rank(b);
        });
        return l;
    }();
    return list;
}

Preset loadPreset(const std::string& nameOrPath)
{
    for (const BuiltinPreset& b : builtinPresets())
        if (b.key == nameOrPath)
            return b.preset;
    if (!nameOrPath.ends_with(".json") && nameOrPath.find('/') == std::string::npos) {
        std::vector<std::string> keys;
        for (const BuiltinPreset& b : builtinPresets())
            keys.push_back(b.key);
        throw InputError("preset '" + printableInput(nameOrPath) + "': no built-in preset has that name (built-in: " +
                         joined(keys) + "); a preset file's name ends in .json");
    }
    const std::string origin = "preset " + printableInput(nameOrPath);
    return parsePreset(readPresetFile(nameOrPath), origin);
}

void applyPreset(const Preset& preset, RunSpec& spec)
{
    const std::string origin = presetOrigin(preset);
    if (preset.scene != spec.scene)
        throw InputError(origin + " is for scene " + sceneInfo(preset.scene).key + ", not " +
                         sceneInfo(spec.scene).key);
    ParamValues values = checkPreset(preset, origin);
    // Everything is checked: from here on nothing can fail, so nothing is half-applied.
    const RunSpec defaults(spec.scene);
    spec.model = preset.model;
    spec.integrator = preset.integrator.value_or(defaults.integrator);
    spec.impacts = preset.impacts.value_or(defaults.impacts);
    spec.dt = preset.dt;
    spec.params = std::move(values);
}

} // namespace ab
