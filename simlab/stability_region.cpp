#include "simlab/stability_region.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <numbers>

#include <Eigen/Eigenvalues>

#include "simcore/integrator_table.h"
#include "simcore/integrators.h"

namespace simlab {

using simcore::hasStabilityFunction;
using simcore::stabilityFunction;

namespace {

using Complex = std::complex<double>;
using Curve = std::vector<Complex>;

// R = P / Q, coefficients in ascending powers of z: the methods' stability functions
// (integrators.cpp, stabilityFunction; the test checks that both agree on the traced boundary).
struct Rational {
    std::vector<double> p, q;
};

Rational rationalOf(const std::string& name) {
    if (name == "euler") return {{1.0, 1.0}, {1.0}};
    if (name == "midpoint") return {{1.0, 1.0, 0.5}, {1.0}};
    if (name == "rk4") return {{1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24}, {1.0}};
    // Dormand-Prince's 5th-order solution: b^T A^(k-1) 1 = 1/k! for k <= 5 and 1/600 for k = 6.
    if (name == "rk45") return {{1.0, 1.0, 1.0 / 2, 1.0 / 6, 1.0 / 24, 1.0 / 120, 1.0 / 600}, {1.0}};
    if (name == "implicit-euler") return {{1.0}, {1.0, -1.0}};
    return {};
}

// All roots of sum c_k z^k (c_d != 0): eigenvalues of the companion matrix, Newton-polished.
std::vector<Complex> polynomialRoots(const std::vector<Complex>& c) {
    const int d = int(c.size()) - 1;
    std::vector<Complex> roots;
    if (d < 1) return roots;
    if (d == 1) return {-c[0] / c[1]};
    Eigen::MatrixXcd companion = Eigen::MatrixXcd::Zero(d, d);
    for (int i = 1; i < d; ++i) companion(i, i - 1) = 1.0;
    for (int i = 0; i < d; ++i) companion(i, d - 1) = -c[std::size_t(i)] / c[std::size_t(d)];
    Eigen::ComplexEigenSolver<Eigen::MatrixXcd> eig(companion, false);
    for (int i = 0; i < d; ++i) {
        Complex z = eig.eigenvalues()[i];
        for (int it = 0; it < 3; ++it) {
            Complex f = 0.0, df = 0.0;
            for (int k = d; k >= 0; --k) {
                df = df * z + f;
                f = f * z + c[std::size_t(k)];
            }
            if (std::abs(df) == 0.0) break;
            z -= f / df;
        }
        roots.push_back(z);
    }
    return roots;
}

// |R(z)| = 1 as closed curves: the roots of P(z) - e^{iθ} Q(z), continued in θ over one turn.
std::vector<Curve> rationalBoundary(const Rational& r, int samples) {
    const std::size_t d = std::max(r.p.size(), r.q.size()) - 1;
    auto rootsAt = [&](double theta) {
        const Complex e = std::polar(1.0, theta);
        std::vector<Complex> c(d + 1, 0.0);
        for (std::size_t k = 0; k <= d; ++k) {
            if (k < r.p.size()) c[k] += r.p[k];
            if (k < r.q.size()) c[k] -= e * r.q[k];
        }
        while (c.size() > 1 && std::abs(c.back()) < 1e-300) c.pop_back();
        return polynomialRoots(c);
    };
    std::vector<Complex> start = rootsAt(0.0);
    const std::size_t n = start.size();
    std::vector<Curve> tracks(n);
    for (std::size_t k = 0; k < n; ++k) tracks[k].push_back(start[k]);
    for (int j = 1; j <= samples; ++j) {
        std::vector<Complex> next = rootsAt(2.0 * std::numbers::pi * j / samples);
        // Each track takes the nearest root not yet taken (the steps are fine enough that
        // roots move far less than they are apart, except where two meet: R' = 0 on |R| = 1).
        std::vector<bool> taken(next.size(), false);
        for (std::size_t k = 0; k < n; ++k) {
            std::size_t best = 0;
            double bestDistance = std::numeric_limits<double>::infinity();
            for (std::size_t i = 0; i < next.size(); ++i)
                if (!taken[i] && std::abs(next[i] - tracks[k].back()) < bestDistance) {
                    bestDistance = std::abs(next[i] - tracks[k].back());
                    best = i;
                }
            taken[best] = true;
            tracks[k].push_back(next[best]);
        }
    }
    // After one turn the roots are the start's, permuted: follow the cycles into closed curves.
    std::vector<std::size_t> successor(n);
    for (std::size_t k = 0; k < n; ++k) {
        std::size_t best = 0;
        for (std::size_t i = 1; i < n; ++i)
            if (std::abs(start[i] - tracks[k].back()) < std::abs(start[best] - tracks[k].back())) best = i;
        successor[k] = best;
    }
    std::vector<bool> used(n, false);
    std::vector<Curve> curves;
    for (std::size_t k = 0; k < n; ++k) {
        if (used[k]) continue;
        Curve curve;
        for (std::size_t t = k; !used[t]; t = successor[t]) {
            used[t] = true;
            curve.insert(curve.end(), tracks[t].begin() + (curve.empty() ? 0 : 1), tracks[t].end());
        }
        curves.push_back(std::move(curve));
    }
    return curves;
}

// A curve y(x) >= 0 of the oscillator methods, mirrored: (x, y(x)) up, then (x, -y(x)) back.
Curve mirroredCurve(double x0, double x1, int samples, const std::function<double(double)>& y, double extent) {
    Curve upper;
    for (int i = 0; i <= samples; ++i) {
        const double x = x0 + (x1 - x0) * i / samples;
        const double v = y(x);
        if (!(v >= 0.0) || v > extent) continue;
        upper.emplace_back(x, v);
    }
    Curve curve = upper;
    for (auto it = upper.rbegin(); it != upper.rend(); ++it) curve.emplace_back(it->real(), -it->imag());
    return curve;
}

}  // namespace

// The compositions of Verlet have no closed-form boundary: along each ray from 0 at angle
// phi in [0, pi] (upper half plane, mirrored), the first exit from the region (rayExit), a
// star-shaped curve: what DT scaling, which moves every point along its ray, can reach.
// Rays that never leave within `extent` are clipped there.
static std::vector<Curve> rayBoundary(const std::string& integrator, double extent, int samples) {
    Curve upper;
    const int rays = std::max(90, samples / 4);
    for (int i = 0; i <= rays; ++i) {
        // phi from pi/2 (the imaginary axis) to pi (the negative real axis); the right half
        // plane (growing modes) lies outside for every method drawn this way.
        const double phi = std::numbers::pi * (0.5 + 0.5 * i / rays);
        const Complex dir = std::polar(1.0, phi);
        const double s = std::min(rayExit(integrator, dir, extent), extent);
        upper.push_back(s * dir);
    }
    Curve curve;
    for (auto it = upper.rbegin(); it != upper.rend(); ++it) curve.emplace_back(it->real(), -it->imag());
    curve.insert(curve.end(), upper.begin() + 1, upper.end());
    curve.push_back(Complex(0.0, upper.front().imag()));
    curve.insert(curve.begin(), Complex(0.0, -upper.front().imag()));
    return {curve};
}

RegionKind regionKind(const std::string& integrator) {
    if (hasStabilityFunction(integrator)) return RegionKind::StabilityFunction;
    if (isPartitioned(integrator)) return RegionKind::Oscillator;
    return RegionKind::None;
}

double regionAmplification(const std::string& integrator, Complex z) {
    switch (regionKind(integrator)) {
        case RegionKind::StabilityFunction: return std::abs(stabilityFunction(integrator, z));
        // The oscillator whose eigenvalue pair is z, conj(z), at h = 1: w = |z|, c = -2 Re z.
        case RegionKind::Oscillator: return modeAmplification(integrator, 1.0, std::abs(z), -2.0 * z.real());
        case RegionKind::None: break;
    }
    return std::numeric_limits<double>::quiet_NaN();
}

bool regionContains(const std::string& integrator, Complex z) {
    const double a = regionAmplification(integrator, z);
    return a <= 1.0 + 1e-9;
}

std::vector<Curve> regionBoundary(const std::string& integrator, double extent, int samples) {
    std::vector<Curve> curves;
    const double sqrt2 = std::numbers::sqrt2;
    switch (regionKind(integrator)) {
        case RegionKind::StabilityFunction: return rationalBoundary(rationalOf(integrator), samples);
        case RegionKind::Oscillator:
            if (integrator == "symplectic-euler") {
                // The arc of (x - 2)^2 + y^2 = 8 left of the imaginary axis (eigenvalue -1), closed
                // by the axis from 2i to -2i (|eigenvalues| = D = 1: undamped, neutral).
                Curve arc = mirroredCurve(0.0, 2.0 - 2.0 * sqrt2, samples / 2,
                                          [](double x) { return std::sqrt(std::max(0.0, 8.0 - (x - 2.0) * (x - 2.0))); },
                                          extent);
                arc.push_back(arc.front());
                curves.push_back(std::move(arc));
            } else if (integrator != "verlet") {
                curves = rayBoundary(integrator, extent, samples);
            } else {
                // W = 4 (1 + k^2) / (1 + k) (eigenvalue -1), k = 1 + x, from the axis at 2i to the
                // line x = -2 (D = k^2 = 1), which the curve approaches from the right.
                auto y = [](double x) {
                    const double k = 1.0 + x;
                    return std::sqrt(std::max(0.0, 4.0 * (1.0 + k * k) / (1.0 + k) - x * x));
                };
                // Sampled densely near x = -2, where the curve climbs to the extent.
                Curve upper;
                for (int i = 0; i <= samples; ++i) {
                    const double u = double(i) / samples;
                    const double x = -2.0 + 2.0 * u * u * u;
                    if (x <= -2.0) continue;
                    const double v = y(x);
                    if (v <= extent) upper.emplace_back(x, v);
                }
                std::reverse(upper.begin(), upper.end());  // from (0, 2) leftwards
                // The neutral pieces: the axis from -2i to 2i and the line x = -2.
                curves.push_back({Complex(0.0, -2.0), Complex(0.0, 2.0)});
                Curve top = upper, bottom;
                for (const Complex& z : upper) bottom.emplace_back(z.real(), -z.imag());
                curves.push_back(std::move(top));
                curves.push_back(std::move(bottom));
                curves.push_back({Complex(-2.0, -extent), Complex(-2.0, extent)});
            }
            return curves;
        case RegionKind::None: break;
    }
    return curves;
}

double realAxisLimit(const std::string& integrator) {
    if (regionKind(integrator) == RegionKind::None) return std::numeric_limits<double>::quiet_NaN();
    return rayExit(integrator, Complex(-1.0, 0.0), 1e6);
}

double rayExit(const std::string& integrator, Complex z, double sMax) {
    const double r = std::abs(z);
    if (r == 0.0) return std::numeric_limits<double>::infinity();
    double s = 1e-6 / r;
    if (!regionContains(integrator, s * z)) return 0.0;
    double lo = s;
    while (s < sMax && regionContains(integrator, s * z)) lo = s, s *= 1.02;
    if (s >= sMax && regionContains(integrator, sMax * z)) return std::numeric_limits<double>::infinity();
    double hi = std::min(s, sMax);
    for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        (regionContains(integrator, mid * z) ? lo : hi) = mid;
    }
    return lo;
}

