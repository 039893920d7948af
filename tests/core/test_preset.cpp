// SPDX-License-Identifier: MIT
// Presets: every built-in loads, applies to its scene and says true things about its
// physics; presets round-trip exactly through text and files; a bad preset file is refused
// naming the field and changes nothing; `amazeballs-cli run --preset` uses them.
#include "app/cli/cli.h"
#include "core/io/embedded_presets.h"
#include "core/io/preset.h"
#include "support/report_listings.h"

#include <Eigen/Geometry>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <sstream>

namespace {

struct CliResult {
    int status;
    std::string out, err;
};

CliResult cli(const std::vector<std::string>& args)
{
    std::ostringstream out, err;
    const int status = ab::cli::run(args, out, err);
    return {status, out.str(), err.str()};
}

std::string readFile(const std::filesystem::path& p)
{
    std::ifstream in(p, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), {}};
}

void writeFile(const std::filesystem::path& p, const std::string& text)
{
    std::ofstream(p, std::ios::binary) << text;
}

// A minimal valid preset document for `scene` with `extra` members appended.
QByteArray doc(const char* scene, const char* extra = "")
{
    return QByteArray(R"({"format": "amazeballs-preset", "version": 1, "name": "t", "scene": ")") + scene +
           R"(", "model": "report")" + extra + "}";
}

const ab::Preset& builtin(const std::string& key)
{
    for (const ab::BuiltinPreset& b : ab::builtinPresets())
        if (b.key == key)
            return b.preset;
    throw std::runtime_error("no built-in preset " + key);
}

Eigen::Vector3d param(const ab::Preset& p, const std::string& key)
{
    ab::RunSpec spec(p.scene);
    ab::applyPreset(p, spec);
    return spec.params.vector(key);
}

// Eqs 2.4-2.11 for equal masses: normal parts exchanged through restitution e,
// tangential parts kept. `n` is the unit line of centres.
std::pair<Eigen::Vector3d, Eigen::Vector3d> collide(const Eigen::Vector3d& v1, const Eigen::Vector3d& v2,
                                                    const Eigen::Vector3d& n, double e)
{
    const double v1n = v1.dot(n), v2n = v2.dot(n);
    const double v2nAfter = (e * (v1n - v2n) + v1n + v2n) / 2.0;       // eq 2.6
    const double v1nAfter = v1n + v2n - v2nAfter;                      // eq 2.7
    return {v1 - v1n * n + v1nAfter * n, v2 - v2n * n + v2nAfter * n}; // eqs 2.8-2.11
}

// Ball 1 moves straight at v1 (no gravity), ball 2 rests: where ball 1 is when the two
// centres are 2r apart, from |p1 + v1 t - p2| = 2r, the smaller root.
Eigen::Vector3d contactPosition(const Eigen::Vector3d& p1, const Eigen::Vector3d& v1, const Eigen::Vector3d& p2,
                                double r)
{
    const Eigen::Vector3d d = p1 - p2;
    const double a = v1.squaredNorm(), b = 2.0 * d.dot(v1), c = d.squaredNorm() - 4.0 * r * r;
    const double t = (-b - std::sqrt(b * b - 4.0 * a * c)) / (2.0 * a);
    return p1 + v1 * t;
}

ab::Preset awkwardPreset()
{
    ab::Preset p;
    p.name = "Tv\xC3\xA5 bollar, \"snett\"\nmed tab\t och \x01";
    p.description = "1/3 = 0.333\xE2\x80\xA6";
    p.scene = ab::SceneId::TwoBalls;
    p.model = ab::ModelKind::Physical;
    p.integrator = ab::Integrator::ImplicitMidpoint;
    p.impacts = ab::ImpactMode::StepEnd;
    p.dt = 1.0 / 3.0;
    p.steps = 4'000'000'000LL;
    p.params = {{"v1", {-1e-300, 5e-324, 0.1 + 0.2}},
                {"k", {2.0 / 3.0, 0, 0}},
                {"p1", {0.1, 1.0 / 3.0, 1e-300}},
                {"max_events", {999999999, 0, 0}},
                {"e", {0.1, 0, 0}}};
    p.view.cameraYaw = -0.1;
    p.view.cameraPitch = 89.99999999999999;
    p.view.cameraDistance = 1e300;
    p.view.cameraTarget = Eigen::Vector3d(1.0 / 3.0, -2.5e-310, 2e15 + 2);
    p.view.charts = {"energy", "momentum"};
    p.view.selectedBall = 1;
    p.view.compare = ab::RunVariant{ab::ModelKind::Physical, ab::Integrator::Rk4, ab::ImpactMode::StepEnd, 1.0 / 7.0};
    return p;
}

} // namespace

