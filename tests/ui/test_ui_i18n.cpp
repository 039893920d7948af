// SPDX-License-Identifier: MIT
// The Swedish translation: every string of the core's tables that the window shows is
// listed for lupdate and translated; the .ts has no unfinished or obsolete entry; and in
// Swedish no visible text of the main window (widgets, menus, actions, tooltips, chart
// titles, the navigator of every stage) is left as its English source. A text may stay
// the same only when all its words are names that read the same in both languages (the
// contract's keys, symbols, "Euler", "CSV", ...). Failures list the offending strings.
#include "ui/charts/motion_chart.h"
#include "ui/i18n/core_text.h"
#include "ui/i18n/language.h"
#include "ui/main_window.h"
#include "ui/panels/chart_panel.h"
#include "ui/panels/stage_navigator.h"
#include "ui/panels/status_readout.h"
#include "ui/shell/window_shell.h"

#include <QAbstractAxis>
#include <QAbstractButton>
#include <QAbstractSeries>
#include <QChartView>
#include <QComboBox>
#include <QFile>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QMenu>
#include <QMenuBar>
#include <QRegularExpression>
#include <QStatusBar>
#include <QTabBar>
#include <QXmlStreamReader>
#include <QtTest>

#include <map>
#include <set>

using ab::SceneId;
using ab::ui::Language;

namespace {

// Words that read the same in English and Swedish: the contract's keys and symbols
// (tokens of three or more letters), proper names, file types, key names.
const std::set<QString>& sameInBothLanguages()
{
    static const std::set<QString> words = [] {
        std::set<QString> w{"Amazeballs", "Ctrl",  "Shift",  "Home", "Euler",   "Explicit",   "Implicit",
                            "Runge",      "Kutta", "Verlet", "Zeno", "Hertz",   "Integrator", "OpenGL",
                            "WebGL",      "CSV",   "PNG",    "SVG",  "English", "Svenska",    "position",
                            "Position",   "sqrt",  "Walton", "rad"};
        auto addTokens = [&w](std::string_view key) {
            const QString s = QString::fromUtf8(key.data(), qsizetype(key.size()));
            for (const QString& token : s.split(QRegularExpression("[^A-Za-z0-9_]+"), Qt::SkipEmptyParts))
                w.insert(token);
        };
        for (const ab::SceneInfo* s : ab::allScenes()) {
            addTokens(s->key);
            for (const ab::ParamSpec& p : s->params) {
                addTokens(p.key);
                addTokens(p.symbol);
            }
        }
        for (ab::Integrator i : ab::allIntegrators())
            addTokens(ab::integratorKey(i));
        for (ab::ModelKind m : ab::allModels())
            addTokens(ab::modelKey(m));
        for (ab::ImpactMode m : {ab::ImpactMode::Located, ab::ImpactMode::StepEnd})
            addTokens(ab::impactModeKey(m));
        return w;
    }();
    return words;
}

// True when `text` needs no translation: no word of three letters or more outside the
// names above (HTML tags and %1 placeholders are not words).
bool readsTheSame(QString text)
{
    text.remove(QRegularExpression("<[^>]*>"));
    text.remove(QRegularExpression("&[a-z]+;"));
    text.remove(QRegularExpression("%[0-9]"));
    text.remove('&'); // mnemonics
    static const QRegularExpression word("[A-Za-z0-9_]+");
    for (auto it = word.globalMatch(text); it.hasNext();) {
        const QString w = it.next().captured();
        int letters = 0;
        for (QChar c : w)
            letters += c.isLetter() ? 1 : 0;
        if (letters >= 3 && !sameInBothLanguages().count(w))
            return false;
    }
    return true;
}

// Every visible text of the window, keyed by where it is (the path of object names and
// child indices), so that the same place can be compared in two languages.
using Texts = std::map<QString, QString>;

QString pathOf(const QObject* o)
{
    QStringList parts;
    for (; o; o = o->parent()) {
        const QObject* p = o->parent();
        const int index = p ? int(p->children().indexOf(const_cast<QObject*>(o))) : 0;
        parts.prepend(
            QStringLiteral("%1:%2#%3")
                .arg(QString::fromLatin1(o->metaObject()->className()), o->objectName(), QString::number(index)));
    }
    return parts.join('/');
}

void put(Texts& out, const QString& where, const QString& text)
{
    if (!text.trimmed().isEmpty())
        out[where] = text;
}

void collectWidget(Texts& out, QWidget* w)
{
    const QString at = pathOf(w);
    put(out, at + " toolTip", w->toolTip());
    if (auto* l = qobject_cast<QLabel*>(w))
        put(out, at + " text", l->text());
    if (auto* b = qobject_cast<QAbstractButton*>(w))
        put(out, at + " text", b->text());
    if (auto* e = qobject_cast<QLineEdit*>(w))
        put(out, at + " placeholder", e->placeholderText());
    if (auto* g = qobject_cast<QGroupBox*>(w))
        put(out, at + " title", g->title());
    if (auto* m = qobject_cast<QMenu*>(w))
        put(out, at + " title", m->title());
    if (auto* c = qobject_cast<QComboBox*>(w))
        for (int i = 0; i < c->count(); ++i)
            put(out, at + QStringLiteral(" item %1").arg(i), c->itemText(i));
    if (auto* v = qobject_cast<QChartView*>(w); v && v->chart()) {
        put(out, at + " chart title", v->chart()->title());
        for (QAbstractAxis* axis : v->chart()->axes())
            put(out, at + " axis " + pathOf(axis), axis->titleText());
        for (QAbstractSeries* s : v->chart()->series())
            put(out, at + " series " + pathOf(s), s->name());
    }
}

Texts collect(QMainWindow& window)
{
    Texts out;
    put(out, "windowTitle", window.windowTitle());
    for (QWidget* w : window.findChildren<QWidget*>())
        collectWidget(out, w);
    for (QAction* a : window.findChildren<QAction*>()) {
        put(out, pathOf(a) + " action", a->text());
        put(out, pathOf(a) + " action toolTip", a->toolTip());
    }
    return out;
}

// The window's texts on every stage, with the navigator's walk off and on.
Texts collectAllStages(ab::ui::MainWindow& window)
{
    Texts all;
    for (const ab::SceneInfo* s : ab::allScenes()) {
        window.showScene(s->id);
        for (bool walking : {false, true}) {
            window.navigator()->setWalking(walking);
            for (auto& [where, text] : collect(window))
                all[QStringLiteral("%1 %2 %3").arg(QString::fromStdString(s->key)).arg(walking).arg(where)] = text;
        }
        window.navigator()->setWalking(false);
    }
    return all;
}

QString listed(const QStringList& items)
{
    return "\n  " + items.join("\n  ");
}

} // namespace

