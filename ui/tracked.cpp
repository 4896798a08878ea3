#include "ui/tracked.h"

#include <cmath>
#include <limits>

#include <QObject>

namespace elui {

QString Tracked::name() const {
    switch (kind) {
        case Kind::ParticleHeight: return QObject::tr("height of particle %1").arg(particle);
        case Kind::ParticleSpeed: return QObject::tr("speed of particle %1").arg(particle);
        case Kind::LayerHeight:
            return layer == 0 ? QObject::tr("height of the inner layer's centre")
                              : QObject::tr("height of the outer layer's centre");
        case Kind::CentreHeight: return QObject::tr("centre-of-mass height");
        case Kind::CentreSpeed: return QObject::tr("centre-of-mass speed");
        case Kind::LayerSeparation: return QObject::tr("layers' separation");
    }
    return {};
}

double Tracked::value(const LaneFrame& lane) const {
    const BodyMeasures& b = lane.body;
    const std::size_t i = std::size_t(std::max(particle, 0));
    switch (kind) {
        case Kind::ParticleHeight:
            if (particle < 0 || 3 * i + 2 >= lane.positions.size()) break;
            return double(lane.positions[3 * i + 1]) - b.floor;
        case Kind::ParticleSpeed:
            if (particle < 0 || 3 * i + 2 >= lane.velocities.size()) break;
            return std::hypot(double(lane.velocities[3 * i]), double(lane.velocities[3 * i + 1]),
                              double(lane.velocities[3 * i + 2]));
        case Kind::LayerHeight: return b.layerCentre[std::size_t(layer == 0 ? 0 : 1)].y() - b.floor;
        case Kind::CentreHeight: return b.centreOfMass.y() - b.floor;
        case Kind::CentreSpeed: return b.centreVelocity.norm();
        case Kind::LayerSeparation: return b.separation();
    }
    return std::numeric_limits<double>::quiet_NaN();
}

}  // namespace elui
