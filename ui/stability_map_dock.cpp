#include "ui/stability_map_dock.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <QCoreApplication>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QVBoxLayout>

#include "qcustomplot.h"
#include "ui/language.h"
#include "ui/mailbox.h"

namespace elui {

namespace {

using Complex = std::complex<double>;

constexpr int kFillCells = 260;          // the region's fill: cells per axis
constexpr double kScanDuration = 2.0;    // "Try it": each trial runs this long [s]

// The parameters with DT replaced: two bodies are the same linearisation when these agree.
simcore::ParameterSet withoutDt(const simcore::ParameterSet& p) {
    simcore::ParameterSet q = p;
    q.set(simcore::Param::Dt, simcore::ParameterSet(p.kind()).get(simcore::Param::Dt));
    return q;
}

// The same world but for DT (the one linearisation), and the same world exactly.
bool sameWorld(const std::optional<simcore::WorldSpec>& a, const std::optional<simcore::WorldSpec>& b, bool dt) {
    if (a.has_value() != b.has_value()) return false;
    if (!a) return true;
    if (a->bodies.size() != b->bodies.size()) return false;
    for (std::size_t k = 0; k < a->bodies.size(); ++k) {
        const simcore::WorldBodySpec &x = a->bodies[k], &y = b->bodies[k];
        if (x.position != y.position || x.velocity != y.velocity) return false;
        if (dt ? !(x.params == y.params) : !(withoutDt(x.params) == withoutDt(y.params))) return false;
    }
    return true;
}

QString seconds(double s) { return num(s, 'g', 3); }

// A view's colour on the map (its edge, when it is not the primary one).
QColor viewColor(int view) {
    static const QColor colors[] = {QColor(30, 110, 40), QColor(190, 90, 0), QColor(130, 40, 160)};
    return colors[view % 3];
}

QString tryTip() {
    return StabilityMapDock::tr("Measure this integrator's largest stable DT on this body or world: the stability "
                                "scan's bisection (%1 s runs; Studies → Stability scan does all integrators), marked "
                                "on the picture")
        .arg(kScanDuration);
}

// The legend's and the notes' font: 85 % of the dock's, at least 6 pt.
QFont smaller(const QFont& font) {
    QFont small = font;
    small.setPointSizeF(std::max(6.0, font.pointSizeF() * 0.85));
    return small;
}

// The mode that limits DT (R methods), as simlab::stepMarginText names it.
QString limitingMode(const simlab::StepMargin& m) {
    if (!m.hasLimiting) return StabilityMapDock::tr("the fastest mode");
    const Complex z = m.limitingPoint();
    if (m.limitingIsReal())
        return (m.limitingIsFastest ? StabilityMapDock::tr("the fastest mode (hλ = %1, a pure decay)")
                                    : StabilityMapDock::tr("the mode (hλ = %1, a pure decay)"))
            .arg(num(z.real(), 'g', 3));
    return (m.limitingIsFastest ? StabilityMapDock::tr("the fastest mode (hλ = %1 ± %2i)")
                                : StabilityMapDock::tr("the mode (hλ = %1 ± %2i)"))
        .arg(num(z.real(), 'g', 3), num(std::abs(z.imag()), 'g', 3));
}

}  // namespace

QString marginSentence(const simlab::StepMargin& m) {
    if (currentLanguage() == QLatin1String("en")) return QString::fromStdString(m.text);
    using Case = simlab::StepMargin::Case;
    // The oscillator methods' basis (predictedStableStep's): their exact step matrix (in the
    // verdict's words, failure_text.cpp), or each mode.
    QString basis = StabilityMapDock::tr("per mode, modal damping");
    if (m.exactStepMatrix) basis = QCoreApplication::translate("FailureText", "exact step matrix");
    const QString factor = num(m.factor, 'f', 2), shrink = num(1.0 / m.factor, 'f', 2), limit = seconds(m.factor * m.dt);
    switch (m.kind) {
        case Case::Xpbd: return StabilityMapDock::tr("xpbd is stable at every DT: no margin to give.");
        case Case::OwnStep:
            return StabilityMapDock::tr("%1 chooses its own internal steps: no DT limit from stability.").arg(QString::fromStdString(m.integrator));
        case Case::Unlimited: return StabilityMapDock::tr("No DT limit: every mode of this body stays in the region for any DT.");
        case Case::NoStableDt:
            if (m.oscillator) return StabilityMapDock::tr("No DT is stable: a mode pair grows for every DT (%1).").arg(basis);
            return StabilityMapDock::tr("No DT is stable: %1 sits where the region only touches the imaginary axis at 0; it grows "
                                        "for every DT (slowly when DT is small).")
                .arg(limitingMode(m));
        case Case::CanGrow:
            if (m.oscillator)
                return StabilityMapDock::tr("DT can grow %1× (to %2 s) before a mode pair goes unstable (%3); the picture is exact "
                                            "for underdamped modes only.")
                    .arg(factor, limit, basis);
            return StabilityMapDock::tr("DT can grow %1× (to %2 s) before %3 leaves the region.").arg(factor, limit, limitingMode(m));
        case Case::Outside:
            if (m.oscillator)
                return StabilityMapDock::tr("DT is already outside the stable range (%1): shrink DT by %2× (to %3 s).")
                    .arg(basis, shrink, limit);
            return StabilityMapDock::tr("DT is already outside: %1 is out of the region; shrink DT by %2× (to %3 s) to bring it back.")
                .arg(limitingMode(m), shrink, limit);
    }
    return QString::fromStdString(m.text);
}

QString spectrumSentence(const simlab::SpectrumPoints& p) {
    if (currentLanguage() == QLatin1String("en")) return QString::fromStdString(p.methodText);
    const QString count = num(static_cast<long long>(p.count));
    switch (p.kind) {
        case simlab::SpectrumPoints::Method::Exact:
            return StabilityMapDock::tr("exact spectrum: all %1 eigenvalues of the linearised first-order system (dense "
                                        "eigen-solve)")
                .arg(count);
        case simlab::SpectrumPoints::Method::Modal:
            return StabilityMapDock::tr("modal: all %1 modes of M⁻¹K (symmetric eigen-solve), damping c = φᵀ(M⁻¹D)φ per mode; "
                                        "λ = −c/2 ± i√(ω² − c²/4)")
                .arg(count);
        case simlab::SpectrumPoints::Method::Iterative: break;
    }
    return StabilityMapDock::tr("iterative: %1 Ritz values of the first-order system, Arnoldi (%2 steps) on the Jacobian "
                                "products, %3 free coordinates: the extreme eigenvalues (largest |λ|) are accurate, inner "
                                "ones are not")
        .arg(count, num(static_cast<long long>(p.arnoldiSteps)), num(static_cast<long long>(p.freeCoordinates)));
}

QString regionNoteSentence(const std::string& integrator) {
    if (currentLanguage() == QLatin1String("en")) return QString::fromStdString(simlab::regionNote(integrator));
    using Kind = simlab::RegionNoteParts::Kind;
    const simlab::RegionNoteParts parts = simlab::regionNoteParts(integrator);
    switch (parts.kind) {
        case Kind::TaylorPolynomial:
            if (parts.imaginaryReach > 0.0)
                return StabilityMapDock::tr("Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of "
                                            "e^z); it touches the imaginary axis up to ±%1i: undamped modes are stable up "
                                            "to hω = 2√2.")
                    .arg(num(parts.imaginaryReach, 'g', 3));
            return StabilityMapDock::tr("Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of e^z); "
                                        "it touches the imaginary axis only at 0: an undamped mode grows for every DT.");
        case Kind::DormandPrince:
            return StabilityMapDock::tr("Region: |R(hλ)| ≤ 1 for Dormand–Prince's 5th-order solution, R = Taylor to z⁵ + "
                                        "z⁶/600, taken at a fixed step. The adaptive run picks its own step from the error "
                                        "tolerance: it does not blow up, it takes smaller steps.");
        case Kind::ImplicitEuler:
            return StabilityMapDock::tr("Region: |1/(1 − hλ)| ≤ 1, everything outside the disc |1 − hλ| < 1, the whole left "
                                        "half-plane (A-stable): no DT limit from stability.");
        case Kind::SymplecticEuler:
            return StabilityMapDock::tr("Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄ "
                                        "(exact when the modes decouple; the real axis shows the critically damped mode). "
                                        "Undamped modes: hω ≤ 2. The margin uses the step matrix, not the picture.");
        case Kind::Verlet:
            return StabilityMapDock::tr("Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄, "
                                        "damping at the half-step velocity (exact when the modes decouple; the real axis "
                                        "shows the critically damped mode). Undamped modes: hω ≤ 2. The margin uses the "
                                        "step matrix, not the picture.");
        case Kind::Composition:
            return StabilityMapDock::tr("Region: no scalar R; the step is a product of %1 Verlet substeps (some backwards), "
                                        "drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄ (damping at the "
                                        "half-kick velocity, as the integrator does), traced ray by ray from 0. Undamped "
                                        "modes: hω ≤ %2 (a step costs %3 force evaluations). The margin uses the step "
                                        "matrix, not the picture.")
                .arg(num(static_cast<long long>(parts.substeps)), num(parts.undampedLimit, 'g', 3),
                     num(static_cast<long long>(parts.forceEvaluations)));
        case Kind::CvodeBdf:
            return StabilityMapDock::tr("No region: adaptive variable-order BDF (orders 1–5): error-controlled, no fixed "
                                        "region. BDF1–2 are A-stable, BDF3–5 A(α)-stable down to α ≈ 51°; CVODE shrinks the "
                                        "step or the order when a mode threatens: no DT limit, DT is only the output "
                                        "interval.");
        case Kind::CvodeAdams:
            return StabilityMapDock::tr("No region: adaptive variable-order Adams (orders 1–12): error-controlled, no fixed "
                                        "region. Its regions are small (explicit-like); CVODE keeps the internal step inside "
                                        "them by its error test: no DT limit, stiff bodies only cost steps.");
        case Kind::Xpbd:
            return StabilityMapDock::tr("No region: XPBD projects the springs as compliant constraints (compliance 1/ks): "
                                        "unconditionally stable, no region in the hλ plane; large DT costs accuracy (the "
                                        "body turns soft), not stability.");
        case Kind::Unknown: break;
    }
    return StabilityMapDock::tr("No stability region for %1.").arg(QString::fromStdString(integrator));
}

StabilityMapDock::StabilityMapDock(QWidget* parent) : QDockWidget(tr("Stability map"), parent) {
    setObjectName(QStringLiteral("StabilityMapDock"));
    m_fromWorker = new Mailbox(this);
    auto* host = new QWidget(this);
    auto* layout = new QVBoxLayout(host);
    layout->setContentsMargins(4, 4, 4, 4);

    createPlot(host);
    layout->addWidget(m_plot, 1);

    m_marginLabel = new QLabel(host);
    m_marginLabel->setObjectName(QStringLiteral("stabilityMargin"));
    m_marginLabel->setWordWrap(true);
    QFont bold = font();
    bold.setBold(true);
    m_marginLabel->setFont(bold);
    layout->addWidget(m_marginLabel);
    m_methodLabel = new QLabel(host);
    m_methodLabel->setObjectName(QStringLiteral("stabilityMethod"));
    m_methodLabel->setWordWrap(true);
    m_methodLabel->setFont(smaller(font()));
    layout->addWidget(m_methodLabel);
    auto* row = new QHBoxLayout;
    m_try = new QPushButton(tr("Try it"), host);
    m_try->setObjectName(QStringLiteral("stabilityTryIt"));
    m_try->setToolTip(tryTip());
    m_try->setEnabled(false);
    row->addWidget(m_try, 0, Qt::AlignTop);
    m_measuredLabel = new QLabel(host);
    m_measuredLabel->setObjectName(QStringLiteral("stabilityMeasured"));
    m_measuredLabel->setWordWrap(true);
    m_measuredLabel->setFont(smaller(font()));
    row->addWidget(m_measuredLabel, 1);
    layout->addLayout(row);
    setWidget(host);
    m_marginLabel->setText(tr("Waiting for a body…"));

    connect(m_try, &QPushButton::clicked, this, &StabilityMapDock::tryIt);
    connect(this, &QDockWidget::visibilityChanged, this, [this](bool visible) {
        if (visible) request();
    });
}

void StabilityMapDock::createPlot(QWidget* host) {
    m_plot = new QCustomPlot(host);
    m_plot->setObjectName(QStringLiteral("stabilityMapPlot"));
    m_plot->setAccessibleName(tr("Stability map"));
    m_plot->setAccessibleDescription(tr("The integrator's stability region and the body's eigenvalues times DT; the "
                                        "margin is written below the map"));
    m_plot->setMinimumSize(260, 240);
    m_plot->xAxis->setLabel(tr("Re(hλ)"));
    m_plot->yAxis->setLabel(tr("Im(hλ)"));
    const QPen zeroPen(QColor(120, 120, 120), 1.0);
    m_plot->xAxis->grid()->setZeroLinePen(zeroPen);
    m_plot->yAxis->grid()->setZeroLinePen(zeroPen);
    // The region: a 0/1 grid, light green where the method is stable (the exact edge is the
    // boundary line drawn over it).
    m_fill = new QCPColorMap(m_plot->xAxis, m_plot->yAxis);
    QCPColorGradient gradient;
    gradient.setColorStopAt(0.0, QColor(255, 255, 255, 0));
    gradient.setColorStopAt(1.0, QColor(196, 232, 190));
    gradient.setLevelCount(2);
    m_fill->setGradient(gradient);
    m_fill->setDataRange(QCPRange(0.0, 1.0));
    m_fill->setInterpolate(false);
    m_fill->setName(tr("stable region"));
    m_fill->removeFromLegend();  // the boundary's entry says it (a colour map has no legend icon)
    m_points = m_plot->addGraph();
    m_points->setLineStyle(QCPGraph::lsNone);
    m_points->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssDisc, QColor(30, 80, 200), 5));
    m_points->setName(tr("DT·λ, every mode"));
    m_limiting = m_plot->addGraph();
    m_limiting->setLineStyle(QCPGraph::lsNone);
    m_limiting->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCircle, QPen(QColor(200, 110, 0), 2.0), Qt::NoBrush, 13));
    m_limiting->setName(tr("leaves first"));
    m_measured = m_plot->addGraph();
    m_measured->setLineStyle(QCPGraph::lsNone);
    m_measured->setScatterStyle(QCPScatterStyle(QCPScatterStyle::ssCross, QPen(QColor(210, 30, 30), 2.5), Qt::NoBrush, 14));
    m_measured->setName(tr("measured limit"));
    // Equal scales, checked on the axis rect the plot is about to draw into (its size is known
    // only once the layout has run: tick labels and the legend take their share first).
    connect(m_plot, &QCustomPlot::afterLayout, this, &StabilityMapDock::keepEqualAspect);
    m_measured->removeFromLegend();
    m_plot->legend->setVisible(true);
    m_plot->legend->setFont(smaller(font()));
    m_plot->legend->setBrush(QColor(255, 255, 255, 210));
    m_plot->axisRect()->insetLayout()->setInsetAlignment(0, Qt::AlignTop | Qt::AlignLeft);
}

