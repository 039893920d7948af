// SPDX-License-Identifier: MIT
// The window on the offscreen platform (no OpenGL there: a placeholder stands where the
// 3D view goes): the navigator switches stages, the constants panel shows exactly the
// stage's table for the chosen model, refused input is shown and never applied, the
// transport moves simulated time by whole steps, and the exports write valid files.
#include "ui/charts/motion_chart.h"
#include "ui/main_window.h"
#include "ui/panels/parameter_panel.h"
#include "ui/panels/run_options_panel.h"
#include "ui/panels/stage_navigator.h"
#include "ui/panels/status_readout.h"
#include "ui/panels/transport_bar.h"

#include "tests/support/sim_helpers.h"
#include "tests/support/window_helpers.h"

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QLineSeries>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QXmlStreamReader>
#include <QtTest>

#include <set>

using ab::SceneId;
using ab::ui::MainWindow;

using testing::typeInto;

namespace {

std::vector<std::string> expectedKeys(SceneId id, ab::ModelKind model)
{
    const unsigned mask = model == ab::ModelKind::Report ? ab::ReportModel : ab::PhysicalModel;
    std::vector<std::string> keys;
    for (const ab::ParamSpec& p : ab::sceneInfo(id).params)
        if (p.usedBy(mask))
            keys.push_back(p.key);
    return keys;
}

double simulatedTime(MainWindow& w)
{
    return w.controller().status().t;
}

} // namespace

class UiWindow : public QObject {
    Q_OBJECT

private slots:
    void opensOnStage1WithAPlaceholderForThe3DView()
    {
        MainWindow w;
        QCOMPARE(w.scene(), SceneId::Bounce1d);
        QVERIFY(w.view() == nullptr);
        auto* placeholder = w.findChild<QLabel*>("viewPlaceholder");
        QVERIFY(placeholder);
        QVERIFY(placeholder->text().contains("OpenGL"));
    }

