// `elastic-lab-cli sweep` (issue 29): a sweep killed half-way (kill -9) and started again with
// --resume ends with the CSV of an uninterrupted run; shards concatenate into the whole; `--csv -`
// streams the same rows; bad requests are refused before anything runs.
//
// The kill comes at a point the test chooses, not by racing the clock: the CLI's test hook
// ELASTIC_LAB_TEST_SWEEP_STOP_AFTER=K makes it stop itself (SIGSTOP) after K new rows, and the
// test then kills it with SIGKILL.
#include <signal.h>

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include "cli_process.h"

namespace {

const QStringList kSweep = {"sweep", "--scene", "ring2d", "--set", "particles=8", "--grid", "pressure=10,20,40",
                            "--grid", "ks=400,800,1600,3200", "--duration", "0.3", "--quiet"};
constexpr int kPoints = 12;

QString readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? QString::fromUtf8(f.readAll()) : QString();
}

// The CSV without its wall_seconds column (the one value that depends on the machine).
QStringList withoutWallTime(const QString& csv) {
    QStringList lines = csv.split('\n', Qt::SkipEmptyParts);
    const auto column = lines.value(0).split(',').indexOf("wall_seconds");
    if (column < 0) return lines;
    for (QString& line : lines) {
        QStringList fields = line.split(',');  // no quoted commas in these rows (every point is ok)
        fields.removeAt(column);
        line = fields.join(',');
    }
    return lines;
}

int dataLines(const QString& path) { return static_cast<int>(readAll(path).count(QChar(10))) - 2; }

// Starts the sweep writing to `out`, lets it journal `rows` new rows (it then stops itself) and
// kills it with SIGKILL. False when it did not get there or did not die of the kill.
bool killAfter(const QStringList& args, const QString& out, int rows) {
    QProcess p;
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("ELASTIC_LAB_TEST_SWEEP_STOP_AFTER", QString::number(rows));
    p.setProcessEnvironment(env);
    p.start(ELASTIC_LAB_CLI, args + QStringList{"--csv", out});
    const bool reached = testsupport::waitUntil([&] { return dataLines(out + ".partial") >= rows; });
    p.kill();
    return testsupport::waitForExit(p) && reached && p.exitStatus() == QProcess::CrashExit;
}

// True once process `pid` is stopped (state T in /proc/PID/stat).
bool isStopped(qint64 pid) {
    const QString stat = readAll(QString("/proc/%1/stat").arg(pid));
    const auto close = stat.lastIndexOf(')');
    return close > 0 && stat.mid(close + 2, 1) == "T";
}

// Starts the sweep writing to `out` (standard output for "-"), lets it finish `rows` new rows
// (it then stops itself), sends `signal` and lets it go on: the handler has run before the
// next point starts, so the sweep stops with exactly `rows` whole rows. `inPoint`: the signal
// comes after the next point has started (it then stops with `rows` or `rows` + 1 rows: where
// the signal lands in the point is up to the machine). The finished process is in `p`.
bool interruptAfter(QProcess& p, const QStringList& args, const QString& out, int rows, int signal, bool inPoint) {
    QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
    env.insert("ELASTIC_LAB_TEST_SWEEP_STOP_AFTER", QString::number(rows));
    p.setProcessEnvironment(env);
    p.start(ELASTIC_LAB_CLI, args + QStringList{"--csv", out});
    if (!p.waitForStarted()) return false;
    const qint64 pid = p.processId();
    if (!testsupport::waitUntil([&] { return isStopped(pid); })) return false;
    if (inPoint) {
        ::kill(static_cast<pid_t>(pid), SIGCONT);
        ::kill(static_cast<pid_t>(pid), signal);
    } else {
        ::kill(static_cast<pid_t>(pid), signal);
        ::kill(static_cast<pid_t>(pid), SIGCONT);
    }
    return testsupport::waitForExit(p) && p.exitStatus() == QProcess::NormalExit;
}

}  // namespace

class TestSweepCli : public QObject {
    Q_OBJECT
    QTemporaryDir m_dir;
    QString m_full;