StabilityMapDock::~StabilityMapDock() {
    if (m_scanCancel) m_scanCancel->store(true);
    if (m_jobThread.joinable()) m_jobThread.join();
    if (m_scanThread.joinable()) m_scanThread.join();
}

void StabilityMapDock::setState(const simcore::ParameterSet& params, const QString& integrator) {
    setState(params, QStringList{integrator});
}

void StabilityMapDock::setWorld(const simcore::WorldSpec& world, const QStringList& integrators) {
    if (integrators.isEmpty() || world.bodies.empty()) return;
    const std::optional<simcore::WorldSpec> wanted(world);
    if (m_hasState && sameWorld(wanted, m_world, true) && integrators == m_integrators) return;
    m_world = wanted;
    m_params = world.bodies.front().params;  // the world's DT (shared by every body)
    m_integrators = integrators;
    m_integrator = integrators.front();
    m_hasState = true;
    request();
}

void StabilityMapDock::setState(const simcore::ParameterSet& params, const QStringList& integrators) {
    if (integrators.isEmpty()) return;
    if (m_hasState && !m_world && params == m_params && integrators == m_integrators) return;
    m_world.reset();
    m_params = params;
    m_integrators = integrators;
    m_integrator = integrators.front();
    m_hasState = true;
    request();
}

