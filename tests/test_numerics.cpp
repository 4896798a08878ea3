// The numerics lab: rk45, implicit Euler, error estimates, stability facts, the study and
// stability engines. Every assertion is physics with an explicit tolerance; nothing is timed.
#include <QtTest>

#include <atomic>
#include <cmath>
#include <numbers>
#include <set>

#include "simcore/integrator_table.h"
#include "simcore/internal/jacobians.h"
#include "simcore/simulation.h"
#include "simlab/analytic.h"
#include "simlab/stability.h"
#include "simlab/study.h"

#include "sim_test_support.h"

using namespace simcore;
using namespace simlab;

namespace {

using testsupport::params;

// Two free 1 kg masses on a 800 N/m spring, no damping, no gravity, walls far away:
// one mode, w = sqrt(k (1/m1 + 1/m2)) = 40 rad/s (docs/model.md). Stretched by 1% only, so that
// a growing solution is seen long before the particles could cross (a 1D spring whose ends
// pass through each other is no longer linear).
ParameterSet freePair(double kd = 0.0) {
    return params(SceneKind::Spring1d,
                  {{"fixed_end", 0.0}, {"kd", kd}, {"gravity", 0.0}, {"box", 1e6}, {"initial_length", 1.01}});
}
constexpr double kPairEnergy = 0.5 * 800.0 * 0.01 * 0.01;  // [J]
constexpr double kPairOmega = 40.0;

// Oscillation energy of the free pair: kinetic + spring (the centre of mass is at rest).
double pairEnergy(const Simulation& sim) { return sim.diagnostics().kinetic + sim.diagnostics().springTotal(); }

struct Run {
    bool failed = false;
    double first = 0.0;   // largest energy in the first half
    double second = 0.0;  // largest energy in the second half
    double last = 0.0;
    double peak() const { return std::max(first, second); }
};

Run runPair(const std::string& integrator, double h, int steps, double kd = 0.0) {
    ParameterSet p = freePair(kd);
    p.set(simcore::Param::Dt, h);
    Simulation sim(p, integrator);
    IntegratorOptions o;
    o.fixedStep = true;
    sim.setIntegratorOptions(o);
    Run r;
    for (int i = 0; i < steps; ++i) {
        if (!sim.step()) {
            r.failed = true;
            break;
        }
        (i < steps / 2 ? r.first : r.second) = std::max(i < steps / 2 ? r.first : r.second, pairEnergy(sim));
    }
    r.last = pairEnergy(sim);
    return r;
}

StudySpec oscillatorStudy(std::vector<std::string> integrators, double kd, std::vector<double> dts) {
    StudySpec spec;
    spec.params = params(SceneKind::Spring1d, {{"kd", kd}, {"box", 1000.0}});
    spec.integrators = std::move(integrators);
    spec.dts = std::move(dts);
    spec.duration = 2.0;
    spec.options.fixedStep = true;
    return spec;
}

std::string withoutWallColumn(const std::string& csv) {
    // The wall times (wall_min, wall_q1, wall_median, wall_q3: columns 8 to 11) are the only
    // fields that differ between two identical runs.
    std::string out;
    std::istringstream in(csv);
    std::string line;
    while (std::getline(in, line)) {
        QStringList f = QString::fromStdString(line).split(',');
        if (f.size() > 10) f.remove(7, 4);
        out += f.join(',').toStdString() + "\n";
    }
    return out;
}

}  // namespace