class UiI18n : public QObject {
    Q_OBJECT
private slots:
    void cleanup() { ab::ui::installLanguage(Language::English); }

    void everyShownCoreStringIsListedForLupdate()
    {
        const std::vector<std::string> listedStrings = ab::ui::coreListedStrings();
        const std::set<std::string> known(listedStrings.begin(), listedStrings.end());
        QStringList missing;
        for (const std::string& s : ab::ui::coreDisplayedStrings())
            if (!known.count(s))
                missing << QString::fromStdString(s);
        QVERIFY2(missing.isEmpty(),
                 qPrintable("add these to ui/i18n/core_strings.cpp, then update the translations:" + listed(missing)));
    }

    void everyShownCoreStringHasASwedishTranslation()
    {
        ab::ui::installLanguage(Language::Swedish);
        QStringList untranslated;
        for (const std::string& s : ab::ui::coreDisplayedStrings()) {
            const QString source = QString::fromStdString(s);
            if (ab::ui::coreText(s) == source && !readsTheSame(source))
                untranslated << source;
        }
        QVERIFY2(untranslated.isEmpty(),
                 qPrintable("core strings without a Swedish translation:" + listed(untranslated)));
    }

    void translationFileHasNoUnfinishedOrObsoleteEntries()
    {
        QFile ts(QStringLiteral(AB_SOURCE_DIR "/resources/translations/amazeballs_sv.ts"));
        QVERIFY(ts.open(QIODevice::ReadOnly));
        QXmlStreamReader xml(&ts);
        QString source;
        QStringList bad;
        int messages = 0;
        while (!xml.atEnd()) {
            if (xml.readNext() != QXmlStreamReader::StartElement)
                continue;
            if (xml.name() == QLatin1String("source")) {
                source = xml.readElementText();
            } else if (xml.name() == QLatin1String("translation")) {
                ++messages;
                const QString type = xml.attributes().value("type").toString();
                // Its text, or a plural's forms (numerusform), each of which must be filled in.
                QString text;
                bool emptyForm = false;
                while (xml.readNext() != QXmlStreamReader::EndElement && !xml.hasError()) {
                    if (xml.isCharacters())
                        text += xml.text().trimmed();
                    else if (xml.isStartElement()) {
                        const QString form = xml.readElementText();
                        emptyForm = emptyForm || form.isEmpty();
                        text += form;
                    }
                }
                if (!type.isEmpty() || text.isEmpty() || emptyForm)
                    bad << QStringLiteral("%1 [%2]").arg(source, type.isEmpty() ? QStringLiteral("empty") : type);
            }
        }
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QVERIFY(messages > 200);
        QVERIFY2(bad.isEmpty(), qPrintable("entries to translate in amazeballs_sv.ts:" + listed(bad)));
    }

