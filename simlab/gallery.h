#pragma once
// The stiff and extreme gallery: named presets with the outcome each must have.
//
// An outcome is either "stays stable and within tolerance" (no failure, finite state, the
// energy balance within a stated fraction of the energy the body can convert) or "is detected
// as failed with a clear reason" (simcore::Simulation's checks: a named cause, the last good state
// kept). Never a NaN, a hang or a crash: every case has a bounded number of steps.
// Each case is a CTest test (tests/CMakeLists.txt, gallery_<name>) and `elastic-lab-cli
// gallery --run NAME` runs it by hand. Expectations were measured on the reference machine
// and are physics, not timings.

#include <string>
#include <utility>
#include <vector>

#include <Eigen/Core>

#include "simcore/params.h"

namespace simlab {

struct GalleryCase {
    std::string name;
    std::string description;
    simcore::SceneKind scene = simcore::SceneKind::Ring2d;
    std::vector<std::pair<simcore::Param, double>> set;  // parameters (id, value)
    std::string integrator = "rk4";
    double duration = 2.0;                            // [s]
    Eigen::Vector3d launch = Eigen::Vector3d::Zero(); // start velocity of every particle [m/s]
    bool expectStable = true;
    std::string expectReason;     // failures: a word the reason must contain
    double driftTolerance = 0.05; // stable: |drift| <= this x energy scale (one-sided: gains only
    bool lossAllowed = false;     //   when lossAllowed, for dissipative implicit-euler)
    bool expectWarning = false;   // the pre-run stability warning must be given
};

struct GalleryOutcome {
    bool asExpected = false;
    bool failed = false;
    bool finite = true;
    bool warned = false;
    std::string reason;       // failure reason, when failed
    double time = 0.0;        // simulated time reached [s]
    double drift = 0.0;       // final energy balance drift [J]
    double maxDrift = 0.0;    // largest |drift| over the run [J]
    double energyScale = 0.0; // [J]
    std::string summary;      // one line for people
};

const std::vector<GalleryCase>& galleryCases();
const GalleryCase* findGalleryCase(const std::string& name);
simcore::ParameterSet galleryParameters(const GalleryCase& c);
GalleryOutcome runGalleryCase(const GalleryCase& c);

}  // namespace simlab