QStringList StabilityMapDock::overlaidIntegrators() const {
    QStringList names;
    for (const std::string& n : m_shownIntegrators)
        if (n != m_shownIntegrator) names << QString::fromStdString(n);
    return names;
}

int StabilityMapDock::pointCount() const { return m_points->data()->size(); }

int StabilityMapDock::boundaryPointCount() const {
    int n = 0;
    for (const QCPCurve* c : m_boundary) n += c->data()->size();
    return n;
}

Complex StabilityMapDock::point(int i) const {
    const QCPGraphData& d = *(m_points->data()->constBegin() + i);
    return {d.key, d.value};
}

QString StabilityMapDock::marginText() const { return m_marginLabel->text(); }
QString StabilityMapDock::methodText() const { return m_methodLabel->text(); }
QString StabilityMapDock::measuredText() const { return m_measuredLabel->text(); }

void StabilityMapDock::request() {
    if (!m_hasState || !isVisible()) return;
    if (m_jobRunning) {
        m_jobPending = true;
        return;
    }
    std::vector<std::string> integrators;
    for (const QString& name : m_integrators) integrators.push_back(name.toStdString());
    if (m_resultSerial > 0 && m_params == m_shownParams && sameWorld(m_world, m_shownWorld, true) &&
        integrators == m_shownIntegrators)
        return;
    Job job{m_params, m_world, integrators, nullptr};
    if (m_modes && m_resultSerial > 0 && withoutDt(m_params) == withoutDt(m_shownParams) &&
        sameWorld(m_world, m_shownWorld, false))
        job.modes = m_modes;
    startJob(std::move(job));
}

