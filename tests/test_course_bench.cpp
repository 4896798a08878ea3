// The numerics course bench (issue 28): raw timings and their quartiles, the time budget,
// several error measures, the fastest of each family, the float build of the reference
// problem and its round-off floor, compensated summation, and long-time energy. Nothing here
// passes or fails by the wall clock: a budget is tested at 0 s past (every run exceeds a
// nanosecond) and at a day (none exceeds it).
#include <QtTest>

#include <cmath>

#include "simcore/integrator_table.h"
#include "simcore/simulation.h"
#include "simlab/analytic.h"
#include "simlab/conservation.h"
#include "simlab/reference_problem.h"
#include "simlab/study.h"

#include "sim_test_support.h"

using namespace simcore;
using namespace simlab;
using testsupport::params;

namespace {

StudySpec undampedStudy(std::vector<std::string> integrators, std::vector<double> dts) {
    StudySpec spec;
    spec.params = params(SceneKind::Spring1d, {{"kd", 0.0}, {"box", 1000.0}});
    spec.integrators = std::move(integrators);
    spec.dts = std::move(dts);
    spec.duration = 2.0;
    return spec;
}

StudyRow syntheticRow(const std::string& integrator, double dt, double wall, double evals, double error) {
    StudyRow r;
    r.item = {integrator, "double", dt, -1.0};
    r.dt = dt;
    r.walls = {wall};
    summariseWalls(r);
    r.forceEvaluations = static_cast<std::uint64_t>(evals);
    r.errorMax = r.errorFinal = r.errorRms = error;
    return r;
}

}  // namespace

class TestCourseBench : public QObject {
    Q_OBJECT
private slots:
    void quartilesInterpolateTheOrderStatistics() {
        QCOMPARE(wallQuantile({4.0, 1.0, 3.0, 2.0}, 0.0), 1.0);
        QCOMPARE(wallQuantile({4.0, 1.0, 3.0, 2.0}, 0.5), 2.5);
        QCOMPARE(wallQuantile({4.0, 1.0, 3.0, 2.0}, 0.25), 1.75);
        QCOMPARE(wallQuantile({4.0, 1.0, 3.0, 2.0}, 1.0), 4.0);
        QCOMPARE(wallQuantile({7.0}, 0.75), 7.0);
    }

    void repeatsKeepEveryRawTime() {
        StudySpec spec = undampedStudy({"rk4"}, {0.01});
        spec.repeat = 5;
        const StudyResult result = runStudy(spec);
        QCOMPARE(result.rows.size(), std::size_t(1));
        const StudyRow& row = result.rows[0];
        QCOMPARE(row.walls.size(), std::size_t(5));
        QVERIFY(row.wallMin <= row.wallQ1 && row.wallQ1 <= row.wallSeconds && row.wallSeconds <= row.wallQ3);
        QCOMPARE(row.wallMin, *std::min_element(row.walls.begin(), row.walls.end()));
        QCOMPARE(row.wallSeconds, wallQuantile(row.walls, 0.5));
        // The long-format timings: one line per repeat, in run order.
        const QStringList lines = QString::fromStdString(studyTimingsCsvRows(row)).trimmed().split('\n');
        QCOMPARE(lines.size(), 5);
        for (int k = 0; k < 5; ++k) {
            const QStringList f = lines[k].split(',');
            QCOMPARE(f.size(), 5);
            QCOMPARE(f[0], QString("rk4"));
            QCOMPARE(f[3].toInt(), k + 1);
            QCOMPARE(f[4].toDouble(), row.walls[static_cast<std::size_t>(k)]);
        }
        // The summary CSV carries the statistics and reads back.
        const auto parsed = parseStudyCsv(studyCsvHeader() + studyCsvRow(row));
        QVERIFY(parsed && parsed->size() == 1);
        QCOMPARE((*parsed)[0].wallQ3, row.wallQ3);
        QCOMPARE((*parsed)[0].errorRms, row.errorRms);
    }

