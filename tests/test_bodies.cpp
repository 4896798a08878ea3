// Body builders: counts, uniqueness, orientation and exact rest volumes (docs/model.md "Bodies").
#include <QtTest>

#include <cmath>
#include <numbers>
#include <algorithm>
#include <vector>

#include "simcore/body.h"
#include "simcore/scaling.h"

using namespace simcore;

namespace {

// Independent volume: sum of signed tetrahedra (origin, a, b, c) as 3x3 determinants.
double tetraVolume(const Surface& s, const Eigen::Matrix3Xd& p) {
    double v = 0.0;
    for (auto [a, b, c] : s.triangles) {
        Eigen::Matrix3d m;
        m << p.col(a), p.col(b), p.col(c);
        v += m.determinant() / 6.0;
    }
    return v;
}

void checkCommonInvariants(const Body& body) {
    const Topology& t = body.topology;
    std::vector<std::pair<int, int>> pairs;
    pairs.reserve(t.springCount());
    for (const SpringSet& family : t.springs)
        for (std::size_t s = 0; s < family.size(); ++s) {
            const int a = family.a[s], b = family.b[s];
            QVERIFY(a != b);
            QVERIFY(a >= 0 && b >= 0 && a < t.particleCount() && b < t.particleCount());
            pairs.push_back(std::minmax(a, b));
            QVERIFY2(family.rest[s] > 1e-6, "a spring has zero rest length");
            if (t.dimension != 1)  // 1D rest length is a parameter, not the start distance
                QVERIFY(std::abs(family.rest[s] - (body.positions.col(b) - body.positions.col(a)).norm()) < 1e-12);
        }
    std::sort(pairs.begin(), pairs.end());
    QVERIFY2(std::adjacent_find(pairs.begin(), pairs.end()) == pairs.end(), "a spring is stored twice");
    const Eigen::Vector3d centre = body.positions.rowwise().mean();
    for (const Surface& s : t.surfaces) {
        QVERIFY(s.restVolume > 0.0);
        for (auto [a, b, c] : s.triangles) {
            const Eigen::Vector3d pa = body.positions.col(a), pb = body.positions.col(b), pc = body.positions.col(c);
            const Eigen::Vector3d n = (pb - pa).cross(pc - pa);
            QVERIFY2(n.dot((pa + pb + pc) / 3.0 - centre) > 0.0, "a triangle faces inward");
        }
        for (auto [a, b] : s.edges) {
            const Eigen::Vector3d d = body.positions.col(b) - body.positions.col(a);
            const Eigen::Vector3d n(d.y(), -d.x(), 0.0);
            const Eigen::Vector3d mid = 0.5 * (body.positions.col(a) + body.positions.col(b));
            QVERIFY2(n.dot(mid - centre) > 0.0, "an edge normal points inward");
        }
    }
}

}  // namespace

class TestBodies : public QObject {
    Q_OBJECT
private slots:
    void spring1d() {
        const Body body = buildSpring1d({1.0, 1.5, true}, 2.0);
        QCOMPARE(body.topology.particleCount(), 2);
        QCOMPARE(body.topology.springCount(), std::size_t(1));
        QCOMPARE(body.topology.springs[0].rest[0], 1.0);
        QCOMPARE(body.positions(1, 1), -1.5);
        QVERIFY(body.fixed[0] && !body.fixed[1]);
        QVERIFY(body.topology.surfaces.empty());
        checkCommonInvariants(body);
    }

    void ring2d_data() {
        QTest::addColumn<int>("n");
        for (int n : {3, 10, 12, 100, 1000}) QTest::addRow("n=%d", n) << n;
    }
    void ring2d() {
        QFETCH(int, n);
        const Body body = buildRing2d({n, 1.5, 2.0}, 1.0, 1.0);
        const Topology& t = body.topology;
        QCOMPARE(t.particleCount(), 2 * n);
        QCOMPARE(t.family(SpringFamily::Structural).size(), std::size_t(2 * n));
        QCOMPARE(t.family(SpringFamily::Radius).size(), std::size_t(n));
        QCOMPARE(t.family(SpringFamily::Shear).size(), std::size_t(2 * n));
        QCOMPARE(t.surfaces.size(), std::size_t(2));
        checkCommonInvariants(body);
        // Exact polygon area of a regular n-gon: n/2 r^2 sin(2 pi / n).
        for (const Surface& s : t.surfaces) {
            const double r = s.layer == Layer::Inner ? 1.5 : 2.0;
            const double exact = 0.5 * n * r * r * std::sin(2.0 * std::numbers::pi / n);
            QVERIFY(std::abs(s.restVolume - exact) < 1e-12 * exact);
        }
    }
    void ringAreaApproachesCircle() {
        double previous = 1.0;
        for (int n : {10, 100, 1000, 10000}) {
            const Body body = buildRing2d({n, 1.5, 2.0}, 1.0, 1.0);
            const double error = std::abs(body.topology.surfaces[1].restVolume / (std::numbers::pi * 4.0) - 1.0);
            QVERIFY(error < previous);
            previous = error;
        }
        QVERIFY(previous < 1e-6);
    }

