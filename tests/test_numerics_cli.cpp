// elastic-lab-cli study / stability / gallery and run's error columns: the scriptable contract.
#include <QtTest>

#include "cli_process.h"

#include <QProcess>
#include <QTemporaryDir>

#include <cmath>

namespace {

using Result = CliResult;
Result cli(const QStringList& args) { return runCli(args); }

QString readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

// The CSV without its wall-time columns wall_min .. wall_q3 (the fields two identical runs do
// not share).
QString withoutWall(const QString& csv) {
    QStringList out;
    for (const QString& line : csv.split('\n', Qt::SkipEmptyParts)) {
        QStringList f = line.split(',');
        f.remove(7, 4);
        out << f.join(',');
    }
    return out.join('\n');
}

const QStringList kStudy = {"study", "--scene", "spring1d", "--set", "box=100", "--integrators",
                            "euler,midpoint,rk4,rk45", "--dts", "0.002,0.001", "--tols", "1e-5,1e-8",
                            "--duration", "1", "--quiet"};

}  // namespace

class TestNumericsCli : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private slots:
    void studyWritesTheDocumentedCsvAndPlot() {
        QStringList args = kStudy;
        args.removeAll("--quiet");
        args << "--csv" << path("full.csv") << "--plot" << path("full.svg") << "--repeat" << "3";
        const Result r = cli(args);
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains("reference    closed form"), qPrintable(r.out));
        QVERIFY(r.out.contains("its estimated error at T"));
        QVERIFY(r.out.contains("fitted convergence order"));
        for (const char* name : {"euler", "midpoint", "rk4", "rk45"}) QVERIFY(r.out.contains(QString("  ") + name));
        const QStringList lines = readAll(path("full.csv")).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.value(0), QString("integrator,family,precision,dt,steps,force_evals,repeats,wall_min,wall_q1,"
                                         "wall_median,wall_q3,error_final,error_max,error_rms,error_energy,status"));
        QCOMPARE(lines.size(), 1 + 3 * 2 + 2);
        for (int i = 1; i < lines.size(); ++i) {
            const QStringList f = lines[i].split(',');
            QCOMPARE(f.size(), 16);
            QCOMPARE(f[15], QString("ok"));
            QCOMPARE(f[6], QString("3"));
            for (int k = 3; k < 15; ++k) QVERIFY2(std::isfinite(f[k].toDouble()), qPrintable(lines[i]));
        }
        QVERIFY(r.out.contains("fastest of each family at each accuracy"));
        const QString svg = readAll(path("full.svg"));
        QVERIFY(svg.startsWith("<svg") && svg.contains("force evaluations") && svg.contains("wall time"));
    }
    void shardsConcatenateIntoTheSameCsv() {
        QStringList full = kStudy;
        full << "--csv" << path("one.csv");
        QCOMPARE(cli(full).code, 0);
        QString joined;
        for (const char* shard : {"1/3", "2/3", "3/3"}) {
            QStringList args = kStudy;
            const QString file = path(QString("shard%1.csv").arg(shard[0]));
            args << "--shard" << shard << "--csv" << file;
            QCOMPARE(cli(args).code, 0);
            joined += readAll(file);
        }
        QCOMPARE(withoutWall(joined), withoutWall(readAll(path("one.csv"))));
        // Merging: fit and plot from the concatenated shards.
        QFile out(path("joined.csv"));
        QVERIFY(out.open(QIODevice::WriteOnly));
        out.write(joined.toUtf8());
        out.close();
        const Result merged = cli({"study", "--from-csv", path("joined.csv"), "--plot", path("joined.svg")});
        QCOMPARE(merged.code, 0);
        QVERIFY(merged.out.contains("rk4"));
        QVERIFY(QFile::exists(path("joined.svg")));
    }
    void failedRunsAreMarkedNotPlotted() {
        const Result r = cli({"study", "--scene", "ring2d", "--set", "ks=1e5", "--integrators", "euler,rk4", "--dts",
                              "0.01,0.0005", "--duration", "0.5", "--samples", "5", "--csv", path("fail.csv"), "--quiet"});
        QCOMPARE(r.code, 0);
        const QStringList lines = readAll(path("fail.csv")).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 5);
        QVERIFY2(lines[1].startsWith("euler,explicit-rk,double,0.01,") && lines[1].contains(",,,,failed@"),
                 qPrintable(lines[1]));
        QVERIFY2(lines[4].startsWith("rk4,") && lines[4].split(',')[3].toDouble() == 0.0005 && lines[4].endsWith(",ok"),
                 qPrintable(lines[4]));
    }
    void studyKeepsRawTimingsAndStopsAtTheBudget() {
        // --timings: one row per run and repeat; --time-budget 1e-9: no run can meet it (every
        // run takes longer than a nanosecond), so every point is "not reached", errors empty.
        const Result r = cli({"study", "--scene", "spring1d", "--integrators", "rk4,yoshida4", "--dts", "0.01,0.005",
                              "--duration", "1", "--repeat", "4", "--timings", path("timings.csv"), "--quiet"});
        QCOMPARE(r.code, 0);
        const QStringList timings = readAll(path("timings.csv")).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(timings.value(0), QString("integrator,precision,dt,repeat,wall_seconds"));
        QCOMPARE(timings.size(), 1 + 2 * 2 * 4);
        QVERIFY(timings[4].startsWith("rk4,double,0.01,4,"));
        const Result over = cli({"study", "--scene", "spring1d", "--integrators", "rk4", "--dts", "0.01,0.005",
                                 "--duration", "1", "--time-budget", "1e-9", "--csv", path("budget.csv")});
        QCOMPARE(over.code, 0);
        QVERIFY2(over.out.contains("not reached"), qPrintable(over.out));
        const QStringList rows = readAll(path("budget.csv")).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(rows.size(), 3);
        for (int i = 1; i < 3; ++i) QVERIFY2(rows[i].endsWith(",,,,,not reached"), qPrintable(rows[i]));
        // The merge mode reads such rows back (and the 9-column rows of older studies).
        QCOMPARE(cli({"study", "--from-csv", path("budget.csv")}).code, 0);
        QFile old(path("old.csv"));
        QVERIFY(old.open(QIODevice::WriteOnly));
        old.write("integrator,dt,steps,force_evals,wall_seconds,error_final,error_max,error_energy,status\n"
                  "rk4,0.01,100,400,1e-4,1e-6,2e-6,1e-3,ok\nrk4,0.005,200,800,2e-4,6e-8,1.2e-7,1e-4,ok\n");
        old.close();
        const Result merged = cli({"study", "--from-csv", path("old.csv")});
        QCOMPARE(merged.code, 0);
        QVERIFY2(merged.out.contains("4.06 (2)"), qPrintable(merged.out));
        QCOMPARE(cli({"study", "--scene", "spring1d", "--integrators", "rk4", "--dts", "0.01", "--time-budget", "-1"}).code, 2);
    }
    void floatPrecisionAndConservation() {
        const Result f = cli({"study", "--scene", "spring1d", "--set", "kd=0", "--integrators", "rk4", "--dts",
                              "0.005,3.90625e-05", "--duration", "2", "--precision", "double,float", "--plot",
                              path("float.svg"), "--quiet"});
        QCOMPARE(f.code, 0);
        QVERIFY(readAll(path("float.svg")).contains("round-off floor, float"));
        // Beyond spring1d the float path of the Simulation (issue 27): rk4 runs, yoshida4 is refused.
        const Result ring = cli({"study", "--scene", "ring2d", "--set", "gravity=0", "--integrators", "rk4", "--dts",
                                 "0.01", "--duration", "0.1", "--precision", "float"});
        QCOMPARE(ring.code, 0);
        QVERIFY2(ring.out.contains("the float32 path") && ring.out.contains("rk4 (float)"), qPrintable(ring.out));
        QCOMPARE(cli({"study", "--scene", "ring2d", "--integrators", "yoshida4", "--dts", "0.01", "--precision", "float"}).code, 2);
        QCOMPARE(cli({"study", "--scene", "spring1d", "--integrators", "rk4", "--dts", "0.01", "--compensated"}).code, 2);
        const Result c = cli({"conservation", "--scene", "spring1d", "--dt", "0.01", "--periods", "200", "--integrators",
                              "verlet,rk4", "--csv", path("cons.csv"), "--curves", path("curves.csv"), "--plot",
                              path("cons.svg")});
        QCOMPARE(c.code, 0);
        QVERIFY2(c.out.contains("undamped (kd = 0"), qPrintable(c.out));
        const QStringList lines = readAll(path("cons.csv")).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        QVERIFY(lines[0].startsWith("integrator,alpha,alpha_lo,alpha_hi,class,"));
        QCOMPARE(lines[1].split(',')[4], QString("bounded"));
        QCOMPARE(lines[2].split(',')[4], QString("drift"));
        QVERIFY(readAll(path("curves.csv")).startsWith("integrator,t,energy_error\n"));
        QVERIFY(readAll(path("cons.svg")).contains("slope 1 (drift)"));
        QCOMPARE(cli({"conservation", "--scene", "spring1d", "--dt", "0.01", "--integrators", "rk45"}).code, 2);
        QCOMPARE(cli({"conservation", "--scene", "spring1d", "--dt", "0.01", "--periods", "0.5"}).code, 2);
        const Result list = cli({"integrators"});
        QVERIFY(list.out.contains("yoshida8           order 8  symplectic"));
    }
    void autoReferenceTurnsToTheStiffSolver() {
        // Issue 13: on the stiff ring rk4 16x below the smallest step (1.25 ms) is unstable; `auto`
        // then takes cvode-bdf at a tight tolerance (it used to end the study with exit 3),
        // says why, and its estimated error is far below the studied errors.
        const Result r = cli({"study", "--scene", "ring2d", "--set", "ks=1e6", "--set", "rks=1e6", "--set", "gravity=0",
                              "--set", "perturb=0.05", "--integrators", "implicit-euler", "--dts", "0.04,0.02",
                              "--duration", "0.08", "--samples", "2"});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains("reference    cvode-bdf at atol = rtol = 1e-11"), qPrintable(r.out));
        QVERIFY2(r.out.contains("because rk4 at dt = 0.00125 s failed"), qPrintable(r.out));
        // An explicit --reference rk4 still fails as before: only auto falls back.
        QCOMPARE(cli({"study", "--scene", "ring2d", "--set", "ks=1e6", "--set", "rks=1e6", "--set", "gravity=0",
                      "--set", "perturb=0.05", "--integrators", "implicit-euler", "--dts", "0.04,0.02", "--duration",
                      "0.08", "--samples", "2", "--reference", "rk4"})
                     .code,
                 3);
    }
    void badStudyInputIsRefused() {
        QCOMPARE(cli({"study", "--scene", "spring1d", "--integrators", "euler", "--dts", "0.3", "--duration", "1"}).code, 2);
        QCOMPARE(cli({"study", "--scene", "spring1d", "--integrators", "leapfrog", "--dts", "0.01"}).code, 2);
        QCOMPARE(cli({"study", "--scene", "spring1d", "--integrators", "euler", "--dts", "0.01", "--shard", "3/2"}).code, 2);
        QCOMPARE(cli({"study", "--scene", "ring2d", "--integrators", "euler", "--dts", "0.01", "--reference", "exact"}).code, 2);
    }
    void refinementWritesTheDocumentedCsvAndPlot() {
        const Result r = cli({"study", "--scene", "ring2d", "--set", "gravity=0", "--refine", "particles=12,24,48",
                              "--integrators", "rk4", "--duration", "0.1", "--temporal-runs", "2", "--csv",
                              path("refine.csv"), "--plot", path("refine.svg")});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains("fitted spatial order") && r.out.contains("  volume ") && r.out.contains("  com "),
                 qPrintable(r.out));
        QVERIFY(r.out.contains("time error"));
        const QStringList lines = readAll(path("refine.csv")).split('\n', Qt::SkipEmptyParts);
        QVERIFY2(lines.value(0).startsWith("key,value,particles,springs,wall_seconds,error_volume,error_com,status"),
                 qPrintable(lines.value(0)));
        QCOMPARE(lines.size(), 1 + 3);
        const QStringList coarse = lines[1].split(','), finest = lines[3].split(',');
        QCOMPARE(coarse.mid(0, 4), QStringList({"particles", "12", "24", "60"}));
        QCOMPARE(coarse[7], QString("ok"));
        QVERIFY(coarse[5].toDouble() > lines[2].split(',')[5].toDouble());  // the volume error shrinks
        QCOMPARE(finest[5].toDouble(), 0.0);
        QCOMPARE(finest.last(), QString("1"));  // the reference
        const QString svg = readAll(path("refine.svg"));
        QVERIFY(svg.startsWith("<svg") && svg.contains("mesh: particles") && svg.contains("step: rk4"));
    }
    void badRefinementInputIsRefused() {
        const QStringList base = {"study", "--scene", "ring2d", "--duration", "0.05", "--quiet"};
        QCOMPARE(cli(QStringList(base) << "--refine" << "ks=1,2").code, 2);
        QCOMPARE(cli(QStringList(base) << "--refine" << "subdivisions=1,2").code, 2);  // sphere3d's key
        QCOMPARE(cli(QStringList(base) << "--refine" << "particles=12").code, 2);
        QCOMPARE(cli(QStringList(base) << "--refine" << "particles=12,24" << "--integrators" << "euler,rk4").code, 2);
        QCOMPARE(cli(QStringList(base) << "--refine" << "particles=12,96" << "--dt" << "0.005").code, 2);  // unstable at 96
        QCOMPARE(cli(QStringList(base) << "--dt" << "0.001" << "--dts" << "0.001").code, 2);  // --dt is --refine's
        QCOMPARE(cli(QStringList(base) << "--refine" << "particles=12,24" << "--dts" << "0.001").code, 2);
        QCOMPARE(cli(QStringList(base) << "--refine" << "particles=12,24" << "--from-csv" << path("refine.csv")).code, 2);
    }
    void stabilityPrintsMeasuredBesidePredicted() {
        const Result r = cli({"stability", "--scene", "spring1d", "--set", "kd=0", "--set", "gravity=0", "--set",
                              "fixed_end=0", "--set", "box=100", "--integrators", "rk4,verlet,implicit-euler",
                              "--duration", "2", "--csv", path("stab.csv")});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains("w_max = 40 rad/s"), qPrintable(r.out));
        const QStringList lines = readAll(path("stab.csv")).split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.value(0), QString("integrator,dt_stable,dt_unstable,dt_predicted,h_omega_stable,h_omega_predicted,reason"));
        QCOMPARE(lines.size(), 4);
        // rk4: predicted h w = 2 sqrt(2); measured within 15% above it (slow growth near the edge).
        const QStringList rk4 = lines[1].split(',');
        QVERIFY(std::abs(rk4[5].toDouble() - 2.0 * std::sqrt(2.0)) < 1e-3);
        QVERIFY2(rk4[4].toDouble() > 0.9 * 2.0 * std::sqrt(2.0) && rk4[4].toDouble() < 1.15 * 2.0 * std::sqrt(2.0),
                 qPrintable(lines[1]));
        const QStringList verlet = lines[2].split(',');
        QVERIFY2(std::abs(verlet[4].toDouble() - 2.0) < 0.1, qPrintable(lines[2]));
        QVERIFY(lines[3].startsWith("implicit-euler,1,inf,inf"));
    }
    void stabilityShardsConcatenate() {
        const QStringList base = {"stability", "--scene", "spring1d", "--integrators", "euler,rk4,verlet",
                                  "--duration", "1", "--quiet"};
        QCOMPARE(cli(QStringList(base) << "--csv" << path("stab-full.csv")).code, 0);
        QString joined;
        for (const char* shard : {"1/2", "2/2"}) {
            const QString file = path(QString("stab-%1.csv").arg(shard[0]));
            QCOMPARE(cli(QStringList(base) << "--shard" << shard << "--csv" << file).code, 0);
            joined += readAll(file);
        }
        QCOMPARE(joined, readAll(path("stab-full.csv")));  // no timings: byte-identical
        QCOMPARE(joined.count('\n'), 4);
    }
    void runExportsErrorEstimates() {
        const Result r = cli({"run", "--scene", "ring2d", "--integrator", "rk4", "--duration", "0.03", "--error-estimate",
                              "--csv", path("est.csv"), "--quiet"});
        QCOMPARE(r.code, 0);
        const QStringList lines = readAll(path("est.csv")).split('\n', Qt::SkipEmptyParts);
        const QStringList header = lines[0].split(',');
        const auto e = header.indexOf("error_estimate");
        QVERIFY(e >= 0 && header.contains("energy_drift"));
        QCOMPARE(lines[1].split(',')[e].toDouble(), -1.0);  // the start row has no step yet
        QVERIFY(lines[2].split(',')[e].toDouble() > 0.0);
        const Result adaptive = cli({"run", "--scene", "ring2d", "--integrator", "rk45", "--atol", "1e-8", "--rtol",
                                     "1e-8", "--duration", "0.5", "--csv", path("rk45.csv"), "--quiet"});
        QCOMPARE(adaptive.code, 0);
        const QStringList rows = readAll(path("rk45.csv")).split('\n', Qt::SkipEmptyParts);
        const QStringList last = rows.last().split(',');
        QCOMPARE(last[1].toDouble(), 0.5);  // lands on the end time
        QVERIFY(last[e].toDouble() >= 0.0);
    }
    void preRunWarningOnlyForExplicitMethods() {
        const QStringList base = {"run", "--scene", "ring2d", "--dt", "0.03", "--duration", "0.06", "--quiet"};
        QVERIFY(cli(QStringList(base) << "--integrator" << "rk4").err.contains("warning: dt = 0.03"));
        QVERIFY(!cli(QStringList(base) << "--integrator" << "implicit-euler").err.contains("warning"));
    }
    void galleryRunsByName() {
        const Result r = cli({"gallery", "--run", "stiff-1e6-implicit"});
        QCOMPARE(r.code, 0);
        QVERIFY(r.out.contains("stiff-1e6-implicit") && r.out.contains(" ok "));
        QCOMPARE(cli({"gallery", "--run", "no-such-case"}).code, 2);
    }
};

QTEST_GUILESS_MAIN(TestNumericsCli)
#include "test_numerics_cli.moc"
