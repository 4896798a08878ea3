#include "ui/language.h"

#include <QCoreApplication>
#include <QFile>
#include <QFontMetrics>
#include <QGuiApplication>
#include <QLibraryInfo>
#include <QTranslator>

namespace elui {

namespace {
QString g_language = QStringLiteral("en");
// The numbers' locale: C (as English, without group separators) until applyLanguage, so that a
// program or test that applies no language shows the same digits on every machine.
QLocale g_locale = [] {
    QLocale c = QLocale::c();
    c.setNumberOptions(QLocale::OmitGroupSeparator);
    return c;
}();

// The .qm files of lrelease, built into the program (ui/CMakeLists.txt, RESOURCE_PREFIX).
QString ourTranslation(const QString& code) { return QStringLiteral(":/i18n/elastic-lab_%1.qm").arg(code); }

// The ones written; which are built is read from the resources.
const QList<Language>& allLanguages() {
    static const QList<Language> all = {
        {QStringLiteral("en"), QStringLiteral("English")},
        {QStringLiteral("de"), QStringLiteral("Deutsch")},
        {QStringLiteral("fr"), QStringLiteral("Français")},
        {QStringLiteral("es"), QStringLiteral("Español")},
        {QStringLiteral("ar"), QStringLiteral("العربية")},
    };
    return all;
}
}  // namespace

QList<Language> languages() {
    QList<Language> out;
    for (const Language& l : allLanguages())
        if (l.code == QLatin1String("en") || QFile::exists(ourTranslation(l.code))) out.append(l);
    return out;
}

bool isLanguage(const QString& code) {
    for (const Language& l : languages())
        if (l.code == code) return true;
    return false;
}

QString chooseLanguage(const QString& option, const QString& saved, const QStringList& systemLanguages) {
    if (!option.isEmpty()) return option;
    if (!saved.isEmpty() && saved != QLatin1String("system") && isLanguage(saved)) return saved;
    for (const QString& name : systemLanguages) {
        // "de-AT", "de_AT.UTF-8", "de": the language part.
        const QString code = name.section(QLatin1Char('-'), 0, 0).section(QLatin1Char('_'), 0, 0).toLower();
        if (isLanguage(code)) return code;
    }
    return QStringLiteral("en");
}

void applyLanguage(const QString& code) {
    g_language = code;
    QLocale locale(code);
    if (code == QLatin1String("en")) locale = QLocale(QLocale::English, QLocale::UnitedStates);
    locale.setNumberOptions(QLocale::OmitGroupSeparator);  // "12345.6", as in the files
    g_locale = locale;
    QLocale::setDefault(locale);
    QGuiApplication::setLayoutDirection(locale.textDirection());
    // The translations of a language applied before are taken away (a test applies several).
    static QTranslator* ours = nullptr;
    static QTranslator* qt = nullptr;
    for (QTranslator** t : {&ours, &qt}) {
        if (*t) QCoreApplication::removeTranslator(*t);
        delete *t;
        *t = nullptr;
    }
    if (code == QLatin1String("en")) return;
    ours = new QTranslator;
    if (ours->load(ourTranslation(code))) QCoreApplication::installTranslator(ours);
    // Qt's own (Debian: qt6-translations-l10n): the buttons of the file and message dialogs.
    qt = new QTranslator;
    if (qt->load(locale, QStringLiteral("qtbase"), QStringLiteral("_"),
                 QLibraryInfo::path(QLibraryInfo::TranslationsPath)))
        QCoreApplication::installTranslator(qt);
}

QString currentLanguage() { return g_language; }

QString simcoreText(std::string_view english) {
    const QByteArray text(english.data(), qsizetype(english.size()));
    return QCoreApplication::translate("simcore", text.constData());
}

QString num(double value, char format, int precision) { return g_locale.toString(value, format, precision); }
QString num(long long value) { return g_locale.toString(value); }

bool setItalicIfLegible(QFont& font, const QString& text) {
    QFont italic = font;
    italic.setItalic(true);
    const QFontMetrics metrics(italic);
    for (const QChar c : text)  // (format characters, such as the Arabic letter mark, draw nothing)
        if (!c.isSpace() && c.category() != QChar::Other_Format && !metrics.inFont(c)) {
            font.setItalic(false);
            return false;
        }
    font = italic;
    return true;
}

QString toCNumber(const QString& text) {
    const QString trimmed = text.trimmed();
    QLocale locale = g_locale;
    locale.setNumberOptions(QLocale::RejectGroupSeparator);
    bool ok = false;
    const double v = locale.toDouble(trimmed, &ok);
    if (!ok) return text;  // C spelling, a name, or bad input: simcore's parser decides
    return QString::number(v, 'g', 17);
}

}  // namespace elui
