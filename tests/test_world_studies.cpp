// The studies of a world (issue 26): the stability map and scan of the whole system, the
// work-precision study and the refinement of every body together, through simlab's front door.
#include <algorithm>
#include <cmath>
#include <complex>
#include <limits>
#include <optional>
#include <string>
#include <vector>

#include <QTest>

#include "simcore/world.h"
#include "simlab/refinement.h"
#include "simlab/request.h"
#include "simlab/stability.h"
#include "simlab/study.h"

#ifndef NDEBUG
#define RELEASE_ONLY() QSKIP("a long physics run: Release only")
#else
#define RELEASE_ONLY() (void)0
#endif

using simcore::Param;
using simcore::ParameterSet;
using simcore::World;
using simcore::WorldSpec;
using simlab::LinearModes;

namespace {

WorldSpec scene(const char* name, std::initializer_list<const char*> settings = {}) {
    WorldSpec spec = *simcore::worldScene(name);
    for (const char* s : settings)
        if (auto error = simcore::assignWorld(spec, s)) qFatal("%s: %s", s, error->c_str());
    return spec;
}

// Whether two lists of eigenvalues are the same multiset, to `tolerance` (relative to the
// largest modulus): each of `a` matched to the nearest unmatched one of `b`.
bool sameSpectrum(const std::vector<std::complex<double>>& a, const std::vector<std::complex<double>>& b, double tolerance,
                  double* worst = nullptr) {
    if (a.size() != b.size()) return false;
    double scale = 0.0;
    for (const auto& l : a) scale = std::max(scale, std::abs(l));
    std::vector<bool> used(b.size(), false);
    double largest = 0.0;
    for (const auto& l : a) {
        std::size_t best = b.size();
        for (std::size_t j = 0; j < b.size(); ++j)
            if (!used[j] && (best == b.size() || std::abs(b[j] - l) < std::abs(b[best] - l))) best = j;
        used[best] = true;
        largest = std::max(largest, std::abs(b[best] - l));
    }
    if (worst) *worst = largest / scale;
    return largest <= tolerance * scale;
}

// The euler scan of weightless collide2d over `duration` (to 5 %).
simlab::StabilitySpec weightlessEuler(double duration) {
    simlab::StabilitySpec spec;
    spec.world = scene("collide2d", {"gravity=0"});
    spec.params = spec.world->bodies.front().params;
    spec.integrators = {"euler"};
    spec.duration = duration;
    spec.relativePrecision = 0.05;
    return spec;
}

// Modes of w^2 ~ 0 (rigid motions: translations and rotations of a free body).
int rigidModes(const LinearModes& modes) {
    int n = 0;
    for (double w2 : modes.omega2)
        if (std::abs(w2) <= 1e-6 * modes.omegaMax * modes.omegaMax) ++n;
    return n;
}

}  // namespace

class TestWorldStudies : public QObject {
    Q_OBJECT

private slots:
    void bodiesApartGiveTheUnionOfTheirSpectra() {
        // At its start no pair is within the skin: the world's Jacobian is block diagonal, its
        // eigenvalues are each body's alone (exact spectra: 2 x 64 free coordinates).
        const WorldSpec spec = scene("collide2d", {"body2.mass=4", "body2.ks=2000"});
        const LinearModes world = simlab::stabilityModes(spec);
        std::vector<std::complex<double>> alone;
        int coordinates = 0;
        for (const auto& body : spec.bodies) {
            const LinearModes one = simlab::stabilityModes(body.params);
            alone.insert(alone.end(), one.eigenvalues.begin(), one.eigenvalues.end());
            coordinates += one.freeCoordinates;
        }
        QCOMPARE(world.freeCoordinates, coordinates);
        QVERIFY(!world.eigenvalues.empty());
        double worst = 0.0;
        QVERIFY2(sameSpectrum(world.eigenvalues, alone, 1e-7, &worst), qPrintable(QString::number(worst)));
        // The bodies differ (a stiffer, heavier body 2), so the union is not one body twice.
        QVERIFY(!sameSpectrum(simlab::stabilityModes(spec.bodies[0].params).eigenvalues,
                              simlab::stabilityModes(spec.bodies[1].params).eigenvalues, 1e-6));
        // The verdict is the world's: the stiffer body limits rk4.
        const double limit = simlab::stabilityVerdict(world, "rk4", 0.001).limit;
        const double first = simlab::stabilityVerdict(simlab::stabilityModes(spec.bodies[0].params), "rk4", 0.001).limit;
        const double second = simlab::stabilityVerdict(simlab::stabilityModes(spec.bodies[1].params), "rk4", 0.001).limit;
        QVERIFY2(std::abs(limit / std::min(first, second) - 1.0) < 1e-6,
                 qPrintable(QString("%1 %2 %3").arg(limit).arg(first).arg(second)));
    }

