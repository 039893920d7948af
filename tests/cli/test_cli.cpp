// SPDX-License-Identifier: MIT
// amazeballs-cli run in process: list, run (reproducing the report's listings), and
// every kind of bad input giving exit status 2 with one line naming it.
#include "support/cli_runner.h"

#include "app/cli/run_setup.h"
#include "support/report_listings.h"

#include "support/sim_helpers.h"

#include <QTemporaryDir>
#include <QtTest>

#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

using testing::cli;
using Result = testing::CliResult;

struct Row {
    double t;
    int ball;
    double p[3], v[3];
};

std::vector<Row> parseCsv(const std::string& text)
{
    std::istringstream in(text);
    std::string line;
    std::getline(in, line);
    if (line != "t,ball,x,y,z,vx,vy,vz")
        throw std::runtime_error("bad header: " + line);
    std::vector<Row> rows;
    while (std::getline(in, line)) {
        Row r{};
        if (std::sscanf(line.c_str(), "%lf,%d,%lf,%lf,%lf,%lf,%lf,%lf", &r.t, &r.ball, &r.p[0], &r.p[1], &r.p[2],
                        &r.v[0], &r.v[1], &r.v[2]) != 8)
            throw std::runtime_error("bad row: " + line);
        rows.push_back(r);
    }
    return rows;
}

using testing::readFile;

} // namespace

class Cli : public QObject {
    Q_OBJECT

private slots:
    void listShowsEveryParameterWithUnitDefaultRangeAndEquation()
    {
        const Result r = cli({"list"});
        QCOMPARE(r.status, 0);
        for (const char* needle : {"bounce1d", "box3d", "two-balls", "many-balls", "max_bounces", "contact_factor",
                                   "unit/step^2", "0.0982", "[0, 1]", "eq 2.3", "2,20,2", "secondary_loss",
                                   "symplectic-euler", "event", "implicit-midpoint", "physical"})
            QVERIFY2(r.out.find(needle) != std::string::npos, needle);
    }

    void runBounce1dWithoutOptionsIsTheReportsStage1()
    {
        const Result r = cli({"run", "bounce1d"});
        QCOMPARE(r.status, 0);
        const auto rows = parseCsv(r.out);
        const auto ref = listing::appendixA(-0.0982, 0.6, 2000, 0, 10, 2000);
        QCOMPARE(rows.size(), std::size_t(2001));
        for (std::size_t i = 0; i < rows.size(); ++i) {
            QCOMPARE(rows[i].t, double(i));
            QVERIFY(std::abs(rows[i].p[1] - ref.p[i]) <= 1e-12 * 2000);
            QVERIFY(std::abs(rows[i].v[1] - ref.v[i]) <= 1e-12 * 2000);
            QCOMPARE(rows[i].p[0], 0.0);
            QCOMPARE(rows[i].v[2], 0.0);
        }
    }

    void runBox3dWithSetValuesMatchesTheListing()
    {
        const Result r =
            cli({"run", "box3d", "--set", "k=0.75", "--set", "g=5", "--set", "max_bounces=30", "--set", "p0=20,60,40"});
        QCOMPARE(r.status, 0);
        const auto rows = parseCsv(r.out);
        const auto ref = listing::appendixB(-5, 0.75, 300, {20, 60, 40}, {10, 0, 15}, 30, 6000);
        QCOMPARE(rows.size(), std::size_t(6001));
        for (std::size_t i = 0; i < rows.size(); ++i) {
            QVERIFY(std::abs(rows[i].t - 0.01 * double(i)) < 1e-9);
            for (int a = 0; a < 3; ++a) {
                QVERIFY(std::abs(rows[i].p[a] - ref.p[i][a]) <= 1e-12 * std::max(1.0, std::abs(ref.p[i][a])));
                QVERIFY(std::abs(rows[i].v[a] - ref.v[i][a]) <= 1e-12 * std::max(1.0, std::abs(ref.v[i][a])));
            }
        }
    }

    void runTwoBallsWritesBothBallsInIndexOrder()
    {
        const Result r = cli({"run", "two-balls", "--steps", "3"});
        QCOMPARE(r.status, 0);
        const auto rows = parseCsv(r.out);
        QCOMPARE(rows.size(), std::size_t(8));
        QCOMPARE(rows[0].ball, 0);
        QCOMPARE(rows[1].ball, 1);
        QCOMPARE(rows[1].p[2], 298.0);
    }

