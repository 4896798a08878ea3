#include "ui/lessons.h"

#include <QFile>
#include <QObject>
#include <QRegularExpression>

#include "ui/language.h"

// The texts are in the UI library's resources; a static library needs them registered by name.
static void initLessonResources() {
    static const bool once = [] {
        Q_INIT_RESOURCE(elastic_lab);
        return true;
    }();
    (void)once;
}

namespace elui {

namespace {
Lesson make(const QString& id, const QString& title, const QString& scene, QList<QPair<simcore::Param, double>> values,
            QStringList integrators, QStringList docks) {
    Lesson l;
    l.id = id;
    l.title = title;
    l.preset.id = QStringLiteral("lesson-") + id;
    l.preset.title = title;
    l.preset.description = QObject::tr("Lessons > Lesson texts explains what to do.");
    l.preset.scene = scene;
    l.preset.values = std::move(values);
    l.preset.integrators = std::move(integrators);
    l.docks = std::move(docks);
    return l;
}
// A lesson on a scene of several bodies: the scene and its --set assignments, rk4.
Lesson makeWorld(const QString& id, const QString& title, const QString& scene, QStringList set, QStringList docks) {
    Lesson l = make(id, title, scene, {}, {QStringLiteral("rk4")}, std::move(docks));
    l.preset.worldSet = std::move(set);
    return l;
}
}  // namespace

QList<Lesson> lessons() {
    const QString bars = QStringLiteral("energy-bars");
    const QString pv = QStringLiteral("pv");
    const QString map = QStringLiteral("stability-map");
    return {
        // The perturbation is the stability scan's (0.01 m, seed 1): the run in the window is
        // the scan's trial run at the DT the student sets.
        make(QStringLiteral("euler-limit"), QObject::tr("1. How large may DT be for Euler?"), QStringLiteral("ring2d"),
             {{simcore::Param::Perturb, 0.01}, {simcore::Param::Dt, 0.007}}, {QStringLiteral("euler")}, {bars, map}),
        make(QStringLiteral("energy-drift"), QObject::tr("2. Energy drift: Euler, midpoint, RK4"),
             QStringLiteral("ring2d"), {{simcore::Param::Dt, 0.003}},
             {QStringLiteral("euler"), QStringLiteral("midpoint"), QStringLiteral("rk4")}, {bars}),
        make(QStringLiteral("heavy-inner"), QObject::tr("3. A heavy inner layer: liquid motion"),
             QStringLiteral("sphere3d"), {{simcore::Param::Subdivisions, 2}, {simcore::Param::MassInner, 5.0}}, {QStringLiteral("rk4")}, {bars}),
        make(QStringLiteral("refine-sphere"), QObject::tr("4. A finer sphere needs a smaller DT"),
             QStringLiteral("sphere3d"), {{simcore::Param::Subdivisions, 1}, {simcore::Param::Perturb, 0.01}, {simcore::Param::Dt, 0.006}},
             {QStringLiteral("rk4")}, {map}),
        make(QStringLiteral("pv-isotherm"), QObject::tr("5. Pressure and volume on the isotherm"),
             QStringLiteral("ring2d"), {}, {QStringLiteral("rk4")}, {pv}),
        make(QStringLiteral("restitution"), QObject::tr("6. Restitution: a particle and a body"),
             QStringLiteral("ring2d"), {{simcore::Param::Restitution, 0.9}, {simcore::Param::Ks, 4000.0}, {simcore::Param::Rks, 4000.0}},
             {QStringLiteral("rk4")}, {bars}),
        make(QStringLiteral("stiff-springs"), QObject::tr("7. Stiff springs: explicit against implicit"),
             QStringLiteral("ring2d"), {{simcore::Param::Ks, 1e6}, {simcore::Param::Dt, 0.01}},
             {QStringLiteral("implicit-euler"), QStringLiteral("rk4")}, {map}),
        make(QStringLiteral("why-symplectic"), QObject::tr("8. Why symplectic? Energy over ten thousand periods"),
             QStringLiteral("spring1d"), {{simcore::Param::Kd, 0.0}, {simcore::Param::Dt, 0.01}},
             {QStringLiteral("verlet"), QStringLiteral("yoshida4"), QStringLiteral("rk4")}, {bars}),
        makeWorld(QStringLiteral("balloons-collide"), QObject::tr("9. Two balloons collide: momentum and energy"),
                  QStringLiteral("collide2d"), {QStringLiteral("gravity=0"), QStringLiteral("body2.mass=4")},
                  {QStringLiteral("bodies")}),
        makeWorld(QStringLiteral("soft-stack"), QObject::tr("10. A soft stack: how the bottom body carries the others"),
                  QStringLiteral("stack3d"),
                  {QStringLiteral("subdivisions=1"), QStringLiteral("pressure=300"), QStringLiteral("kd=40"),
                   QStringLiteral("rkd=120")},
                  {QStringLiteral("bodies"), QStringLiteral("energy-bars")}),
    };
}

const Lesson* findLesson(const QString& id) {
    // Made again when the language changes (the titles are translated): the command line's help
    // lists the lessons before the language is chosen.
    static QList<Lesson> all;
    static QString madeIn;
    if (all.isEmpty() || madeIn != currentLanguage()) {
        all = lessons();
        madeIn = currentLanguage();
    }
    for (const Lesson& l : all)
        if (l.id == id) return &l;
    return nullptr;
}

QStringList lessonIds() {
    QStringList ids;
    for (const Lesson& l : lessons()) ids << l.id;
    return ids;
}

QString Lesson::html() const {
    initLessonResources();
    QFile file(QStringLiteral(":/lessons/%1.html").arg(id));
    if (!file.open(QIODevice::ReadOnly)) return {};
    return QString::fromUtf8(file.readAll());
}

QStringList lessonSectionTitles() {
    return {QObject::tr("Goal"), QObject::tr("What to do"), QObject::tr("What to look at"),
            QObject::tr("The measured answer"), QObject::tr("Why")};
}

QStringList lessonSections(const QString& html) {
    static const QRegularExpression h3(QStringLiteral("<h3[^>]*>(.*?)</h3>"),
                                       QRegularExpression::DotMatchesEverythingOption);
    QStringList out;
    for (auto it = h3.globalMatch(html); it.hasNext();) out << it.next().captured(1).trimmed();
    return out;
}

QMap<QString, LessonAnswer> lessonAnswers(const QString& html, QString* error) {
    // <span class="answer" data-key="K" data-tol="T">V</span>, attributes in this order.
    static const QRegularExpression span(
        QStringLiteral("<span class=\"answer\" data-key=\"([^\"]+)\" data-tol=\"([^\"]+)\">([^<]*)</span>"));
    QMap<QString, LessonAnswer> out;
    auto fail = [&](const QString& message) {
        if (error && error->isEmpty()) *error = message;
    };
    for (auto it = span.globalMatch(html); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        const QString key = m.captured(1);
        bool okValue = false, okTol = false;
        // A minus sign may be written as U+2212 in the text, and the German, French and Spanish
        // texts write a decimal comma.
        QString number = m.captured(3).trimmed();
        number.replace(QChar(0x2212), QLatin1Char('-'));
        number.replace(QLatin1Char(','), QLatin1Char('.'));
        const LessonAnswer answer{number.toDouble(&okValue), m.captured(2).toDouble(&okTol)};
        if (out.contains(key)) fail(QStringLiteral("answer %1 is marked twice").arg(key));
        else if (!okValue) fail(QStringLiteral("answer %1 is not a number: %2").arg(key, m.captured(3)));
        else if (!okTol || answer.relativeTolerance <= 0.0 || answer.relativeTolerance > 0.2)
            fail(QStringLiteral("answer %1 has no tolerance in (0, 0.2]: %2").arg(key, m.captured(2)));
        else out.insert(key, answer);
    }
    return out;
}

QList<LessonValue> lessonValues(const QString& html) {
    static const QRegularExpression span(
        QStringLiteral("<span class=\"(setting|try)\" data-key=\"([^\"]+)\">([^<]*)</span>"));
    QList<LessonValue> out;
    for (auto it = span.globalMatch(html); it.hasNext();) {
        const QRegularExpressionMatch m = it.next();
        LessonValue v;
        v.kind = m.captured(1);
        v.key = m.captured(2);
        v.value = QString(m.captured(3).trimmed()).replace(QLatin1Char(','), QLatin1Char('.')).toDouble(&v.valid);
        out << v;
    }
    return out;
}

QString lessonSection(const QString& html, const QString& title) {
    const QString open = QStringLiteral("<h3>%1</h3>").arg(title);
    const qsizetype from = html.indexOf(open);
    if (from < 0) return {};
    const qsizetype start = from + open.size();
    const qsizetype next = html.indexOf(QStringLiteral("<h3"), start);
    return html.mid(start, next < 0 ? -1 : next - start);
}

QList<double> lessonUntil(const QString& html) {
    static const QRegularExpression span(QStringLiteral("<span class=\"until\">([^<]*)</span>"));
    QList<double> out;
    for (auto it = span.globalMatch(html); it.hasNext();) {
        bool ok = false;
        const double t = it.next().captured(1).trimmed().replace(QLatin1Char(','), QLatin1Char('.')).toDouble(&ok);
        if (ok) out << t;
    }
    return out;
}

}  // namespace elui
