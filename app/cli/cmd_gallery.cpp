// `gallery`: the stiff and extreme presets (simcore/gallery.h) and their expected outcomes.
#include <cstdio>

#include "cli.h"
#include "gallery.h"

namespace cli {

int commandGallery(const std::vector<std::string>& args) {
    Options options(args, {"run"}, {"list"});
    const std::string which = options.valueOr("run", "");
    if (which.empty() || options.has("list")) {
        for (const simcore::GalleryCase& c : simcore::galleryCases())
            std::printf("%-34s %-8s %s\n", c.name.c_str(), c.expectStable ? "stable" : "fails", c.description.c_str());
        return kExitOk;
    }
    int bad = 0, count = 0;
    for (const simcore::GalleryCase& c : simcore::galleryCases()) {
        if (which != "all" && which != c.name) continue;
        ++count;
        const simcore::GalleryOutcome o = simcore::runGalleryCase(c);
        std::printf("%-34s %-4s %s\n", c.name.c_str(), o.asExpected ? "ok" : "FAIL", o.summary.c_str());
        std::fflush(stdout);
        bad += o.asExpected ? 0 : 1;
    }
    if (count == 0) throw UsageError("unknown gallery case '" + which + "'; see elastic-lab-cli gallery --list");
    return bad == 0 ? kExitOk : kExitFailed;
}

}  // namespace cli
