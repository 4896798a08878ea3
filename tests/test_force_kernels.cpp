// The force kernels of each instruction set (portable, AVX2, AVX-512: one source over
// simcore/simd.h, compiled per set) called directly on blocks of every length from 0 to 40 at
// an offset, so that every remainder of the four- and eight-lane loops and of the quad pairs
// is run: all sets must write the same force rows and return the same sums, bit for bit, and
// the one degenerate spring must be counted once.
#include <QtTest>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <random>

#include "kernel_inputs.h"
#include "simcore/force_kernels.h"
#include "simcore/forces.h"
#include "simcore/simulation.h"

using namespace simcore;
namespace kernels = simcore::kernels;

namespace {

using namespace kernel_inputs;

// What one call of a kernel leaves: the padded rows (or the unpadded output) and its sums.
struct Outcome {
    std::vector<double> rows;
    std::vector<double> sums;
    int degenerate = 0;
    bool operator==(const Outcome& o) const {
        // Bit for bit (memcmp also tells -0.0 from 0.0).
        // (An empty vector's data() may be null, which memcmp must not be given even for 0 bytes.)
        auto same = [](const std::vector<double>& a, const std::vector<double>& b) {
            return a.size() == b.size() && (a.empty() || std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0);
        };
        return degenerate == o.degenerate && same(rows, o.rows) && same(sums, o.sums);
    }
};

enum class Kernel { Springs, Run, Quads, Triangles, Unpad };

Outcome call(const Inputs& in, Kernel kernel, std::size_t length) {
    kernels::AlignedBuffer f4(4 * kParticles);
    std::copy(in.f4Start.begin(), in.f4Start.end(), f4.data());
    const std::size_t begin = kBegin, end = kBegin + length;
    const double *x = in.x.data(), *v = in.v.data();
    Outcome r;
    switch (kernel) {
        case Kernel::Springs: {
            const kernels::SpringSums s = kernels::springBlock(in.springs, begin, end, 30.0, 0.7, x, v, f4.data(), r.degenerate);
            r.sums = {s.power, s.stretch2};
            break;
        }
        case Kernel::Run: {
            const kernels::SpringSums s =
                kernels::springRunBlock(in.run, begin, end, kPerLayer, 30.0, 0.7, x, v, f4.data(), r.degenerate);
            r.sums = {s.power, s.stretch2};
            break;
        }
        case Kernel::Quads: {
            const kernels::QuadSums s = kernels::quadBlock(in.quads, begin, end, kPerLayer, {30.0, 20.0}, {0.7, 0.4},
                                                           x, v, f4.data(), r.degenerate);
            r.sums = {s.power, s.stretch2[0], s.stretch2[1]};
            break;
        }
        case Kernel::Triangles:
            r.sums = {kernels::triangleBlock(in.surface, begin, end, x, f4.data())};
            break;
        case Kernel::Unpad: {
            kernels::AlignedBuffer g4(4 * kParticles);
            for (std::size_t i = 0; i < g4.size(); ++i) g4.data()[i] = in.f4Start[(i * 7) % in.f4Start.size()];
            std::vector<double> out(3 * kParticles, -1.0);
            const int b = static_cast<int>(begin), e = static_cast<int>(end);
            kernels::unpad(f4.data(), g4.data(), 0.3, in.invMass3.data(), b, e, out.data());
            kernels::unpad(f4.data(), nullptr, 0.0, nullptr, b + e, 2 * e, out.data());  // the other branches
            r.rows = out;
            return r;
        }
    }
    r.rows.assign(f4.data(), f4.data() + f4.size());
    return r;
}

}  // namespace

class TestForceKernels : public QObject {
    Q_OBJECT

private slots:
    void cleanup() { kernels::useKernels(kernels::widestKernels()); }