RegionNoteParts regionNoteParts(const std::string& integrator) {
    using Kind = RegionNoteParts::Kind;
    RegionNoteParts parts;
    if (integrator == "euler" || integrator == "midpoint" || integrator == "rk4") {
        parts.kind = Kind::TaylorPolynomial;
        parts.imaginaryReach = integrator == "rk4" ? 2.0 * std::numbers::sqrt2 : 0.0;
    } else if (integrator == "rk45") {
        parts.kind = Kind::DormandPrince;
    } else if (integrator == "implicit-euler") {
        parts.kind = Kind::ImplicitEuler;
    } else if (integrator == "symplectic-euler") {
        parts.kind = Kind::SymplecticEuler;
    } else if (integrator == "verlet") {
        parts.kind = Kind::Verlet;
    } else if (integrator == "yoshida4" || integrator == "yoshida8") {
        parts.kind = Kind::Composition;
        parts.substeps = integrator == "yoshida4" ? 3 : 15;
        parts.forceEvaluations = parts.substeps + 1;
        parts.undampedLimit = rayExit(integrator, Complex(0.0, 1.0), 100.0);
    } else if (integrator == "cvode-bdf") {
        parts.kind = Kind::CvodeBdf;
    } else if (integrator == "cvode-adams") {
        parts.kind = Kind::CvodeAdams;
    } else if (integrator == "xpbd") {
        parts.kind = Kind::Xpbd;
    }
    return parts;
}