    void contactBetweenBodiesIsInTheLinearisation() {
        // Weightless and free: apart, each ring can translate freely along x and y, four
        // modes of zero stiffness in all (a turn is not one: the start is not an equilibrium,
        // the gas inflates the rings, and a turned force changes with the turn). Pressed
        // together, the pair's barrier ties their approach: fewer free modes.
        World world(scene("collide2d", {"gravity=0"}), "rk4");
        const LinearModes apart = simlab::linearModes(world, simlab::kVerdictExactLimit, simlab::kVerdictExactLimit);
        QCOMPARE(rigidModes(apart), 4);
        while (world.diagnostics().contactPairsActive == 0) QVERIFY(world.step());
        QVERIFY(world.advanceTo(world.time() + 0.1));
        QVERIFY(world.diagnostics().contactPairsActive > 0);
        const LinearModes pressed = simlab::linearModes(world, simlab::kVerdictExactLimit, simlab::kVerdictExactLimit);
        qInfo("apart: %d rigid modes, w_max %.4g rad/s; in contact (%d pairs): %d rigid modes, w_max %.4g rad/s",
              rigidModes(apart), apart.omegaMax, world.diagnostics().contactPairsActive, rigidModes(pressed),
              pressed.omegaMax);
        QVERIFY(rigidModes(pressed) < 4);
    }

    void eulerLimitAgreesWithRunning() {
        // The world's predicted euler limit beside a bisection by running the whole world (as
        // the one-body scan: perturbed trials, NaN, runaway energy or a crossing = unstable).
        // Weightless collide2d before the bodies meet (0.4 s): the start's linearisation.
        const simlab::StabilitySpec spec = weightlessEuler(0.4);
        simlab::checkStability(spec);
        const LinearModes modes = simlab::stabilityModes(spec);
        const simlab::StabilityRow row = simlab::runStability(spec, modes).front();
        qInfo("collide2d weightless, euler over 0.4 s: predicted %.4g s, measured stable %.4g s, unstable %.4g s (%s), "
              "%d runs",
              row.predicted, row.stable, row.unstable, row.reasonAbove.c_str(), row.runs);
        QVERIFY(row.predicted > 0.0 && std::isfinite(row.predicted));
        QVERIFY2(std::abs(row.predicted / row.stable - 1.0) < 0.15,
                 qPrintable(QString("predicted %1, measured %2").arg(row.predicted).arg(row.stable)));
    }

    void eulerLimitThroughTheImpact() {
        RELEASE_ONLY();
        // Through the impact (1.2 s) the pairs' barrier is the stiffest thing in the world: the
        // measured limit falls below the start's prediction, and above the prediction at the
        // deepest contact (linearModes of the World there, the pairs within the skin in it):
        // the impact is brief, a step may amplify for a few steps and recover.
        const simlab::StabilitySpec spec = weightlessEuler(1.2);
        World world(*spec.world, "rk4");
        double closest = std::numeric_limits<double>::infinity();
        std::optional<LinearModes> deepest;
        while (world.time() < spec.duration) {
            QVERIFY(world.step());
            if (world.diagnostics().contactPairsActive > 0 && world.diagnostics().minGap < closest) {
                closest = world.diagnostics().minGap;
                deepest = simlab::linearModes(world, simlab::kVerdictExactLimit, simlab::kVerdictExactLimit);
            }
        }
        QVERIFY(deepest.has_value());
        const double atStart = simlab::predictedStableStep("euler", simlab::stabilityModes(spec));
        const double atImpact = simlab::predictedStableStep("euler", *deepest);
        const simlab::StabilityRow row = simlab::runStability(spec, simlab::stabilityModes(spec)).front();
        qInfo("collide2d weightless, euler over 1.2 s: predicted at the start %.4g s, at the deepest contact (gap %.3g m) "
              "%.4g s, measured stable %.4g s, unstable %.4g s (%s)",
              atStart, closest, atImpact, row.stable, row.unstable, row.reasonAbove.c_str());
        QVERIFY2(atImpact < row.stable && row.stable < atStart,
                 qPrintable(QString("at the impact %1, measured %2").arg(atImpact).arg(row.stable)));
    }

    void aWorldsTrialRunsTheWorld() {
        // The trial is the world's: far above the limit it blows up, below it runs through.
        simlab::StabilitySpec spec;
        spec.world = scene("collide2d");
        spec.duration = 0.5;
        const double limit = simlab::predictedStableStep("rk4", simlab::stabilityModes(spec));
        QVERIFY(simlab::stabilityTrial(spec, "rk4", 4.0 * limit).has_value());
        QVERIFY(!simlab::stabilityTrial(spec, "rk4", 0.5 * limit).has_value());
    }

