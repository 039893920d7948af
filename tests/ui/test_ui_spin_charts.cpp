// SPDX-License-Identifier: MIT
// Spin in the window's charts and navigator (docs/spin.md): the spin chart and the energy
// chart's split into translation and rotation follow the rough-sphere closed forms, show
// only where the balls turn, and each spin preset does what its description says,
// checked against hand-worked impacts (S3-S4, S9-S13).
#include "ui/charts/chart_data_csv.h"
#include "ui/charts/motion_chart.h"
#include "ui/i18n/language.h"
#include "ui/main_window.h"
#include "ui/panels/chart_panel.h"
#include "ui/panels/stage_navigator.h"
#include "ui/presets/preset_actions.h"
#include "ui/sim/recording.h"
#include "ui/sim/run_controller.h"
#include "ui/sim/run_engine.h"

#include "core/io/preset.h"

#include <QLineSeries>
#include <QtTest>

#include <cmath>
#include <sstream>

using ab::SceneId;
using ab::ui::ChartKind;
using ab::ui::MainWindow;

namespace {

constexpr double g = 9.82;

// Opens the built-in preset `key` and steps its whole run.
bool playPreset(MainWindow& w, const char* key)
{
    auto* presets = w.findChild<ab::ui::PresetActions*>();
    if (!presets || presets->open(QString::fromLatin1(key)))
        return false;
    const long long steps = w.controller().plannedSteps();
    for (long long i = 0; i < steps; ++i)
        w.controller().stepOnce();
    const bool done = QTest::qWaitFor([&] { return w.controller().status().steps >= steps; }, 60000);
    w.controller().poll();
    return done;
}

ab::ui::MotionTrack trackOf(MainWindow& w)
{
    ab::ui::MotionTrack copy;
    w.controller().engine().read([&](const ab::ui::Recording& rec, const ab::ui::Frame&) { copy = rec.track(); });
    return copy;
}

bool near(double a, double b, double tol)
{
    return std::abs(a - b) <= tol * std::max(1.0, std::abs(b));
}

// The first sample after which the velocity component `axis` differs from its start by
// more than `jump` (an impact), or the track's size.
std::size_t firstJump(const ab::ui::MotionTrack& m, int axis, double jump)
{
    for (std::size_t i = 1; i < m.size(); ++i)
        if (std::abs(m.v(axis)[i] - m.v(axis)[0]) > jump)
            return i;
    return m.size();
}

} // namespace

class UiSpinCharts : public QObject {
    Q_OBJECT
private slots:
    void cleanup() { ab::ui::installLanguage(ab::ui::Language::English); }

    // The window is rebuilt in the new language with the run it had; the preset's text
    // beside it is translated as it is shown, so it follows too.
    void aPresetsTextFollowsALanguageChosenAfterItOpened()
    {
        MainWindow english;
        QVERIFY(english.findChild<ab::ui::PresetActions*>()->open("box3d-sliding-to-rolling") == std::nullopt);
        QVERIFY(english.navigator()->text().contains("A sliding ball starts to roll"));
        ab::ui::installLanguage(ab::ui::Language::Swedish);
        MainWindow swedish;
        swedish.takeRunOf(english);
        QVERIFY2(swedish.navigator()->text().contains(QString::fromUtf8("En glidande boll börjar rulla")),
                 qPrintable(swedish.navigator()->text().left(200)));
        QVERIFY(!swedish.navigator()->text().contains("A sliding ball"));
    }

    // A ball set down at v0 = 5 m/s on a floor with mu = 0.02 (q = 2/5): v = v0 - mu g t
    // until t* = q v0 / ((1 + q) mu g) = 7.274 s (S3), then 5/7 v0 with r w = v (S4). The
    // event integrator follows it exactly; the spin chart draws w_z = -v / r (rolling along
    // +x turns the ball about -z).
    void theSlidingPresetsSpinChartShowsTheFiveSeventhsRule()
    {
        MainWindow w;
        QVERIFY(playPreset(w, "box3d-sliding-to-rolling"));
        const double q = 0.4, mu = 0.02, v0 = 5.0, r = 3.75;
        const double tStar = q * v0 / ((1 + q) * mu * g);
        QVERIFY(near(tStar, 7.274, 1e-3));
        const ab::ui::MotionTrack m = trackOf(w);
        QVERIFY(m.size() > 100);
        for (std::size_t i = 0; i < m.size(); ++i) {
            const double t = m.t()[i];
            const double v = t < tStar ? v0 - mu * g * t : v0 / (1 + q);
            const double rw = t < tStar ? mu * g * t / q : v0 / (1 + q); // S2 integrated, then S4
            QVERIFY2(near(m.v(0)[i], v, 1e-9), qPrintable(QStringLiteral("t = %1: vx %2").arg(t).arg(m.v(0)[i])));
            QVERIFY2(near(-r * m.w(2)[i], rw, 1e-9), qPrintable(QStringLiteral("t = %1: r wz %2").arg(t)));
        }
        QVERIFY(w.charts()->chartShown(ChartKind::Spin));
        const QLineSeries* wz = w.charts()->chart(ChartKind::Spin)->line(2);
        QVERIFY(wz->isVisible() && wz->count() > 10);
        QVERIFY(near(wz->points().back().y(), -v0 / (1 + q) / r, 1e-9));
    }