    void sphere3dCounts_data() {
        QTest::addColumn<int>("level");
        for (int l = 0; l <= 7; ++l) QTest::addRow("L=%d", l) << l;
    }
    void sphere3dCounts() {
        QFETCH(int, level);
        const long p4 = 1L << (2 * level);  // 4^L
        const TriangleMesh mesh = subdividedOctahedron(level);
        QCOMPARE(long(mesh.vertices.cols()), 4 * p4 + 2);
        QCOMPARE(long(mesh.triangles.size()), 8 * p4);
        QCOMPARE(long(meshEdges(mesh.triangles).size()), 12 * p4);
        for (Eigen::Index i = 0; i < mesh.vertices.cols(); ++i)
            QVERIFY(std::abs(mesh.vertices.col(i).norm() - 1.0) < 1e-12);
        const Body body = buildSphere3d({level, 1.5, 2.0}, 1.0, 1.0);
        const Topology& t = body.topology;
        QCOMPARE(long(t.particleCount()), 2 * (4 * p4 + 2));
        QCOMPARE(long(t.family(SpringFamily::Structural).size()), 2 * 12 * p4);
        QCOMPARE(long(t.family(SpringFamily::Radius).size()), 4 * p4 + 2);
        QCOMPARE(long(t.family(SpringFamily::Shear).size()), 2 * 12 * p4);
        QCOMPARE(long(t.surfaces[0].triangles.size()), 8 * p4);
        checkCommonInvariants(body);
        for (const Surface& s : t.surfaces)
            QVERIFY(std::abs(s.restVolume - tetraVolume(s, body.positions)) < 1e-12 * s.restVolume);
    }
    void octahedronVolumeIsExact() {
        // Level 0 is the octahedron: V = 4/3 r^3.
        const Body body = buildSphere3d({0, 1.5, 2.0}, 1.0, 1.0);
        QVERIFY(std::abs(body.topology.surfaces[1].restVolume - 4.0 / 3.0 * 8.0) < 1e-12);
        QVERIFY(std::abs(body.topology.surfaces[0].restVolume - 4.0 / 3.0 * 3.375) < 1e-12);
    }
    void sphereVolumeApproachesBall() {
        const double ball = 4.0 / 3.0 * std::numbers::pi * 8.0;
        double previous = 1.0;
        for (int level = 0; level <= 6; ++level) {
            const Body body = buildSphere3d({level, 1.5, 2.0}, 1.0, 1.0);
            const double error = 1.0 - body.topology.surfaces[1].restVolume / ball;
            QVERIFY(error > 0.0);  // inscribed polyhedron
            QVERIFY2(error < previous, "volume error must shrink with each level");
            previous = error;
        }
        QVERIFY(previous < 1e-3);
    }