std::string regionNote(const std::string& integrator) {
    using Kind = RegionNoteParts::Kind;
    const RegionNoteParts parts = regionNoteParts(integrator);
    char text[600];
    switch (parts.kind) {
        case Kind::TaylorPolynomial:
            if (parts.imaginaryReach > 0.0)
                std::snprintf(text, sizeof text,
                              "Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of e^z); it "
                              "touches the imaginary axis up to ±%.3gi: undamped modes are stable up to hω = 2√2.",
                              parts.imaginaryReach);
            else
                std::snprintf(text, sizeof text,
                              "Region: |R(hλ)| ≤ 1 for its stability polynomial R (the Taylor polynomial of e^z); it "
                              "touches the imaginary axis only at 0: an undamped mode grows for every DT.");
            return text;
        case Kind::DormandPrince:
            return "Region: |R(hλ)| ≤ 1 for Dormand–Prince's 5th-order solution, R = Taylor to z⁵ + z⁶/600, taken at a "
                   "fixed step. The adaptive run picks its own step from the error tolerance: it does not blow up, it "
                   "takes smaller steps.";
        case Kind::ImplicitEuler:
            return "Region: |1/(1 − hλ)| ≤ 1, everything outside the disc |1 − hλ| < 1, the whole left half-plane "
                   "(A-stable): no DT limit from stability.";
        case Kind::SymplecticEuler:
            return "Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄ (exact when the "
                   "modes decouple; the real axis shows the critically damped mode). Undamped modes: hω ≤ 2. The margin "
                   "uses the step matrix, not the picture.";
        case Kind::Verlet:
            return "Region: no scalar R; drawn for an oscillator mode whose eigenvalue pair is hλ, hλ̄, damping at the "
                   "half-step velocity (exact when the modes decouple; the real axis shows the critically damped mode). "
                   "Undamped modes: hω ≤ 2. The margin uses the step matrix, not the picture.";
        case Kind::Composition:
            std::snprintf(text, sizeof text,
                          "Region: no scalar R; the step is a product of %d Verlet substeps (some backwards), drawn for an "
                          "oscillator mode whose eigenvalue pair is hλ, hλ̄ (damping at the half-kick velocity, as the "
                          "integrator does), traced ray by ray from 0. Undamped modes: hω ≤ %.3g (a step costs %d force "
                          "evaluations). The margin uses the step matrix, not the picture.",
                          parts.substeps, parts.undampedLimit, parts.forceEvaluations);
            return text;
        case Kind::CvodeBdf:
            return "No region: adaptive variable-order BDF (orders 1–5): error-controlled, no fixed region. BDF1–2 are "
                   "A-stable, BDF3–5 A(α)-stable down to α ≈ 51°; CVODE shrinks the step or the order when a mode "
                   "threatens: no DT limit, DT is only the output interval.";
        case Kind::CvodeAdams:
            return "No region: adaptive variable-order Adams (orders 1–12): error-controlled, no fixed region. Its regions "
                   "are small (explicit-like); CVODE keeps the internal step inside them by its error test: no DT limit, "
                   "stiff bodies only cost steps.";
        case Kind::Xpbd:
            return "No region: XPBD projects the springs as compliant constraints (compliance 1/ks): unconditionally "
                   "stable, no region in the hλ plane; large DT costs accuracy (the body turns soft), not stability.";
        case Kind::Unknown: break;
    }
    return "No stability region for " + integrator + ".";
}

