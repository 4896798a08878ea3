// Issue 31, "nothing lost": a command's outputs all or none, standard streams written in place,
// temporary names that fit any target and never collide, setuid bits kept, Ctrl+C and SIGTERM
// writing the run so far (exit 130 / 143), the progress line on a terminal and --quiet, the
// scene reader's depth, memory and 64-bit bounds, out of memory inside the exit contract, and
// non-finite values written as such.
#include <QtTest>

#include <pty.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <QProcess>
#include <QTemporaryDir>
#include <QXmlStreamReader>

#include <cmath>
#include <csignal>
#include <limits>
#include <string>

#include "cli_process.h"
#include "simlab/output.h"
#include "simlab/scenefile.h"
#include "simlab/study.h"

namespace {

QByteArray readAll(const QString& path) {
    QFile f(path);
    return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray("<missing>");
}

void writeFile(const QString& path, const QByteArray& bytes) {
    QFile f(path);
    QVERIFY(f.open(QIODevice::WriteOnly));
    f.write(bytes);
}

QStringList entries(const QString& folder) {
    return QDir(folder).entryList(QDir::AllEntries | QDir::Hidden | QDir::System | QDir::NoDotAndDotDot);
}

// Bytes in the files process pid holds open under folder (an unnamed O_TMPFILE output shows
// there as "folder/#inode (deleted)").
qint64 streamedBytes(qint64 pid, const QString& folder) {
    qint64 bytes = 0;
    const QString fds = QString("/proc/%1/fd").arg(pid);
    for (const QFileInfo& fd : QDir(fds).entryInfoList(QDir::Files | QDir::System | QDir::NoDotAndDotDot))
        if (QFile::symLinkTarget(fd.filePath()).startsWith(folder + "/")) bytes += fd.size();
    return bytes;
}

// Runs the CLI with standard output and error on a pseudo-terminal (as a person at a terminal
// sees it); returns what the terminal received and the exit status.
std::pair<QByteArray, int> runOnTerminal(const QStringList& args) {
    std::vector<std::string> strings{ELASTIC_LAB_CLI};
    for (const QString& a : args) strings.push_back(a.toStdString());
    std::vector<char*> argv;
    for (std::string& s : strings) argv.push_back(s.data());
    argv.push_back(nullptr);
    int master = -1;
    const pid_t pid = ::forkpty(&master, nullptr, nullptr, nullptr);
    if (pid == 0) {
        ::execv(argv[0], argv.data());
        ::_exit(127);
    }
    QByteArray seen;
    char buffer[4096];
    for (;;) {  // until the terminal closes (EIO once the child has exited)
        const ssize_t n = ::read(master, buffer, sizeof buffer);
        if (n <= 0) break;
        seen.append(buffer, static_cast<int>(n));
    }
    int status = 0;
    ::waitpid(pid, &status, 0);
    ::close(master);
    return {seen, WIFEXITED(status) ? WEXITSTATUS(status) : -1};
}

}  // namespace

