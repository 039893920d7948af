// SPDX-License-Identifier: MIT
// The stability suite: every row of every case runs to an honest outcome with finite
// figures; on the stiff spring each integrator holds below its limit and fails above it
// when it steps across the contact on its own, and the implicit ones never fail with the
// contact located.
#include "core/stability/stability_limit.h"
#include "core/stability/suite.h"

#include <QtTest>

#include <cmath>
#include <sstream>

using namespace ab;
using namespace ab::stability;

namespace {

std::vector<RowResult> runCase(const std::string& name, long long maxSteps = 0)
{
    std::vector<RowResult> out;
    for (CaseRow row : findCase(name)->rows()) {
        if (maxSteps > 0)
            row.steps = std::min(row.steps, maxSteps);
        out.push_back(runRow(row));
    }
    return out;
}

bool finiteFigures(const RowResult& r)
{
    const auto& f = r.figures;
    return std::isfinite(f.maxEnergyGain) && std::isfinite(f.maxPenetration) &&
           (!f.maxMomentumError || std::isfinite(*f.maxMomentumError)) &&
           (!f.maxOverlap || std::isfinite(*f.maxOverlap)) && (!r.referenceError || std::isfinite(*r.referenceError));
}

} // namespace

class StabilitySuite : public QObject {
    Q_OBJECT

private slots:
    void everyRowEndsWithAnHonestOutcome_data()
    {
        QTest::addColumn<QString>("name");
        for (const StabilityCase& c : stabilityCases())
            QTest::newRow(c.name.c_str()) << QString::fromStdString(c.name);
    }