    void theFrontDoorChecksAWorldsIntegrators() {
        // xpbd takes one set of springs: bodies with different springs are refused before a run.
        simlab::StabilitySpec spec;
        spec.world = scene("collide2d", {"body2.ks=2000"});
        spec.integrators = {"rk4", "xpbd"};
        try {
            simlab::checkStability(spec);
            QFAIL("accepted");
        } catch (const simlab::RequestError& e) {
            QVERIFY2(std::string(e.what()).find("xpbd") != std::string::npos, e.what());
        }
        simlab::StudySpec study;
        study.world = scene("collide2d");
        study.integrators = {"rk4"};
        study.dts = {0.01};
        study.duration = 0.1;
        study.precisions = {"double", "float"};
        try {
            simlab::checkStudy(study);
            QFAIL("accepted");
        } catch (const simlab::RequestError& e) {
            QVERIFY2(std::string(e.what()).find("several bodies") != std::string::npos, e.what());
        }
    }

    void workPrecisionThroughAnImpact() {
        RELEASE_ONLY();
        // Weightless collide2d to T = 1 s (contact from about 0.45 s): the study's error_final
        // against its rk4 reference halves the step as ordersThroughAnImpact measures it
        // (test_world): euler ~ 1, midpoint ~ 2, rk4 ~ 4.
        simlab::StudySpec spec;
        spec.world = scene("collide2d", {"gravity=0"});
        spec.params = spec.world->bodies.front().params;
        spec.integrators = {"euler", "midpoint", "rk4"};
        spec.dts = {0.002, 0.001, 0.0005};
        spec.duration = 1.0;
        spec.samples = 4;
        simlab::checkStudy(spec);
        const simlab::StudyResult result = simlab::runStudy(spec);
        QCOMPARE(result.rows.size(), std::size_t{9});
        auto error = [&](const std::string& name, double dt) {
            for (const auto& r : result.rows)
                if (r.item.integrator == name && r.item.dt == dt) {
                    if (!r.ok) qFatal("%s at %g: %s", name.c_str(), dt, r.failure.c_str());
                    return r.errorFinal;
                }
            qFatal("no row");
        };
        for (const auto& [name, order] : {std::pair{"euler", 1.0}, {"midpoint", 2.0}, {"rk4", 4.0}}) {
            const double dt = name == std::string("rk4") ? 0.002 : 0.001;
            const double measured = std::log2(error(name, dt) / error(name, dt / 2));
            qInfo("%s: error_final %.3e -> %.3e, order %.2f", name, error(name, dt), error(name, dt / 2), measured);
            QVERIFY2(std::abs(measured - order) < 0.35, qPrintable(QString("%1: %2").arg(name).arg(measured)));
        }
        // The reference is the world's rk4 at 16x below the smallest step, its own error far below.
        QVERIFY(result.reference.description.find("rk4") != std::string::npos);
        QVERIFY(result.reference.estimatedError < 1e-3 * error("rk4", 0.0005) + 1e-12);
        QCOMPARE(int(result.reference.positions.front().cols()), World(*spec.world, "rk4").particleCount());  // every body's
    }

    void refiningEveryBodyTogether() {
        // Every body's particles raised together: the world's particle count doubles with the
        // level, and each coarser level's errors (volume, centre of mass: every body's) are
        // measured against the finest.
        simlab::RefinementSpec spec;
        spec.world = scene("collide2d", {"gravity=0"});
        spec.params = spec.world->bodies.front().params;
        spec.key = "particles";
        spec.values = {8, 16, 32};
        spec.duration = 0.1;
        spec.interval = 0.05;
        spec.temporalRuns = 1;
        simlab::checkRefinement(spec);
        const simlab::RefinementResult result = simlab::runRefinement(spec);
        QCOMPARE(result.rows.size(), std::size_t{3});
        QCOMPARE(result.rows[0].particles, 2 * 2 * 8);
        QCOMPARE(result.rows[2].particles, 2 * 2 * 32);
        QVERIFY(result.rows[2].reference);
        QVERIFY(result.rows[0].ok && result.rows[1].ok);
        QVERIFY(result.rows[0].errorVolume > result.rows[1].errorVolume && result.rows[1].errorVolume > 0.0);
        QVERIFY(result.rows[0].errorCom > 0.0);
        qInfo("collide2d particles 8/16/32: error_volume %.3e %.3e, error_com %.3e %.3e; %s",
              result.rows[0].errorVolume, result.rows[1].errorVolume, result.rows[0].errorCom, result.rows[1].errorCom,
              result.stepRule.c_str());
        // Bodies of different kinds refine with different keys: refused.
        simlab::RefinementSpec mixed = spec;
        mixed.world = scene("collide3d");
        mixed.world->bodies[1].params = ParameterSet(simcore::SceneKind::Sphere3dLatLong);
        mixed.params = mixed.world->bodies.front().params;
        mixed.key = "subdivisions";
        mixed.values = {1, 2};
        const auto refusal = simlab::validateRefinement(mixed);
        QVERIFY(refusal && refusal->find("body2 refines with slices") != std::string::npos);
    }
};

QTEST_APPLESS_MAIN(TestWorldStudies)
#include "test_world_studies.moc"
