// The command line for scripts (issue 29): `--json` on scenes, params, integrators and run, and
// `--csv -` writing the rows to standard output with the report moved to standard error; bench
// --interleave (paired timing for the benchmark scripts, issue 27).
#include <cmath>

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <tuple>
#include <vector>

#include "app/cli/cli.h"
#include "cli_process.h"

namespace {

QJsonDocument json(const QString& text) {
    QJsonParseError error{};
    QJsonDocument doc = QJsonDocument::fromJson(text.toUtf8(), &error);
    if (error.error != QJsonParseError::NoError) qWarning("not JSON: %s", qPrintable(error.errorString()));
    return doc;
}

}  // namespace

class TestCliScripts : public QObject {
    Q_OBJECT

private slots:
    // bench --interleave N: the runs of every thread count take turns of N steps in one process
    // (paired timing beside a load that drifts). Each run still takes its steps from the same
    // start: the rows' steps and hashes are those of the runs one after the other.
    void benchInterleavesTheRuns() {
        const QStringList base{"bench", "--scene", "sphere3d", "--set", "subdivisions=4", "--set", "perturb=0.01",
                               "--warmup", "2", "--steps", "11", "--threads", "1,2", "--header"};
        auto hashes = [&](const QStringList& extra) {
            const CliResult r = runCli(base + extra);
            if (r.code != 0) qWarning("%s", qPrintable(r.err));
            const QStringList lines = r.out.trimmed().split('\n');
            const QStringList header = lines[0].split(',');
            QStringList out;  // threads:steps:hash per row
            for (qsizetype k = 1; k < lines.size(); ++k) {
                const QStringList row = lines[k].split(',');
                out << row[header.indexOf("threads")] + ":" + row[header.indexOf("steps")] + ":" +
                           row[header.indexOf("state_hash")];
            }
            return out;
        };
        const QStringList apart = hashes({});
        QCOMPARE(apart.size(), 2);
        QCOMPARE(hashes({"--interleave", "4"}), apart);   // 4 + 4 + 3 steps per run
        QCOMPARE(hashes({"--interleave", "11"}), apart);  // one turn each
        QCOMPARE(hashes({"--interleave", "50"}), apart);  // a turn longer than the run
        QCOMPARE(runCli(base + QStringList{"--interleave", "0"}).code, 2);
        // The turns: each run in order, every turn at most N steps, each run's turns adding up
        // to its steps, and no run two turns ahead of another.
        for (auto [steps, n, runs] : {std::tuple{11L, 4L, 2}, {12L, 4L, 3}, {5L, 9L, 2}, {1L, 1L, 1}}) {
            const std::vector<cli::BenchTurn> turns = cli::benchTurns(steps, n, runs);
            std::vector<long> done(static_cast<std::size_t>(runs), 0);
            for (std::size_t k = 0; k < turns.size(); ++k) {
                QCOMPARE(turns[k].run, static_cast<int>(k % static_cast<std::size_t>(runs)));
                QVERIFY(turns[k].steps >= 1 && turns[k].steps <= n);
                done[static_cast<std::size_t>(turns[k].run)] += turns[k].steps;
            }
            for (long d : done) QCOMPARE(d, steps);
            QCOMPARE(turns.size(), static_cast<std::size_t>(runs) * static_cast<std::size_t>((steps + n - 1) / n));
        }
    }
    void listingsAsJson() {
        const CliResult scenes = runCli({"scenes", "--json"});
        QCOMPARE(scenes.code, 0);
        const QJsonArray s = json(scenes.out).array();
        QCOMPARE(s.size(), 7);  // four of one body, three of several
        QCOMPARE(s[0].toObject()["name"].toString(), QString("spring1d"));
        QCOMPARE(s[0].toObject()["gas"].toBool(), false);
        QCOMPARE(s[1].toObject()["gas"].toBool(), true);
        QVERIFY(!s[3].toObject().contains("bodies"));
        QCOMPARE(s[4].toObject()["name"].toString(), QString("collide2d"));
        QCOMPARE(s[4].toObject()["bodies"].toInt(), 2);
        QCOMPARE(s[6].toObject()["name"].toString(), QString("stack3d"));
        QCOMPARE(s[6].toObject()["bodies"].toInt(), 3);

        // A scene of several bodies: the world's values and each body's, after --set.
        const CliResult world = runCli({"params", "--scene", "collide3d", "--set", "body2.mass=4", "--set",
                                        "gravity=0", "--json"});
        QCOMPARE(world.code, 0);
        const QJsonObject w = json(world.out).object();
        QCOMPARE(w["world"].toObject()["gravity"].toDouble(), 0.0);
        QCOMPARE(w["bodies"].toArray().size(), 2);
        QCOMPARE(w["bodies"][0].toObject()["mass"].toDouble(), 1.0);
        QCOMPARE(w["bodies"][1].toObject()["mass"].toDouble(), 4.0);
        QCOMPARE(w["bodies"][1].toObject()["kind"].toString(), QString("sphere3d"));
        QVERIFY(!w["bodies"][1].toObject().contains("gravity"));

        const CliResult integrators = runCli({"integrators", "--json"});
        QCOMPARE(integrators.code, 0);
        bool rk4 = false;
        for (const QJsonValue& i : json(integrators.out).array())
            rk4 |= i.toObject()["name"].toString() == "rk4" && i.toObject()["order"].toInt() == 4;
        QVERIFY(rk4);

        const CliResult params = runCli({"params", "--scene", "ring2d", "--set", "ks=900", "--json"});
        QCOMPARE(params.code, 0);
        QJsonObject ks, pressureInner, contact;
        for (const QJsonValue& p : json(params.out).array()) {
            const QJsonObject o = p.toObject();
            if (o["key"] == "ks") ks = o;
            if (o["key"] == "pressure_inner") pressureInner = o;
            if (o["key"] == "contact") contact = o;
        }
        QCOMPARE(ks["unit"].toString(), QString("N/m"));
        QCOMPARE(ks["default"].toDouble(), 800.0);
        QCOMPARE(ks["value"].toDouble(), 900.0);  // after --set
        QCOMPARE(ks["min"].toDouble(), 0.0);
        QVERIFY(pressureInner["default"].isNull());
        QCOMPARE(pressureInner["inherits"].toString(), QString("pressure"));
        QCOMPARE(contact["choices"].toArray(), QJsonArray({"force", "projection"}));
    }

