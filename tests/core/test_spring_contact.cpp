// SPDX-License-Identifier: MIT
// The spring floor (report 1.2): stiffness and damping from the restitution and contact
// time reproduce both when the contact is integrated finely; each integrator's measured
// stability limit matches the textbook value; the implicit ones stay bounded however
// stiff the spring.
#include "core/physical/spring_contact.h"
#include "core/stability/stability_limit.h"
#include "support/sim_helpers.h"

#include <QtTest>

#include <cmath>
#include <map>
#include <numbers>

using namespace ab;
using namespace ab::physical;

namespace {

struct Bounce {
    double exitSpeed;
    double duration;
};

// Enters the floor at y = 0 with speed u and integrates finely with RK4 until it leaves;
// the exit is interpolated linearly within the last step.
Bounce integrateOneContact(const SpringFloor& floor, double u, double dt)
{
    PointState s{0.0, -u};
    double t = 0.0;
    for (long long i = 0; i < 100'000'000; ++i) {
        const PointState next = springStep(Integrator::Rk4, floor, s, dt);
        if (t > 0.0 && next.y >= 0.0) {
            const double f = -s.y / (next.y - s.y);
            return {s.v + f * (next.v - s.v), t + f * dt};
        }
        s = next;
        t += dt;
    }
    return {0.0, 0.0};
}

// Highest point of the flight after the first contact, stepping without keeping states.
double firstRebound(const RunSpec& spec, long long steps)
{
    auto sim = makeSimulation(spec);
    State s = sim->start();
    State next;
    double top = 0.0;
    for (long long i = 0; i < steps; ++i) {
        sim->step(s, next);
        std::swap(s, next);
        if (s.count == 1)
            top = std::max(top, s.p(1, 0));
    }
    return top;
}

const std::vector<Integrator> springIntegrators = {Integrator::Euler,         Integrator::SymplecticEuler,
                                                   Integrator::Verlet,        Integrator::Rk4,
                                                   Integrator::ImplicitEuler, Integrator::ImplicitMidpoint};

} // namespace

class SpringContact : public QObject {
    Q_OBJECT

private slots:
    void dampingRatioInvertsTheRestitutionFormula()
    {
        // zeta = 1/2 by hand: e = exp(-(pi / 2) / sqrt(3 / 4)) = exp(-pi / sqrt 3).
        QVERIFY(std::abs(restitutionForDampingRatio(0.5) - std::exp(-std::numbers::pi / std::sqrt(3.0))) < 1e-15);
        for (double e : {0.01, 0.3, 0.6, 0.9, 0.99, 1.0})
            QVERIFY(std::abs(restitutionForDampingRatio(dampingRatioForRestitution(e)) - e) < 1e-14);
        QCOMPARE(dampingRatioForRestitution(0.0), 1.0);
        QCOMPARE(dampingRatioForRestitution(1.0), 0.0);
    }

    void linearSpringBouncesWithRestitutionKAndContactTimeTc_data()
    {
        QTest::addColumn<double>("e");
        QTest::addColumn<double>("tc");
        QTest::newRow("rubber e=0.6 tc=5") << 0.6 << 5.0;
        QTest::newRow("lively e=0.95 tc=0.01") << 0.95 << 0.01;
        QTest::newRow("dead e=0.05 tc=2") << 0.05 << 2.0;
        QTest::newRow("elastic e=1 tc=1") << 1.0 << 1.0;
    }

    void linearSpringBouncesWithRestitutionKAndContactTimeTc()
    {
        QFETCH(double, e);
        QFETCH(double, tc);
        // Without gravity the closed form is exact: exit speed e u after t_c.
        const SpringFloor floor = linearFloorFromContactTime(e, tc, 0.0);
        for (double u : {0.1, 3.0}) {
            const Bounce b = integrateOneContact(floor, u, tc / 20000.0);
            QVERIFY2(std::abs(b.exitSpeed - e * u) <= 2e-5 * u, qPrintable(QString::number(b.exitSpeed / u)));
            QVERIFY2(std::abs(b.duration - tc) <= 1e-4 * tc, qPrintable(QString::number(b.duration)));
        }
    }

    void hertzUndampedContactTimeIsTheClosedForm()
    {
        // tau = 2 x_max I, x_max = (5/4)^(2/5) from 1/2 = 2/5 x^(5/2), and
        // I = int_0^1 (1 - u^(5/2))^(-1/2) du = sqrt(pi) Gamma(7/5) / Gamma(9/10).
        const double tau =
            2.0 * std::pow(1.25, 0.4) * std::sqrt(std::numbers::pi) * std::tgamma(1.4) / std::tgamma(0.9);
        QVERIFY(std::abs(tau - 3.2181) < 1e-4);
        QVERIFY(std::abs(hertzDampingForRestitution(1.0).tau - tau) < 1e-5);
        QCOMPARE(hertzDampingForRestitution(1.0).alpha, 0.0);
    }

