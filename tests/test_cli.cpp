// elastic-lab-cli contract: listings, CSV and state columns, exit codes, no NaN in output.
#include <QtTest>

#include <sys/stat.h>
#include <unistd.h>

#include "cli_process.h"

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

#include <cmath>
#include <csignal>

#include "simcore/parallel.h"
#include "simcore/params.h"
#include "simcore/scenes.h"
#include "simcore/world.h"

namespace {

using Result = CliResult;
Result cli(const QStringList& args) { return runCli(args); }

QList<QStringList> readCsv(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    QList<QStringList> rows;
    for (const QByteArray& line : f.readAll().split('\n'))
        if (!line.isEmpty()) rows << QString::fromUtf8(line).split(',');
    return rows;
}

QStringList readLines(const QString& path) {
    QStringList lines;
    for (const QStringList& row : readCsv(path)) lines << row.join(',');
    return lines;
}

// Whether process pid holds a file open under folder (an unnamed O_TMPFILE output shows there
// as "folder/#inode (deleted)").
bool holdsFileIn(qint64 pid, const QString& folder) {
    for (const QFileInfo& fd : QDir(QString("/proc/%1/fd").arg(pid)).entryInfoList(QDir::Files | QDir::System | QDir::NoDotAndDotDot))
        if (QFile::symLinkTarget(fd.filePath()).startsWith(folder + "/")) return true;
    return false;
}

// Bytes in the files process pid holds open under folder (its unnamed O_TMPFILE outputs show
// there as "folder/#inode (deleted)").
qint64 streamedBytes(qint64 pid, const QString& folder) {
    qint64 bytes = 0;
    const QString fds = QString("/proc/%1/fd").arg(pid);
    for (const QFileInfo& fd : QDir(fds).entryInfoList(QDir::Files | QDir::System | QDir::NoDotAndDotDot))
        if (fd.symLinkTarget().startsWith(folder + "/") || QFile::symLinkTarget(fd.filePath()).startsWith(folder + "/"))
            bytes += fd.size();
    return bytes;
}

}  // namespace

