// SPDX-License-Identifier: MIT
// amazeballs: the window.
// `amazeballs [FILE.json] [--preset NAME|FILE] [--scene KEY] [--set NAME=VALUE]... [--speed X]
//  [--play] [--threads N] [--measure-frames S] [--fresh] [--lecture] [--theme KEY]
//  [--compare MODEL[:INTEGRATOR[:IMPACTS]]]`.
#include "cli/suggest.h"
#include "frame_measure.h"
#include "window_options.h"

#include "ui/i18n/language.h"
#include "ui/main_window.h"
#include "ui/presets/preset_actions.h"
#include "ui/settings/window_settings.h"
#include "ui/shell/window_shell.h"
#include "ui/theme/theme.h"

#include "core/io/atomic_file.h"
#include "core/io/preset.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QIcon>
#include <QLocale>
#include <QScreen>
#include <QSettings>
#include <QSurfaceFormat>

#include <algorithm>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace {

// --compare MODEL[:INTEGRATOR[:IMPACTS]], each part a core key.
ab::RunVariant parseCompare(const QString& text)
{
    const QStringList parts = text.split(':');
    auto fail = [&](const QString& why) {
        throw ab::InputError(QStringLiteral("--compare: %1").arg(why).toStdString());
    };
    if (parts.size() > 3)
        fail(QApplication::translate("main", "'%1' has more than MODEL:INTEGRATOR:IMPACTS").arg(text));
    ab::RunVariant v;
    const auto model = ab::parseModel(parts[0].toStdString());
    if (!model)
        fail(QApplication::translate("main", "unknown model '%1'").arg(parts[0]));
    v.model = *model;
    if (parts.size() > 1) {
        const auto integrator = ab::parseIntegrator(parts[1].toStdString());
        if (!integrator)
            fail(QApplication::translate("main", "unknown integrator '%1'").arg(parts[1]));
        v.integrator = *integrator;
    }
    if (parts.size() > 2) {
        const auto impacts = ab::parseImpactMode(parts[2].toStdString());
        if (!impacts)
            fail(QApplication::translate("main", "unknown impact mode '%1'").arg(parts[2]));
        v.impacts = *impacts;
    }
    return v;
}

} // namespace

