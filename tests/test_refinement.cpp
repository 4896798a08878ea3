// The refinement study (simlab/refinement.h): the same physical body at several resolutions
// against the finest. A weightless ring inflating from its rest shape to its equilibrium is a
// smooth motion every level resolves: its volume error shrinks at second order in the spacing,
// and a symmetric body's centre of mass does not move at all (round-off, never fitted).
#include <QtTest>

#include <atomic>
#include <cmath>

#include "simcore/simulation.h"
#include "simlab/refinement.h"
#include "simlab/stability.h"

#include "sim_test_support.h"

using namespace simcore;
using namespace simlab;

namespace {

RefinementSpec weightlessRing(std::vector<int> levels) {
    RefinementSpec spec;
    spec.params = testsupport::params(SceneKind::Ring2d, {{"gravity", 0.0}});
    spec.key = "particles";
    spec.values = std::move(levels);
    spec.duration = 0.2;
    return spec;
}

}  // namespace

class TestRefinement : public QObject {
    Q_OBJECT
private slots:
    void volumeErrorShrinksAtSecondOrder() {
        // Given out of order: rows come back coarse to fine, the finest the reference.
        const RefinementSpec spec = weightlessRing({48, 12, 24});
        const RefinementResult r = runRefinement(spec);
        QVERIFY(!r.cancelled);
        QCOMPARE(int(r.rows.size()), 3);
        QCOMPARE(r.rows[0].value, 12);
        QCOMPARE(r.rows[2].value, 48);
        QVERIFY(r.rows[2].reference && !r.rows[0].reference && !r.rows[1].reference);
        QCOMPARE(r.rows[2].errorVolume, 0.0);
        QCOMPARE(r.rows[2].errorCom, 0.0);
        for (const RefinementRow& row : r.rows) {
            QVERIFY2(row.ok, row.failure.c_str());
            QCOMPARE(row.particles, 2 * row.value);
            QCOMPARE(row.steps, std::lround(spec.duration / r.dt));
        }
        // Spacing halves per level; the error against the finest, C (h^2 - h_48^2), falls 5x
        // from 12 to 24 at second order (3x at first order).
        QVERIFY(std::abs(r.rows[0].h / r.rows[1].h - 2.0) < 0.05);
        const double e12 = r.rows[0].errorVolume, e24 = r.rows[1].errorVolume;
        QVERIFY2(e24 > 0.0 && e12 / e24 > 4.0 && e12 / e24 < 6.5, qPrintable(QString("%1 %2").arg(e12).arg(e24)));
        // The step's own error, measured on the temporal curve, is far below the mesh's.
        QVERIFY(std::isfinite(r.timeErrorVolume));
        QVERIFY(r.timeErrorVolume < 1e-4 * e24);
        QCOMPARE(r.temporalValue, 24);
        QCOMPARE(int(r.temporal.size()), spec.temporalRuns);
        QVERIFY(r.temporal[0].ok && r.temporal[1].ok);
        QVERIFY(r.temporal[1].errorVolume > r.temporal[0].errorVolume);  // a coarser step errs more
        const std::vector<SpatialOrder> fits = fitSpatialOrders(r);
        QCOMPARE(fits[0].observable, std::string("volume"));
        QCOMPARE(fits[0].points, 2);
        QVERIFY2(fits[0].order > 1.8 && fits[0].order < 2.8, qPrintable(QString::number(fits[0].order)));
        // The symmetric weightless body's centre of mass stays put: round-off only, not fitted.
        QVERIFY(r.rows[0].errorCom < 1e-12);
        QCOMPARE(fits[1].points, 0);
        QVERIFY(std::isnan(fits[1].order));
    }

    void chosenStepIsStableAtTheFinestAndDividesTheGrid() {
        const RefinementSpec spec = weightlessRing({12, 48});
        const auto [dt, rule] = refinementStep(spec);
        QVERIFY(isWholeMultiple(spec.interval, dt));
        QVERIFY(dt <= 0.25 * spec.params.get(simcore::Param::Dt));
        ParameterSet finest = refinementLevel(spec, 48);
        finest.set(simcore::Param::Dt, dt);
        QVERIFY(!stabilityAdvice(Simulation(finest, "rk4")).has_value());
        QVERIFY(rule.find("quarter") != std::string::npos);
        // A given step is used as given.
        RefinementSpec given = spec;
        given.dt = 0.0005;
        QCOMPARE(refinementStep(given).first, 0.0005);
    }