class Presets : public QObject {
    Q_OBJECT

private slots:
    void everyStageHasAPresetAsInTheReportAndTheInstructiveOnesExist()
    {
        std::vector<std::string> keys;
        for (const ab::BuiltinPreset& b : ab::builtinPresets())
            keys.push_back(b.key);
        for (const char* key :
             {"bounce1d-report", "box3d-report", "two-balls-report", "many-balls-report", "many-balls-200",
              "two-balls-head-on", "two-balls-oblique", "bounce1d-zeno-k09", "box3d-tunnelling"})
            QVERIFY2(std::find(keys.begin(), keys.end(), key) != keys.end(), key);
        // Listed in the report's order of stages.
        for (std::size_t i = 1; i < ab::builtinPresets().size(); ++i)
            QVERIFY(ab::sceneInfo(ab::builtinPresets()[i - 1].preset.scene).stage <=
                    ab::sceneInfo(ab::builtinPresets()[i].preset.scene).stage);
    }

    void everyBuiltinLoadsByNameAndAppliesToItsScene()
    {
        for (const ab::BuiltinPreset& b : ab::builtinPresets()) {
            const ab::Preset p = ab::loadPreset(b.key);
            QVERIFY2(p == b.preset, b.key.c_str());
            QVERIFY2(!p.name.empty() && p.description.size() > 40, b.key.c_str());
            ab::RunSpec spec(p.scene);
            ab::applyPreset(p, spec);
            QCOMPARE(spec.model, p.model);
            for (const auto& [key, value] : p.params)
                QVERIFY2(spec.params.vector(key) == value, (b.key + " " + key).c_str());
            if (p.model == ab::ModelKind::Report) {
                const auto sim = ab::makeSimulation(spec); // the report's model builds and steps
                ab::State s = sim->start(), next;
                sim->step(s, next);
                QVERIFY(next.p.allFinite());
            }
        }
    }

    void reportPresetsAreExactlyTheReportsConstants()
    {
        for (const char* key : {"bounce1d-report", "box3d-report", "two-balls-report", "many-balls-report"}) {
            const ab::Preset& p = builtin(key);
            QVERIFY2(p.model == ab::ModelKind::Report && p.params.empty() && !p.dt && !p.steps && !p.integrator, key);
            ab::RunSpec spec(p.scene);
            spec.params.set("g", Eigen::Vector3d(1.0, 0, 0)); // stale values are reset
            spec.dt = 0.5;
            ab::applyPreset(p, spec);
            QVERIFY2(spec.params == ab::sceneInfo(p.scene).defaults(), key);
            QVERIFY2(!spec.dt, key);
        }
        QCOMPARE(param(builtin("many-balls-200"), "n").x(), 200.0); // Figure 3.1
    }

    void headOnPresetStopsTheMovingBall()
    {
        const ab::Preset& p = builtin("two-balls-head-on");
        QCOMPARE(p.model, ab::ModelKind::Physical);
        const Eigen::Vector3d p1 = param(p, "p1"), v1 = param(p, "v1"), p2 = param(p, "p2"), v2 = param(p, "v2");
        QCOMPARE(param(p, "g").x(), 0.0);
        QCOMPARE(v2.norm(), 0.0);
        QVERIFY((p2 - p1).normalized().cross(v1).norm() < 1e-15); // centre on centre
        const double r = param(p, "r").x();
        QCOMPARE(((p2 - p1).norm() - 2.0 * r) / v1.norm(), 9.0); // "they touch at t = 9 s"
        const auto [after1, after2] = collide(v1, v2, (p2 - p1).normalized(), param(p, "e").x());
        QCOMPARE(after1.norm(), 0.0); // stops dead
        QVERIFY((after2 - v1).norm() < 1e-12);
    }