namespace {

// Qt's own options, which QApplication takes out of argv (-platform offscreen, -style ...):
// the early parse, made before QApplication, lets them through.
QStringList withoutQtOptions(const QStringList& args)
{
    static const QStringList withValue{
        "platform",        "platformpluginpath", "platformtheme", "plugin",  "qmljsdebugger",
        "qwindowgeometry", "qwindowicon",        "qwindowtitle",  "session", "display",
        "style",           "stylesheet",         "geometry",      "title",   "name"};
    static const QStringList flags{"reverse", "widgetcount", "nograb", "dograb", "sync"};
    QStringList kept;
    for (qsizetype i = 0; i < args.size(); ++i) {
        const QString& a = args[i];
        if (i > 0 && a.startsWith('-') && !a.startsWith(QLatin1String("--"))) {
            const QString name = a.mid(1);
            if (withValue.contains(name)) {
                ++i; // and its value
                continue;
            }
            if (flags.contains(name))
                continue;
        }
        kept.push_back(a);
    }
    return kept;
}

// A message on one line: no control character of the user's text reaches the terminal.
std::string oneLine(const std::string& text)
{
    std::string out;
    for (const char c : text) {
        const auto u = static_cast<unsigned char>(c);
        if (u < 0x20 || u == 0x7F) {
            char buf[8];
            std::snprintf(buf, sizeof buf, "\\x%02x", unsigned(u));
            out += buf;
        } else {
            out += c;
        }
    }
    return out;
}

// The window's options, read and checked before any window (or display) exists.
struct Options {
    std::optional<ab::Preset> preset;
    std::optional<ab::SceneId> scene;
    QStringList sets;
    std::optional<ab::RunVariant> compare;
    std::optional<double> speed, measureSeconds;
    std::optional<int> threads;
    std::optional<ab::ui::Theme> theme;
    bool play = false, fresh = false, lecture = false;
};

// A --set checked against the stage it is for, or, with no stage named, against the first
// stage that has the parameter (the window checks it again against its stage). A name no
// stage has is named with the nearest names, as amazeballs-cli names it.
void checkAssignment(const QString& assignment, std::optional<ab::SceneId> scene)
{
    const std::string text = assignment.toStdString();
    const std::string name(ab::assignmentName(text));
    const QString printed = QString::fromStdString(ab::printableInput(name));
    const auto unknown = [&](const std::vector<std::string>& names, QString why) {
        const std::vector<std::string> near = ab::cli::nearest(name, names);
        why += near.empty()
                   ? QApplication::translate("main", " (man amazeballs lists them)")
                   : QApplication::translate("main", " (did you mean %1?)").arg(QString::fromStdString(near.front()));
        return ab::InputError(why.toStdString());
    };
    if (scene) {
        const ab::SceneInfo& info = ab::sceneInfo(*scene);
        if (!name.empty() && !ab::RunSpec(*scene).params.indexOf(name))
            throw unknown(info.paramKeys(), QApplication::translate("main", "--set: unknown parameter '%1' for %2")
                                                .arg(printed, QString::fromStdString(info.key)));
        ab::RunSpec(*scene).params.parseAssignment(text);
        return;
    }
    std::vector<std::string> all;
    for (const ab::SceneInfo* info : ab::allScenes()) {
        ab::RunSpec spec(info->id);
        if (!name.empty() && spec.params.indexOf(name)) {
            spec.params.parseAssignment(text);
            return;
        }
        for (const std::string& key : info->paramKeys())
            if (std::find(all.begin(), all.end(), key) == all.end())
                all.push_back(key);
    }
    if (!name.empty())
        throw unknown(all, QApplication::translate("main", "--set: no stage has a parameter '%1'").arg(printed));
    ab::RunSpec(ab::allScenes().front()->id).params.parseAssignment(text); // names what is wrong
}

std::vector<std::string> sceneKeys()
{
    std::vector<std::string> keys;
    for (const ab::SceneInfo* info : ab::allScenes())
        keys.push_back(info->key);
    return keys;
}

// " (did you mean --steps?)" for the nearest of `names` to a misspelt `word`, or nothing.
QString suggestion(const QString& word, const std::vector<std::string>& names, const char* prefix)
{
    const std::vector<std::string> near = ab::cli::nearest(word.toStdString(), names);
    if (near.empty())
        return {};
    return QApplication::translate("main", " (did you mean %1?)").arg(QString::fromStdString(prefix + near.front()));
}

// Reads the options; returns an exit status when the program ends here (--help,
// --version: 0; a bad option or preset: 2, with one line on stderr).
std::optional<int> readOptions(const QStringList& arguments, Options& o)
{
    QCommandLineParser parser;
    parser.setApplicationDescription(QApplication::translate("main", "Bouncing and colliding balls, stage by stage."));
    const QCommandLineOption helpOption = parser.addHelpOption();
    const QCommandLineOption versionOption = parser.addVersionOption();
    for (const ab::app::WindowOption& w : ab::app::windowOptions())
        parser.addOption(QCommandLineOption(QString::fromLatin1(w.name), QApplication::translate("main", w.help),
                                            QString::fromLatin1(w.value)));
    parser.addPositionalArgument("FILE.json", QApplication::translate("main", "A preset file to open."), "[FILE.json]");
    auto fail = [](const QString& why) {
        std::fprintf(stderr, "amazeballs: %s\n", oneLine(why.toStdString()).c_str());
        return 2;
    };
    if (!parser.parse(withoutQtOptions(arguments))) {
        std::vector<std::string> names{"help", "help-all", "version"};
        for (const ab::app::WindowOption& w : ab::app::windowOptions())
            names.emplace_back(w.name);
        const QStringList unknown = parser.unknownOptionNames();
        const QString near = unknown.isEmpty() ? QString() : suggestion(unknown.front(), names, "--");
        QString why = parser.errorText();
        if (!near.isEmpty() && why.endsWith('.'))
            why.chop(1); // "Unknown option 'sceen' (did you mean --scene?)"
        return fail(why + near);
    }
    if (parser.isSet(helpOption)) {
        std::fputs(qPrintable(parser.helpText()), stdout);
        return std::fflush(stdout) == 0 && !std::ferror(stdout) ? 0 : 4;
    }
    if (parser.isSet(versionOption)) {
        std::printf("amazeballs %s\n", PROJECT_VERSION_TEXT);
        return std::fflush(stdout) == 0 && !std::ferror(stdout) ? 0 : 4;
    }
    try {
        const QStringList files = parser.positionalArguments();
        if (files.size() > 1 || (files.size() == 1 && parser.isSet(QStringLiteral("preset"))))
            throw ab::InputError(
                QApplication::translate("main", "give one preset: a FILE.json or --preset NAME|FILE").toStdString());
        if (!files.isEmpty() || parser.isSet(QStringLiteral("preset"))) {
            if (parser.isSet(QStringLiteral("scene")))
                throw ab::InputError(
                    QApplication::translate("main", "--scene: a preset names its own stage; give one or the other")
                        .toStdString());
            o.preset = ab::loadPreset(
                (files.isEmpty() ? parser.value(QStringLiteral("preset")) : files.front()).toStdString());
            o.scene = o.preset->scene;
        }
        if (parser.isSet(QStringLiteral("scene"))) {
            const ab::SceneInfo* scene = ab::findScene(parser.value(QStringLiteral("scene")).toStdString());
            if (!scene)
                throw ab::InputError((QApplication::translate("main", "--scene: unknown scene '%1'")
                                          .arg(parser.value(QStringLiteral("scene"))) +
                                      suggestion(parser.value(QStringLiteral("scene")), sceneKeys(), ""))
                                         .toStdString());
            o.scene = scene->id;
        }
        o.sets = parser.values(QStringLiteral("set"));
        for (const QString& assignment : o.sets)
            checkAssignment(assignment, o.scene);
        if (parser.isSet(QStringLiteral("compare")))
            o.compare = parseCompare(parser.value(QStringLiteral("compare")));
        if (parser.isSet(QStringLiteral("speed"))) {
            o.speed = ab::parseReal(parser.value(QStringLiteral("speed")).toStdString(), "--speed");
            if (*o.speed < 0.1 || *o.speed > 10.0)
                throw ab::InputError(QApplication::translate("main", "--speed: %1 is outside [0.1, 10]")
                                         .arg(QString::fromStdString(ab::formatNumber(*o.speed)))
                                         .toStdString());
        }
        if (parser.isSet(QStringLiteral("threads"))) {
            const long long threads =
                ab::parseInteger(parser.value(QStringLiteral("threads")).toStdString(), "--threads");
            if (threads < 1 || threads > ab::kMaxThreads)
                throw ab::InputError(QApplication::translate("main", "--threads: %1 is outside [1, %2]")
                                         .arg(threads)
                                         .arg(ab::kMaxThreads)
                                         .toStdString());
            o.threads = static_cast<int>(threads);
        }
        if (parser.isSet(QStringLiteral("measure-frames"))) {
            // Bounded: a measurement is at most an hour (a timer counts int milliseconds).
            o.measureSeconds =
                ab::parseReal(parser.value(QStringLiteral("measure-frames")).toStdString(), "--measure-frames");
            if (!(*o.measureSeconds >= 1.0 && *o.measureSeconds <= 3600.0))
                throw ab::InputError(
                    QApplication::translate("main", "--measure-frames: %1 is outside [1, 3600] seconds")
                        .arg(QString::fromStdString(ab::formatNumber(*o.measureSeconds)))
                        .toStdString());
        }
        if (parser.isSet(QStringLiteral("theme"))) {
            o.theme = ab::ui::parseTheme(parser.value(QStringLiteral("theme")));
            if (!o.theme)
                throw ab::InputError(QApplication::translate("main", "--theme: unknown theme '%1'")
                                         .arg(parser.value(QStringLiteral("theme")))
                                         .toStdString());
        }
    } catch (const ab::InputError& e) {
        return fail(QString::fromStdString(e.what()));
    }
    o.play = parser.isSet(QStringLiteral("play"));
    o.fresh = parser.isSet(QStringLiteral("fresh"));
    o.lecture = parser.isSet(QStringLiteral("lecture"));
    return std::nullopt;
}

void setApplicationNames()
{
    QCoreApplication::setApplicationName("Amazeballs");
    QCoreApplication::setOrganizationName("Amazeballs");
    QCoreApplication::setApplicationVersion(QStringLiteral(PROJECT_VERSION_TEXT));
}

// What the options ask of the window, in order; false (with one line said) when the window
// refuses a value.
bool applyOptions(ab::ui::WindowShell& shell, ab::ui::MainWindow& window, const Options& o)
{
    try {
        if (o.preset)
            ab::ui::applyPresetToWindow(window, *o.preset);
        else if (o.scene)
            window.showScene(*o.scene);
        if (!o.sets.isEmpty()) {
            ab::ParamValues values = window.controller().spec().params;
            for (const QString& assignment : o.sets)
                values.parseAssignment(assignment.toStdString());
            if (!window.applyValues(values))
                throw ab::InputError(
                    QApplication::translate("main", "--set: the values were refused (see the window's status bar)")
                        .toStdString());
        }
        if (o.compare) {
            ab::ui::RunOptions options = window.options();
            options.compare = *o.compare;
            if (!window.applyOptions(options))
                throw ab::InputError(QApplication::translate("main", "--compare: refused: %1")
                                         .arg(window.runOptions()->errorText())
                                         .toStdString());
        }
        if (o.speed)
            window.controller().setSpeed(*o.speed);
        if (o.theme)
            shell.setTheme(*o.theme);
    } catch (const ab::InputError& e) {
        std::fprintf(stderr, "amazeballs: %s\n", oneLine(e.what()).c_str());
        return false;
    }
    return true;
}

} // namespace

