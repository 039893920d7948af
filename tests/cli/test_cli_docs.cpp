// SPDX-License-Identifier: MIT
// The man pages and shell completions the build generates: every option the parsers know
// is in them, the pages render without a warning, and bash and zsh complete what the tables
// hold.
#include "support/cli_runner.h"

#include "app/cli/command_table.h"
#include "app/cli/docgen.h"
#include "app/cli/parser.h"
#include "app/window_options.h"

#include "core/scene.h"

#ifdef AB_WINDOW_PATH
#include "ui/theme/theme.h"
#endif

#include <CLI/CLI.hpp>
#include <QProcess>
#include <QRegularExpression>
#include <QtTest>

namespace {

using testing::readFile;

const std::string kDocs = AB_DOCS_DIR;

bool found(const char* program)
{
    const std::string path = program;
    return !path.empty() && path.find("NOTFOUND") == std::string::npos;
}

// Every long option name of the parser, as "--name".
std::vector<std::string> longNames(const CLI::App& app)
{
    std::vector<std::string> names;
    for (const CLI::Option* o : app.get_options())
        for (const std::string& n : o->get_lnames())
            names.push_back("--" + n);
    return names;
}

// What bash's completion function offers for the words (the last one being completed).
QStringList complete(const std::string& script, const std::string& function, const QStringList& words)
{
    QString line;
    for (const QString& w : words)
        line += " '" + w + "'";
    const QString program = QString::fromStdString("source '" + script + "'; COMP_WORDS=(") + line +
                            "); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); " + QString::fromStdString(function) +
                            "; printf '%s\\n' \"${COMPREPLY[@]}\"";
    QProcess bash;
    bash.start(AB_BASH, {"--norc", "-c", program});
    if (!bash.waitForFinished(20000) || bash.exitCode() != 0)
        qWarning() << bash.readAllStandardError();
    return QString::fromUtf8(bash.readAllStandardOutput()).split('\n', Qt::SkipEmptyParts);
}

// What zsh's completion system offers for the words, sorted (tests/cli/zsh_complete.zsh).
QStringList zshComplete(const QStringList& words)
{
    QProcess zsh;
    zsh.start(AB_ZSH, QStringList{"-f", AB_ZSH_COMPLETE, QString::fromStdString(kDocs + "/zsh")} + words);
    if (!zsh.waitForFinished(30000))
        zsh.kill();
    QStringList offered = QString::fromUtf8(zsh.readAllStandardOutput()).split('\n', Qt::SkipEmptyParts);
    offered.sort();
    offered.removeDuplicates();
    return offered;
}

std::string roffOption(const std::string& dashed)
{
    return ab::cli::roff(dashed);
}

} // namespace

class CliDocs : public QObject {
    Q_OBJECT

private slots:
    void everyOptionOfAmazeballsCliIsInTheManPageAndBothCompletions()
    {
        const std::string man = readFile(kDocs + "/man/amazeballs-cli.1");
        const std::string bash = readFile(kDocs + "/bash/amazeballs-cli");
        const std::string zsh = readFile(kDocs + "/zsh/_amazeballs-cli");
        QVERIFY(!man.empty() && !bash.empty() && !zsh.empty());
        for (const std::string& name : longNames(*ab::cli::makeTopLevelParser())) {
            QVERIFY2(man.find("\\fB" + roffOption(name) + "\\fR") != std::string::npos, name.c_str());
            QVERIFY2(bash.find(" " + name) != std::string::npos, name.c_str());
            QVERIFY2(zsh.find(name) != std::string::npos, name.c_str());
        }
        for (const ab::cli::CommandSpec& c : ab::cli::commandTable()) {
            QVERIFY2(man.find(".SS \"" + ab::cli::roff(c.synopsis()) + "\"") != std::string::npos, c.name.c_str());
            QVERIFY2(bash.find("    " + c.name + ") options=") != std::string::npos, c.name.c_str());
            QVERIFY2(zsh.find("  " + c.name + ")\n") != std::string::npos, c.name.c_str());
            // The man page lists the command's options under its own heading.
            const std::size_t section = man.find(".SS \"" + ab::cli::roff(c.synopsis()) + "\"");
            const std::size_t next = man.find(".S", section + 4);
            const std::string own = man.substr(section, next - section);
            for (const std::string& name : longNames(*ab::cli::makeParser(c))) {
                const std::string what = c.name + " " + name;
                QVERIFY2(own.find("\\fB" + roffOption(name) + "\\fR") != std::string::npos, what.c_str());
                QVERIFY2(bash.find(" " + name) != std::string::npos, what.c_str());
                QVERIFY2(zsh.find("'" + name + "[") != std::string::npos ||
                             zsh.find("'*" + name + "[") != std::string::npos || name == "--help",
                         what.c_str());
            }
        }
    }