    void obliquePresetSendsTheBallsOffAtRightAngles()
    {
        const ab::Preset& p = builtin("two-balls-oblique");
        const Eigen::Vector3d p1 = param(p, "p1"), v1 = param(p, "v1"), p2 = param(p, "p2"), v2 = param(p, "v2");
        const double r = param(p, "r").x();
        QCOMPARE(param(p, "g").x(), 0.0);
        const Eigen::Vector3d n = (p2 - contactPosition(p1, v1, p2, r)).normalized();
        QVERIFY(std::abs(std::acos(n.dot(v1.normalized())) - std::numbers::pi / 6.0) <
                1e-12); // 30 degrees off the path
        const auto [after1, after2] = collide(v1, v2, n, param(p, "e").x());
        QVERIFY(std::abs(after1.dot(after2)) < 1e-12);                                      // right angles
        QVERIFY(std::abs(after2.norm() - 10.0 * std::cos(std::numbers::pi / 6.0)) < 1e-12); // 8.66 m/s
        QVERIFY(std::abs(after1.norm() - 5.0) < 1e-12);                                     // 10 sin 30
        QVERIFY(std::abs((after1 + after2 - v1).norm()) < 1e-12);                           // momentum, eq 2.4
    }

    void zenoPresetRunsPastTheZenoTime()
    {
        const ab::Preset& p = builtin("bounce1d-zeno-k09");
        QCOMPARE(p.integrator, std::optional(ab::Integrator::Event));
        const double k = param(p, "k").x(), g = param(p, "g").x(), h0 = param(p, "h0").x();
        QCOMPARE(k, 0.9);
        // First fall t0 = sqrt(2 h0 / g); flights 2 k^i t0 sum to t0 (1 + k) / (1 - k).
        const double t0 = std::sqrt(2.0 * h0 / g);
        const double zeno = t0 * (1.0 + k) / (1.0 - k);
        QVERIFY(std::abs(t0 - 201.8) < 0.05);
        QVERIFY(std::abs(zeno - 3835.0) < 1.0);
        const double dt = p.dt.value_or(ab::sceneInfo(p.scene).reportDt);
        QVERIFY(double(*p.steps) * dt > zeno * 1.1); // the run shows the ball at rest
    }

    void tunnellingPresetStepJumpsThirtyMetresPastTheWall()
    {
        const ab::Preset& p = builtin("box3d-tunnelling");
        QCOMPARE(p.impacts, std::optional(ab::ImpactMode::StepEnd));
        QCOMPARE(p.integrator, std::optional(ab::Integrator::Euler));
        const double dt = *p.dt, box = param(p, "box").x();
        const Eigen::Vector3d p0 = param(p, "p0"), v0 = param(p, "v0");
        QCOMPARE(v0.x() * dt, 60.0); // "one step covers 60 m, a fifth of the box"
        QCOMPARE(v0.x() * dt / box, 0.2);
        // x has no force, so every scheme moves it by vx dt until the first impact.
        double x = p0.x();
        while (x + v0.x() * dt <= box)
            x += v0.x() * dt;
        QCOMPARE(x, 270.0);
        QCOMPARE(x + v0.x() * dt - box, 30.0);
        QVERIFY(p0.z() + v0.z() * (x - p0.x()) / v0.x() < box); // z reaches no wall first
    }

    void everyBuiltinFileIsInTheWritersFormAndRoundTripsExactly()
    {
        QCOMPARE(ab::embedded::presetFiles().size(), ab::builtinPresets().size());
        for (const ab::embedded::File& f : ab::embedded::presetFiles()) {
            const ab::Preset p = ab::parsePreset(f.text, std::string(f.key));
            QCOMPARE(ab::presetToJson(p), std::string(f.text));
            QVERIFY(ab::parsePreset(ab::presetToJson(p), "again") == p);
        }
    }

    void awkwardDoublesRoundTripExactlyThroughAFile()
    {
        const ab::Preset p = awkwardPreset();
        QVERIFY(ab::parsePreset(ab::presetToJson(p), "text") == p);
        QTemporaryDir dir;
        const std::filesystem::path path = dir.filePath("awkward.json").toStdString();
        ab::savePreset(path, p);
        const ab::Preset back = ab::loadPreset(path.string());
        QVERIFY(back == p);
        QCOMPARE(back.params[2].second.z(), 1e-300);
        QCOMPARE(back.params[0].second.y(), 5e-324);
        QCOMPARE(*back.dt, 1.0 / 3.0);
        QCOMPARE(readFile(path), ab::presetToJson(p));
    }

