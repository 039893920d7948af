// SPDX-License-Identifier: MIT
// Presets: every built-in loads, applies to its scene and says true things about its
// physics; applying one sets the whole setup or nothing; `amazeballs-cli run --preset` uses
// them. Their files: test_preset_files.cpp.
#include "core/io/preset.h"
#include "support/cli_runner.h"
#include "support/preset_helpers.h"
#include "support/report_listings.h"

#include <Eigen/Geometry>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <filesystem>
#include <numbers>
#include <sstream>

namespace {

using testing::cli;
using testing::CliResult;
using testing::presetDoc;
using testing::writeFile;

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
            const ab::Preset p = ab::loadPreset(key);
            QVERIFY2(p.model == ab::ModelKind::Report && p.params.empty() && !p.dt && !p.steps && !p.integrator, key);
            ab::RunSpec spec(p.scene);
            spec.params.set("g", Eigen::Vector3d(1.0, 0, 0)); // stale values are reset
            spec.dt = 0.5;
            ab::applyPreset(p, spec);
            QVERIFY2(spec.params == ab::sceneInfo(p.scene).defaults(), key);
            QVERIFY2(!spec.dt, key);
        }
        QCOMPARE(param(ab::loadPreset("many-balls-200"), "n").x(), 200.0); // Figure 3.1
    }

    void headOnPresetStopsTheMovingBall()
    {
        const ab::Preset p = ab::loadPreset("two-balls-head-on");
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
        const ab::Preset p = ab::loadPreset("two-balls-oblique");
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
        const ab::Preset p = ab::loadPreset("bounce1d-zeno-k09");
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
        const ab::Preset p = ab::loadPreset("box3d-tunnelling");
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

    void presetForAnotherSceneOrWithBadValuesChangesNothing()
    {
        ab::RunSpec spec(ab::SceneId::Box3d);
        spec.params.set("k", Eigen::Vector3d(0.5, 0, 0));
        const ab::RunSpec before = spec;
        const ab::Preset other = ab::loadPreset("two-balls-head-on");
        try {
            ab::applyPreset(other, spec);
            QFAIL("applied a two-balls preset to box3d");
        } catch (const ab::InputError& e) {
            QVERIFY2(std::string(e.what()).find("is for scene two-balls, not box3d") != std::string::npos, e.what());
        }
        // Valid values first, then a box too small for the start point: nothing is set.
        ab::Preset bad = ab::loadPreset("box3d-tunnelling");
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
        ab::applyPreset(ab::loadPreset("box3d-tunnelling"), spec);
        QCOMPARE(spec.model, ab::ModelKind::Physical);
        QCOMPARE(spec.integrator, ab::Integrator::Euler);
        QCOMPARE(spec.impacts, ab::ImpactMode::StepEnd);
        QCOMPARE(spec.dt, std::optional(0.25));
        QCOMPARE(spec.params.real("g"), 9.82); // not in the preset: the default again
        QVERIFY(spec.params.vector("v0") == Eigen::Vector3d(240, 0, 100));
        ab::applyPreset(ab::loadPreset("box3d-report"), spec);
        QCOMPARE(spec.integrator, ab::RunSpec(ab::SceneId::Box3d).integrator);
        QCOMPARE(spec.impacts, ab::ImpactMode::Located);
        QVERIFY(!spec.dt);
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
        writeFile(path, presetDoc("box3d", R"(, "steps": 700, "params": {"k": 0.75, "g": 5, "max_bounces": 30,
                                       "p0": [20, 60, 40]}, "view": {"selected_ball": 0})"));
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