    void swedishWindowLeavesNoTextInEnglish()
    {
        ab::ui::WindowShell shell;
        const Texts english = collectAllStages(shell.window());
        shell.setLanguage(Language::Swedish); // rebuilds the window in Swedish
        const Texts swedish = collectAllStages(shell.window());
        QStringList untranslated, lost;
        for (const auto& [where, source] : english) {
            const auto it = swedish.find(where);
            if (it == swedish.end()) {
                lost << where;
                continue;
            }
            if (it->second == source && !readsTheSame(source))
                untranslated << QStringLiteral("\"%1\"  (%2)").arg(source, where);
        }
        QVERIFY2(lost.isEmpty(), qPrintable("texts missing from the Swedish window:" + listed(lost)));
        QVERIFY2(untranslated.isEmpty(), qPrintable("English left in the Swedish window:" + listed(untranslated)));
        QVERIFY(english.size() > 100); // the walk did find the window's texts
    }

    void swedishNavigatorShowsNoEnglishCoreText()
    {
        ab::ui::installLanguage(Language::Swedish);
        ab::ui::MainWindow w;
        for (const ab::SceneInfo* s : ab::allScenes()) {
            w.showScene(s->id);
            const QString text = w.navigator()->text();
            QStringList english;
            auto check = [&](const std::string& source) {
                const QString q = QString::fromStdString(source);
                if (!readsTheSame(q) && text.contains(q))
                    english << q;
            };
            check(s->title);
            check(s->summary);
            for (const ab::Equation& e : s->equations)
                check(e.meaning);
            for (const ab::ReportNote& n : s->notes)
                check(n.text);
            for (const char* label : {"Equations", "Notes on the report", "Stage "})
                if (text.contains(QLatin1String(label)))
                    english << QLatin1String(label);
            QVERIFY2(english.isEmpty(), qPrintable(QString::fromStdString(s->key) + ":" + listed(english)));
        }
    }

    void swedishParameterPanelRefusesInSwedish()
    {
        ab::ui::installLanguage(Language::Swedish);
        ab::ui::MainWindow w;
        w.showScene(SceneId::Box3d);
        const double before = w.controller().spec().params.real("k");
        auto* k = w.findChild<QLineEdit*>(QStringLiteral("param-k"));
        auto* error = w.findChild<QLabel*>(QStringLiteral("paramError-k")); // under its field
        QVERIFY(k && error);
        const QStringList typed{QStringLiteral("5"), QStringLiteral("abc")};
        const QStringList expected{QStringLiteral("k: 5 ligger utanför det tillåtna intervallet"),
                                   QStringLiteral("k: 'abc' är inget tal")};
        for (int i = 0; i < typed.size(); ++i) {
            k->setText(typed[i]);
            emit k->editingFinished();
            QVERIFY2(error->text().contains(expected[i]), qPrintable(error->text()));
            QVERIFY2(!error->text().contains(QLatin1String(" is ")), qPrintable(error->text()));
        }
        // The range stays whole on one line in a narrow column: "[0, 1]" with a no-break space.
        k->setText(QStringLiteral("5"));
        emit k->editingFinished();
        QVERIFY2(error->text().endsWith(QStringLiteral("[0,") + QChar(0x00A0) + QStringLiteral("1]")),
                 qPrintable(error->text()));
        QCOMPARE(w.controller().spec().params.real("k"), before); // nothing applied
    }

    void swedishMenusNameTheKeysInSwedish()
    {
        // The Run menu's shortcuts are named by Qt's own translation (the setup script
        // installs Qt's translations): "Mellanslag", "Höger", not "Space", "Right".
        ab::ui::installLanguage(Language::Swedish);
        QCOMPARE(QKeySequence(Qt::Key_Space).toString(QKeySequence::NativeText), QString("Mellanslag"));
        QCOMPARE(QKeySequence(Qt::Key_Right).toString(QKeySequence::NativeText), QString::fromUtf8("Höger"));
        ab::ui::installLanguage(Language::English);
        QCOMPARE(QKeySequence(Qt::Key_Space).toString(QKeySequence::NativeText), QString("Space"));
    }

