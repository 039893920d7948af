// SPDX-License-Identifier: MIT
// The work-precision study on small sweeps: the convergence orders fitted from it are the
// textbook ones (1 for impacts found at the step's end whatever the integrator; 2 for
// verlet and 4 for rk4 with located impacts under drag), event is exact at any sampling
// interval, and the tables carry what the contract names.
#include "core/study/study.h"
#include "support/sim_helpers.h"

#include <QtTest>

#include <sstream>

using ab::ImpactMode;
using ab::Integrator;
using ab::study::Method;

namespace {

ab::study::Result small(ab::SceneId scene, std::initializer_list<std::string> set, double tEnd, double dtMax,
                        double dtMin, int perDecade)
{
    ab::study::Options o = ab::study::defaultOptions(testing::spec(scene, set, ab::ModelKind::Physical));
    o.tEnd = tEnd;
    o.dts = ab::study::logSweep(dtMax, dtMin, perDecade);
    o.repeats = 1;
    o.minBatchSeconds = 0.0;
    return ab::study::runStudy(o);
}

void checkOrder(const ab::study::Result& r, Method m, double expected, double tolerance)
{
    const auto order = ab::study::fittedOrder(r, m);
    QVERIFY2(order, qPrintable(QString::fromStdString(m.label() + ": too few rows to fit")));
    QVERIFY2(
        std::abs(*order - expected) <= tolerance,
        qPrintable(QString::fromStdString(m.label()) + QString(": order %1, expected %2").arg(*order).arg(expected)));
}

} // namespace

class StudyTest : public QObject {
    Q_OBJECT

private slots:
    void stepEndDetectionIsFirstOrderWhateverTheIntegrator()
    {
        // Three bounces of the report's ball, dt from 4 down to 1/64 step.
        const auto r = small(ab::SceneId::Bounce1d, {}, 600.0, 4.0, 1.0 / 64.0, 3);
        for (Integrator i : {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4})
            checkOrder(r, {i, ImpactMode::StepEnd}, 1.0, 0.2);
        // Located impacts do not help a first-order integrator.
        checkOrder(r, {Integrator::Euler, ImpactMode::Located}, 1.0, 0.2);
        checkOrder(r, {Integrator::SymplecticEuler, ImpactMode::Located}, 1.0, 0.2);
    }

    void locatedImpactsKeepVerletSecondAndRk4FourthOrderUnderDrag()
    {
        // Quadratic drag (terminal speed sqrt(m g / c) = 9.9 unit/step), rest included.
        // rk4's rows below 1e-11 relative error (round-off) are left out of its fit.
        const auto r = small(ab::SceneId::Bounce1d, {"c=0.001"}, 600.0, 4.0, 1.0 / 64.0, 3);
        checkOrder(r, {Integrator::Verlet, ImpactMode::Located}, 2.0, 0.2);
        checkOrder(r, {Integrator::Rk4, ImpactMode::Located}, 4.0, 0.3);
        for (Integrator i : {Integrator::Euler, Integrator::SymplecticEuler, Integrator::Verlet, Integrator::Rk4})
            checkOrder(r, {i, ImpactMode::StepEnd}, 1.0, 0.2);
        // No event rows: it refuses drag.
        for (const auto& row : r.rows)
            QVERIFY(row.method.integrator != Integrator::Event);
    }

    void eventIsExactAtAnySamplingIntervalAndCheapest()
    {
        const auto r = small(ab::SceneId::Box3d, {}, 22.0, 0.3, 0.003, 1);
        QVERIFY(r.complete);
        for (const auto& row : r.rows) {
            if (!row.method.exact())
                continue;
            QVERIFY2(row.relativeError <= 1e-13, qPrintable(QString("event error %1").arg(row.relativeError)));
            QVERIFY(row.impactTimeError && *row.impactTimeError <= 1e-12);
            QVERIFY(row.energyError <= 1e-13);
        }
        QVERIFY(ab::study::cpuToReach(r, {Integrator::Event, ImpactMode::Located}, 1e-10));
        QVERIFY(!ab::study::cpuToReach(r, {Integrator::Euler, ImpactMode::StepEnd}, 1e-10));
    }