int main(int argc, char** argv)
{
    // A file being saved is removed, not left half-written, when the program is ended by a
    // signal (core/io/atomic_file.h).
    ab::removeTempFilesOnSignals(true);

    // The options are read before the window's application exists, so that --help,
    // --version and a bad option need no display.
    Options options;
    {
        QCoreApplication early(argc, argv);
        setApplicationNames();
        ab::ui::installLanguage(ab::ui::languageForLocale(QLocale::system()));
        if (const auto status = readOptions(QCoreApplication::arguments(), options))
            return *status;
    }

    // Every GL context the window makes is OpenGL 3.3 core (the view's shaders need it).
    QSurfaceFormat format;
    format.setVersion(3, 3);
    format.setProfile(QSurfaceFormat::CoreProfile);
    format.setDepthBufferSize(24);
    QSurfaceFormat::setDefaultFormat(format);

    QApplication app(argc, argv);
    setApplicationNames();
    QApplication::setDesktopFileName("amazeballs");
    QApplication::setWindowIcon(QIcon(":/icons/amazeballs.svg"));
    ab::ui::installLanguage(ab::ui::languageForLocale(QLocale::system())); // the Language menu changes it

    if (options.threads) // before the first run is built
        ab::ui::RunController::setEngineThreads(*options.threads);
    ab::ui::WindowShell shell;
    ab::ui::MainWindow& window = shell.window(); // replaced by a language switch: use only before it
    QSettings store;
    bool placed = false;
    if (!options.fresh) {
        // Each window remembers from its start; a language switch carries the setup over,
        // so the rebuilt window only needs a new recorder.
        auto remember = [&app, &store](ab::ui::MainWindow& w) {
            auto* settings = new ab::ui::WindowSettings(w, store); // owned by the window
            QObject::connect(&app, &QCoreApplication::aboutToQuit, settings, &ab::ui::WindowSettings::save);
            return settings;
        };
        ab::ui::WindowSettings* settings = remember(window);
        placed = settings->restore();
        for (const QString& skipped : settings->skipped())
            std::fprintf(stderr, "amazeballs: %s %s\n",
                         qPrintable(QApplication::translate("main", "a remembered setup was skipped:")),
                         qPrintable(skipped));
        QObject::connect(&shell, &ab::ui::WindowShell::windowReplaced, &shell,
                         [remember](ab::ui::MainWindow* w) { remember(*w); });
    }
    if (!applyOptions(shell, window, options))
        return 2;
    if (!placed) // a first start: as large as the screen's free area allows, up to 1400 x 900
        window.setGeometry(ab::ui::WindowSettings::firstStartGeometry(window.screen()->availableGeometry()));
    window.show();
    if (options.lecture)
        shell.lecture().setActive(true);
    if (options.measureSeconds)
        ab::app::measureFrames(window, *options.measureSeconds);
    else if (options.play)
        window.controller().play();
    return app.exec();
}
