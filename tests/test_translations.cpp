// Languages (issue 30; ui/language.h, docs/teachers.md): the translations are complete and say
// the same things, and the window follows the language.
//
//   complete     lupdate is run on today's sources into a copy of each .ts: German, French and
//                Spanish must come out with no text unfinished (a new or changed text in the
//                code that nobody translated) and none vanished (a text the code lost)
//   the same     a translation keeps its source's placeholders (%1, %2 ...), units in brackets
//                ([s], [N/m]), HTML tags and line breaks
//   lessons      each guided experiment's text exists in German, French and Spanish, with the
//                sections' translated titles, the same measured answers (keys and values) and
//                the same marked settings, values to try and "run until" times
//   the window   in Arabic the layout runs right to left (the menu bar starts on the right) and
//                the menus are in Arabic; in German the numbers have a decimal comma and a field
//                reads "0,004" as 0.004
#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QGuiApplication>
#include <QLineEdit>
#include <QMenuBar>
#include <QProcess>
#include <QRegularExpression>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include "simcore/params.h"
#include "simlab/stability.h"
#include "ui/failure_banner.h"
#include "ui/language.h"
#include "ui/lessons.h"
#include "ui/main_window.h"
#include "ui/parameter_dock.h"

using namespace elui;

namespace {

struct Message {
    QString context, source, translation, type;  // type: "", "unfinished", "vanished", "obsolete"
};

QList<Message> readTs(const QString& path) {
    QList<Message> out;
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly)) return out;
    QXmlStreamReader xml(&file);
    QString context;
    Message m;
    while (!xml.atEnd()) {
        xml.readNext();
        if (!xml.isStartElement()) continue;
        const auto name = xml.name();
        if (name == QLatin1String("name")) context = xml.readElementText();
        else if (name == QLatin1String("message")) m = Message{context, {}, {}, {}};
        else if (name == QLatin1String("source")) m.source = xml.readElementText();
        else if (name == QLatin1String("translation")) {
            m.type = xml.attributes().value(QLatin1String("type")).toString();
            m.translation = xml.readElementText();
            out.append(m);
        }
    }
    return out;
}

// What a translation must keep: placeholders, units in brackets, tags, line breaks, sorted.
QStringList marks(const QString& text) {
    QStringList out;
    static const QRegularExpression placeholder(QStringLiteral("%L?(\\d+)"));
    for (const auto& m : placeholder.globalMatch(text)) out << QStringLiteral("%") + m.captured(1);
    // A unit: short, letters of SI symbols, digits, / ^ * ² ³ (not "[force contact]").
    static const QRegularExpression unit(QStringLiteral("\\[([A-Za-z]{1,3}(?:[/*^]?[A-Za-z0-9²³]{1,3}){0,3})\\]"));
    for (const auto& m : unit.globalMatch(text)) out << m.captured(0);
    static const QRegularExpression tag(QStringLiteral("</?([a-zA-Z0-9]+)[^>]*>"));
    for (const auto& m : tag.globalMatch(text)) out << QStringLiteral("<") + m.captured(1) + QStringLiteral(">");
    out << QStringLiteral("lines %1").arg(text.count(QLatin1Char('\n')));
    out.sort();
    return out;
}

QString tsFile(const QString& lang) {
    return QStringLiteral(ELASTIC_LAB_SOURCE_DIR "/translations/elastic-lab_%1.ts").arg(lang);
}

}  // namespace

class TestTranslations : public QObject {
    Q_OBJECT
private slots:
    void initTestCase() { QStandardPaths::setTestModeEnabled(true); }

    void completeAfterLupdate_data() {
        QTest::addColumn<QString>("lang");
        for (const char* lang : {"de", "fr", "es"}) QTest::newRow(lang) << QString::fromLatin1(lang);
    }
    void completeAfterLupdate() {
        QFETCH(QString, lang);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString copy = dir.filePath(QStringLiteral("copy.ts"));
        QVERIFY(QFile::copy(tsFile(lang), copy));
        // The project file CMake wrote for the update_translations target: today's sources.
        const QString project = dir.filePath(QStringLiteral("project.json"));
        QProcess cmake;
        cmake.start(QStringLiteral(ELASTIC_LAB_CMAKE),
                    {QStringLiteral("-DIN_FILE=" ELASTIC_LAB_LUPDATE_PROJECT), QStringLiteral("-DOUT_FILE=") + project,
                     QStringLiteral("-P"), QStringLiteral(ELASTIC_LAB_LUPDATE_PROJECT_SCRIPT)});
        QVERIFY(cmake.waitForFinished(-1));
        QCOMPARE(cmake.exitCode(), 0);
        QProcess lupdate;
        QStringList args{QStringLiteral("-project"), project};
        args << QString::fromLatin1(ELASTIC_LAB_LUPDATE_OPTIONS).split(QLatin1Char('|'));
        args << QStringLiteral("-ts") << copy;
        lupdate.start(QStringLiteral(ELASTIC_LAB_LUPDATE), args);
        QVERIFY(lupdate.waitForFinished(-1));
        QVERIFY2(lupdate.exitCode() == 0, lupdate.readAllStandardError().constData());
        const QList<Message> messages = readTs(copy);
        QVERIFY(messages.size() > 500);
        QStringList problems;
        for (const Message& m : messages)
            if (!m.type.isEmpty() || m.translation.isEmpty())
                problems << QStringLiteral("%1 [%2] %3").arg(m.type.isEmpty() ? QStringLiteral("empty") : m.type,
                                                            m.context, m.source.left(80));
        QVERIFY2(problems.isEmpty(), qPrintable(QStringLiteral("%1 text(s) not translated in %2 (run "
                                                               "`cmake --build --preset release -t "
                                                               "update_translations`, then translate):\n")
                                                    .arg(problems.size())
                                                    .arg(lang) +
                                                problems.join(QLatin1Char('\n'))));
    }

