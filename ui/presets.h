#pragma once
// Presets: the thesis's scenes and experiments, one click each.

#include <QList>
#include <QPair>
#include <QString>
#include <QStringList>

#include <optional>

#include "simcore/params.h"
#include "simcore/world.h"

namespace elui {

struct Preset {
    QString id;            // short name, also accepted by --preset
    QString title;         // menu text
    QString description;   // what to look at (status bar, help)
    QString scene;         // scene name
    QList<QPair<simcore::Param, double>> values;  // parameters the preset sets (id, value)
    QStringList integrators;       // one: normal view; two or three: side by side
    double kickInner = 0.0;        // start velocity along x of inner / outer particles [m/s]
    double kickOuter = 0.0;
    // A scene of several bodies (scene: collide2d, collide3d, stack3d): its --set assignments
    // ("gravity=0", "body2.mass=4"), applied after `values`.
    QStringList worldSet = {};

    // The parameter set the preset builds (throws nothing: preset values are valid); for a
    // scene of several bodies, the first body's.
    simcore::ParameterSet parameters() const;
    // The world the preset builds, or nothing for a scene of one body.
    std::optional<simcore::WorldSpec> world() const;
};

QList<Preset> teachingPresets();
// The thesis's stability experiment (§7.2.2, figs. 41-43): euler, midpoint and rk4 side by
// side on the ring at one DT each of 0.003, 0.03 and 0.3.
QList<Preset> stabilityPresets();
const Preset* findPreset(const QString& id);

}  // namespace elui