    void latLong_data() {
        QTest::addColumn<int>("slices");
        QTest::addColumn<int>("stacks");
        QTest::newRow("3x2") << 3 << 2;
        QTest::newRow("8x4") << 8 << 4;
        QTest::newRow("16x8") << 16 << 8;
        QTest::newRow("33x17") << 33 << 17;
    }
    void latLong() {
        QFETCH(int, slices);
        QFETCH(int, stacks);
        const Body body = buildLatLongSphere({slices, stacks, 1.5, 2.0}, 1.0, 1.0);
        const Topology& t = body.topology;
        const int perLayer = 2 + slices * (stacks - 1);
        QCOMPARE(t.particleCount(), 2 * perLayer);
        // Rings: slices*(stacks-1) edges; meridians: slices*stacks edges (pole to pole).
        const int edges = slices * (stacks - 1) + slices * stacks;
        QCOMPARE(int(t.family(SpringFamily::Structural).size()), 2 * edges);
        QCOMPARE(int(t.family(SpringFamily::Radius).size()), perLayer);
        QCOMPARE(int(t.family(SpringFamily::Shear).size()), 2 * edges);
        QCOMPARE(int(t.surfaces[0].triangles.size()), 2 * slices * (stacks - 1));
        checkCommonInvariants(body);
        for (const Surface& s : t.surfaces)
            QVERIFY(std::abs(s.restVolume - tetraVolume(s, body.positions)) < 1e-12 * s.restVolume);
    }
    void latLongVolumeApproachesBall() {
        const double ball = 4.0 / 3.0 * std::numbers::pi * 8.0;
        double previous = 1.0;
        for (int k : {4, 8, 16, 32, 64}) {
            const Body body = buildLatLongSphere({2 * k, k, 1.5, 2.0}, 1.0, 1.0);
            const double error = 1.0 - body.topology.surfaces[1].restVolume / ball;
            QVERIFY(error > 0.0 && error < previous);
            previous = error;
        }
        QVERIFY(previous < 2e-3);
    }
    void massesPerLayer() {
        const Body body = buildSphere3d({1, 1.0, 2.0}, 5.0, 0.5);
        for (int i = 0; i < body.topology.particleCount(); ++i)
            QCOMPARE(body.mass[i], body.topology.layer[std::size_t(i)] == Layer::Inner ? 5.0 : 0.5);
    }
    void refusesCrossedRadii() {
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, buildRing2d({12, 2.0, 1.5}, 1.0, 1.0));
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, buildSphere3d({1, 2.0, 2.0}, 1.0, 1.0));
        ParameterSet p(SceneKind::Sphere3dLatLong);
        p.set(simcore::Param::RadiusInner, 2.5);
        const auto error = validateShape(p);
        QVERIFY(error && error->find("radius_inner") != std::string::npos);
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, buildBody(p));
    }
    // bodySize counts without building; it must agree with what the builders make.
    void sizeWithoutBuildingMatchesTheBody_data() {
        QTest::addColumn<int>("kind");
        QTest::addColumn<QString>("key");
        QTest::addColumn<int>("value");
        QTest::addColumn<int>("stacks");
        QTest::newRow("spring1d") << int(SceneKind::Spring1d) << "" << 0 << 0;
        for (int n : {3, 12, 1001})
            QTest::addRow("ring %d", n) << int(SceneKind::Ring2d) << "particles" << n << 0;
        for (int level = 0; level <= 5; ++level)
            QTest::addRow("sphere L%d", level) << int(SceneKind::Sphere3d) << "subdivisions" << level << 0;
        for (auto [slices, stacks] : {std::pair{3, 2}, std::pair{8, 4}, std::pair{37, 19}})
            QTest::addRow("latlong %dx%d", slices, stacks)
                << int(SceneKind::Sphere3dLatLong) << "slices" << slices << stacks;
    }
    void sizeWithoutBuildingMatchesTheBody() {
        QFETCH(int, kind);
        QFETCH(QString, key);
        QFETCH(int, value);
        QFETCH(int, stacks);
        ParameterSet p{SceneKind(kind)};
        if (!key.isEmpty()) QVERIFY(!p.set(key.toStdString(), value));
        if (stacks) QVERIFY(!p.set(simcore::Param::Stacks, stacks));
        const Body body = buildBody(p);
        long long faces = 0;
        for (const Surface& s : body.topology.surfaces)
            faces += static_cast<long long>(s.triangles.size() + s.edges.size());
        const BodySize size = bodySize(p);
        QCOMPARE(size.particles, static_cast<long long>(body.topology.particleCount()));
        QCOMPARE(size.springs, static_cast<long long>(body.topology.springCount()));
        QCOMPARE(size.faces, faces);
    }
    // The largest resolutions the table allows are checked against the stated memory limit
    // before anything is built; the message names the resolution and says what fits.
    void refusesResolutionsBeyondTheMemoryLimit() {
        ParameterSet latlong(SceneKind::Sphere3dLatLong);
        latlong.set(simcore::Param::Slices, 1024);
        latlong.set(simcore::Param::Stacks, 512);
        const auto error = validateShape(latlong);
        QVERIFY(error);
        for (const char* word : {"slices=1024", "stacks=512", "GiB", "limit is 1 GiB", "particles for this scene"})
            QVERIFY2(error->find(word) != std::string::npos, error->c_str());
        QVERIFY_THROWS_EXCEPTION(std::invalid_argument, buildBody(latlong));
        // What the table allows for the octahedron sphere (L7, 262,152 particles) and the ring
        // (100,000 per layer) fits; so does a lat/long sphere of the same size as L7.
        ParameterSet sphere(SceneKind::Sphere3d);
        sphere.set(simcore::Param::Subdivisions, 7);
        QVERIFY(!validateShape(sphere));
        ParameterSet ring(SceneKind::Ring2d);
        ring.set(simcore::Param::Particles, 100000);
        QVERIFY(!validateShape(ring));
        latlong.set(simcore::Param::Slices, 512);
        latlong.set(simcore::Param::Stacks, 256);
        QVERIFY(!validateShape(latlong));
        QVERIFY(memoryBoundBytes(bodySize(latlong)) <= kMemoryLimitBytes);
    }
};

QTEST_GUILESS_MAIN(TestBodies)
#include "test_bodies.moc"
