// SPDX-License-Identifier: MIT
// Preset files: every built-in file is in the writer's form; presets round-trip exactly
// through text and files; a bad or oversized file is refused naming the field and changes
// nothing; saving never leaves a half-written or wrong file.
#include "core/io/embedded_presets.h"
#include "core/io/preset.h"
#include "support/cli_runner.h"
#include "support/preset_helpers.h"

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <limits>

namespace {

using testing::readFile;
using testing::writeFile;

QByteArray doc(const char* scene, const char* extra = "")
{
    return QByteArray::fromStdString(testing::presetDoc(scene, extra));
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

class PresetFiles : public QObject {
    Q_OBJECT

private slots:
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
        ab::Preset p = ab::loadPreset("box3d-report");
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
        ab::Preset p = ab::loadPreset("bounce1d-report");
        QVERIFY(!p.view.compare); // written before comparisons existed: still loads, with none
        for (const ab::RunVariant& v :
             {ab::RunVariant{ab::ModelKind::Report, ab::Integrator::SymplecticEuler, ab::ImpactMode::Located, {}},
              ab::RunVariant{ab::ModelKind::Physical, ab::Integrator::Event, ab::ImpactMode::StepEnd, 0.1 + 0.2}}) {
            p.view.compare = v;
            const ab::Preset back = ab::parsePreset(ab::presetToJson(p), "text");
            QVERIFY(back == p);
            QVERIFY(back.view.compare == v);
        }
        const ab::Preset shipped = ab::loadPreset("bounce1d-compare-report-physical");
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
};

QTEST_GUILESS_MAIN(PresetFiles)
#include "test_preset_files.moc"