std::string spectrumMethodText(const SpectrumPoints& points) {
    const std::string count = std::to_string(points.count);
    switch (points.kind) {
        case SpectrumPoints::Method::Exact:
            return "exact spectrum: all " + count + " eigenvalues of the linearised first-order system (dense eigen-solve)";
        case SpectrumPoints::Method::Modal:
            return "modal: all " + count +
                   " modes of M⁻¹K (symmetric eigen-solve), damping c = φᵀ(M⁻¹D)φ per mode; λ = −c/2 ± i√(ω² − c²/4)";
        case SpectrumPoints::Method::Iterative: break;
    }
    return "iterative: " + count + " Ritz values of the first-order system, Arnoldi (" +
           std::to_string(points.arnoldiSteps) + " steps) on the Jacobian products, " +
           std::to_string(points.freeCoordinates) +
           " free coordinates: the extreme eigenvalues (largest |λ|) are accurate, inner ones are not";
}

SpectrumPoints spectrumPoints(const LinearModes& modes) {
    SpectrumPoints points;
    if (!modes.eigenvalues.empty()) {
        points.lambda = modes.eigenvalues;
        points.method = "exact";
        points.kind = SpectrumPoints::Method::Exact;
        points.count = modes.eigenvalues.size();
        points.methodText = spectrumMethodText(points);
        return points;
    }
    for (std::size_t i = 0; i < modes.omega2.size(); ++i) {
        // lambda^2 + c lambda + w^2 = 0
        const Complex disc = std::sqrt(Complex(modes.damping[i] * modes.damping[i] / 4.0 - modes.omega2[i], 0.0));
        points.lambda.push_back(-modes.damping[i] / 2.0 + disc);
        points.lambda.push_back(-modes.damping[i] / 2.0 - disc);
    }
    if (modes.dense) {
        points.method = "modal";
        points.kind = SpectrumPoints::Method::Modal;
        points.count = modes.omega2.size();
    } else {
        points.method = "iterative";
        points.kind = SpectrumPoints::Method::Iterative;
        points.lambda = modes.ritzValues;
        points.count = modes.ritzValues.size();
        points.arnoldiSteps = modes.arnoldiSteps;
        points.freeCoordinates = modes.freeCoordinates;
    }
    points.methodText = spectrumMethodText(points);
    return points;
}

