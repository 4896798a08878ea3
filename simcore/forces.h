#pragma once
// Force terms (thesis ch. 4, docs/model.md "Forces"), each a separate kernel over flat arrays.
//
// Positions, velocities and forces are flat arrays of 3N doubles (x0 y0 z0 x1 ...). A scene
// declares the terms it has (TermSet); a term it does not have is never evaluated, and the
// evaluation counters prove it. The kernels are free functions: testable without a world.

#include <array>
#include <cstdint>
#include <vector>

#include <Eigen/Core>

#include "simcore/body.h"
#include "simcore/contact.h"
#include "simcore/force_kernels.h"
#include "simcore/parallel.h"

namespace simcore {

enum class Term : int { Gravity, Springs, Gas, Pointer, Collisions, LayerConstraint, Count };
inline constexpr int kTermCount = static_cast<int>(Term::Count);
std::string_view termName(Term term);

struct TermSet {
    std::array<bool, kTermCount> on{};
    bool has(Term t) const { return on[static_cast<std::size_t>(t)]; }
    void set(Term t, bool value) { on[static_cast<std::size_t>(t)] = value; }
};

// The tunables the force terms read, resolved from the parameter table.
// Naming: `ks`/`kd` (and `rks`/`rkd`) are only the table's keys, the structural (and radius and
// shear) springs' values as the user types them (Params::Forces). What a body's springs use,
// per family and scaled to its resolution, is `stiffness`/`damping` [structural, radius, shear].
struct ForceParams {
    std::array<double, kSpringFamilyCount> stiffness{};  // per spring family, scaled [N/m]
    std::array<double, kSpringFamilyCount> damping{};    // per spring family, scaled [N*s/m]
    double gravity = 9.81;                        // |g| [m/s^2], acting along -y
    std::array<double, 2> gasConstant{};          // nRT of the gas in [inner, outer] [J]
    double mks = 150.0;                           // mouse spring stiffness [N/m]
    double mkd = 25.0;                            // mouse spring damping [N*s/m]
    double mouseRest = 0.0;                       // mouse spring rest length [m]
};

// The mouse spring: anchor r_m held by the pointer, attached to one particle.
struct PointerSpring {
    bool active = false;
    int particle = -1;
    Eigen::Vector3d anchor = Eigen::Vector3d::Zero();
};

// Per-evaluation by-products of the forces.
struct ForceExtras {
    std::array<double, 2> volume{};    // enclosed volume of [inner, outer] layer
    std::array<double, 2> pressure{};  // P = c / V
    double dampingPower = 0.0;         // power removed by spring and mouse damping [W], >= 0
    std::array<double, kSpringFamilyCount> springEnergy{};  // elastic energy per family [J]
    int degenerateSprings = 0;         // springs shorter than kDegenerateLength
    double contactEnergy = 0.0;        // wall contact + layer barrier energy [J] (contact = force)
    double contactPower = 0.0;         // power removed by contact dissipation and friction [W], >= 0
};

// One particle's force split by where it comes from (a free-body diagram): the force terms,
// with the springs per family, the gas per layer and contact per kind.
enum class ForcePart : int {
    Gravity,
    Structural,  // springs of each family (SpringFamily order)
    Radius,
    Shear,
    GasInner,    // the gas of the inner layer (acts on inner particles only)
    GasOuter,    // ... of the outer layer
    Walls,       // wall contact (contact = force)
    Barrier,     // the layer barrier (contact = force)
    Mouse,       // the mouse spring
    BodyContact, // a world's: contact from the other bodies (contact_pairs.h)
    SelfContact, // a world's: the body's outer layer against its own non-adjacent elements
    Count
};
inline constexpr int kForcePartCount = static_cast<int>(ForcePart::Count);
std::string_view forcePartName(ForcePart part);  // "gravity", "structural springs", ...

struct ForceBreakdown {
    int particle = -1;
    std::array<Eigen::Vector3d, kForcePartCount> part{};  // force of each part on the particle [N]
    std::array<bool, kForcePartCount> present{};          // the body has this part (else it is 0)
    Eigen::Vector3d total = Eigen::Vector3d::Zero();      // the force of a full evaluation [N]
    Eigen::Vector3d& operator[](ForcePart p) { return part[static_cast<std::size_t>(p)]; }
    const Eigen::Vector3d& operator[](ForcePart p) const { return part[static_cast<std::size_t>(p)]; }
    bool has(ForcePart p) const { return present[static_cast<std::size_t>(p)]; }
};

// Kernels. Each adds into f (3N). x, v are 3N.
void addGravity(const Eigen::VectorXd& mass, double g, double* f);
// Returns the damping power of the family.
double addSprings(const SpringSet& springs, double stiffness, double damping, const double* x, const double* v,
                  double* f, int& degenerate);
// Gas of one closed layer with nRT = c. Returns the volume V; force P * dV/dx.
double addGas(const Surface& surface, int dimension, double c, const double* x, double* f);
// The mouse spring's force on its particle into force[0..2] and its damping power; false
// (nothing written) when it does not act (inactive, or the particle on the anchor).
bool pointerForce(const PointerSpring& pointer, double mks, double mkd, double rest,
                  const double* x, const double* v, double* force, double& power);
double addPointer(const PointerSpring& pointer, double mks, double mkd, double rest,
                  const double* x, const double* v, double* f);

// Energies of the conservative parts, per family.
double springEnergy(const SpringSet& springs, double stiffness, const double* x);
double gasEnergy(double c, double volume);  // -c ln V
double pointerEnergy(const PointerSpring& pointer, double mks, double rest, const double* x);

// Index into the [inner, outer] arrays for a surface's layer.
inline int layerSlot(Layer layer) { return layer == Layer::Inner ? 0 : 1; }

double partialVolume(const Surface& surface, int dimension, const double* x, std::size_t begin,
                     std::size_t end);  // sum of x_a.(x_b x x_c) (3D) or shoelace terms (2D)

class ThreadPool;

// Evaluates every declared term and counts evaluations.
//
// Large bodies are split into fixed pieces by particle ownership (chunksFor: two, or kChunks
// for the largest); each chunk writes only its own particles' forces, and the few springs and
// faces joining two chunks are added afterwards in a fixed order. The split does not depend on
// the number of threads, so results are bit-identical whether a pool of 1 or 2 threads runs
// the chunks. More chunks than threads let a thread that is free take the next chunk when the
// other was preempted or runs slow.
class ForceModel {
public:
    static constexpr int kChunks = 4;
    // Bodies with fewer springs than this run as one chunk (threads would cost more than win).
    static constexpr std::size_t kChunkThreshold = 8192;
    // Bodies with at least this many springs (level 6 and up: 212,994 at level 6; level 5 has
    // 53,250) run as kChunks chunks, the others from kChunkThreshold as two. Four chunks at
    // level 6 share 7,210 elements (of ~280,000) where two share 3,408; eight shared 11,568 and
    // ran two threads at 333 steps/s against four chunks' 555 (stop 40, docs/performance.md).
    static constexpr std::size_t kFineThreshold = 100000;
    // The chunks of a body with `springs` springs.
    static int chunksFor(std::size_t springs) { return springs >= kFineThreshold ? kChunks : springs >= kChunkThreshold ? 2 : 1; }
    // Particles per block of the last stage (unpadding, xdot = v and the caller's `then`).
    static constexpr int kStageBlock = 256;

