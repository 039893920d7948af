// SPDX-License-Identifier: MIT
// Presets in the window (offscreen): a saved preset reads back equal and, opened, puts
// the window back exactly; a bad preset is refused with one message naming the field and
// changes nothing; a dropped .json file opens; every built-in opens and does what its
// description says, checked against the physics (closed forms and conservation laws).
#include "ui/main_window.h"
#include "ui/panels/chart_panel.h"
#include "ui/panels/parameter_panel.h"
#include "ui/panels/run_options_panel.h"
#include "ui/presets/preset_actions.h"
#include "ui/sim/run_controller.h"

#include "core/io/preset.h"

#include <QChartView>
#include <QComboBox>
#include <QFile>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QMessageBox>
#include <QMimeData>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QUrl>
#include <QtTest>

#include <numbers>

using ab::Preset;
using ab::SceneId;
using ab::ui::MainWindow;
using ab::ui::PresetActions;

namespace {

PresetActions* presetsOf(MainWindow& w)
{
    return w.findChild<PresetActions*>();
}

Preset snapshot(MainWindow& w)
{
    return ab::ui::capturePreset(w, "snapshot", "");
}

void writeText(const QString& path, const QByteArray& text)
{
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(text);
}

// The window's run from its own spec: every state up to `tEnd`.
std::vector<ab::State> runOf(MainWindow& w, double tEnd)
{
    auto sim = ab::makeSimulation(w.controller().spec());
    const long long steps = std::llround(std::ceil(tEnd / sim->dt()));
    std::vector<ab::State> states;
    ab::runRecorded(*sim, sim->start(), steps, 1, [&](const ab::State& s) { states.push_back(s); });
    return states;
}

const ab::State& at(const std::vector<ab::State>& states, double t)
{
    return *std::find_if(states.begin(), states.end(), [t](const ab::State& s) { return s.t >= t - 1e-9; });
}

} // namespace

class UiPresets : public QObject {
    Q_OBJECT

private slots:
    void savedPresetReadsBackEqualAndRestoresTheWindow()
    {
        QTemporaryDir dir;
        MainWindow w;
        // A setup far from the defaults: stage 2, physical model, RK4, own step and run
        // length, two constants changed, one chart hidden.
        w.showScene(SceneId::Box3d);
        ab::ui::RunOptions options{
            ab::ModelKind::Physical, ab::Integrator::Rk4, ab::ImpactMode::StepEnd, 0.005, 1234, {}};
        QVERIFY(w.applyOptions(options));
        ab::ParamValues values = w.controller().spec().params;
        values.parse("k", "0.75");
        values.parse("v0", "3,4,5");
        QVERIFY(w.applyValues(values));
        w.charts()->chartView(ab::ui::ChartKind::Energy)->setHidden(true);
        const Preset before = snapshot(w);

        const QString path = dir.filePath("mine.json");
        presetsOf(w)->saveTo(path);
        const Preset read = ab::loadPreset(path.toStdString());
        QCOMPARE(read.scene, before.scene);
        QVERIFY(read.view == before.view);
        QVERIFY(read.params == before.params);
        QVERIFY(read.integrator == before.integrator);
        QVERIFY(read.dt == std::optional<double>(0.005));
        QVERIFY(read.steps == std::optional<long long>(1234));

        // A fresh window opens it and shows the same setup everywhere.
        MainWindow other;
        QVERIFY(!presetsOf(other)->open(path));
        Preset again = snapshot(other);
        again.name = read.name;
        again.description = read.description;
        QVERIFY(again == read);
        QCOMPARE(other.scene(), SceneId::Box3d);
        QCOMPARE(other.controller().plannedSteps(), 1234LL);
        QCOMPARE(other.runOptions()->modelBox()->currentData().toInt(), int(ab::ModelKind::Physical));
        QCOMPARE(other.runOptions()->integratorBox()->currentData().toInt(), int(ab::Integrator::Rk4));
        QCOMPARE(other.parameters()->field("k")->text(), QString("0.75"));
        QVERIFY(other.charts()->chartView(ab::ui::ChartKind::Energy)->isHidden());
        QVERIFY(!other.charts()->chartView(ab::ui::ChartKind::Position)->isHidden());
        QVERIFY(other.controller().spec().params == w.controller().spec().params);
    }

    void badPresetIsRefusedNamingTheFieldAndChangesNothing_data()
    {
        QTest::addColumn<QByteArray>("text");
        QTest::addColumn<QString>("named");
        const QByteArray head = R"({"format": "amazeballs-preset", "version": 1, "name": "x", )";
        QTest::newRow("restitution above 1") << head + R"("scene": "box3d", "model": "physical", "params": {"k": 1.5}})"
                                             << "params.k";
        QTest::newRow("unknown integrator")
            << head + R"("scene": "box3d", "model": "physical", "integrator": "leapfrog"})"
            << "integrator";
        QTest::newRow("negative step") << head + R"("scene": "bounce1d", "model": "report", "dt": -1})"
                                       << "dt";
        QTest::newRow("unknown chart") << head +
                                              R"("scene": "box3d", "model": "report", "view": {"charts": ["torque"]}})"
                                       << "view.charts[0]";
        QTest::newRow("ball out of range")
            << head + R"("scene": "two-balls", "model": "report", "view": {"selected_ball": 2}})"
            << "selected_ball";
        QTest::newRow("malformed json") << QByteArray(R"({"format": "amazeballs-preset", "version": 1,)") << "line";
        QTest::newRow("newer version") << QByteArray(R"({"format": "amazeballs-preset", "version": 7})") << "version";
    }