    void runSummaryAsJson() {
        const CliResult r = runCli({"run", "--scene", "ring2d", "--duration", "0.3", "--json"});
        QCOMPARE(r.code, 0);
        const QJsonObject o = json(r.out).object();
        QCOMPARE(o["scene"].toString(), QString("ring2d"));
        QCOMPARE(o["status"].toString(), QString("ok"));
        QCOMPARE(o["steps"].toInt(), 100);
        QCOMPARE(o["integrator"].toString(), QString("rk4"));
        QVERIFY(o["energy"].toObject().contains("gas"));
        QVERIFY(o["layers"].toObject()["volume_inner"].toDouble() > 0);
        QCOMPARE(o["cost"].toObject()["force_evaluations"].toInt(), 400);

        // A failed run: exit 3, and the summary says why.
        const CliResult failed = runCli({"run", "--scene", "spring1d", "--integrator", "euler", "--dt", "0.09", "--set",
                                         "kd=0", "--duration", "100", "--json"});
        QCOMPARE(failed.code, 3);
        const QJsonObject f = json(failed.out).object();
        QCOMPARE(f["status"].toString(), QString("failed"));
        QVERIFY(!f["failure"].toObject()["reason"].toString().isEmpty());

        // A scene of several bodies: the totals, min_gap and each body.
        const CliResult w = runCli({"run", "--scene", "collide2d", "--set", "gravity=0", "--set", "body2.mass=4",
                                    "--duration", "0.03", "--json"});
        QCOMPARE(w.code, 0);
        const QJsonObject wo = json(w.out).object();
        QCOMPARE(wo["scene"].toString(), QString("collide2d"));
        QCOMPARE(wo["status"].toString(), QString("ok"));
        QCOMPARE(wo["bodies"].toArray().size(), 2);
        // mass is per particle: 24 particles of 1 kg and of 4 kg.
        QCOMPARE(wo["bodies"][0].toObject()["mass"].toDouble(), 24.0);
        QCOMPARE(wo["bodies"][1].toObject()["mass"].toDouble(), 96.0);
        // Body 1 moves at +2 m/s, body 2 at -2 m/s: p_x = 24*2 - 96*2 = -144 kg m/s.
        QVERIFY(std::abs(wo["momentum"][0].toDouble() + 144.0) < 1e-9);
        QVERIFY(wo["min_gap"].toDouble() > 0.0);

        // The stability of a world: one verdict of the whole system (its spectrum, its trials).
        const CliResult st = runCli({"stability", "--scene", "collide2d", "--set", "gravity=0", "--integrators",
                                     "rk4,implicit-euler", "--duration", "0.3", "--json"});
        QCOMPARE(st.code, 0);
        const QJsonObject so = json(st.out).object();
        QCOMPARE(so["scene"].toString(), QString("collide2d"));
        QCOMPARE(so["bodies"].toInt(), 2);
        QCOMPARE(so["free_coordinates"].toInt(), 2 * 48);
        QVERIFY(so["basis"].toString().startsWith("exact spectrum"));
        const QJsonArray rows = so["rows"].toArray();
        QCOMPARE(rows.size(), 2);
        QCOMPARE(rows[0].toObject()["integrator"].toString(), QString("rk4"));
        QVERIFY(rows[0].toObject()["dt_stable"].toDouble() > 0.0);
        QVERIFY(rows[0].toObject()["dt_stable"].toDouble() < rows[0].toObject()["dt_unstable"].toDouble());
        QVERIFY(rows[1].toObject()["dt_predicted"].isNull());  // implicit Euler: unlimited
    }

    void csvDashWritesTheRowsToStandardOutput() {
        QTemporaryDir dir;
        const QString file = dir.filePath("run.csv");
        const QStringList args = {"run", "--scene", "ring2d", "--duration", "0.1", "--every", "5"};
        QCOMPARE(runCli(args + QStringList{"--csv", file, "--quiet"}).code, 0);
        QFile f(file);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QString rows = QString::fromUtf8(f.readAll());

        const CliResult r = runCli(args + QStringList{"--csv", "-"});
        QCOMPARE(r.code, 0);
        QCOMPARE(r.out, rows);                       // the rows alone on standard output
        QVERIFY2(r.err.contains("integrator   rk4"), qPrintable(r.err));  // the summary on standard error
        QVERIFY(!QFile::exists("-"));

        const CliResult study = runCli({"study", "--scene", "spring1d", "--integrators", "euler,rk4", "--dts",
                                        "0.01,0.005", "--duration", "0.2", "--csv", "-"});
        QCOMPARE(study.code, 0);
        QVERIFY2(study.out.startsWith("integrator,"), qPrintable(study.out));
        QVERIFY2(!study.out.contains("fitted convergence order"), qPrintable(study.out));
        QVERIFY2(study.err.contains("fitted convergence order"), qPrintable(study.err));
    }
};

QTEST_GUILESS_MAIN(TestCliScripts)
#include "test_cli_scripts.moc"
