#include "ui/presets.h"

#include <QObject>

#include "simcore/scenes.h"

namespace elui {

std::optional<simcore::WorldSpec> Preset::world() const {
    auto spec = simcore::worldScene(scene.toStdString());
    if (!spec) return std::nullopt;
    for (const auto& [param, value] : values)
        for (auto& b : spec->bodies) (void)b.params.set(param, value);
    for (const QString& assignment : worldSet) (void)simcore::assignWorld(*spec, assignment.toStdString());
    return spec;
}

simcore::ParameterSet Preset::parameters() const {
    if (const auto spec = world()) return spec->bodies.front().params;
    const simcore::SceneInfo* info = simcore::findScene(scene.toStdString());
    simcore::ParameterSet params(info ? info->kind : simcore::SceneKind::Ring2d);
    for (const auto& [param, value] : values) params.set(param, value);
    return params;
}

QList<Preset> teachingPresets() {
    const QStringList rk4{QStringLiteral("rk4")};
    return {
        {"drop1d", QObject::tr("1D drop: two masses on a spring"),
         QObject::tr("Both masses fall, hit the floor and bounce; the spring oscillates (thesis fig. 7)."),
         "spring1d", {{simcore::Param::FixedEnd, 0}, {simcore::Param::InitialLength, 1.2}}, rk4},
        {"hang1d", QObject::tr("1D hanging spring"),
         QObject::tr("The top mass is fixed; the lower one oscillates around the stretched rest length."),
         "spring1d", {}, rk4},
        {"ring2d", QObject::tr("2D ring"),
         QObject::tr("Two gas-filled rings joined by radius and shear springs drop onto the floor (thesis 3.4)."),
         "ring2d", {}, rk4},
        {"sphere3d", QObject::tr("3D sphere"),
         QObject::tr("Two gas-filled spheres (subdivided octahedron) drop and bounce (thesis 3.5.2)."),
         "sphere3d", {{simcore::Param::Subdivisions, 2}}, rk4},
        {"latlong3d", QObject::tr("3D lat/long sphere (non-uniform)"),
         QObject::tr("The lat/long sphere: particles crowd at the poles, so the body is not uniform (thesis 3.5.1)."),
         "sphere3d-latlong", {{simcore::Param::Slices, 12}, {simcore::Param::Stacks, 8}}, rk4},
        {"heavy-inner", QObject::tr("Heavy inner layer (non-uniform density)"),
         QObject::tr("The inner layer is five times heavier: it sinks inside the outer one and the body lands "
                     "bottom-heavy (thesis 8.1)."),
         "sphere3d", {{simcore::Param::Subdivisions, 2}, {simcore::Param::MassInner, 5.0}}, rk4},
        {"liquid", QObject::tr("Liquid motion and inertia"),
         QObject::tr("Inner and outer layers pushed in opposite directions (3 m/s), without gravity and with "
                     "soft, lightly damped radius and shear springs: the inner layer sloshes inside the outer "
                     "one like a liquid (thesis fig. 47)."),
         "ring2d", {{simcore::Param::Gravity, 0.0}, {simcore::Param::Rks, 40.0}, {simcore::Param::Rkd, 0.5}}, rk4, 3.0, -3.0},
    };
}

QList<Preset> stabilityPresets() {
    const QStringList three{QStringLiteral("euler"), QStringLiteral("midpoint"), QStringLiteral("rk4")};
    QList<Preset> out;
    for (double dt : {0.003, 0.03, 0.3})
        out.push_back({QStringLiteral("stability-%1").arg(dt), QObject::tr("Stability experiment, DT = %1 s").arg(dt),
                       QObject::tr("Euler, midpoint and RK4 from the same start at DT = %1 s (thesis 7.2.2, "
                                   "figs. 41-43). Watch which one blows up.")
                           .arg(dt),
                       "ring2d", {{simcore::Param::Particles, 10}, {simcore::Param::Dt, dt}}, three});
    return out;
}

const Preset* findPreset(const QString& id) {
    static const QList<Preset> all = teachingPresets() + stabilityPresets();
    for (const Preset& p : all)
        if (p.id == id) return &p;
    return nullptr;
}

}  // namespace elui
