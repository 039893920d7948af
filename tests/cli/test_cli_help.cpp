// SPDX-License-Identifier: MIT
// amazeballs-cli's help, version and "did you mean ...?": what a new user meets first.
#include "support/cli_runner.h"

#include "app/cli/command_table.h"
#include "app/cli/parser.h"
#include "app/cli/suggest.h"

#include <CLI/CLI.hpp>
#include <QtTest>

namespace {

using testing::cli;
using Result = testing::CliResult;

std::vector<std::string> toStd(const QStringList& list)
{
    std::vector<std::string> out;
    for (const QString& s : list)
        out.push_back(s.toStdString());
    return out;
}

} // namespace

class CliHelp : public QObject {
    Q_OBJECT

private slots:
    void versionPrintsTheNameAndTheProjectVersion()
    {
        const Result r = cli({"--version"});
        QCOMPARE(r.status, 0);
        QCOMPARE(r.out, std::string("amazeballs-cli ") + AB_PROJECT_VERSION + "\n");
        QVERIFY(r.err.empty());
    }

    void noArgumentsIsOneLinePointingAtHelp()
    {
        const Result r = cli({});
        QCOMPARE(r.status, 2);
        QVERIFY(r.out.empty());
        QCOMPARE(std::count(r.err.begin(), r.err.end(), '\n'), 1L);
        QVERIFY2(r.err.find("amazeballs-cli --help") != std::string::npos, r.err.c_str());
    }

    void helpListsEveryCommand()
    {
        for (const char* asked : {"--help", "-h", "help"}) {
            const Result r = cli({asked});
            QCOMPARE(r.status, 0);
            for (const std::string& name : ab::cli::commandNames())
                QVERIFY2(r.out.find("  " + name) != std::string::npos, name.c_str());
        }
    }

    // help COMMAND, COMMAND --help and COMMAND SCENE --help print the same usage, and it
    // names every option the command's parser takes, with the defaults the table gives.
    void everyWayOfAskingGivesTheCommandsUsageWithItsOptions()
    {
        for (const ab::cli::CommandSpec& c : ab::cli::commandTable()) {
            const Result help = cli({"help", c.name});
            QCOMPARE(help.status, 0);
            QVERIFY(help.err.empty());
            QVERIFY2(help.out.rfind("usage: amazeballs-cli " + c.name, 0) == 0, help.out.c_str());
            const Result dashed = cli({c.name, "--help"});
            QCOMPARE(dashed.status, 0);
            QCOMPARE(dashed.out, help.out);
            const std::unique_ptr<CLI::App> parser = ab::cli::makeParser(c);
            for (const CLI::Option* o : parser->get_options())
                for (const std::string& name : o->get_lnames())
                    QVERIFY2(help.out.find("--" + name) != std::string::npos, (c.name + " --" + name).c_str());
            const std::string flowed = QString::fromStdString(help.out).simplified().toStdString(); // unwrapped
            for (const ab::cli::OptionSpec& o : c.options)
                if (!o.fallback.empty())
                    QVERIFY2(flowed.find("(default: " + o.fallback + ")") != std::string::npos,
                             (c.name + " --" + o.name).c_str());
        }
        const Result withScene = cli({"run", "bounce1d", "--help"});
        QCOMPARE(withScene.status, 0);
        QCOMPARE(withScene.out, cli({"help", "run"}).out);
        QVERIFY(withScene.out.find("--steps N") != std::string::npos);
        QVERIFY(withScene.out.find("in the scene's time unit") != std::string::npos); // units
    }