    void placeholdersMatch_data() {
        QTest::addColumn<QString>("lang");
        for (const char* lang : {"de", "fr", "es", "ar"}) QTest::newRow(lang) << QString::fromLatin1(lang);
    }
    void placeholdersMatch() {
        QFETCH(QString, lang);
        const QList<Message> messages = readTs(tsFile(lang));
        QVERIFY(!messages.isEmpty());
        QStringList problems;
        for (const Message& m : messages) {
            if (m.type == QLatin1String("unfinished")) continue;  // Arabic: partly; falls back to English
            if (marks(m.source) != marks(m.translation))
                problems << QStringLiteral("%1: \"%2\" -> \"%3\" (%4 against %5)")
                                .arg(m.context, m.source.left(60), m.translation.left(60),
                                     marks(m.source).join(QLatin1Char(' ')), marks(m.translation).join(QLatin1Char(' ')));
        }
        QVERIFY2(problems.isEmpty(), qPrintable(problems.join(QLatin1Char('\n'))));
    }

    void theMarksAreChecked() {
        // The check itself: a lost placeholder, a changed unit or a dropped tag is seen.
        QVERIFY(marks(QStringLiteral("DT = %1 s [s]")) != marks(QStringLiteral("DT = s [s]")));
        QVERIFY(marks(QStringLiteral("energy [J]")) != marks(QStringLiteral("Energie [kJ]")));
        QVERIFY(marks(QStringLiteral("<b>%1</b>")) != marks(QStringLiteral("%1")));
        QCOMPARE(marks(QStringLiteral("%1 and %2")), marks(QStringLiteral("%2 und %1")));
        QCOMPARE(marks(QStringLiteral("slip [force contact]")), marks(QStringLiteral("Gleiten [Kontakt force]")));
    }

    void lessonsInEveryLanguage_data() {
        QTest::addColumn<QString>("lang");
        for (const char* lang : {"de", "fr", "es"}) QTest::newRow(lang) << QString::fromLatin1(lang);
    }
    void lessonsInEveryLanguage() {
        QFETCH(QString, lang);
        QMap<QString, QString> english;
        QMap<QString, QMap<QString, LessonAnswer>> englishAnswers;
        applyLanguage(QStringLiteral("en"));
        for (const QString& id : lessonIds()) {
            english[id] = findLesson(id)->html();
            englishAnswers[id] = lessonAnswers(english[id]);
            QVERIFY(!englishAnswers[id].isEmpty());
        }
        applyLanguage(lang);
        const QStringList titles = lessonSectionTitles();
        QVERIFY(titles.front() != QLatin1String("Goal"));  // translated
        for (const QString& id : lessonIds()) {
            const QString html = findLesson(id)->html();
            QVERIFY2(!html.isEmpty() && html != english[id], qPrintable(id));
            QCOMPARE(lessonSections(html), titles);
            QString error;
            const QMap<QString, LessonAnswer> answers = lessonAnswers(html, &error);
            QVERIFY2(error.isEmpty(), qPrintable(id + QStringLiteral(": ") + error));
            QCOMPARE(answers.keys(), englishAnswers[id].keys());
            for (const QString& key : answers.keys()) {
                QCOMPARE(answers[key].value, englishAnswers[id][key].value);
                QCOMPARE(answers[key].relativeTolerance, englishAnswers[id][key].relativeTolerance);
            }
            // What to do: the same marked settings, values to try and "run until" times.
            const QList<LessonValue> values = lessonValues(html), englishValues = lessonValues(english[id]);
            QCOMPARE(values.size(), englishValues.size());
            for (qsizetype i = 0; i < values.size(); ++i) {
                QVERIFY2(values[i].valid, qPrintable(id + QStringLiteral(": ") + values[i].key));
                QCOMPARE(values[i].kind, englishValues[i].kind);
                QCOMPARE(values[i].key, englishValues[i].key);
                QCOMPARE(values[i].value, englishValues[i].value);
            }
            QCOMPARE(lessonUntil(html), lessonUntil(english[id]));
        }
        applyLanguage(QStringLiteral("en"));
    }

