// The scans beside the force kernels (simcore/scan_kernels.h) in every kernel set against the
// plain loops they replaced, on ranges starting at every offset and of every length up to 40
// (every remainder of the four-particle steps): the state scan gives the same energies and
// fastest speed bit for bit and the same extent and finiteness; the paired contact screen
// finds every particle beyond a wall and every pair beyond its plane wherever it sits in the
// range, and nothing outside it.
#include <QtTest>

#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <Eigen/Core>

#include "simcore/force_kernels.h"
#include "simcore/scan_kernels.h"

using namespace simcore;
namespace kernels = simcore::kernels;

namespace {

constexpr int kParticles = 64;
constexpr int kMaxLength = 40;
constexpr double kInf = std::numeric_limits<double>::infinity();

std::vector<kernels::KernelSet> availableSets() {
    std::vector<kernels::KernelSet> sets;
    for (kernels::KernelSet set : {kernels::KernelSet::Portable, kernels::KernelSet::Avx2, kernels::KernelSet::Avx512})
        if (set <= kernels::widestKernels()) sets.push_back(set);
    return sets;
}

QString setName(kernels::KernelSet set) { return QString::fromUtf8(kernels::kernelSetName(set)); }

bool sameBits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

struct State {
    std::vector<double> x, v, invMass3, mass;
    std::vector<bool> fixed;
};

// Random rows; every seventh particle fixed (no inverse mass), and from particle 40 on the z
// axis does not move (a coordinate left out of the extent while the particle is free).
State makeState() {
    std::mt19937_64 rng(27);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    State s;
    for (int i = 0; i < kParticles; ++i) {
        const bool fixed = i % 7 == 3;
        const double m = 0.5 + 0.25 * (unit(rng) + 1.0);
        s.mass.push_back(m);
        s.fixed.push_back(fixed);
        for (int axis = 0; axis < 3; ++axis) {
            s.x.push_back(3.0 * unit(rng));
            s.v.push_back(5.0 * unit(rng));
            s.invMass3.push_back(fixed || (axis == 2 && i >= 40) ? 0.0 : 1.0 / m);
        }
    }
    return s;
}

// The plain loop scanPiece ran before the kernels (its fixed flags, Eigen's squaredNorm).
kernels::StateScan plainScan(const State& s, bool weighs, double g, int begin, int end) {
    kernels::StateScan r;
    r.low = {kInf, kInf, kInf};
    r.high = {-kInf, -kInf, -kInf};
    double nonFinite = 0.0;
    for (int i = begin; i < end; ++i) {
        for (int axis = 0; axis < 3; ++axis) {
            const auto k = static_cast<std::size_t>(3 * i + axis), a = static_cast<std::size_t>(axis);
            nonFinite += (s.x[k] - s.x[k]) + (s.v[k] - s.v[k]);
            const bool moves = s.invMass3[k] != 0.0;
            r.low[a] = std::min(r.low[a], moves ? s.x[k] : kInf);
            r.high[a] = std::max(r.high[a], moves ? s.x[k] : -kInf);
        }
        const double speed2 = Eigen::Map<const Eigen::Vector3d>(s.v.data() + 3 * i).squaredNorm();
        r.fastest2 = std::max(r.fastest2, speed2);
        if (s.fixed[static_cast<std::size_t>(i)]) continue;
        const double m = s.mass[static_cast<std::size_t>(i)];
        r.kinetic += 0.5 * m * speed2;
        if (weighs) r.gravity += m * g * s.x[static_cast<std::size_t>(3 * i + 1)];
    }
    r.finite = nonFinite == 0.0;
    return r;
}

kernels::StateScan kernelScan(const State& s, bool weighs, double g, int begin, int end) {
    return kernels::scanState(s.x.data(), s.v.data(), s.invMass3.data(), s.mass.data(), weighs, g, begin, end);
}

// Two layers of kParticles, pair (i, i + kParticles); g4 padded (aligned, as the force model's
// buffer is). Every particle inside the walls [-2, 2]^3, every inner one inside its plane.
struct Pairs {
    std::vector<double> x;
    kernels::AlignedBuffer g4{4 * 2 * kParticles};
    std::array<double, 3> low{-2.0, -2.0, -2.0}, high{2.0, 2.0, 2.0};
};

Pairs makePairs() {
    std::mt19937_64 rng(38);
    std::uniform_real_distribution<double> unit(-1.0, 1.0);
    Pairs p;
    p.x.resize(3 * 2 * kParticles);
    for (int o = kParticles; o < 2 * kParticles; ++o) {
        double* g = p.g4.data() + 4 * o;
        double* xo = p.x.data() + 3 * o;
        double* xi = p.x.data() + 3 * (o - kParticles);
        for (int a = 0; a < 3; ++a) {
            g[a] = unit(rng);
            xo[a] = 1.5 * unit(rng);
        }
        g[3] = 0.0;
        const double length = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        // The inner partner 0.1 inside, along -g.
        for (int a = 0; a < 3; ++a) xi[a] = xo[a] - 0.1 * g[a] / length;
    }
    return p;
}

// The plain loop scanPairedRanges ran before the kernels.
kernels::PairScanBits plainPairs(const Pairs& p, int begin, int end) {
    double lo[3] = {p.low[0], p.low[1], p.low[2]}, hi[3] = {p.high[0], p.high[1], p.high[2]};
    int beyond = 0;
    for (int i = begin; i < end; ++i) {
        const double* xi = p.x.data() + 3 * i;
        const double* xo = p.x.data() + 3 * (i + kParticles);
        const double* g = p.g4.data() + 4 * (i + kParticles);
        for (int a = 0; a < 3; ++a) {
            lo[a] = std::min(lo[a], std::min(xi[a], xo[a]));
            hi[a] = std::max(hi[a], std::max(xi[a], xo[a]));
        }
        beyond |= (xi[0] - xo[0]) * g[0] + (xi[1] - xo[1]) * g[1] + (xi[2] - xo[2]) * g[2] > 0.0;
    }
    kernels::PairScanBits r;
    r.outsideWalls = lo[0] < p.low[0] || lo[1] < p.low[1] || lo[2] < p.low[2] || hi[0] > p.high[0] ||
                     hi[1] > p.high[1] || hi[2] > p.high[2];
    r.beyondPlane = beyond != 0;
    return r;
}

kernels::PairScanBits kernelPairs(const Pairs& p, int begin, int end) {
    return kernels::scanPairs(p.low, p.high, p.x.data(), p.g4.data(), begin, end, kParticles);
}

}  // namespace

