// SPDX-License-Identifier: MIT
// The window as a lecture runs it: each stage and built-in preset shows what it is about
// within a few seconds of Play at its own speed; numeric fields take no shortcut keys,
// Enter applies and hands the keys back, Esc reverts; refusals stay until fixed and
// clear with "Report values"; the report model's greyed controls name its own scheme; the
// status bar reads the moment on screen in the window's words and language; a language
// switch keeps the run.
#include "ui/i18n/language.h"
#include "ui/main_window.h"
#include "ui/panels/parameter_panel.h"
#include "ui/panels/run_options_panel.h"
#include "ui/panels/stage_navigator.h"
#include "ui/panels/status_readout.h"
#include "ui/panels/transport_bar.h"
#include "ui/presets/preset_actions.h"
#include "ui/shell/window_shell.h"
#include "ui/sim/pacing.h"

#include "core/diagnostics/health.h"
#include "core/io/preset.h"

#include "tests/support/window_helpers.h"

#include <QApplication>
#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QRegularExpression>
#include <QSlider>
#include <QToolButton>
#include <QtTest>

#include <cmath>
#include <limits>

using ab::SceneId;
using ab::ui::Language;
using ab::ui::MainWindow;

using testing::typeInto;

namespace {

// The simulated time of the first thing a run is about: the first impact that turns a
// velocity on the stage's axes of interest (the floor in stage 1; a wall or the other
// ball in stages 2-4, not the floor bounce that comes before), or a failure the health
// check finds (balls through each other), whichever comes first. The impact is dated by
// the state after it: the step that holds it ends then. NaN when none comes in `steps`.
double firstEventTime(const ab::RunSpec& spec, long long steps)
{
    auto sim = ab::makeSimulation(spec);
    const ab::State start = sim->start();
    ab::diagnostics::HealthCheck health(*sim, start);
    const double g = spec.params.real("g"), dt = sim->dt();
    const bool vertical = spec.scene == SceneId::Bounce1d;
    double found = std::numeric_limits<double>::quiet_NaN();
    ab::State before = start;
    bool first = true;
    // Stops at the first event: the street's many balls make every further step dear.
    ab::runRecorded(
        *sim, start, steps, 1,
        [&](const ab::State& s) {
            if (first || !std::isnan(found)) {
                first = false;
                before = s;
                return;
            }
            for (int i = 0; i < s.size() && std::isnan(found); ++i) {
                Eigen::Vector3d dv = s.v.col(i) - before.v.col(i);
                dv.y() += g * dt; // free flight changes vy by -g dt only (eq 2.12)
                const double turn = vertical ? std::abs(dv.y()) : std::hypot(dv.x(), dv.z());
                if (turn > 1e-9 * (before.v.col(i).norm() + 1.0))
                    found = s.t;
            }
            if (std::isnan(found) && health.check(before, s) == ab::diagnostics::Health::Failed)
                found = s.t;
            before = s;
        },
        [&] { return !std::isnan(found); });
    return found - start.t;
}

// Wall-clock seconds from Play to the window's first event at its speed.
double secondsToFirstEvent(MainWindow& w)
{
    const ab::SceneInfo& info = ab::sceneInfo(w.controller().spec().scene);
    const double rate = w.controller().speed() * ab::ui::RunController::realTimeRate(info);
    return firstEventTime(w.controller().spec(), w.controller().plannedSteps()) / rate;
}

// Runs the window's run `steps` steps on and brings the window up to date.
bool stepOn(MainWindow& w, long long steps)
{
    const long long target = w.controller().status().steps + steps;
    for (long long i = 0; i < steps; ++i)
        w.controller().stepOnce();
    // A minute: a sanitizer build on a loaded machine (only a failing run waits that long).
    const bool done = QTest::qWaitFor([&] { return w.controller().status().steps >= target; }, 60000);
    w.controller().poll();
    return done;
}

// Plays until the health check pauses the run on a failure.
bool playUntilPaused(MainWindow& w)
{
    w.controller().setSpeed(10.0);
    w.controller().play();
    const bool paused = QTest::qWaitFor(
        [&] {
            w.controller().poll();
            return w.controller().status().pausedOnHealth;
        },
        20000);
    w.controller().poll();
    return paused;
}

} // namespace