    ForceModel() = default;
    ForceModel(const Topology* topology, const Eigen::VectorXd* mass, TermSet terms);

    ForceParams params;
    ContactParams contact;  // read when the walls or the layer barrier are forces
    PointerSpring pointer;

    // The layer barrier's pairs and normals' rest lengths from the rest shape (3N), and which
    // particles are fixed (no contact force on them). Called once the body is built.
    void prepareContact(const double* restPositions, const std::vector<bool>& fixed);
    // Whether contact is part of the force evaluation (contact = force): walls, barrier.
    bool contactWalls() const { return contact.walls && m_terms.has(Term::Collisions); }
    bool contactBarrier() const {
        return contact.layerBarrier && m_terms.has(Term::LayerConstraint) && m_terms.has(Term::Gas);
    }
    // Contact energy at x by its own pass (walls and barrier) [J].
    double contactEnergy(const double* x);
    // Every layer-barrier pair, with its fan (for the Jacobians and the checks).
    const LayerBarrierSet& barrierPairs() const { return m_barrierAll; }

    const TermSet& terms() const { return m_terms; }
    // The pool that runs the chunks (nullptr: the calling thread runs them all).
    void setPool(ThreadPool* pool) { m_pool = pool; }
    ThreadPool* pool() const { return m_pool; }
    int chunks() const { return m_chunks; }
    // Springs and faces evaluated after the chunks because they join particles of two chunks.
    std::size_t sharedElements() const;
    // Edge quads over all parts (each holds four springs).
    std::size_t quadCount() const;
    // Parts whose radius springs form a run (kernels::springRunBlock).
    int radiusRuns() const;