    void errorMeasuresAreFinalMaxAndRms() {
        const StudyResult result = runStudy(undampedStudy({"yoshida4"}, {0.01, 0.005, 0.0025}));
        for (const StudyRow& r : result.rows) {
            QVERIFY(r.ok);
            // RMS over the grid lies between the largest and the largest / sqrt(G).
            const double g = static_cast<double>(result.reference.times.size());
            QVERIFY(r.errorRms <= r.errorMax * (1 + 1e-12) && r.errorRms >= r.errorMax / std::sqrt(g) * (1 - 1e-12));
            QVERIFY(r.errorFinal <= r.errorMax * (1 + 1e-12));
        }
        // Fitted orders per measure: 4 on each for the undamped closed form.
        const auto fits = fitOrders(result.rows, result.reference.estimatedError);
        QCOMPARE(fits.size(), std::size_t(1));
        QVERIFY2(std::abs(fits[0].order - 4.0) < 0.15, qPrintable(QString::number(fits[0].order)));
        QVERIFY2(std::abs(fits[0].orderRms - 4.0) < 0.15, qPrintable(QString::number(fits[0].orderRms)));
        QCOMPARE(fits[0].pointsFinal, 3);
        QVERIFY(std::isfinite(fits[0].orderFinal));
    }

    void yoshida8IsEighthOrderInTheStudy() {
        const StudyResult result = runStudy(undampedStudy({"yoshida8"}, {0.02, 0.01, 0.005}));
        const auto fits = fitOrders(result.rows, result.reference.estimatedError);
        QVERIFY2(fits[0].order > 7.5 && fits[0].order < 8.5, qPrintable(QString::number(fits[0].order)));
    }

    void timeBudgetRecordsNotReachedAndStopsTheCurve() {
        StudySpec spec = undampedStudy({"rk4"}, {0.01, 0.005});
        spec.timeBudget = 1e-9;  // every run takes longer than a nanosecond
        const StudyResult over = runStudy(spec);
        QCOMPARE(over.rows.size(), std::size_t(2));
        for (const StudyRow& r : over.rows) {
            QVERIFY(!r.ok && !r.reached);
            QCOMPARE(r.status(), std::string("not reached"));
            const QStringList f = QString::fromStdString(studyCsvRow(r)).trimmed().split(',');
            QCOMPARE(f.size(), 16);
            for (int k = 11; k <= 14; ++k) QVERIFY(f[k].isEmpty());
            QCOMPARE(f[15], QString("not reached"));
        }
        // The second (costlier) point was not even run: the curve stopped at the first.
        QVERIFY(over.rows[1].failure.find("cheaper point") != std::string::npos);
        const auto parsed = parseStudyCsv(studyCsvHeader() + studyCsvRow(over.rows[0]));
        QVERIFY(parsed && !(*parsed)[0].reached);
        // A day is enough for both.
        spec.timeBudget = 86400.0;
        for (const StudyRow& r : runStudy(spec).rows) QVERIFY(r.ok && r.reached);
        // A cheaper point of another curve does not stop this one.
        StudyRow unreached = syntheticRow("euler", 0.01, 0.0, 0, 0.0);
        unreached.ok = unreached.reached = false;
        spec.timeBudget = 0.0;
        const StudyReference ref = computeReference(spec);
        QVERIFY(runStudyPoint(spec, {"rk4", "double", 0.005, -1.0}, ref, {unreached}).reached);
        unreached.item.integrator = "rk4";
        QVERIFY(!runStudyPoint(spec, {"rk4", "double", 0.005, -1.0}, ref, {unreached}).reached);
        QVERIFY(validateStudy([&] { StudySpec s = spec; s.timeBudget = -1.0; return s; }()));
    }

    void fastestOfEachFamilyIsFoundByInterpolation() {
        // rk4 reaches 1e-3 at 2e-3 s (log-log midway between its points), euler never does;
        // verlet at 1e-3 s beats yoshida4 at 4e-3 s among the symplectic methods.
        const std::vector<StudyRow> rows = {
            syntheticRow("euler", 0.01, 1e-3, 100, 1e-1),   syntheticRow("euler", 0.005, 2e-3, 200, 5e-2),
            syntheticRow("rk4", 0.01, 1e-3, 400, 1e-2),     syntheticRow("rk4", 0.005, 4e-3, 800, 1e-4),
            syntheticRow("verlet", 0.01, 1e-3, 200, 1e-3),  syntheticRow("yoshida4", 0.01, 4e-3, 400, 1e-3),
        };
        const auto best = fastestByFamily(rows);
        auto find = [&](const std::string& family, double level) -> const FamilyBest* {
            for (const FamilyBest& b : best)
                if (b.family == family && std::abs(b.error / level - 1.0) < 1e-9) return &b;
            return nullptr;
        };
        const FamilyBest* rk = find("explicit-rk", 1e-3);
        QVERIFY(rk);
        QCOMPARE(rk->integrator, std::string("rk4"));
        QVERIFY(std::abs(rk->wallSeconds - 2e-3) < 1e-12);
        QVERIFY(std::abs(rk->forceEvaluations - 400.0 * std::sqrt(2.0)) < 1e-9);
        const FamilyBest* rk1 = find("explicit-rk", 1e-1);
        QVERIFY(rk1 && rk1->integrator == "euler");  // euler's first point is already there, cheapest
        const FamilyBest* sym = find("symplectic", 1e-3);
        QVERIFY(sym && sym->integrator == "verlet");
        QVERIFY(!find("symplectic", 1e-4));  // no symplectic curve gets there
        // The diagram rings them and draws the band.
        const std::string svg = studySvg(rows, "t");
        QVERIFY(svg.find("class=\"fastest\"") != std::string::npos);
        QVERIFY(svg.find("class=\"band\"") != std::string::npos);
        QVERIFY(svg.find("[symplectic]") != std::string::npos);
    }