void StabilityMapDock::startJob(Job job) {
    m_jobRunning = true;
    if (m_resultSerial == 0 || !sameWorld(job.world, m_shownWorld, false))
        m_marginLabel->setText(job.world ? tr("Linearising the world (%1 bodies)…").arg(job.world->bodies.size())
                                         : tr("Linearising the body…"));
    if (m_jobThread.joinable()) m_jobThread.join();  // the last job ended (its result was delivered)
    m_jobThread = std::thread([this, job = std::move(job)] {
        Result r;
        r.params = job.params;
        r.world = job.world;
        r.integrators = job.integrators;
        r.modes = job.modes ? job.modes
                            : std::make_shared<const simlab::LinearModes>(job.world ? simlab::stabilityModes(*job.world)
                                                                                    : simlab::stabilityModes(job.params));
        r.points = simlab::spectrumPoints(*r.modes);
        // Every view on the same points; the primary one is the first with the smallest margin.
        for (const std::string& name : job.integrators)
            r.views.push_back(View{name, simlab::stepMargin(name, *r.modes, r.points, job.params.get(simcore::Param::Dt)),
                                   simlab::regionBoundary(name)});
        std::size_t primary = 0;
        for (std::size_t v = 1; v < r.views.size(); ++v)
            if (r.views[v].margin.factor < r.views[primary].margin.factor) primary = v;
        r.integrator = r.views[primary].integrator;
        r.margin = r.views[primary].margin;
        r.boundary = r.views[primary].boundary;
        m_fromWorker->post([this, r] {
            m_jobRunning = false;
            present(r);
            if (m_jobPending) {
                m_jobPending = false;
                request();
            }
        });
    });
}

