#include "ui/body_measures.h"

#include <algorithm>

#include "simcore/simulation.h"

namespace elui {

BodyMeasures measureBody(const simcore::Simulation& sim) {
    BodyMeasures out;
    const auto x = sim.positions();
    const auto v = sim.velocities();
    const Eigen::VectorXd& m = sim.body().mass;
    const auto& layer = sim.topology().layer;
    const Eigen::Index n = x.cols();
    if (n == 0) return out;
    double total = 0.0;
    std::array<int, 2> count{0, 0};
    double lowest = x(1, 0);
    for (Eigen::Index i = 0; i < n; ++i) {
        out.centreOfMass += m[i] * x.col(i);
        out.centreVelocity += m[i] * v.col(i);
        total += m[i];
        const int l = layer[std::size_t(i)] == simcore::Layer::Inner ? 0 : 1;
        out.layerCentre[std::size_t(l)] += x.col(i);
        ++count[std::size_t(l)];
        lowest = std::min(lowest, x(1, i));
    }
    if (total > 0.0) {
        out.centreOfMass /= total;
        out.centreVelocity /= total;
    }
    out.layered = count[0] > 0 && count[1] > 0;
    if (out.layered) {
        out.layerCentre[0] /= count[0];
        out.layerCentre[1] /= count[1];
    } else {
        const Eigen::Vector3d all = (out.layerCentre[0] + out.layerCentre[1]) / double(n);
        out.layerCentre = {all, all};
    }
    out.floor = sim.boxCentre().y() - sim.boxHalfSize();
    out.lowest = lowest - out.floor;
    return out;
}

double layerSag(const simcore::Simulation& sim) { return measureBody(sim).sag(); }

}  // namespace elui