class TestNumerics : public QObject {
    Q_OBJECT
private slots:
    // --- orders, through the study engine against the closed form ---
    void convergenceOrders_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<double>("kd");
        QTest::addColumn<double>("low");
        QTest::addColumn<double>("high");
        QTest::newRow("euler") << "euler" << 1.0 << 0.9 << 1.15;
        QTest::newRow("midpoint") << "midpoint" << 1.0 << 1.9 << 2.1;
        QTest::newRow("rk4") << "rk4" << 1.0 << 3.8 << 4.2;
        QTest::newRow("rk45 fixed step") << "rk45" << 0.0 << 4.7 << 5.3;
        QTest::newRow("symplectic-euler") << "symplectic-euler" << 1.0 << 0.9 << 1.1;
        QTest::newRow("verlet undamped") << "verlet" << 0.0 << 1.9 << 2.1;
        QTest::newRow("yoshida4 undamped") << "yoshida4" << 0.0 << 3.9 << 4.1;
        // Damping taken at the half-step velocity: velocity Verlet drops to first order.
        QTest::newRow("verlet damped") << "verlet" << 5.0 << 0.85 << 1.15;
        QTest::newRow("implicit-euler") << "implicit-euler" << 1.0 << 0.85 << 1.1;
    }
    void convergenceOrders() {
        QFETCH(QString, integrator);
        QFETCH(double, kd);
        QFETCH(double, low);
        QFETCH(double, high);
        const std::string name = integrator.toStdString();
        // Euler needs h < kd/ks = 1/800 here; the others are shown in their asymptotic range.
        const std::vector<double> dts = name == "rk45" ? std::vector<double>{0.02, 0.01, 0.005}
                                        : name == "rk4" ? std::vector<double>{0.01, 0.005, 0.0025}
                                        : name == "euler" || name == "implicit-euler"
                                            ? std::vector<double>{0.0005, 0.00025, 0.000125}
                                            : std::vector<double>{0.004, 0.002, 0.001};
        const StudySpec spec = oscillatorStudy({name}, kd, dts);
        QVERIFY(!validateStudy(spec));
        const StudyResult result = runStudy(spec);
        QVERIFY2(result.reference.description.find("closed form") != std::string::npos, "1D uses the closed form");
        for (const StudyRow& r : result.rows) QVERIFY(r.ok);
        const auto fits = fitOrders(result.rows, result.reference.estimatedError);
        QCOMPARE(fits.size(), std::size_t(1));
        QVERIFY2(fits[0].order >= low && fits[0].order <= high,
                 qPrintable(QString("%1: order %2, expected [%3, %4]").arg(integrator).arg(fits[0].order).arg(low).arg(high)));
    }

    // --- stability facts (docs/model.md, issue 3 notes) ---
    void everyIntegratorHasItsOwnStudyColour() {
        // The study diagrams tell the curves apart by colour: a new integrator needs its own
        // (cvode-bdf, cvode-adams and xpbd were all drawn grey when they arrived).
        std::set<std::string> colours;
        for (const simcore::IntegratorInfo& info : simcore::integratorTable()) {
            const std::string colour = simlab::studyColour(info.name);
            QVERIFY2(colour != "#7f7f7f", std::string(info.name).c_str());
            QVERIFY2(colours.insert(colour).second, std::string(info.name).c_str());
        }
    }
    void stabilityScanCancelKeepsWholeRows() {
        // Cancel while the second integrator is being scanned: the first row is kept whole, the
        // second (cut short, its limits unknown) is not reported, the third never starts.
        StabilitySpec spec;
        spec.params = ParameterSet(SceneKind::Spring1d);
        spec.integrators = {"euler", "rk4", "verlet"};
        spec.duration = 0.2;
        std::atomic<bool> cancel{false};
        int trialsAfterCancel = 0;
        const auto rows = runStability(
            spec, linearModes(spec.params),
            [&](const StabilityProgress& p) {
                if (p.what == "rk4") cancel = true;
                if (cancel && p.what == "verlet") ++trialsAfterCancel;
            },
            &cancel);
        QCOMPARE(int(rows.size()), 1);
        QCOMPARE(rows[0].integrator, std::string("euler"));
        QVERIFY(rows[0].stable > 0.0 && rows[0].unstable > rows[0].stable);
        QCOMPARE(trialsAfterCancel, 0);
        // A trial that sees the flag stops at once and claims nothing.
        QVERIFY(!stabilityTrial(spec, "euler", 0.1, &cancel).has_value());
        QVERIFY(stabilityTrial(spec, "euler", 0.1).has_value());  // the same step without cancel fails
    }
    void undampedEulerGrowsForEveryStep() {
        // Explicit Euler on x'' = -w^2 x multiplies w^2 x^2 + v^2 by exactly (1 + h^2 w^2) per
        // step: it grows for every h > 0, however small.
        for (double h : {1e-5, 1e-4, 1e-3, 3e-3}) {
            const int steps = 200;
            const Run r = runPair("euler", h, steps);
            QVERIFY(!r.failed);
            const double expected = kPairEnergy * std::pow(1.0 + h * h * kPairOmega * kPairOmega, steps);
            QVERIFY2(r.last > kPairEnergy, qPrintable(QString("h = %1: energy %2 did not grow").arg(h).arg(r.last)));
            QVERIFY2(std::abs(r.last / expected - 1.0) < 1e-9,
                     qPrintable(QString("h = %1: energy %2, expected %3").arg(h).arg(r.last).arg(expected)));
            QVERIFY(modeAmplification("euler", h, kPairOmega, 0.0) > 1.0);
        }
        LinearModes modes = linearModes(freePair());
        QCOMPARE(predictedStableStep("euler", modes), 0.0);
    }
    void explicitLimitsOnUndampedOscillator_data() {
        QTest::addColumn<QString>("integrator");
        QTest::addColumn<double>("limit");  // h w
        QTest::newRow("rk4") << "rk4" << 2.0 * std::numbers::sqrt2;
        QTest::newRow("symplectic-euler") << "symplectic-euler" << 2.0;
        QTest::newRow("verlet") << "verlet" << 2.0;
        // The compositions: |trace| of the product of Verlet step matrices reaches 2 there
        // (bisection on the 2x2 product, independently of the code).
        QTest::newRow("yoshida4") << "yoshida4" << 1.5734019474;
        QTest::newRow("yoshida8") << "yoshida8" << 2.3565081394;
    }
    void explicitLimitsOnUndampedOscillator() {
        QFETCH(QString, integrator);
        QFETCH(double, limit);
        const std::string name = integrator.toStdString();
        // The linear analysis...
        const LinearModes modes = linearModes(freePair());
        QVERIFY(std::abs(modes.omegaMax - kPairOmega) < 1e-9 * kPairOmega);
        const double predicted = predictedStableStep(name, modes) * kPairOmega;
        QVERIFY2(std::abs(predicted - limit) < 1e-3 * limit, qPrintable(QString("predicted h w = %1").arg(predicted)));
        // ...and the simulation: bounded just below the limit, growing just above.
        const int steps = 4000;
        // Near hw = 2 the energy of symplectic Euler and Verlet oscillates by 1/(1 - h^2w^2/4)
        // (a bounded modified energy); it must not trend upwards.
        const Run below = runPair(name, 0.97 * limit / kPairOmega, steps);
        QVERIFY(!below.failed);
        QVERIFY2(below.peak() < 50.0 * kPairEnergy && below.second <= 1.01 * below.first,
                 qPrintable(QString("below: %1 then %2").arg(below.first).arg(below.second)));
        const Run above = runPair(name, 1.03 * limit / kPairOmega, steps);
        QVERIFY2(above.failed || above.peak() > 1000.0 * kPairEnergy,
                 qPrintable(QString("above: %1 then %2").arg(above.first).arg(above.second)));
    }
    void eulerOnDampedSpringNeedsDtBelowKdOverKs() {
        // m z'' + kd z' + ks z = 0 (underdamped): Euler's |1 + h lambda| <= 1 gives
        // h <= 2 gamma / w0^2 = kd / ks. ks = 100, kd = 2, m = 1: h <= 0.02.
        const double ks = 100.0, kd = 2.0, limit = kd / ks;
        QVERIFY(std::abs(modeAmplification("euler", limit, std::sqrt(ks), kd) - 1.0) < 1e-12);
        ParameterSet p = params(SceneKind::Spring1d, {{"ks", ks}, {"kd", kd}, {"box", 1e6}, {"gravity", 0.0}});
        QVERIFY(std::abs(predictedStableStep("euler", linearModes(p)) - limit) < 1e-6 * limit);
        auto amplitudeRatio = [&](double h) {
            ParameterSet q = p;
            q.set(simcore::Param::Dt, h);
            Simulation sim(q, "euler");
            const double y0 = sim.positions()(1, 1) + 1.0;  // displacement from rest (y = -L0)
            sim.advanceTo(20.0);
            double late = 0.0;
            for (int i = 0; i < 200; ++i) {
                sim.step();
                late = std::max(late, std::abs(sim.positions()(1, 1) + 1.0));
            }
            return late / std::abs(y0);
        };
        QVERIFY2(amplitudeRatio(0.95 * limit) < 0.5, "below kd/ks the oscillation decays");
        QVERIFY2(amplitudeRatio(1.05 * limit) > 2.0, "above kd/ks it grows");
    }
    void implicitEulerStableWhereExplicitFail() {
        // KS = 1e6 at DT = 0.01 on the two-layer ring: every explicit method is detected as
        // failed; implicit Euler runs through and keeps the shape.
        ParameterSet p = params(SceneKind::Ring2d, {{"ks", 1e6}, {"dt", 0.01}});
        for (const char* name : {"euler", "midpoint", "rk4", "symplectic-euler", "verlet", "rk45"}) {
            Simulation sim(p, name);
            IntegratorOptions o;
            o.fixedStep = true;
            sim.setIntegratorOptions(o);
            QVERIFY2(!sim.advanceTo(2.0), name);
            QVERIFY(sim.state().allFinite());
            QVERIFY(!sim.failure()->reason.empty());
        }
        Simulation implicit(p, "implicit-euler");
        QVERIFY2(implicit.advanceTo(2.0), implicit.failed() ? implicit.failure()->reason.c_str() : "");
        const Diagnostics& d = implicit.diagnostics();
        QVERIFY(d.volume[0] > 0.8 * d.restVolume[0] && d.volume[1] > 0.8 * d.restVolume[1]);
        // Thesis defaults at DT 0.3: stable too (contacts are inside its solve).
        ParameterSet thesis = params(SceneKind::Ring2d, {{"dt", 0.3}});
        Simulation big(thesis, "implicit-euler");
        QVERIFY2(big.advanceTo(5.0), big.failed() ? big.failure()->reason.c_str() : "");
    }
    void implicitEulerMatchesClosedFormToFirstOrder() {
        ParameterSet p = params(SceneKind::Spring1d, {{"ks", 100.0}, {"kd", 1.0}, {"box", 1000.0}, {"dt", 1e-4}});
        Simulation sim(p, "implicit-euler");
        QVERIFY(sim.advanceTo(1.0));
        Eigen::Matrix3Xd x, v;
        spring1dExact(p, sim.time(), x, v);
        QVERIFY2((sim.positions() - x).norm() < 2e-3, qPrintable(QString::number((sim.positions() - x).norm())));
    }
    void jacobianMatchesFiniteDifferences() {
        // Every spring stretched (no clamping), v = 0: K from the kernels equals dF/dx, gas
        // rank-one and pressure terms included.
        for (SceneKind kind : {SceneKind::Ring2d, SceneKind::Sphere3d}) {
            ParameterSet p(kind);
            if (kind == SceneKind::Sphere3d) p.set(simcore::Param::Subdivisions, 1.0);
            Simulation sim(p, "implicit-euler");
            Eigen::Matrix3Xd x = sim.positions() * 1.1;
            sim.setState(x, Eigen::Matrix3Xd::Zero(3, sim.particleCount()));
            OdeSystem& system = sim.odeSystem();
            system.linearize(0.0, sim.state());
            const Eigen::Index n = 3 * sim.particleCount();
            Eigen::VectorXd dx = Eigen::VectorXd::Random(n) * 1e-6, zero = Eigen::VectorXd::Zero(n), kdx(n);
            for (Eigen::Index k = 0; k < n; ++k)
                if (system.coordinateMass()[k] == 0.0) dx[k] = 0.0;
            system.forceJacobianProduct(dx, zero, kdx);
            Eigen::VectorXd yp = sim.state(), ym = sim.state(), fp(yp.size()), fm(yp.size());
            yp.head(n) += dx;
            ym.head(n) -= dx;
            system.derivative(0.0, yp, fp);
            system.derivative(0.0, ym, fm);
            const Eigen::VectorXd fd = (fp - fm).segment(n, n).cwiseProduct(system.coordinateMass()) / 2.0;
            QVERIFY2((fd - kdx).norm() < 1e-6 * fd.norm(),
                     qPrintable(QString("relative %1").arg((fd - kdx).norm() / fd.norm())));
        }
    }

    // --- rk45 ---
    void rk45AdaptiveMeetsTolerances() {
        ParameterSet p = params(SceneKind::Spring1d, {{"kd", 1.0}, {"box", 1000.0}, {"dt", 0.5}});
        double previous = 1e9;
        for (double tol : {1e-4, 1e-7, 1e-10}) {
            Simulation sim(p, "rk45");
            IntegratorOptions o;
            o.atol = o.rtol = tol;
            sim.setIntegratorOptions(o);
            QVERIFY(sim.integrator().adaptive());
            long rejectedSteps = 0;
            QVERIFY(sim.advanceTo(2.0));
            QCOMPARE(sim.time(), 2.0);  // lands on T exactly
            QVERIFY(sim.diagnostics().errorEstimate >= 0.0);
            (void)rejectedSteps;
            Eigen::Matrix3Xd x, v;
            spring1dExact(p, 2.0, x, v);
            const double error = (sim.positions() - x).norm();
            QVERIFY2(error < previous, qPrintable(QString("tol %1: error %2").arg(tol).arg(error)));
            QVERIFY2(error < 1000.0 * tol, qPrintable(QString("tol %1: error %2").arg(tol).arg(error)));
            previous = error;
        }
        // A first step of 0.5 s on a 28 rad/s oscillator is rejected and shrunk.
        Simulation sim(p, "rk45");
        sim.step();
        QVERIFY(sim.diagnostics().dt < 0.5);
        QVERIFY(sim.diagnostics().forceEvaluations > 7);  // rejected attempts are counted
    }
    void rk45EstimateTracksTrueLocalError() {
        // Fixed step, one step from the start: the embedded estimate (the 4th-order
        // solution's error) has the size of the propagated 5th-order solution's true error or
        // more: within [0.1, 1e4] of it.
        ParameterSet p = params(SceneKind::Spring1d, {{"kd", 1.0}, {"box", 1000.0}, {"dt", 0.02}});
        Simulation sim(p, "rk45");
        IntegratorOptions o;
        o.fixedStep = true;
        sim.setIntegratorOptions(o);
        sim.step();
        Eigen::Matrix3Xd x, v;
        spring1dExact(p, sim.time(), x, v);
        const double trueError = (sim.positions() - x).norm() / std::sqrt(2.0);  // RMS over 2 particles
        const double estimate = sim.diagnostics().errorEstimate;
        QVERIFY2(estimate >= 0.1 * trueError && estimate < 1e4 * trueError,
                 qPrintable(QString("estimate %1, true %2").arg(estimate).arg(trueError)));
    }

    // --- step doubling ---
    void stepDoublingEstimatesAndCounts() {
        ParameterSet p = params(SceneKind::Spring1d, {{"kd", 1.0}, {"box", 1000.0}, {"dt", 0.001}});
        Simulation plain(p, "rk4"), estimated(p, "rk4");
        IntegratorOptions o;
        o.stepDoubling = true;
        estimated.setIntegratorOptions(o);
        for (int i = 0; i < 50; ++i) {
            plain.step();
            estimated.step();
        }
        QCOMPARE(plain.diagnostics().errorEstimate, -1.0);
        QVERIFY(estimated.diagnostics().errorEstimate > 0.0);
        // Same trajectory (the run keeps the full step), three times the evaluations.
        QCOMPARE(estimated.state(), plain.state());
        QCOMPARE(estimated.diagnostics().forceEvaluations, 3 * plain.diagnostics().forceEvaluations);
        // Euler, one step: the estimate is the true local error within 20%.
        ParameterSet q = params(SceneKind::Spring1d, {{"kd", 1.0}, {"box", 1000.0}, {"dt", 0.001}});
        Simulation euler(q, "euler");
        euler.setIntegratorOptions(o);
        euler.step();
        Eigen::Matrix3Xd x, v;
        spring1dExact(q, euler.time(), x, v);
        const double trueError = (euler.positions() - x).norm() / std::sqrt(2.0);
        const double estimate = euler.diagnostics().errorEstimate;
        QVERIFY2(std::abs(estimate / trueError - 1.0) < 0.2,
                 qPrintable(QString("estimate %1, true %2").arg(estimate).arg(trueError)));
    }

    // --- linearised model ---
    void linearModesOfTheSpring() {
        ParameterSet fixed = params(SceneKind::Spring1d, {});
        const LinearModes a = linearModes(fixed);
        QCOMPARE(a.freeCoordinates, 1);
        QVERIFY(std::abs(a.omegaMax - std::sqrt(800.0)) < 1e-9);
        QVERIFY(std::abs(a.dampingAtMax - 15.0) < 1e-9);  // c = kd / m
        const LinearModes b = linearModes(freePair(15.0));
        QCOMPARE(b.freeCoordinates, 2);
        QVERIFY(std::abs(b.omegaMax - kPairOmega) < 1e-9);
        QVERIFY(std::abs(b.dampingAtMax - 30.0) < 1e-9);  // kd (1/m1 + 1/m2)
        QVERIFY(std::isinf(predictedStableStep("implicit-euler", b)));
    }

    // --- study engine: shards, CSV ---
    void shardsConcatenateToTheFullStudy() {
        StudySpec spec = oscillatorStudy({"euler", "rk4", "verlet"}, 1.0, {0.02, 0.01});
        spec.options.fixedStep = false;
        spec.integrators.push_back("rk45");
        spec.tolerances = {1e-4, 1e-6};
        const StudyResult full = runStudy(spec);
        std::string fullCsv = studyCsvHeader();
        for (const auto& r : full.rows) fullCsv += studyCsvRow(r);
        std::string joined;
        int rows = 0;
        for (int k = 0; k < 3; ++k) {
            StudySpec shard = spec;
            shard.shardIndex = k;
            shard.shardCount = 3;
            const StudyResult part = runStudy(shard);
            rows += static_cast<int>(part.rows.size());
            if (k == 0) joined += studyCsvHeader();
            for (const auto& r : part.rows) joined += studyCsvRow(r);
        }
        QCOMPARE(rows, 8);
        QCOMPARE(withoutWallColumn(joined), withoutWallColumn(fullCsv));
        const auto parsed = parseStudyCsv(joined);
        QVERIFY(parsed && parsed->size() == 8);
    }
    void studyCsvFormat() {
        QCOMPARE(studyCsvHeader(), std::string("integrator,family,precision,dt,steps,force_evals,repeats,wall_min,wall_q1,"
                                               "wall_median,wall_q3,error_final,error_max,error_rms,error_energy,status\n"));
        // A failing run: euler far above its limit on a stiff ring.
        StudySpec spec;
        spec.params = params(SceneKind::Ring2d, {{"ks", 1e5}});
        spec.integrators = {"euler"};
        spec.dts = {0.01};
        spec.duration = 0.5;
        spec.reference = "rk4";
        spec.samples = 5;
        const StudyReference ref = computeReference(spec);
        const StudyRow row = runStudyItem(spec, spec.integrators.size() ? StudyItem{"euler", "double", 0.01, -1.0} : StudyItem{}, ref);
        QVERIFY(!row.ok);
        const QString line = QString::fromStdString(studyCsvRow(row)).trimmed();
        const QStringList f = line.split(',');
        QCOMPARE(f.size(), 16);
        QCOMPARE(f[1], QString("explicit-rk"));
        QCOMPARE(f[2], QString("double"));
        for (int k = 11; k <= 14; ++k) QVERIFY(f[k].isEmpty());  // never an error value
        QVERIFY2(f[15].startsWith("failed@"), qPrintable(line));
        QVERIFY(f[15].mid(7).toDouble() >= 0.0 && f[15].mid(7).toDouble() < 0.5);
        // The reference printed its own error estimate.
        QVERIFY(std::isfinite(ref.estimatedError) && ref.estimatedError >= 0.0);
        QVERIFY(ref.description.find("rk4") != std::string::npos);
    }
    void studyRefusesBadSpecs() {
        StudySpec spec = oscillatorStudy({"euler"}, 1.0, {0.3});  // 2 s is not a multiple of 0.3
        QVERIFY(validateStudy(spec));
        spec.dts = {0.01};
        spec.integrators = {"leapfrog"};
        QVERIFY(validateStudy(spec));
        spec.integrators = {"euler"};
        spec.shardIndex = 3;
        spec.shardCount = 2;
        QVERIFY(validateStudy(spec));
    }
    void cancelStopsAStudy() {
        StudySpec spec = oscillatorStudy({"euler", "rk4"}, 1.0, {0.01, 0.005});
        std::atomic<bool> cancel{false};
        int calls = 0;
        const StudyResult r = runStudy(spec, [&](const StudyProgress& p) {
            ++calls;
            if (p.done >= 2) cancel = true;
        }, &cancel);
        QVERIFY(r.cancelled);
        QVERIFY(r.rows.size() < 4);
        QVERIFY(calls >= 2);
    }
};

QTEST_GUILESS_MAIN(TestNumerics)
#include "test_numerics.moc"
