#pragma once
// A quantity a teacher picks off the body to plot against time (right-click in the view):
// a particle's height or speed, a layer centre's height, the centre of mass's height or speed,
// or the distance between the layers' centres. Heights are above the floor (the box's bottom).

#include <QString>

#include "ui/frame.h"

namespace elui {

struct Tracked {
    enum class Kind { ParticleHeight, ParticleSpeed, LayerHeight, CentreHeight, CentreSpeed, LayerSeparation };
    Kind kind = Kind::CentreHeight;
    int particle = -1;  // ParticleHeight, ParticleSpeed
    int layer = 0;      // LayerHeight: 0 inner, 1 outer

    QString name() const;  // legend text, e.g. "height of particle 7"
    bool isSpeed() const { return kind == Kind::ParticleSpeed || kind == Kind::CentreSpeed; }
    QString unit() const { return isSpeed() ? QStringLiteral("m/s") : QStringLiteral("m"); }
    // The value in a lane of a frame; NaN when the lane has no such particle.
    double value(const LaneFrame& lane) const;
    bool operator==(const Tracked& o) const {
        return kind == o.kind && particle == o.particle && (kind != Kind::LayerHeight || layer == o.layer);
    }
};

}  // namespace elui
