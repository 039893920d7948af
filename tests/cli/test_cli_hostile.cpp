// SPDX-License-Identifier: MIT
// amazeballs-cli as an attacker runs it, each case a row: FIFOs, devices, symbolic links
// and read-only files as targets and inputs, a full disk (a file size limit set with
// setrlimit, SIGXFSZ ignored: no root, no mount), a closed or full standard output,
// signals sent to the running child, huge and malformed input. Every row runs the real
// program in a fresh folder and checks its exit status (or the signal it died of), the
// number of lines on stderr and a word of the line, that no temporary file is left, and
// that the files it was given are untouched (content and mode) unless it was to write them.
#include "hostile_support.h"

#include <QtTest>

#include <csignal>
#include <sys/stat.h>
#include <unistd.h>

namespace {

using namespace hostile;

std::vector<Case>& cases()
{
    static std::vector<Case> all = [] {
        std::vector<Case> c;
        addTargetCases(c);
        addInputCases(c);
        addNumberCases(c);
        addSignalCases(c);
        addWindowCases(c);
        return c;
    }();
    return all;
}

} // namespace

class CliHostile : public QObject {
    Q_OBJECT

private slots:
    void behavesPerTheContract_data()
    {
        QTest::addColumn<int>("index");
        for (std::size_t i = 0; i < cases().size(); ++i)
            QTest::newRow(cases()[i].name.c_str()) << int(i);
    }

    void behavesPerTheContract()
    {
        QFETCH(int, index);
        const Case& c = cases()[std::size_t(index)];
        const Outcome o = runCase(c);
        QVERIFY2(o.problem.empty(), o.problem.c_str());
    }

    // The core's list of chart keys a preset may name is the window's list.
    void presetChartKeysAreTheWindowsCharts() { QVERIFY2(chartKeysAgree(), "core/io/preset.cpp and ui/charts differ"); }
};

QTEST_GUILESS_MAIN(CliHostile)
#include "test_cli_hostile.moc"