    void everySetGivesTheSameBitsForEveryBlockLength_data() {
        QTest::addColumn<int>("kernel");
        QTest::newRow("indexed springs") << static_cast<int>(Kernel::Springs);
        QTest::newRow("radius run") << static_cast<int>(Kernel::Run);
        QTest::newRow("edge quads") << static_cast<int>(Kernel::Quads);
        QTest::newRow("triangles") << static_cast<int>(Kernel::Triangles);
        QTest::newRow("unpad") << static_cast<int>(Kernel::Unpad);
    }
    void everySetGivesTheSameBitsForEveryBlockLength() {
        QFETCH(int, kernel);
        const Kernel which = static_cast<Kernel>(kernel);
        const Inputs in = makeInputs();
        int compared = 0;
        for (std::size_t length = 0; length <= kMaxLength; ++length) {
            QCOMPARE(kernels::useKernels(kernels::KernelSet::Portable), kernels::KernelSet::Portable);
            const Outcome portable = call(in, which, length);
            // The blocks do something: rows change once there is an element, and the
            // degenerate spring (the block's sixth) is counted once when it is in the block.
            if (which != Kernel::Unpad) QCOMPARE(portable.rows == in.f4Start, length == 0);
            if (which == Kernel::Springs) QCOMPARE(portable.degenerate, length > 5 ? 1 : 0);
            else QCOMPARE(portable.degenerate, 0);
            for (kernels::KernelSet set : {kernels::KernelSet::Avx2, kernels::KernelSet::Avx512}) {
                if (set > kernels::widestKernels()) continue;
                QCOMPARE(kernels::useKernels(set), set);
                const Outcome vector = call(in, which, length);
                QVERIFY2(vector == portable, qPrintable(QStringLiteral("%1 kernels, block length %2")
                                                            .arg(QString::fromUtf8(kernels::kernelSetName(set)))
                                                            .arg(length)));
                ++compared;
            }
        }
        if (compared == 0) QSKIP("this build or CPU has only the portable kernels: nothing to compare with");
    }

    // The integrators' stage sums (kernels::stageSum, rk4Sum) in every set against the plain
    // element-wise sums they replaced (Eigen's y + c k and y + h/6 (k1 + 2 k2 + 2 k3 + k4)),
    // bit for bit, for every length of the four- and eight-wide loops' remainders.
    void stageSumsAreThePlainSums() {
        const std::size_t n = 41;
        Eigen::VectorXd y(n), k1(n), k2(n), k3(n), k4(n);
        for (Eigen::Index i = 0; i < Eigen::Index(n); ++i) {
            y[i] = 1.0 / (3.0 + double(i));
            k1[i] = std::sin(0.7 * double(i)) * 1e3;
            k2[i] = std::cos(1.3 * double(i)) / 7.0;
            k3[i] = double(i) / 11.0 - 1.9;
            k4[i] = std::exp(-0.1 * double(i)) * 3.3;
        }
        const double c = 0.0015, h6 = 0.003 / 6.0;
        int compared = 0;
        for (kernels::KernelSet set : {kernels::KernelSet::Portable, kernels::KernelSet::Avx2, kernels::KernelSet::Avx512}) {
            if (set > kernels::widestKernels()) continue;
            QCOMPARE(kernels::useKernels(set), set);
            for (std::size_t length = 0; length <= n; ++length) {
                const auto l = Eigen::Index(length);
                Eigen::VectorXd out = Eigen::VectorXd::Constant(Eigen::Index(n), -5.0), expected = out;
                kernels::stageSum(out.data(), y.data(), c, k2.data(), length);
                expected.head(l) = y.head(l) + c * k2.head(l);
                QVERIFY2(out == expected, qPrintable(QStringLiteral("stageSum, %1 kernels, length %2")
                                                         .arg(QString::fromUtf8(kernels::kernelSetName(set)))
                                                         .arg(length)));
                Eigen::VectorXd sum = y;
                expected = y;
                kernels::rk4Sum(sum.data(), h6, k1.data(), k2.data(), k3.data(), k4.data(), length);
                expected.head(l) += h6 * (k1.head(l) + 2.0 * k2.head(l) + 2.0 * k3.head(l) + k4.head(l));
                QVERIFY2(sum == expected, qPrintable(QStringLiteral("rk4Sum, %1 kernels, length %2")
                                                         .arg(QString::fromUtf8(kernels::kernelSetName(set)))
                                                         .arg(length)));
                ++compared;
            }
        }
        QVERIFY(compared > 0);
    }