    void familyColoursAreShadesOfOneHue() {
        for (const IntegratorInfo& info : integratorTable()) {
            // Each member's colour is in the same hue family: the darkest member is the family's.
            QVERIFY(std::string(familyColour(info.family)) != "#7f7f7f");
        }
        QCOMPARE(std::string(familyColour("symplectic")), std::string(studyColour("symplectic-euler")));
        QCOMPARE(std::string(familyColour("explicit-rk")), std::string(studyColour("euler")));
    }

    void floatBuildInDoubleIsTheSimulation() {
        // The reference problem's double build integrates the same equations as the Simulation:
        // the same positions to round-off, for a fixed and a free top, damped and undamped.
        for (double fixed : {1.0, 0.0})
            for (const char* method : {"rk4", "verlet", "yoshida4"}) {
                const ParameterSet p = params(SceneKind::Spring1d, {{"fixed_end", fixed}, {"kd", 3.0}, {"box", 1000.0}});
                const std::vector<double> grid = {0.25, 0.5};
                const ReferenceProblemRun run = runReferenceProblem(p, method, 0.005, grid, "double", false);
                QCOMPARE(run.positions.size(), std::size_t(2));
                ParameterSet q = p;
                q.set(Param::Dt, 0.005);
                Simulation sim(q, method);
                QVERIFY(sim.advanceTo(0.5));
                const double diff = (sim.positions() - run.positions.back()).cwiseAbs().maxCoeff();
                QVERIFY2(diff < 1e-12, qPrintable(QString("%1 fixed %2: %3").arg(method).arg(fixed).arg(diff)));
                QCOMPARE(static_cast<std::uint64_t>(run.evaluations), sim.diagnostics().forceEvaluations);
            }
    }

    void floatRoundOffStopsTheErrorFalling() {
        // rk4 on the undamped closed form, h halved 9 times: in double the error keeps falling
        // (by ~16 each halving); in float it stops near 1e-6 and rises again as the steps get
        // more (each rounding a random kick), above the truncation error by far.
        StudySpec spec = undampedStudy({"rk4"}, {0.005, 0.0025, 0.00125, 0.000625, 0.0003125, 0.00015625, 7.8125e-05,
                                                 3.90625e-05});
        spec.precisions = {"double", "float"};
        QVERIFY(!validateStudy(spec));
        const StudyResult result = runStudy(spec);
        std::vector<double> dbl, flt;
        for (const StudyRow& r : result.rows) {
            QVERIFY(r.ok);
            (r.item.precision == "float" ? flt : dbl).push_back(r.errorMax);
        }
        QCOMPARE(dbl.size(), std::size_t(8));
        QCOMPARE(flt.size(), std::size_t(8));
        for (std::size_t k = 1; k < dbl.size(); ++k) QVERIFY2(dbl[k] < dbl[k - 1] / 10.0, qPrintable(QString::number(k)));
        const double floorMin = *std::min_element(flt.begin(), flt.end());
        QVERIFY2(floorMin > 1e-7 && floorMin < 1e-5, qPrintable(QString::number(floorMin)));
        QVERIFY2(flt.back() > 4.0 * floorMin, qPrintable(QString("%1 vs %2").arg(flt.back()).arg(floorMin)));
        QVERIFY(flt.back() > 1e6 * dbl.back());
        // The predicted floor eps X sqrt(T / h) is of the measured size at the smallest step.
        const double predicted = roundoffFloor("float", referenceScale(result.reference), 2.0, 3.90625e-05);
        QVERIFY2(flt.back() > predicted / 10.0 && flt.back() < predicted * 10.0,
                 qPrintable(QString("%1 predicted %2").arg(flt.back()).arg(predicted)));
        // The fits are per curve: rk4 and rk4 (float).
        QCOMPARE(fitOrders(result.rows, 0.0).size(), std::size_t(2));
        // The floor is drawn.
        QVERIFY(studySvg(result.rows, "t", referenceScale(result.reference), 2.0).find("round-off floor, float") !=
                std::string::npos);

        // Compensated summation of the state update: the rise is gone at the smallest step.
        spec.precisions = {"float"};
        spec.dts = {3.90625e-05};
        spec.compensated = true;
        const StudyResult kahan = runStudy(spec);
        QVERIFY2(kahan.rows[0].errorMax < flt.back() / 4.0,
                 qPrintable(QString("%1 vs %2").arg(kahan.rows[0].errorMax).arg(flt.back())));
    }

