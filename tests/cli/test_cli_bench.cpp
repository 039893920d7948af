// SPDX-License-Identifier: MIT
// amazeballs-cli bench, run in process on small N: the CSV carries the contract's columns
// with a finite positive cost for every case, the Markdown table is written, rough balls
// run with --set, and every
// bad argument exits with status 2, one line on stderr and no file left behind.
#include "support/cli_runner.h"

#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

using testing::cli;
using Result = testing::CliResult;

std::vector<std::string> split(const std::string& line)
{
    std::vector<std::string> cells;
    std::stringstream in(line);
    std::string cell;
    while (std::getline(in, cell, ','))
        cells.push_back(cell);
    return cells;
}

std::vector<std::vector<std::string>> readCsv(const std::filesystem::path& path)
{
    std::ifstream in(path);
    std::vector<std::vector<std::string>> rows;
    for (std::string line; std::getline(in, line);)
        rows.push_back(split(line));
    return rows;
}

} // namespace

class CliBench : public QObject {
    Q_OBJECT

private slots:
    void smallRunWritesTheContractColumns()
    {
        QTemporaryDir dir;
        const std::string csv = dir.filePath("bench.csv").toStdString();
        const std::string md = dir.filePath("bench.md").toStdString();
        const Result r = cli({"bench", "--balls", "150", "--balls", "1000", "--steps", "5", "--repeats", "1",
                              "--threads", "2", "--out", csv, "--markdown", md});
        QCOMPARE(r.status, 0);
        const auto rows = readCsv(csv);
        QCOMPARE(rows.size(), std::size_t(5)); // header; 150 and 1000, each grid and all-pairs
        const std::vector<std::string> contract{"balls", "broadphase", "threads", "ns_per_ball_step",
                                                "steps_per_second"};
        QVERIFY(std::equal(contract.begin(), contract.end(), rows[0].begin()));
        const std::vector<std::pair<std::string, std::string>> cases{
            {"150", "grid"}, {"150", "all-pairs"}, {"1000", "grid"}, {"1000", "all-pairs"}};
        for (std::size_t i = 0; i < cases.size(); ++i) {
            const auto& row = rows[i + 1];
            QCOMPARE(row.size(), rows[0].size());
            QCOMPARE(row[0], cases[i].first);
            QCOMPARE(row[1], cases[i].second);
            QCOMPARE(row[2], std::string("2"));
            const double ns = std::stod(row[3]), sps = std::stod(row[4]);
            QVERIFY(std::isfinite(ns) && ns > 0.0);
            // steps per second is the same measurement: 1e9 / (ns N), to the printed digits.
            QVERIFY(std::abs(sps * ns * std::stod(row[0]) / 1e9 - 1.0) < 1e-3);
        }
        std::ifstream table(md);
        const std::string text{std::istreambuf_iterator<char>(table), {}};
        QVERIFY(text.find("| 1000 | physical | all-pairs | 2 |") != std::string::npos);
    }

    void reportModelRunsOnItsOwnThread()
    {
        const Result r = cli(
            {"bench", "--model", "report", "--balls", "300", "--broadphase", "grid", "--steps", "3", "--repeats", "1"});
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.rfind("balls,broadphase,threads,ns_per_ball_step,steps_per_second", 0) == 0);
        QVERIFY(r.out.find("\n300,grid,1,") != std::string::npos);
    }

    void roughBallsRunWithTheirSettingsNamed()
    {
        // --set mu, beta, inertia and spin make the same workload's balls rough; the
        // Markdown's footnote names them.
        QTemporaryDir dir;
        const std::string md = dir.filePath("bench.md").toStdString();
        const Result r = cli({"bench", "--balls", "1000", "--broadphase", "grid", "--steps", "5", "--repeats", "1",
                              "--set", "mu=0.5", "--set", "beta=0.3", "--set", "spin=0.2", "--markdown", md});
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.find("\n1000,grid,1,") != std::string::npos);
        std::ifstream table(md);
        const std::string text{std::istreambuf_iterator<char>(table), {}};
        QVERIFY(text.find(" --set mu=0.5 --set beta=0.3 --set spin=0.2") != std::string::npos);
    }

    void badArgumentsExitWithStatusTwo_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::newRow("no balls") << QStringList{"--balls", "0"};
        QTest::newRow("balls not a number") << QStringList{"--balls", "many"};
        QTest::newRow("too many balls") << QStringList{"--balls", "5000000"};
        QTest::newRow("no threads") << QStringList{"--threads", "0"};
        QTest::newRow("unknown broadphase") << QStringList{"--broadphase", "octree"};
        QTest::newRow("unknown model") << QStringList{"--model", "bullet"};
        QTest::newRow("no steps") << QStringList{"--steps", "0"};
        QTest::newRow("all-pairs too large") << QStringList{"--broadphase", "all-pairs", "--balls", "100000"};
        QTest::newRow("report on two threads") << QStringList{"--model", "report", "--threads", "2"};
        QTest::newRow("unknown option") << QStringList{"--fast"};
        QTest::newRow("stray argument") << QStringList{"many-balls"};
        QTest::newRow("--set of the workload") << QStringList{"--set", "n=5"};
        QTest::newRow("--set out of range") << QStringList{"--set", "mu=20"};
        QTest::newRow("--set with the report model") << QStringList{"--model", "report", "--set", "mu=0.5"};
        QTest::newRow("unwritable output") << QStringList{"--balls", "150", "--out", "/nonexistent/dir/b.csv"};
    }
    void badArgumentsExitWithStatusTwo()
    {
        QFETCH(QStringList, args);
        QTemporaryDir dir;
        std::vector<std::string> argv{"bench", "--steps", "2", "--repeats", "1"};
        for (const QString& a : args)
            argv.push_back(a.toStdString());
        argv.push_back("--markdown");
        argv.push_back(dir.filePath("table.md").toStdString());
        const Result r = cli(argv);
        QCOMPARE(r.status, 2);
        QVERIFY(r.err.rfind("amazeballs-cli: ", 0) == 0);
        QCOMPARE(std::count(r.err.begin(), r.err.end(), '\n'), 1L);
        QVERIFY(std::filesystem::is_empty(dir.path().toStdString()));
    }
};

QTEST_GUILESS_MAIN(CliBench)
#include "test_cli_bench.moc"
