// Integrators against the closed-form 1D oscillator: convergence orders and exact free fall.
#include <QtTest>

#include <cmath>

#include "simcore/compositions.h"
#include "simcore/integrator_table.h"
#include "simcore/simulation.h"
#include "simcore/step_doubling.h"
#include "simlab/analytic.h"

using namespace simcore;
using namespace simlab;

namespace {

// spring1d hanging from a fixed top, no walls in reach: a damped linear oscillator.
ParameterSet oscillator(double kd) {
    ParameterSet p(SceneKind::Spring1d);
    p.set(simcore::Param::Ks, 100.0);
    p.set(simcore::Param::Kd, kd);
    p.set(simcore::Param::Mass, 1.0);
    p.set(simcore::Param::Length, 1.0);
    p.set(simcore::Param::InitialLength, 1.5);
    p.set(simcore::Param::Box, 1000.0);
    return p;
}

// Position error of the moving particle at t = T against the closed form.
double errorAt(ParameterSet p, const std::string& integrator, double dt, double T) {
    p.set(simcore::Param::Dt, dt);
    Simulation sim(p, integrator);
    if (!sim.advanceTo(T)) return std::nan("");
    Eigen::Matrix3Xd x, v;
    spring1dExact(p, sim.time(), x, v);
    return (sim.positions() - x).norm() + (sim.velocities() - v).norm() / 10.0;
}

double observedOrder(const ParameterSet& p, const std::string& integrator, double h) {
    const double e1 = errorAt(p, integrator, h, 2.0);
    const double e2 = errorAt(p, integrator, h / 2.0, 2.0);
    const double e3 = errorAt(p, integrator, h / 4.0, 2.0);
    // Least-squares slope over three halvings.
    return (std::log2(e1) - std::log2(e3)) / 2.0 + 0.0 * e2;
}

// y' = lambda y on a state of one coordinate and its velocity slot (positions = 1, no aux).
class Decay final : public OdeSystem {
public:
    explicit Decay(double lambda) : m_lambda(lambda) {}
    using OdeSystem::derivative;
    StateLayout layout() const override { return {1, 0}; }
    void derivative(double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) override { dydt = m_lambda * y; }

private:
    double m_lambda;
};

// Coupled pendulums as a second-order system, y = [x (n) | v (n) | dissipated energy]:
// x' = v, a = -sin x - 0.1 v + 0.5 (neighbours' x - 2 x), aux' = 0.1 |v|^2. With `motion`, it
// says it is second order and its derivativeMotion leaves x' as NaN (a method that read it
// would show); its vector work runs in three pieces, so that ranges straddle v and aux.
class Pendulums final : public OdeSystem {
public:
    explicit Pendulums(bool motion) : m_motion(motion) {}
    static constexpr Eigen::Index n = 24;
    using OdeSystem::derivative;
    StateLayout layout() const override { return {n, 1}; }
    void derivative(double, const Eigen::VectorXd& y, Eigen::VectorXd& dydt) override {
        dydt.head(n) = y.segment(n, n);
        double power = 0.0;
        for (Eigen::Index i = 0; i < n; ++i) {
            const double v = y[n + i], left = y[(i + n - 1) % n], right = y[(i + 1) % n];
            dydt[n + i] = -std::sin(y[i]) - 0.1 * v + 0.5 * (left + right - 2.0 * y[i]);
            power += 0.1 * v * v;
        }
        dydt[2 * n] = power;
    }
    bool secondOrder() const override { return m_motion; }
    void derivativeMotion(double t, const Eigen::VectorXd& y, Eigen::VectorXd& dydt, RangeWork then) override {
        derivative(t, y, dydt);
        dydt.head(n).setConstant(std::nan(""));
        inPieces(dydt.size() - n, [&](Eigen::Index b, Eigen::Index l) { then(n + b, l); });
    }
    int pieces() const override { return 3; }
    void runPieces(TaskRef task) override {
        for (int k = 0; k < 3; ++k) task(k);
    }

private:
    bool m_motion;
};

}  // namespace