class UiFlow : public QObject {
    Q_OBJECT
private slots:
    void cleanup() { ab::ui::installLanguage(Language::English); }

    // Stage 1: the first bounce at 201.8 steps, 2.0 s at 10x (10 steps a second); stage
    // 2: the first wall at 19.9 s, 2.0 s at 10x; stage 3: the balls meet after 9.8 s,
    // 2.0 s at 5x; stage 4: the balls collide in the first frames.
    void everyStageShowsItsFirstEventWithinThreeSecondsOfPlay()
    {
        MainWindow w;
        for (const ab::SceneInfo* s : ab::allScenes()) {
            w.showScene(s->id);
            QCOMPARE(w.controller().speed(), ab::ui::defaultSpeed(s->id));
            const double wait = secondsToFirstEvent(w);
            QVERIFY2(wait > 0.0 && wait <= ab::ui::kLessonWait,
                     qPrintable(QString::fromStdString(s->key) + QStringLiteral(": %1 s").arg(wait)));
        }
        w.showScene(SceneId::Bounce1d);
        // At 1x the same bounce would wait 20 s: the speed is what brings it in. Eq 2.16
        // moves the position with the old velocity, p_n = h0 - g n (n - 1) / 2 (dt = 1),
        // first at or below the floor at n = 203 (2000 - 0.0491 x 203 x 202 < 0); the step
        // from there is the floor hit, so the turned state is at t = 204: 20.4 s at 1x.
        const double atOneX = secondsToFirstEvent(w) * w.controller().speed();
        QVERIFY2(std::abs(atOneX - 20.4) < 1e-9, qPrintable(QString::number(atOneX)));
        QCOMPARE(w.transport()->speedText(), QString::fromUtf8("10× real time"));
    }

    void aRunTheMachineCannotKeepUpWithSaysTheSpeedItPlaysAt()
    {
        // 10,000 balls down the street asked at 10x real time (600 steps a second) play far
        // slower here: the label says so ("10×, plays at 0.3×"), not "10× real time".
        MainWindow w;
        w.show();
        w.showScene(SceneId::Street);
        w.controller().setSpeed(10.0);
        w.controller().play();
        QTRY_VERIFY_WITH_TIMEOUT(w.transport()->speedText().startsWith(QString::fromUtf8("10×, plays at ")), 20000);
        bool ok = false;
        const double kept = w.transport()->speedText().section(' ', -1).chopped(1).toDouble(&ok);
        QVERIFY2(ok && kept > 0.0 && kept < 8.0, qPrintable(w.transport()->speedText()));
        w.controller().pause();
        QTRY_COMPARE(w.transport()->speedText(), QString::fromUtf8("10× real time"));
        // Stage 2 keeps 1x with room to spare: no such word.
        w.showScene(SceneId::Box3d);
        w.controller().setSpeed(1.0);
        w.controller().play();
        QTest::qWait(2500);
        QCOMPARE(w.transport()->speedText(), QString::fromUtf8("1× real time"));
        w.controller().pause();
    }

    void everyBuiltinPresetShowsItsEventWithinThreeSecondsOfPlay()
    {
        MainWindow w;
        auto* presets = w.findChild<ab::ui::PresetActions*>();
        QVERIFY(presets);
        for (const ab::BuiltinPreset& b : ab::builtinPresets()) {
            QVERIFY(!presets->open(QString::fromStdString(b.key)));
            const double wait = secondsToFirstEvent(w);
            QVERIFY2(wait > 0.0 && wait <= ab::ui::kLessonWait,
                     qPrintable(QString::fromStdString(b.key) + QStringLiteral(": %1 s").arg(wait)));
            // Its explanation is in the navigator while its stage is shown.
            QVERIFY(w.navigator()->text().contains(QString::fromStdString(b.preset.description).left(40)));
        }
        w.showScene(SceneId::ManyBalls);
        QVERIFY(w.navigator()->presetName().isEmpty()); // a stage chosen: no preset's text
    }