    void frameRateSaysOneBildAndTwoBilderAndTenthsBelowTen()
    {
        // The status bar's frame rate in Swedish: "1 bild/s", "30 bilder/s" (it read "1 bilder/s").
        const auto shown = [](Language language, double fps) {
            ab::ui::installLanguage(language);
            QStatusBar bar;
            ab::ui::StatusReadout readout(&bar);
            readout.setFrameRate(fps);
            QStringList texts;
            for (const QLabel* label : bar.findChildren<QLabel*>())
                if (label->text().contains(QLatin1String("/s")) || label->text().contains(QLatin1String("fps")))
                    texts << label->text();
            return texts.join(QLatin1Char('|'));
        };
        QCOMPARE(shown(Language::Swedish, 1.02), QStringLiteral("1 bild/s"));
        QCOMPARE(shown(Language::Swedish, 30.4), QStringLiteral("30 bilder/s"));
        QCOMPARE(shown(Language::English, 1.02), QStringLiteral("1 fps"));
        QCOMPARE(shown(Language::English, 30.4), QStringLiteral("30 fps"));
        // Under 10 a second, a tenth: a view drawing a frame a step of 1.2 s read "0 fps".
        QCOMPARE(shown(Language::English, 0.83), QStringLiteral("0.8 fps"));
        QCOMPARE(shown(Language::Swedish, 0.42), QStringLiteral("0.4 bilder/s"));
        QCOMPARE(shown(Language::English, 7.25), QStringLiteral("7.3 fps"));
        QCOMPARE(shown(Language::English, 0.03), QStringLiteral("< 0.1 fps"));
        QCOMPARE(shown(Language::English, 9.97), QStringLiteral("10 fps"));
    }

    void localeChoosesTheLanguage()
    {
        QCOMPARE(ab::ui::languageForLocale(QLocale(QLocale::Swedish, QLocale::Sweden)), Language::Swedish);
        QCOMPARE(ab::ui::languageForLocale(QLocale(QLocale::Swedish, QLocale::Finland)), Language::Swedish);
        QCOMPARE(ab::ui::languageForLocale(QLocale(QLocale::English, QLocale::UnitedKingdom)), Language::English);
        QCOMPARE(ab::ui::languageForLocale(QLocale(QLocale::German, QLocale::Germany)), Language::English);
    }

    void switchingLanguageKeepsTheStageAndItsConstants()
    {
        ab::ui::WindowShell shell;
        shell.window().showScene(SceneId::Box3d);
        ab::ParamValues values = shell.window().controller().spec().params;
        values.parseAssignment("k=0.5");
        QVERIFY(shell.window().applyValues(values));
        shell.setLanguage(Language::Swedish);
        QCOMPARE(shell.window().scene(), SceneId::Box3d);
        QCOMPARE(shell.window().controller().spec().params.real("k"), 0.5);
        QVERIFY(shell.window().windowTitle().startsWith(QStringLiteral("Amazeballs - etapp 2")));
        shell.setLanguage(Language::English);
        QVERIFY(shell.window().windowTitle().startsWith(QStringLiteral("Amazeballs - stage 2")));
    }

    void switchingLanguageKeepsTheLecturesPlace()
    {
        // Two equations into the walk, on the second page of charts: the Swedish window goes on
        // there (it opened the walk at no equation and the charts at their first page).
        ab::ui::WindowShell shell;
        shell.window().resize(1280, 720);
        shell.window().showScene(SceneId::Street);
        shell.lecture().setActive(true);
        shell.lecture().next();
        shell.lecture().next();
        QCOMPARE(shell.window().navigator()->revealed(), 2);
        QTabBar* pages = shell.window().charts()->pages();
        QTRY_VERIFY(pages->count() >= 2);
        pages->setCurrentIndex(1);
        shell.setLanguage(Language::Swedish);
        QCOMPARE(shell.window().scene(), SceneId::Street);
        QCOMPARE(shell.window().navigator()->revealed(), 2);
        QTRY_VERIFY(shell.window().charts()->pages()->count() >= 2);
        QCOMPARE(shell.window().charts()->pages()->currentIndex(), 1);
        shell.lecture().setActive(false);
        shell.setLanguage(Language::English);
    }
};

QTEST_MAIN(UiI18n)
#include "test_ui_i18n.moc"
