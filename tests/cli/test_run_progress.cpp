// SPDX-License-Identifier: MIT
// The progress line of a long `run` (app/cli/run_progress.h) on a clock the test sets: nothing
// in the first two seconds, then the scene time, the share done and the time left at the
// pace so far, elapsed (total - done) / done, rewritten in place at most twice a second, and
// wiped at the end so that the health check's line starts clean.
#include "app/cli/run_progress.h"

#include <QtTest>

#include <sstream>

using ab::cli::RunProgress;

namespace {

// A progress line of `total` steps to `tEnd` seconds, written to a string on a clock the test
// moves by setting `now`.
struct Watched {
    std::ostringstream err;
    double now = 0.0;
    RunProgress line;

    Watched(long long total, double tEnd, bool shown = true)
        : line(err, shown, total, tEnd, "s", [this] { return now; })
    {
    }
};

} // namespace

class RunProgressLine : public QObject {
    Q_OBJECT

private slots:
    void nothingIsWrittenInTheFirstTwoSeconds()
    {
        Watched w(100, 9.0);
        w.now = 1.9;
        w.line.update(50, 4.5);
        w.line.end();
        QCOMPARE(w.err.str(), std::string());
    }

    void theLineGivesTheSceneTimeTheShareAndTheTimeLeftAtThePaceSoFar()
    {
        // 2 s for 135 of 540 steps: 2 x 405 / 135 = 6 s left.
        Watched w(540, 9.0);
        w.now = 2.0;
        w.line.update(135, 2.25);
        QCOMPARE(w.err.str(), std::string("\rrun: t = 2.25 of 9 s (25%), about 0:06 left"));
    }

    void theLineIsRewrittenAtMostTwiceASecondAndAShorterOneCoversTheLonger()
    {
        Watched w(1000, 16.0);
        w.now = 3.0;
        w.line.update(1, 0.01); // 3 x 999 = 2997 s left: 49:57
        const std::string first = "\rrun: t = 0.01 of 16 s (0%), about 49:57 left";
        QCOMPARE(w.err.str(), first);
        w.now = 3.4; // within half a second: nothing
        w.line.update(2, 0.02);
        QCOMPARE(w.err.str(), first);
        w.now = 3.5; // 3.5 x 100 / 900 = 0.39 s, shown as a whole second
        w.line.update(900, 14.4);
        const std::string second = "run: t = 14.4 of 16 s (90%), about 0:01 left";
        QCOMPARE(w.err.str(), first + "\r" + second + std::string(first.size() - 1 - second.size(), ' '));
    }

    void theEndWipesTheLine()
    {
        std::ostringstream err;
        {
            double now = 0.0;
            RunProgress p(err, true, 20, 2.0, "s", [&] { return now; });
            now = 2.5;
            p.update(10, 1.0);
        } // a run that ends by an exception wipes the line as well
        const std::string line = "run: t = 1 of 2 s (50%), about 0:03 left";
        QCOMPARE(err.str(), "\r" + line + "\r" + std::string(line.size(), ' ') + "\r");
    }

    void nothingIsWrittenWhereItIsNotShown()
    {
        Watched w(20, 2.0, false);
        w.now = 10.0;
        w.line.update(10, 1.0);
        w.line.end();
        QCOMPARE(w.err.str(), std::string());
        QVERIFY(!RunProgress::isTerminal(w.err)); // a string stream is no terminal
    }

    void timesLeftReadAsAClock()
    {
        QCOMPARE(RunProgress::clockTime(0.0), std::string("0:00"));
        QCOMPARE(RunProgress::clockTime(59.2), std::string("1:00"));
        QCOMPARE(RunProgress::clockTime(3725.0), std::string("1:02:05"));
        QCOMPARE(RunProgress::clockTime(std::nan("")), std::string("0:00"));
    }
};

QTEST_APPLESS_MAIN(RunProgressLine)
#include "test_run_progress.moc"