    // Two balls 12.5 m apart at t = 5 s close at 50 m/s with a step of 0.5 s: at the next
    // step end they are 12.5 m apart on the other's side. Located impacts find the
    // contact (centres 2 r = 10 m apart) at t = 5 + 2.5 / 50 = 5.05 s and turn them.
    void theTunnellingPresetPassesTheBallsThroughEachOtherUntilImpactsAreLocated()
    {
        const ab::Preset& preset = ab::loadPreset("two-balls-tunnelling");
        ab::RunSpec spec(preset.scene);
        ab::applyPreset(preset, spec);
        auto states = [&spec](long long steps) {
            auto sim = ab::makeSimulation(spec);
            std::vector<ab::State> out;
            ab::runRecorded(*sim, sim->start(), steps, 1, [&](const ab::State& s) { out.push_back(s); });
            return out;
        };
        const auto stepEnd = states(12);
        QCOMPARE(stepEnd[10].t, 5.0);
        QCOMPARE(stepEnd[10].p(2, 1) - stepEnd[10].p(2, 0), 12.5);
        QCOMPARE(stepEnd[11].p(2, 1) - stepEnd[11].p(2, 0), -12.5); // through each other
        QCOMPARE(stepEnd[11].v(2, 0), 25.0);                        // untouched
        spec.impacts = ab::ImpactMode::Located;
        const auto located = states(12);
        // Turned at 5.05 s with e = 1: back by 25 m/s x 0.45 s from the contact at 136.25 m.
        QVERIFY(std::abs(located[11].p(2, 0) - (136.25 - 25.0 * 0.45)) < 1e-9);
        QCOMPARE(located[11].v(2, 0), -25.0);
    }