    // The street (stage 5) on the command line: physical and `event` without asking, spins in
    // the trajectory (its balls are rough by default), the balls between the house fronts.
    void runStreetStartsPhysicalAndWritesSpins()
    {
        const Result r = cli({"run", "street", "--set", "n=50", "--steps", "30", "--every", "30"});
        QCOMPARE(r.status, 0);
        std::istringstream in(r.out);
        std::string header, line;
        std::getline(in, header);
        QCOMPARE(header, std::string("t,ball,x,y,z,vx,vy,vz,wx,wy,wz"));
        int rows = 0;
        while (std::getline(in, line)) {
            double t = 0, x = 0, y = 0, z = 0;
            int ball = 0;
            QCOMPARE(std::sscanf(line.c_str(), "%lf,%d,%lf,%lf,%lf", &t, &ball, &x, &y, &z), 5);
            QVERIFY(std::abs(z) < 9.0 && y > 0.0 && x > 0.0); // between the house fronts, over block 1
            ++rows;
        }
        QCOMPARE(rows, 100);                    // the start and t = 0.5 s, 50 balls each
        QVERIFY2(r.err.empty(), r.err.c_str()); // healthy
    }

    // After the report's limit stops stage 3, its counter runs on (a contact a step for the
    // balls touching at rest): --summary gives the count at the stop, the same for a run of 40 s
    // or 60 s, past the limit of 100 by the stopping step's contacts only (it printed 1184
    // and 5184, and more with max_events=10 than with 100).
    void summaryGivesTheCountAtTheReportsStopNotTheCounterRunningOn()
    {
        const auto atStop = [](const std::vector<std::string>& more) {
            std::vector<std::string> args{"run", "two-balls", "--summary"};
            args.insert(args.end(), more.begin(), more.end());
            const Result r = cli(args);
            long long counted = -1, end = -1;
            const std::size_t at = r.out.find("contacts counted: ");
            if (r.status != 0 || at == std::string::npos ||
                std::sscanf(r.out.c_str() + at,
                            "contacts counted: %lld up to the stop at t = 34.58 s (the report's counter runs on "
                            "while the balls lie at rest: %lld by the end)",
                            &counted, &end) != 2)
                return std::pair<long long, long long>{-1, -1};
            return std::pair{counted, end};
        };
        const auto [at40, end40] = atStop({"--steps", "4000"});
        const auto [at60, end60] = atStop({"--steps", "6000"});
        QCOMPARE(at40, at60);
        QVERIFY2(at40 > 100 && at40 <= 103,
                 qPrintable(QString::number(at40))); // max_events = 100, 3 contacts a step at most
        QVERIFY(end60 > end40 && end40 > at40);
        const Result ten = cli({"run", "two-balls", "--summary", "--steps", "6000", "--set", "max_events=10"});
        long long atTen = -1;
        const std::size_t k = ten.out.find("contacts counted: ");
        QVERIFY2(k != std::string::npos, ten.out.c_str());
        QCOMPARE(std::sscanf(ten.out.c_str() + k, "contacts counted: %lld up to the stop", &atTen), 1);
        QVERIFY2(atTen > 10 && atTen <= 13, ten.out.c_str());
    }

    // --summary counts the street's impacts as its engine does (the street keeps no report
    // counters: it said "contacts counted: 0" while 300 balls landed on the road).
    void summaryCountsTheStreetsImpactsAsItsEngineDoes()
    {
        const Result r = cli({"run", "street", "--set", "n=300", "--steps", "60", "--summary"});
        QCOMPARE(r.status, 0);
        long long printed = -1;
        const std::size_t at = r.out.find("\nimpacts: ");
        QVERIFY2(at != std::string::npos, r.out.c_str());
        QCOMPARE(std::sscanf(r.out.c_str() + at, "\nimpacts: %lld (ball on ball and on the street", &printed), 1);
        QVERIFY2(r.out.find("contacts counted") == std::string::npos, r.out.c_str());

        const ab::State s =
            testing::record(testing::spec(ab::SceneId::Street, {"n=300"}, ab::ModelKind::Physical), 60).back();
        QVERIFY(s.impacts > 300); // every ball landed on the road at least once
        QCOMPARE(printed, s.impacts);
        // Its times as a person writes them: 60 steps of 1/60 s are 1 s, whatever the round-off.
        QVERIFY2(r.out.find(", dt 1/60 s, 60 steps to t = 1 s\n") != std::string::npos, r.out.c_str());
    }

