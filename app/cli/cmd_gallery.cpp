// `gallery`: the stiff and extreme presets (simlab/gallery.h) and their expected outcomes.
#include <cstdio>

#include "app/cli/cli.h"
#include "simlab/gallery.h"

namespace cli {

namespace {

int runGallery(const std::string& which, bool list) {
    if (which.empty() || list) {
        for (const simlab::GalleryCase& c : simlab::galleryCases())
            std::printf("%-34s %-8s %s\n", c.name.c_str(), c.expectStable ? "stable" : "fails", c.description.c_str());
        return kExitOk;
    }
    int bad = 0;
    for (const simlab::GalleryCase& c : simlab::galleryCases()) {
        if (which != "all" && which != c.name) continue;
        const simlab::GalleryOutcome o = simlab::runGalleryCase(c);
        std::printf("%-34s %-4s %s\n", c.name.c_str(), o.asExpected ? "ok" : "FAIL", o.summary.c_str());
        std::fflush(stdout);
        bad += o.asExpected ? 0 : 1;
    }
    return bad == 0 ? kExitOk : kExitFailed;
}

}  // namespace

Command addGalleryCommand(CLI::App& app) {
    struct Args {
        std::string run;
        bool list = false;
    };
    auto args = std::make_shared<Args>();
    CLI::App* sub = app.add_subcommand("gallery", "stiff and extreme presets with their expected outcome; exit 3 when "
                                                  "one does not end as expected");
    sub->add_option("--run", args->run, "run one case by name, or all")->type_name("NAME|all");
    sub->add_flag("--list", args->list, "list the cases (the default)");
    return {sub,
            [args] {
                if (args->run.empty() || args->run == "all") return;
                for (const simlab::GalleryCase& c : simlab::galleryCases())
                    if (c.name == args->run) return;
                throw UsageError("unknown gallery case " + simcore::quoteShort(args->run) +
                                 "; see elastic-lab-cli gallery --list");
            },
            [args] { return runGallery(args->run, args->list); }};
}

}  // namespace cli