class TestScanKernels : public QObject {
    Q_OBJECT

private slots:
    void cleanup() { kernels::useKernels(kernels::widestKernels()); }

    // The energies and the fastest speed bit for bit (the sums in particle order), the
    // extent and finiteness equal, with and without gravity, in every set.
    void stateScanIsThePlainLoop() {
        const State s = makeState();
        for (kernels::KernelSet set : availableSets()) {
            QCOMPARE(kernels::useKernels(set), set);
            for (bool weighs : {false, true})
                for (int begin = 0; begin < 4; ++begin)
                    for (int length = 0; length <= kMaxLength; ++length) {
                        const int end = begin + length;
                        const kernels::StateScan got = kernelScan(s, weighs, 9.81, begin, end);
                        const kernels::StateScan want = plainScan(s, weighs, 9.81, begin, end);
                        const QString where = QStringLiteral("%1 kernels, particles %2-%3, gravity %4")
                                                  .arg(setName(set)).arg(begin).arg(end).arg(weighs);
                        QVERIFY2(got.finite && want.finite, qPrintable(where));
                        QVERIFY2(sameBits(got.kinetic, want.kinetic), qPrintable(where));
                        QVERIFY2(sameBits(got.gravity, want.gravity), qPrintable(where));
                        QVERIFY2(sameBits(got.fastest2, want.fastest2), qPrintable(where));
                        // (== : the extent is compared with the walls, where -0 and +0 are one.)
                        QVERIFY2(got.low == want.low && got.high == want.high, qPrintable(where));
                    }
            // The scan sees something: a range with free particles has energy and extent.
            const kernels::StateScan all = kernelScan(s, true, 9.81, 0, kParticles);
            QVERIFY(all.kinetic > 0.0 && all.gravity != 0.0 && all.fastest2 > 0.0);
            QVERIFY(all.low[2] < all.high[2] && all.low[0] > -3.0 && all.high[0] < 3.0);
        }
    }