void StabilityMapDock::present(const Result& r) {
    m_shownParams = r.params;
    m_shownWorld = r.world;
    m_shownIntegrator = r.integrator;
    m_shownIntegrators = r.integrators;
    m_shownDt = r.params.get(simcore::Param::Dt);
    m_modes = r.modes;
    m_spectrum = r.points;
    m_margin = r.margin;
    m_curves = r.boundary;
    const bool hasRegion = simlab::regionKind(r.integrator) != simlab::RegionKind::None;
    drawEdges(r, hasRegion);
    drawEigenvalues(hasRegion);
    const QString name = QString::fromStdString(r.integrator);
    describe(r);
    m_try->setEnabled(hasRegion || m_scanRunning);
    m_try->setToolTip(hasRegion ? tryTip() : tr("%1 has no fixed stability limit to measure").arg(name));
    // A measured limit holds for the body (or world) and the method, whatever DT is now.
    if (m_scanRow && !(withoutDt(m_scanParams) == withoutDt(m_shownParams) && sameWorld(m_scanWorld, m_shownWorld, false) &&
                       m_scanIntegrator == m_shownIntegrator)) {
        m_scanRow.reset();
        m_measuredText.clear();
    }
    showMeasured();
    fitView();
    ++m_resultSerial;
    m_plot->replot(QCustomPlot::rpQueuedReplot);
}