    void fitAndCostAreReadOffTheRows()
    {
        // A synthetic result: error 3 dt^2, the CPU time 1/dt microseconds.
        ab::study::Result r;
        r.lengthScale = 10.0;
        const Method m{Integrator::Verlet, ImpactMode::Located};
        for (double dt : {1.0, 0.5, 0.25, 0.125, 0.0625}) {
            ab::study::Row row;
            row.method = m;
            row.dt = dt;
            row.maxError = 3.0 * dt * dt;
            row.relativeError = row.maxError / 10.0;
            row.cpuSeconds = 1e-6 / dt;
            r.rows.push_back(row);
        }
        QVERIFY(std::abs(*ab::study::fittedOrder(r, m) - 2.0) < 1e-12);
        // Relative error 0.3 dt^2 <= 0.01 first at dt = 0.125 (0.0047): 8 microseconds.
        QCOMPARE(*ab::study::cpuToReach(r, m, 0.01), 8e-6);
        QVERIFY(!ab::study::cpuToReach(r, m, 1e-6));
        QVERIFY(!ab::study::fittedOrder(r, {Integrator::Rk4, ImpactMode::Located}));
    }

    void csvAndMarkdownCarryEveryRow()
    {
        const auto r = small(ab::SceneId::Bounce1d, {"k=0.8"}, 300.0, 1.0, 0.1, 1);
        QCOMPARE(r.rows.size(), std::size_t(9 * 2));
        std::ostringstream csv, md;
        ab::study::writeCsv(csv, r);
        ab::study::writeMarkdown(md, r);
        std::istringstream lines(csv.str());
        std::string line;
        std::getline(lines, line);
        QVERIFY(line.rfind("integrator,impacts,dt,max_error,cpu_seconds,", 0) == 0);
        int rows = 0;
        while (std::getline(lines, line)) {
            ++rows;
            QVERIFY(line.find("nan") == std::string::npos && line.find("inf") == std::string::npos);
        }
        QCOMPARE(rows, 18);
        QVERIFY(csv.str().find("\nevent,exact,1,") != std::string::npos);
        QVERIFY(csv.str().find("\nverlet,step-end,0.1,") != std::string::npos);
        for (const char* needle : {"## Work-precision: bounce1d", "`k=0.8`", "| dt (step) |", "rk4 located",
                                   "### Summary", "observed order"})
            QVERIFY2(md.str().find(needle) != std::string::npos, needle);
    }

    void cancellingReturnsWhatWasDoneMarkedIncomplete()
    {
        ab::study::Options o =
            ab::study::defaultOptions(testing::spec(ab::SceneId::Bounce1d, {}, ab::ModelKind::Physical));
        o.repeats = 1;
        int rows = 0;
        const auto r = ab::study::runStudy(
            o, [&](std::size_t, std::size_t, const ab::study::Row&) { ++rows; }, [&] { return rows >= 2; });
        QVERIFY(!r.complete);
        QCOMPARE(r.rows.size(), std::size_t(2));
    }

    void progressCountsEveryRowUpToTheTotal()
    {
        ab::study::Options o =
            ab::study::defaultOptions(testing::spec(ab::SceneId::Bounce1d, {}, ab::ModelKind::Physical));
        o.dts = {0.5, 0.25};
        o.methods = {{ab::Integrator::Verlet, ab::ImpactMode::Located},
                     {ab::Integrator::Event, ab::ImpactMode::Located}};
        o.repeats = 1;
        std::vector<std::size_t> seen;
        const auto r = ab::study::runStudy(o, [&](std::size_t done, std::size_t total, const ab::study::Row&) {
            QCOMPARE(total, std::size_t(4));
            seen.push_back(done);
        });
        QVERIFY(r.complete);
        QCOMPARE(seen, (std::vector<std::size_t>{1, 2, 3, 4}));
    }

    void scenesWithoutAClosedFormAreRefused()
    {
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::study::defaultOptions(testing::spec(ab::SceneId::Box3d, {"b=0.1"},
                                                                                         ab::ModelKind::Physical)));
        QVERIFY_THROWS_EXCEPTION(ab::InputError, ab::study::defaultOptions(testing::spec(ab::SceneId::ManyBalls, {},
                                                                                         ab::ModelKind::Physical)));
    }
};

QTEST_GUILESS_MAIN(StudyTest)
#include "test_study.moc"