    void hertzRestitutionIsKAtEveryImpactSpeed_data()
    {
        QTest::addColumn<double>("e");
        QTest::newRow("e=0.3") << 0.3;
        QTest::newRow("e=0.6") << 0.6;
        QTest::newRow("e=0.9") << 0.9;
    }

    void hertzRestitutionIsKAtEveryImpactSpeed()
    {
        QFETCH(double, e);
        const double tc = 2.0;
        const double design = 5.0; // the speed the stiffness is chosen for
        const SpringFloor floor = hertzFloorFromContactTime(e, tc, design, 0.0);
        const Bounce atDesign = integrateOneContact(floor, design, tc / 20000.0);
        QVERIFY2(std::abs(atDesign.exitSpeed - e * design) <= 2e-4 * design,
                 qPrintable(QString::number(atDesign.exitSpeed)));
        QVERIFY2(std::abs(atDesign.duration - tc) <= 1e-3 * tc, qPrintable(QString::number(atDesign.duration)));
        // Tsuji's damping makes e independent of the speed; t_c scales as u^(-1/5).
        const Bounce slow = integrateOneContact(floor, design / 32.0, tc / 20000.0);
        QVERIFY(std::abs(slow.exitSpeed - e * design / 32.0) <= 2e-4 * design / 32.0);
        QVERIFY(std::abs(slow.duration - 2.0 * tc) <= 2e-3 * tc);
    }

    void compressionAllowanceIsTheEnergyBalance()
    {
        // Linear: 1/2 k d^2 - g d = E. k = 100, g = 10, E = 20: d = (10 + sqrt(100 + 4000)) / 100.
        const SpringFloor lin{ContactLaw::LinearSpring, 100.0, 0.0, 10.0, true};
        QVERIFY(std::abs(maxCompression(lin, 20.0) - (10.0 + std::sqrt(4100.0)) / 100.0) < 1e-14);
        const SpringFloor hertz{ContactLaw::Hertz, 50.0, 0.0, 2.0, true};
        const double d = maxCompression(hertz, 7.0);
        QVERIFY(std::abs(0.4 * 50.0 * std::pow(d, 2.5) - 2.0 * d - 7.0) < 1e-12);
    }

    void measuredStabilityLimitsMatchTheoryWithin10Percent_data()
    {
        QTest::addColumn<int>("integrator");
        QTest::newRow("symplectic-euler below 2") << int(Integrator::SymplecticEuler);
        QTest::newRow("verlet below 2") << int(Integrator::Verlet);
        QTest::newRow("rk4 below 2 sqrt 2") << int(Integrator::Rk4);
    }

