// The stability map's numbers (simcore/stability_region.h): the regions' boundaries against
// the known real-axis limits and |R| = 1, R against one step of the real integrators, the
// iterative eigenvalue estimate against the exact spectrum, and the margin against the
// measured limit.
#include <QtTest>

#include <cmath>
#include <complex>
#include <limits>
#include <numbers>

#include "sim_test_support.h"
#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simlab/stability.h"
#include "simlab/stability_region.h"

using namespace simcore;
using namespace simlab;
using testsupport::params;
using Complex = std::complex<double>;

namespace {

// y' = J y with J = [[a, -b], [b, a]]: the real form of y' = (a + ib) y.
class RotationSystem final : public OdeSystem {
public:
    RotationSystem(double a, double b) : m_a(a), m_b(b) {}
    using OdeSystem::derivative;
    StateLayout layout() const override { return {1, 0}; }
    void derivative(double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) override {
        dydt[0] = m_a * y[0] - m_b * y[1];
        dydt[1] = m_b * y[0] + m_a * y[1];
    }

private:
    double m_a, m_b;
};

const std::vector<std::string> kRegionMethods = {"euler", "midpoint", "rk4", "rk45", "implicit-euler",
                                                 "symplectic-euler", "verlet", "yoshida4", "yoshida8"};

}  // namespace

