// SPDX-License-Identifier: MIT
// The window's languages: English (the source) and Swedish (the report's language).
// The Swedish texts are compiled from resources/translations/amazeballs_sv.ts at build
// time and embedded under :/i18n/. Installing a language sends every widget a
// QEvent::LanguageChange.
#pragma once

#include <QLocale>
#include <QString>

#include <vector>

namespace ab::ui {

enum class Language { English, Swedish };

const std::vector<Language>& allLanguages();
// The language's own name ("English", "Svenska"), the same in every language.
QString nativeName(Language language);
QString languageCode(Language language); // "en", "sv"
// Swedish for a Swedish locale, otherwise English.
Language languageForLocale(const QLocale& locale);

// Replaces the application's translation (the program's texts and Qt's own dialogs).
// Throws std::runtime_error when an embedded translation is missing (a build fault).
void installLanguage(Language language);
Language installedLanguage();

} // namespace ab::ui
