// SPDX-License-Identifier: MIT
// amazeballs-cli's health reporting and the `stability` command, in process: a run that
// overflows stops before the first non-finite state with status 3 and a valid CSV; the
// report model's known failures are named on stderr; `stability` writes its table and
// files and refuses unknown cases.
#include "support/cli_runner.h"

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

using testing::cli;
using Result = testing::CliResult;

using testing::readFile;

long lines(const std::string& s)
{
    return static_cast<long>(std::count(s.begin(), s.end(), '\n'));
}

} // namespace

class CliStability : public QObject {
    Q_OBJECT

private slots:
    void overflowingRunStopsBeforeTheNonFiniteStateWithStatus3()
    {
        // dt = 1e200: after one step the speed is 9.8e198 and its energy overflows.
        QTemporaryDir dir;
        const std::string path = dir.filePath("run.csv").toStdString();
        const Result r = cli({"run", "bounce1d", "--dt", "1e200", "--out", path});
        QCOMPARE(r.status, 3);
        QCOMPARE(lines(r.err), 1L);
        QVERIFY2(r.err.find("non-finite") != std::string::npos, r.err.c_str());
        const std::string csv = readFile(path);
        QCOMPARE(csv, std::string("t,ball,x,y,z,vx,vy,vz\n0,0,0,2000,0,0,0,0\n"));
    }

    void reportModelsKnownFailureIsNamedOnStderr()
    {
        // Stage 1's Euler gains energy in flight: a warning, the run itself succeeds.
        const Result r = cli({"run", "bounce1d", "--steps", "50"});
        QCOMPARE(r.status, 0);
        QCOMPARE(lines(r.err), 1L);
        QVERIFY2(r.err.find("warning: energy") != std::string::npos && r.err.find("eq 2.16") != std::string::npos,
                 r.err.c_str());
        QVERIFY(r.out.find("nan") == std::string::npos);
    }

    void springContactRunsThroughTheCli()
    {
        const Result r = cli({"run", "bounce1d", "--model", "physical", "--set", "contact=1", "--integrator",
                              "implicit-euler", "--steps", "500", "--summary"});
        QCOMPARE(r.status, 0);
        QVERIFY(r.err.empty());
        QVERIFY(r.out.find("implicit-euler") != std::string::npos);
    }

    void stabilityWritesTableCsvAndMarkdown()
    {
        QTemporaryDir dir;
        const std::string csv = dir.filePath("s.csv").toStdString();
        const std::string md = dir.filePath("s.md").toStdString();
        const Result r =
            cli({"stability", "--case", "plastic", "--case", "extreme-constants", "--out", csv, "--markdown", md});
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.find("plastic") != std::string::npos);
        QVERIFY(r.out.find("rows:") != std::string::npos);
        const std::string table = readFile(csv);
        QVERIFY(table.rfind("case,model,integrator,max_energy_gain,max_penetration,escaped,nonfinite,verdict,"
                            "momentum_error,max_overlap,reference_error,steps,cpu_seconds",
                            0) == 0);
        QVERIFY(table.find("refused, as it must be") != std::string::npos);
        QVERIFY(table.find("nan") == std::string::npos);
        QVERIFY(readFile(md).find("## Stability limits") != std::string::npos);
    }

    void stabilityListsItsCases()
    {
        const Result r = cli({"stability", "--list"});
        QCOMPARE(r.status, 0);
        for (const char* name : {"stiff-spring", "coarse-step", "energy-drift", "zeno-0.99", "tiny-step", "tunnelling",
                                 "dense-packing", "degenerate", "extreme-constants"})
            QVERIFY2(r.out.find(name) != std::string::npos, name);
    }

    void stabilityRefusesAnUnknownCaseOnOneLine()
    {
        const Result r = cli({"stability", "--case", "warp-drive"});
        QCOMPARE(r.status, 2);
        QCOMPARE(lines(r.err), 1L);
        QVERIFY(r.err.find("--case: unknown case 'warp-drive'") != std::string::npos);
        QVERIFY(r.out.empty());
    }
};

QTEST_GUILESS_MAIN(CliStability)
#include "test_cli_stability.moc"