    void floatPathStudyFlattensAtTheRoundOffFloor() {
        // Every body but the reference problem runs the float path of the Simulation
        // (float_path.h). A ring in free flight, rk4 against its rk4 reference: in double the
        // error falls ~16x per halving of the step; in float it flattens where the step's
        // rounding overtakes the truncation error, far above the double curve.
        StudySpec spec;
        spec.params = params(SceneKind::Ring2d, {{"gravity", 0.0}, {"perturb", 0.02}});
        spec.integrators = {"rk4"};
        spec.dts = {0.01, 0.005, 0.0025, 0.00125};
        spec.duration = 0.2;
        spec.precisions = {"double", "float"};
        QVERIFY(!floatOnReferenceProblem(spec));
        QVERIFY(!validateStudy(spec));
        const StudyResult result = runStudy(spec);
        std::vector<double> dbl, flt;
        for (const StudyRow& r : result.rows) {
            QVERIFY2(r.ok, r.failure.c_str());
            QCOMPARE(r.steps, std::lround(spec.duration / r.item.dt));
            QVERIFY(r.forceEvaluations >= static_cast<std::uint64_t>(4 * r.steps));  // rk4: four a step
            (r.item.precision == "float" ? flt : dbl).push_back(r.errorMax);
        }
        QCOMPARE(dbl.size(), std::size_t(4));
        QCOMPARE(flt.size(), std::size_t(4));
        for (std::size_t k = 1; k < dbl.size(); ++k)
            QVERIFY2(dbl[k] < dbl[k - 1] / 8.0, qPrintable(QString("%1: %2 vs %3").arg(k).arg(dbl[k]).arg(dbl[k - 1])));
        // At the largest step truncation rules both: float is double's error (2.5e-5 m).
        QVERIFY2(std::abs(flt[0] - dbl[0]) < 0.05 * dbl[0], qPrintable(QString("%1 vs %2").arg(flt[0]).arg(dbl[0])));
        // At the smallest the float curve has flattened (it no longer falls 16x) at its floor,
        // of the predicted size eps X sqrt(T / h), far above the double one (measured: float
        // 7.0e-7, 6.6e-7, 8.5e-7 m from 5 ms down; double 7.1e-7, 3.3e-8, 1.8e-9 m).
        QVERIFY2(flt[3] > flt[2] / 4.0, qPrintable(QString("%1 vs %2").arg(flt[3]).arg(flt[2])));
        QVERIFY2(flt[3] > 100.0 * dbl[3], qPrintable(QString("%1 vs %2").arg(flt[3]).arg(dbl[3])));
        const double predicted = roundoffFloor("float", referenceScale(result.reference), spec.duration, spec.dts[3]);
        QVERIFY2(flt[3] > predicted / 30.0 && flt[3] < predicted * 30.0,
                 qPrintable(QString("%1 predicted %2").arg(flt[3]).arg(predicted)));
        QVERIFY(roundoffFloor("float", 1.0, 1.0, 0.01) > 1e8 * roundoffFloor("double", 1.0, 1.0, 0.01));
    }