    void aTrajectoryOver100MegabytesIsAnnouncedWithWhatWritesLess()
    {
        // The street's 10,000 balls every 1/60 s for 5 s with spins: 10,000 x 301 rows of 11
        // numbers of about 18 characters, 596 MB (586 MB written): said before the run.
        const auto note = ab::cli::largeTrajectoryNote(10000, 300, 1, true);
        QVERIFY(note);
        QCOMPARE(*note, std::string("about 600 MB of CSV (3010000 rows: every ball at every step); --every K writes "
                                    "every K-th step, --summary a few lines"));
        QVERIFY(!ab::cli::largeTrajectoryNote(10000, 300, 10, true)); // 31 states: 61 MB
        QVERIFY(!ab::cli::largeTrajectoryNote(2, 30000, 1, false));   // stage 3's run: 8.6 MB
        // The command says it on a terminal only: a script's standard error keeps its one line
        // (test_cli_hostile's interrupted runs of terabytes say only that they were interrupted).
    }

    void everyKeepsEveryKthStateAndTEndSetsTheLength()
    {
        const Result r = cli({"run", "bounce1d", "--t-end", "100", "--every", "10"});
        QCOMPARE(r.status, 0);
        const auto rows = parseCsv(r.out);
        QCOMPARE(rows.size(), std::size_t(11));
        QCOMPARE(rows.back().t, 100.0);
    }

    void outWritesTheFileWholeAndInitResumesFromIt()
    {
        QTemporaryDir dir;
        const std::string first = dir.filePath("first.csv").toStdString();
        QCOMPARE(cli({"run", "box3d", "--steps", "500", "--every", "500", "--out", first}).status, 0);
        // Resume from the last recorded state: build a one-state file from it.
        auto rows = parseCsv(readFile(first));
        QCOMPARE(rows.size(), std::size_t(2));
        const std::string resume = dir.filePath("resume.csv").toStdString();
        {
            std::ofstream f(resume);
            char line[256];
            std::snprintf(line, sizeof line, "t,ball,x,y,z,vx,vy,vz\n%.17g,0,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g\n",
                          rows[1].t, rows[1].p[0], rows[1].p[1], rows[1].p[2], rows[1].v[0], rows[1].v[1],
                          rows[1].v[2]);
            f << line;
        }
        const Result resumed = cli({"run", "box3d", "--init", resume, "--steps", "500"});
        QCOMPARE(resumed.status, 0);
        const auto r2 = parseCsv(resumed.out);
        const Result whole = cli({"run", "box3d", "--steps", "1000"});
        const auto r1 = parseCsv(whole.out);
        // Same rule from the same state: the free-flight part agrees (no contact counted
        // before step 500 changes the rule, the counter restarts only matters at the limit).
        QCOMPARE(r2.front().t, 5.0);
        QVERIFY(std::abs(r2.back().t - 10.0) < 1e-9);
        for (int a = 0; a < 3; ++a)
            QVERIFY(std::abs(r2.back().p[a] - r1.back().p[a]) < 1e-9 * 300);
        // No temporary file left beside the output.
        int files = 0;
        for (const auto& e : std::filesystem::directory_iterator(dir.path().toStdString()))
            files += e.is_regular_file();
        QCOMPARE(files, 2);
    }