    void badPresetIsRefusedNamingTheFieldAndChangesNothing()
    {
        QFETCH(QByteArray, text);
        QFETCH(QString, named);
        QTemporaryDir dir;
        const QString path = dir.filePath("bad.json");
        writeText(path, text);

        MainWindow w;
        w.showScene(SceneId::Bounce1d);
        ab::ParamValues values = w.controller().spec().params;
        values.parse("k", "0.5");
        QVERIFY(w.applyValues(values));
        w.controller().stepOnce();
        w.controller().stepOnce();
        QTRY_COMPARE(w.controller().status().steps, 2LL);
        const Preset before = snapshot(w);
        const auto* engine = &w.controller().engine();

        const auto error = presetsOf(w)->open(path);
        QVERIFY(error);
        QVERIFY2(error->contains(named), qPrintable(*error));
        QVERIFY2(!error->contains('\n'), qPrintable(*error)); // one line
        auto* box = w.findChild<QMessageBox*>("presetError");
        QVERIFY(box);
        QCOMPARE(box->text(), *error);

        QVERIFY(snapshot(w) == before);
        QCOMPARE(w.scene(), SceneId::Bounce1d);
        QCOMPARE(&w.controller().engine(), engine); // the same run, not a new one
        QCOMPARE(w.controller().status().steps, 2LL);
        QCOMPARE(w.parameters()->field("k")->text(), QString("0.5"));
    }

