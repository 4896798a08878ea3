// One-body runs pinned bit for bit (issue 26): several bodies in one world must leave every
// one-body scene exactly as it was. Each case runs `elastic-lab-cli run` and compares the
// SHA-256 of its CSV time series and its final state table with the digests of the outputs
// written before the world of several bodies existed (commit c016009).
//
// A change that means to change one-body trajectories (a physics fix) updates the digests
// here, in the same commit, and says why in its message. Release only: the digests are of
// the Release build's bits (the sanitizer presets compile with other flags).
#include <QtTest>

#include <QCryptographicHash>
#include <QTemporaryDir>

#include "cli_process.h"

namespace {

struct PinnedRun {
    const char* name;
    QStringList args;
    const char* csvSha256;
    const char* stateSha256;
};

// clang-format off
const std::vector<PinnedRun>& pinnedRuns() {
    static const std::vector<PinnedRun> runs = {
        {"ring2d_rk4", {"--scene", "ring2d", "--integrator", "rk4", "--duration", "1"},
         "e0e631b94f1b86d75ae4b49e870f8889fbcd5c32eed903de6535eb09930a10fb",
         "44a9b7b7495ea70c8a1179bedde2a49a7b179775e6e63742b4da0c7f5c60172d"},
        {"sphere3d_rk45", {"--scene", "sphere3d", "--integrator", "rk45", "--duration", "0.5"},
         "ef8c7b4d5717cd725179fc486d696392861256f3debd7ef58ae031fff155592b",
         "091d247bfc85b2868e4dbb9bda39293d3eae7b14ad41a1370307430a5edb3467"},
        {"spring1d_midpoint", {"--scene", "spring1d", "--integrator", "midpoint", "--duration", "1"},
         "ce44839851d5fc9038dab73b9dd4aff37512cc7129472ec83b09b25da85566a1",
         "9a0805dcec149c7cb7b83cb1308896257f434550ffe86989e0c0adcefa7f6ab1"},
        {"sphere3d_xpbd", {"--scene", "sphere3d", "--integrator", "xpbd", "--duration", "0.5"},
         "540aab9b6a936d83bbcff11ead10b3ab8994e8e34934ec4af2b6f65d487940e6",
         "6f407c6f4f566fb7b736dff047a7e933c94307815a9c51e9961cbe4e2242a4d3"},
        {"ring2d_cvode_projection", {"--scene", "ring2d", "--integrator", "cvode-bdf", "--set", "contact=projection",
                                     "--duration", "1", "--every", "25"},
         "83a1c11b9da7a6463a041c11ce3424a55c64a151b83b06cb90bcadf0ff19b901",
         "9736373d3615d90e9f70c29041cbe969fcbea4a964c460a8065e2517b8b7ae9f"},
        {"ring2d_implicit_projection", {"--scene", "ring2d", "--integrator", "implicit-euler", "--set",
                                        "contact=projection", "--duration", "1"},
         "8ec5f765f7cddbf9920586f12ed5c341d63cf3cde70b48fcefed56443e96c5d8",
         "3b7a0aa3525c0b21501d619e6a1455cb13e975f15a12e3345c555a12f2cf0591"},
        {"ring2d_rk4_error", {"--scene", "ring2d", "--integrator", "rk4", "--error-estimate", "--duration", "1"},
         "a133ce0f007220e346b1105cad3bce01e2ea35f30a1e95f46d6a2cd9ff829a7d",
         "44a9b7b7495ea70c8a1179bedde2a49a7b179775e6e63742b4da0c7f5c60172d"},
        {"latlong_verlet", {"--scene", "sphere3d-latlong", "--integrator", "verlet", "--duration", "0.3"},
         "fd603439c803af1a45271e3fc4b22d363fb437c2aede5015b8b92f545c7a3a75",
         "2e514ecef5b47d4790bf3c94665b68d20db013cdf90fc41ff3d8ebf3ed82944b"},
    };
    return runs;
}
// clang-format on

QByteArray sha256Of(const QString& path) {
    QFile f(path);
    if (!f.open(QIODevice::ReadOnly)) return {};
    return QCryptographicHash::hash(f.readAll(), QCryptographicHash::Sha256).toHex();
}

}  // namespace

class TestPinnedRuns : public QObject {
    Q_OBJECT
private slots:
    void oneBodyRunsAreUnchanged_data() {
        QTest::addColumn<int>("index");
        for (std::size_t k = 0; k < pinnedRuns().size(); ++k)
            QTest::newRow(pinnedRuns()[k].name) << static_cast<int>(k);
    }
    void oneBodyRunsAreUnchanged() {
#if defined(__SANITIZE_ADDRESS__) || defined(__SANITIZE_THREAD__)
        QSKIP("the digests are of the Release build's outputs");
#endif
        QFETCH(int, index);
        const PinnedRun& run = pinnedRuns()[static_cast<std::size_t>(index)];
        QTemporaryDir dir;
        const QString csv = dir.filePath("run.csv"), state = dir.filePath("run.state");
        const CliResult r = runCli(QStringList{"run"} + run.args + QStringList{"--csv", csv, "--state", state, "--quiet"});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QCOMPARE(sha256Of(csv), QByteArray(run.csvSha256));
        QCOMPARE(sha256Of(state), QByteArray(run.stateSha256));
    }
};

QTEST_GUILESS_MAIN(TestPinnedRuns)
#include "test_pinned_runs.moc"
