// SPDX-License-Identifier: MIT
// The event-driven integrator against the closed forms: bounce1d to 1e-10 of the start
// height up to 0.999 of the Zeno time and exact rest after it with a bounded number of
// events for any k < 1; box3d and the head-on two-balls meeting to 1e-9 m.
#include "core/physical/physical_simulation.h"
#include "core/reference/bounce_reference.h"
#include "core/reference/reference.h"
#include "support/sim_helpers.h"

#include <QtTest>

#include <cmath>

using ab::Integrator;
using ab::ModelKind;
using ab::SceneId;

namespace {

ab::RunSpec eventSpec(SceneId scene, std::initializer_list<std::string> assignments, double dt)
{
    ab::RunSpec s = testing::spec(scene, assignments, ModelKind::Physical);
    s.integrator = Integrator::Event;
    s.dt = dt;
    return s;
}

// Largest distance between the run and the closed form over every recorded state.
double maxDeviation(const ab::RunSpec& spec, long long steps)
{
    const auto ref = ab::reference::makeReference(spec, (steps + 1) * *spec.dt);
    double worst = 0.0;
    for (const ab::State& s : testing::record(spec, steps))
        for (int b = 0; b < s.size(); ++b)
            worst = std::max(worst, (s.p.col(b) - ref->position(b, s.t)).norm());
    return worst;
}

} // namespace

class PhysicalEvent : public QObject {
    Q_OBJECT

private slots:
    void bounce1dMatchesTheClosedFormThenRests_data()
    {
        QTest::addColumn<double>("k");
        QTest::addColumn<double>("h0");
        QTest::addColumn<double>("v0");
        QTest::newRow("k 0: no rebound") << 0.0 << 2000.0 << 0.0;
        QTest::newRow("k 0.3") << 0.3 << 2000.0 << 0.0;
        QTest::newRow("report: k 0.6 from 2000") << 0.6 << 2000.0 << 0.0;
        QTest::newRow("k 0.6 thrown up") << 0.6 << 500.0 << 3.5;
        QTest::newRow("k 0.6 thrown down") << 0.6 << 500.0 << -5.0;
        QTest::newRow("k 0.9") << 0.9 << 2000.0 << 0.0;
        QTest::newRow("k 0.99") << 0.99 << 2000.0 << 0.0;
        QTest::newRow("k 0.999") << 0.999 << 100.0 << 0.0;
    }

    void bounce1dMatchesTheClosedFormThenRests()
    {
        QFETCH(double, k);
        QFETCH(double, h0);
        QFETCH(double, v0);
        const auto tz = ab::reference::BounceReference(0.0982, k, h0, v0).restTime();
        // About 20000 samples to 1.2 t_Z, the sampling interval not a divisor of t_Z.
        const double dt = 1.2 * tz / 20011.0;
        const auto spec =
            eventSpec(SceneId::Bounce1d,
                      {"k=" + ab::formatNumber(k), "h0=" + ab::formatNumber(h0), "v0=" + ab::formatNumber(v0)}, dt);
        const auto ref = ab::reference::makeReference(spec, 2.0 * tz);
        const auto states = testing::record(spec, 20011);
        double worst = 0.0;
        int afterRest = 0;
        for (const ab::State& s : states) {
            const double y = s.p(1, 0);
            QVERIFY2(y >= 0.0, "the ball sank below the floor");
            if (s.t <= 0.999 * tz) {
                worst = std::max(worst, std::abs(y - ref->position(0, s.t).y()));
            } else if (s.t >= tz) {
                QCOMPARE(y, 0.0); // rests exactly: no chatter, no sinking
                QCOMPARE(s.v(1, 0), 0.0);
                ++afterRest;
            }
        }
        QVERIFY2(worst <= 1e-10 * h0, qPrintable(QString("largest deviation %1").arg(worst)));
        QVERIFY(afterRest > 1000);
        // The whole Zeno series is a handful of events, whatever k: the first impact, and
        // the series summed to its accumulation time.
        QVERIFY2(states.back().count <= 2, qPrintable(QString("%1 events").arg(states.back().count)));
    }