    // The window's options as its own parser lists them (amazeballs --help, no display).
    void everyOptionOfTheWindowIsInItsManPageAndBothCompletions()
    {
#ifndef AB_WINDOW_PATH
        QSKIP("the window is not built");
#else
        QProcess window;
        window.start(AB_WINDOW_PATH, {"--help"});
        QVERIFY(window.waitForFinished(30000));
        QCOMPARE(window.exitCode(), 0);
        const QString help = QString::fromUtf8(window.readAllStandardOutput());
        QStringList names;
        for (const QRegularExpressionMatch& m : QRegularExpression(R"((?:^|[ ,])(--[a-z][a-z-]+))").globalMatch(help))
            names << m.captured(1);
        names.removeDuplicates();
        QVERIFY2(names.size() >= int(ab::app::windowOptions().size()) + 2, qPrintable(help));
        const std::string man = readFile(kDocs + "/man/amazeballs.1");
        const std::string bash = readFile(kDocs + "/bash/amazeballs");
        const std::string zsh = readFile(kDocs + "/zsh/_amazeballs");
        for (const QString& n : names) {
            const std::string name = n.toStdString();
            QVERIFY2(man.find("\\fB" + roffOption(name) + "\\fR") != std::string::npos, name.c_str());
            QVERIFY2(bash.find(" " + name) != std::string::npos || bash.find("\"" + name) != std::string::npos,
                     name.c_str());
            QVERIFY2(zsh.find(name + "[") != std::string::npos, name.c_str());
        }
#endif
    }

    // The window's option table lists --theme's values for the completions: they are the
    // window's themes.
    void theWindowsThemeWordsAreItsThemes()
    {
#ifndef AB_WINDOW_PATH
        QSKIP("the window is not built");
#else
        QStringList themes;
        for (ab::ui::Theme t : ab::ui::allThemes())
            themes << ab::ui::themeKey(t);
        for (const ab::app::WindowOption& w : ab::app::windowOptions())
            if (std::string(w.name) == "theme")
                QCOMPARE(QString::fromLatin1(w.words).split(' '), themes);
#endif
    }

    void theManPagesListEverySceneParameter()
    {
        for (const char* page : {"/man/amazeballs-cli.1", "/man/amazeballs.1"}) {
            const std::string man = readFile(kDocs + page);
            for (const ab::SceneInfo* s : ab::allScenes())
                for (const ab::ParamSpec& p : s->params)
                    QVERIFY2(man.find(".B " + ab::cli::roff(p.key) + "\n") != std::string::npos, p.key.c_str());
        }
    }

    void theManPagesRenderWithoutWarnings()
    {
        if (!found(AB_GROFF))
            QSKIP("groff is not installed (Debian: groff-base)");
        for (const char* page : {"/man/amazeballs-cli.1", "/man/amazeballs.1"}) {
            QProcess groff;
            groff.start(AB_GROFF, {"-man", "-Tutf8", "-ww", "-z", QString::fromStdString(kDocs + page)});
            QVERIFY(groff.waitForFinished(30000));
            QCOMPARE(groff.exitCode(), 0);
            const QByteArray warnings = groff.readAllStandardError();
            QVERIFY2(warnings.isEmpty(), warnings.constData());
        }
    }

