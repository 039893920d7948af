// SPDX-License-Identifier: MIT
// What leaves the street at its open foot (docs/street.md): a ball that passes it takes its
// energy with it (State::energyLeft), and the one-ball preset leaves where and as fast as its
// description's closed form says (St1).
#include "core/diagnostics/conservation.h"
#include "core/io/preset.h"
#include "core/street/street_census.h"
#include "core/street/street_engine.h"

#include <QtTest>

#include <cmath>
#include <numbers>

using ab::RunSpec;
using ab::SceneId;
using ab::State;

namespace {

RunSpec streetSpec(const QStringList& assignments)
{
    RunSpec s(SceneId::Street);
    for (const QString& a : assignments)
        s.params.parseAssignment(a.toStdString());
    s.dt = 1.0 / 60.0;
    return s;
}

} // namespace

class StreetFoot : public QObject {
    Q_OBJECT

private slots:
    void anElasticSuperballTakesAllItsEnergyOutAtTheFoot()
    {
        // The energy of a ball that leaves at the open foot goes with it (State::energyLeft):
        // with nothing lost on the way (e = beta = 1, sticking friction), what it took is what
        // it had at the top, and the street keeps none of it.
        RunSpec spec = streetSpec({"n=1", "blocks=1", "slope=30", "e=1", "beta=1", "mu=10", "rest_height=0"});
        const ab::street::Layout layout = ab::street::Layout::fromParams(spec.params);
        auto sim = ab::makeSimulation(spec);
        const ab::ConservationMeter meter(*sim);
        State s = sim->start(), next;
        const double e0 = meter.measure(s).energy.total();
        QCOMPARE(s.energyLeft, 0.0);
        int stepsAfter = -1;
        for (int k = 0; k < 1200 && stepsAfter < 30; ++k) {
            sim->step(s, next);
            std::swap(s, next);
            const ab::EnergyParts e = meter.measure(s).energy;
            QVERIFY2(
                std::abs(e.total() - e0) <= 1e-9 * e0,
                qPrintable(
                    QString("t = %1: energy %2 against %3").arg(s.t).arg(e.total(), 0, 'g', 17).arg(e0, 0, 'g', 17)));
            if (!ab::street::hasLeft(layout, s.p(0, 0))) {
                QCOMPARE(e.left, 0.0);
                continue;
            }
            ++stepsAfter;
            // Gone: at rest past the foot, no kinetic or potential energy left on the street.
            QCOMPARE(e.kinetic, 0.0);
            QCOMPARE(e.potential, 0.0);
            QVERIFY(std::abs(e.left - e0) <= 1e-9 * e0);
        }
        QCOMPARE(stepsAfter, 30); // it left, and what it took stayed the same for 30 steps
    }

    void theOneBallPresetRollsToTheFootAsItsDescriptionSays()
    {
        // St1: rolling without slipping from rest, a = g sin(theta) / (1 + q), so at a distance
        // d down the road v^2 = 2 a d. The description: set down 48.7 m up the road from the
        // foot, it leaves after 6.9 s at 14.1 m/s, within the preset's 8 s.
        RunSpec spec(SceneId::Street);
        const ab::Preset preset = ab::loadPreset("street-one-ball");
        ab::applyPreset(preset, spec);
        const ab::street::Layout layout = ab::street::Layout::fromParams(spec.params);
        const double theta = spec.params.real("slope") * std::numbers::pi / 180.0;
        const double q = spec.params.real("inertia"), g = spec.params.real("g");
        const double a = g * std::sin(theta) / (1.0 + q);
        auto sim = ab::makeSimulation(spec);
        State s = sim->start(), next;
        const double x0 = s.p(0, 0);
        const double toFoot = (layout.xFoot - x0) / std::cos(theta);
        QVERIFY2(std::abs(toFoot - 48.7) < 0.05, qPrintable(QString::number(toFoot)));
        QVERIFY(std::abs(std::sqrt(2.0 * a * toFoot) - 14.1) < 0.05);
        QVERIFY(std::abs(std::sqrt(2.0 * toFoot / a) - 6.9) < 0.05); // t = v / a = sqrt(2 d / a)
        State last = s, rolling;
        for (long long k = 0; k < *preset.steps && !ab::street::hasLeft(layout, s.p(0, 0)); ++k) {
            last = s;
            if (k == 60)
                rolling = s; // at t = 1 s, long since landed
            sim->step(s, next);
            std::swap(s, next);
        }
        QVERIFY(ab::street::hasLeft(layout, s.p(0, 0))); // within the run
        QVERIFY2(std::abs(s.t - 6.9) < 0.05, qPrintable(QString::number(s.t)));
        // Rolling from t = 1 s to its last step on the street: v^2 - v1^2 = 2 a (d - d1), and
        // r w = v, to round-off (the flight is exact).
        const double d = (last.p(0, 0) - rolling.p(0, 0)) / std::cos(theta);
        const double v = last.v.col(0).norm(), v1 = rolling.v.col(0).norm();
        QVERIFY2(std::abs(v * v - v1 * v1 - 2.0 * a * d) < 1e-9 * v * v,
                 qPrintable(QString("v^2 - v1^2 = %1 against 2 a d = %2").arg(v * v - v1 * v1).arg(2.0 * a * d)));
        QVERIFY(std::abs(spec.params.real("r") * last.w.col(0).norm() - v) < 1e-9 * v);
        QVERIFY(std::abs(v - 14.1) < 0.1);
    }
};

QTEST_APPLESS_MAIN(StreetFoot)
#include "test_street_foot.moc"