// The region's edge (filled when the method has one), and the other views' edges dashed.
void StabilityMapDock::drawEdges(const Result& r, bool hasRegion) {
    for (QCPCurve* c : m_boundary) m_plot->removePlottable(c);
    m_boundary.clear();
    for (const auto& curve : m_curves) {
        auto* c = new QCPCurve(m_plot->xAxis, m_plot->yAxis);
        QVector<QCPCurveData> points;
        points.reserve(int(curve.size()));
        for (std::size_t i = 0; i < curve.size(); ++i) points.append(QCPCurveData(double(i), curve[i].real(), curve[i].imag()));
        c->data()->set(points, true);
        c->setPen(QPen(QColor(30, 110, 40), 2.0));
        if (m_boundary.empty()) c->setName(simlab::regionKind(r.integrator) == simlab::RegionKind::Oscillator ? tr("edge (radius 1)") : tr("edge |R| = 1"));
        else c->removeFromLegend();
        m_boundary.push_back(c);
    }
    m_fill->setVisible(hasRegion);
    // The other views' edges: dashed, each in its view's colour, named in the legend.
    for (QCPCurve* c : m_overlay) m_plot->removePlottable(c);
    m_overlay.clear();
    for (std::size_t v = 0; v < r.views.size(); ++v) {
        if (r.views[v].integrator == r.integrator) continue;
        bool named = false;
        for (const auto& curve : r.views[v].boundary) {
            auto* c = new QCPCurve(m_plot->xAxis, m_plot->yAxis);
            QVector<QCPCurveData> points;
            points.reserve(int(curve.size()));
            for (std::size_t i = 0; i < curve.size(); ++i)
                points.append(QCPCurveData(double(i), curve[i].real(), curve[i].imag()));
            c->data()->set(points, true);
            c->setPen(QPen(viewColor(int(v)), 2.0, Qt::DashLine));
            if (!named) c->setName(tr("edge of view %1 (%2)").arg(v + 1).arg(QString::fromStdString(r.views[v].integrator)));
            else c->removeFromLegend();
            named = true;
            m_overlay.push_back(c);
        }
    }
}

// The eigenvalues times DT, and the limiting pair marked where the method has a region.
void StabilityMapDock::drawEigenvalues(bool hasRegion) {
    QVector<double> xs, ys;
    for (const Complex& l : m_spectrum.lambda) {
        xs.append(m_shownDt * l.real());
        ys.append(m_shownDt * l.imag());
    }
    m_points->setData(xs, ys);
    m_limiting->data()->clear();
    if (m_margin.hasLimiting && hasRegion) {
        const Complex z = m_shownDt * m_margin.limiting;
        m_limiting->addData(z.real(), z.imag());
        m_limiting->addData(z.real(), -z.imag());
    }
    m_limiting->setVisible(m_margin.hasLimiting && hasRegion);
    if (m_limiting->visible()) m_limiting->addToLegend();
    else m_limiting->removeFromLegend();
}

// The axis, each view's margin in words and how the eigenvalues were found.
void StabilityMapDock::describe(const Result& r) {
    const QString name = QString::fromStdString(r.integrator);
    m_plot->xAxis->setLabel(tr("Re(hλ), h = DT = %1 s").arg(num(m_shownDt)));
    if (r.views.size() <= 1) {
        m_marginLabel->setText(QStringLiteral("%1: %2").arg(name, marginSentence(m_margin)));
    } else {
        // Side by side: every view's margin, the primary (smallest margin) first.
        QStringList lines{tr("View %1, %2 (filled): %3")
                              .arg(int(std::find_if(r.views.begin(), r.views.end(),
                                                    [&](const View& v) { return v.integrator == r.integrator; }) -
                                       r.views.begin()) + 1)
                              .arg(name, marginSentence(m_margin))};
        for (std::size_t v = 0; v < r.views.size(); ++v)
            if (r.views[v].integrator != r.integrator)
                lines << tr("View %1, %2 (dashed): %3")
                             .arg(v + 1)
                             .arg(QString::fromStdString(r.views[v].integrator), marginSentence(r.views[v].margin));
        m_marginLabel->setText(lines.join(QLatin1Char('\n')));
    }
    const QString world = r.world ? tr("The whole world (%1 bodies) linearised as one system: every body's modes, "
                                       "and the contact between bodies where two are within the contact skin. ")
                                        .arg(r.world->bodies.size())
                                  : QString();
    m_methodLabel->setText(world + tr("Eigenvalues: %1.\n%2").arg(spectrumSentence(m_spectrum), regionNoteSentence(r.integrator)));
}

