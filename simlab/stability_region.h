#pragma once
// Stability regions in the complex h·lambda plane, for the GUI's stability map.
//
//   Im(hλ)                         A one-step method applied to y' = λ y advances y by R(hλ);
//     │   ╭──╮  boundary |R| = 1   it is stable at h when |R(hλ)| <= 1 for every eigenvalue λ
//     │  ╱ ·· ╲                    of the linearised body (first-order system, 2 per free
//   ──┼─┤ · ●  ├──── Re(hλ)        coordinate). The region {|R| <= 1} is drawn, the points hλ
//     │  ╲ ·· ╱                    on it; DT scales every point along its ray from 0.
//     │   ╰──╯
//
// What is drawn, per integrator (regionKind):
//   euler, midpoint, rk4, rk45 (fixed step), implicit-euler: R is a rational function
//     (integrators.h, stabilityFunction). The boundary {|R(z)| = 1} is the union over θ of the
//     roots of P(z) - e^{iθ} Q(z) = 0 (R = P/Q): traced exactly by polynomial roots (companion
//     matrix, Newton-polished) continued in θ, the root paths joined into closed curves by the
//     permutation the roots undergo over one turn. (By the maximum principle |R| has no local
//     maximum, so this level set is exactly the region's boundary.)
//   symplectic-euler, verlet: partitioned methods have no scalar R. On the oscillator
//     x'' + c x' + w^2 x = 0, whose eigenvalue pair is hλ, conj(hλ) (h w = |hλ|,
//     h c = -2 Re hλ), the step is a 2x2 matrix with trace T and determinant D; it is stable
//     iff |D| <= 1 and |T| <= 1 + D (Jury). Worked out (W = h^2 w^2, x = Re hλ):
//       symplectic Euler  T = 2 - W + 2x, D = 1 + 2x: the disc (x - 2)^2 + y^2 <= 8 cut by x <= 0
//                         (undamped: h w <= 2; critically damped, double root at -a: a <= 2 (sqrt 2 - 1))
//       velocity Verlet   (damping at the half-step velocity, as the integrator does)
//                         D = (1 + x)^2, T = 1 - W/2 + k^2 - W k/2 with k = 1 + x:
//                         -2 <= x <= 0 and W <= 4 (1 + k^2) / (1 + k) (undamped: h w <= 2;
//                         the strip reaches up the line x = -2, where both eigenvalues are 1)
//     The region is exact for a mode that decouples (proportional damping); on the real axis it
//     shows the critically damped mode (double root). The margin of these methods comes from
//     their exact step matrix (predictedStableStep), as the stability scan's prediction does.
//   cvode-bdf, cvode-adams: variable order and step, error-controlled: no fixed region.
//   xpbd: constraint projection (compliance 1/ks), unconditionally stable: no limit on DT.

#include <complex>
#include <string>
#include <vector>

#include "simlab/stability.h"

