#pragma once
// The front door's bounds (simlab/request.h checks them; docs/reliability.md gives the reasons).
// In a header of their own so that the studies that also apply them while they run (sweep,
// conservation) share the figures without including the front door, which includes them.

namespace simlab {

// The most steps one run may take (1e9: about 3 days for the default ring on this machine).
inline constexpr double kMaxSteps = 1e9;
// The most particle-steps (steps x particles) of one measurement that runs a body for a fixed
// simulated time whatever its size (restitution: 10 s per speed), about an hour of one core.
inline constexpr double kMaxParticleSteps = 1e10;
// The most bytes of results one request may hold in memory at once (1 GiB).
inline constexpr double kMaxHeldBytes = 1024.0 * 1024.0 * 1024.0;
// A stability trial at the smallest step scanned must take at least this many steps: a
// shorter one shows no growth (a duration of 1e-300 s called every method stable up to hmax).
inline constexpr double kMinTrialSteps = 100.0;

}  // namespace simlab
