// SPDX-License-Identifier: MIT
// `amazeballs-cli study` in process: the CSV with the contract's columns, the Markdown
// report, the chart as PNG and SVG, progress on stderr, bad input refused (exit 2, one
// line, no file), and Ctrl+C leaving no file behind.
#include "app/cli/interrupt.h"
#include "support/cli_runner.h"

#include <QImage>
#include <QTemporaryDir>
#include <QtTest>

#include <csignal>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace {

using testing::cli;
using Result = testing::CliResult;

using testing::readFile;

// A sweep of two steps, one repeat: quick, and every method present.
std::vector<std::string> small(std::vector<std::string> args)
{
    for (const char* a : {"--t-end", "300", "--dt-max", "2", "--dt-min", "0.2", "--per-decade", "1", "--repeats", "1"})
        args.emplace_back(a);
    return args;
}

} // namespace

class CliStudy : public QObject {
    Q_OBJECT

private slots:
    void writesTheCsvMarkdownAndPngChart()
    {
        QTemporaryDir dir;
        const std::string csv = dir.filePath("study.csv").toStdString();
        const std::string md = dir.filePath("study.md").toStdString();
        const std::string png = dir.filePath("study.png").toStdString();
        const Result r = cli(small({"study", "bounce1d", "--quiet", "--out", csv, "--markdown", md, "--chart", png}));
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.empty()); // the report went to the file

        std::istringstream lines(readFile(csv));
        std::string line;
        std::getline(lines, line);
        QVERIFY2(line.rfind("integrator,impacts,dt,max_error,cpu_seconds", 0) == 0, line.c_str());
        int rows = 0, exact = 0;
        while (std::getline(lines, line)) {
            ++rows;
            char integrator[32], impacts[16];
            double dt = 0.0, error = -1.0, cpu = -1.0;
            QVERIFY2(std::sscanf(line.c_str(), "%31[^,],%15[^,],%lf,%lf,%lf", integrator, impacts, &dt, &error, &cpu) ==
                         5,
                     line.c_str());
            QVERIFY(error >= 0.0 && cpu > 0.0 && (dt == 2.0 || dt == 0.2));
            if (std::string(impacts) == "exact") {
                ++exact;
                QCOMPARE(std::string(integrator), std::string("event"));
                QVERIFY(error < 1e-9); // in units, start height 2000
            } else {
                QVERIFY(std::string(impacts) == "located" || std::string(impacts) == "step-end");
            }
        }
        QCOMPARE(rows, 18); // (4 integrators x 2 impact modes + event) x 2 steps
        QCOMPARE(exact, 2);

        const std::string report = readFile(md);
        for (const char* needle : {"## Work-precision: bounce1d", "### Summary", "| dt (step) |", "verlet step-end"})
            QVERIFY2(report.find(needle) != std::string::npos, needle);

        const QImage image(QString::fromStdString(png));
        QVERIFY(!image.isNull());
        QCOMPARE(image.size(), QSize(1200, 800));
    }

    void writesAnSvgChartAndTheReportToStdout()
    {
        QTemporaryDir dir;
        const std::string svg = dir.filePath("wp.svg").toStdString();
        const Result r = cli(small({"study", "box3d", "--quiet", "--chart", svg}));
        QCOMPARE(r.status, 0);
        QVERIFY(r.out.find("## Work-precision: box3d") != std::string::npos);
        QVERIFY(readFile(svg).find("<svg") != std::string::npos);
    }

    void reportsProgressOnStderr()
    {
        const Result r = cli(small({"study", "bounce1d", "--set", "c=0.001"}));
        QCOMPARE(r.status, 0);
        // With drag the event integrator is left out: 8 methods x 2 steps.
        QVERIFY2(r.err.find("study bounce1d: 1/16") != std::string::npos, r.err.c_str());
        QVERIFY(r.err.find("16/16") != std::string::npos);
        QVERIFY(r.out.find("`c=0.001`") != std::string::npos);
    }

    void badInputIsRefusedBeforeAnythingIsWritten_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        QTest::newRow("no scene") << QStringList{"study"} << "study: missing SCENE";
        QTest::newRow("unknown scene") << QStringList{"study", "nowhere"} << "unknown scene 'nowhere'";
        QTest::newRow("many balls") << QStringList{"study", "many-balls"} << "many-balls: there is no closed form";
        QTest::newRow("box3d with drag") << QStringList{"study", "box3d", "--set", "c=0.1"} << "c: 0.1 is not covered";
        QTest::newRow("value out of range") << QStringList{"study", "bounce1d", "--set", "k=2"} << "k: 2 is outside";
        QTest::newRow("negative t-end") << QStringList{"study", "bounce1d", "--t-end", "-5"} << "--t-end: -5 must be";
        QTest::newRow("steps upside down") << QStringList{"study", "bounce1d", "--dt-min", "2", "--dt-max", "1"}
                                           << "--dt-min: 2 is larger than --dt-max 1";
        QTest::newRow("per decade zero") << QStringList{"study", "bounce1d", "--per-decade", "0"} << "--per-decade: 0";
        QTest::newRow("chart type") << QStringList{"study", "bounce1d", "--chart", "OUT/x.jpg"}
                                    << "unknown image type 'jpg'";
        QTest::newRow("missing folder") << QStringList{"study", "bounce1d", "--out", "OUT/none/x.csv"}
                                        << "does not exist";
        QTest::newRow("run option") << QStringList{"study", "bounce1d", "--integrator", "rk4"}
                                    << "unknown option '--integrator'";
    }

    void badInputIsRefusedBeforeAnythingIsWritten()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        QTemporaryDir dir;
        std::vector<std::string> argv;
        for (QString a : args)
            argv.push_back(a.replace("OUT", dir.path()).toStdString());
        argv.push_back("--markdown");
        argv.push_back(dir.filePath("never.md").toStdString());
        const Result r = cli(argv);
        QCOMPARE(r.status, 2);
        QVERIFY2(r.err.find(message.toStdString()) != std::string::npos, r.err.c_str());
        QCOMPARE(std::count(r.err.begin(), r.err.end(), '\n'), 1L);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 0);
    }

    // Last: the interrupt flag stays set for the rest of the process.
    void ctrlCLeavesNoFileBehind()
    {
        QTemporaryDir dir;
        const std::string csv = dir.filePath("study.csv").toStdString();
        ab::cli::installInterruptHandler();
        std::raise(SIGINT);
        const Result r = cli({"study", "box3d", "--quiet", "--out", csv});
        QCOMPARE(r.status, 130);
        QVERIFY(r.err.find("interrupted") != std::string::npos);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 0);
    }
};

QTEST_MAIN(CliStudy)
#include "test_cli_study.moc"
