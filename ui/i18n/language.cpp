// SPDX-License-Identifier: MIT
#include "language.h"

#include <QCoreApplication>
#include <QLibraryInfo>
#include <QTranslator>

#include <memory>
#include <stdexcept>

namespace ab::ui {

namespace {

struct Installed {
    Language language = Language::English;
    std::unique_ptr<QTranslator> program;
    std::unique_ptr<QTranslator> qt; // Qt's own buttons and dialogs, where the system has them
};

Installed& installed()
{
    static Installed state;
    return state;
}

} // namespace

const std::vector<Language>& allLanguages()
{
    static const std::vector<Language> all{Language::English, Language::Swedish};
    return all;
}

QString nativeName(Language language)
{
    return language == Language::Swedish ? QStringLiteral("Svenska") : QStringLiteral("English");
}

QString languageCode(Language language)
{
    return language == Language::Swedish ? QStringLiteral("sv") : QStringLiteral("en");
}

Language languageForLocale(const QLocale& locale)
{
    return locale.language() == QLocale::Swedish ? Language::Swedish : Language::English;
}

void installLanguage(Language language)
{
    Installed& state = installed();
    for (auto* t : {&state.program, &state.qt})
        if (*t) {
            QCoreApplication::removeTranslator(t->get());
            t->reset();
        }
    state.language = language;
    if (language == Language::English) {
        // Removing a translator sends LanguageChange too; nothing more to load.
        return;
    }
    const QString code = languageCode(language);
    auto program = std::make_unique<QTranslator>();
    if (!program->load(QStringLiteral(":/i18n/amazeballs_%1.qm").arg(code)))
        throw std::runtime_error("the embedded translation amazeballs_" + code.toStdString() + ".qm is missing");
    auto qt = std::make_unique<QTranslator>();
    if (qt->load(QStringLiteral("qt_%1").arg(code), QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator((state.qt = std::move(qt)).get());
    QCoreApplication::installTranslator((state.program = std::move(program)).get());
}

Language installedLanguage()
{
    return installed().language;
}

} // namespace ab::ui