namespace simlab {

enum class RegionKind {
    StabilityFunction,  // |R(z)| <= 1, R rational: euler, midpoint, rk4, rk45, implicit-euler
    Oscillator,         // the 2x2 step matrix of an oscillator mode: symplectic-euler, verlet
    None,               // no fixed region: cvode-bdf, cvode-adams, xpbd
};
RegionKind regionKind(const std::string& integrator);

// Whether z = h·lambda lies in the region (|R| <= 1 + 1e-9; the oscillator's spectral radius
// likewise). False for RegionKind::None.
bool regionContains(const std::string& integrator, std::complex<double> z);
// The growth factor per step at z: |R(z)|, or the oscillator's spectral radius.
double regionAmplification(const std::string& integrator, std::complex<double> z);

// The boundary as closed (or, for unbounded pieces, clipped) polylines, each point on
// |R| = 1 to round-off. Pieces further than `extent` from 0 are clipped there.
std::vector<std::vector<std::complex<double>>> regionBoundary(const std::string& integrator, double extent = 8.0,
                                                              int samples = 1440);
// The largest a with [-a, 0] inside the region (inf when unbounded): euler 2, midpoint 2,
// rk4 2.785, rk45 ~3.3; symplectic-euler and verlet: the critically damped mode.
double realAxisLimit(const std::string& integrator);
// One sentence: what the picture shows for this integrator and what holds.
std::string regionNote(const std::string& integrator);
// The same in parts, for a window that says it in another language (the GUI's Stability map
// dock): which paragraph, and the numbers in it. regionNote writes its English from these.
struct RegionNoteParts {
    enum class Kind {
        TaylorPolynomial,  // euler, midpoint, rk4: |R| <= 1 for the Taylor polynomial of e^z
        DormandPrince,     // rk45, taken at a fixed step
        ImplicitEuler,     // the whole left half-plane (A-stable)
        SymplecticEuler,   // the oscillator's step matrix
        Verlet,            // the same, damping at the half-step velocity
        Composition,       // yoshida4, yoshida8: products of Verlet substeps
        CvodeBdf,          // no region: adaptive variable-order BDF
        CvodeAdams,        // no region: adaptive variable-order Adams
        Xpbd,              // no region: constraint projection, unconditionally stable
        Unknown,           // not an integrator this file knows
    };
    Kind kind = Kind::Unknown;
    // TaylorPolynomial: how far up the imaginary axis the region reaches (rk4: 2√2 ≈ 2.83;
    // 0: only at 0, so an undamped mode grows for every DT).
    double imaginaryReach = 0.0;
    // Composition: its Verlet substeps, force evaluations per step and the largest hω of a
    // stable undamped mode (yoshida4: 3, 4, 1.57).
    int substeps = 0, forceEvaluations = 0;
    double undampedLimit = 0.0;
};
RegionNoteParts regionNoteParts(const std::string& integrator);

// The points h·lambda of the linearised body at the step h, with how they were found.
struct SpectrumPoints {
    std::vector<std::complex<double>> lambda;  // eigenvalues [1/s] (upper and lower half plane)
    std::string method;                        // "exact", "modal", "iterative" (see spectrumMethodText)
    std::string methodText;                    // one line for the dock (spectrumMethodText)
    // The line in parts (the GUI says it in the window's language): the method and what it
    // counted: the eigenvalues (exact), the modes of M^-1 K (modal), the Ritz values (iterative,
    // with its Arnoldi steps and the body's free coordinates).
    enum class Method { Exact, Modal, Iterative };
    Method kind = Method::Exact;
    std::size_t count = 0;
    int arnoldiSteps = 0, freeCoordinates = 0;
};
// methodText from the parts: "exact spectrum: all 96 eigenvalues of ...".
std::string spectrumMethodText(const SpectrumPoints& points);
// exact: the first-order eigenvalues of linearModes; modal: lambda = -c/2 ± i sqrt(w^2 - c^2/4)
// from each mode of M^-1 K and its modal damping; iterative: Ritz values of the first-order
// system by Arnoldi on the Jacobian products (linearModes's large-body path), whose extreme
// (largest-modulus) eigenvalues are the ones that limit an explicit method.
SpectrumPoints spectrumPoints(const LinearModes& modes);

// The step margin: the largest factor s such that DT·s keeps the method stable on this body
// (s < 1: already unstable at DT), and the point that limits it.
struct StepMargin {
    double factor = 0.0;                   // s (inf: unlimited; 0: unstable for every DT)
    std::complex<double> limiting{0, 0};   // lambda of the limiting mode [1/s] (R methods)
    bool hasLimiting = false;              // R methods only (the oscillator methods' step matrix names no point)
    std::complex<double> fastest{0, 0};    // the fastest counted mode's lambda [1/s]
    std::string text;                      // "DT can grow 2.3× before ..." in words (stepMarginText)
    // The words in parts (the GUI says them in the window's language).
    enum class Case {
        OwnStep,     // cvode-bdf, cvode-adams: they choose their own internal steps
        Xpbd,        // stable at every DT: no margin to give
        Unlimited,   // every mode stays in the region for any DT (factor inf)
        NoStableDt,  // the limiting mode grows for every DT (factor 0)
        CanGrow,     // DT can grow by factor >= 1 before a mode leaves the region
        Outside,     // DT is already outside: shrink it by 1 / factor
    };
    Case kind = Case::NoStableDt;
    std::string integrator;
    double dt = 0.0;                 // the step judged [s]: the limit is factor·dt, the point dt·limiting
    bool oscillator = false;         // RegionKind::Oscillator: the step matrix's margin, no point named
    bool exactStepMatrix = false;    // oscillator: its basis, the exact step matrix (else per mode, modal damping)
    bool limitingIsFastest = false;  // the limiting point is the fastest counted mode
    // The limiting point h·lambda as the words give it: a real or imaginary part below round-off
    // (1e-9 of |lambda|; an undamped mode's -1.7e-16) is 0, so the sentence reads "0 ± 0.0849i".
    std::complex<double> limitingPoint() const;
    bool limitingIsReal() const;  // a pure decay (no imaginary part beyond round-off)
};
// text from the parts: "DT can grow 2.30× (to 0.0123 s) before the fastest mode (hλ = ...) ...".
std::string stepMarginText(const StepMargin& margin);
// R methods: the first exit of s·h·lambda from the region along each ray (scan, then
// bisection), the smallest over the body's points (rigid modes |lambda| ~ 0 and physically
// growing modes, Re lambda > 0, excluded, as predictedStableStep does): the same number as
// predictedStableStep / h on the exact or modal spectrum. Oscillator methods:
// predictedStableStep / h (their exact step matrix for small bodies, the modes otherwise).
StepMargin stepMargin(const std::string& integrator, const LinearModes& modes, const SpectrumPoints& points, double h);
// The first exit factor of s·z from the region along its ray, up to sMax (inf beyond).
double rayExit(const std::string& integrator, std::complex<double> z, double sMax = 1e6);

}  // namespace simlab
