#pragma once
// Restitution measured, not assumed: a particle alone and a whole body hit the floor at a
// given speed (weightless, so that only the contact acts on the rebound), and the rebound
// speed is divided by the impact speed. docs/numerics.md plots the curve over 0.3-30 m/s
// beside the parameter e (contact.h explains why a single particle matches e at
// contact_speed exactly and departs elsewhere, and why a body rebounds less).

#include <string>

#include "simcore/params.h"

namespace simlab {

struct ImpactRow {
    double speed = 0.0;     // impact speed [m/s]
    double particle = 0.0;  // a free particle's rebound / impact speed (< 0: no rebound in time)
    double body = 0.0;      // the body's centre-of-mass rebound / impact speed (< 0: none)
    double depth = 0.0;     // the body's deepest penetration [m]
    double dt = 0.0;        // the step used [s]
    std::string note;       // why the body has no rebound (its run failed, or never left)
};

// params: the scene (its contact, restitution, stiffness, mass and box are used; gravity is
// set to 0). The step: dt(speed) = min(params dt, 3e-4 s / speed) (contact lasts longer than
// ~0.01 s / speed^(1/2) here; tested to converge).
ImpactRow measureImpact(const simcore::ParameterSet& params, const std::string& integrator, double speed);

}  // namespace simlab