    void droppedJsonFileOpensAsAPreset()
    {
        QTemporaryDir dir;
        const QString path = dir.filePath("dropped.json");
        writeText(path, QByteArray::fromStdString(ab::presetToJson(ab::loadPreset("two-balls-oblique"))));
        MainWindow w;
        QCOMPARE(w.scene(), SceneId::Bounce1d);

        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile(path)});
        QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(&w, &enter);
        QVERIFY(enter.isAccepted());
        QDropEvent drop(QPointF(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        QCoreApplication::sendEvent(&w, &drop);
        QVERIFY(drop.isAccepted());

        QCOMPARE(w.scene(), SceneId::TwoBalls);
        QCOMPARE(w.controller().spec().model, ab::ModelKind::Physical);
        QVERIFY(w.controller().spec().params.vector("p2") == Eigen::Vector3d(155, 150, 200));
    }

    void dragOfAnotherFileIsNotTaken()
    {
        MainWindow w;
        QMimeData mime;
        mime.setUrls({QUrl::fromLocalFile("/tmp/picture.png")});
        QDragEnterEvent enter(QPoint(10, 10), Qt::CopyAction, &mime, Qt::LeftButton, Qt::NoModifier);
        enter.setAccepted(false);
        QCoreApplication::sendEvent(&w, &enter);
        QVERIFY(!enter.isAccepted());
    }

    void presetsMenuListsEveryBuiltInByStageWithItsDescription()
    {
        MainWindow w;
        auto* menu = w.menuBar()->findChild<QMenu*>("presetsMenu");
        QVERIFY(menu);
        QStringList keys, sections;
        for (QAction* a : menu->actions()) {
            if (a->isSeparator()) {
                sections << a->text();
                continue;
            }
            keys << a->data().toString();
            const auto& b =
                *std::find_if(ab::builtinPresets().begin(), ab::builtinPresets().end(),
                              [&](const ab::BuiltinPreset& p) { return p.key == a->data().toString().toStdString(); });
            QCOMPARE(a->toolTip(), QString::fromStdString(b.preset.description));
        }
        QCOMPARE(keys.size(), qsizetype(ab::builtinPresets().size()));
        QCOMPARE(sections.size(), qsizetype(ab::allScenes().size())); // one section per stage
        QVERIFY(sections.front().startsWith("Stage 1"));
        QVERIFY(sections.back().startsWith("Stage 5"));
        // Every stage of the report has its preset "as in the report"; the street, the
        // physical model's, its own.
        for (const char* key : {"bounce1d-report", "box3d-report", "two-balls-report", "many-balls-report", "street"})
            QVERIFY2(keys.contains(key), key);
    }

    void everyBuiltInOpensInTheWindowAsWritten()
    {
        for (const ab::BuiltinPreset& b : ab::builtinPresets()) {
            MainWindow w;
            const QString key = QString::fromStdString(b.key);
            const auto error = presetsOf(w)->open(key);
            QVERIFY2(!error, qPrintable(key + ": " + error.value_or("")));
            const ab::RunSpec& spec = w.controller().spec();
            QCOMPARE(spec.scene, b.preset.scene);
            QCOMPARE(spec.model, b.preset.model);
            if (b.preset.integrator)
                QCOMPARE(spec.integrator, *b.preset.integrator);
            if (b.preset.steps)
                QCOMPARE(w.controller().plannedSteps(), *b.preset.steps);
            for (const auto& [name, value] : b.preset.params)
                QVERIFY(spec.params.raw(*spec.params.indexOf(name)) == value);
            QVERIFY(w.statusBar()->currentMessage().contains(QString::fromStdString(b.preset.name)));
        }
    }

    // "ball 1 stops dead and ball 2 leaves at 10 m/s" (eqs 2.6-2.7 with e = 1).
    void headOnPresetStopsTheMovingBall()
    {
        MainWindow w;
        QVERIFY(!presetsOf(w)->open("two-balls-head-on"));
        const auto states = runOf(w, 12.0);
        const ab::State& before = at(states, 8.0);
        const ab::State& after = at(states, 11.0);
        QVERIFY(std::abs(before.v(2, 0) - 10.0) < 1e-9);
        QVERIFY(after.v.col(0).norm() < 1e-6);
        QVERIFY((after.v.col(1) - Eigen::Vector3d(0, 0, 10)).norm() < 1e-6);
    }

    // "10 cos 30 = 8.66 m/s passes to ball 2; 5 m/s stays with ball 1; right angles".
    void obliquePresetSendsTheBallsOffAtRightAngles()
    {
        MainWindow w;
        QVERIFY(!presetsOf(w)->open("two-balls-oblique"));
        const auto states = runOf(w, 12.0);
        const ab::State& after = at(states, 11.0);
        const Eigen::Vector3d v1 = after.v.col(0), v2 = after.v.col(1);
        QVERIFY(std::abs(v1.norm() - 5.0) < 1e-6);
        QVERIFY(std::abs(v2.norm() - 10.0 * std::cos(std::numbers::pi / 6)) < 1e-6);
        QVERIFY(std::abs(v1.dot(v2)) < 1e-6);
        QVERIFY((v1 + v2 - Eigen::Vector3d(0, 0, 10)).norm() < 1e-6); // momentum, equal masses
    }

    // Flights shrink by k = 0.9 each bounce and sum to t0 (1 + k) / (1 - k) = 19 t0.
    void zenoPresetComesToRestAtNineteenFirstFalls()
    {
        MainWindow w;
        QVERIFY(!presetsOf(w)->open("bounce1d-zeno-k09"));
        const ab::RunSpec& spec = w.controller().spec();
        QCOMPARE(spec.params.real("k"), 0.9);
        const double t0 = std::sqrt(2.0 * spec.params.real("h0") / spec.params.real("g")); // first fall
        const double tRest = 19.0 * t0;
        const auto states = runOf(w, tRest + 20.0);
        QVERIFY(states.back().t > tRest);
        double late = 0.0; // the highest bounce between 80 % and 95 % of the time to rest
        for (const ab::State& s : states)
            if (s.t > 0.8 * tRest && s.t < 0.95 * tRest)
                late = std::max(late, s.p(1, 0));
        QVERIFY(late > 0.1);
        const ab::State& rest = at(states, tRest + 10.0);
        QVERIFY(std::abs(rest.p(1, 0)) < 1e-6);
        QVERIFY(std::abs(rest.v(1, 0)) < 1e-6);
    }

    // "the step from x = 270 m lands at x = 330 m, 30 m beyond the wall, before the impact
    // is noticed": at step end the ball is put back on the wall at t = 1.25 s, where it
    // should have turned at t = 1.125 s. Located impacts solve that time inside the step,
    // so the ball is already k 240 m/s x 0.125 s back from the wall at t = 1.25 s.
    void tunnellingPresetNoticesTheWallOnlyAfterTheStepUntilImpactsAreLocated()
    {
        MainWindow w;
        QVERIFY(!presetsOf(w)->open("box3d-tunnelling"));
        const double k = w.controller().spec().params.real("k");
        const auto stepEnd = runOf(w, 1.5); // a state is final once the step from it is taken
        const ab::State& late = at(stepEnd, 1.25);
        QCOMPARE(late.p(0, 0), 300.0);
        QVERIFY(std::abs(late.v(0, 0) - -k * 240.0) < 1e-9);

        ab::ui::RunOptions options{
            ab::ModelKind::Physical, ab::Integrator::Euler, ab::ImpactMode::Located, 0.25, 400, {}};
        QVERIFY(w.applyOptions(options));
        const auto inside = runOf(w, 1.5);
        const ab::State& located = at(inside, 1.25);
        QVERIFY(std::abs(located.p(0, 0) - (300.0 - k * 240.0 * 0.125)) < 1e-9);
    }
};

QTEST_MAIN(UiPresets)
#include "test_ui_presets.moc"
