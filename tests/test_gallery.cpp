// The stiff and extreme gallery: every preset has its expected outcome (simlab/gallery.h).
// CTest runs each case as its own test (gallery_<name>, see tests/CMakeLists.txt) through
// Qt Test's function:tag selection; run without arguments this executable runs them all.
#include <QtTest>

#include <cmath>

#include "simlab/gallery.h"

using namespace simcore;
using namespace simlab;

class TestGallery : public QObject {
    Q_OBJECT
private slots:
    void everyCaseIsRegisteredWithCTest() {
        // The CMake list must name every preset, or a case would silently go untested.
        const QStringList registered = QString(ELASTIC_LAB_GALLERY_CASES).split(',', Qt::SkipEmptyParts);
        for (const GalleryCase& c : galleryCases())
            QVERIFY2(registered.contains(QString::fromStdString(c.name)),
                     qPrintable("add " + QString::fromStdString(c.name) + " to GALLERY_CASES in tests/CMakeLists.txt"));
        QCOMPARE(registered.size(), static_cast<qsizetype>(galleryCases().size()));
    }
    void coversTheIssuesList() {
        // Stiff springs 1e5-1e7, the thesis experiment (3 steps x every integrator), mass ratio
        // 100:1, pressure extremes, a fast impact, near-coincident particles, restitution 0 and 1.
        int thesis = 0;
        for (const GalleryCase& c : galleryCases()) thesis += c.name.rfind("thesis-dt", 0) == 0;
        QCOMPARE(thesis, 21);
        for (const char* name : {"stiff-1e5-rk4-small-step", "stiff-1e6-implicit", "stiff-1e7-light-implicit",
                                 "heavy-inner-collapses-rk4", "light-outer-implicit", "pressure-high-rk4",
                                 "pressure-zero-3d-rk4", "impact-30mps-rk4", "near-coincident-layers",
                                 "restitution-0", "restitution-1"})
            QVERIFY2(findGalleryCase(name), name);
    }
    void runCase_data() {
        QTest::addColumn<QString>("name");
        for (const GalleryCase& c : galleryCases()) QTest::newRow(c.name.c_str()) << QString::fromStdString(c.name);
    }
    void runCase() {
        QFETCH(QString, name);
        const GalleryCase* c = findGalleryCase(name.toStdString());
        QVERIFY(c);
        const GalleryOutcome o = runGalleryCase(*c);
        QVERIFY2(o.finite, "no NaN ever leaves the simulation");
        if (o.failed) QVERIFY2(!o.reason.empty(), "a failure always has a reason");
        QVERIFY2(o.asExpected, o.summary.c_str());
    }
};

QTEST_GUILESS_MAIN(TestGallery)
#include "test_gallery.moc"