    void savingAnInvalidPresetLeavesTheOldFileAlone()
    {
        QTemporaryDir dir;
        const std::filesystem::path path = dir.filePath("keep.json").toStdString();
        writeFile(path, "precious\n");
        ab::Preset p = builtin("box3d-report");
        p.params = {{"k", {1.5, 0, 0}}};
        try {
            ab::savePreset(path, p);
            QFAIL("saved a preset with k = 1.5");
        } catch (const ab::InputError& e) {
            QVERIFY2(std::string(e.what()).find("params.k: 1.5 is outside") != std::string::npos, e.what());
        }
        p.params.clear();
        p.dt = std::numeric_limits<double>::quiet_NaN();
        try {
            ab::savePreset(path, p);
            QFAIL("saved a preset with a NaN step");
        } catch (const ab::InputError& e) {
            const std::string m = e.what();
            QVERIFY2(m.find("dt: a non-finite value must be a positive step") != std::string::npos, e.what());
            QVERIFY2(m.find("nan") == std::string::npos, e.what()); // never printed
        }
        p.dt.reset();
        p.params = {{"k", {0.5, 0.5, 0}}}; // a scalar holding a vector would not survive the file
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::savePreset(path, p));
        QCOMPARE(readFile(path), std::string("precious\n"));
        QCOMPARE(std::distance(std::filesystem::directory_iterator(path.parent_path()), {}), 1L);
    }

    void badPresetFileIsRefusedNamingTheFieldAndChangesNothing_data()
    {
        QTest::addColumn<QByteArray>("json");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("malformed JSON") << QByteArray(R"({"format": "amazeballs-preset", "version": 1,})")
                                        << "line 1 column 46: syntax error while parsing object key - unexpected '}'";
        QTest::newRow("number beyond a double")
            << doc("box3d", R"(, "params": {"k": 1e999})") << "the number 1e999 is outside the range of a double";
        QTest::newRow("duplicate key") << doc("box3d", R"(, "params": {"k": 0.5, "k": 0.6})") << "duplicate key 'k'";
        QTest::newRow("not an object") << QByteArray("[1, 2]") << "expected an object, found an array";
        QTest::newRow("not a preset") << QByteArray(R"({"format": "csv", "version": 1})")
                                      << "format: this is not an Amazeballs preset";
        QTest::newRow("missing format") << QByteArray(R"({"version": 1, "scene": "box3d"})")
                                        << "missing field 'format'";
        QTest::newRow("newer version")
            << QByteArray(R"({"format": "amazeballs-preset", "version": 2, "scene": "box3d", "lights": true})")
            << "version: made by a newer Amazeballs (file version 2; this program reads version 1)";
        QTest::newRow("version zero") << QByteArray(R"({"format": "amazeballs-preset", "version": 0})")
                                      << "version: 0 is not a preset version";
        QTest::newRow("version as text") << QByteArray(R"({"format": "amazeballs-preset", "version": "1"})")
                                         << "version: expected a number, found a string";
        QTest::newRow("missing scene")
            << QByteArray(R"({"format": "amazeballs-preset", "version": 1, "name": "t", "model": "report"})")
            << "missing field 'scene'";
        QTest::newRow("missing model")
            << QByteArray(R"({"format": "amazeballs-preset", "version": 1, "name": "t", "scene": "box3d"})")
            << "missing field 'model'";
        QTest::newRow("unknown scene") << doc("three-balls")
                                       << "scene: unknown value 'three-balls' (choose bounce1d, box3d, two-balls";
        QTest::newRow("unknown key") << doc("box3d", R"(, "colour": "red")") << "colour: unknown key (known here:";
        QTest::newRow("unknown key with a line break")
            << doc("box3d", ", \"a\\nb\": 1") << "a\\nb: unknown key (known here:";
        QTest::newRow("unknown key in the camera") << doc("box3d", R"(, "view": {"camera": {"zoom": 2}})")
                                                   << "view.camera.zoom: unknown key (known here: yaw, pitch";
        QTest::newRow("name as a number") << QByteArray(R"({"format": "amazeballs-preset", "version": 1, "name": 5})")
                                          << "name: expected a string, found a number";
        QTest::newRow("step as text") << doc("box3d", R"(, "dt": "0.01")") << "dt: expected a number, found a string";
        QTest::newRow("zero step") << doc("box3d", R"(, "dt": 0)") << "dt: 0 must be a positive step in s";
        QTest::newRow("fractional steps") << doc("box3d", R"(, "steps": 2.5)") << "steps: 2.5 is not a whole number";
        QTest::newRow("negative steps") << doc("box3d", R"(, "steps": -1)") << "steps: -1 is outside [0, 4000000000]";
        QTest::newRow("unknown integrator")
            << doc("box3d", R"(, "integrator": "leapfrog")") << "integrator: unknown value 'leapfrog'";
        QTest::newRow("impacts as a flag")
            << doc("box3d", R"(, "impacts": true)") << "impacts: expected a string, found true or false";
        QTest::newRow("params as a list")
            << doc("box3d", R"(, "params": [0.5])") << "params: expected an object, found an array";
        QTest::newRow("unknown parameter") << doc("box3d", R"(, "params": {"q": 1})")
                                           << "params.q: unknown parameter of box3d (known: g, k, box, p0, v0, ";
        QTest::newRow("parameter of another scene")
            << doc("box3d", R"(, "params": {"e": 0.5})") << "params.e: unknown parameter of box3d";
        QTest::newRow("out of range") << doc("box3d", R"(, "params": {"k": 1.5})")
                                      << "params.k: 1.5 is outside the allowed range [0, 1]";
        QTest::newRow("box of side zero") << doc("box3d", R"(, "params": {"box": 0})")
                                          << "params.box: 0 is outside the allowed range (0, 1000000000] m";
        QTest::newRow("short vector") << doc("box3d", R"(, "params": {"p0": [1, 2]})")
                                      << "params.p0: expected an array of 3 numbers [x, y, z]";
        QTest::newRow("text in a vector")
            << doc("box3d", R"(, "params": {"p0": [1, "2", 3]})") << "params.p0[1]: expected a number, found a string";
        QTest::newRow("vector for a number")
            << doc("box3d", R"(, "params": {"k": [1, 2, 3]})") << "params.k: expected a number, found an array";
        QTest::newRow("fractional count")
            << doc("box3d", R"(, "params": {"max_bounces": 2.5})") << "params.max_bounces: 2.5 is not a whole number";
        QTest::newRow("start outside the box")
            << doc("box3d", R"(, "params": {"p0": [400, 5, 5]})") << "params.p0: 400,5,5 lies outside the box";
        QTest::newRow("huge n") << doc("many-balls", R"(, "params": {"n": 1e12})")
                                << "params.n: 1000000000000 is outside the allowed range [1, 4000000]";
        QTest::newRow("selected ball beyond the scene")
            << doc("box3d", R"(, "view": {"selected_ball": 1})") << "view.selected_ball: 1 is not a ball of this scene";
        QTest::newRow("selected ball beyond n")
            << doc("many-balls", R"(, "params": {"n": 10}, "view": {"selected_ball": 10})")
            << "view.selected_ball: 10 is not a ball of this scene (balls 0 to 9)";
        QTest::newRow("camera upside down") << doc("box3d", R"(, "view": {"camera": {"pitch": 120}})")
                                            << "view.camera.pitch: 120 is outside [-90, 90] degrees";
        QTest::newRow("camera behind its target") << doc("box3d", R"(, "view": {"camera": {"distance": -5}})")
                                                  << "view.camera.distance: -5 must be a positive distance";
        QTest::newRow("chart as a number")
            << doc("box3d", R"(, "view": {"charts": [1]})") << "view.charts[0]: expected a string, found a number";
        QTest::newRow("unknown chart") << doc("box3d", R"(, "view": {"charts": ["nosuchchart"]})")
                                       << "view.charts[0]: unknown chart 'nosuchchart'";
        QTest::newRow("chart twice") << doc("box3d", R"(, "view": {"charts": ["velocity", "velocity"]})")
                                     << "view.charts[1]: 'velocity' is listed twice";
        QTest::newRow("compare without a model")
            << doc("box3d", R"(, "view": {"compare": {"integrator": "rk4"}})") << "view.compare: missing field 'model'";
        QTest::newRow("compare with an unknown model")
            << doc("box3d", R"(, "view": {"compare": {"model": "magic"}})")
            << "view.compare.model: unknown value 'magic' (choose report, physical)";
        QTest::newRow("compare with an unknown integrator")
            << doc("box3d", R"(, "view": {"compare": {"model": "physical", "integrator": "leapfrog"}})")
            << "view.compare.integrator: unknown value 'leapfrog'";
        QTest::newRow("compare with an unknown key")
            << doc("box3d", R"(, "view": {"compare": {"model": "physical", "colour": "red"}})")
            << "view.compare.colour: unknown key";
        QTest::newRow("compare with a negative step")
            << doc("box3d", R"(, "view": {"compare": {"model": "physical", "dt": -1}})")
            << "view.compare.dt: -1 must be a positive step";
        QTest::newRow("compare as a string")
            << doc("box3d", R"(, "view": {"compare": "physical"})") << "view.compare: expected an object";
    }

    void compareChoiceRoundTripsExactlyAndAnOldPresetHasNone()
    {
        ab::Preset p = builtin("bounce1d-report");
        QVERIFY(!p.view.compare); // written before comparisons existed: still loads, with none
        for (const ab::RunVariant& v :
             {ab::RunVariant{ab::ModelKind::Report, ab::Integrator::SymplecticEuler, ab::ImpactMode::Located, {}},
              ab::RunVariant{ab::ModelKind::Physical, ab::Integrator::Event, ab::ImpactMode::StepEnd, 0.1 + 0.2}}) {
            p.view.compare = v;
            const ab::Preset back = ab::parsePreset(ab::presetToJson(p), "text");
            QVERIFY(back == p);
            QVERIFY(back.view.compare == v);
        }
        const ab::Preset& shipped = builtin("bounce1d-compare-report-physical");
        QCOMPARE(shipped.model, ab::ModelKind::Report);
        QVERIFY(shipped.view.compare);
        QCOMPARE(shipped.view.compare->model, ab::ModelKind::Physical);
        QCOMPARE(shipped.view.compare->integrator, ab::Integrator::SymplecticEuler);
    }

    void badPresetFileIsRefusedNamingTheFieldAndChangesNothing()
    {
        QFETCH(QByteArray, json);
        QFETCH(QString, mentions);
        QTemporaryDir dir;
        const std::string path = dir.filePath("bad.json").toStdString();
        writeFile(path, json.toStdString());

        ab::RunSpec spec(ab::SceneId::Box3d);
        spec.model = ab::ModelKind::Physical;
        spec.integrator = ab::Integrator::Rk4;
        spec.impacts = ab::ImpactMode::StepEnd;
        spec.dt = 0.02;
        spec.params.set("k", Eigen::Vector3d(0.5, 0, 0));
        const ab::RunSpec before = spec;
        try {
            ab::applyPreset(ab::loadPreset(path), spec);
            QFAIL("the preset was accepted");
        } catch (const ab::InputError& e) {
            const QString message = e.what();
            QVERIFY2(message.startsWith(QString::fromStdString("preset " + path + ": ")) ||
                         message.startsWith(QString::fromStdString("preset " + path + " line ")),
                     e.what());
            QVERIFY2(message.contains(mentions), e.what());
            QVERIFY2(!message.contains('\n'), e.what());
        }
        QCOMPARE(spec.model, before.model);
        QCOMPARE(spec.integrator, before.integrator);
        QCOMPARE(spec.impacts, before.impacts);
        QCOMPARE(spec.dt, before.dt);
        QVERIFY(spec.params == before.params);
    }

    void presetForAnotherSceneOrWithBadValuesChangesNothing()
    {
        ab::RunSpec spec(ab::SceneId::Box3d);
        spec.params.set("k", Eigen::Vector3d(0.5, 0, 0));
        const ab::RunSpec before = spec;
        const ab::Preset& other = builtin("two-balls-head-on");
        try {
            ab::applyPreset(other, spec);
            QFAIL("applied a two-balls preset to box3d");
        } catch (const ab::InputError& e) {
            QVERIFY2(std::string(e.what()).find("is for scene two-balls, not box3d") != std::string::npos, e.what());
        }
        // Valid values first, then a box too small for the start point: nothing is set.
        ab::Preset bad = builtin("box3d-tunnelling");
        bad.params = {{"k", {0.25, 0, 0}}, {"box", {1, 0, 0}}};
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::applyPreset(bad, spec));
        QCOMPARE(spec.model, before.model);
        QCOMPARE(spec.dt, before.dt);
        QVERIFY(spec.params == before.params);
    }

    void applyingSetsTheWholeSetupAndResetsWhatThePresetLeavesOut()
    {
        ab::RunSpec spec(ab::SceneId::Box3d);
        spec.integrator = ab::Integrator::Verlet;
        spec.params.set("g", Eigen::Vector3d(1.0, 0, 0));
        ab::applyPreset(builtin("box3d-tunnelling"), spec);
        QCOMPARE(spec.model, ab::ModelKind::Physical);
        QCOMPARE(spec.integrator, ab::Integrator::Euler);
        QCOMPARE(spec.impacts, ab::ImpactMode::StepEnd);
        QCOMPARE(spec.dt, std::optional(0.25));
        QCOMPARE(spec.params.real("g"), 9.82); // not in the preset: the default again
        QVERIFY(spec.params.vector("v0") == Eigen::Vector3d(240, 0, 100));
        ab::applyPreset(builtin("box3d-report"), spec);
        QCOMPARE(spec.integrator, ab::RunSpec(ab::SceneId::Box3d).integrator);
        QCOMPARE(spec.impacts, ab::ImpactMode::Located);
        QVERIFY(!spec.dt);
    }

    void unknownNameListsTheBuiltinPresets()
    {
        try {
            ab::loadPreset("box3d-repot");
            QFAIL("loaded a preset that does not exist");
        } catch (const ab::InputError& e) {
            const std::string m = e.what();
            QVERIFY2(m.find("preset 'box3d-repot': no built-in preset") != std::string::npos, e.what());
            QVERIFY2(m.find("box3d-report, ") != std::string::npos, e.what());
        }
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::loadPreset("/nonexistent/folder/x.json"));
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::loadPreset("/tmp"));
    }

    void oversizedFileIsRefusedUnparsed()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("big.json").toStdString();
        writeFile(path, std::string(doc("box3d").constData()) + std::string(2 << 20, ' '));
        try {
            ab::loadPreset(path);
            QFAIL("loaded a 2 MiB preset");
        } catch (const ab::InputError& e) {
            QVERIFY2(std::string(e.what()).find("larger than 1 MiB") != std::string::npos, e.what());
        }
    }

    void cliRunWithTheReportPresetIsTheDefaultRun()
    {
        const CliResult preset = cli({"run", "box3d", "--preset", "box3d-report"});
        const CliResult plain = cli({"run", "box3d"});
        QCOMPARE(preset.status, 0);
        QCOMPARE(preset.out.size(), plain.out.size());
        QVERIFY(preset.out == plain.out);
        // Options after the preset still win.
        QVERIFY(cli({"run", "box3d", "--preset", "box3d-report", "--set", "k=0.5"}).out ==
                cli({"run", "box3d", "--set", "k=0.5"}).out);
    }

    void cliRunWithAPresetFileFollowsTheReportsListing()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("mine.json").toStdString();
        writeFile(path, doc("box3d", R"(, "steps": 700, "params": {"k": 0.75, "g": 5, "max_bounces": 30,
                                       "p0": [20, 60, 40]}, "view": {"selected_ball": 0})")
                            .toStdString());
        const CliResult r = cli({"run", "box3d", "--preset", path});
        QCOMPARE(r.status, 0);
        std::istringstream in(r.out);
        std::string line;
        std::getline(in, line);
        const auto ref = listing::appendixB(-5, 0.75, 300, {20, 60, 40}, {10, 0, 15}, 30, 700);
        std::size_t rows = 0;
        while (std::getline(in, line)) {
            double t, p[3], v[3];
            int ball;
            QCOMPARE(std::sscanf(line.c_str(), "%lf,%d,%lf,%lf,%lf,%lf,%lf,%lf", &t, &ball, &p[0], &p[1], &p[2], &v[0],
                                 &v[1], &v[2]),
                     8);
            for (int a = 0; a < 3; ++a)
                QVERIFY(std::abs(p[a] - ref.p[rows][a]) <= 1e-12 * std::max(1.0, std::abs(ref.p[rows][a])));
            ++rows;
        }
        QCOMPARE(rows, std::size_t(701)); // the preset's steps, and the start
    }

    void cliRefusesAMissingPresetFileWithStatus2()
    {
        const CliResult missing = cli({"run", "box3d", "--preset", "/nonexistent/preset.json"});
        QCOMPARE(missing.status, 2);
        QVERIFY2(missing.err.find("preset: /nonexistent/preset.json: no such file") != std::string::npos,
                 missing.err.c_str());
        QVERIFY(missing.out.empty());
        const CliResult wrongScene = cli({"run", "two-balls", "--preset", "box3d-report"});
        QCOMPARE(wrongScene.status, 2);
        QVERIFY2(wrongScene.err.find("is for scene box3d, not two-balls") != std::string::npos, wrongScene.err.c_str());
    }
};

QTEST_GUILESS_MAIN(Presets)
#include "test_preset.moc"
