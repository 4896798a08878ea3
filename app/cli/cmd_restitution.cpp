// `restitution`: rebound / impact speed of a particle and of the scene's body against impact speed.
#include <cstdio>
#include <memory>

#include "cli.h"
#include "impact.h"
#include "output.h"

namespace cli {

int commandRestitution(const std::vector<std::string>& args) {
    auto names = sceneOptionNames();
    names.insert(names.end(), {"speeds", "csv"});
    Options options(args, names, {});
    checkDistinctFiles(options, {"csv", "plot"});
    SceneSetup setup = sceneSetup(options);
    const std::vector<double> speeds = numberList("speeds", options.has("speeds") ? options.value("speeds") : "0.3,1,3,10,30");
    std::unique_ptr<simcore::AtomicFile> csv;
    if (options.has("csv")) {
        csv = std::make_unique<simcore::AtomicFile>(options.value("csv"));
        if (!csv->ok()) throw UsageError(csv->error());
    }
    const simcore::ParameterSet& p = setup.params;
    std::printf("scene        %s, %s, contact = %s, e = %g, contact_speed = %g m/s, contact_stiffness = %g N/m^3\n",
                setup.sceneName.c_str(), setup.integrator.c_str(), p.get("contact") == 1.0 ? "projection" : "force",
                p.get("restitution"), p.get("contact_speed"), p.get("contact_stiffness"));
    std::printf("             weightless; rebound / impact speed of a free particle and of the body's centre of mass\n\n");
    std::printf("%-12s %-12s %-12s %-14s %-10s\n", "speed_m/s", "particle", "body", "body_depth_m", "dt_s");
    std::string text = "speed,e_set,particle,body,body_depth,dt\n";  // -1: no rebound
    for (double speed : speeds) {
        if (!(speed > 0.0)) throw UsageError("--speeds: every speed must be > 0");
        const simcore::ImpactRow row = simcore::measureImpact(p, setup.integrator, speed);
        std::printf("%-12g %-12.4f %-12.4f %-14.4g %-10.3g %s\n", row.speed, row.particle, row.body, row.depth, row.dt,
                    row.note.c_str());
        text += simcore::formatDouble(row.speed) + ',' + simcore::formatDouble(p.get("restitution")) + ',' +
                simcore::formatDouble(row.particle) + ',' + simcore::formatDouble(row.body) + ',' +
                simcore::formatDouble(row.depth) + ',' + simcore::formatDouble(row.dt) + '\n';
    }
    if (csv) {
        csv->write(text);
        if (!csv->commit()) throw UsageError(csv->error());
    }
    return kExitOk;
}

}  // namespace cli
