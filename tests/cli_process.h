#pragma once
// Runs the elastic-lab-cli binary of this build (ELASTIC_LAB_CLI) and collects what it says.
#include <QProcess>
#include <QString>
#include <QStringList>

#include "test_support.h"

struct CliResult {
    int code = -1;  // exit status; -1 if it hung (see test_support.h)
    QString out;
    QString err;
};

inline CliResult runCli(const QStringList& args) {
    QProcess p;
    p.start(ELASTIC_LAB_CLI, args);
    if (!testsupport::waitForExit(p)) return {};
    return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}