void StabilityMapDock::showMeasured() {
    m_measured->data()->clear();
    m_measuredMark.reset();
    if (m_scanRow) {
        const simlab::StabilityRow& row = *m_scanRow;
        QString text;
        if (row.stable <= 0.0) {
            text = tr("Measured: no stable DT down to 1e-5 s.");
        } else {
            text = std::isinf(row.unstable)
                       ? tr("Measured: stable up to the largest DT scanned, %1 s").arg(seconds(row.stable))
                       : tr("Measured: stable at DT = %1 s, blows up at %2 s").arg(seconds(row.stable), seconds(row.unstable));
            text += tr(" (%1 runs of %2 s; predicted %3 s).")
                        .arg(row.runs)
                        .arg(kScanDuration)
                        .arg(std::isinf(row.predicted) ? tr("unlimited") : seconds(row.predicted));
            // The limiting mode (R methods) or the fastest one (oscillator methods) at the
            // measured DT: on its dot's ray, on the boundary when the prediction holds.
            Complex l = m_margin.hasLimiting ? m_margin.limiting : m_margin.fastest;
            if (l != Complex(0.0, 0.0)) {
                if (l.imag() < 0) l = std::conj(l);
                m_measuredMark = row.stable * l;
                m_measured->addData(m_measuredMark->real(), m_measuredMark->imag());
                text += m_margin.hasLimiting ? tr(" ✕ = the ringed mode at the measured DT.")
                                             : tr(" ✕ = the fastest mode at the measured DT.");
            }
        }
        m_measuredText = text;
    }
    m_measured->setVisible(m_measuredMark.has_value());
    if (m_measuredMark) m_measured->addToLegend();
    else m_measured->removeFromLegend();
    m_measuredLabel->setText(m_scanRunning ? tr("Measuring the largest stable DT of %1…").arg(QString::fromStdString(m_scanIntegrator))
                                           : m_measuredText);
}

void StabilityMapDock::fitView() {
    // The region's heart (its boundary within |z| <= 4) and every point, with a margin.
    double x0 = -1.0, x1 = 0.5, y0 = -1.0, y1 = 1.0;
    auto take = [&](Complex z) {
        x0 = std::min(x0, z.real());
        x1 = std::max(x1, z.real());
        y0 = std::min(y0, z.imag());
        y1 = std::max(y1, z.imag());
    };
    std::vector<std::vector<Complex>> curves = m_curves;
    for (const QCPCurve* c : m_overlay) {
        std::vector<Complex> pts;
        for (auto it = c->data()->constBegin(); it != c->data()->constEnd(); ++it) pts.emplace_back(it->key, it->value);
        curves.push_back(std::move(pts));
    }
    for (const auto& curve : curves)
        for (const Complex& z : curve)
            if (std::abs(z) <= 4.0) take(z);
            else if (std::abs(z.real()) <= 4.0) take(Complex(z.real(), std::clamp(z.imag(), -3.0, 3.0)));  // Verlet's strip
    const double regionSize = std::max(x1 - x0, y1 - y0);
    // Points far out (DT much too large) widen the view up to 40 region sizes.
    const double cap = 40.0 * regionSize;
    for (const Complex& l : m_spectrum.lambda) {
        const Complex z = m_shownDt * l;
        if (std::abs(z) <= cap) take(z);
    }
    if (m_measuredMark && std::abs(*m_measuredMark) <= cap) take(*m_measuredMark);
    double padX = 0.08 * (x1 - x0), padY = 0.08 * (y1 - y0);
    x0 -= padX, x1 += padX, y0 -= padY, y1 += padY;
    // Equal scales on both axes: circles stay circles.
    const QRect rect = m_plot->axisRect()->rect();
    const double w = rect.width() > 10 ? rect.width() : m_plot->width() * 0.8;
    const double h = rect.height() > 10 ? rect.height() : m_plot->height() * 0.8;
    if (w > 0 && h > 0) {
        const double perPixel = std::max((x1 - x0) / w, (y1 - y0) / h);
        const double cx = 0.5 * (x0 + x1), cy = 0.5 * (y0 + y1);
        x0 = cx - 0.5 * perPixel * w, x1 = cx + 0.5 * perPixel * w;
        y0 = cy - 0.5 * perPixel * h, y1 = cy + 0.5 * perPixel * h;
    }
    m_plot->xAxis->setRange(x0, x1);
    m_plot->yAxis->setRange(y0, y1);
    drawRegion();
}

