#pragma once
// Languages (issue 30; docs/teachers.md, "Languages"): the GUI in English, German, French,
// Spanish and Arabic (right to left).
//
// The texts go through Qt's translation system: every user-visible string of ui/ is a tr() (or
// QCoreApplication::translate) call, and the texts of simcore's tables that the GUI shows (a
// parameter's meaning, a scene's or an integrator's description) are marked SIMCORE_TEXT there
// and read through simcoreText(). lupdate collects them into translations/elastic-lab_LANG.ts
// (cmake --build --preset release -t update_translations); lrelease makes the .qm files, which
// are built into the program (resources :/i18n/).
//
// The language is chosen once, at start (main.cpp): --lang CODE, else the one picked in
// View > Language (kept in the settings; it applies at the next start, as the menu says: every
// dock, plot and dialog is built in its language, and the running experiment is not torn down
// for it), else the first of the system's languages (LANGUAGE, LC_ALL, LC_MESSAGES, LANG) that
// is shipped, else English. The locale of the language formats the numbers the GUI shows
// (num(): decimal comma in German, French and Spanish); files keep their own formats.
#include <string_view>

#include <QFont>
#include <QList>
#include <QLocale>
#include <QString>
#include <QStringList>

namespace elui {

struct Language {
    QString code;        // "en", "de", "fr", "es", "ar"
    QString nativeName;  // as its speakers write it: "Deutsch"
};

// English first, then every translation built into the program.
QList<Language> languages();
bool isLanguage(const QString& code);

// The language to start in: `option` (--lang) if given, else `saved` (View > Language; empty or
// "system": none), else the first of `systemLanguages` (QLocale::uiLanguages(), "de-AT") whose
// language is shipped, else "en". Never fails: a bad --lang is refused by the caller
// (isLanguage) before.
QString chooseLanguage(const QString& option, const QString& saved, const QStringList& systemLanguages);

// Installs the translations of `code` (Elastic Lab's and Qt's own, for the standard dialogs'
// buttons), makes its locale the default (numbers, QCustomPlot's axes) and sets the layout
// direction (right to left for Arabic). Call before any widget is made. English installs none.
void applyLanguage(const QString& code);
// The language applied (en until applyLanguage).
QString currentLanguage();

// A text of simcore's tables (SIMCORE_TEXT) in the current language.
QString simcoreText(std::string_view english);

// A number as the GUI shows it, in the current locale: "0,0025" in German, "0.0025" in English.
QString num(double value, char format = 'g', int precision = 6);
QString num(long long value);
// A number typed into a field: the locale's spelling ("0,0025") or the C one ("0.0025", "1e-3"),
// as the C text simcore's parsers read; the text unchanged when it is neither (a choice's name,
// or bad input left for the parser's message). Group separators are not read ("1.000" is 1 in
// English and German alike, never a thousand).
QString toCNumber(const QString& text);

// `font` in italics when its italic face has every character of `text`, upright otherwise: on
// a Debian desktop the italic face of the default font (DejaVu Sans Oblique) has no Arabic
// letters or Arabic-Indic digits, and italic Arabic came out as empty boxes. Returns whether
// it is italic.
bool setItalicIfLegible(QFont& font, const QString& text);

}  // namespace elui