    void floatIsRefusedWhereItHasNoBuild() {
        StudySpec spec = undampedStudy({"rk45"}, {0.01});
        spec.precisions = {"float"};
        QVERIFY(validateStudy(spec));
        // The float path (every other body): the front door's words, as run's and bench's.
        spec.params = params(SceneKind::Ring2d, {});
        spec.integrators = {"rk4", "yoshida4"};
        QCOMPARE(QString::fromStdString(validateStudy(spec).value_or("")),
                 QString("precision float is built for the explicit integrators euler, midpoint, rk4, "
                         "symplectic-euler, verlet, not 'yoshida4'"));
        spec.integrators = {"rk4", "symplectic-euler"};
        QVERIFY(!validateStudy(spec));
        spec.compensated = true;  // Kahan: the reference problem's only
        QVERIFY(validateStudy(spec));
        spec = undampedStudy({"rk4"}, {0.01});
        spec.compensated = true;  // compensated without float
        QVERIFY(validateStudy(spec));
        spec.precisions = {"float", "quad"};
        QVERIFY(validateStudy(spec));
    }

    void slopeIntervalOnKnownData() {
        std::vector<std::pair<double, double>> pts;
        for (int k = 0; k < 20; ++k) {
            const double t = std::pow(10.0, k / 5.0);
            pts.emplace_back(t, 3.0 * std::sqrt(t) * (k % 2 ? 1.1 : 0.9));
        }
        const SlopeFit fit = logLogSlopeInterval(pts);
        QVERIFY(std::abs(fit.slope - 0.5) < 0.02);
        QVERIFY(fit.lo < fit.slope && fit.slope < fit.hi && fit.hi - fit.lo < 0.1);
        QCOMPARE(growthClass(0.1), std::string("bounded"));
        QCOMPARE(growthClass(0.5), std::string("random-walk"));
        QCOMPARE(growthClass(1.0), std::string("drift"));
    }

    void conservationClassifiesTheMethods() {
        // spring1d undamped, 300 periods of its mode at h w = 0.28: Verlet and yoshida4 keep
        // the energy error bounded, rk4 loses energy steadily (alpha ~ 1).
        ConservationSpec spec;
        spec.params = params(SceneKind::Spring1d, {});  // kd = 15 by default: switched off
        spec.integrators = {"verlet", "yoshida4", "rk4"};
        spec.periods = 300;
        spec.dt = 0.01;
        QVERIFY(!validateConservation(spec));
        const ConservationResult result = runConservation(spec);
        QVERIFY(result.undamped.find("kd = 0") != std::string::npos);
        QVERIFY(std::abs(result.omegaMax - std::sqrt(800.0)) < 1e-6);
        QCOMPARE(result.rows.size(), std::size_t(3));
        QCOMPARE(result.rows[0].growth, std::string("bounded"));
        QCOMPARE(result.rows[1].growth, std::string("bounded"));
        QCOMPARE(result.rows[2].growth, std::string("drift"));
        QVERIFY(result.rows[2].alphaLo > 0.9 && result.rows[2].alphaHi < 1.1);
        QVERIFY(result.rows[1].finalError < result.rows[0].finalError);  // 4th order: smaller bound
        const QStringList header = QString::fromStdString(conservationCsvHeader()).trimmed().split(',');
        QCOMPARE(header.mid(0, 5), QStringList({"integrator", "alpha", "alpha_lo", "alpha_hi", "class"}));
        const QStringList row = QString::fromStdString(conservationCsvRow(result.rows[2])).trimmed().split(',');
        QCOMPARE(row.size(), header.size());
        QCOMPARE(row[4], QString("drift"));
        QVERIFY(conservationSvg(result, "t").find("slope 1/2") != std::string::npos);
    }

    void roundOffWalksLikeTheSquareRootOfTime() {
        // In float, yoshida8's truncation error is far below the rounding: the energy error is
        // a random walk, alpha ~ 1/2 (Brouwer's law).
        ConservationSpec spec;
        spec.params = params(SceneKind::Spring1d, {});
        spec.integrators = {"yoshida8"};
        spec.periods = 2000;
        spec.dt = 0.0005;
        spec.precision = "float";
        QVERIFY(!validateConservation(spec));
        const ConservationResult result = runConservation(spec);
        QCOMPARE(result.rows[0].growth, std::string("random-walk"));
        QVERIFY2(result.rows[0].alpha > 0.3 && result.rows[0].alpha < 0.7, qPrintable(QString::number(result.rows[0].alpha)));
        spec.integrators = {"rk45"};
        QVERIFY(validateConservation(spec));
    }
};

QTEST_GUILESS_MAIN(TestCourseBench)
#include "test_course_bench.moc"