    // The volume gradient gathered per corner (kernels::vertexGradients) on a real two-layer
    // sphere (level 2: 60 corners of six triangles and 6 of four per layer), its state
    // perturbed: every set writes the same rows and returns the same sum, bit for bit, for
    // ranges starting and ending at every offset (the four-particle groups, the ones with a
    // four-triangle fan, the remainders); and the rows are the triangles' own gradients
    // (triangleBlock, added triangle by triangle) and the sum three times theirs, to round-off.
    void vertexGradientsAreTheTrianglesGathered() {
        ParameterSet p(SceneKind::Sphere3d);
        p.set(Param::Subdivisions, 2);
        const Simulation sim(p, "rk4");
        const Topology& topo = sim.body().topology;
        const int n = topo.particleCount();
        const kernels::VertexFans fans = kernels::vertexFans(topo);
        QCOMPARE(int(fans.ring6.size()), n);
        QCOMPARE(int(std::count(fans.ring6.begin(), fans.ring6.end(), 1)), n - 12);
        std::vector<double> x(sim.state().data(), sim.state().data() + 3 * n);
        std::mt19937 random(7);
        std::uniform_real_distribution<double> jitter(-0.05, 0.05);
        for (double& c : x) c += jitter(random) + 0.3;  // off the origin too
        // The triangles' gradients and sums (each layer alone: its particles are one range).
        kernels::useKernels(kernels::KernelSet::Portable);
        std::vector<double> byFaces(4 * std::size_t(n), 0.0);
        double faces6 = 0.0;
        for (const Surface& s : topo.surfaces)
            faces6 += kernels::triangleBlock(s, 0, s.triangles.size(), x.data(), byFaces.data());
        double scale = 0.0;
        for (double g : byFaces) scale = std::max(scale, std::abs(g));
        int compared = 0;
        for (int begin : {0, 1, 2, 3, 5}) {
            for (int end : {n, n - 1, n - 2, n - 3}) {
                std::vector<Outcome> outcomes;
                for (kernels::KernelSet set : {kernels::KernelSet::Portable, kernels::KernelSet::Avx2, kernels::KernelSet::Avx512}) {
                    if (set > kernels::widestKernels()) continue;
                    QCOMPARE(kernels::useKernels(set), set);
                    Outcome r;
                    r.rows.assign(4 * std::size_t(n), -7.0);  // written, not added to
                    r.sums = {kernels::vertexGradients(fans, begin, end, x.data(), r.rows.data())};
                    outcomes.push_back(r);
                }
                for (std::size_t k = 1; k < outcomes.size(); ++k, ++compared)
                    QVERIFY2(outcomes[k] == outcomes[0], qPrintable(QStringLiteral("set %1, particles %2-%3").arg(k).arg(begin).arg(end)));
                const Outcome& r = outcomes[0];
                for (int i = 0; i < n; ++i)
                    for (int a = 0; a < 4; ++a) {
                        const std::size_t k = 4 * std::size_t(i) + std::size_t(a);
                        const double expected = i >= begin && i < end ? (a < 3 ? byFaces[k] : 0.0) : -7.0;
                        QVERIFY2(std::abs(r.rows[k] - expected) <= 1e-13 * scale,
                                 qPrintable(QStringLiteral("particle %1 axis %2: %3 against %4").arg(i).arg(a).arg(r.rows[k]).arg(expected)));
                    }
                if (begin == 0 && end == n) QVERIFY(std::abs(r.sums[0] - 3.0 * faces6) <= 1e-12 * std::abs(faces6));
            }
        }
        if (compared == 0) QWARN("this build or CPU has only the portable kernels: the sets were not compared");
    }

    // Portable against a plain per-spring computation: the lane code over double (a block's
    // last springs) and over vectors give the same forces as F = [ks (L - L0) + kd (dv.u)] u.
    void portableSpringsMatchThePlainFormula() {
        const Inputs in = makeInputs();
        kernels::useKernels(kernels::KernelSet::Portable);
        for (std::size_t length : {std::size_t{3}, std::size_t{4}, std::size_t{7}}) {
            const Outcome r = call(in, Kernel::Springs, length);
            std::vector<double> expected = in.f4Start;
            double stretch2 = 0.0;
            for (std::size_t k = kBegin; k < kBegin + length; ++k) {
                const int a = in.springs.a[k], b = in.springs.b[k];
                double d[3], dv[3];
                for (int i = 0; i < 3; ++i) {
                    d[i] = in.x[3 * b + i] - in.x[3 * a + i];
                    dv[i] = in.v[3 * b + i] - in.v[3 * a + i];
                }
                const double length2 = d[0] * d[0] + d[1] * d[1] + d[2] * d[2];
                const double l = std::sqrt(length2);
                stretch2 += (l - in.springs.rest[k]) * (l - in.springs.rest[k]);
                if (l < kDegenerateLength) continue;
                const double closing = (dv[0] * d[0] + dv[1] * d[1] + dv[2] * d[2]) / l;
                const double magnitude = 30.0 * (l - in.springs.rest[k]) + 0.7 * closing;
                for (int i = 0; i < 3; ++i) {
                    expected[static_cast<std::size_t>(4 * a + i)] += magnitude * d[i] / l;
                    expected[static_cast<std::size_t>(4 * b + i)] -= magnitude * d[i] / l;
                }
            }
            for (std::size_t i = 0; i < expected.size(); ++i)
                QVERIFY2(std::abs(r.rows[i] - expected[i]) <= 1e-12 * (1.0 + std::abs(expected[i])),
                         qPrintable(QStringLiteral("row double %1, block length %2").arg(i).arg(length)));
            QVERIFY(std::abs(r.sums[1] - stretch2) <= 1e-12 * (1.0 + stretch2));
        }
    }
};

QTEST_APPLESS_MAIN(TestForceKernels)
#include "test_force_kernels.moc"