    // Computes f = F(x, v) (3N). Overwrites f. With count = false the evaluation is not
    // counted (a display asking for the current forces is not part of the run's cost).
    void evaluate(const double* x, const double* v, double* f, ForceExtras& extras, bool count = true);
    // The same forces as the right-hand side of the equations of motion: xdot = v and
    // a = F * invMass3 (3N each, 0 where invMass3 is 0), written by the chunks in parallel.
    // With `then`, each chunk calls then(begin, length) on its ranges of the combined vector
    // [xdot | a] (xdot at 0, a at 3N) as soon as they are written; no element of x or v is
    // read after its range is handed over, so `then` may overwrite them. With xdot nullptr,
    // `then` runs on a's ranges only, each handing over x's and v's of the same particles.
    void evaluateMotion(const double* x, const double* v, const double* invMass3, double* xdot,
                        double* a, ForceExtras& extras, bool count = true, const RangeWork* then = nullptr);
    // The same with its last stage held back: extras are final, xdot and a are written by
    // finishMotion(then), on the ranges of that call's pool run (so that the caller's next pass
    // over them shares the run), or before anything else uses the force buffers (any other
    // evaluation), whichever comes first; v and invMass3 must then still be there.
    // dropMotion() forgets it (the caller's buffers are about to change or go away).
    // `beside`, when given, is called with each chunk's index at the end of that chunk's task
    // in the first pool run (work that only reads: the step's scan).
    void evaluateMotionDeferred(const double* x, const double* v, const double* invMass3, double* xdot, double* a,
                                ForceExtras& extras, bool count = true, const TaskRef* beside = nullptr);
    // Writes the held-back xdot and a (with `then` on their ranges, as evaluateMotion's);
    // false when nothing is held back. Without xdot, a alone (as evaluateMotion's with xdot
    // nullptr).
    bool finishMotion(const RangeWork* then = nullptr, bool xdot = true);
    void dropMotion() { m_pending.held = false; }
    // One particle's force split by part (ForcePart), for a free-body diagram. Every part is a
    // whole evaluation by evaluate() with only that part switched on (the other terms off, the
    // other spring families' stiffness and damping and the other layer's nRT set to 0, restored after), so
    // the parts come from the very code the step runs; total is the evaluation with all of
    // them. The parts add up to the total up to rounding. f: scratch of 3N. Not counted.
    void breakdown(int particle, const double* x, const double* v, double* f, ForceBreakdown& out);
    // The same forces by the plain one-pass kernels (the reference the fast path is tested on).
    void evaluateReference(const double* x, const double* v, double* f, ForceExtras& extras);
    // dV/dx of each particle's own layer, unscaled, padded (4 doubles per particle): as left by
    // the last evaluation (valid until the next one), or computed alone at x by the gas part
    // of an evaluation, in its order (the same bits). nullptr when the body has no gas.
    kernels::PaddedRows volumeGradient() const {
        return kernels::PaddedRows(m_terms.has(Term::Gas) ? m_gradient4.data() : nullptr);
    }
    kernels::PaddedRows computeVolumeGradient(const double* x);
    // Elastic energy per spring family and enclosed volume per surface, chunked like forces.
    std::array<double, kSpringFamilyCount> springEnergies(const double* x);
    std::array<double, 2> volumes(const double* x);  // [inner, outer]; 0 where absent