    void misspeltNamesGetTheNearestInTheSameLine_data()
    {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("says");
        QTest::newRow("command") << QStringList{"rnu"} << "unknown command 'rnu' (did you mean run?)";
        QTest::newRow("help's command") << QStringList{"help", "chrat"} << "did you mean chart?";
        QTest::newRow("program option") << QStringList{"--verison"}
                                        << "unknown option '--verison' (did you mean --version?)";
        QTest::newRow("option cut short") << QStringList{"run", "bounce1d", "--ste", "5"} << "--steps";
        QTest::newRow("option with its value")
            << QStringList{"run", "bounce1d", "--sumary=1"} << "unknown option '--sumary' (did you mean --summary?)";
        QTest::newRow("scene") << QStringList{"run", "bounxe1d"} << "unknown scene 'bounxe1d' (did you mean bounce1d?)";
        QTest::newRow("study's scene") << QStringList{"study", "box3", "--quiet"} << "did you mean box3d?";
        QTest::newRow("parameter") << QStringList{"run", "bounce1d", "--set", "kk=1"}
                                   << "unknown parameter 'kk' for bounce1d (did you mean k?)";
        QTest::newRow("model") << QStringList{"run", "bounce1d", "--model", "physicl"}
                               << "--model: unknown value 'physicl' (did you mean physical?)";
        QTest::newRow("integrator") << QStringList{"run", "box3d", "--integrator", "verlte"}
                                    << "--integrator: unknown value 'verlte' (did you mean verlet?)";
        QTest::newRow("impacts") << QStringList{"run", "box3d", "--impacts", "step_end"} << "did you mean step-end?";
        QTest::newRow("bench model") << QStringList{"bench", "--model", "reprot"} << "did you mean report?";
        QTest::newRow("compare's model") << QStringList{"chart", "box3d",      "--chart",   "energy",
                                                        "--out", "/tmp/x.png", "--compare", "phsyical"}
                                         << "did you mean physical?";
        QTest::newRow("flag given a value")
            << QStringList{"run", "bounce1d", "--summary=yes"} << "--summary: takes no value";
        QTest::newRow("far from every name") << QStringList{"run", "bounce1d", "--set", "zz=1"}
                                             << "unknown parameter 'zz' for bounce1d (amazeballs-cli list names them)";
        QTest::newRow("value far from every choice")
            << QStringList{"run", "box3d", "--model", "magic"} << "(choose report, physical)";
    }

    void misspeltNamesGetTheNearestInTheSameLine()
    {
        QFETCH(QStringList, args);
        QFETCH(QString, says);
        const Result r = cli(toStd(args));
        QCOMPARE(r.status, 2);
        QVERIFY(r.out.empty());
        QCOMPARE(std::count(r.err.begin(), r.err.end(), '\n'), 1L);
        QVERIFY2(QString::fromStdString(r.err).contains(says), r.err.c_str());
    }

    void editDistanceCountsInsertionsDeletionsSubstitutionsAndSwaps()
    {
        QCOMPARE(ab::cli::editDistance("kitten", "sitting"), std::size_t(3)); // 2 substitutions, 1 insertion
        QCOMPARE(ab::cli::editDistance("physicl", "physical"), std::size_t(1));
        QCOMPARE(ab::cli::editDistance("ca", "ac"), std::size_t(1)); // one swap, not two substitutions
        QCOMPARE(ab::cli::editDistance("", "abc"), std::size_t(3));
        QCOMPARE(ab::cli::editDistance("same", "same"), std::size_t(0));
    }

    void aSuggestionNeedsToBeNear()
    {
        const std::vector<std::string> names{"g", "k", "y0", "v0", "max_bounces"};
        QCOMPARE(ab::cli::nearest("kk", names), std::vector<std::string>{"k"});
        QVERIFY(ab::cli::nearest("zz", names).empty()); // two edits from "g": half the word
        QCOMPARE(ab::cli::nearest("max", names), std::vector<std::string>{"max_bounces"}); // cut short
        QVERIFY(ab::cli::nearest(std::string(200, 'x'), names).empty());
    }

    void anOptionGivenTwiceKeepsTheLastAndRepeatableOnesKeepAll()
    {
        const ab::cli::Parsed p = ab::cli::parseCommand(
            *ab::cli::findCommand("run"), {"bounce1d", "--steps", "3", "--set", "k=0.5", "--steps=4", "--set", "g=1"});
        QCOMPARE(p.positional("SCENE"), std::string("bounce1d"));
        QCOMPARE(*p.integer("steps", 1, 10), 4LL);
        QCOMPARE(p.options("set"), (std::vector<std::string>{"k=0.5", "g=1"}));
        QVERIFY(!p.flag("summary"));
        // "--" ends the options: what follows is the operand even where it looks like one.
        const Result r = cli({"run", "--steps", "2", "--", "bounce1d"});
        QCOMPARE(r.status, 0);
        QCOMPARE(std::count(r.out.begin(), r.out.end(), '\n'), 4L); // header and 3 states
    }
};

QTEST_GUILESS_MAIN(CliHelp)
#include "test_cli_help.moc"