    void spaceAndBracketsNeverTypeIntoANumericField()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        for (QLineEdit* field :
             {w.parameters()->field("k"), w.findChild<QLineEdit*>("stepsField"), w.findChild<QLineEdit*>("dtField")}) {
            QVERIFY(field);
            const QString before = field->text();
            field->setFocus();
            field->end(false);
            for (int key : {int(Qt::Key_Space), int(Qt::Key_BracketRight), int(Qt::Key_BracketLeft)})
                QTest::keyClick(field, Qt::Key(key), Qt::NoModifier);
            QTest::keyClicks(field, "] [x");
            QCOMPARE(field->text(), before);
        }
        QVERIFY(!w.controller().playing());
    }

    void enterAppliesAndHandsTheKeysBackAndEscReverts()
    {
        MainWindow w;
        w.show();
        QVERIFY(QTest::qWaitForWindowExposed(&w));
        QLineEdit* k = w.parameters()->field("k");
        typeInto(k, "0.5");
        QCOMPARE(w.controller().spec().params.real("k"), 0.5);
        QVERIFY(!k->hasFocus());
        k->setFocus();
        k->selectAll();
        QTest::keyClicks(k, "0.7");
        QTest::keyClick(k, Qt::Key_Escape);
        QCOMPARE(k->text(), QString("0.5"));
        QCOMPARE(w.controller().spec().params.real("k"), 0.5);
    }

    void anInvalidEntryStaysInRedUntilFixedWhenAnotherFieldIsEdited()
    {
        MainWindow w;
        w.show();
        QLineEdit* k = w.parameters()->field("k");
        typeInto(k, "2");
        QVERIFY(w.parameters()->errorText().contains("k: 2"));
        typeInto(w.parameters()->field("h0"), "1000");
        QCOMPARE(w.controller().spec().params.real("h0"), 1000.0); // the other edit applies
        QCOMPARE(k->text(), QString("2"));                         // the refused entry stays
        QVERIFY(k->property("refused").toBool());
        QVERIFY(w.parameters()->errorText().contains("k: 2"));
        typeInto(k, "0.5"); // fixed
        QCOMPARE(w.controller().spec().params.real("k"), 0.5);
        QCOMPARE(w.parameters()->errorText(), QString());
        QVERIFY(!k->property("refused").toBool());
    }

    void refusalsClearWhenReportValuesIsPressed()
    {
        MainWindow w;
        w.show();
        QLineEdit* steps = w.findChild<QLineEdit*>("stepsField");
        typeInto(steps, "-3");
        QVERIFY(w.runOptions()->errorText().contains("steps: -3"));
        QCOMPARE(steps->text(), QString("-3"));
        // Another choice still applies while the refused entry stays.
        w.runOptions()->modelBox()->setCurrentIndex(w.runOptions()->modelBox()->findData(int(ab::ModelKind::Physical)));
        QCOMPARE(w.controller().spec().model, ab::ModelKind::Physical);
        QCOMPARE(steps->text(), QString("-3"));
        typeInto(w.parameters()->field("k"), "2");
        QVERIFY(!w.parameters()->errorText().isEmpty());
        QTest::mouseClick(w.findChild<QPushButton*>("reportValues"), Qt::LeftButton);
        QCOMPARE(w.parameters()->errorText(), QString());
        QCOMPARE(w.runOptions()->errorText(), QString());
        QCOMPARE(steps->text(), QString::number(w.controller().plannedSteps()));
        QVERIFY(!steps->property("refused").toBool());
    }

    void reportModelControlsShowTheReportsOwnScheme()
    {
        MainWindow w;
        const std::map<SceneId, std::pair<QString, QString>> expected{
            {SceneId::Bounce1d, {"explicit Euler", "step's end"}},
            {SceneId::Box3d, {"semi-implicit", "step's end"}},
            {SceneId::TwoBalls, {"semi-implicit", "step's end"}},
            {SceneId::ManyBalls, {"one update per frame", "each frame"}},
        };
        for (const auto& [id, words] : expected) {
            w.showScene(id);
            QComboBox* integrator = w.runOptions()->integratorBox();
            QComboBox* impacts = w.findChild<QComboBox*>("impactsCombo");
            QVERIFY(!integrator->isEnabled() && !impacts->isEnabled());
            QVERIFY2(integrator->currentText().contains(words.first), qPrintable(integrator->currentText()));
            QVERIFY2(impacts->currentText().contains(words.second), qPrintable(impacts->currentText()));
        }
        w.showScene(SceneId::Box3d);
        QComboBox* model = w.runOptions()->modelBox();
        model->setCurrentIndex(model->findData(int(ab::ModelKind::Physical)));
        QComboBox* integrator = w.runOptions()->integratorBox();
        QVERIFY(integrator->isEnabled());
        QCOMPARE(integrator->count(), int(ab::allIntegrators().size())); // the report's entry is gone
        QCOMPARE(integrator->currentData().toInt(), int(w.controller().spec().integrator));
        // Compared with the report model, the comparison's impacts are the report's too.
        ab::RunVariant report;
        report.model = ab::ModelKind::Report;
        w.runOptions()->compareBox()->setCurrentIndex(w.runOptions()->compareIndex(report));
        QVERIFY(w.controller().comparing());
        QVERIFY2(w.runOptions()->compareImpactsBox()->currentText().contains("step's end"),
                 qPrintable(w.runOptions()->compareImpactsBox()->currentText()));
    }

    void theStatusAfterAScrubIsThatOfTheMomentShown()
    {
        MainWindow w;
        w.showScene(SceneId::Bounce1d);
        const std::optional<double> shown = testing::stepThenLookBack(w, 400, 1, 4);
        QVERIFY(shown);
        w.controller().poll();
        double t = 0.0, energy = 0.0;
        w.controller().engine().read([&](const ab::ui::Recording& rec, const ab::ui::Frame&) {
            const ab::ui::Frame* f = rec.frameAt(*shown);
            QVERIFY(f);
            t = f->t;
            energy = f->scene.energy.total();
        });
        QVERIFY(t < 150.0); // a quarter of 400 steps, far from the live 400
        QCOMPARE(w.readout()->timeText(), QStringLiteral("t = %1 step").arg(t, 0, 'f', t < 100 ? 2 : 1));
        QVERIFY2(w.readout()->energyText().contains(QString::number(energy, 'g', 5)),
                 qPrintable(w.readout()->energyText()));
    }

    void healthFindingsNumberBallsAsTheChartsAndUseTheWindowsWords()
    {
        MainWindow w;
        QVERIFY(!w.findChild<ab::ui::PresetActions*>()->open("two-balls-tunnelling"));
        QVERIFY(playUntilPaused(w));
        QTRY_VERIFY(!w.readout()->warningText().isEmpty());
        const QString text = w.readout()->warningText();
        QVERIFY2(text.startsWith("Paused: Balls 1 and 2 passed through each other within one step at t = 5.5 s"),
                 qPrintable(text + " | " + QString::fromStdString(w.controller().status().healthLine)));
        QVERIFY2(text.contains("impacts located inside the step"), qPrintable(text));
        QVERIFY(!text.contains("--")); // no command-line option
    }

    void theSwedishStatusHasNoEnglishSentenceAfterAHealthFinding()
    {
        ab::ui::installLanguage(Language::Swedish);
        MainWindow w;
        QVERIFY(!w.findChild<ab::ui::PresetActions*>()->open("two-balls-tunnelling"));
        QVERIFY(playUntilPaused(w));
        QTRY_VERIFY(!w.readout()->warningText().isEmpty());
        const QString text = w.readout()->warningText();
        static const QRegularExpression english(
            "\\b(the|and|passed|through|each|other|within|step|closest|approach|contact|balls?|impacts?|choose|"
            "smaller|located|inside|Paused|report)\\b",
            QRegularExpression::CaseInsensitiveOption);
        QVERIFY2(!english.match(text).hasMatch(), qPrintable(text));
    }

    // Stage 4 (report): a ball that reaches the floor is never updated again (Appendix D)
    // and keeps its velocity; stage 3: after the counter the floor rule leaves the balls
    // g dt^2 = 9.82 x 0.01^2 = 0.000982 m below the floor, E/m = 2 g y < 0.
    void theReportsRulesThatLeaveEnergyWithNothingMovingAreSaid()
    {
        MainWindow w;
        w.showScene(SceneId::ManyBalls);
        QVERIFY(stepOn(w, 1000));
        w.transport()->goLive();
        QTRY_VERIFY2(w.readout()->warningText().contains("Appendix D"), qPrintable(w.readout()->warningText()));
        QVERIFY(w.readout()->warningText().contains("do not move"));
        w.showScene(SceneId::TwoBalls);
        QVERIFY(stepOn(w, 4000));
        QTRY_VERIFY2(w.readout()->warningText().contains("below the floor"), qPrintable(w.readout()->warningText()));
        QVERIFY(w.readout()->warningText().contains("Appendix C"));
        QVERIFY(w.readout()->warningText().contains("0.000982 m"));
        // Stage 2's limit moves the ball to the origin: its x and z fall to 0 in the charts, and
        // the headline says where the ball went, not only that it stopped.
        w.showScene(SceneId::Box3d);
        QVERIFY(stepOn(w, 4000));
        QTRY_VERIFY2(w.readout()->warningText().contains("at the origin"), qPrintable(w.readout()->warningText()));
    }

    // At 1280x720 in lecture mode the bar held "150 of 150 balls lie on the floor with a
    // velocity b": cut mid-word. A headline that does not fit whole gives way to the kind
    // of message, with Details beside it; a wide window shows the headline again.
    void aLongMessageInTheStatusBarIsNeverCutMidWord()
    {
        ab::ui::WindowShell shell;
        MainWindow& w = shell.window();
        w.showScene(SceneId::ManyBalls);
        QVERIFY(stepOn(w, 1000)); // before the window shows: no 150 balls drawn per step
        w.resize(1280, 720);
        w.show();
        shell.lecture().setActive(true);
        w.transport()->goLive();
        QTRY_VERIFY2(w.readout()->warningText().contains("Appendix D"), qPrintable(w.readout()->warningText()));
        auto* label = w.findChild<QLabel*>("statusWarning");
        QVERIFY(label);
        auto fitsWhole = [label] {
            return label->fontMetrics().horizontalAdvance(label->text()) <= label->contentsRect().width();
        };
        QTRY_VERIFY2(fitsWhole(), qPrintable(QStringLiteral("'%1' in %2 px").arg(label->text()).arg(label->width())));
        QCOMPARE(label->text(), w.readout()->warningShown());
        QVERIFY(w.readout()->warningText().startsWith(label->text()) || label->text() == "The report's rules at work");
        QVERIFY(w.readout()->detailsButton()->isVisible()); // the whole message is a click away
        shell.lecture().setActive(false);
        w.resize(1900, 1000);
        QTRY_VERIFY2(label->text().endsWith("do not move"), qPrintable(label->text()));
        QVERIFY(fitsWhole());
    }

    void theReportsOwnEnergyGainIsNamedAsItsRuleNotAsAFault()
    {
        // Stage 1's default run: the report's explicit Euler (eq 2.16) adds g^2 dt^2 / 2 of
        // energy a step of flight from the first step. In lecture mode at 1280x720 the bar has
        // room for the kind of message only: the report's rules, not a health check's warning.
        ab::ui::WindowShell shell;
        MainWindow& w = shell.window();
        w.showScene(SceneId::Bounce1d);
        QVERIFY(stepOn(w, 20));
        w.resize(1280, 720);
        w.show();
        shell.lecture().setActive(true);
        w.transport()->goLive();
        QTRY_VERIFY2(w.readout()->warningText().contains("explicit Euler"), qPrintable(w.readout()->warningText()));
        auto* label = w.findChild<QLabel*>("statusWarning");
        QVERIFY(label);
        QTRY_COMPARE(label->text(), QString("The report's rules at work"));
        shell.lecture().setActive(false);
        // With room, the headline says so itself: the figure, then whose doing it is.
        w.resize(1900, 1000);
        QTRY_VERIFY2(label->text().startsWith("The energy is ") && label->text().endsWith(": the report's own rule"),
                     qPrintable(label->text()));
    }

    void aLanguageSwitchKeepsTheRun()
    {
        ab::ui::WindowShell shell;
        shell.window().showScene(SceneId::TwoBalls);
        shell.window().controller().selectBall(1);
        QVERIFY(stepOn(shell.window(), 300));
        QSlider* slider = shell.window().transport()->timeSlider();
        slider->setValue(slider->maximum() / 2);
        const std::optional<double> shown = shell.window().transport()->viewTime();
        QVERIFY(shown);
        const ab::ui::EngineStatus before = shell.window().controller().status();
        std::size_t frames = 0;
        shell.window().controller().engine().read(
            [&](const ab::ui::Recording& rec, const ab::ui::Frame&) { frames = rec.frames().size(); });
        shell.setLanguage(Language::Swedish);
        MainWindow& w = shell.window();
        QCOMPARE(w.scene(), SceneId::TwoBalls);
        QCOMPARE(w.controller().status().steps, before.steps);
        QCOMPARE(w.controller().status().t, before.t);
        QCOMPARE(w.controller().selectedBall(), 1);
        std::size_t after = 0;
        w.controller().engine().read(
            [&](const ab::ui::Recording& rec, const ab::ui::Frame&) { after = rec.frames().size(); });
        QCOMPARE(after, frames);
        QCOMPARE(w.transport()->viewTime(), shown);
        QCOMPARE(w.controller().speed(), ab::ui::defaultSpeed(SceneId::TwoBalls));
    }

    void theStatusFontFollowsLectureMode()
    {
        ab::ui::WindowShell shell;
        MainWindow& w = shell.window();
        QVERIFY(stepOn(w, 10));
        auto* warning = w.findChild<QLabel*>("statusWarning");
        const qreal normal = warning->font().pointSizeF();
        shell.lecture().setActive(true);
        QVERIFY(stepOn(w, 10)); // the readings are set again in lecture mode
        QVERIFY(warning->font().pointSizeF() > normal);
        shell.lecture().setActive(false);
        QVERIFY(stepOn(w, 10));
        QCOMPARE(warning->font().pointSizeF(), normal);
    }
};

QTEST_MAIN(UiFlow)
#include "test_ui_flow.moc"