    QString path(const QString& name) const { return m_dir.filePath(name); }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        m_full = path("full.csv");
        const CliResult r = runCli(kSweep + QStringList{"--csv", m_full});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.err.isEmpty(), qPrintable(r.err));  // --quiet: no progress line
        QCOMPARE(withoutWallTime(readAll(m_full)).size(), kPoints + 1);
        QVERIFY(!QFile::exists(m_full + ".partial"));  // the journal is gone once the CSV is whole
        // Rows in grid order, every point ok.
        const QStringList lines = withoutWallTime(readAll(m_full));
        for (int i = 1; i <= kPoints; ++i) {
            QVERIFY2(lines[i].startsWith(QString::number(i - 1) + ","), qPrintable(lines[i]));
            QVERIFY2(lines[i].contains(",rk4,ok,,"), qPrintable(lines[i]));
        }
    }

    void killedAndResumedEndsWithTheSameCsv_data() {
        QTest::addColumn<int>("stopAfter");
        QTest::addColumn<bool>("tornLine");
        QTest::newRow("after 1 row") << 1 << false;
        QTest::newRow("half-way") << kPoints / 2 << false;
        QTest::newRow("half-way, killed inside a row") << kPoints / 2 << true;
    }
    void killedAndResumedEndsWithTheSameCsv() {
        QFETCH(int, stopAfter);
        QFETCH(bool, tornLine);
        const QString out = path(QString("resumed-%1-%2.csv").arg(stopAfter).arg(tornLine));
        const QString journal = out + ".partial";
        QVERIFY(killAfter(kSweep, out, stopAfter));
        QVERIFY(!QFile::exists(out));  // nothing final before every point is done
        QCOMPARE(dataLines(journal), stopAfter);
        if (tornLine) {  // a row cut short by the kill: dropped and run again
            QFile f(journal);
            QVERIFY(f.open(QIODevice::Append));
            f.write("7,20,160");
        }

        const CliResult resumed = runCli(kSweep + QStringList{"--csv", out, "--resume"});
        QCOMPARE(resumed.code, 0);
        QCOMPARE(withoutWallTime(readAll(out)), withoutWallTime(readAll(m_full)));
        QVERIFY(!QFile::exists(journal));
    }

    // Ctrl+C and SIGTERM (issue 31): after every number of finished points, the sweep stops
    // with the journal holding exactly those rows (whole), an existing OUT byte-identical,
    // nothing else in the folder, exit 130 / 143 and a message naming --resume; --resume then
    // ends with the same CSV as an uninterrupted sweep.
    void interruptedSweepKeepsWholeRowsAndResumes_data() {
        QTest::addColumn<int>("rows");
        QTest::addColumn<int>("signal");
        QTest::addColumn<bool>("inPoint");
        for (int rows = 1; rows < kPoints; ++rows)
            QTest::addRow("SIGINT after %d", rows) << rows << int(SIGINT) << false;
        for (int rows : {1, 6, 11}) QTest::addRow("SIGTERM after %d", rows) << rows << int(SIGTERM) << false;
        for (int rows : {1, 4, 7, 10}) QTest::addRow("SIGINT inside point %d", rows + 1) << rows << int(SIGINT) << true;
    }
    void interruptedSweepKeepsWholeRowsAndResumes() {
        QFETCH(int, rows);
        QFETCH(int, signal);
        QFETCH(bool, inPoint);
        QTemporaryDir dir;
        QVERIFY(dir.isValid());
        const QString out = dir.filePath("sweep.csv"), journal = out + ".partial";
        {
            QFile old(out);
            QVERIFY(old.open(QIODevice::WriteOnly));
            old.write("the last sweep's table\n");
        }
        QProcess p;
        QVERIFY(interruptAfter(p, kSweep, out, rows, signal, inPoint));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitCode(), 128 + signal);
        const int kept = dataLines(journal);
        QVERIFY2(kept == rows || (inPoint && kept == rows + 1), qPrintable(QString::number(kept)));
        QVERIFY2(err.contains(QString("sweep stopped by %1 after %2 of %3 points")
                                  .arg(signal == SIGINT ? "SIGINT" : "SIGTERM").arg(kept).arg(kPoints)),
                 qPrintable(err));
        QVERIFY2(err.contains("--resume"), qPrintable(err));
        QCOMPARE(readAll(out), QString("the last sweep's table\n"));  // OUT untouched
        QCOMPARE(QDir(dir.path()).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot),
                 QStringList({"sweep.csv", "sweep.csv.partial"}));
        // Every journalled row whole and equal to the uninterrupted sweep's.
        const QStringList full = withoutWallTime(readAll(m_full));
        const QStringList lines = withoutWallTime(readAll(journal).section('\n', 1));  // after the fingerprint
        QCOMPARE(lines, full.mid(0, kept + 1));

        const CliResult resumed = runCli(kSweep + QStringList{"--csv", out, "--resume"});
        QCOMPARE(resumed.code, 0);
        QCOMPARE(withoutWallTime(readAll(out)), full);
        QVERIFY(!QFile::exists(journal));
    }

    // The same with --csv -: the rows streamed before the signal are whole, none after it.
    void interruptedStreamKeepsWholeRows() {
        for (int rows : {1, 5, 11}) {
            QProcess p;
            QVERIFY(interruptAfter(p, kSweep, "-", rows, SIGINT, false));
            QCOMPARE(p.exitCode(), 130);
            const QStringList lines = withoutWallTime(QString::fromUtf8(p.readAllStandardOutput()));
            QCOMPARE(lines, withoutWallTime(readAll(m_full)).mid(0, rows + 1));
            const QString err = QString::fromUtf8(p.readAllStandardError());
            QVERIFY2(err.contains(QString("sweep stopped by SIGINT after %1 of 12 points; the rows above are whole").arg(rows)),
                     qPrintable(err));
        }
    }

    void resumeComputesOnlyWhatIsMissing() {
        const QString out = path("only-missing.csv");
        QVERIFY(killAfter(kSweep, out, 5));
        const QStringList before = readAll(out + ".partial").split('\n', Qt::SkipEmptyParts);
        QStringList args = kSweep;
        args.removeAll("--quiet");
        const CliResult resumed = runCli(args + QStringList{"--csv", out, "--resume"});
        QCOMPARE(resumed.code, 0);
        QVERIFY2(resumed.err.contains("resuming, 5 of 12 points already done"), qPrintable(resumed.err));
        QVERIFY2(resumed.err.contains("sweep: 7/7 points"), qPrintable(resumed.err));
        // The five journaled rows (wall times included) are in the final CSV unchanged.
        const QString final = readAll(out);
        for (int i = 2; i < before.size(); ++i) QVERIFY2(final.contains(before[i] + "\n"), qPrintable(before[i]));
    }

    void resumeRefusesAnotherSweepsJournal() {
        const QString out = path("other.csv");
        QVERIFY(killAfter(kSweep, out, 2));
        QStringList other = kSweep;
        other[other.indexOf("0.3")] = "0.4";  // another duration: other rows
        const CliResult r = runCli(other + QStringList{"--csv", out, "--resume"});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("was written by another sweep"), qPrintable(r.err));
        QCOMPARE(dataLines(out + ".partial"), 2);  // left as it was
        QVERIFY(!QFile::exists(out));
    }

    void shardsConcatenateIntoTheWholeSweep() {
        QStringList rows;
        for (const char* shard : {"1/3", "2/3", "3/3"}) {
            const QString out = path(QString("shard-%1.csv").arg(shard[0]));
            const CliResult r = runCli(kSweep + QStringList{"--csv", out, "--shard", shard});
            QCOMPARE(r.code, 0);
            QStringList lines = withoutWallTime(readAll(out));
            if (!rows.isEmpty()) lines.removeFirst();  // the header once
            rows += lines;
        }
        QCOMPARE(rows, withoutWallTime(readAll(m_full)));
    }

    void csvDashStreamsTheRowsToStandardOutput() {
        const CliResult r = runCli(kSweep + QStringList{"--csv", "-"});
        QCOMPARE(r.code, 0);
        QCOMPARE(withoutWallTime(r.out), withoutWallTime(readAll(m_full)));
    }

    void badRequestsAreRefusedBeforeAnythingRuns_data() {
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QString>("message");
        const QStringList base = {"sweep", "--scene", "ring2d", "--duration", "0.1"};
        QTest::newRow("unknown key") << base + QStringList{"--grid", "stiffness=1,2", "--csv", "x.csv"} << "unknown parameter 'stiffness'";
        QTest::newRow("out of range") << base + QStringList{"--grid", "ks=-5", "--csv", "x.csv"} << "ks = -5 is out of range";
        QTest::newRow("twice") << base + QStringList{"--grid", "ks=1,2", "--grid", "ks=3", "--csv", "x.csv"} << "'ks' is given twice";
        QTest::newRow("listed twice") << base + QStringList{"--grid", "ks=1,1", "--csv", "x.csv"} << "ks: '1' is listed twice";
        QTest::newRow("bad range") << base + QStringList{"--grid", "ks=log:0:10:3", "--csv", "x.csv"} << "needs both ends > 0";
        QTest::newRow("unknown metric") << base + QStringList{"--metrics", "bounce", "--csv", "x.csv"} << "metrics: unknown 'bounce'";
        QTest::newRow("1D has no volumes") << QStringList{"sweep", "--scene", "spring1d", "--metrics", "volume_inner_final", "--csv", "x.csv"}
                                           << "metrics: unknown 'volume_inner_final' for spring1d";
        QTest::newRow("no csv") << base << "--csv is required";
        QTest::newRow("resume to stdout") << base + QStringList{"--csv", "-", "--resume"} << "--resume needs a file";
    }
    void badRequestsAreRefusedBeforeAnythingRuns() {
        QFETCH(QStringList, args);
        QFETCH(QString, message);
        QProcess p;
        p.setWorkingDirectory(m_dir.path());
        p.start(ELASTIC_LAB_CLI, args);
        QVERIFY(testsupport::waitForExit(p));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitCode(), 2);
        QVERIFY2(err.contains(message), qPrintable(err));
        QVERIFY(!QFile::exists(m_dir.filePath("x.csv")));
        QVERIFY(!QFile::exists(m_dir.filePath("x.csv.partial")));
    }

    void rangesAndOverBudgetRows() {
        const CliResult r = runCli({"sweep", "--scene", "ring2d", "--grid", "dt=decades:0.0001:0.001:1", "--duration", "0.05",
                                    "--max-steps", "100", "--metrics", "steps", "--csv", "-", "--quiet"});
        QCOMPARE(r.code, 0);
        const QStringList lines = r.out.split('\n', Qt::SkipEmptyParts);
        QCOMPARE(lines.size(), 3);
        QVERIFY2(lines[1].startsWith("0,1e-04,rk4,over budget,would take 500 steps"), qPrintable(lines[1]));
        QVERIFY2(lines[2].startsWith("1,0.001,rk4,ok,,50,"), qPrintable(lines[2]));
    }
};

QTEST_GUILESS_MAIN(TestSweepCli)
#include "test_sweep_cli.moc"