class TestOutputs : public QObject {
    Q_OBJECT
private slots:
    void severalOutputsCommitAllOrNone() {
        // The CSV is complete before the state fails on /dev/full: the old CSV must keep its
        // bytes (it used to be replaced, outputs being committed one by one), and a new one
        // must not appear.
        QTemporaryDir dir;
        const QString old = dir.filePath("old.csv"), fresh = dir.filePath("new.csv");
        writeFile(old, "precious\n");
        CliResult r = runCli({"run", "--scene", "spring1d", "--duration", "0.1", "--csv", old, "--state", "/dev/full"});
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.contains("/dev/full"), qPrintable(r.err));
        QCOMPARE(readAll(old), QByteArray("precious\n"));
        r = runCli({"run", "--scene", "spring1d", "--duration", "0.1", "--csv", fresh, "--state", "/dev/full"});
        QCOMPARE(r.code, 2);
        QCOMPARE(entries(dir.path()), QStringList{"old.csv"});
        // The library's own commit: one good file and one that failed.
        {
            simlab::AtomicFile good(old.toStdString()), bad("/dev/full");
            QVERIFY(good.write("new\n"));
            bad.write(std::string(70000, 'x'));  // fails here or at the commit
            QVERIFY(simlab::commitAll({&good, &bad}).has_value());
        }
        QCOMPARE(readAll(old), QByteArray("precious\n"));
        QCOMPARE(entries(dir.path()), QStringList{"old.csv"});
    }

    void standardOutputAppendedToIsNotReplaced() {
        // `--csv /dev/stdout >> log.txt`: /dev/stdout leads to log.txt; the writer must write
        // through the descriptor it was given (appending), not rename a new file over log.txt.
        QTemporaryDir dir;
        const QString log = dir.filePath("log.txt");
        writeFile(log, "first line\n");
        struct stat before {};
        QCOMPARE(::stat(log.toUtf8().constData(), &before), 0);
        QProcess p;
        p.setStandardOutputFile(log, QIODevice::Append);
        p.start(ELASTIC_LAB_CLI, {"run", "--scene", "spring1d", "--duration", "0.05", "--csv", "/dev/stdout", "--quiet"});
        QVERIFY(testsupport::waitForExit(p));
        QCOMPARE(p.exitCode(), 0);
        const QByteArray text = readAll(log);
        QVERIFY2(text.startsWith("first line\nstep,t,"), text.left(80).constData());
        struct stat after {};
        QCOMPARE(::stat(log.toUtf8().constData(), &after), 0);
        QCOMPARE(after.st_ino, before.st_ino);  // the same file, written in place
        QCOMPARE(entries(dir.path()), QStringList{"log.txt"});
    }

    void aLongLegalNameIsWritten() {
        // A 250-byte name is legal (NAME_MAX 255); a temporary name made by appending to it
        // (".tmp-PID") was not, and the run failed only at the end.
        QTemporaryDir dir;
        const QString name = dir.filePath(QString(246, 'a') + ".csv");
        const CliResult r = runCli({"run", "--scene", "spring1d", "--duration", "0.05", "--csv", name, "--quiet"});
        QCOMPARE(r.code, 0);
        QVERIFY(readAll(name).startsWith("step,t,"));
        QCOMPARE(entries(dir.path()).size(), 1);
    }

    void replacedFilesKeepSetuidBits() {
        // Owner first, then mode: a change of owner clears setuid/setgid, so the mode set
        // before it lost them.
        QTemporaryDir dir;
        const QString csv = dir.filePath("suid.csv");
        writeFile(csv, "old\n");
        QCOMPARE(::chmod(csv.toUtf8().constData(), 06750), 0);
        QCOMPARE(runCli({"run", "--scene", "spring1d", "--duration", "0.05", "--csv", csv, "--quiet"}).code, 0);
        struct stat st {};
        QCOMPARE(::stat(csv.toUtf8().constData(), &st), 0);
        QCOMPARE(st.st_mode & 07777, mode_t(06750));
        QVERIFY(readAll(csv).startsWith("step,t,"));
    }

    void interruptedRunWritesTheRunSoFar_data() {
        QTest::addColumn<int>("signal");
        QTest::addColumn<int>("code");
        QTest::newRow("SIGINT") << int(SIGINT) << 130;
        QTest::newRow("SIGTERM") << int(SIGTERM) << 143;
    }
    void interruptedRunWritesTheRunSoFar() {
        // Ctrl+C or SIGTERM (a Slurm limit, a container stop): the run stops after a whole
        // step, the CSV up to there and the final state are written, exit 128 + signal.
        QFETCH(int, signal);
        QFETCH(int, code);
        QTemporaryDir dir;
        const QString csv = dir.filePath("series.csv"), state = dir.filePath("state.csv");
        writeFile(csv, "precious\n");
        QProcess p;
        p.setChildProcessModifier([] {  // the dispositions a terminal gives
            ::signal(SIGINT, SIG_DFL);
            ::signal(SIGTERM, SIG_DFL);
        });
        p.start(ELASTIC_LAB_CLI, {"run", "--scene", "ring2d", "--duration", "100000", "--every", "10", "--csv", csv,
                                  "--state", state});
        QVERIFY(p.waitForStarted(testsupport::kHangGuardMs));
        QVERIFY(testsupport::waitUntil([&] { return streamedBytes(p.processId(), dir.path()) > 4096; }));
        ::kill(static_cast<pid_t>(p.processId()), signal);
        QVERIFY(testsupport::waitForExit(p));
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QCOMPARE(p.exitCode(), code);
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QVERIFY2(err.contains(signal == SIGINT ? "stopped by SIGINT at step" : "stopped by SIGTERM at step"), qPrintable(err));
        const QList<QByteArray> rows = readAll(csv).trimmed().split('\n');
        QVERIFY(rows.size() > 10);
        QVERIFY(rows.front().startsWith("step,t,"));
        // The state table whole: as many rows as a run that was not interrupted writes.
        const QString full = dir.filePath("full-state.csv");
        QCOMPARE(runCli({"run", "--scene", "ring2d", "--duration", "0.01", "--state", full, "--quiet"}).code, 0);
        QCOMPARE(readAll(state).count('\n'), readAll(full).count('\n'));
        QFile::remove(full);
        QCOMPARE(entries(dir.path()), QStringList({"series.csv", "state.csv"}));
    }

    void progressLineOnATerminalAndQuiet() {
        // On a terminal: a line rewritten in place ("\r"), cleared at the end. --quiet: none,
        // and no notes. Not on a terminal (a pipe, a file): none.
        const QStringList args = {"run", "--scene", "spring1d", "--duration", "0.2505", "--dt", "0.001"};
        const auto [shown, code] = runOnTerminal(args);
        QCOMPARE(code, 0);
        QVERIFY2(shown.contains("\r0.001 / 0.2505 s (0 %), step 1"), shown.left(200).constData());
        QVERIFY2(shown.contains("note: --duration"), shown.constData());
        const auto [quiet, quietCode] = runOnTerminal(args + QStringList{"--quiet"});
        QCOMPARE(quietCode, 0);
        QVERIFY2(!quiet.contains("/ 0.2505 s ("), quiet.constData());  // (a terminal shows "\n" as "\r\n")
        QVERIFY2(!quiet.contains("note:"), quiet.constData());
        const CliResult piped = runCli(args);
        QCOMPARE(piped.code, 0);
        QVERIFY2(!piped.err.contains("/ 0.2505 s ("), qPrintable(piped.err));
    }

    void sceneReaderBoundsDepthAndMemory() {
        // 64 MiB of '[' peaked at 4.9 GB: refused at the 16th level, at once.
        const std::string nested(1'000'000, '[');
        simlab::SceneFileResult r = simlab::parseSceneFile(nested);
        QVERIFY(!r.file);
        QVERIFY2(r.error.find("nested deeper than 16 levels") != std::string::npos, r.error.c_str());
        // Many small containers at a legal depth: refused by the memory estimate while parsing
        // (~128 B each: 7 million empty arrays would pass 768 MiB). Built only in Release:
        // parsing up to the bound takes ~0.5 GB.
        if (testsupport::kBuildSlowdown == 1) {
            std::string flat = "{\"format\": \"elastic-lab-scene\", \"version\": 3, \"scene\": \"ring2d\", \"x\": [";
            for (int i = 0; i < 7'000'000; ++i) flat += "[],";
            flat += "[]]}";
            r = simlab::parseSceneFile(flat);
            QVERIFY(!r.file);
            QVERIFY2(r.error.find("MiB of memory") != std::string::npos, r.error.c_str());
        }
        // The same through the CLI: exit 2, one line.
        QTemporaryDir dir;
        const QString file = dir.filePath("deep.json");
        writeFile(file, QByteArray(100000, '['));
        const CliResult cli = runCli({"run", "--scene", file});
        QCOMPARE(cli.code, 2);
        QVERIFY2(cli.err.contains("nested deeper than 16 levels"), qPrintable(cli.err));
    }

    void versionsAndStepCountsAreRead64Bit() {
        const std::string head = "{\"format\": \"elastic-lab-scene\", \"scene\": \"spring1d\", ";
        // 2^32 + 2 was read as version 2.
        simlab::SceneFileResult r = simlab::parseSceneFile(head + "\"version\": 4294967298}");
        QVERIFY(!r.file);
        QVERIFY2(r.error.find("version 4294967298 is newer") != std::string::npos, r.error.c_str());
        r = simlab::parseSceneFile(head + "\"version\": 18446744073709551615}");
        QVERIFY(!r.file);
        QVERIFY2(r.error.find("is newer") != std::string::npos, r.error.c_str());
        // A saved step count with no room left to run (it overflowed and wrote a file the
        // program then refused): refused when read, with the bound.
        for (const char* step : {"9223372036854775807", "9007199254740993"}) {
            r = simlab::parseSceneFile(head + "\"version\": 3, \"state\": {\"step\": " + step + "}}");
            QVERIFY(!r.file);
            QVERIFY2(r.error.find("state.step: expected a whole number in [0, 9007199254740992]") != std::string::npos,
                     r.error.c_str());
        }
    }

    void outOfMemoryIsExitThree() {
        // A request within the 1 GiB limit on a machine (here: an address-space limit) that
        // cannot give it: std::bad_alloc is exit 3 with a message, not exit 1. Not under the
        // sanitizers, whose runtimes reserve terabytes of address space at start.
        if (testsupport::kBuildSlowdown != 1) QSKIP("an address-space limit and a sanitizer runtime do not mix");
        QProcess p;
        p.setChildProcessModifier([] {
            const rlimit limit{400ul << 20, 400ul << 20};
            ::setrlimit(RLIMIT_AS, &limit);
        });
        p.start(ELASTIC_LAB_CLI, {"run", "--scene", "sphere3d-latlong", "--set", "slices=512", "--set", "stacks=256",
                                  "--integrator", "implicit-euler", "--duration", "0.001", "--quiet"});
        QVERIFY(testsupport::waitForExit(p));
        const QString err = QString::fromUtf8(p.readAllStandardError());
        QCOMPARE(p.exitStatus(), QProcess::NormalExit);
        QVERIFY2(p.exitCode() == 3 || p.exitCode() == 2, qPrintable(QString::number(p.exitCode()) + ": " + err));
        QVERIFY2(err.contains("out of memory"), qPrintable(err));
    }

    void everyEchoedValueIsQuotedAndCut_data() {
        // A value a message echoes, as a hostile or careless user gives it: escape sequences
        // that retitle and clear the terminal, then 100 kB. Each message goes through the one
        // quoting helper (simcore::quoteShort, simlab::quoted): cut to 40 bytes, control bytes
        // as \xNN, the length said.
        QTest::addColumn<QStringList>("args");
        QTest::addColumn<QByteArray>("sceneFile");
        const QString evil = QString("\x1b]0;pwned\x07\x1b[2J") + QString(100000, 'x');
        QTest::newRow("--integrator") << QStringList{"run", "--scene", "spring1d", "--integrator", evil} << QByteArray();
        QTest::newRow("--set without =") << QStringList{"run", "--scene", "spring1d", "--set", evil} << QByteArray();
        QTest::newRow("--set value") << QStringList{"run", "--scene", "spring1d", "--set", "ks=" + evil} << QByteArray();
        QTest::newRow("study --precision") << QStringList{"study", "--scene", "spring1d", "--integrators", "rk4", "--dts",
                                                          "0.01", "--precision", evil} << QByteArray();
        QTest::newRow("study --reference") << QStringList{"study", "--scene", "spring1d", "--integrators", "rk4", "--dts",
                                                          "0.01", "--reference", evil} << QByteArray();
        QTest::newRow("conservation --precision")
            << QStringList{"conservation", "--scene", "spring1d", "--precision", evil} << QByteArray();
        const QByteArray head = "{\"format\": \"elastic-lab-scene\", \"version\": 3, ";
        QTest::newRow("scene file: scene") << QStringList{"run", "--scene", "@file"}
                                           << head + "\"scene\": \"\\u001b]0;pwned\\u0007" + QByteArray(100000, 'x') + "\"}";
        QTest::newRow("scene file: integrator")
            << QStringList{"run", "--scene", "@file"}
            << head + "\"scene\": \"spring1d\", \"integrator\": \"\\u001b[2J" + QByteArray(100000, 'x') + "\"}";
    }
    void everyEchoedValueIsQuotedAndCut() {
        QFETCH(QStringList, args);
        QFETCH(QByteArray, sceneFile);
        QTemporaryDir dir;
        const QString file = dir.filePath("evil.json");
        if (!sceneFile.isEmpty()) writeFile(file, sceneFile);
        args.replaceInStrings("@file", file);
        const CliResult r = runCli(args);
        QCOMPARE(r.code, 2);
        QVERIFY2(r.err.size() < 700, qPrintable(r.err.left(300)));
        QVERIFY2(!r.err.contains(QChar(0x1b)) && !r.err.contains(QChar(0x07)), qPrintable(r.err.left(300)));
        QVERIFY2(r.err.contains("\\x1b") || r.err.contains("bytes)"), qPrintable(r.err));
    }

    void svgTextIsEscaped() {
        // A title, axis label or legend with & or < broke the plot (not well-formed XML).
        simlab::SvgPanel panel;
        panel.xLabel = "cost <force evaluations>";
        panel.yLabel = "error & more";
        simlab::SvgSeries series;
        series.name = "rk4 \"fast\" & <b>";
        series.colour = "#000";
        series.points = {{1.0, 1.0}, {10.0, 0.1}};
        series.labels = {"a<b", ""};
        panel.series.push_back(series);
        const QByteArray svg = QByteArray::fromStdString(simlab::logLogSvg({panel}, "R&D: <bold> \x1b[2J"));
        QXmlStreamReader xml(svg);
        while (!xml.atEnd()) xml.readNext();
        QVERIFY2(!xml.hasError(), qPrintable(xml.errorString()));
        QVERIFY(svg.contains("R&amp;D: &lt;bold&gt; \xEF\xBF\xBD[2J"));
        QVERIFY(svg.contains("rk4 &quot;fast&quot; &amp; &lt;b&gt;"));
        QVERIFY(svg.contains("a&lt;b") && svg.contains("error &amp; more") && svg.contains("cost &lt;force"));
    }

    void nonFiniteValuesAreWrittenAsSuch() {
        QCOMPARE(simlab::formatDouble(std::numeric_limits<double>::infinity()), std::string("inf"));
        QCOMPARE(simlab::formatDouble(-std::numeric_limits<double>::infinity()), std::string("-inf"));
        QCOMPARE(simlab::formatDouble(std::nan("")), std::string("nan"));
        QCOMPARE(simlab::formatDouble(0.1), std::string("0.1"));
    }
};

QTEST_GUILESS_MAIN(TestOutputs)
#include "test_outputs.moc"
