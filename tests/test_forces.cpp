// Force terms: forces are minus the gradient of their energies, internal forces sum to zero,
// momentum is conserved, a term a scene does not have is never evaluated, and one particle's
// force split by part (the free-body diagram) adds up to its total.
#include <QtTest>

#include <cmath>
#include <random>

#include "simcore/forces.h"
#include "simcore/simulation.h"

using namespace simcore;

Q_DECLARE_METATYPE(simcore::SceneKind)

namespace {

Eigen::VectorXd randomised(const Body& body, double amplitude, unsigned seed) {
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-amplitude, amplitude);
    Eigen::VectorXd x = Eigen::Map<const Eigen::VectorXd>(body.positions.data(), body.positions.size());
    for (Eigen::Index k = 0; k < x.size(); ++k)
        if (body.topology.dimension == 3 || k % 3 != 2) x[k] += u(rng);
    return x;
}

// Central finite difference of E at x along every coordinate; compares with f = -grad E.
template <class Energy>
double maxRelativeGradientError(const Eigen::VectorXd& x, const Eigen::VectorXd& f, Energy energy) {
    const double h = 1e-6;
    double worst = 0.0;
    const double scale = f.cwiseAbs().maxCoeff();
    Eigen::VectorXd probe = x;
    for (Eigen::Index k = 0; k < x.size(); ++k) {
        probe[k] = x[k] + h;
        const double ep = energy(probe);
        probe[k] = x[k] - h;
        const double em = energy(probe);
        probe[k] = x[k];
        const double numeric = -(ep - em) / (2.0 * h);
        worst = std::max(worst, std::abs(numeric - f[k]) / scale);
    }
    return worst;
}

Body bodyFor(const QString& name) {
    if (name == "ring2d") return buildRing2d({12, 1.5, 2.0}, 1.0, 1.0);
    if (name == "sphere3d") return buildSphere3d({2, 1.5, 2.0}, 1.0, 1.0);
    return buildLatLongSphere({8, 5, 1.5, 2.0}, 1.0, 1.0);
}

}  // namespace