    // With r w = v the rotational energy is q times the translational one (I = q m r^2):
    // E_rot = q m r^2 w^2 / 2 = q m v^2 / 2. Before, the two parts add up to the kinetic
    // energy, and sliding loses (1 - 1/(1 + q)) of the start's energy in all.
    void theEnergyChartSplitsKineticEnergyIntoTranslationAndRotation()
    {
        MainWindow w;
        QVERIFY(playPreset(w, "box3d-sliding-to-rolling"));
        const ab::ui::MotionTrack m = trackOf(w);
        const double q = 0.4, r = 3.75, mass = 1.0;
        for (std::size_t i = 0; i < m.size(); ++i) {
            const double v2 = m.v(0)[i] * m.v(0)[i] + m.v(1)[i] * m.v(1)[i] + m.v(2)[i] * m.v(2)[i];
            const double w2 = m.w(0)[i] * m.w(0)[i] + m.w(1)[i] * m.w(1)[i] + m.w(2)[i] * m.w(2)[i];
            QVERIFY(near(m.translation()[i], 0.5 * mass * v2, 1e-12));
            QVERIFY(near(m.rotation()[i], 0.5 * q * mass * r * r * w2, 1e-12));
            QVERIFY(near(m.translation()[i] + m.rotation()[i], m.kinetic()[i], 1e-12));
        }
        QVERIFY(near(m.rotation().back(), q * m.translation().back(), 1e-9));
        QVERIFY(near(m.kinetic().back(), m.kinetic().front() / (1 + q), 1e-9)); // (1/2 m v0^2) (1 + q) / (1 + q)^2
        const ab::ui::MotionChart* energy = w.charts()->chart(ChartKind::Energy);
        QStringList names;
        for (const ab::ui::LegendEntry& e : energy->legendEntries())
            names << e.text;
        QVERIFY2(names.contains("translation") && names.contains("rotation") && !names.contains("kinetic"),
                 qPrintable(names.join(", ")));
    }

    // Balls that never turn have no spin chart and a kinetic energy in one part; the report
    // model says in the navigator that friction and spin act in the physical model only.
    void theSpinChartShowsOnlyWhereTheBallsTurn()
    {
        MainWindow w;
        w.showScene(SceneId::Box3d);
        QVERIFY(!w.charts()->shownCharts().empty());
        for (ChartKind k : w.charts()->shownCharts())
            QVERIFY(k != ChartKind::Spin);
        QVERIFY(!w.navigator()->text().contains("rotation"));
        QVERIFY(w.findChild<ab::ui::PresetActions*>()->open("box3d-backspin-bounce") == std::nullopt);
        QVERIFY(w.charts()->chartShown(ChartKind::Spin));
        QVERIFY(w.navigator()->text().contains("S13"));
        // The same constants under the report model: no chart, and the navigator says why.
        ab::RunSpec spec = w.controller().spec();
        spec.model = ab::ModelKind::Report;
        ab::ui::RunOptions options = w.options();
        options.model = ab::ModelKind::Report;
        options.steps = 100;
        QVERIFY(!w.showSetup(spec, options));
        QVERIFY(!w.charts()->shownCharts().empty());
        for (ChartKind k : w.charts()->shownCharts())
            QVERIFY(k != ChartKind::Spin);
        QVERIFY2(w.navigator()->text().contains("The report's model has no rotation"),
                 qPrintable(w.navigator()->text().right(300)));
    }

    // Back-spin (S13 with beta = 0, sticking): the ball leaves the floor at
    // v' = (v - q r w) / (1 + q) = (6 - 0.4 x 3.75 x 6.8) / 1.4 = -3 m/s, rolling:
    // r w' = -v' ... in the rolling sense, r w_z = 3.75 x 0.8 = 3 m/s.
    void theBackSpinPresetBouncesBackwardsAtThreeMetresASecond()
    {
        MainWindow w;
        QVERIFY(playPreset(w, "box3d-backspin-bounce"));
        const ab::ui::MotionTrack m = trackOf(w);
        const std::size_t hit = firstJump(m, 0, 1e-6);
        QVERIFY(hit < m.size());
        QVERIFY(near(m.v(0)[hit], -3.0, 1e-9));
        QVERIFY(near(3.75 * m.w(2)[hit], 3.0, 1e-9));
    }