class TestIntegrators : public QObject {
    Q_OBJECT
private slots:
    void closedFormIsRight() {
        // The closed form satisfies m y'' = -k (y + L0) - c y' - m g (checked by differences).
        const ParameterSet p = oscillator(2.0);
        const double h = 1e-5, t = 0.7;
        Eigen::Matrix3Xd x0, v0, xm, vm, xp, vp;
        spring1dExact(p, t, x0, v0);
        spring1dExact(p, t - h, xm, vm);
        spring1dExact(p, t + h, xp, vp);
        const double acc = (vp(1, 1) - vm(1, 1)) / (2 * h);
        const double expected = -100.0 * (x0(1, 1) + 1.0) - 2.0 * v0(1, 1) - 9.81;
        QVERIFY(std::abs(acc - expected) < 1e-5 * std::abs(expected));
        QVERIFY(std::abs((xp(1, 1) - xm(1, 1)) / (2 * h) - v0(1, 1)) < 1e-6);
        QCOMPARE(x0(1, 0), 0.0);  // the fixed end stays
    }

    void convergenceOrder_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<double>("kd");
        QTest::addColumn<double>("h");
        QTest::addColumn<double>("low");
        QTest::addColumn<double>("high");
        QTest::newRow("euler") << "euler" << 1.0 << 0.0005 << 0.95 << 1.25;
        QTest::newRow("midpoint") << "midpoint" << 1.0 << 0.004 << 1.9 << 2.1;
        QTest::newRow("rk4") << "rk4" << 1.0 << 0.02 << 3.9 << 4.1;
        QTest::newRow("symplectic-euler") << "symplectic-euler" << 1.0 << 0.002 << 0.9 << 1.1;
        QTest::newRow("verlet undamped") << "verlet" << 0.0 << 0.004 << 1.9 << 2.1;
        // Damping evaluated at the half-step velocity: only first order (a known property).
        QTest::newRow("verlet damped") << "verlet" << 5.0 << 0.002 << 0.9 << 1.1;
        // The compositions of Verlet: their order on the undamped oscillator; with damping
        // (the half-kick velocity, as Verlet) first order.
        QTest::newRow("yoshida4 undamped") << "yoshida4" << 0.0 << 0.02 << 3.9 << 4.1;
        QTest::newRow("yoshida8 undamped") << "yoshida8" << 0.0 << 0.06 << 7.7 << 8.3;
        QTest::newRow("yoshida4 damped") << "yoshida4" << 5.0 << 0.002 << 0.9 << 1.1;
    }
    void convergenceOrder() {
        QFETCH(QString, integrator);
        QFETCH(double, kd);
        QFETCH(double, h);
        QFETCH(double, low);
        QFETCH(double, high);
        const double order = observedOrder(oscillator(kd), integrator.toStdString(), h);
        QVERIFY2(order >= low && order <= high,
                 qPrintable(QString("%1: measured order %2, expected [%3, %4]").arg(integrator).arg(order).arg(low).arg(high)));
    }

    void freeFall_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<bool>("exact");
        QTest::newRow("euler") << "euler" << false;
        QTest::newRow("midpoint") << "midpoint" << true;
        QTest::newRow("rk4") << "rk4" << true;
        QTest::newRow("symplectic-euler") << "symplectic-euler" << false;
        QTest::newRow("verlet") << "verlet" << true;
        QTest::newRow("yoshida4") << "yoshida4" << true;
        QTest::newRow("yoshida8") << "yoshida8" << true;
    }
    void freeFall() {
        // Two free masses on a relaxed spring fall together: y = y0 - g t^2 / 2. Methods of
        // order >= 2 integrate a quadratic exactly; the Euler variants are off by O(h).
        QFETCH(QString, integrator);
        QFETCH(bool, exact);
        ParameterSet p(SceneKind::Spring1d);
        p.set(simcore::Param::FixedEnd, 0.0);
        p.set(simcore::Param::InitialLength, 1.0);
        p.set(simcore::Param::Box, 1000.0);
        p.set(simcore::Param::Dt, 0.01);
        Simulation sim(p, integrator.toStdString());
        QVERIFY(sim.advanceTo(1.0));
        const double t = sim.time();
        const double expected = -1.0 - 0.5 * 9.81 * t * t;
        const double error = std::abs(sim.positions()(1, 1) - expected);
        const double vError = std::abs(sim.velocities()(1, 1) + 9.81 * t);
        if (exact) {
            QVERIFY2(error < 1e-11 && vError < 1e-11, qPrintable(QString::number(error)));
        } else {
            QVERIFY2(error > 1e-3, "the Euler variants must show their O(h) error");
            QVERIFY(error < 0.1);
        }
        QCOMPARE(sim.positions()(1, 0) - sim.positions()(1, 1), 1.0);  // spring never stretched
    }

    void freeOscillatorMatchesClosedForm() {
        // Both ends free with gravity: centre of mass falls, separation oscillates.
        ParameterSet p(SceneKind::Spring1d);
        p.set(simcore::Param::FixedEnd, 0.0);
        p.set(simcore::Param::Box, 1000.0);
        p.set(simcore::Param::Dt, 0.001);
        Simulation sim(p, "rk4");
        QVERIFY(sim.advanceTo(1.0));
        Eigen::Matrix3Xd x, v;
        spring1dExact(p, sim.time(), x, v);
        QVERIFY2((sim.positions() - x).norm() < 1e-8, qPrintable(QString::number((sim.positions() - x).norm())));
    }

    void everyStageEvaluatesForces() {
        for (const auto& [name, stages] : std::vector<std::pair<std::string, int>>{
                 {"euler", 1}, {"midpoint", 2}, {"rk4", 4}, {"symplectic-euler", 1}, {"verlet", 2}, {"yoshida4", 4},
                 {"yoshida8", 16}}) {
            Simulation sim(oscillator(1.0), name);
            for (int i = 0; i < 10; ++i) sim.step();
            QCOMPARE(sim.diagnostics().forceEvaluations, std::uint64_t(10 * stages));
            QCOMPARE(sim.integrator().evaluationsPerStep(), stages);
        }
    }
    // RK4 on a second-order system (OdeSystem::derivativeMotion: x' never copied out of v,
    // the stage states kept apart) takes the same steps, bit for bit, as on the same system
    // through derivative().
    void rk4SecondOrderIsTheSameSteps() {
        Pendulums motion(true), plain(false);
        const auto a = makeIntegrator("rk4"), b = makeIntegrator("rk4");
        a->prepare(motion.layout());
        b->prepare(plain.layout());
        Eigen::VectorXd y(2 * Pendulums::n + 1);
        for (Eigen::Index i = 0; i < y.size(); ++i) y[i] = std::sin(1.7 * double(i));
        y[2 * Pendulums::n] = 0.0;
        Eigen::VectorXd z = y;
        for (int step = 0; step < 50; ++step) {
            a->step(motion, 0.01 * step, 0.01, y);
            b->step(plain, 0.01 * step, 0.01, z);
            QVERIFY2(y == z, qPrintable(QString("step %1").arg(step)));  // bit for bit
        }
        QVERIFY(y.allFinite() && y.head(Pendulums::n).cwiseAbs().maxCoeff() > 0.1);
    }
    void longRunsLandOnTheirEndTime() {
        // 10^6 steps of 1 ms: the step count is exact (no extra step from summed round-off).
        ParameterSet p = oscillator(1.0);
        p.set(simcore::Param::Dt, 0.001);
        Simulation sim(p, "euler");
        QVERIFY(sim.advanceTo(1000.0));
        QCOMPARE(sim.stepCount(), 1000000L);
        QVERIFY(std::abs(sim.time() - 1000.0) < 1e-9);
    }
    void stepDoublingIsRichardson() {
        // StepDoubling wraps a method's step: the run keeps the one step of h, and the
        // estimate is (y_h/2 - y_h) / (1 - 2^-p). For euler on y' = l y from y0:
        // y_h = (1 + hl) y0, y_h/2 = (1 + hl/2)^2 y0, so e = 2 (hl/2)^2 y0 = (hl)^2 y0 / 2,
        // the leading term of the true local error e^{hl} - 1 - hl.
        const double lambda = -3.0, h = 0.01;
        Decay system(lambda);
        auto euler = makeIntegrator("euler");
        euler->prepare(system.layout());
        Eigen::VectorXd plain(2), wrapped(2);
        plain << 1.5, -0.5;
        wrapped = plain;
        const Eigen::VectorXd y0 = plain;
        StepDoubling doubling;
        doubling.prepare(wrapped.size());
        QVERIFY(doubling.localError() == nullptr);
        const StepReport unwrapped = euler->step(system, 0.0, h, plain);
        const StepReport report = doubling.step(*euler, system, 0.0, h, wrapped);
        QVERIFY(!report.failure && !unwrapped.failure);
        QVERIFY(wrapped == plain);  // the run keeps y_h, bit for bit
        QVERIFY(unwrapped.errorEstimate < 0.0);
        const double* e = doubling.localError();
        QVERIFY(e != nullptr);
        for (int k = 0; k < 2; ++k) {
            const double expected = (h * lambda) * (h * lambda) / 2.0 * y0[k];
            QVERIFY2(std::abs(e[k] - expected) <= 1e-12 * std::abs(expected),
                     qPrintable(QString("e[%1] = %2, expected %3").arg(k).arg(e[k]).arg(expected)));
        }
        // The report's estimate: the RMS of e over the positions per particle (one here).
        QVERIFY(std::abs(report.errorEstimate - std::abs(e[0])) <= 1e-15);
        // Order 2 (midpoint): the estimate is 4/3 of the half steps' difference and shrinks
        // as h^3.
        auto midpoint = makeIntegrator("midpoint");
        midpoint->prepare(system.layout());
        auto estimate = [&](double step) {
            Eigen::VectorXd y = y0;
            return doubling.step(*midpoint, system, 0.0, step, y).errorEstimate;
        };
        const double ratio = estimate(0.02) / estimate(0.01);
        QVERIFY2(std::abs(ratio - 8.0) < 0.2, qPrintable(QString("ratio %1").arg(ratio)));
        // A non-finite step has no estimate.
        Eigen::VectorXd bad(2);
        bad << std::nan(""), 1.0;
        QVERIFY(doubling.step(*euler, system, 0.0, h, bad).errorEstimate < 0.0);
        QVERIFY(doubling.localError() == nullptr);
    }

    void compositionsAreVerletSubsteps() {
        // Undamped, one step of yoshida4 is three Verlet steps of w h (w1 = 1/(2 - 2^(1/3)),
        // w0 = 1 - 2 w1), bit for bit up to round-off of the substep sums, and verlet is the
        // one-substep composition.
        const std::span<const double> w = compositionWeights("yoshida4");
        QCOMPARE(w.size(), std::size_t(3));
        QVERIFY(std::abs(w[0] - 1.0 / (2.0 - std::cbrt(2.0))) < 1e-15);
        QVERIFY(std::abs(w[0] + w[1] + w[2] - 1.0) < 1e-15);
        QCOMPARE(compositionWeights("yoshida8").size(), std::size_t(15));
        double sum = 0.0;
        for (double x : compositionWeights("yoshida8")) sum += x;
        QVERIFY(std::abs(sum - 1.0) < 1e-14);
        QCOMPARE(compositionWeights("verlet").size(), std::size_t(1));
        QVERIFY(compositionWeights("rk4").empty());
        const double h = 0.01;
        ParameterSet p = oscillator(0.0);
        p.set(simcore::Param::Dt, h);
        Simulation composed(p, "yoshida4");
        composed.step();
        Simulation plain(p, "verlet");
        auto verlet = makeIntegrator("verlet");
        verlet->prepare(plain.odeSystem().layout());
        Eigen::VectorXd y = plain.state();
        double t = 0.0;
        for (double x : w) verlet->step(plain.odeSystem(), t, x * h, y), t += x * h;
        const Eigen::Index n = plain.odeSystem().layout().positions;
        QVERIFY2((y.head(2 * n) - composed.state().head(2 * n)).norm() < 1e-14,
                 qPrintable(QString::number((y.head(2 * n) - composed.state().head(2 * n)).norm())));
    }

    void familiesCoverEveryIntegrator() {
        for (const IntegratorInfo& info : integratorTable()) {
            const auto families = integratorFamilies();
            QVERIFY2(std::find(families.begin(), families.end(), info.family) != families.end(), info.name.data());
        }
        QCOMPARE(integratorFamily("yoshida8"), std::string_view("symplectic"));
        QCOMPARE(integratorFamily("rk4"), std::string_view("explicit-rk"));
        QCOMPARE(integratorFamily("cvode-bdf"), std::string_view("production"));
        QCOMPARE(integratorFamily("xpbd"), std::string_view("constraint"));
        QVERIFY(integratorFamily("leapfrog").empty());
    }

    void unknownIntegratorIsRefused() {
        QVERIFY(!makeIntegrator("rk5"));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, Simulation(oscillator(1.0), "leapfrog"));
    }
};

QTEST_GUILESS_MAIN(TestIntegrators)
#include "test_integrators.moc"