class TestForces : public QObject {
    Q_OBJECT
private slots:
    void springForceIsMinusGradient_data() {
        QTest::addColumn<QString>("scene");
        QTest::newRow("ring2d") << "ring2d";
        QTest::newRow("sphere3d") << "sphere3d";
        QTest::newRow("latlong") << "latlong";
    }
    void springForceIsMinusGradient() {
        QFETCH(QString, scene);
        const Body body = bodyFor(scene);
        const Eigen::VectorXd x = randomised(body, 0.2, 7);
        const Eigen::VectorXd v = Eigen::VectorXd::Zero(x.size());
        for (int fam = 0; fam < kSpringFamilyCount; ++fam) {
            const SpringSet& springs = body.topology.springs[std::size_t(fam)];
            Eigen::VectorXd f = Eigen::VectorXd::Zero(x.size());
            int degenerate = 0;
            addSprings(springs, 800.0 + 100.0 * fam, 0.0, x.data(), v.data(), f.data(), degenerate);
            QCOMPARE(degenerate, 0);
            const double error = maxRelativeGradientError(x, f, [&](const Eigen::VectorXd& p) {
                return springEnergy(springs, 800.0 + 100.0 * fam, p.data());
            });
            QVERIFY2(error < 1e-6, qPrintable(QString("family %1 error %2").arg(fam).arg(error)));
        }
    }
    void gasForceIsMinusGradient_data() { springForceIsMinusGradient_data(); }
    void gasForceIsMinusGradient() {
        QFETCH(QString, scene);
        const Body body = bodyFor(scene);
        const Eigen::VectorXd x = randomised(body, 0.2, 11);
        for (const Surface& s : body.topology.surfaces) {
            Eigen::VectorXd f = Eigen::VectorXd::Zero(x.size());
            const double c = 20.0;
            addGas(s, body.topology.dimension, c, x.data(), f.data());
            const double error = maxRelativeGradientError(x, f, [&](const Eigen::VectorXd& p) {
                return gasEnergy(c, enclosedVolume(s, p.data(), body.topology.dimension));
            });
            QVERIFY2(error < 1e-6, qPrintable(QString("gas error %1").arg(error)));
        }
    }
    void pointerForceIsMinusGradient() {
        const Body body = bodyFor("sphere3d");
        const Eigen::VectorXd x = randomised(body, 0.1, 3);
        const Eigen::VectorXd v = Eigen::VectorXd::Zero(x.size());
        PointerSpring pointer{true, 5, Eigen::Vector3d(3.0, 1.0, -0.5)};
        Eigen::VectorXd f = Eigen::VectorXd::Zero(x.size());
        addPointer(pointer, 150.0, 0.0, 0.3, x.data(), v.data(), f.data());
        const double error = maxRelativeGradientError(
            x, f, [&](const Eigen::VectorXd& p) { return pointerEnergy(pointer, 150.0, 0.3, p.data()); });
        QVERIFY(error < 1e-6);
    }
    void internalForcesSumToZero() {
        // Springs (with damping, random velocities) and gas are internal: no net force or torque
        // about the origin (for gas: a closed surface under uniform pressure).
        for (const QString scene : {"ring2d", "sphere3d", "latlong"}) {
            const Body body = bodyFor(scene);
            const Eigen::VectorXd x = randomised(body, 0.2, 5);
            const Eigen::VectorXd v = randomised(body, 1.0, 9) - x;
            Eigen::VectorXd f = Eigen::VectorXd::Zero(x.size());
            int degenerate = 0;
            for (const SpringSet& s : body.topology.springs)
                addSprings(s, 800.0, 15.0, x.data(), v.data(), f.data(), degenerate);
            for (const Surface& s : body.topology.surfaces)
                addGas(s, body.topology.dimension, 20.0, x.data(), f.data());
            const Eigen::Map<const Eigen::Matrix3Xd> F(f.data(), 3, body.topology.particleCount());
            QVERIFY2(F.rowwise().sum().norm() < 1e-10 * F.cwiseAbs().sum(), qPrintable(scene));
        }
    }
    void degenerateSpringGivesNoNaN() {
        SpringSet s;
        s.add(0, 1, 1.0);
        Eigen::VectorXd x = Eigen::VectorXd::Zero(6), v = Eigen::VectorXd::Zero(6), f = Eigen::VectorXd::Zero(6);
        int degenerate = 0;
        addSprings(s, 800.0, 15.0, x.data(), v.data(), f.data(), degenerate);
        QCOMPARE(degenerate, 1);
        QVERIFY(f.allFinite());
    }
    void momentumIsConserved_data() { springForceIsMinusGradient_data(); }
    void momentumIsConserved() {
        // Gravity off, box far away: only internal forces act, so total momentum stays put.
        QFETCH(QString, scene);
        ParameterSet p(findScene(scene == "latlong" ? "sphere3d-latlong" : scene.toStdString())->kind);
        QVERIFY(!p.set(simcore::Param::Gravity, 0.0));
        QVERIFY(!p.set(simcore::Param::Box, 1000.0));
        QVERIFY(!p.set(simcore::Param::Perturb, 0.1));
        QVERIFY(!p.set(simcore::Param::MassInner, 3.0));
        Simulation sim(p, "rk4");
        Eigen::Matrix3Xd vel = Eigen::Matrix3Xd::Random(3, sim.particleCount());
        if (sim.topology().dimension == 2) vel.row(2).setZero();
        sim.setState(sim.positions(), vel);
        auto momentum = [&] {
            Eigen::Vector3d m = Eigen::Vector3d::Zero();
            for (int i = 0; i < sim.particleCount(); ++i) m += sim.body().mass[i] * sim.velocities().col(i);
            return m;
        };
        const Eigen::Vector3d before = momentum();
        for (int i = 0; i < 300; ++i) QVERIFY(sim.step());
        QVERIFY2((momentum() - before).norm() < 1e-10 * (1.0 + before.norm()),
                 qPrintable(QString::number((momentum() - before).norm())));
        QVERIFY(sim.diagnostics().removedDamping > 0.0);  // it did deform and damp
    }
    void absentTermsAreNeverEvaluated() {
        // The 1D spring declares no gas and no layer constraint: neither runs, ever.
        ParameterSet p(SceneKind::Spring1d);
        Simulation sim(p, "rk4");
        for (int i = 0; i < 100; ++i) QVERIFY(sim.step());
        const ForceModel& f = sim.forces();
        QCOMPARE(f.evaluations(Term::Gas), std::uint64_t(0));
        QCOMPARE(f.evaluations(Term::LayerConstraint), std::uint64_t(0));
        QCOMPARE(f.evaluations(Term::Pointer), std::uint64_t(0));  // nothing grabbed
        QCOMPARE(f.evaluations(Term::Springs), std::uint64_t(400));  // 4 RK4 stages x 100 steps
        QCOMPARE(f.evaluations(Term::Gravity), std::uint64_t(400));
        QCOMPARE(f.evaluations(Term::Collisions), std::uint64_t(400));  // contact = force: every stage
        QVERIFY(!sim.diagnostics().hasGas);

        ParameterSet ring(SceneKind::Ring2d);
        Simulation sim2(ring, "midpoint");
        for (int i = 0; i < 10; ++i) QVERIFY(sim2.step());
        QCOMPARE(sim2.forces().evaluations(Term::Gas), std::uint64_t(20));
        QCOMPARE(sim2.forces().evaluations(Term::LayerConstraint), std::uint64_t(20));  // the barrier, every stage
        sim2.grab(20, Eigen::Vector3d(3, 3, 0));
        QVERIFY(sim2.step());
        QCOMPARE(sim2.forces().evaluations(Term::Pointer), std::uint64_t(2));
    }

