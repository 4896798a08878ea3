// Camera: the framing of the 3D view keeps the body whole in a view of any shape.
#include <QtTest>

#include <cmath>

#include "ui/camera.h"

using elui::Camera;

namespace {

// Normalised device coordinates of a world point (x, y in [-1, 1] when on screen).
QVector3D ndc(const Camera& camera, const QSize& size, const QVector3D& point) {
    return (camera.projection(size) * camera.view()).map(point);
}

}  // namespace

class TestCamera : public QObject {
    Q_OBJECT
private slots:
    void bodyStaysWholeInNarrowViews_data() {
        QTest::addColumn<QSize>("size");
        QTest::newRow("wide 2:1") << QSize(800, 400);
        QTest::newRow("square") << QSize(600, 600);
        QTest::newRow("narrow 1:2") << QSize(400, 800);  // three views side by side, or docks around
        QTest::newRow("narrow 1:3") << QSize(300, 900);
    }
    void bodyStaysWholeInNarrowViews() {
        QFETCH(QSize, size);
        // The default sphere: radius 2 m in a box of half-size 2.5 m, seen from the home view.
        Camera camera;
        const QVector3D centre(0.0f, 2.5f, 0.0f);
        const float radius = 2.0f;
        camera.fit(centre, radius, 2.5f);
        // Every point of the body's sphere (and of one squashed 1.5 times wider on the floor)
        // lands on screen.
        float widest = 0.0f;
        for (int i = 0; i <= 24; ++i)
            for (int j = 0; j < 48; ++j) {
                const double theta = M_PI * i / 24.0, phi = 2.0 * M_PI * j / 48.0;
                const QVector3D onSphere(float(std::sin(theta) * std::cos(phi)), float(std::cos(theta)),
                                         float(std::sin(theta) * std::sin(phi)));
                const QVector3D squashed(1.5f * onSphere.x(), 0.6f * onSphere.y(), 1.5f * onSphere.z());
                for (const QVector3D& p : {onSphere, squashed}) {
                    const QVector3D q = ndc(camera, size, centre + radius * p);
                    widest = std::max({widest, std::abs(q.x()), std::abs(q.y())});
                }
            }
        QVERIFY2(widest <= 1.0f, qPrintable(QString("the body reaches %1 of the half-view").arg(widest)));
        // And it is not lost in the middle: it fills at least a third of the half-view.
        QVERIFY(widest > 0.33f);
    }

    void wideViewsKeepTheirVerticalAngle() {
        // Wider than tall: 40 degrees vertically, as always; taller than wide: 40 across.
        Camera camera;
        QCOMPARE(camera.fovY(QSize(800, 400)), 40.0f);
        QCOMPARE(camera.fovY(QSize(500, 500)), 40.0f);
        const float narrow = camera.fovY(QSize(400, 800));
        const float across = 2.0f * std::atan(0.5f * std::tan(narrow * float(M_PI) / 360.0f)) * 180.0f / float(M_PI);
        QVERIFY(std::abs(across - 40.0f) < 1e-3f);
        // A pixel is the same world length across and up (square pixels), so picking radii and
        // the grab ray agree with what is drawn.
        camera.fit(QVector3D(0, 0, 0), 1.0f, 2.5f);
        const QSize size(300, 900);
        const QVector3D right = QVector3D::crossProduct(camera.forward(), QVector3D(0, 1, 0)).normalized();
        const float half = 0.5f * float(size.width()) * camera.worldPerPixel(size);
        const QVector3D edge = ndc(camera, size, right * half);
        QVERIFY2(std::abs(std::abs(edge.x()) - 1.0f) < 1e-3f, qPrintable(QString::number(edge.x())));
    }
};

QTEST_GUILESS_MAIN(TestCamera)
#include "test_camera.moc"