    void box3dMatchesTheClosedForm_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::newRow("report start, past the Zeno time") << QStringList{};
        QTest::newRow("steep throw into a corner") << QStringList{"p0=150,50,10", "v0=-30,20,40", "k=0.8"};
        QTest::newRow("elastic walls") << QStringList{"p0=10,5,280", "v0=25,0,-35", "k=1"};
    }

    void box3dMatchesTheClosedForm()
    {
        QFETCH(QStringList, assignments);
        ab::RunSpec spec = eventSpec(SceneId::Box3d, {}, 0.01);
        for (const QString& a : assignments)
            spec.params.parseAssignment(a.toStdString());
        const double worst = maxDeviation(spec, 6000);
        QVERIFY2(worst <= 1e-9, qPrintable(QString("largest deviation %1 m").arg(worst)));
    }

    void headOnTwoBallsMatchTheClosedForm_data()
    {
        QTest::addColumn<QStringList>("assignments");
        QTest::newRow("report preset (Appendix C)") << QStringList{};
        QTest::newRow("mirrored throw, higher, slower")
            << QStringList{"p1=40,60,20", "v1=-6,4,11", "p2=40,60,280", "v2=-6,4,-11", "e=0.7", "r=2"};
    }

    void headOnTwoBallsMatchTheClosedForm()
    {
        QFETCH(QStringList, assignments);
        ab::RunSpec spec = eventSpec(SceneId::TwoBalls, {}, 0.01);
        for (const QString& a : assignments)
            spec.params.parseAssignment(a.toStdString());
        const double worst = maxDeviation(spec, 6000);
        QVERIFY2(worst <= 1e-9, qPrintable(QString("largest deviation %1 m").arg(worst)));
    }

    void restSpeedEndsTheSeriesAtTheFirstSlowRebound()
    {
        // u1 = sqrt(2 g h0) = 19.819; rebounds 0.6^n u1 = 11.89, 7.13, 4.28, 2.57, 1.54, 0.92:
        // the sixth (0.92 <= 1) is cut. Impact times t1 = 201.82 and then flights 2 u / g.
        const double g = 0.0982, u1 = std::sqrt(2.0 * g * 2000.0);
        double t6 = u1 / g;
        for (int n = 1; n <= 5; ++n)
            t6 += 2.0 * u1 * std::pow(0.6, n) / g;
        const auto spec = eventSpec(SceneId::Bounce1d, {"rest_speed=1"}, 0.5);
        const auto states = testing::record(spec, 2000);
        for (const ab::State& s : states) {
            if (s.t >= t6 + 1e-9)
                QVERIFY(s.p(1, 0) == 0.0 && s.v(1, 0) == 0.0);
            else if (s.t >= t6 - 1.0 && s.t < t6 - 1e-9)
                QVERIFY(s.p(1, 0) > 0.0);
        }
    }

    void continuesFromAnEarlierStateAsIfItHadNotLeftIt()
    {
        // step() continues its own last state; handed any other it starts afresh from it.
        const auto spec = eventSpec(SceneId::Box3d, {}, 0.1);
        const auto states = testing::record(spec, 300);
        auto sim = ab::makeSimulation(spec);
        ab::State from = states[150], next;
        sim->step(from, next);
        QVERIFY((next.p - states[151].p).norm() < 1e-9);
        QVERIFY((next.v - states[151].v).norm() < 1e-9);
    }

    void refusesDragAndStepEndImpacts()
    {
        for (const char* drag : {"b=0.1", "c=0.01"}) {
            auto spec = eventSpec(SceneId::Bounce1d, {drag}, 1.0);
            try {
                ab::makeSimulation(spec);
                QFAIL("event accepted air drag");
            } catch (const ab::InputError& e) {
                QVERIFY2(std::string(e.what()).find("drag") != std::string::npos, e.what());
            }
        }
        auto spec = eventSpec(SceneId::Box3d, {}, 0.01);
        spec.impacts = ab::ImpactMode::StepEnd;
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::makeSimulation(spec));
    }
};

QTEST_GUILESS_MAIN(PhysicalEvent)
#include "test_physical_event.moc"
