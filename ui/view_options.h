#pragma once
// What the viewport draws: one switch per thing a teacher may want to hide or show.

namespace elui {

struct ViewOptions {
    bool springs[3] = {true, true, true};  // structural, radius, shear
    bool faces = true;
    bool particles = true;
    bool normals = false;
    bool forces = false;
    bool velocities = false;  // velocity arrows beside the force arrows
    bool ruler = false;       // left-drag measures a distance in the view instead of grabbing
    bool strain = false;   // springs coloured by strain (L - L0) / L0 instead of by family
    bool box = true;
    double strainRange = 0.2;  // strain shown at full colour (20 %)
};

}  // namespace elui