    // Garwin's superball, k = beta = 1, q = 2/5, incoming u = 10 m/s without spin. Floor:
    // v1 = u (1 - q)/(1 + q) = 3/7 u and r w1 = 2u/(1 + q) = 10/7 u (S9 with the slip u).
    // At the table the normal is reversed, so the spin's slip adds to the centre's:
    // u2 = v1 + r w1 = 13/7 u, and S9 changes the centre by -2 q/(1 + q) u2 = -52/49 u:
    // v2 = 21/49 u - 52/49 u = -31/49 u, back out. k = beta = 1 keeps the energy.
    void theSuperballPresetComesBackOutFromUnderTheTable()
    {
        MainWindow w;
        QVERIFY(playPreset(w, "box3d-superball-table"));
        const ab::ui::MotionTrack m = trackOf(w);
        const double u = 10.0;
        QCOMPARE(m.v(0)[0], -u); // in from the left: -x is to the right, seen from above
        const std::size_t floorHit = firstJump(m, 0, 1e-6);
        QVERIFY(floorHit < m.size());
        QVERIFY(near(m.v(0)[floorHit], -3.0 / 7.0 * u, 1e-9));
        std::size_t tableHit = floorHit;
        while (tableHit < m.size() && m.v(0)[tableHit] == m.v(0)[floorHit])
            ++tableHit;
        QVERIFY(tableHit < m.size());
        QVERIFY(near(m.v(0)[tableHit], 31.0 / 49.0 * u, 1e-9));
        for (std::size_t i = 0; i < m.size(); ++i)
            QVERIFY(near(m.energy()[i], m.energy()[0], 1e-12));
    }

    // Two equal balls (m = 1, r = 2, q = 2/5), ball 1 at 5 m/s spinning at w = 4 rad/s
    // about y into ball 2 at rest. The contact point's slip is r w = 8 m/s along x; the
    // pair's effective mass is q/(1 + q) m/2 = 1/7, so sticking (beta = 0, within
    // mu P_n = 0.5 x 1.95 x 0.5 x 5) takes P_t = 8/7: each ball moves off at 8/7 m/s
    // sideways (opposite ways) and both spins change by r P_t / I = (16/7)/1.6 = -10/7 rad/s
    // (S11-S12): ball 1 keeps 18/7, ball 2 turns at -10/7.
    void theFrictionPresetPassesSpinFromOneBallToTheOther()
    {
        MainWindow w;
        QVERIFY(playPreset(w, "two-balls-friction-spin"));
        ab::ui::MotionTrack one = trackOf(w);
        const std::size_t hit = firstJump(one, 2, 1e-6);
        QVERIFY(hit < one.size());
        QVERIFY(near(one.w(1)[hit], 18.0 / 7.0, 1e-9));
        QVERIFY(near(one.v(0)[hit], -8.0 / 7.0, 1e-9));
        w.controller().selectBall(1);
        w.controller().poll();
        const ab::ui::MotionTrack two = trackOf(w);
        std::size_t at = 0;
        while (at < two.size() && two.t()[at] < one.t()[hit])
            ++at;
        QVERIFY(at < two.size());
        QVERIFY(near(two.w(1)[at], -10.0 / 7.0, 1e-6)); // the frames are floats
        QVERIFY(near(two.v(0)[at], 8.0 / 7.0, 1e-6));
    }

    // The chart CSV of balls that turn ends with the spin and the kinetic energy's parts.
    void theChartCsvOfTurningBallsEndsWithSpinAndTheEnergysParts()
    {
        ab::ui::MotionTrack m;
        ab::ConservationSample s;
        s.energy.kinetic = 7.0;
        s.energy.rotation = 2.0;
        m.add(0, 0.0, Eigen::Vector3d(1, 2, 3), Eigen::Vector3d(4, 5, 6), Eigen::Vector3d(0.5, -0.25, 2), s);
        ab::ui::ChartData d;
        d.run = &m;
        d.spins = true;
        std::ostringstream out;
        ab::ui::writeChartCsv(out, d);
        const QStringList lines = QString::fromStdString(out.str()).split('\n');
        QVERIFY(lines[0].endsWith(
            "impacts [1],wx [rad/s],wy [rad/s],wz [rad/s],energy_translation [m^2/s^2],energy_rotation [m^2/s^2]"));
        QVERIFY2(lines[1].endsWith(",0.5,-0.25,2,5,2"), qPrintable(lines[1]));
        d.spins = false;
        std::ostringstream plain;
        ab::ui::writeChartCsv(plain, d);
        QVERIFY(QString::fromStdString(plain.str()).split('\n')[0].endsWith("impacts [1]"));
    }
};

QTEST_MAIN(UiSpinCharts)
#include "test_ui_spin_charts.moc"
