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
//   the physics  a run's failure, the stability verdict and advice, and the Stability map's
//                margin, spectrum method and region notes, composed from simcore's and simlab's
//                parts: no English left, the numbers in the language's format
#include <complex>
#include <limits>
#include <optional>
#include <set>

#include <QApplication>
#include <QDir>
#include <QDockWidget>
#include <QFile>
#include <QFontInfo>
#include <QFontMetrics>
#include <QGuiApplication>
#include <QLineEdit>
#include <QMenuBar>
#include <QProcess>
#include <QRegularExpression>
#include <QSet>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QXmlStreamReader>

#include "simcore/failure_texts.h"
#include "simcore/params.h"
#include "simcore/simulation.h"
#include "simcore/world.h"
#include "simcore/world_spec.h"
#include "simcore/integrator_table.h"
#include "simlab/stability.h"
#include "simlab/stability_region.h"
#include "test_support.h"
#include "ui/failure_banner.h"
#include "ui/failure_text.h"
#include "ui/language.h"
#include "ui/lessons.h"
#include "ui/main_window.h"
#include "ui/parameter_dock.h"
#include "ui/stability_map_dock.h"

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

    // The lesson dock marks a measured answer in italics; in Arabic the number has Arabic-Indic
    // digits, which the default font's italic face (DejaVu Sans Oblique) does not have: they
    // came out as empty boxes. Italic only where the italic face has every character.
    void italicOnlyWhereTheFaceHasTheCharacters() {
        applyLanguage(QStringLiteral("ar"));
        const QString arabic = num(-2.683, 'g', 4);
        QVERIFY(arabic.contains(QChar(0x0662)));  // Arabic-Indic two
        QFont font = QApplication::font();
        const bool italic = setItalicIfLegible(font, arabic);
        QCOMPARE(font.italic(), italic);
        const QFontMetrics metrics(font);
        for (const QChar c : arabic)
            QVERIFY2(c.isSpace() || c.category() == QChar::Other_Format || metrics.inFont(c),
                     qPrintable(QStringLiteral("U+%1 not in %2%3").arg(c.unicode(), 4, 16, QLatin1Char('0'))
                                    .arg(QFontInfo(font).family(), font.italic() ? QStringLiteral(" italic") : QString())));
        applyLanguage(QStringLiteral("en"));
        QFont latin = QApplication::font();
        QVERIFY(setItalicIfLegible(latin, num(-2.683, 'g', 4)));  // every italic face has the ASCII digits
        QVERIFY(latin.italic());
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

    // A run's failure in the window's language (ui/failure_text.h): every sentence simcore
    // reports with (simcore/failure_texts.h) is said in German, French and Spanish with its
    // numbers in the language's format; in English, and for a sentence it does not know, the
    // text as it came.
    void failureReasonsInEveryLanguage_data() {
        QTest::addColumn<QString>("lang");
        for (const char* lang : {"de", "fr", "es"}) QTest::newRow(lang) << QString::fromLatin1(lang);
    }
    void failureReasonsInEveryLanguage() {
        QFETCH(QString, lang);
        namespace ft = simcore::failure_text;
        struct Case {
            std::string english;
            QStringList numbers;  // as the language writes them
        };
        applyLanguage(lang);
        const std::vector<Case> cases = {
            {ft::nonFinite(), {}},
            {ft::runawayVelocity(1234.5), {num(1234.5)}},
            {ft::runawayVelocity(2.5e+07), {num(2.5e7)}},
            {ft::runawayEnergy(812.25, 40.5, 1000), {num(812.25), num(40.5), num(1000.0)}},
            {ft::layerLost(std::nullopt, simcore::Layer::Inner, 2, 0.0125, 3.5), {num(0.0125), num(3.5)}},
            {ft::layerLost(std::nullopt, simcore::Layer::Outer, 3, -0.25, 30.5), {num(-0.25), num(30.5)}},
            {ft::layerLost(std::size_t{2}, simcore::Layer::Single, 3, 0.5, 12.5), {QStringLiteral("2"), num(0.5), num(12.5)}},
            {ft::layersCrossed(1, 2, 0.05), {QStringLiteral("1"), QStringLiteral("2"), num(0.05)}},
            {ft::layersCrossed(3, 3, 0.0125), {QStringLiteral("3"), num(0.0125)}},
            {ft::floatNotFinite(17), {QStringLiteral("17")}},
            {ft::floatReachedWall(4711), {QStringLiteral("4711")}},
            {ft::kRk45MinimumStep, {}},
            {ft::kImplicitEulerNoConvergence, {}},
        };
        const QRegularExpression english(QStringLiteral("\\b(runaway|layer|particle|the state|inside out|collapsed|"
                                                        "rest|body|converge|minimum step|wall)\\b"));
        for (const Case& c : cases) {
            const QString said = failureReason(c.english);
            const QString source = QString::fromStdString(c.english);
            QVERIFY2(said != source, qPrintable(lang + ": not translated: " + source));
            QVERIFY2(!english.match(said).hasMatch(), qPrintable(lang + ": English left in: " + said));
            for (const QString& n : c.numbers) QVERIFY2(said.contains(n), qPrintable(lang + ": " + n + " missing in: " + said));
        }
        // A sentence it does not know (a SUNDIALS message) stays as it came.
        QCOMPARE(failureReason("cvode: at t = 0.1, mxstep steps taken"), QStringLiteral("cvode: at t = 0.1, mxstep steps taken"));
        applyLanguage(QStringLiteral("en"));
        for (const Case& c : cases) QCOMPARE(failureReason(c.english), QString::fromStdString(c.english));
    }

    // The failures simcore really reports come back translated: a body thrown apart by a step far
    // too large (the one-body simulation), and two bodies of a world (its own checks).
    void realFailuresAreTranslated() {
        applyLanguage(QStringLiteral("fr"));
        simcore::ParameterSet p(simcore::SceneKind::Ring2d);
        QVERIFY(!p.set(simcore::Param::Dt, 0.05));
        simcore::Simulation sim(p, "euler");
        for (int k = 0; k < 200 && sim.step(); ++k) {}
        QVERIFY(sim.failure());
        const QString said = failureReason(sim.failure()->reason);
        QVERIFY2(said != QString::fromStdString(sim.failure()->reason), qPrintable(said));
        auto world = simcore::worldScene("collide2d");
        QVERIFY(world);
        QVERIFY(!simcore::assignWorld(*world, "dt=0.05"));
        simcore::World w(*world, "euler");
        for (int k = 0; k < 200 && w.step(); ++k) {}
        QVERIFY(w.failure());
        const QString saidWorld = failureReason(*w.failure());
        QVERIFY2(saidWorld != QString::fromStdString(*w.failure()), qPrintable(saidWorld));
        applyLanguage(QStringLiteral("en"));
    }

    // simlab's stability sentences from their parts: the verdict with every basis and limit, and
    // the pre-run advice of a real body (euler at DT 0.03 on the ring), in the window's language;
    // in English, simlab's own text.
    void stabilitySentencesInEveryLanguage_data() { failureReasonsInEveryLanguage_data(); }
    void stabilitySentencesInEveryLanguage() {
        QFETCH(QString, lang);
        using Basis = simlab::StabilityVerdict::Basis;
        std::vector<simlab::StabilityVerdict> verdicts;
        for (Basis basis : {Basis::ExactSpectrum, Basis::Arnoldi, Basis::Modes, Basis::StepMatrix})
            for (double limit : {0.00888, 0.0, std::numeric_limits<double>::infinity()}) {
                simlab::StabilityVerdict v;
                v.integrator = "rk4";
                v.dt = 0.03;
                v.limit = limit;
                v.basisKind = basis;
                v.basisValues = 96;
                v.basisOf = 192;
                v.basis = "exact spectrum, 96 eigenvalues";
                verdicts.push_back(v);
            }
        verdicts.front().ownStep = true;
        simcore::ParameterSet p(simcore::SceneKind::Ring2d);
        QVERIFY(!p.set(simcore::Param::Dt, 0.03));
        const simcore::Simulation sim(p, "euler");
        const auto advice = simlab::stabilityAdvice(sim);
        QVERIFY(advice);
        const QRegularExpression english(QStringLiteral("\\b(stable up to|is stable|chooses|eigenvalues|spectrum|step matrix|"
                                                        "Ritz values of|largest stable step|will likely|grows)\\b"));
        applyLanguage(lang);
        for (const simlab::StabilityVerdict& v : verdicts) {
            const QString said = verdictSentence(v);
            QVERIFY2(said != QString::fromStdString(simlab::verdictText(v)), qPrintable(said));
            QVERIFY2(!english.match(said).hasMatch(), qPrintable(lang + ": English left in: " + said));
            if (v.limit > 0.0 && !std::isinf(v.limit) && !v.ownStep) QVERIFY2(said.contains(num(0.00888)), qPrintable(said));
        }
        const QString advised = adviceSentence(*advice);
        QVERIFY2(!english.match(advised).hasMatch() && advised.contains(num(0.03)), qPrintable(advised));
        applyLanguage(QStringLiteral("en"));
        for (const simlab::StabilityVerdict& v : verdicts)
            QCOMPARE(verdictSentence(v), QString::fromStdString(simlab::verdictText(v)));
        QCOMPARE(adviceSentence(*advice), QString::fromStdString(advice->message));
    }

    // The Stability map dock's words (ui/stability_map_dock.h): every region note (every
    // integrator, and a name it does not know), every way the spectrum is found and every case of
    // the margin, in each language with its numbers in the language's format; in English,
    // simlab's own text. The margins are made by hand for every case and by simlab on a real
    // body for each case a body can reach.
    void stabilityMapInEveryLanguage_data() {
        QTest::addColumn<QString>("lang");
        for (const char* lang : {"de", "fr", "es", "ar"}) QTest::newRow(lang) << QString::fromLatin1(lang);
    }
    void stabilityMapInEveryLanguage() {
        QFETCH(QString, lang);
        using Case = simlab::StepMargin::Case;
        using Complex = std::complex<double>;
        // Words of simlab's English no translation has (the method names, hλ, DT, BDF and R stay).
        static const QRegularExpression english(QStringLiteral(
            "\\b(the|of|is|are|its|for|every|before|grows?|leaves|already|outside|shrink|pair|picture|underdamped|decay|"
            "fastest|chooses|internal|sits|touches|eigenvalues|spectrum|accurate|inner|coordinates|steps|substeps|"
            "backwards|drawn|whose|damping|undamped|polynomial|imaginary|axis|tolerance|takes|costs|springs|"
            "unconditionally|accuracy|region|Region|margin|bodies)\\b"));
        // The language's numbers: a decimal comma (Arabic: its own digits and separator), never
        // "0.0159" in a German sentence.
        static const QRegularExpression decimalPoint(QStringLiteral("[0-9]\\.[0-9]"));
        QStringList problems;
        auto check = [&](const QString& what, const QString& said, const std::string& englishText, const QStringList& numbers) {
            if (said == QString::fromStdString(englishText)) problems << what + QStringLiteral(": not translated: ") + said;
            if (const auto m = english.match(said); m.hasMatch())
                problems << what + QStringLiteral(": English (\"%1\") left in: ").arg(m.captured(0)) + said;
            if (!num(0.5).contains(QLatin1Char('.')) && decimalPoint.match(said).hasMatch())
                problems << what + QStringLiteral(": a number in English format in: ") + said;
            for (const QString& n : numbers)
                if (!said.contains(n)) problems << what + QStringLiteral(": ") + n + QStringLiteral(" missing in: ") + said;
        };
        applyLanguage(lang);

        // Every integrator's note: translated, its numbers in the language's format, and as many
        // different notes as in English (no two families said alike).
        std::vector<std::string> names;
        for (const simcore::IntegratorInfo& info : simcore::integratorTable()) names.emplace_back(info.name);
        names.emplace_back("not-an-integrator");
        QSet<QString> notes;
        std::set<std::string> englishNotes;
        for (const std::string& name : names) {
            const simlab::RegionNoteParts parts = simlab::regionNoteParts(name);
            QStringList numbers;
            if (parts.imaginaryReach > 0.0) numbers << num(parts.imaginaryReach, 'g', 3);
            if (parts.kind == simlab::RegionNoteParts::Kind::Composition)
                numbers << num(parts.undampedLimit, 'g', 3) << num(static_cast<long long>(parts.substeps))
                        << num(static_cast<long long>(parts.forceEvaluations));
            const QString said = regionNoteSentence(name);
            check(QString::fromStdString(name) + QStringLiteral(" note"), said, simlab::regionNote(name), numbers);
            notes.insert(said);
            englishNotes.insert(simlab::regionNote(name));
        }
        QCOMPARE(notes.size(), qsizetype(englishNotes.size()));
        QVERIFY(regionNoteSentence("rk4").contains(num(2.83)));

        // How the eigenvalues were found: made by hand (every method) and from a real body.
        std::vector<simlab::SpectrumPoints> spectra(3);
        spectra[0].kind = simlab::SpectrumPoints::Method::Exact;
        spectra[1].kind = simlab::SpectrumPoints::Method::Modal;
        spectra[2].kind = simlab::SpectrumPoints::Method::Iterative;
        spectra[2].arnoldiSteps = 90;
        spectra[2].freeCoordinates = 1536;
        for (std::size_t k = 0; k < spectra.size(); ++k) spectra[k].count = 96 + k;
        for (simlab::SpectrumPoints& p : spectra) p.methodText = simlab::spectrumMethodText(p);
        simcore::ParameterSet spring(simcore::SceneKind::Spring1d);
        QVERIFY(!spring.set(simcore::Param::Dt, 0.001));
        const simlab::LinearModes springModes = simlab::linearModes(spring);
        spectra.push_back(simlab::spectrumPoints(springModes));
        spectra.push_back(simlab::spectrumPoints(simlab::linearModes(spring, 0)));
        QCOMPARE(spectra[3].kind, simlab::SpectrumPoints::Method::Exact);
        QCOMPARE(spectra[4].kind, simlab::SpectrumPoints::Method::Modal);
        QSet<QString> methods;
        for (const simlab::SpectrumPoints& p : spectra) {
            QStringList numbers{num(static_cast<long long>(p.count))};
            if (p.kind == simlab::SpectrumPoints::Method::Iterative)
                numbers << num(static_cast<long long>(p.arnoldiSteps)) << num(static_cast<long long>(p.freeCoordinates));
            const QString said = spectrumSentence(p);
            check(QString::fromStdString(p.method) + QStringLiteral(" spectrum"), said, p.methodText, numbers);
            methods.insert(said);
        }
        QCOMPARE(methods.size(), qsizetype(spectra.size()));

        // Every case of the margin, made by hand: the limiting mode a pure decay or a pair, the
        // fastest or not, or none named; the oscillator methods' two bases.
        auto made = [](const char* integrator, Case kind, double factor, bool oscillator, std::optional<Complex> limiting,
                       bool fastest = true, bool exactStepMatrix = true) {
            simlab::StepMargin m;
            m.integrator = integrator;
            m.kind = kind;
            m.factor = factor;
            m.dt = 0.003;
            m.oscillator = oscillator;
            m.hasLimiting = limiting.has_value();
            m.limiting = limiting.value_or(Complex(0.0, 0.0));
            m.limitingIsFastest = fastest;
            m.exactStepMatrix = exactStepMatrix;
            m.text = simlab::stepMarginText(m);
            return m;
        };
        const double inf = std::numeric_limits<double>::infinity();
        std::vector<simlab::StepMargin> margins = {
            made("xpbd", Case::Xpbd, inf, false, {}),
            made("cvode-bdf", Case::OwnStep, inf, false, {}),
            made("implicit-euler", Case::Unlimited, inf, false, {}),
            made("euler", Case::NoStableDt, 0.0, false, Complex(-0.5, 28.3)),
            made("verlet", Case::NoStableDt, 0.0, true, {}),
            made("rk4", Case::CanGrow, 5.3, false, Complex(-175.0, 0.0)),
            made("euler", Case::CanGrow, 2.9, false, Complex(-72.7, 107.0), false),
            made("rk4", Case::CanGrow, 33.3, false, {}),
            made("verlet", Case::CanGrow, 1.25, true, {}, true, false),
            made("rk4", Case::Outside, 0.5, false, Complex(-75.0, 272.7)),
            made("midpoint", Case::Outside, 0.38, false, Complex(-1737.0, 0.0), false),
            made("symplectic-euler", Case::Outside, 0.4, true, {}),
        };
        // And simlab's own on the spring (w^2 = 800, c = 15) for each case a body reaches.
        simcore::ParameterSet undamped = spring;
        QVERIFY(!undamped.set(simcore::Param::Kd, 0.0));
        const simlab::LinearModes undampedModes = simlab::linearModes(undamped);
        const struct {
            const char* integrator;
            const simlab::LinearModes* modes;
            double dt;
            Case kind;
        } real[] = {{"euler", &springModes, 0.001, Case::CanGrow},       {"rk4", &springModes, 0.2, Case::Outside},
                    {"verlet", &springModes, 0.001, Case::CanGrow},      {"yoshida4", &springModes, 0.2, Case::Outside},
                    {"euler", &undampedModes, 0.001, Case::NoStableDt},  {"implicit-euler", &springModes, 0.001, Case::Unlimited},
                    {"xpbd", &springModes, 0.001, Case::Xpbd},           {"cvode-adams", &springModes, 0.001, Case::OwnStep}};
        for (const auto& r : real) {
            margins.push_back(simlab::stepMargin(r.integrator, *r.modes, simlab::spectrumPoints(*r.modes), r.dt));
            QVERIFY2(margins.back().kind == r.kind, margins.back().text.c_str());
        }
        QSet<QString> said;
        std::set<std::string> englishMargins;
        for (const simlab::StepMargin& m : margins) {
            englishMargins.insert(m.text);
            QStringList numbers;
            if (m.kind == Case::CanGrow) numbers << num(m.factor, 'f', 2) << num(m.factor * m.dt, 'g', 3);
            if (m.kind == Case::Outside) numbers << num(1.0 / m.factor, 'f', 2) << num(m.factor * m.dt, 'g', 3);
            // The limiting mode is named where DT meets the region's edge (or never gets inside).
            const bool named = m.hasLimiting && (m.kind == Case::CanGrow || m.kind == Case::Outside || m.kind == Case::NoStableDt);
            if (named) numbers << num(m.limitingPoint().real(), 'g', 3);
            if (named && !m.limitingIsReal()) numbers << num(std::abs(m.limitingPoint().imag()), 'g', 3);
            if (m.kind == Case::OwnStep) numbers << QString::fromStdString(m.integrator);
            const QString sentence = marginSentence(m);
            check(QStringLiteral("%1 margin (%2)").arg(QString::fromStdString(m.integrator)).arg(int(m.kind)), sentence, m.text, numbers);
            said.insert(sentence);
        }
        QCOMPARE(said.size(), qsizetype(englishMargins.size()));

        // The dock says them: a spring in the window's language.
        {
            StabilityMapDock dock;
            dock.resize(420, 520);
            dock.show();
            dock.setState(spring, QStringLiteral("rk4"));
            QVERIFY(testsupport::waitUntil([&] { return dock.resultSerial() > 0 && !dock.computing(); }));
            const simlab::StepMargin margin = simlab::stepMargin("rk4", springModes, simlab::spectrumPoints(springModes), 0.001);
            QCOMPARE(dock.marginText(), QStringLiteral("rk4: ") + marginSentence(margin));
            check(QStringLiteral("the dock's margin"), dock.marginText(), "rk4: " + margin.text, {num(margin.factor, 'f', 2)});
            check(QStringLiteral("the dock's notes"), dock.methodText(),
                  "Eigenvalues: " + simlab::spectrumPoints(springModes).methodText + ".\n" + simlab::regionNote("rk4"), {});
        }
        QVERIFY2(problems.isEmpty(), qPrintable(lang + QStringLiteral(":\n") + problems.join(QLatin1Char('\n'))));

        // English: simlab's text as it is (the CLI's, the docs').
        applyLanguage(QStringLiteral("en"));
        for (const std::string& name : names) QCOMPARE(regionNoteSentence(name), QString::fromStdString(simlab::regionNote(name)));
        for (const simlab::SpectrumPoints& p : spectra) QCOMPARE(spectrumSentence(p), QString::fromStdString(p.methodText));
        for (const simlab::StepMargin& m : margins) QCOMPARE(marginSentence(m), QString::fromStdString(m.text));
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
