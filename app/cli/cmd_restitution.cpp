// `restitution`: rebound / impact speed of a particle and of the scene's body against impact speed.
#include <cstdio>
#include <memory>

#include "app/cli/cli.h"
#include "simlab/impact.h"
#include "simlab/output.h"

namespace cli {

namespace {

struct RestitutionArgs {
    SceneArgs scene;
    std::string speeds = "0.3,1,3,10,30", csv;
    std::vector<double> speedList;  // after check()
    SceneSetup setup;
};

void checkRestitution(RestitutionArgs& args) {
    checkDistinctFiles({{"scene", sceneFileOf(args.scene)}, {"csv", args.csv}});
    args.setup = sceneSetup(args.scene);
    args.speedList = numberList("speeds", args.speeds);
    for (double speed : args.speedList)
        if (!(speed > 0.0 && speed <= 1e4)) throw UsageError("--speeds: every speed must be in (0, 10000] m/s, got " + simlab::formatDouble(speed));
}

int runRestitution(const RestitutionArgs& args) {
    const SceneSetup& setup = args.setup;
    std::unique_ptr<simlab::AtomicFile> csv;
    if (!args.csv.empty()) {
        csv = std::make_unique<simlab::AtomicFile>(args.csv);
        if (!csv->ok()) throw UsageError(csv->error());
    }
    const simcore::ParameterSet& p = setup.params;
    std::printf("scene        %s, %s, contact = %s, e = %g, contact_speed = %g m/s, contact_stiffness = %g N/m^3\n",
                setup.sceneName.c_str(), setup.integrator.c_str(), p.get(simcore::Param::Contact) == 1.0 ? "projection" : "force",
                p.get(simcore::Param::Restitution), p.get(simcore::Param::ContactSpeed), p.get(simcore::Param::ContactStiffness));
    std::printf("             weightless; rebound / impact speed of a free particle and of the body's centre of mass\n\n");
    std::printf("%-12s %-12s %-12s %-14s %-10s\n", "speed_m/s", "particle", "body", "body_depth_m", "dt_s");
    std::string text = "speed,e_set,particle,body,body_depth,dt\n";  // -1: no rebound
    for (double speed : args.speedList) {
        const simlab::ImpactRow row = simlab::measureImpact(p, setup.integrator, speed);
        std::printf("%-12g %-12.4f %-12.4f %-14.4g %-10.3g %s\n", row.speed, row.particle, row.body, row.depth, row.dt,
                    row.note.c_str());
        text += simlab::formatDouble(row.speed) + ',' + simlab::formatDouble(p.get(simcore::Param::Restitution)) + ',' +
                simlab::formatDouble(row.particle) + ',' + simlab::formatDouble(row.body) + ',' +
                simlab::formatDouble(row.depth) + ',' + simlab::formatDouble(row.dt) + '\n';
    }
    if (csv) {
        csv->write(text);
        if (!csv->commit()) throw UsageError(csv->error());
    }
    return kExitOk;
}

}  // namespace

Command addRestitutionCommand(CLI::App& app) {
    auto args = std::make_shared<RestitutionArgs>();
    CLI::App* sub = app.add_subcommand("restitution", "rebound / impact speed of a free particle and of the body against "
                                                      "impact speed (weightless), beside the restitution e");
    addSceneOptions(*sub, args->scene);
    sub->add_option("--speeds", args->speeds, "comma-separated impact speeds [m/s]")->type_name("v1,v2,...")->capture_default_str();
    addCsvOption(*sub, args->csv, "write one row per speed");
    return {sub, [args] { checkRestitution(*args); }, [args] { return runRestitution(*args); }};
}

}  // namespace cli