bool StepMargin::limitingIsReal() const { return std::abs(limiting.imag()) <= 1e-9 * std::abs(limiting); }

Complex StepMargin::limitingPoint() const {
    const double tiny = 1e-9 * std::abs(limiting);
    return dt * Complex(std::abs(limiting.real()) <= tiny ? 0.0 : limiting.real(), limitingIsReal() ? 0.0 : limiting.imag());
}

std::string stepMarginText(const StepMargin& margin) {
    using Case = StepMargin::Case;
    char text[400], mode[160] = "";
    const double limit = margin.factor * margin.dt;
    // predictedStableStep's basis for the oscillator methods: the exact step matrix up to
    // kExactStepLimit free coordinates, else each mode with its modal damping.
    const char* basis = margin.exactStepMatrix ? "exact step matrix" : "per mode, modal damping";
    const char* which = margin.limitingIsFastest ? "the fastest mode" : "the mode";
    const Complex z = margin.limitingPoint();
    if (margin.hasLimiting && margin.limitingIsReal())
        std::snprintf(mode, sizeof mode, "%s (hλ = %.3g, a pure decay)", which, z.real());
    else if (margin.hasLimiting)
        std::snprintf(mode, sizeof mode, "%s (hλ = %.3g ± %.3gi)", which, z.real(), std::abs(z.imag()));
    else
        std::snprintf(mode, sizeof mode, "the fastest mode");
    switch (margin.kind) {
        case Case::Xpbd: return "xpbd is stable at every DT: no margin to give.";
        case Case::OwnStep: return margin.integrator + " chooses its own internal steps: no DT limit from stability.";
        case Case::Unlimited: return "No DT limit: every mode of this body stays in the region for any DT.";
        case Case::NoStableDt:
            if (margin.oscillator)
                std::snprintf(text, sizeof text, "No DT is stable: a mode pair grows for every DT (%s).", basis);
            else
                std::snprintf(text, sizeof text,
                              "No DT is stable: %s sits where the region only touches the imaginary axis at 0; it grows "
                              "for every DT (slowly when DT is small).",
                              mode);
            return text;
        case Case::CanGrow:
            if (margin.oscillator)
                std::snprintf(text, sizeof text,
                              "DT can grow %.2f× (to %.3g s) before a mode pair goes unstable (%s); the picture is exact "
                              "for underdamped modes only.",
                              margin.factor, limit, basis);
            else
                std::snprintf(text, sizeof text, "DT can grow %.2f× (to %.3g s) before %s leaves the region.",
                              margin.factor, limit, mode);
            return text;
        case Case::Outside:
            if (margin.oscillator)
                std::snprintf(text, sizeof text, "DT is already outside the stable range (%s): shrink DT by %.2f× (to %.3g s).",
                              basis, 1.0 / margin.factor, limit);
            else
                std::snprintf(text, sizeof text,
                              "DT is already outside: %s is out of the region; shrink DT by %.2f× (to %.3g s) to bring it "
                              "back.",
                              mode, 1.0 / margin.factor, limit);
            return text;
    }
    return {};
}

