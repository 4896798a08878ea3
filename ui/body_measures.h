#pragma once
// What a teacher reads off a body besides the energy book: its centre of mass and that
// centre's velocity, each layer's centre (the mean position of its particles), and its lowest
// point. Qt-free; computed on the worker for every published frame (LaneFrame::body) and by
// the lessons' measurements (ui/lesson_measures.h), so the window and the tests read the same.

#include <array>

#include <Eigen/Core>

namespace simcore {
class Simulation;
}

namespace elui {

struct BodyMeasures {
    Eigen::Vector3d centreOfMass = Eigen::Vector3d::Zero();  // [m]
    Eigen::Vector3d centreVelocity = Eigen::Vector3d::Zero();  // of the centre of mass [m/s]
    // Mean position of the inner [0] and outer [1] layer's particles; `layered` false when the
    // body has one layer (both are then the mean of all particles).
    std::array<Eigen::Vector3d, 2> layerCentre{Eigen::Vector3d::Zero(), Eigen::Vector3d::Zero()};
    bool layered = false;
    double floor = 0.0;   // the floor's y (the box's bottom plane) [m]
    double lowest = 0.0;  // the lowest particle's height above the floor [m]

    // The outer layer's centre minus the inner layer's, along y (up) [m]: how far the inner
    // layer sits below (> 0) the outer one.
    double sag() const { return layerCentre[1].y() - layerCentre[0].y(); }
    // The distance between the layers' centres [m].
    double separation() const { return (layerCentre[1] - layerCentre[0]).norm(); }
};

BodyMeasures measureBody(const simcore::Simulation& sim);
// measureBody(sim).sag().
double layerSag(const simcore::Simulation& sim);

}  // namespace elui