    void navigatorSwitchesStagesInTheReportsOrder()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        ab::ui::StageNavigator* nav = w.navigator();
        QVERIFY(nav->text().contains("eq 2.16")); // stage 1's typo note
        QVERIFY(nav->text().contains("(2.3)"));
        nav->next();
        QCOMPARE(w.scene(), SceneId::Box3d);
        QCOMPARE(w.controller().spec().scene, SceneId::Box3d);
        QVERIFY(nav->text().contains("One ball in a box"));
        QTest::mouseClick(nav->findChild<QPushButton*>("stage-many-balls"), Qt::LeftButton);
        QCOMPARE(w.scene(), SceneId::ManyBalls);
        QVERIFY(nav->text().contains("eq 2.31")); // stage 4's typo note
        nav->previous();
        QCOMPARE(w.scene(), SceneId::TwoBalls);
        QTest::keyClick(&w, Qt::Key_1);
        QCOMPARE(w.scene(), SceneId::Bounce1d);
        QTest::keyClick(&w, Qt::Key_4);
        QCOMPARE(w.scene(), SceneId::ManyBalls);
    }

    void constantsPanelShowsExactlyTheStagesParameters_data()
    {
        QTest::addColumn<int>("scene");
        for (const ab::SceneInfo* s : ab::allScenes())
            QTest::newRow(s->key.c_str()) << int(s->id);
    }

    void constantsPanelShowsExactlyTheStagesParameters()
    {
        QFETCH(int, scene);
        const SceneId id = SceneId(scene);
        MainWindow w;
        w.showScene(id);
        // The stage opens on its default model: the report's, the physical one on the street.
        QCOMPARE(w.parameters()->shownKeys(), expectedKeys(id, ab::RunSpec(id).model));
        if (id == SceneId::Bounce1d) {
            // One axis: every constant is a number, no x/z vector anywhere.
            for (const std::string& key : w.parameters()->shownKeys())
                QVERIFY(!w.parameters()->field(key)->text().contains(','));
        }
        if (id == SceneId::ManyBalls)
            QCOMPARE(w.parameters()->field("n")->text(), QString("150"));
        // The tooltip names the equation and the range.
        const ab::ParamSpec& first = ab::sceneInfo(id).params.front();
        const QString tip = w.parameters()->field(first.key)->toolTip();
        QVERIFY(tip.contains(QString::fromStdString(first.equation)));
        QVERIFY(tip.contains("Range"));
    }

    void aValidConstantIsAppliedAndRestartsTheRun()
    {
        MainWindow w;
        w.show();
        typeInto(w.parameters()->field("k"), "0.5");
        QCOMPARE(w.controller().spec().params.real("k"), 0.5);
        QCOMPARE(w.parameters()->errorText(), QString());
        QCOMPARE(simulatedTime(w), 0.0);
        QTest::mouseClick(w.findChild<QPushButton*>("reportValues"), Qt::LeftButton);
        QCOMPARE(w.controller().spec().params.real("k"), 0.6);
        QCOMPARE(w.parameters()->field("k")->text(), QString("0.6"));
    }

    void anInvalidConstantIsRefusedVisiblyAndNotApplied_data()
    {
        QTest::addColumn<int>("scene");
        QTest::addColumn<QString>("key");
        QTest::addColumn<QString>("text");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("out of range") << int(SceneId::Bounce1d) << "k"
                                      << "2"
                                      << "k: 2 is outside";
        // The fields take only what can begin a number ("high" cannot be typed): what is
        // left to refuse is a number begun and not finished, or one beyond a double.
        QTest::newRow("not a number") << int(SceneId::Bounce1d) << "h0"
                                      << "1e"
                                      << "h0: '1e' is not a number";
        QTest::newRow("beyond a double") << int(SceneId::Box3d) << "g"
                                         << "1e999"
                                         << "g: '1e999' is too large for a double";
        QTest::newRow("outside the box") << int(SceneId::Box3d) << "p0"
                                         << "400,5,5"
                                         << "outside the box";
        QTest::newRow("box too small") << int(SceneId::ManyBalls) << "box"
                                       << "1.5"
                                       << "leaves no room";
    }

    void anInvalidConstantIsRefusedVisiblyAndNotApplied()
    {
        QFETCH(int, scene);
        QFETCH(QString, key);
        QFETCH(QString, text);
        QFETCH(QString, mentions);
        MainWindow w;
        w.show();
        w.showScene(SceneId(scene));
        const ab::ParamValues before = w.controller().spec().params;
        w.controller().stepOnce();
        QTRY_COMPARE(w.controller().status().steps, 1LL);
        QLineEdit* field = w.parameters()->field(key.toStdString());
        typeInto(field, text);
        QVERIFY2(w.parameters()->errorText().contains(mentions), qPrintable(w.parameters()->errorText()));
        QVERIFY(field->property("refused").toBool());
        QVERIFY(w.controller().spec().params == before); // nothing applied
        QCOMPARE(w.controller().status().steps, 1LL);    // and the run went on untouched
    }

    void aRunOptionTheCoreRefusesKeepsThePreviousRun()
    {
        MainWindow w;
        w.show();
        w.showScene(SceneId::ManyBalls);
        // The report's stage 4 advances one frame per step; the core refuses any other dt.
        typeInto(w.findChild<QLineEdit*>("dtField"), "0.5");
        QVERIFY(w.runOptions()->errorText().contains("one frame"));
        QVERIFY(w.statusBar()->currentMessage().contains("one frame"));
        QVERIFY(!w.controller().spec().dt.has_value());
        // The refused entry stays in red until it is fixed or reverted (Esc).
        QLineEdit* dt = w.findChild<QLineEdit*>("dtField");
        QCOMPARE(dt->text(), QString("0.5"));
        QVERIFY(dt->property("refused").toBool());
        dt->setFocus();
        QTest::keyClick(dt, Qt::Key_Escape);
        QCOMPARE(dt->text(), QString());
        QVERIFY(!dt->property("refused").toBool());
        QCOMPARE(w.runOptions()->errorText(), QString());
    }

    void emptyStepFieldHintsTheModelsStepInSixDigits()
    {
        // The hint of an empty step field is read, not typed back: 1/60 s shows as 0.0166667,
        // not as the seventeen digits that read back to the same double.
        MainWindow w;
        w.show();
        w.showScene(SceneId::Street);
        QLineEdit* dt = w.findChild<QLineEdit*>("dtField");
        QCOMPARE(dt->text(), QString());
        QVERIFY2(dt->placeholderText().startsWith("0.0166667 "), qPrintable(dt->placeholderText()));
        w.showScene(SceneId::Bounce1d);
        QVERIFY2(!dt->placeholderText().contains("000000") && !dt->placeholderText().contains("999999"),
                 qPrintable(dt->placeholderText()));
    }

    void modelAndIntegratorListsComeFromTheCore()
    {
        MainWindow w;
        QComboBox* integrators = w.runOptions()->integratorBox();
        // The core's integrators, and while the report model runs, its own scheme first.
        QCOMPARE(integrators->count(), int(ab::allIntegrators().size()) + 1);
        QVERIFY(!integrators->isEnabled()); // the report model has one scheme per stage
        QCOMPARE(integrators->currentIndex(), 0);
        QCOMPARE(w.runOptions()->modelBox()->count(), int(ab::allModels().size()));
    }

    void stepPlayPauseAndResetMoveSimulatedTime()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.showScene(SceneId::Box3d); // dt = 0.01 s
        QTest::keyClick(&w, Qt::Key_Right);
        QTRY_COMPARE(w.controller().status().steps, 1LL);
        QTest::mouseClick(w.transport()->stepButton(), Qt::LeftButton);
        QTRY_COMPARE(w.controller().status().steps, 2LL);
        QVERIFY(std::abs(simulatedTime(w) - 0.02) < 1e-12);

        QTest::keyClick(&w, Qt::Key_Space);
        QVERIFY(w.controller().playing());
        QTRY_VERIFY(w.controller().status().steps > 5);
        QTest::keyClick(&w, Qt::Key_Space);
        QTRY_VERIFY(!w.controller().status().playing);
        const long long paused = w.controller().status().steps;
        QTest::qWait(200);
        QCOMPARE(w.controller().status().steps, paused); // paused means no steps

        QTest::keyClick(&w, Qt::Key_R);
        QCOMPARE(w.controller().status().steps, 0LL);
        QCOMPARE(simulatedTime(w), 0.0);
    }

    void whilePlayingThePanelsKeepUpAndTheStopShowsTheLastState()
    {
        // The panels' refresh is spread over frames while playing (MainWindow::refresh);
        // it must still follow the run, and the moment play stops must leave every chart,
        // the slider and the readings at the last recorded state.
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        w.showScene(SceneId::Box3d);
        w.controller().setSpeed(1.0); // real time, not the stage's 10x: a few frames a step
        auto lastTime = [&](ab::ui::ChartKind kind) {
            const QList<QPointF> points = w.charts()->chart(kind)->line(0)->points();
            return points.isEmpty() ? -1.0 : points.back().x();
        };
        QTest::keyClick(&w, Qt::Key_Space);
        QTRY_VERIFY(w.controller().status().steps > 40);
        // Played on, both charts have caught up with at least the first 0.2 s.
        QTRY_VERIFY(lastTime(ab::ui::ChartKind::Position) >= 0.2);
        QTRY_VERIFY(lastTime(ab::ui::ChartKind::Velocity) >= 0.2);
        QTest::keyClick(&w, Qt::Key_Space);
        QTRY_VERIFY(!w.controller().status().playing);
        const double end = w.controller().status().t;
        double recorded = -1.0; // the track ends at the state shown, final or not
        w.controller().engine().read(
            [&](const ab::ui::Recording& rec, const ab::ui::Frame&) { recorded = rec.track().t().back(); });
        QCOMPARE(recorded, end);
        QTRY_COMPARE(lastTime(ab::ui::ChartKind::Position), recorded);
        QTRY_COMPARE(lastTime(ab::ui::ChartKind::Velocity), recorded);
        QTRY_COMPARE(w.readout()->timeText(), QString("t = %1 s").arg(end, 0, 'f', 2));
        QSlider* time = w.transport()->timeSlider();
        QCOMPARE(time->value(), time->maximum()); // live, at the end of the record
    }

    void speedRunsFromATenthToTenTimesRealTime()
    {
        MainWindow w;
        QSlider* speed = w.transport()->speedSlider();
        speed->setValue(speed->minimum());
        QVERIFY(std::abs(w.controller().speed() - 0.1) < 1e-12);
        speed->setValue(speed->maximum());
        QVERIFY(std::abs(w.controller().speed() - 10.0) < 1e-12);
    }

    void timeSliderScrubsBackAndTheChartCursorFollows()
    {
        MainWindow w;
        w.show();
        w.showScene(SceneId::Bounce1d);
        const std::optional<double> shown = testing::stepThenLookBack(w, 100, 1, 2);
        QVERIFY(shown.has_value());
        QVERIFY(std::abs(*shown - 50.0) < 0.1);
        QSlider* time = w.transport()->timeSlider();
        const QList<QPointF> cursor = w.charts()->chart(ab::ui::ChartKind::Position)->cursorLine()->points();
        QCOMPARE(cursor.size(), 2);
        QVERIFY(std::abs(cursor[0].x() - 50.0) < 0.1);
        time->setValue(time->maximum());
        QVERIFY(!w.transport()->viewTime().has_value()); // the right end is live
    }

    void theBarAndTheStatusReadTheTimeOfTheStateShown()
    {
        // A third of 100 steps is 33.33 steps on the slider; the state recorded there is the one
        // of step 33, which the view draws: the bar over the view reads its time, as the status
        // bar does, not the slider's.
        MainWindow w;
        w.show();
        w.showScene(SceneId::Bounce1d);
        const std::optional<double> looked = testing::stepThenLookBack(w, 100, 1, 3);
        QVERIFY(looked && std::abs(*looked - 100.0 / 3.0) < 0.1 && std::abs(*looked - 33.0) > 0.2);
        w.controller().poll();
        auto* label = w.findChild<QLabel*>("timeLabel");
        QVERIFY(label);
        QTRY_VERIFY2(label->text().startsWith("t = 33.00 of 100.0 step"), qPrintable(label->text()));
        QTRY_COMPARE(w.readout()->timeText(), QString("t = 33.00 step"));
        // And the charts' cursor stands there.
        QTRY_VERIFY(!w.charts()->chart(ab::ui::ChartKind::Position)->cursorLine()->points().isEmpty());
        QTRY_COMPARE(w.charts()->chart(ab::ui::ChartKind::Position)->cursorLine()->points().front().x(), 33.0);
    }

    void theTimeSliderKeepsItsLengthWhileHeld()
    {
        // Dragged from live, the label's long "looking back" form took room from the slider under
        // the pointer: the handle ran ahead of it (aimed at 12 s, landed on 13.78 s).
        MainWindow w;
        w.show();
        w.showScene(SceneId::Bounce1d);
        QVERIFY(testing::stepThenLookBack(w, 100, 1, 1) == std::nullopt); // live at the end
        auto* label = w.findChild<QLabel*>("timeLabel");
        QSlider* time = w.transport()->timeSlider();
        QApplication::processEvents();
        const int length = time->width();
        time->setSliderDown(true); // held
        time->setValue(time->maximum() / 3);
        for (int i = 0; i < 5; ++i)
            QApplication::processEvents(); // the layout's turn
        QCOMPARE(time->width(), length);
        QVERIFY2(label->text().startsWith("t = 33.") && !label->text().contains("looking back"),
                 qPrintable(label->text()));
        time->setSliderDown(false); // let go: the whole form
        QTRY_VERIFY2(label->text().contains("looking back: Play goes on from here"), qPrintable(label->text()));
    }

    void theBarStaysPutAsTheLiveTimeGainsDigits()
    {
        // Playing, "t = 9.50 step (live)" became "t = 950.0 step (live)" and, in lecture mode's
        // large text, took its room from the time slider a digit at a time.
        ab::ui::TransportBar bar;
        QFont big = bar.font();
        big.setPointSizeF(big.pointSizeF() * 1.6);
        bar.setFont(big);
        bar.resize(1280, bar.sizeHint().height());
        bar.show();
        QVERIFY(QTest::qWaitForWindowExposed(&bar));
        int length = -1;
        for (const double t : {0.0, 9.5, 95.0, 950.0, 9500.0}) {
            bar.setRecorded(0.0, t, "step");
            for (int i = 0; i < 5; ++i)
                QApplication::processEvents(); // the layout's turn
            if (length < 0)
                length = bar.timeSlider()->width();
            QCOMPARE(bar.timeSlider()->width(), length);
        }
    }

    void chartsFollowTheChosenBall()
    {
        MainWindow w;
        w.show();
        w.showScene(SceneId::TwoBalls);
        w.findChild<QSpinBox*>("ballSpin")->setValue(2);
        QCOMPARE(w.controller().selectedBall(), 1);
        QCOMPARE(w.charts()->chart(ab::ui::ChartKind::Position)->title(), QString("Position of ball 2"));
        // Ball 2 starts at z = 298 (Appendix C); its chart starts there after one step.
        w.controller().stepOnce();
        QTRY_COMPARE(w.controller().status().steps, 1LL);
        w.controller().poll();
        QTRY_VERIFY(!w.charts()->chart(ab::ui::ChartKind::Position)->line(2)->points().isEmpty());
        QCOMPARE(w.charts()->chart(ab::ui::ChartKind::Position)->line(2)->points().front().y(), 298.0);
    }

    void exportWritesAValidPngSvgAndCsv()
    {
        MainWindow w;
        w.show();
        w.showScene(SceneId::Box3d);
        for (int i = 0; i < 300; ++i)
            w.controller().stepOnce();
        QTRY_COMPARE(w.controller().status().steps, 300LL);
        w.controller().poll();
        QTemporaryDir dir;
        const QString png = dir.filePath("position.png");
        w.exportChartTo(ab::ui::ChartKind::Position, png);
        const QImage image(png);
        QVERIFY(!image.isNull());
        std::set<QRgb> colours;
        for (int y = 0; y < image.height(); y += 5)
            for (int x = 0; x < image.width(); x += 5)
                colours.insert(image.pixel(x, y));
        QVERIFY(colours.size() > 8); // not a uniform image

        const QString svg = dir.filePath("velocity.svg");
        w.exportChartTo(ab::ui::ChartKind::Velocity, svg);
        QFile file(svg);
        QVERIFY(file.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&file);
        while (!xml.atEnd() && xml.readNext() != QXmlStreamReader::StartElement) {
        }
        QCOMPARE(xml.name().toString(), QString("svg"));
        while (!xml.atEnd())
            xml.readNext();
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));

        const QString csv = dir.filePath("data.csv");
        w.exportDataTo(csv);
        QFile data(csv);
        QVERIFY(data.open(QIODevice::ReadOnly));
        QStringList lines = QString::fromUtf8(data.readAll()).split('\n', Qt::SkipEmptyParts);
        while (!lines.isEmpty() && lines.front().startsWith('#')) // how the run was made
            lines.removeFirst();
        QVERIFY(
            lines.front().startsWith("t [s],ball,x [m],y [m],z [m],vx [m/s],vy [m/s],vz [m/s],energy_total [m^2/s^2],"
                                     "energy_kinetic [m^2/s^2],energy_potential [m^2/s^2],"));
        QCOMPARE(lines.size(), 1 + 301); // the start and the 300 steps' states, the last the one shown
        QVERIFY(lines[1].startsWith("0,1,2,20,2,10,0,15,")); // Appendix B's start, ball 1 as the window says
        // The last row is the moment on screen (it stopped a step before it).
        QCOMPARE(lines.back().section(',', 0, 0).toDouble(), w.controller().status().t);
    }

    void exportToAFolderThatDoesNotExistIsRefused()
    {
        MainWindow w;
        QVERIFY_THROWS_EXCEPTION(ab::InputError, w.exportChartTo(ab::ui::ChartKind::Energy, "/nonexistent-dir/e.png"));
        QVERIFY_THROWS_EXCEPTION(ab::InputError,
                                 w.exportChartTo(ab::ui::ChartKind::Energy, QDir::tempPath() + "/e.jpg"));
        QVERIFY_THROWS_EXCEPTION(ab::InputError, w.exportViewTo(QDir::tempPath() + "/view.png")); // no view here
    }

    void statusBarShowsTimeAndEnergyInTheScenesUnits()
    {
        MainWindow w;
        w.show();
        w.showScene(SceneId::Bounce1d);
        w.controller().stepOnce();
        QTRY_COMPARE(w.controller().status().steps, 1LL);
        w.controller().poll();
        QTRY_COMPARE(w.readout()->timeText(), QString("t = 1.00 step"));
        // E/m at rest at h0 = 2000 under g = 0.0982: 196.4; after one step of eq 2.15-2.16
        // the ball still stands at 2000 with v = -0.0982: 196.4 + 0.0982^2 / 2.
        QVERIFY(std::abs(w.controller().status().energy - (196.4 + 0.0982 * 0.0982 / 2)) < 1e-9);
    }

    void aFailedHealthCheckPausesTheRunAtTheFailureAndNamesIt()
    {
        // The report's two balls at 100 m a step each way swap sides without ever being
        // closer than 2 r at a step's end: the health check finds them passed through each
        // other in the step from the start, and the run pauses there, once.
        MainWindow w;
        w.show();
        w.showScene(SceneId::TwoBalls);
        const ab::RunSpec failing = testing::spec(
            SceneId::TwoBalls, {"g=0", "p1=150,20,100", "p2=150,20,200", "v1=0,0,10000", "v2=0,0,-10000"});
        QVERIFY(w.applyValues(failing.params));
        w.controller().play();
        QTRY_VERIFY(w.controller().status().pausedOnHealth);
        const ab::ui::EngineStatus s = w.controller().status();
        QVERIFY(!s.playing);
        QVERIFY(!s.finished);
        QCOMPARE(s.health, ab::diagnostics::Health::Failed);
        QCOMPARE(s.steps, 2LL); // the step from the start is final once the next is taken
        QVERIFY(s.healthLine.find("passed through each other") != std::string::npos);
        QTRY_VERIFY(w.readout()->warningText().startsWith("Paused: "));
        QVERIFY(w.readout()->warningText().contains("passed through each other"));

        // Play goes on from there; the same failure does not stop the run again.
        w.controller().play();
        QTRY_VERIFY(w.controller().status().steps > 6);
        QVERIFY(w.controller().playing());
        QTRY_VERIFY(!w.readout()->warningText().startsWith("Paused: "));
    }

    void aHealthWarningIsShownWithoutPausing()
    {
        // The report's stage 1 moves the position with the old velocity (eq 2.16): explicit
        // Euler gains g^2 dt^2 / 2 per step, which the health check names as the report's
        // own rule, a warning that does not stop the lesson.
        MainWindow w;
        w.show();
        w.showScene(SceneId::Bounce1d);
        w.controller().play();
        QTRY_VERIFY(w.controller().status().steps > 3);
        QTRY_COMPARE(w.controller().status().health, ab::diagnostics::Health::Warning);
        QVERIFY(w.controller().playing());
        QTRY_VERIFY(w.readout()->warningText().contains("above its start"));
        QVERIFY(w.readout()->warningText().contains("the report's own rule"));
    }
};

QTEST_MAIN(UiWindow)
#include "test_ui_window.moc"