    // Counts an evaluation whose result was kept from an uncounted one at the same state.
    void countReusedEvaluation() { countTerms(); }
    // Counts one evaluation of a post-step term (collisions, layer constraint).
    void countPostStep(Term term) { ++m_evaluations[static_cast<std::size_t>(term)]; }
    std::uint64_t evaluations(Term term) const { return m_evaluations[static_cast<std::size_t>(term)]; }
    std::uint64_t forceEvaluations() const { return m_forceEvaluations; }
    // The counters above, to checkpoint and restore a run (Simulation::snapshot).
    struct Counters {
        std::array<std::uint64_t, kTermCount> terms{};
        std::uint64_t forceEvaluations = 0;
    };
    Counters counters() const { return {m_evaluations, m_forceEvaluations}; }
    void setCounters(const Counters& c) {
        m_evaluations = c.terms;
        m_forceEvaluations = c.forceEvaluations;
    }

private:
    template <class F>
    void runChunks(F&& task);
    static std::pair<std::size_t, std::size_t> range(std::size_t count, int chunk, int chunks);
    void countTerms();
    // evaluate() and evaluateMotion(): out = F (invMass3 == nullptr) or F * invMass3, and
    // xdot = v when xdot is given.
    void evaluateInto(const double* x, const double* v, const double* invMass3, double* xdot,
                      double* out, ForceExtras& extras, bool count, const RangeWork* then, bool defer = false,
                      const TaskRef* beside = nullptr);
    // An evaluation's last stage (unpadding, xdot = v, the pointer's particle, `then`): what it
    // needs besides the padded buffers.
    struct LastStage {
        bool held = false;  // held back by evaluateMotionDeferred
        const double* v = nullptr;
        const double* invMass3 = nullptr;
        double* xdot = nullptr;
        double* out = nullptr;
        std::array<double, 2> pressure{};  // per layer slot
        int pulled = -1;                   // the pointer's particle, or -1
        std::array<double, 3> pointerOut{};
    };
    void lastStage(const LastStage& last, const RangeWork* then);
    LastStage m_pending;

    const Topology* m_topology = nullptr;
    const Eigen::VectorXd* m_mass = nullptr;
    TermSet m_terms;
    ThreadPool* m_pool = nullptr;
    int m_chunks = 1;
    std::array<std::uint64_t, kTermCount> m_evaluations{};
    std::uint64_t m_forceEvaluations = 0;
    // Scratch, sized once: per-element results and per-chunk force buffers.
    // Springs and faces split by owner: parts 0..kChunks-1 touch only their chunk's
    // particles; part kChunks holds those shared between chunks.
    struct Part {
        kernels::QuadSet quads;  // most structural and shear springs of a two-layer body
        std::array<SpringSet, kSpringFamilyCount> springs;  // the rest
        // Whether the radius springs form a run (kernels::springRunBlock): particle k to k + n.
        bool radiusRun = false;
        std::vector<Surface> surfaces;
        // Layer-barrier pairs whose inner, outer and fan particles all belong to this part's
        // chunk (the shared part: the rest), evaluated once g of the outer vertex is complete.
        LayerBarrierSet barrier;
    };
    void partition();
    std::array<std::vector<bool>, kSpringFamilyCount> partitionQuads();  // partition()'s steps
    void partitionSurfaces();
    // What one part adds up besides forces: enclosed-volume sums (6V in 3D, 2A in 2D) per
    // layer, damping power, squared stretch per spring family, degenerate springs.
    struct Sums {
        std::array<double, 2> volume{};
        double power = 0.0;
        std::array<double, kSpringFamilyCount> stretch2{};
        int degenerate = 0;
        double contactEnergy = 0.0;
        double contactPower = 0.0;
    };
    int ownerOf(int particle) const;
    // Adds the part's spring forces to f4 and its gas gradient dV/dx to g4 (padded, 4 doubles
    // per particle); adds its sums to `sums`.
    void accumulatePart(const Part& part, const double* x, const double* v, double* f4, double* g4, Sums& sums) const;
    // The gas part of that: the part's faces' volume sums and gradient.
    void accumulateGas(const Part& part, const double* x, double* g4, Sums& sums) const;
    // Chunk c's owned rows of g4 cleared.
    void clearGradient(int chunk);
    std::array<Part, kChunks + 1> m_parts;
    std::array<std::vector<std::pair<int, int>>, kChunks> m_ownedRanges;  // particle ranges per chunk
    kernels::AlignedBuffer m_force4;                  // forces, padded (4N)
    kernels::AlignedBuffer m_gradient4;               // dV/dx of each particle's layer, padded (4N)
    // 3D bodies whose particles each lie on one surface of their own layer: dV/dx gathered
    // per corner (kernels::vertexGradients), each chunk writing its own particles' rows
    // whole. Empty otherwise (2D, or another shape): the faces add into cleared rows.
    kernels::VertexFans m_fans;
    std::vector<std::uint8_t> m_contactFree;          // 1 where a particle feels wall contact
    LayerBarrierSet m_barrierAll;                     // every pair, in pair order
};

}  // namespace simcore