    void measuredStabilityLimitsMatchTheoryWithin10Percent()
    {
        QFETCH(int, integrator);
        const Integrator method = static_cast<Integrator>(integrator);
        const stability::StabilityLimit limit = stability::measureStabilityLimit(method);
        const double theory = stability::theoreticalLimit(method);
        QVERIFY(!limit.stableEverywhere && !limit.unstableEverywhere);
        QVERIFY2(std::abs(limit.h - theory) <= 0.1 * theory,
                 qPrintable(QString("measured %1, theory %2").arg(limit.h).arg(theory)));
        // Longer watching does not move a true limit.
        const stability::StabilityLimit longer = stability::measureStabilityLimit(method, {100'000, 10.0, 1e-4, 1e4});
        QVERIFY(std::abs(longer.h - theory) <= 0.1 * theory);
    }

    void explicitEulerHasNoStableStep()
    {
        // Its "limit" is only how long one watches: sqrt(G^(2/n) - 1) -> 0 as n grows.
        for (long long steps : {1'000LL, 100'000LL}) {
            const stability::GrowthCriterion c{steps, 10.0, 1e-5, 1e4};
            const stability::StabilityLimit limit = stability::measureStabilityLimit(Integrator::Euler, c);
            const double expected = stability::expectedMeasuredLimit(Integrator::Euler, c);
            QVERIFY2(std::abs(limit.h - expected) <= 0.1 * expected,
                     qPrintable(QString("measured %1, expected %2").arg(limit.h).arg(expected)));
        }
        QVERIFY(stability::expectedMeasuredLimit(Integrator::Euler, {100'000, 10.0, 1e-5, 1e4}) < 0.01);
        // Every step grows the amplitude by sqrt(1 + h^2), however small.
        QVERIFY(stability::oscillatorGrowth(Integrator::Euler, 1e-3, 1'000'000) > 1.6);
    }

    void implicitIntegratorsAreStableAtEveryStepAndDampAsTheoryTells()
    {
        for (Integrator method : {Integrator::ImplicitEuler, Integrator::ImplicitMidpoint})
            QVERIFY(stability::measureStabilityLimit(method).stableEverywhere);
        // One step on the oscillator multiplies y + i v by 1 / (1 + i h) (implicit Euler,
        // amplitude 1 / sqrt(1 + h^2)) or (1 - i h/2) / (1 + i h/2) (midpoint, amplitude 1).
        const SpringFloor spring{ContactLaw::LinearSpring, 1.0, 0.0, 0.0, false};
        for (double h : {0.1, 2.0, 1e3}) {
            const PointState ie = springStep(Integrator::ImplicitEuler, spring, {1.0, 0.0}, h);
            QVERIFY(std::abs(std::hypot(ie.y, ie.v) - 1.0 / std::sqrt(1.0 + h * h)) < 1e-14);
            const PointState mid = springStep(Integrator::ImplicitMidpoint, spring, {1.0, 0.0}, h);
            QVERIFY(std::abs(std::hypot(mid.y, mid.v) - 1.0) < 1e-14);
        }
    }

    void implicitIntegratorsStayBoundedAtEveryStiffness_data()
    {
        QTest::addColumn<int>("contact");
        QTest::addColumn<QString>("stiffness");
        for (int contact : {1, 2})
            for (const char* k : {"1e1", "1e3", "1e5", "1e7", "1e9"})
                QTest::newRow(qPrintable(QString("contact=%1 stiffness=%2").arg(contact).arg(k)))
                    << contact << QString(k);
    }

    void implicitIntegratorsStayBoundedAtEveryStiffness()
    {
        QFETCH(int, contact);
        QFETCH(QString, stiffness);
        for (Integrator method : {Integrator::ImplicitEuler, Integrator::ImplicitMidpoint}) {
            RunSpec s = testing::spec(
                SceneId::Bounce1d,
                {"contact=" + std::to_string(contact), "stiffness=" + stiffness.toStdString(), "h0=10", "k=0.8"},
                ModelKind::Physical);
            s.integrator = method;
            s.dt = 0.5; // dt omega0 from ~1.6 to ~1.6e4
            const SpringFloor floor = springFloorFor(s);
            const double e0 = startEnergy(s);
            const double deepest = maxCompression(floor, e0);
            // In flight the energy never exceeds its start; in the spring, within 5% (the
            // midpoint rule conserves quadratic invariants only, and Hertz's is not one).
            for (const State& st : testing::record(s, 400)) {
                const double y = st.p(1, 0);
                const double v = st.v(1, 0);
                const double energy = 0.5 * v * v + floor.potential(y);
                QVERIFY(std::isfinite(y) && std::isfinite(v));
                QVERIFY2(y <= 10.0 * (1.0 + 1e-12), qPrintable(QString::number(y)));
                QVERIFY2(-y <= deepest * (1.0 + 1e-9), qPrintable(QString("%1 > %2").arg(-y).arg(deepest)));
                QVERIFY2(energy <= e0 * (y >= 0.0 ? 1.0 + 1e-9 : 1.05), qPrintable(QString::number(energy / e0)));
            }
        }
    }

    void fineStepsReachTheRestitutionApexes_data()
    {
        QTest::addColumn<int>("integrator");
        QTest::addColumn<int>("contact");
        for (Integrator i : springIntegrators)
            for (int contact : {1, 2})
                QTest::newRow(qPrintable(QString("%1 contact=%2").arg(integratorKey(i).data()).arg(contact)))
                    << int(i) << contact;
    }

    void fineStepsReachTheRestitutionApexes()
    {
        // A ball dropped from h0 rises to k^2 h0 after the first contact (the spring's
        // restitution is k); gravity during the contact shifts it by O(g t_c / u) ~ 0.5%.
        QFETCH(int, integrator);
        QFETCH(int, contact);
        RunSpec s = testing::spec(
            SceneId::Bounce1d, {"contact=" + std::to_string(contact), "contact_time=0.002", "g=9.82", "h0=1", "k=0.7"},
            ModelKind::Physical);
        s.integrator = static_cast<Integrator>(integrator);
        // First-order methods need finer steps: explicit Euler gains and implicit Euler
        // loses energy at every step in the contact (dt omega0 ~ 1e-4 and 1e-3 here), and
        // symplectic Euler's damping is first order (dt omega0 ~ 6e-3; 0.06 for the rest).
        const std::map<Integrator, double> steps{
            {Integrator::Euler, 2e-7}, {Integrator::ImplicitEuler, 2e-6}, {Integrator::SymplecticEuler, 1e-5}};
        s.dt = steps.count(s.integrator) ? steps.at(s.integrator) : 1e-4;
        const double top = firstRebound(s, static_cast<long long>(0.9 / *s.dt));
        QVERIFY2(std::abs(top - 0.49) <= 0.02 * 0.49, qPrintable(QString::number(top)));
    }

    void implicitStepsSolveTheirEquationsOnTheHertzFloor()
    {
        // Whatever Newton did, the result must satisfy the method's own equations:
        // implicit Euler y1 = y0 + dt v1, v1 = v0 + dt a(y1, v1); implicit midpoint
        // y1 = y0 + dt vm, v1 = v0 + dt a(ym, vm) with (ym, vm) the averages.
        const SpringFloor floor = hertzFloorFromContactTime(0.6, 0.5, 4.0, 9.82);
        for (double dt : {1e-3, 0.05, 0.4}) {
            for (const PointState s0 :
                 {PointState{0.01, -4.0}, PointState{-0.05, -2.0}, PointState{-0.2, 3.0}, PointState{-1e-6, 0.5}}) {
                const PointState ie = springStep(Integrator::ImplicitEuler, floor, s0, dt);
                QVERIFY(std::abs(ie.y - (s0.y + dt * ie.v)) <= 1e-12 * (std::abs(s0.y) + dt * std::abs(ie.v)));
                QVERIFY(std::abs(ie.v - (s0.v + dt * floor.acceleration(ie.y, ie.v))) <= 1e-9 * std::abs(s0.v));
                const PointState mid = springStep(Integrator::ImplicitMidpoint, floor, s0, dt);
                const double ym = 0.5 * (s0.y + mid.y);
                const double vm = 0.5 * (s0.v + mid.v);
                QVERIFY(std::abs(mid.y - (s0.y + dt * vm)) <= 1e-12 * (std::abs(s0.y) + dt * std::abs(vm)));
                QVERIFY2(std::abs(mid.v - (s0.v + dt * floor.acceleration(ym, vm))) <= 1e-9 * std::abs(s0.v),
                         qPrintable(QString("dt %1 y0 %2").arg(dt).arg(s0.y)));
            }
        }
    }

    void implicitMidpointHertzConvergesToRk4()
    {
        auto endHeight = [](Integrator method, double dt) {
            RunSpec s = testing::spec(SceneId::Bounce1d, {"contact=2", "contact_time=0.5", "g=9.82", "h0=1", "k=0.6"},
                                      ModelKind::Physical);
            s.integrator = method;
            s.dt = dt;
            return testing::record(s, static_cast<long long>(std::llround(1.0 / dt))).back().p(1, 0);
        };
        const double ref = endHeight(Integrator::Rk4, 1e-5);
        const double coarse = std::abs(endHeight(Integrator::ImplicitMidpoint, 4e-3) - ref);
        const double fine = std::abs(endHeight(Integrator::ImplicitMidpoint, 1e-3) - ref);
        // The damping's d^(1/4) has no slope at contact onset, so the order there drops
        // below 2; a quarter of the step still cuts the error by more than 3.
        QVERIFY2(fine < 1e-4 && fine < coarse / 3.0, qPrintable(QString("%1 %2").arg(coarse).arg(fine)));
    }

    void contactOptionRoutesOnlyTheSpringFloors()
    {
        RunSpec event = testing::spec(SceneId::Bounce1d, {"contact=1"}, ModelKind::Physical);
        event.integrator = Integrator::Event;
        try {
            makeSimulation(event);
            QFAIL("event accepted");
        } catch (const InputError& e) {
            QVERIFY(std::string(e.what()).find("no impacts to find") != std::string::npos);
        }
        RunSpec spring = testing::spec(SceneId::Bounce1d, {"contact=2"}, ModelKind::Physical);
        QVERIFY(makeSimulation(spring) != nullptr);
        // The report model ignores the physical model's contact option.
        const auto withOption = testing::record(testing::spec(SceneId::Bounce1d, {"contact=1"}), 300);
        const auto without = testing::record(testing::spec(SceneId::Bounce1d), 300);
        QCOMPARE(withOption.back().p(1, 0), without.back().p(1, 0));
    }

    void contactCountsEachArrivalOnTheFloor()
    {
        RunSpec s = testing::spec(SceneId::Bounce1d, {"contact=1", "contact_time=0.01", "g=9.82", "h0=1", "k=0.5"},
                                  ModelKind::Physical);
        s.integrator = Integrator::Verlet;
        s.dt = 1e-4;
        // Fall sqrt(2 h0 / g) = 0.451 s, then flights of 2 k u / g = 0.451, 0.226, 0.113 s
        // with contacts of 0.01 s between: arrivals at 0.451, 0.912, 1.148 and 1.271 s.
        const auto states = testing::record(s, 12'000);
        QCOMPARE(states.back().count, 3LL);
    }
};

QTEST_GUILESS_MAIN(SpringContact)
#include "test_spring_contact.moc"
