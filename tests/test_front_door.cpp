// The one front door (simlab/request.h): one table of bad requests (tests/data/bad_requests.json)
// fed to the CLI and to the GUI's command line, each refused with exit 2 and the same one-line
// text ("error: " and "elastic-lab: " before it). python/tests/test_front_door.py feeds the
// same table to Python and expects ValueError with that text.
#include <sys/stat.h>

#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QtTest>

#include "cli_process.h"

class TestFrontDoor : public QObject {
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    QJsonArray table() {
        QFile file(QStringLiteral(ELASTIC_LAB_BAD_REQUESTS));
        if (!file.open(QIODevice::ReadOnly)) return {};
        return QJsonDocument::fromJson(file.readAll()).array();
    }
    QString substituted(QString text) const { return text.replace(QStringLiteral("{dir}"), m_dir.path()); }
    QStringList arguments(const QJsonValue& value) const {
        QStringList args;
        for (const QJsonValue& a : value.toArray()) args << substituted(a.toString());
        return args;
    }

private slots:
    void initTestCase() {
        QVERIFY(m_dir.isValid());
        // The inputs the table names: a saved experiment and a FIFO.
        const CliResult saved = runCli({"run", "--scene", "spring1d", "--duration", "0.01", "--quiet", "--save-scene",
                                        m_dir.filePath("exp.json")});
        QCOMPARE(saved.code, 0);
        QCOMPARE(::mkfifo(qPrintable(m_dir.filePath("fifo")), 0600), 0);
        QVERIFY(table().size() >= 15);
    }

    void theCliRefusesEachWithTheTablesText() {
        int rows = 0;
        for (const QJsonValue& row : table()) {
            const QJsonObject r = row.toObject();
            if (!r.contains("cli")) continue;
            ++rows;
            const CliResult result = runCli(arguments(r["cli"]));
            const QString what = r["name"].toString() + ": " + result.err;
            QVERIFY2(result.code == 2, qPrintable(what));
            QCOMPARE(result.err, "error: " + substituted(r["message"].toString()) + "\n");
            QVERIFY2(result.out.isEmpty(), qPrintable(what));
        }
        QVERIFY(rows >= 12);
        // Nothing was written beside the inputs, and the scene file is whole.
        QCOMPARE(QDir(m_dir.path()).entryList(QDir::Files | QDir::System | QDir::Hidden).size(), 2);
    }

    void theGuiRefusesEachWithTheTablesText() {
#ifndef ELASTIC_LAB_GUI
        QSKIP("the GUI is not built");
#else
        int rows = 0;
        for (const QJsonValue& row : table()) {
            const QJsonObject r = row.toObject();
            if (!r.contains("gui")) continue;
            ++rows;
            QProcess gui;
            QProcessEnvironment env = QProcessEnvironment::systemEnvironment();
            env.insert("QT_QPA_PLATFORM", "offscreen");  // refused before any window exists
            env.insert("XDG_RUNTIME_DIR", m_dir.path());
            gui.setProcessEnvironment(env);
            gui.start(ELASTIC_LAB_GUI, arguments(r["gui"]));
            QVERIFY(testsupport::waitForExit(gui));
            const QString err = QString::fromUtf8(gui.readAllStandardError());
            QVERIFY2(gui.exitCode() == 2, qPrintable(r["name"].toString() + ": " + err));
            QCOMPARE(err, "elastic-lab: " + substituted(r["message"].toString()) + "\n");
        }
        QVERIFY(rows >= 8);
#endif
    }
};

QTEST_GUILESS_MAIN(TestFrontDoor)
#include "test_front_door.moc"