StepMargin stepMargin(const std::string& integrator, const LinearModes& modes, const SpectrumPoints& points, double h) {
    StepMargin margin;
    margin.integrator = integrator;
    margin.dt = h;
    if (regionKind(integrator) == RegionKind::None) {
        margin.factor = std::numeric_limits<double>::infinity();
        margin.kind = integrator == "xpbd" ? StepMargin::Case::Xpbd : StepMargin::Case::OwnStep;
        margin.text = stepMarginText(margin);
        return margin;
    }
    // The limiting point: the first to leave along its ray (rigid and growing modes left out).
    double scale = 0.0;
    for (const Complex& l : points.lambda) scale = std::max(scale, std::abs(l));
    double fastest = 0.0;
    double smallest = std::numeric_limits<double>::infinity();
    margin.oscillator = regionKind(integrator) == RegionKind::Oscillator;
    for (const Complex& l : points.lambda) {
        if (!(std::abs(l) > 1e-6 * scale) || l.real() > 1e-9 * scale) continue;
        if (std::abs(l) > fastest) {
            fastest = std::abs(l);
            margin.fastest = l;
        }
        // Oscillator methods: the picture is exact only for underdamped modes that decouple;
        // their margin comes from the step matrix, which names no single point.
        if (margin.oscillator) continue;
        const double s = rayExit(integrator, h * l);
        if (s < smallest || (s == smallest && std::abs(l) > std::abs(margin.limiting))) {
            smallest = s;
            margin.limiting = l;
            margin.hasLimiting = true;
        }
    }
    // The factor: the one verdict (stabilityVerdict: predictedStableStep on the exact or
    // Arnoldi spectrum, the exact step matrix for small bodies' partitioned methods), so the
    // map says what the banners and `stability` say; the rays above only name the point
    // that leaves first.
    margin.factor = stabilityVerdict(modes, integrator, h).limit / h;
    margin.limitingIsFastest = margin.hasLimiting && std::abs(std::abs(margin.limiting) - fastest) <= 1e-9 * fastest;
    margin.exactStepMatrix = modes.stiffness.rows() > 0 && modes.unstableModes == 0;
    using Case = StepMargin::Case;
    margin.kind = std::isinf(margin.factor) ? Case::Unlimited
                  : margin.factor <= 0.0    ? Case::NoStableDt
                  : margin.factor >= 1.0    ? Case::CanGrow
                                            : Case::Outside;
    margin.text = stepMarginText(margin);
    return margin;
}

}  // namespace simlab