    void badInputExitsWith2AndOneLineNamingIt_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("no command") << QStringList{} << "usage";
        QTest::newRow("unknown command") << QStringList{"fly"} << "unknown command 'fly'";
        QTest::newRow("unknown scene") << QStringList{"run", "three-balls"} << "unknown scene 'three-balls'";
        QTest::newRow("missing scene") << QStringList{"run"} << "missing SCENE";
        QTest::newRow("unknown option") << QStringList{"run", "bounce1d", "--speed", "3"} << "unknown option '--speed'";
        QTest::newRow("unknown parameter")
            << QStringList{"run", "bounce1d", "--set", "p0=1,2,3"} << "unknown parameter 'p0'";
        QTest::newRow("out of range") << QStringList{"run", "bounce1d", "--set", "k=2"} << "k: 2 is outside";
        QTest::newRow("non-finite") << QStringList{"run", "box3d", "--set", "g=nan"}
                                    << "g: 'nan' is not a finite number";
        QTest::newRow("malformed vector") << QStringList{"run", "box3d", "--set", "v0=1;2;3"} << "v0: '1;2;3'";
        QTest::newRow("bad dt") << QStringList{"run", "box3d", "--dt", "-1"} << "--dt";
        QTest::newRow("non-finite dt") << QStringList{"run", "box3d", "--dt", "inf"} << "--dt";
        QTest::newRow("bad steps") << QStringList{"run", "box3d", "--steps", "ten"} << "--steps: 'ten'";
        QTest::newRow("negative steps") << QStringList{"run", "box3d", "--steps", "-5"} << "--steps: -5 is outside";
        QTest::newRow("steps and t-end") << QStringList{"run", "box3d", "--steps", "5", "--t-end", "3"} << "not both";
        QTest::newRow("bad model") << QStringList{"run", "box3d", "--model", "magic"} << "--model: unknown value";
        QTest::newRow("bad integrator") << QStringList{"run", "box3d", "--integrator", "leapfrog"}
                                        << "--integrator: unknown value 'leapfrog'";
        QTest::newRow("missing value") << QStringList{"run", "box3d", "--set"} << "--set: missing value";
        QTest::newRow("start outside box") << QStringList{"run", "box3d", "--set", "p0=301,5,5"} << "outside the box";
        QTest::newRow("report frame step") << QStringList{"run", "many-balls", "--dt", "0.5"} << "one frame";
        QTest::newRow("unwritable folder")
            << QStringList{"run", "bounce1d", "--out", "/nonexistent-dir/x.csv"} << "does not exist";
        QTest::newRow("output is a folder") << QStringList{"run", "bounce1d", "--out", "/tmp"} << "is a folder";
        QTest::newRow("missing init file")
            << QStringList{"run", "box3d", "--init", "/nonexistent.csv"} << "--init: /nonexistent.csv: no such file";
        QTest::newRow("stray argument") << QStringList{"list", "extra"} << "unexpected argument 'extra'";
        QTest::newRow("street with the report model")
            << QStringList{"run", "street", "--model", "report"} << "the report's rules stop at the box";
        QTest::newRow("street with rk4") << QStringList{"run", "street", "--integrator", "rk4"} << "rk4 is not offered";
        QTest::newRow("street too narrow")
            << QStringList{"run", "street", "--set", "width=0.2"} << "width: 0.2 m leaves no room";
        QTest::newRow("street with too many cars")
            << QStringList{"run", "street", "--set", "blocks=1", "--set", "cars=500"} << "cars: 500 do not fit";
        QTest::newRow("bench of the box scene")
            << QStringList{"bench", "--scene", "box3d"} << "--scene: bench times many-balls and street";
    }

    void badInputExitsWith2AndOneLineNamingIt()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        std::vector<std::string> a;
        for (const QString& s : args)
            a.push_back(s.toStdString());
        const Result r = cli(a);
        QCOMPARE(r.status, 2);
        QVERIFY2(QString::fromStdString(r.err).contains(mentions), r.err.c_str());
        if (!args.isEmpty())
            QCOMPARE(std::count(r.err.begin(), r.err.end(), '\n'), 1L);
        QVERIFY(r.out.empty());
    }

    void malformedInitFileIsRefusedNamingTheLine()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("bad.csv").toStdString();
        std::ofstream(path) << "t,ball,x,y,z,vx,vy,vz\n0,0,1,2,3,4,5,6\n0,1,1,2,x,4,5,6\n";
        const Result r = cli({"run", "many-balls", "--init", path});
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find("line 3 column z") != std::string::npos, r.err.c_str());
        const Result wrongCount = cli({"run", "box3d", "--init", path});
        QCOMPARE(wrongCount.status, 2);
    }

    void failedRunLeavesAnExistingOutputUntouched()
    {
        QTemporaryDir dir;
        const std::string path = dir.filePath("keep.csv").toStdString();
        std::ofstream(path) << "precious\n";
        QCOMPARE(cli({"run", "box3d", "--set", "k=7", "--out", path}).status, 2);
        QCOMPARE(readFile(path), std::string("precious\n"));
    }
};

QTEST_GUILESS_MAIN(Cli)
#include "test_cli.moc"