class TestCli : public QObject {
    Q_OBJECT
private:
    QTemporaryDir m_dir;
    QString path(const QString& name) const { return m_dir.filePath(name); }

private slots:
    void scenesListsEveryScene() {
        const Result r = cli({"scenes"});
        QCOMPARE(r.code, 0);
        const QStringList lines = r.out.trimmed().split('\n');
        QCOMPARE(lines.size(), int(simcore::sceneTable().size() + simcore::worldSceneTable().size()));
        for (const char* name : {"spring1d", "ring2d", "sphere3d", "sphere3d-latlong", "collide2d", "collide3d", "stack3d"}) {
            bool found = false;
            for (const QString& line : lines) found |= line.split(' ').first() == name;
            QVERIFY2(found, name);
        }
    }
    void paramsComesFromTheTable() {
        const Result all = cli({"params"});
        QCOMPARE(all.code, 0);
        for (const simcore::ParamSpec& spec : simcore::parameterTable())
            QVERIFY2(all.out.contains(QString::fromUtf8(spec.key.data(), int(spec.key.size())) + " "), spec.key.data());
        const Result spring = cli({"params", "--scene", "spring1d"});
        QCOMPARE(spring.code, 0);
        QVERIFY(spring.out.contains("\nks "));
        QVERIFY(spring.out.contains("N/m"));
        QVERIFY(!spring.out.contains("pressure"));
        QVERIFY(!spring.out.contains("rks"));
        QCOMPARE(cli({"params", "--scene", "torus"}).code, 2);
    }
    void csvHasTheContractColumns_data() {
        QTest::addColumn<QString>("scene");
        QTest::addColumn<bool>("gas");
        QTest::newRow("spring1d") << "spring1d" << false;
        QTest::newRow("ring2d") << "ring2d" << true;
        QTest::newRow("sphere3d") << "sphere3d" << true;
        QTest::newRow("sphere3d-latlong") << "sphere3d-latlong" << true;
    }
    void csvHasTheContractColumns() {
        QFETCH(QString, scene);
        QFETCH(bool, gas);
        const QString csv = path(scene + ".csv"), state = path(scene + "-state.csv");
        const Result r = cli({"run", "--scene", scene, "--duration", "0.3", "--dt", "0.003", "--every", "10",
                              "--csv", csv, "--state", state});
        QCOMPARE(r.code, 0);
        const auto rows = readCsv(csv);
        const QStringList header = rows.value(0);
        for (const char* column : {"t", "energy_kinetic", "energy_spring", "energy_gravity", "energy_total", "energy_removed"})
            QVERIFY2(header.contains(column), column);
        for (const char* column : {"volume_inner", "volume_outer", "pressure_inner", "pressure_outer", "energy_gas"})
            QCOMPARE(header.contains(column), gas);
        // 100 steps, a row every 10 plus the start: 11 rows after the header.
        QCOMPARE(rows.size(), 12);
        const auto t = header.indexOf("t");
        QCOMPARE(rows[1][t].toDouble(), 0.0);
        QVERIFY(std::abs(rows.last()[t].toDouble() - 0.3) < 1e-9);
        for (int i = 1; i < rows.size(); ++i) {
            QCOMPARE(rows[i].size(), header.size());
            for (const QString& cell : rows[i]) {
                bool ok = false;
                QVERIFY(std::isfinite(cell.toDouble(&ok)) && ok);
            }
        }
        const auto states = readCsv(state);
        QCOMPARE(states.value(0).join(','), QString("index,layer,x,y,z,vx,vy,vz"));
        QVERIFY(states.size() > 2);
        const QString expectedLayer = gas ? "inner" : "single";
        QCOMPARE(states[1][1], expectedLayer);
        if (gas) QCOMPARE(states.last()[1], QString("outer"));
    }
    void badInputExitsWithTwo_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("unknown scene") << QStringList{"run", "--scene", "cube"} << "cube";
        QTest::newRow("unknown key") << QStringList{"run", "--set", "stiff=1"} << "stiff";
        QTest::newRow("key absent in 1D") << QStringList{"run", "--scene", "spring1d", "--set", "pressure=1"} << "pressure";
        QTest::newRow("zero mass") << QStringList{"run", "--set", "mass=0"} << "mass";
        QTest::newRow("nan") << QStringList{"run", "--set", "ks=nan"} << "ks";
        QTest::newRow("restitution") << QStringList{"run", "--set", "restitution=1.5"} << "[0, 1]";
        QTest::newRow("negative dt") << QStringList{"run", "--dt", "-0.1"} << "dt";
        QTest::newRow("unknown integrator") << QStringList{"run", "--integrator", "leapfrog"} << "rk4";
        QTest::newRow("bad duration") << QStringList{"run", "--duration", "abc"} << "duration";
        QTest::newRow("bad every") << QStringList{"run", "--every", "0"} << "every";
        QTest::newRow("unknown option") << QStringList{"run", "--color"} << "--color";
        QTest::newRow("unwritable csv") << QStringList{"run", "--csv", "/nonexistent-dir/x.csv"} << "/nonexistent-dir/x.csv";
        QTest::newRow("unknown command") << QStringList{"fly"} << "fly";
        QTest::newRow("unknown kernels") << QStringList{"bench", "--kernels", "sse9"} << "sse9";
        QTest::newRow("crossed radii") << QStringList{"run", "--set", "radius_inner=3"} << "radius_inner";
        // Scenes of several bodies (issue 26): one line naming the body and the key.
        QTest::newRow("a body the scene has not") << QStringList{"run", "--scene", "collide3d", "--set", "body3.mass=2"}
                                                  << "body3.mass: the scene has 2 bodies";
        QTest::newRow("a world key for one body") << QStringList{"run", "--scene", "collide2d", "--set", "body2.gravity=0"}
                                                  << "body2.gravity";
        QTest::newRow("a key a body has not") << QStringList{"run", "--scene", "collide3d", "--set", "body1.particles=8"}
                                              << "body1";
        QTest::newRow("a body out of range") << QStringList{"run", "--scene", "collide3d", "--set", "body2.mass=-1"}
                                             << "body2: mass";
        QTest::newRow("bodies overlapping") << QStringList{"run", "--scene", "collide3d", "--set", "body2.position_x=-2"}
                                            << "bodies 1 and 2 overlap at the start";
        QTest::newRow("a body outside the box") << QStringList{"run", "--scene", "stack3d", "--set", "body3.position_y=6"}
                                                << "body3 sticks out of the box";
        QTest::newRow("a world for one-body commands") << QStringList{"conservation", "--scene", "collide2d"}
                                                       << "'collide2d' is a scene of several bodies";
        QTest::newRow("more bodies than allowed")
            << QStringList{"run", "--scene", QFINDTESTDATA("data/world-17-bodies.json")} << "at most 16";
        QTest::newRow("an unknown body kind")
            << QStringList{"run", "--scene", QFINDTESTDATA("data/world-unknown-kind.json")} << "body2.kind: unknown body kind 'torus'";
        QTest::newRow("beyond the memory limit")
            << QStringList{"run", "--scene", "sphere3d-latlong", "--set", "slices=1024", "--set", "stacks=512"}
            << "limit is 1 GiB";
    }
    void badInputExitsWithTwo() {
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        const Result r = cli(args);
        QCOMPARE(r.code, 2);
        QCOMPARE(r.err.trimmed().count('\n'), 0);  // one line
        QVERIFY2(r.err.contains(mentions), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }
    // bench: one row per run with the header's columns; the body's counts, the steps and the
    // kernels used are reported as they are; times are positive and consistent.
    void benchReportsTheRunItTimed_data() {
        QTest::addColumn<QString>("kernels");
        QTest::newRow("default") << "";
        QTest::newRow("portable") << "portable";
        QTest::newRow("avx512") << "avx512";
    }
    void benchReportsTheRunItTimed() {
        QFETCH(QString, kernels);
        QStringList args{"bench", "--scene", "sphere3d", "--set", "subdivisions=2", "--steps", "30",
                         "--threads", "2", "--integrator", "verlet", "--header"};
        if (!kernels.isEmpty()) args << "--kernels" << kernels;
        const Result r = cli(args);
        QCOMPARE(r.code, 0);
        const QStringList lines = r.out.trimmed().split('\n');
        QCOMPARE(lines.size(), 2);
        const QStringList header = lines[0].split(','), row = lines[1].split(',');
        QCOMPARE(header, (QStringList{"scene", "integrator", "precision", "threads", "particles", "springs", "faces",
                                      "steps", "us_per_step", "ns_per_spring_eval", "steps_per_second",
                                      "real_time_factor", "build_seconds", "peak_rss_mib", "state_hash", "kernels"}));
        QCOMPARE(row.size(), header.size());
        auto at = [&](const char* column) { return row[header.indexOf(column)]; };
        QCOMPARE(at("scene"), QString("sphere3d"));
        QCOMPARE(at("integrator"), QString("verlet"));
        QCOMPARE(at("precision"), QString("double"));
        QCOMPARE(at("state_hash").size(), 16);
        // Level 2: 2 x 66 particles, 834 springs, 2 x 128 triangles; one chunk below 8,192
        // springs, so a second thread is not started.
        QCOMPARE(at("particles"), QString("132"));
        QCOMPARE(at("springs"), QString("834"));
        QCOMPARE(at("faces"), QString("256"));
        QCOMPARE(at("steps"), QString("30"));
        const double us = at("us_per_step").toDouble(), rate = at("steps_per_second").toDouble();
        QVERIFY(us > 0.0 && at("ns_per_spring_eval").toDouble() > 0.0 && at("peak_rss_mib").toDouble() > 0.0);
        QVERIFY(std::abs(rate * us / 1e6 - 1.0) < 0.01);  // steps/s = 1e6 / us per step (rounded)
        QVERIFY(std::abs(at("real_time_factor").toDouble() / (rate * 0.003) - 1.0) < 0.01);  // DT 0.003
        const QStringList sets{"portable", "avx2", "avx512"};
        QVERIFY(sets.contains(at("kernels")));
        if (kernels == "portable") QCOMPARE(at("kernels"), QString("portable"));
        // Asking for more than the CPU has falls back; never wider than asked.
        if (!kernels.isEmpty()) QVERIFY(sets.indexOf(at("kernels")) <= sets.indexOf(kernels));
    }
    // bench's state_hash fingerprints the final state: the same for 1 and 2 threads (a body
    // of two chunks, level 4, so that the second thread does work), and different when the
    // trajectory changes (one step more, or another DT). The default thread counts are 1 and
    // all CPUs this process may use.
    void benchHashFollowsTheTrajectory() {
        auto rows = [&](QStringList extra) {
            QStringList args{"bench", "--scene", "sphere3d", "--set", "subdivisions=4", "--set", "perturb=0.01",
                             "--warmup", "2", "--header"};
            const Result r = cli(args + extra);
            if (r.code != 0) qWarning("%s", qPrintable(r.err));
            const QStringList lines = r.out.trimmed().split('\n');
            const QStringList header = lines[0].split(',');
            QList<QPair<QString, QString>> out;  // (threads, hash) per row
            for (qsizetype k = 1; k < lines.size(); ++k) {
                const QStringList row = lines[k].split(',');
                out.append({row[header.indexOf("threads")], row[header.indexOf("state_hash")]});
            }
            return out;
        };
        const auto both = rows({"--steps", "12", "--threads", "1,2"});
        QCOMPARE(both.size(), 2);
        QCOMPARE(both[0].first, QString("1"));
        QCOMPARE(both[1].first, QString("2"));
        QCOMPARE(both[0].second, both[1].second);
        QCOMPARE(rows({"--steps", "12", "--threads", "2"})[0].second, both[0].second);  // warm-up and steps only
        QVERIFY(rows({"--steps", "13", "--threads", "1"})[0].second != both[0].second);
        QVERIFY(rows({"--steps", "12", "--threads", "1", "--dt", "0.0029"})[0].second != both[0].second);
        const auto byDefault = rows({"--steps", "1"});
        QCOMPARE(byDefault.size(), simcore::availableThreads() > 1 ? 2 : 1);
        QCOMPARE(byDefault[0].first, QString("1"));
    }
    // run and bench --precision float (issue 27): the float path runs, says so, writes its
    // state, agrees with double to a float tolerance, and is refused for a method without a
    // float build (and by bench for --stages).
    void precisionFloat() {
        const QStringList scene{"--scene", "ring2d", "--set", "gravity=0", "--set", "perturb=0.01", "--duration", "0.3"};
        const Result f = cli(QStringList{"run", "--precision", "float", "--json"} + scene);
        QCOMPARE(f.code, 0);
        const Result d = cli(QStringList{"run", "--json"} + scene);
        QCOMPARE(d.code, 0);
        const QJsonObject fj = QJsonDocument::fromJson(f.out.toUtf8()).object(), dj = QJsonDocument::fromJson(d.out.toUtf8()).object();
        QCOMPARE(fj["precision"].toString(), QString("float"));
        QCOMPARE(dj["precision"].toString(), QString("double"));
        QCOMPARE(fj["steps"].toInt(), dj["steps"].toInt());
        const double ef = fj["energy"].toObject()["total"].toDouble(), ed = dj["energy"].toObject()["total"].toDouble();
        QVERIFY2(std::abs(ef - ed) < 1e-4 * std::abs(ed) && ef != ed, qPrintable(QString("%1 vs %2").arg(ef).arg(ed)));
        const QString state = path("float-state.csv");
        QCOMPARE(cli(QStringList{"run", "--precision", "float", "--quiet", "--state", state} + scene).code, 0);
        QVERIFY(readCsv(state).size() > 1);
        const Result refused = cli(QStringList{"run", "--precision", "float", "--integrator", "implicit-euler"} + scene);
        QCOMPARE(refused.code, 2);
        QVERIFY2(refused.err.contains("explicit integrators"), qPrintable(refused.err));
        QCOMPARE(cli({"bench", "--scene", "ring2d", "--precision", "float", "--stages", "--steps", "3"}).code, 2);
        const Result bench = cli({"bench", "--scene", "ring2d", "--set", "gravity=0", "--precision", "float", "--steps", "3",
                                  "--threads", "1", "--header"});
        QCOMPARE(bench.code, 0);
        const QStringList lines = bench.out.trimmed().split('\n');
        QCOMPARE(lines[1].split(',')[lines[0].split(',').indexOf("precision")], QString("float"));
    }
    // bench --stages: one column per stage of the step (simulation.h's order) after the
    // others; each stage's time lies inside its step, so they add up to no more than the step.
    void benchTimesTheStages() {
        const Result r = cli({"bench", "--scene", "ring2d", "--set", "contact=projection", "--steps", "300",
                              "--integrator", "rk4", "--header", "--stages", "--threads", "1"});
        QCOMPARE(r.code, 0);
        const QStringList lines = r.out.trimmed().split('\n');
        QCOMPARE(lines.size(), 2);
        const QStringList header = lines[0].split(','), row = lines[1].split(',');
        QCOMPARE(row.size(), header.size());
        const QStringList stages{"save", "size", "integrate", "scan", "collide", "measure", "constrain", "check", "commit"};
        const qsizetype first = header.indexOf("kernels") + 1;
        QCOMPARE(header.mid(first), [&] {
            QStringList columns;
            for (const QString& stage : stages) columns << "us_" + stage;
            return columns;
        }());
        double sum = 0.0;
        for (qsizetype k = first; k < row.size(); ++k) {
            bool ok = false;
            const double us = row[k].toDouble(&ok);
            QVERIFY2(ok && us >= 0.0, qPrintable(row[k]));
            sum += us;
        }
        const double step = row[header.indexOf("us_per_step")].toDouble();
        QVERIFY(row[header.indexOf("us_integrate")].toDouble() > 0.0);
        // us_per_step is printed to 0.01 us and each stage to 0.001 us.
        QVERIFY2(sum <= step + 0.005 + 0.0005 * static_cast<double>(stages.size()), qPrintable(QString("stages %1 us, step %2 us").arg(sum).arg(step)));
        // Without --stages: no stage columns.
        const Result plain = cli({"bench", "--scene", "ring2d", "--steps", "3", "--header"});
        QCOMPARE(plain.out.split('\n').first().split(',').last(), QString("kernels"));
    }
    // A scene of several bodies (issue 26): per-body columns with the body's number, the total
    // momentum and min_gap; z columns only in 3D; the state table's body column; params lists
    // the world's values and each body's.
    void worldCsvHasPerBodyColumns() {
        const QString csv = path("world.csv"), state = path("world-state.csv");
        const Result r = cli({"run", "--scene", "collide2d", "--set", "gravity=0", "--set", "body2.mass=4", "--duration",
                              "0.05", "--csv", csv, "--state", state});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY(r.out.contains("2 bodies"));
        const QStringList header = readLines(csv).value(0).split(',');
        for (const char* column : {"volume_outer_1", "volume_inner_2", "pressure_outer_2", "com_x_1", "com_y_2",
                                   "velocity_x_2", "momentum_x", "momentum_y", "angular_momentum_z", "min_gap",
                                   "energy_total", "energy_drift"})
            QVERIFY2(header.contains(column), column);
        QVERIFY(!header.contains("com_z_1"));  // 2D
        QVERIFY(!header.contains("momentum_z"));
        const QStringList rows = readLines(csv);
        QCOMPARE(rows.size(), 1 + 1 + 17);  // header, start, 17 steps of 0.003 s
        const QStringList last = rows.last().split(',');
        QCOMPARE(last.size(), header.size());
        // Body 2 is four times as heavy: its centre moves at -2 m/s, so momentum is 24*2 - 96*2.
        QVERIFY(std::abs(last[header.indexOf("momentum_x")].toDouble() - (24.0 * 2 - 96.0 * 2)) < 1e-9);
        QCOMPARE(readLines(state).value(0), QString("index,body,layer,x,y,z,vx,vy,vz"));
        QVERIFY(readLines(state).value(1).startsWith("0,1,inner,"));
        QVERIFY(readLines(state).last().contains(",2,outer,"));

        const Result three = cli({"run", "--scene", "collide3d", "--duration", "0.01", "--csv", path("w3.csv"), "--quiet"});
        QVERIFY2(three.code == 0, qPrintable(three.err));
        const QStringList header3 = readLines(path("w3.csv")).value(0).split(',');
        for (const char* column : {"com_z_1", "velocity_z_2", "momentum_z", "angular_momentum_x"})
            QVERIFY2(header3.contains(column), column);

        const Result params = cli({"params", "--scene", "collide3d", "--set", "body2.mass=4", "--set", "offset=1"});
        QVERIFY2(params.code == 0, qPrintable(params.err));
        QVERIFY(params.out.contains("body1: sphere3d"));
        QVERIFY(params.out.contains("body2: sphere3d"));
        QVERIFY(params.out.contains("(3, 0.5, 0) m"));  // body 2's start, offset across the line
    }
    // A scene file of several bodies: --save-scene writes the world with its exact state, and a
    // run from it continues the trajectory bit for bit (the state tables of 0.06 s straight and
    // of 0.03 s + 0.03 s from the file are the same text).
    void worldSceneFileResumesExactly() {
        const QStringList common = {"--set", "gravity=0", "--set", "body2.mass=4", "--set", "offset=0.5",
                                    "--integrator", "rk4", "--quiet"};
        QCOMPARE(cli(QStringList{"run", "--scene", "collide2d", "--duration", "0.06", "--state", path("straight.csv")} +
                     common).code, 0);
        const QString saved = path("half.json");
        QCOMPARE(cli(QStringList{"run", "--scene", "collide2d", "--duration", "0.03", "--save-scene", saved} + common)
                     .code, 0);
        QFile file(saved);
        QVERIFY(file.open(QIODevice::ReadOnly));
        const QByteArray text = file.readAll();
        QVERIFY(text.contains("\"version\": 4"));
        QVERIFY(text.contains("\"bodies\": ["));
        const Result resumed = cli({"run", "--scene", saved, "--duration", "0.03", "--state", path("resumed.csv"),
                                    "--quiet"});
        QVERIFY2(resumed.code == 0, qPrintable(resumed.err));
        QCOMPARE(readLines(path("resumed.csv")), readLines(path("straight.csv")));
        // A one-body command refuses it by what it is.
        const Result study = cli({"conservation", "--scene", saved});
        QCOMPARE(study.code, 2);
        QVERIFY2(study.err.contains("a scene of several bodies"), qPrintable(study.err));
    }
    // Bodies thrown too fast for a fixed step: the run ends with exit 3 naming both bodies.
    void worldIntersectionExitsWithThree() {
        const Result r = cli({"run", "--scene", "collide2d", "--set", "gravity=0", "--dt", "0.01", "--integrator", "euler",
                              "--set", "body1.velocity_x=60", "--set", "body2.velocity_x=-60", "--duration", "0.5",
                              "--quiet"});
        QCOMPARE(r.code, 3);
        QVERIFY2(r.err.contains("simulation failed at step"), qPrintable(r.err));
    }
    void failedRunExitsWithThreeAndKeepsGoodRows() {
        const QString csv = path("fail.csv"), state = path("fail-state.csv");
        const Result r = cli({"run", "--scene", "ring2d", "--integrator", "euler", "--dt", "0.3", "--set", "perturb=0.01",
                              "--duration", "100", "--csv", csv, "--state", state});
        QCOMPARE(r.code, 3);
        QVERIFY2(r.err.contains("failed at step"), qPrintable(r.err));
        QVERIFY(r.err.contains("t = "));
        QVERIFY(r.err.contains("warning: dt"));  // warned before the run
        const auto rows = readCsv(csv);
        QVERIFY(rows.size() >= 2);
        for (int i = 1; i < rows.size(); ++i)
            for (const QString& cell : rows[i]) {
                QVERIFY(!cell.contains("nan", Qt::CaseInsensitive));
                QVERIFY(!cell.contains("inf", Qt::CaseInsensitive));
            }
        QVERIFY(readCsv(state).size() > 1);
    }
    void failedWriteLeavesNoFileBehind() {
        // /dev/full accepts the open and fails the write: error 2, nothing renamed into place.
        // A device cannot be renamed over: it is written in place and the failure reported.
        const Result r = cli({"run", "--duration", "0.1", "--csv", "/dev/full"});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("/dev/full"), qPrintable(r.err));
        QVERIFY(QFileInfo("/dev/full").exists() && !QFileInfo("/dev/full").isFile());
        QVERIFY(QDir("/dev").entryList({"full.tmp-*"}, QDir::AllEntries | QDir::System).isEmpty());
    }
    void paramsSaysWhatTheBodyUses() {
        // scaling=physical at subdivisions=4: 1,026 particles per layer carry the 66 kg of the
        // default layer (66 / 1026 = 0.0643275 kg each); the membrane keeps 800 N/m.
        const Result r = cli({"params", "--scene", "sphere3d", "--set", "subdivisions=4"});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains("scaling=physical, subdivisions=4 (1026 particles per layer; reference 66)"), qPrintable(r.out));
        QVERIFY2(r.out.contains("per particle: inner 0.0643275 kg, outer 0.0643275 kg (layers 66 kg and 66 kg)"), qPrintable(r.out));
        QVERIFY2(r.out.contains("structural 800 N/m"), qPrintable(r.out));
        const Result t = cli({"params", "--scene", "sphere3d", "--set", "subdivisions=4", "--set", "scaling=thesis"});
        QVERIFY2(t.out.contains("per particle: inner 1 kg, outer 1 kg (layers 1026 kg and 1026 kg)"), qPrintable(t.out));
        QCOMPARE(cli({"params", "--set", "subdivisions=4"}).code, 2);  // --set needs a scene
    }
    void refinedRunIsWarnedWithAStableDt() {
        // A finer physical ring has faster modes: at 96 particles rk4's limit is ~0.7 ms, so
        // the default DT 0.003 is refused with the step the prediction offers, which runs.
        const Result r = cli({"run", "--scene", "ring2d", "--set", "particles=96", "--set", "gravity=0", "--duration", "0.05"});
        const qsizetype at = r.err.indexOf("(predicted stable: --dt ");
        QVERIFY2(at >= 0, qPrintable(r.err));
        const QString dt = r.err.mid(at + 24).section(')', 0, 0);
        QVERIFY2(dt.toDouble() > 0.0 && dt.toDouble() < 0.00072, qPrintable(dt));
        const Result ok = cli({"run", "--scene", "ring2d", "--set", "particles=96", "--set", "gravity=0", "--dt", dt,
                               "--duration", "0.5"});
        QCOMPARE(ok.code, 0);
        QVERIFY2(!ok.err.contains("warning"), qPrintable(ok.err));
    }
    void outputsNeverOverwriteInputsOrEachOther() {
        // Issue 18: compared by file identity, not spelling: the same name, "./" and "..", a
        // hard link and a symbolic link all count. Refused with exit 2 before anything is written.
        QDir(m_dir.path()).mkdir("sub");
        const QString scene = path("exp.json");
        QCOMPARE(cli({"run", "--scene", "ring2d", "--duration", "0.01", "--save-scene", scene}).code, 0);
        QFile f(scene);
        QVERIFY(f.open(QIODevice::ReadOnly));
        const QByteArray saved = f.readAll();
        f.close();
        QVERIFY(QFile::link(scene, path("link.csv")));
        QCOMPARE(::link(scene.toUtf8().constData(), path("hard.csv").toUtf8().constData()), 0);
        const QString fresh = path("fresh.csv"), freshOtherSpelling = m_dir.path() + "/sub/../fresh.csv";
        const QList<QStringList> clashes = {
            {"run", "--duration", "0.01", "--csv", fresh, "--state", fresh},
            {"run", "--duration", "0.01", "--csv", fresh, "--state", freshOtherSpelling},
            {"run", "--scene", scene, "--duration", "0.01", "--csv", scene},
            {"run", "--scene", scene, "--duration", "0.01", "--state", path("link.csv")},
            {"run", "--scene", scene, "--duration", "0.01", "--csv", path("hard.csv")},
            {"study", "--scene", "spring1d", "--integrators", "rk4", "--dts", "0.01", "--csv", fresh, "--plot", fresh},
            {"stability", "--scene", scene, "--integrators", "rk4", "--csv", scene},
        };
        for (const QStringList& args : clashes) {
            const Result r = cli(args);
            QCOMPARE(r.code, 2);
            QVERIFY2(r.err.contains("is the same file as --"), qPrintable(r.err));
            QVERIFY2(!QFileInfo::exists(fresh), qPrintable(args.join(' ')));
        }
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), saved);
        // Distinct files are fine.
        QCOMPARE(cli({"run", "--scene", scene, "--duration", "0.01", "--csv", fresh, "--state", path("state.csv")}).code, 0);
    }
    void runawayStepCountsAreRefused() {
        // --dt 1e-300 for 0.01 s would be 1e298 steps: refused at once, with the limit and the
        // way around it.
        const Result r = cli({"run", "--scene", "ring2d", "--dt", "1e-300", "--duration", "0.01"});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("steps; at most 1e9 per run"), qPrintable(r.err));
        QCOMPARE(cli({"run", "--scene", "ring2d", "--dt", "1e-5", "--duration", "0.001"}).code, 0);
        // The same limit, lowered, refuses a fixed-step run and stops an adaptive one (exit 3,
        // its files holding the run so far); a stability scan's smallest step is bounded too.
        const Result fixed = cli({"run", "--dt", "0.001", "--duration", "1", "--max-steps", "999"});
        QCOMPARE(fixed.code, 2);
        QVERIFY2(fixed.err.contains("at most 999 per run"), qPrintable(fixed.err));
        const QString csv = path("adaptive.csv");
        const Result adaptive = cli({"run", "--integrator", "rk45", "--duration", "1", "--max-steps", "50", "--csv", csv, "--quiet"});
        QCOMPARE(adaptive.code, 3);
        QVERIFY2(adaptive.err.contains("50 steps taken, the most one run may take"), qPrintable(adaptive.err));
        QCOMPARE(readCsv(csv).size(), 1 + 1 + 50);  // header, the start, 50 steps
        const Result scan = cli({"stability", "--integrators", "rk4", "--hmin", "1e-300"});
        QCOMPARE(scan.code, 2);
        QVERIFY2(scan.err.contains("would take 2e300 steps; at most 1e9 per run"), qPrintable(scan.err));
    }
    void nonsenseIsRefusedAndNothingIsSilent() {
        // Issue 18: lists without empty or repeated items, bounded study work, a checked
        // standard output, and a run that ends past --duration says so.
        const QList<QPair<QStringList, QString>> refused = {
            {{"stability", "--integrators", ""}, "needs a comma-separated list"},
            {{"stability", "--integrators", "rk4,,euler"}, "item 2 is empty"},
            {{"study", "--scene", "spring1d", "--integrators", "rk4,rk4", "--dts", "0.01"}, "'rk4' is listed twice"},
            {{"study", "--scene", "spring1d", "--integrators", "rk4", "--dts", "0.01,0.010"}, "listed twice"},
            {{"study", "--scene", "spring1d", "--integrators", "rk4", "--dts", "1e-300"}, "at most 1e9"},
        };
        for (const auto& [args, message] : refused) {
            const Result r = cli(args);
            QCOMPARE(r.code, 2);
            QVERIFY2(r.err.contains(message), qPrintable(args.join(' ') + ": " + r.err));
        }
        // --from-csv is an input like a scene file: a FIFO is not waited on, /dev/zero not read.
        const QString fifo = path("rows.fifo");
        QCOMPARE(::mkfifo(fifo.toUtf8().constData(), 0600), 0);
        for (const auto& [input, message] : {std::pair{fifo, QString("is not a regular file (a FIFO)")},
                                             {QString("/dev/zero"), QString("is not a regular file (a character device)")},
                                             {m_dir.path(), QString("is a directory")}}) {
            const Result r = cli({"study", "--from-csv", input});
            QCOMPARE(r.code, 2);
            QVERIFY2(r.err.contains(message), qPrintable(r.err));
        }
        QProcess full;
        full.setStandardOutputFile("/dev/full");
        full.start(ELASTIC_LAB_CLI, {"study", "--scene", "spring1d", "--integrators", "rk4", "--dts", "0.01", "--duration", "0.1"});
        QVERIFY(testsupport::waitForExit(full));
        QCOMPARE(full.exitCode(), 2);
        QVERIFY(full.readAllStandardError().contains("writing standard output failed"));
        const Result overshoot = cli({"run", "--integrator", "implicit-euler", "--dt", "0.5", "--duration", "0.1"});
        QCOMPARE(overshoot.code, 0);
        QVERIFY2(overshoot.err.contains("ended at t = 0.5 s"), qPrintable(overshoot.err));
        // --quiet silences notes too (issue 31).
        const Result quiet = cli({"run", "--integrator", "implicit-euler", "--dt", "0.5", "--duration", "0.1", "--quiet"});
        QCOMPARE(quiet.code, 0);
        QVERIFY2(quiet.err.isEmpty(), qPrintable(quiet.err));
    }
    void replacedFilesKeepTheirPermissions() {
        // A 600 file replaced by a run stays 600 (the temporary file used to give it 644).
        const QString csv = path("private.csv");
        {
            QFile f(csv);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("old\n");
        }
        QVERIFY(QFile::setPermissions(csv, QFile::ReadOwner | QFile::WriteOwner));
        QCOMPARE(cli({"run", "--duration", "0.01", "--csv", csv, "--quiet"}).code, 0);
        struct stat st {};
        QCOMPARE(::stat(csv.toUtf8().constData(), &st), 0);
        QCOMPARE(st.st_mode & 0777, mode_t(0600));
        QVERIFY(readCsv(csv).size() > 1);  // and it was replaced
    }
    void killedRunLeavesExistingFilesAndNothingElse_data() {
        // SIGKILL (no handler can run). SIGTERM and SIGINT ended the run by their default action
        // until issue 31; they now write the run so far and exit 130 / 143 (test_outputs).
        QTest::addColumn<int>("signal");
        QTest::newRow("SIGKILL") << int(SIGKILL);
    }
    void killedRunLeavesExistingFilesAndNothingElse() {
        // A run killed outright (SIGKILL: no handler, no destructor runs) while it streams its
        // CSV and state: the files that were there keep their bytes and nothing else appears
        // in the folder (the output is written to an unnamed O_TMPFILE file until the commit).
        QTemporaryDir dir;
        const QString csv = dir.filePath("series.csv"), state = dir.filePath("state.csv");
        for (const QString& name : {csv, state}) {
            QFile f(name);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("precious " + name.toUtf8() + "\n");
        }
        QFETCH(int, signal);
        QProcess p;
        // The child starts with the default dispositions a terminal gives (a non-interactive
        // shell's background job would inherit SIGINT ignored).
        p.setChildProcessModifier([] {
            ::signal(SIGINT, SIG_DFL);
            ::signal(SIGTERM, SIG_DFL);
        });
        p.start(ELASTIC_LAB_CLI, {"run", "--scene", "sphere3d", "--set", "subdivisions=4", "--set", "scaling=thesis", "--set", "gravity=0",
                                  "--duration", "100000", "--csv", csv, "--state", state});
        QVERIFY(p.waitForStarted(testsupport::kHangGuardMs));
        // Killed while it streams: once its unnamed CSV file in the folder holds rows.
        QVERIFY(testsupport::waitUntil([&] { return streamedBytes(p.processId(), dir.path()) > 4096; }));
        QCOMPARE(p.state(), QProcess::Running);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden).size(), 2);  // nothing named yet
        ::kill(static_cast<pid_t>(p.processId()), signal);
        QVERIFY(testsupport::waitForExit(p));
        QCOMPARE(p.exitStatus(), QProcess::CrashExit);  // ended by the signal, not by an exit
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden | QDir::System),
                 QStringList({"series.csv", "state.csv"}));
        for (const QString& name : {csv, state}) {
            QFile f(name);
            QVERIFY(f.open(QIODevice::ReadOnly));
            QCOMPARE(f.readAll(), "precious " + name.toUtf8() + "\n");
        }
    }
    // Issue 17: a conventional command line. --help (the tool's and each command's) goes to
    // standard output with exit 0 and names every option with its default; --version says the
    // CMake project's version; `help COMMAND` is `COMMAND --help`.
    void helpAndVersion() {
        const Result version = cli({"--version"});
        QCOMPARE(version.code, 0);
        QCOMPARE(version.out.trimmed(), QString("elastic-lab-cli " ELASTIC_LAB_VERSION));
        const Result top = cli({"--help"});
        QCOMPARE(top.code, 0);
        for (const char* command : {"scenes", "params", "integrators", "run", "study", "conservation", "stability",
                                    "restitution", "gallery", "bench", "completion"})
            QVERIFY2(top.out.contains(QString("\n  %1 ").arg(command)), command);
        const Result run = cli({"run", "--help"});
        QCOMPARE(run.code, 0);
        QVERIFY(run.err.isEmpty());
        // Every option with its unit and default where it has one.
        for (const char* option : {"--scene S|FILE.json=ring2d", "--set KEY=VALUE", "--dt H", "--integrator NAME",
                                   "--duration T:in (0, 1e+07]=5", "--csv FILE", "--every N", "--state FILE",
                                   "--save-scene FILE.json", "--quiet", "--atol A", "--rtol R", "--newton N",
                                   "--fixed-step", "--error-estimate", "[s]"})
            QVERIFY2(run.out.contains(option), option);
        QCOMPARE(cli({"help", "run"}).out, run.out);
        const Result study = cli({"study", "--help"});
        for (const char* option : {"--integrators", "--dts", "--tols", "--refine", "--from-csv", "--shard K/N", "--samples G",
                                   "--reference NAME", "--temporal-runs", "--interval"})
            QVERIFY2(study.out.contains(option), option);
    }
    // Mistakes the parser catches: a value given twice, options that contradict each other.
    void contradictionsAreRefused_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("mentions");
        QTest::newRow("twice") << QStringList{"run", "--dt", "0.01", "--dt", "0.02"} << "--dt";
        QTest::newRow("merge runs nothing") << QStringList{"study", "--from-csv", "x.csv", "--dts", "0.1"} << "--from-csv excludes --dts";
        QTest::newRow("dt belongs to --refine") << QStringList{"study", "--dt", "0.1"} << "--dt requires --refine";
        QTest::newRow("refine has no --dts") << QStringList{"study", "--refine", "particles=12,24", "--dts", "0.1"} << "--refine excludes --dts";
        QTest::newRow("set needs scene") << QStringList{"params", "--set", "ks=1"} << "--set requires --scene";
        QTest::newRow("crossed scan bounds") << QStringList{"stability", "--hmin", "0.1", "--hmax", "0.01"} << "is below hmin";
        QTest::newRow("unknown option before a command") << QStringList{"--bogus"} << "unknown option '--bogus'";
        QTest::newRow("stray word") << QStringList{"run", "x"} << "run takes --help, --scene";
        QTest::newRow("unknown gallery case") << QStringList{"gallery", "--run", "nope"} << "nope";
        QTest::newRow("runaway speed") << QStringList{"restitution", "--speeds", "1,1e9"} << "(0, 10000]";
    }
    void contradictionsAreRefused() {
        QFETCH(QStringList, args);
        QFETCH(QString, mentions);
        const Result r = cli(args);
        QCOMPARE(r.code, 2);
        QCOMPARE(r.err.trimmed().count('\n'), 0);
        QVERIFY2(r.err.contains(mentions), qPrintable(r.err));
        QVERIFY(r.out.isEmpty());
    }
    // The bash completion, written by the tool from its own commands, completes in bash.
    void bashCompletionCompletes() {
        const Result script = cli({"completion"});
        QCOMPARE(script.code, 0);
        const QString file = path("completion.bash");
        {
            QFile f(file);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write(script.out.toUtf8());
        }
        auto complete = [&](const QStringList& words) {
            QProcess bash;
            const QString quoted = "(" + words.join(' ') + ")";
            bash.start("bash", {"-c", QString("source '%1'; COMP_WORDS=%2; COMP_CWORD=%3; _elastic_lab_cli; "
                                              "printf '%s\\n' \"${COMPREPLY[@]}\"")
                                      .arg(file, quoted)
                                      .arg(words.size() - 1)});
            if (!testsupport::waitForExit(bash)) return QStringList{"(hung)"};
            return QString::fromUtf8(bash.readAllStandardOutput()).split('\n', Qt::SkipEmptyParts);
        };
        QCOMPARE(complete({"elastic-lab-cli", "st"}), QStringList({"study", "stability"}));
        QCOMPARE(complete({"elastic-lab-cli", "run", "--du"}), QStringList({"--duration"}));
        QCOMPARE(complete({"elastic-lab-cli", "run", "--integrator", "rk"}), QStringList({"rk4", "rk45"}));
        QCOMPARE(complete({"elastic-lab-cli", "bench", "--kernels", "a"}), QStringList({"avx2", "avx512"}));
        QVERIFY(complete({"elastic-lab-cli", "study", "--"}).contains("--temporal-runs"));
        QCOMPARE(complete({"elastic-lab-cli", "run", "--scene", "sphere3d-"}), QStringList({"sphere3d-latlong"}));
    }
    void interruptedStudyLeavesExistingFilesAndNothingElse() {
        // The same outcome for a study (issue 18): SIGTERM while it computes its reference
        // leaves the CSV that was there byte for byte and adds nothing to the folder.
        QTemporaryDir dir;
        const QString csv = dir.filePath("study.csv");
        {
            QFile f(csv);
            QVERIFY(f.open(QIODevice::WriteOnly));
            f.write("precious\n");
        }
        QProcess p;
        p.setChildProcessModifier([] { ::signal(SIGTERM, SIG_DFL); });
        p.start(ELASTIC_LAB_CLI, {"study", "--scene", "ring2d", "--integrators", "rk4", "--dts", "0.001", "--duration", "50000",
                                  "--csv", csv, "--plot", dir.filePath("study.svg")});
        QVERIFY(p.waitForStarted(testsupport::kHangGuardMs));
        // Interrupted once it holds its unnamed output open in the folder (it opens it first).
        QVERIFY(testsupport::waitUntil([&] { return holdsFileIn(p.processId(), dir.path()); }));
        ::kill(static_cast<pid_t>(p.processId()), SIGTERM);
        QVERIFY(testsupport::waitForExit(p));
        QCOMPARE(p.exitStatus(), QProcess::CrashExit);
        QCOMPARE(QDir(dir.path()).entryList(QDir::Files | QDir::Hidden | QDir::System), QStringList({"study.csv"}));
        QFile f(csv);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("precious\n"));
    }
    void memoryLimitCountsTheIntegrator() {
        // A body within the 1 GiB bound for the textbook methods is refused for CVODE, whose ~40
        // extra state vectors do not fit (issue 13): refused before the body is built.
        const QStringList shape{"--scene", "sphere3d-latlong", "--set", "slices=700", "--set", "stacks=350"};
        QCOMPARE(cli(QStringList{"params"} + shape).code, 0);
        const Result r = cli(QStringList{"run"} + shape + QStringList{"--integrator", "cvode-bdf", "--quiet"});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("limit is 1 GiB") && r.err.contains("with cvode-bdf"), qPrintable(r.err));
    }
    void existingFileSurvivesAFailedRunStart() {
        const QString csv = path("keep.csv");
        QFile f(csv);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("precious\n");
        f.close();
        QCOMPARE(cli({"run", "--set", "ks=-1", "--csv", csv}).code, 2);
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("precious\n"));
    }
};

QTEST_GUILESS_MAIN(TestCli)
#include "test_cli.moc"