    void breakdownSumsToTotal_data() {
        QTest::addColumn<SceneKind>("kind");
        QTest::newRow("ring2d") << SceneKind::Ring2d;
        QTest::newRow("sphere3d") << SceneKind::Sphere3d;
    }
    void breakdownSumsToTotal() {
        // A body dropped onto the floor (contact = force), one outer particle pulled by the
        // mouse spring and one inner particle pushed beyond its outer partner's tangent plane
        // (the layer barrier acts): every part of the free-body diagram is exercised, and for
        // every particle the parts add up to the total force, which is the model's own.
        QFETCH(SceneKind, kind);
        Simulation sim(ParameterSet(kind), "rk4");
        const double floor = sim.boxCentre().y() - sim.boxHalfSize();
        auto lowest = [&] {
            Eigen::Index i = 0;
            sim.positions().row(1).minCoeff(&i);
            return int(i);
        };
        for (int steps = 0; steps < 200000 && sim.positions()(1, lowest()) >= floor; ++steps) QVERIFY(sim.step());
        QVERIFY2(sim.positions()(1, lowest()) < floor, "the body never reached the floor");
        const int inContact = lowest();
        const Topology& topo = sim.topology();
        const auto [inner, outer] = topo.layerPairs[topo.layerPairs.size() / 3];
        Eigen::Matrix3Xd x = sim.positions(), v = sim.velocities();
        const Eigen::Vector3d centre = x.rowwise().mean();
        x.col(inner) = x.col(outer) + 0.1 * (x.col(outer) - centre).normalized();
        sim.setState(x, v);
        int pulled = -1;
        for (int i = 0; i < topo.particleCount(); ++i)
            if (topo.layer[std::size_t(i)] == Layer::Outer && i != outer && i != inContact) pulled = i;
        sim.grab(pulled, sim.positions().col(pulled) + Eigen::Vector3d(0.3, 0.4, 0.0));

        const std::uint64_t evaluations = sim.forces().forceEvaluations();
        std::vector<double> f(std::size_t(3 * topo.particleCount()));
        sim.currentForces(f.data());
        auto part = [](const ForceBreakdown& b, ForcePart p) { return b[p].norm(); };
        for (int i = 0; i < topo.particleCount(); ++i) {
            const ForceBreakdown b = sim.forceBreakdown(i);
            QCOMPARE(b.particle, i);
            Eigen::Vector3d sum = Eigen::Vector3d::Zero();
            double scale = 0.0;
            for (int k = 0; k < kForcePartCount; ++k) {
                sum += b.part[std::size_t(k)];
                scale += b.part[std::size_t(k)].norm();
                if (!b.present[std::size_t(k)]) QCOMPARE(b.part[std::size_t(k)].norm(), 0.0);
            }
            // The total is the step's force, bit for bit.
            for (int a = 0; a < 3; ++a) QCOMPARE(b.total[a], f[std::size_t(3 * i + a)]);
            QVERIFY2((sum - b.total).norm() <= 1e-12 * scale,
                     qPrintable(QString("particle %1: |sum - total| = %2, sum of |parts| = %3")
                                    .arg(i).arg((sum - b.total).norm()).arg(scale)));
            // Gravity is the particle's weight.
            QCOMPARE(b[ForcePart::Gravity].y(), -sim.body().mass[i] * sim.forces().params.gravity);
            // A particle feels only its own layer's gas.
            const bool isInner = topo.layer[std::size_t(i)] == Layer::Inner;
            QCOMPARE(part(b, isInner ? ForcePart::GasOuter : ForcePart::GasInner), 0.0);
            QVERIFY(part(b, isInner ? ForcePart::GasInner : ForcePart::GasOuter) > 0.0);
            QVERIFY(part(b, ForcePart::Structural) > 0.0);
            QCOMPARE(part(b, ForcePart::Mouse) > 0.0, i == pulled);
        }
        QVERIFY(sim.forceBreakdown(inContact)[ForcePart::Walls].y() > 0.0);  // the floor pushes up
        QVERIFY(part(sim.forceBreakdown(inner), ForcePart::Barrier) > 0.0);
        QVERIFY(sim.forceBreakdown(inner).has(ForcePart::Barrier));
        QVERIFY(sim.forceBreakdown(pulled)[ForcePart::Mouse].x() > 0.0);      // towards the anchor
        QCOMPARE(sim.forces().forceEvaluations(), evaluations);                // not counted
        QCOMPARE(sim.forceBreakdown(-1).particle, -1);
        QCOMPARE(sim.forceBreakdown(topo.particleCount()).total.norm(), 0.0);

        // Contact = projection: the walls are no force, so no part.
        ParameterSet projection(kind);
        QVERIFY(!projection.set(simcore::Param::Contact, 1.0));
        Simulation projected(projection, "rk4");
        const ForceBreakdown b = projected.forceBreakdown(0);
        QVERIFY(!b.has(ForcePart::Walls) && !b.has(ForcePart::Barrier));
        QVERIFY(b.has(ForcePart::Gravity) && b.has(ForcePart::Structural));
    }
};

QTEST_GUILESS_MAIN(TestForces)
#include "test_forces.moc"