    // A NaN or an infinity in any coordinate of x or v, wherever it sits in the range, makes the
    // scan not finite; one just outside the range does not.
    void stateScanFindsEveryNonFiniteCoordinate() {
        const State clean = makeState();
        for (kernels::KernelSet set : availableSets()) {
            QCOMPARE(kernels::useKernels(set), set);
            for (int begin : {0, 1, 3})
                for (int length : {1, 3, 4, 5, 8, 13}) {
                    const int end = begin + length;
                    for (int at = begin - 1; at <= end; ++at) {
                        if (at < 0) continue;
                        for (int k = 0; k < 6; ++k) {
                            State s = clean;
                            std::vector<double>& rows = k < 3 ? s.x : s.v;
                            rows[static_cast<std::size_t>(3 * at + k % 3)] = k % 2 ? kInf : std::nan("");
                            const bool inside = at >= begin && at < end;
                            QVERIFY2(kernelScan(s, true, 9.81, begin, end).finite == !inside,
                                     qPrintable(QStringLiteral("%1 kernels, particles %2-%3, bad coordinate %4 of particle %5")
                                                    .arg(setName(set)).arg(begin).arg(end).arg(k).arg(at)));
                        }
                    }
                }
        }
    }

    // The screen with nothing to find says nothing; one particle beyond a wall (inner or outer,
    // each axis, each side) or one pair beyond its plane, at any place in the range, is found
    // (and only that one: the other flag stays off); outside the range it is not.
    void pairScanFindsEveryCrossing() {
        const Pairs clean = makePairs();
        for (kernels::KernelSet set : availableSets()) {
            QCOMPARE(kernels::useKernels(set), set);
            for (int begin = 0; begin < 4; ++begin)
                for (int length = 0; length <= 13; ++length) {
                    const int end = begin + length;
                    const kernels::PairScanBits none = kernelPairs(clean, begin, end);
                    QVERIFY(!none.outsideWalls && !none.beyondPlane);
                    for (int at = std::max(0, begin - 1); at <= end; ++at) {
                        const bool inside = at >= begin && at < end;
                        const QString where = QStringLiteral("%1 kernels, pairs %2-%3, pair %4")
                                                  .arg(setName(set)).arg(begin).arg(end).arg(at);
                        for (int layer = 0; layer < 2; ++layer)
                            for (int axis = 0; axis < 3; ++axis)
                                for (double wall : {-2.5, 2.5}) {
                                    Pairs p = clean;
                                    p.x[static_cast<std::size_t>(3 * (at + layer * kParticles) + axis)] = wall;
                                    const kernels::PairScanBits got = kernelPairs(p, begin, end);
                                    const kernels::PairScanBits want = plainPairs(p, begin, end);
                                    QVERIFY2(got.outsideWalls == inside && want.outsideWalls == inside,
                                             qPrintable(where + QStringLiteral(", layer %1 axis %2 at %3").arg(layer).arg(axis).arg(wall)));
                                    QCOMPARE(got.beyondPlane, want.beyondPlane);
                                }
                        // The inner partner 0.1 outside its plane instead of inside.
                        Pairs p = clean;
                        const double* g = p.g4.data() + 4 * (at + kParticles);
                        for (int a = 0; a < 3; ++a)
                            p.x[static_cast<std::size_t>(3 * at + a)] =
                                p.x[static_cast<std::size_t>(3 * (at + kParticles) + a)] + 0.05 * g[a];
                        const kernels::PairScanBits got = kernelPairs(p, begin, end);
                        QVERIFY2(got.beyondPlane == inside && !got.outsideWalls, qPrintable(where + QStringLiteral(", beyond its plane")));
                        QCOMPARE(plainPairs(p, begin, end).beyondPlane, inside);
                    }
                }
        }
    }
};

QTEST_APPLESS_MAIN(TestScanKernels)
#include "test_scan_kernels.moc"