void StabilityMapDock::keepEqualAspect() {
    // Widen the axis with fewer units per pixel about its centre until both have the same: a
    // circle (Euler's region) stays a circle whatever the dock's shape.
    const QRect rect = m_plot->axisRect()->rect();
    if (rect.width() < 10 || rect.height() < 10) return;
    const QCPRange xr = m_plot->xAxis->range(), yr = m_plot->yAxis->range();
    const double px = xr.size() / rect.width(), py = yr.size() / rect.height();
    if (!(px > 0) || !(py > 0) || std::abs(px - py) <= 1e-9 * std::max(px, py)) return;
    if (px < py) m_plot->xAxis->setRange(xr.center(), py * rect.width(), Qt::AlignCenter);
    else m_plot->yAxis->setRange(yr.center(), px * rect.height(), Qt::AlignCenter);
    drawRegion();
}

void StabilityMapDock::drawRegion() {
    if (!m_fill->visible()) return;
    const QCPRange xr = m_plot->xAxis->range(), yr = m_plot->yAxis->range();
    QCPColorMapData* cells = m_fill->data();
    cells->setSize(kFillCells, kFillCells);
    cells->setRange(xr, yr);
    for (int i = 0; i < kFillCells; ++i)
        for (int j = 0; j < kFillCells; ++j) {
            double x = 0.0, y = 0.0;
            cells->cellToCoord(i, j, &x, &y);
            cells->setCell(i, j, simlab::regionContains(m_shownIntegrator, Complex(x, y)) ? 1.0 : 0.0);
        }
}

void StabilityMapDock::resizeEvent(QResizeEvent* event) {
    QDockWidget::resizeEvent(event);
    if (m_resultSerial == 0) return;
    // After the layout has given the plot its new size.
    QMetaObject::invokeMethod(this, [this] {
        fitView();
        m_plot->replot(QCustomPlot::rpQueuedReplot);
    }, Qt::QueuedConnection);
}

void StabilityMapDock::tryIt() {
    if (m_scanRunning) {
        if (m_scanCancel) m_scanCancel->store(true);
        m_measuredLabel->setText(tr("Cancelling…"));
        return;
    }
    if (!m_modes || simlab::regionKind(m_shownIntegrator) == simlab::RegionKind::None) return;
    m_scanRunning = true;
    m_scanParams = m_shownParams;
    m_scanWorld = m_shownWorld;
    m_scanIntegrator = m_shownIntegrator;
    m_scanRow.reset();
    m_measuredText.clear();
    m_try->setText(tr("Cancel"));
    showMeasured();
    m_plot->replot(QCustomPlot::rpQueuedReplot);
    m_scanCancel = std::make_shared<std::atomic<bool>>(false);
    simlab::StabilitySpec spec;
    spec.params = m_scanParams;
    spec.world = m_scanWorld;  // a world: its trials run the whole world
    spec.integrators = {m_scanIntegrator};
    spec.duration = kScanDuration;
    if (m_scanThread.joinable()) m_scanThread.join();  // the last scan ended (its end was delivered)
    m_scanThread = std::thread([this, spec, modes = m_modes, cancel = m_scanCancel, name = m_scanIntegrator] {
        simlab::StabilityRow row = simlab::scanIntegrator(spec, name, *modes, cancel.get());
        const bool cancelled = cancel->load();
        m_fromWorker->post([this, row, cancelled] {
            m_scanRunning = false;
            m_try->setText(tr("Try it"));
            m_try->setEnabled(simlab::regionKind(m_shownIntegrator) != simlab::RegionKind::None);
            if (cancelled) m_measuredText = tr("Measurement cancelled.");
            else m_scanRow = row;
            // The body or the method may have changed meanwhile: the row is kept only for its own.
            if (m_scanRow && !(withoutDt(m_scanParams) == withoutDt(m_shownParams) &&
                               sameWorld(m_scanWorld, m_shownWorld, false) && m_scanIntegrator == m_shownIntegrator)) {
                m_scanRow.reset();
                m_measuredText = tr("The body or the integrator changed during the measurement: press Try it again.");
            }
            showMeasured();
            fitView();
            ++m_resultSerial;
            m_plot->replot(QCustomPlot::rpQueuedReplot);
        });
    });
}

}  // namespace elui