class TestStabilityRegion : public QObject {
    Q_OBJECT
private slots:
    void realAxisLimits_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<double>("limit");
        QTest::newRow("euler") << "euler" << 2.0;
        QTest::newRow("midpoint") << "midpoint" << 2.0;
        // 1 - a + a^2/2 - a^3/6 + a^4/24 = -1: a = 2.785293563...
        QTest::newRow("rk4") << "rk4" << 2.785293563;
        // Critically damped oscillator (double root at -a): symplectic Euler's disc
        // (x - 2)^2 + y^2 <= 8 meets the axis at 2 - 2 sqrt 2; Verlet's strip ends at x = -2.
        QTest::newRow("symplectic-euler") << "symplectic-euler" << 2.0 * std::numbers::sqrt2 - 2.0;
        QTest::newRow("verlet") << "verlet" << 2.0;
        QTest::newRow("implicit-euler") << "implicit-euler" << std::numeric_limits<double>::infinity();
    }
    void realAxisLimits() {
        QFETCH(QString, integrator);
        QFETCH(double, limit);
        const double a = realAxisLimit(integrator.toStdString());
        if (std::isinf(limit)) {
            QVERIFY(std::isinf(a));
            return;
        }
        QVERIFY2(std::abs(a - limit) < 1e-6, qPrintable(QString("limit %1, expected %2").arg(a, 0, 'g', 12).arg(limit)));
        // And the traced boundary reaches the real axis there: its leftmost point.
        double left = 0.0;
        for (const auto& curve : regionBoundary(integrator.toStdString()))
            for (const Complex& z : curve) left = std::min(left, z.real());
        if (integrator != "verlet")  // Verlet's boundary includes the line x = -2 itself
            QVERIFY2(std::abs(-left - limit) < 1e-3, qPrintable(QString("leftmost %1").arg(left)));
    }
    void rk45RealAxisLimitIsWhereItsPolynomialReachesMinusOne() {
        // Dormand-Prince's 5th-order R with its z^6/600 term: the limit is the first a > 0 with
        // |R(-a)| = 1, a = 3.3066, where R has come back up to +1 (the z^6 term; the degree-5
        // Taylor polynomial alone ends at 3.2170, where it reaches -1).
        const double a = realAxisLimit("rk45");
        QVERIFY2(std::abs(a - 3.3066) < 1e-4, qPrintable(QString::number(a, 'g', 10)));
        QVERIFY2(std::abs(stabilityFunction("rk45", -a).real() - 1.0) < 1e-7,
                 qPrintable(QString("R(-%1) = %2").arg(a, 0, 'g', 12).arg(stabilityFunction("rk45", -a).real(), 0, 'g', 12)));
        for (double s = 0.01; s < a; s += 0.01) QVERIFY(std::abs(stabilityFunction("rk45", -s)) <= 1.0 + 1e-12);
    }
    void boundaryPointsAreOnTheUnitLevel() {
        for (const std::string& name : kRegionMethods) {
            const auto curves = regionBoundary(name);
            QVERIFY2(!curves.empty(), name.c_str());
            int points = 0;
            double worst = 0.0;
            for (const auto& curve : curves)
                for (const Complex& z : curve) {
                    worst = std::max(worst, std::abs(regionAmplification(name, z) - 1.0));
                    ++points;
                }
            QVERIFY2(points > 200, name.c_str());
            // Oscillator methods: a double eigenvalue (Verlet's line x = -2, the disc's ends)
            // is found to ~sqrt(eps).
            const double tolerance = regionKind(name) == RegionKind::Oscillator ? 1e-6 : 1e-9;
            QVERIFY2(worst < tolerance, qPrintable(QString("%1: |amplification - 1| up to %2")
                                                       .arg(QString::fromStdString(name)).arg(worst)));
        }
    }
    void boundaryIsClosedAndDense() {
        // Every curve of an R method is closed and has no gap wider than 0.05 (the exact level
        // set, continued in θ without losing a branch).
        for (const std::string name : {"euler", "midpoint", "rk4", "rk45", "implicit-euler"}) {
            for (const auto& curve : regionBoundary(name)) {
                QVERIFY(std::abs(curve.front() - curve.back()) < 1e-6);
                for (std::size_t i = 1; i < curve.size(); ++i)
                    QVERIFY2(std::abs(curve[i] - curve[i - 1]) < 0.05, name.c_str());
            }
        }
        // Euler: the circle |1 + z| = 1, once.
        const auto euler = regionBoundary("euler");
        QCOMPARE(int(euler.size()), 1);
        for (const Complex& z : euler.front()) QVERIFY(std::abs(std::abs(z + 1.0) - 1.0) < 1e-12);
    }
    void insideAndOutsideAgreeWithTheKnownFacts() {
        // Undamped modes: rk4 to h w = 2 sqrt 2, the oscillator methods to 2; euler never.
        QVERIFY(regionContains("rk4", Complex(0, 2.8)) && !regionContains("rk4", Complex(0, 2.9)));
        QVERIFY(regionContains("verlet", Complex(0, 1.99)) && !regionContains("verlet", Complex(0, 2.01)));
        // The compositions of Verlet: undamped to h w = 1.5734 (yoshida4), 2.3565 (yoshida8).
        QVERIFY(regionContains("yoshida4", Complex(0, 1.573)) && !regionContains("yoshida4", Complex(0, 1.574)));
        QVERIFY(regionContains("yoshida8", Complex(0, 2.356)) && !regionContains("yoshida8", Complex(0, 2.357)));
        QCOMPARE(regionKind("yoshida4"), RegionKind::Oscillator);
        QVERIFY(regionNote("yoshida4").find("1.57") != std::string::npos);
        // Damped: the disc (x - 2)^2 + y^2 <= 8, so damping lowers symplectic Euler's reach.
        QVERIFY(regionContains("symplectic-euler", Complex(-0.1, 1.8)) &&
                !regionContains("symplectic-euler", Complex(-0.1, 1.9)));
        QVERIFY(!regionContains("euler", Complex(0, 0.1)));
        QVERIFY(regionContains("implicit-euler", Complex(-100, 50)) && !regionContains("implicit-euler", Complex(0.5, 0)));
        QCOMPARE(regionKind("cvode-bdf"), RegionKind::None);
        QCOMPARE(regionKind("xpbd"), RegionKind::None);
        QVERIFY(!regionNote("cvode-adams").empty());
    }
    void stabilityFunctionIsOneStepOfTheIntegrator_data() {
        QTest::addColumn<QString>("integrator");
        for (const char* name : {"euler", "midpoint", "rk4", "rk45"}) QTest::newRow(name) << name;
    }
    void stabilityFunctionIsOneStepOfTheIntegrator() {
        // The drawn R is the method's own: one fixed step of the integrator (rk45 with its
        // Dormand-Prince tableau) on y' = lambda y, for a few complex z = h lambda.
        QFETCH(QString, integrator);
        const std::string name = integrator.toStdString();
        for (const Complex z : {Complex(-1.0, 0.5), Complex(-0.3, 2.5), Complex(-2.0, -1.0), Complex(0.2, 0.7)}) {
            RotationSystem system(z.real(), z.imag());
            auto method = makeIntegrator(name);
            IntegratorOptions options;
            options.fixedStep = true;
            method->setOptions(options);
            method->prepare(system.layout());
            Eigen::VectorXd y(2);
            y << 1.0, 0.0;
            method->step(system, 0.0, 1.0, y);
            const Complex r = stabilityFunction(name, z);
            QVERIFY2(std::abs(Complex(y[0], y[1]) - r) < 1e-12,
                     qPrintable(QString("z = (%1, %2): step (%3, %4), R (%5, %6)")
                                    .arg(z.real()).arg(z.imag()).arg(y[0]).arg(y[1]).arg(r.real()).arg(r.imag())));
        }
    }
    void iterativeEstimateMatchesTheExactSpectrum() {
        // A ring of 40 + 40 particles (160 free coordinates): the exact first-order spectrum
        // (dense, 320 eigenvalues), the modal one, and the large-body path (Arnoldi, 80 steps,
        // on the Jacobian products) forced on it.
        const ParameterSet p = params(SceneKind::Ring2d, {{"particles", 40}});
        const LinearModes exact = linearModes(p);
        const LinearModes modal = linearModes(p, 0);
        const LinearModes iterative = linearModes(p, 0, 0);
        QVERIFY(!exact.eigenvalues.empty());
        QVERIFY(modal.eigenvalues.empty() && modal.dense);
        QVERIFY(!iterative.dense);
        const SpectrumPoints e = spectrumPoints(exact), m = spectrumPoints(modal), it = spectrumPoints(iterative);
        QCOMPARE(QString::fromStdString(e.method), QStringLiteral("exact"));
        QCOMPARE(QString::fromStdString(m.method), QStringLiteral("modal"));
        QCOMPARE(QString::fromStdString(it.method), QStringLiteral("iterative"));
        QCOMPARE(int(e.lambda.size()), 2 * exact.freeCoordinates);
        QCOMPARE(iterative.arnoldiSteps, 80);
        QCOMPARE(int(it.lambda.size()), 80);
        QVERIFY(it.methodText.find("Arnoldi") != std::string::npos);
        auto fastest = [](const SpectrumPoints& s) {
            double top = 0.0;
            for (const Complex& l : s.lambda) top = std::max(top, std::abs(l));
            return top;
        };
        // The highest frequency (300 power iterations: slow where the top frequencies crowd)
        // against the dense one.
        QVERIFY2(std::abs(iterative.omegaMax / modal.omegaMax - 1.0) < 1e-2,
                 qPrintable(QString("iterative w %1, dense %2").arg(iterative.omegaMax).arg(modal.omegaMax)));
        // The fastest eigenvalue of the first-order system: the Ritz estimate against the exact.
        const double exactTop = fastest(e);
        QVERIFY2(std::abs(fastest(it) / exactTop - 1.0) < 1e-6,
                 qPrintable(QString("iterative |lambda| %1, exact %2").arg(fastest(it), 0, 'g', 12).arg(exactTop, 0, 'g', 12)));
        // And what the dock says from them: the margins of the explicit methods.
        for (const std::string name : {"euler", "rk4", "rk45"}) {
            const double fromExact = stepMargin(name, exact, e, 0.001).factor;
            const double fromRitz = stepMargin(name, iterative, it, 0.001).factor;
            QVERIFY2(std::abs(fromRitz / fromExact - 1.0) < 0.01,
                     qPrintable(QString("%1: margin %2 from the Ritz values, %3 exact").arg(name.c_str()).arg(fromRitz).arg(fromExact)));
            // On the exact spectrum the margin is the stability scan's prediction.
            QVERIFY(std::abs(fromExact * 0.001 / predictedStableStep(name, exact) - 1.0) < 1e-6);
        }
    }
    void marginAgreesWithTheMeasuredLimitOnTheSpring_data() {
        QTest::addColumn<QString>("integrator");
        for (const char* name : {"euler", "rk4", "verlet", "yoshida4"}) QTest::newRow(name) << name;
    }
    void marginAgreesWithTheMeasuredLimitOnTheSpring() {
        // The 1D spring (w^2 = 800, c = 15): margin * DT is the predicted limit; the
        // stability scan's bisection (the "Try it" button) brackets it to within 10 %.
        QFETCH(QString, integrator);
        const std::string name = integrator.toStdString();
        StabilitySpec spec;
        spec.params = params(SceneKind::Spring1d, {{"dt", 0.001}});
        spec.duration = 2.0;
        const LinearModes modes = linearModes(spec.params);
        const SpectrumPoints points = spectrumPoints(modes);
        const StepMargin margin = stepMargin(name, modes, points, 0.001);
        QVERIFY(margin.factor > 1.0 && std::isfinite(margin.factor));
        QCOMPARE(margin.hasLimiting, regionKind(name) == RegionKind::StabilityFunction);
        QVERIFY2(QString::fromStdString(margin.text).startsWith("DT can grow"), margin.text.c_str());
        const double limit = margin.factor * 0.001;
        if (name == "euler")  // |1 + h lambda| = 1: h = -2 Re lambda / |lambda|^2 = c / w^2
            QVERIFY(std::abs(limit - 15.0 / 800.0) < 1e-6 * limit);
        // The limiting point sits on the boundary at the limit.
        if (regionKind(name) == RegionKind::StabilityFunction)
            QVERIFY(std::abs(regionAmplification(name, limit * margin.limiting) - 1.0) < 1e-6);
        const StabilityRow row = scanIntegrator(spec, name, modes);
        QVERIFY2(row.stable <= 1.1 * limit && row.unstable >= 0.9 * limit,
                 qPrintable(QString("measured %1 .. %2, predicted %3").arg(row.stable).arg(row.unstable).arg(limit)));
        // At a DT beyond the limit the words turn round.
        const StepMargin outside = stepMargin(name, modes, points, 2.0 * limit);
        QVERIFY(outside.factor < 1.0);
        QVERIFY2(QString::fromStdString(outside.text).startsWith("DT is already outside"), outside.text.c_str());
    }
    void undampedEulerHasNoStableStep() {
        const ParameterSet p = params(SceneKind::Spring1d, {{"kd", 0.0}});
        const LinearModes modes = linearModes(p);
        const StepMargin margin = stepMargin("euler", modes, spectrumPoints(modes), 0.001);
        QCOMPARE(margin.factor, 0.0);
        QVERIFY2(QString::fromStdString(margin.text).startsWith("No DT is stable"), margin.text.c_str());
        QVERIFY(std::isinf(stepMargin("implicit-euler", modes, spectrumPoints(modes), 0.001).factor));
        // The undamped pair is named without its round-off (the Ritz value's real part came out
        // as -5.7e-14 1/s, "hλ = -5.68e-17 ± 0.0283i"): "hλ = 0 ± 0.0283i" on every path.
        for (const LinearModes& m : {modes, linearModes(p, 0), linearModes(p, 0, 0)}) {
            const std::string text = stepMargin("euler", m, spectrumPoints(m), 0.001).text;
            QVERIFY2(text.find("(hλ = 0 ± 0.0283i)") != std::string::npos, text.c_str());
        }
    }
};

QTEST_GUILESS_MAIN(TestStabilityRegion)
#include "test_stability_region.moc"