    void arabicMirrorsTheWindow() {
        QVERIFY(isLanguage(QStringLiteral("ar")));
        applyLanguage(QStringLiteral("ar"));
        QCOMPARE(QGuiApplication::layoutDirection(), Qt::RightToLeft);
        {
            MainWindow window(false);
            window.resize(1000, 700);
            window.show();
            QVERIFY(QTest::qWaitForWindowExposed(&window));
            QCOMPARE(window.layoutDirection(), Qt::RightToLeft);
            // The File menu, in Arabic, first from the right.
            QAction* file = window.menuBar()->actions().front();
            QCOMPARE(file->text(), QStringLiteral("&ملف"));
            const QRect first = window.menuBar()->actionGeometry(file);
            QVERIFY2(first.left() > window.menuBar()->width() / 2,
                     qPrintable(QStringLiteral("File menu at x = %1 of %2").arg(first.left()).arg(window.menuBar()->width())));
            // A translated title: the Parameters dock's.
            QVERIFY(window.findChild<QDockWidget*>(QStringLiteral("ParametersDock")));
            QCOMPARE(window.findChild<QDockWidget*>(QStringLiteral("ParametersDock"))->windowTitle(),
                     QStringLiteral("المعاملات"));
        }
        applyLanguage(QStringLiteral("en"));
        QCOMPARE(QGuiApplication::layoutDirection(), Qt::LeftToRight);
    }

    void germanNumbersHaveADecimalComma() {
        applyLanguage(QStringLiteral("de"));
        QCOMPARE(num(0.0025), QStringLiteral("0,0025"));
        QCOMPARE(num(12345.5, 'f', 1), QStringLiteral("12345,5"));  // no group separator
        QCOMPARE(toCNumber(QStringLiteral("0,004")).toDouble(), 0.004);
        QCOMPARE(toCNumber(QStringLiteral("0.004")), QStringLiteral("0.004"));  // the C spelling passes
        QCOMPARE(toCNumber(QStringLiteral("ring")), QStringLiteral("ring"));
        {
            ParameterForm form(simcore::SceneKind::Ring2d, {simcore::ParamGroup::Springs});
            QLineEdit* ks = form.field(QStringLiteral("ks"));
            QVERIFY(ks);
            form.setValues(simcore::ParameterSet(simcore::SceneKind::Ring2d));
            QCOMPARE(ks->text(), QStringLiteral("800"));
            QCOMPARE(form.field(QStringLiteral("kd"))->text(), QStringLiteral("15"));
            double v = 0;
            QVERIFY(ParameterForm::validate(simcore::paramSpec(simcore::Param::Ks), QStringLiteral("812,5"), &v).isEmpty());
            QCOMPARE(v, 812.5);
            QVERIFY(ParameterForm::validate(simcore::paramSpec(simcore::Param::Ks), QStringLiteral("812.5"), &v).isEmpty());
            QCOMPARE(v, 812.5);
            // A refused value is said in German.
            const QString error = ParameterForm::validate(simcore::paramSpec(simcore::Param::Ks), QStringLiteral("-1"));
            QVERIFY2(error.contains(QStringLiteral("nicht erlaubt")), qPrintable(error));
            // simcore's texts through the "simcore" context.
            QVERIFY(simcoreText(simcore::paramSpec(simcore::Param::Gravity).meaning).startsWith(QStringLiteral("Fallbeschleunigung")));
        }
        // The failure banner's verdict: the same sentences in German, simlab's words in English.
        simlab::FailureCheck check;
        check.checked = true;
        check.from = 0.5;
        check.rerunDt = 0.0025;
        check.until = 0.9;
        const QString german = FailureBanner::checkText(check);
        QVERIFY2(german.startsWith(QStringLiteral("Der Schritt war zu groß")) && german.contains(QStringLiteral("t = 0,500 s")) &&
                     german.contains(QStringLiteral("0,0025 s")),
                 qPrintable(german));
        applyLanguage(QStringLiteral("en"));
        QCOMPARE(FailureBanner::checkText(check), QString::fromStdString(simlab::failureCheckText(check)));
        QCOMPARE(num(0.0025), QStringLiteral("0.0025"));
    }

    void theLanguageIsChosen() {
        // --lang first, then View > Language's choice, then the system's, then English.
        QCOMPARE(chooseLanguage(QStringLiteral("fr"), QStringLiteral("de"), {QStringLiteral("es-ES")}), QStringLiteral("fr"));
        QCOMPARE(chooseLanguage({}, QStringLiteral("de"), {QStringLiteral("es-ES")}), QStringLiteral("de"));
        QCOMPARE(chooseLanguage({}, QStringLiteral("system"), {QStringLiteral("es-ES")}), QStringLiteral("es"));
        QCOMPARE(chooseLanguage({}, {}, {QStringLiteral("pt-BR"), QStringLiteral("de-AT")}), QStringLiteral("de"));
        QCOMPARE(chooseLanguage({}, {}, {QStringLiteral("pt-BR")}), QStringLiteral("en"));
        QCOMPARE(languages().size(), 5);
    }
};

QTEST_MAIN(TestTranslations)
#include "test_translations.moc"