    void badSpecsAreNamed() {
        RefinementSpec spec = weightlessRing({12, 24});
        QVERIFY(!validateRefinement(spec));
        spec.key = "subdivisions";  // another scene's key
        QVERIFY(validateRefinement(spec)->find("particles") != std::string::npos);
        spec.key = "ks";
        QVERIFY(validateRefinement(spec).has_value());
        spec = weightlessRing({24, 24});
        QVERIFY(validateRefinement(spec)->find("two different levels") != std::string::npos);
        spec = weightlessRing({12, 24});
        spec.params = ParameterSet(SceneKind::Spring1d);
        QVERIFY(validateRefinement(spec).has_value());
        spec = weightlessRing({12, 96});
        spec.dt = 0.005;  // stable on 12 particles, not on 96
        const auto unstable = validateRefinement(spec);
        QVERIFY(unstable && unstable->find("particles=96") != std::string::npos);
        spec.dt = 0.003;  // does not divide the 0.01 s grid
        QVERIFY(validateRefinement(spec)->find("whole multiple") != std::string::npos);
        spec = weightlessRing({12, 24});
        spec.duration = 0.215;
        QVERIFY(validateRefinement(spec).has_value());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, runRefinement(spec));
    }

    void latLongRefinesSlicesWithHalfAsManyStacks() {
        RefinementSpec spec;
        spec.params = ParameterSet(SceneKind::Sphere3dLatLong);
        spec.key = refinementKey(SceneKind::Sphere3dLatLong);
        QCOMPARE(spec.key, std::string("slices"));
        QCOMPARE(refinementLevel(spec, 16).getInt(simcore::Param::Stacks), 8);
        QCOMPARE(refinementKey(SceneKind::Sphere3d), std::string("subdivisions"));
        QVERIFY(refinementKey(SceneKind::Spring1d).empty());
    }

    void cancelStopsTheStudy() {
        // Cancelled while the reference runs (its first progress report): nothing to compare with.
        RefinementSpec spec = weightlessRing({12, 24, 48});
        std::atomic<bool> cancel{false};
        std::vector<std::string> seen;
        RefinementResult r = runRefinement(spec, [&](const StudyProgress& p) {
            seen.push_back(p.what);
            cancel = true;
        }, &cancel);
        QVERIFY(r.cancelled);
        QVERIFY(r.rows.empty() && r.temporal.empty());
        QCOMPARE(seen.back(), std::string("cancelled"));
        // Cancelled when the second level starts: the reference and the first level are kept,
        // the rest (and the temporal curve) never run.
        cancel = false;
        r = runRefinement(spec, [&](const StudyProgress& p) {
            if (p.what == "particles=24") cancel = true;
        }, &cancel);
        QVERIFY(r.cancelled);
        QCOMPARE(int(r.rows.size()), 2);
        QCOMPARE(r.rows[0].value, 12);
        QVERIFY(r.rows[1].reference);
        QVERIFY(r.temporal.empty());
    }

    void csvAndPlot() {
        RefinementSpec spec = weightlessRing({12, 24});
        spec.duration = 0.05;
        spec.temporalRuns = 2;
        const RefinementResult r = runRefinement(spec);
        QVERIFY(refinementCsvHeader().rfind("key,value,particles,springs,wall_seconds,error_volume,error_com,status", 0) == 0);
        const std::string finest = refinementCsvRow(spec.key, r.rows[1]);
        QVERIFY(finest.rfind("particles,24,48,", 0) == 0);
        QVERIFY(finest.find(",0,0,ok,") != std::string::npos);
        QVERIFY(finest.size() > 2 && finest.substr(finest.size() - 3) == ",1\n");
        // A failed row: empty errors, the reason in the status without commas.
        RefinementRow failed = r.rows[0];
        failed.ok = false;
        failed.failedAt = 0.5;
        failed.failure = "runaway velocity, fast";
        const std::string line = refinementCsvRow(spec.key, failed);
        QVERIFY(line.find(",,,failed@0.5: runaway velocity; fast,") != std::string::npos);
        const std::string svg = refinementSvg(spec, r, "t");
        QVERIFY(svg.rfind("<svg", 0) == 0);
        QVERIFY(svg.find("mesh: particles") != std::string::npos && svg.find("step: rk4") != std::string::npos);
    }
};

QTEST_APPLESS_MAIN(TestRefinement)
#include "test_refinement.moc"