    void bashCompletesCommandsOptionsScenesAndEachScenesParameters()
    {
        if (!found(AB_BASH))
            QSKIP("bash is not installed");
        const std::string cli = kDocs + "/bash/amazeballs-cli";
        QCOMPARE(complete(cli, "_amazeballs_cli", {"amazeballs-cli", "ch"}), QStringList{"chart"});
        QCOMPARE(complete(cli, "_amazeballs_cli", {"amazeballs-cli", "run", "bounce1d", "--ste"}),
                 QStringList{"--steps"});
        QCOMPARE(complete(cli, "_amazeballs_cli", {"amazeballs-cli", "run", "b"}), (QStringList{"bounce1d", "box3d"}));
        QCOMPARE(complete(cli, "_amazeballs_cli", {"amazeballs-cli", "run", "box3d", "--model", ""}),
                 (QStringList{"report", "physical"}));
        QCOMPARE(complete(cli, "_amazeballs_cli", {"amazeballs-cli", "help", "st"}),
                 (QStringList{"stability", "study"}));
        // After --set: the names of the scene on the line, each ready for its value.
        for (const ab::SceneInfo* s : ab::allScenes()) {
            QStringList expected;
            for (const ab::ParamSpec& p : s->params)
                expected << QString::fromStdString(p.key + "=");
            QCOMPARE(complete(cli, "_amazeballs_cli",
                              {"amazeballs-cli", "run", QString::fromStdString(s->key), "--set", ""}),
                     expected);
        }
        QCOMPARE(complete(cli, "_amazeballs_cli", {"amazeballs-cli", "chart", "box3d", "--preset", "box"}),
                 (QStringList{"box3d-report", "box3d-backspin-bounce", "box3d-sliding-to-rolling",
                              "box3d-superball-table", "box3d-tunnelling"}));
        const std::string window = kDocs + "/bash/amazeballs";
        QCOMPARE(complete(window, "_amazeballs", {"amazeballs", "--the"}), QStringList{"--theme"});
        QCOMPARE(complete(window, "_amazeballs", {"amazeballs", "--scene", "two"}), QStringList{"two-balls"});
    }

    void zshCompletesCommandsOptionsScenesAndEachScenesParameters()
    {
        if (!found(AB_ZSH))
            QSKIP("zsh is not installed");
        QCOMPARE(zshComplete({"amazeballs-cli", "ch"}), QStringList{"chart"});
        QStringList commands;
        for (const std::string& name : ab::cli::commandNames())
            commands << QString::fromStdString(name);
        commands << "--help"
                 << "--version";
        commands.sort();
        QCOMPARE(zshComplete({"amazeballs-cli", ""}), commands);
        QCOMPARE(zshComplete({"amazeballs-cli", "run", "bounce1d", "--ste"}), QStringList{"--steps"});
        QCOMPARE(zshComplete({"amazeballs-cli", "run", "box3d", "--model", ""}), (QStringList{"physical", "report"}));
        QCOMPARE(zshComplete({"amazeballs-cli", "help", "st"}), (QStringList{"stability", "study"}));
        for (const ab::SceneInfo* s : ab::allScenes()) {
            QStringList expected;
            for (const ab::ParamSpec& p : s->params)
                expected << QString::fromStdString(p.key);
            expected.sort();
            QCOMPARE(zshComplete({"amazeballs-cli", "run", QString::fromStdString(s->key), "--set", ""}), expected);
        }
        QCOMPARE(zshComplete({"amazeballs", "--the"}), QStringList{"--theme"});
        QCOMPARE(zshComplete({"amazeballs", "--scene", "two"}), QStringList{"two-balls"});
    }
};

QTEST_GUILESS_MAIN(CliDocs)
#include "test_cli_docs.moc"