    void everyRowEndsWithAnHonestOutcome()
    {
        // Rows shortened to 20000 steps: this checks outcomes, not the long runs' figures.
        QFETCH(QString, name);
        const auto rows = runCase(name.toStdString(), 20'000);
        QVERIFY(!rows.empty());
        for (const RowResult& r : rows) {
            const QString where =
                QString::fromStdString(r.caseName + " " + r.model + " " + r.integrator + " " + r.setting);
            switch (r.outcome) {
            case RowOutcome::Ran:
                QVERIFY2(r.verdict == "ok" || r.verdict == "degraded" || r.verdict == "failed", qPrintable(where));
                QVERIFY2(finiteFigures(r), qPrintable(where));
                QVERIFY2(r.figures.steps > 0, qPrintable(where));
                // A failure always says what happened.
                QVERIFY2(r.verdict == "ok" || !r.note.empty(), qPrintable(where));
                // The physical model never loses a ball: impacts are located or the walls
                // clamp, and the spring floor's backstop holds an unstable integrator.
                if (r.model == "physical")
                    QVERIFY2(r.figures.escaped == 0, qPrintable(where + " " + QString::fromStdString(r.note)));
                break;
            case RowOutcome::Refused:
                QVERIFY2(r.verdict == "ok", qPrintable(where + " " + QString::fromStdString(r.note)));
                break;
            case RowOutcome::NotAvailable:
                QCOMPARE(r.note, std::string("not available in this build"));
                QCOMPARE(r.model, std::string("physical"));
                break;
            case RowOutcome::Skipped:
                QVERIFY(r.note.find("not run: ") == 0);
                break;
            }
        }
    }

    void roughSuperballsKeepTheirEnergyOverAMillionSteps()
    {
        // k = e = 1, beta = 1, friction that sticks: every impact keeps the energy of
        // translation and rotation exactly, so over 1e6 steps verlet, rk4 and event end
        // within 1e-9 of the start energy (box3d's back-and-forth superball, two-balls);
        // explicit Euler gains, as it does without spin. Many-balls' grazing contacts slide
        // and lose energy, but it never rises above the start.
        int checked = 0;
        for (CaseRow row : findCase("spin-energy-drift")->rows()) {
            const bool exact = row.integrator == Integrator::Verlet || row.integrator == Integrator::Rk4 ||
                               row.integrator == Integrator::Event;
            if (row.scene == SceneId::ManyBalls)
                row.steps = 20'000;
            else if (!exact && row.integrator != Integrator::Euler)
                continue;
            const RowResult r = runRow(row);
            const QString where = QString::fromStdString(r.integrator + " " + r.setting + ": " + r.note);
            QCOMPARE(r.outcome, RowOutcome::Ran);
            QVERIFY2(r.referenceError.has_value(), qPrintable(where));
            if (row.scene == SceneId::ManyBalls) {
                QVERIFY2(r.figures.maxEnergyGain < 1e-9 && *r.referenceError < 0.0, qPrintable(where));
            } else if (exact) {
                QVERIFY2(std::abs(*r.referenceError) < 1e-9 && r.figures.maxEnergyGain < 1e-9, qPrintable(where));
                QVERIFY2(r.verdict == "ok", qPrintable(where));
            } else {
                QVERIFY2(*r.referenceError > 0.1 && r.verdict == "failed", qPrintable(where)); // euler gains
            }
            ++checked;
        }
        QCOMPARE(checked, 7); // box3d euler, verlet, rk4, event; two-balls verlet, event; many-balls
    }

    void fastBackSpinAtAWallStaysInsideAndLosesEnergy()
    {
        // A ball at up to 3000 m/s with ten times as much back-spin meets the wall: every
        // integrator keeps it in the box, and friction only takes energy away.
        for (const RowResult& r : runCase("spin-backspin-wall")) {
            const QString where = QString::fromStdString(r.integrator + " " + r.setting + ": " + r.note);
            QCOMPARE(r.outcome, RowOutcome::Ran);
            QVERIFY2(r.figures.escaped == 0 && !r.figures.nonfinite && r.verdict != "failed", qPrintable(where));
            QVERIFY2(r.referenceError && *r.referenceError < 0.0, qPrintable(where));
        }
    }

    void valuesOutsideTheTableAreRefused()
    {
        bool sawRefusal = false;
        for (const RowResult& r : runCase("extreme-constants", 2000))
            if (r.outcome == RowOutcome::Refused) {
                sawRefusal = true;
                QVERIFY(r.note.find("k: 1.5 is outside the allowed range [0, 1]") != std::string::npos);
            }
        QVERIFY(sawRefusal);
    }

    void stiffSpringHoldsBelowEachLimitAndFailsAboveIt()
    {
        // Stepping across the contact on its own (step-end), each explicit integrator on
        // the linear spring of stiffness 1e1 and 1e3 fails at 1.25 times its limit on the
        // spring's damped oscillator and does not fail at 0.8 times it.
        int checked = 0;
        for (const RowResult& r : runCase("stiff-spring")) {
            const bool stepEnd = r.setting.rfind("step-end, linear stiffness 1e1,", 0) == 0 ||
                                 r.setting.rfind("step-end, linear stiffness 1e3,", 0) == 0;
            const QString where = QString::fromStdString(r.integrator + " " + r.setting + ": " + r.note);
            if (r.integrator == "implicit-euler" ||
                (r.integrator == "implicit-midpoint" && r.setting.rfind("located", 0) == 0)) {
                // Bounded at every stiffness and step tried.
                QVERIFY2(r.verdict != "failed" && !r.figures.nonfinite && r.figures.escaped == 0, qPrintable(where));
                continue;
            }
            if (!stepEnd || r.integrator == "implicit-midpoint")
                continue;
            const bool above = r.setting.find("= 1.25 x") != std::string::npos;
            QVERIFY2(above ? r.verdict == "failed" : r.verdict != "failed", qPrintable(where));
            ++checked;
        }
        QCOMPARE(checked, 16); // 4 explicit integrators x 2 steps x 2 stiffnesses
    }

    void theReportsCoarseStepFailsWhereItsEulerGainsAQuarter()
    {
        // Stage 1 at dt = 100: three steps of fall already add 3 g^2 dt^2 / 2 = 145 to
        // E0 = g h0 = 196 (74%): failed; at the report's own dt = 1, degraded.
        const auto rows = runCase("coarse-step");
        for (const RowResult& r : rows) {
            if (r.model != "report")
                continue;
            if (r.dt == 100.0) {
                QCOMPARE(r.verdict, std::string("failed"));
                QVERIFY(r.figures.maxEnergyGain >= 1.5 * 0.0982 * 0.0982 * 1e4 / (0.0982 * 2000.0));
            }
            if (r.dt == 1.0)
                QCOMPARE(r.verdict, std::string("degraded"));
        }
    }

    void csvHasTheContractColumnsAndNoNaN()
    {
        std::ostringstream csv;
        writeCsv(csv, runCase("degenerate"));
        const std::string text = csv.str();
        QVERIFY(text.rfind("case,model,integrator,max_energy_gain,max_penetration,escaped,nonfinite,verdict,", 0) == 0);
        QVERIFY(text.find("nan") == std::string::npos);
        QVERIFY(text.find("inf") == std::string::npos);
        QVERIFY(text.find("not available") == std::string::npos); // only runs are CSV rows
    }

    void suiteRunsEveryRowInOrderAndCountsToTheTotal()
    {
        // The suite of one case gives the same rows, with the same figures, as running
        // the case row by row (runRow is deterministic), and progress counts 1..total.
        const std::vector<CaseRow> rows = suiteRows({findCase("plastic")});
        const std::vector<RowResult> direct = runCase("plastic");
        std::vector<std::size_t> seen;
        const SuiteResult suite = runSuite(rows, [&](std::size_t done, std::size_t total, const RowResult&) {
            QCOMPARE(total, rows.size());
            seen.push_back(done);
        });
        QVERIFY(suite.complete);
        QCOMPARE(suite.rows.size(), direct.size());
        QCOMPARE(seen.size(), rows.size());
        for (std::size_t i = 0; i < seen.size(); ++i)
            QCOMPARE(seen[i], i + 1);
        for (std::size_t i = 0; i < direct.size(); ++i) {
            QCOMPARE(suite.rows[i].setting, direct[i].setting);
            QCOMPARE(suite.rows[i].verdict, direct[i].verdict);
            QCOMPARE(suite.rows[i].figures.maxPenetration, direct[i].figures.maxPenetration);
        }
        std::size_t all = 0;
        for (const StabilityCase& c : stabilityCases())
            all += c.rows().size();
        QCOMPARE(suiteRows().size(), all);
    }

    void cancellingTheSuiteKeepsTheFinishedRowsOnly()
    {
        // Cancelled after the second row is told: two rows, marked incomplete.
        const std::vector<CaseRow> rows = suiteRows({findCase("coarse-step")});
        QVERIFY(rows.size() > 2);
        std::size_t told = 0;
        const SuiteResult suite = runSuite(
            rows, [&](std::size_t done, std::size_t, const RowResult&) { told = done; }, [&] { return told >= 2; });
        QVERIFY(!suite.complete);
        QCOMPARE(suite.rows.size(), std::size_t(2));
        QCOMPARE(suite.rows[1].setting, runRow(rows[1]).setting);
    }

    void aRowCancelledPartWayIsDropped()
    {
        // Cancelled between steps of the first row: that row's figures cover part of the
        // run only, so the suite returns none.
        const std::vector<CaseRow> rows = suiteRows({findCase("coarse-step")});
        int polls = 0;
        const SuiteResult suite = runSuite(rows, {}, [&] { return ++polls > 3; });
        QVERIFY(!suite.complete);
        QVERIFY(suite.rows.empty());
    }

    void markdownListsTheLimitsAndEveryRow()
    {
        std::ostringstream md;
        const auto rows = runCase("plastic");
        writeMarkdown(md, rows);
        const std::string text = md.str();
        QCOMPARE(static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')), rows.size() + 2);
        std::ostringstream limits;
        writeLimits(limits);
        QVERIFY(limits.str().find("| rk4 | 2.829") != std::string::npos);
    }
};

QTEST_GUILESS_MAIN(StabilitySuite)
#include "test_stability_suite.moc"
