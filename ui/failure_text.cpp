#include "ui/failure_text.h"

#include <cmath>

#include <QCoreApplication>
#include <QRegularExpression>

#include "simcore/failure_texts.h"
#include "ui/language.h"

namespace elui {

namespace {

// A number as std::ostream wrote it (default format), shown in the window's format.
QString number(const QString& written) {
    bool ok = false;
    const double value = written.toDouble(&ok);
    return ok ? num(value) : written;  // inf, nan: as written
}

const QString kNumber = QStringLiteral("([-+]?(?:[0-9]*\\.?[0-9]+(?:[eE][-+]?[0-9]+)?|inf|nan))");

QRegularExpression sentence(const QString& pattern) {
    return QRegularExpression(QStringLiteral("^") + pattern + QStringLiteral("$"));
}

QString layerPhrase(const QString& layer) {
    if (layer == QLatin1String("inner")) return QCoreApplication::translate("FailureText", "the inner layer");
    if (layer == QLatin1String("outer")) return QCoreApplication::translate("FailureText", "the outer layer");
    return QCoreApplication::translate("FailureText", "the layer");
}

QString layerLost(const QRegularExpressionMatch& m) {
    const bool insideOut = m.captured(3) == QLatin1String("turned inside out");
    const bool area = m.captured(4) == QLatin1String("area");
    const char* text = insideOut ? (area ? QT_TRANSLATE_NOOP("FailureText", "%1 turned inside out (its area is %2, rest %3)")
                                         : QT_TRANSLATE_NOOP("FailureText", "%1 turned inside out (its volume is %2, rest %3)"))
                                 : (area ? QT_TRANSLATE_NOOP("FailureText", "%1 collapsed (its area is %2, rest %3)")
                                         : QT_TRANSLATE_NOOP("FailureText", "%1 collapsed (its volume is %2, rest %3)"));
    const QString said = QCoreApplication::translate("FailureText", text).arg(layerPhrase(m.captured(2)), number(m.captured(5)), number(m.captured(6)));
    if (m.captured(1).isEmpty()) return said;
    return QCoreApplication::translate("FailureText", "body %1: %2").arg(m.captured(1), said);
}

}  // namespace

QString failureReason(const std::string& reason) {
    const QString english = QString::fromStdString(reason);
    if (currentLanguage() == QLatin1String("en")) return english;
    if (reason == simcore::failure_text::nonFinite())
        return QCoreApplication::translate("FailureText", "the state became non-finite (NaN or infinity): the step is far too large for these forces");
    if (reason == simcore::failure_text::kRk45MinimumStep)
        return QCoreApplication::translate("FailureText", "rk45: the step size fell below the minimum step; the tolerance cannot be met (the system is too stiff "
                  "or singular)");
    if (reason == simcore::failure_text::kImplicitEulerNoConvergence)
        return QCoreApplication::translate("FailureText", "implicit-euler: the linear solve (conjugate gradient) did not converge; the linearised system is not "
                  "positive definite at this step (the body is too deformed or the step too large)");
    static const QRegularExpression velocity =
        sentence(QStringLiteral("runaway velocity: a particle moves %1 m/s, farther than the whole box in one step").arg(kNumber));
    static const QRegularExpression energy = sentence(
        QStringLiteral("runaway energy: kinetic \\+ elastic energy %1 J exceeds %1 J \\(%1 x the body's energy scale\\)").arg(kNumber));
    static const QRegularExpression layer =
        sentence(QStringLiteral("(?:body ([0-9]+): )?the (inner|outer|single) layer (turned inside out|collapsed) \\(its "
                                "(area|volume) is %1, rest %1\\)")
                     .arg(kNumber));
    static const QRegularExpression notFinite = sentence(QStringLiteral("the state is no longer finite \\(particle ([0-9]+)\\)"));
    static const QRegularExpression wall =
        sentence(QStringLiteral("particle ([0-9]+) reached a wall: the float path has no contact \\(use precision double\\)"));
    if (const auto m = velocity.match(english); m.hasMatch())
        return QCoreApplication::translate("FailureText", "runaway velocity: a particle moves %1 m/s, farther than the whole box in one step").arg(number(m.captured(1)));
    if (const auto m = energy.match(english); m.hasMatch())
        return QCoreApplication::translate("FailureText", "runaway energy: kinetic + elastic energy %1 J exceeds %2 J (%3 × the body's energy scale)")
            .arg(number(m.captured(1)), number(m.captured(2)), number(m.captured(3)));
    if (const auto m = layer.match(english); m.hasMatch()) return layerLost(m);
    static const QRegularExpression crossed = sentence(
        QStringLiteral("(?:body ([0-9]+)'s outer layer passed through itself|bodies ([0-9]+) and ([0-9]+) intersect \\(their "
                       "outer layers crossed\\)) in a step of %1 s: the step is too large for this impact \\(a smaller dt, "
                       "or an adaptive integrator, which halves such a step\\)")
            .arg(kNumber));
    if (const auto m = crossed.match(english); m.hasMatch()) {
        if (!m.captured(1).isEmpty())
            return QCoreApplication::translate("FailureText", "body %1's outer layer passed through itself in a step of %2 s: the "
                                               "step is too large for this impact (a smaller dt, or an adaptive integrator, "
                                               "which halves such a step)")
                .arg(m.captured(1), number(m.captured(4)));
        return QCoreApplication::translate("FailureText", "bodies %1 and %2 intersect (their outer layers crossed) in a step of "
                                           "%3 s: the step is too large for this impact (a smaller dt, or an adaptive "
                                           "integrator, which halves such a step)")
            .arg(m.captured(2), m.captured(3), number(m.captured(4)));
    }
    if (const auto m = notFinite.match(english); m.hasMatch())
        return QCoreApplication::translate("FailureText", "the state is no longer finite (particle %1)").arg(m.captured(1));
    if (const auto m = wall.match(english); m.hasMatch())
        return QCoreApplication::translate("FailureText", "particle %1 reached a wall: the float path has no contact (use precision double)").arg(m.captured(1));
    return english;
}

namespace {

QString basisPhrase(const simlab::StabilityVerdict& v) {
    using Basis = simlab::StabilityVerdict::Basis;
    switch (v.basisKind) {
        case Basis::ExactSpectrum:
            return QCoreApplication::translate("FailureText", "exact spectrum, %1 eigenvalues").arg(v.basisValues);
        case Basis::Arnoldi:
            return QCoreApplication::translate("FailureText", "Arnoldi, %1 Ritz values of %2").arg(v.basisValues).arg(v.basisOf);
        case Basis::StepMatrix: return QCoreApplication::translate("FailureText", "exact step matrix");
        case Basis::Modes: break;
    }
    return QCoreApplication::translate("FailureText", "modes of M^-1 K");
}

}  // namespace

QString verdictSentence(const simlab::StabilityVerdict& v) {
    if (currentLanguage() == QLatin1String("en")) return QString::fromStdString(simlab::verdictText(v));
    const QString method = QString::fromStdString(v.integrator);
    if (v.ownStep)
        return QCoreApplication::translate("FailureText", "%1 chooses its own step: no DT limit from stability").arg(method);
    if (std::isinf(v.limit))
        return QCoreApplication::translate("FailureText", "%1 is stable at every DT on this body").arg(method);
    if (!(v.limit > 0.0))
        return QCoreApplication::translate("FailureText",
                                           "%1 has no stable DT on this body: its undamped modes grow for every DT (%2)")
            .arg(method, basisPhrase(v));
    return QCoreApplication::translate("FailureText", "%1 is stable up to DT = %2 s on this body (%3)")
        .arg(method, num(v.limit, 'g', 3), basisPhrase(v));
}

QString adviceSentence(const simlab::StabilityAdvice& a) {
    if (currentLanguage() == QLatin1String("en")) return QString::fromStdString(a.message);
    const QString method = QString::fromStdString(a.verdict.integrator);
    if (a.noStableStep)
        return QCoreApplication::translate("FailureText",
                                           "%1 has no stable step on this body's undamped modes (highest w = %2 rad/s): its "
                                           "energy grows for every dt, here by ~%3 per second; use dt <= %4 s (growth below "
                                           "1 per second) or another method")
            .arg(method, num(a.omegaMax, 'g', 3), num(a.growthPerSecond, 'g', 2), num(a.suggestedDt, 'g', 2));
    return QCoreApplication::translate("FailureText",
                                       "dt = %1 s is above %2's largest stable step on this body, %3 s (linearised: %4; "
                                       "fastest |lambda| = %5 1/s); it will likely blow up (implicit-euler or rk45 will not)")
        .arg(num(a.verdict.dt), method, num(a.verdict.limit, 'g', 3), basisPhrase(a.verdict),
             num(std::abs(a.verdict.fastest), 'g', 3));
}

}  // namespace elui
