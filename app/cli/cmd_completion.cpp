// `completion`: the bash completion script, written from the command tree itself, so that it
// names every command and option the tool has (the build installs its output).
#include <cstdio>
#include <string>

#include "app/cli/cli.h"
#include "simcore/integrator_table.h"
#include "simcore/integrators.h"
#include "simcore/scenes.h"

namespace cli {

namespace {

std::string words(const std::string& listWithCommas) {
    std::string out = listWithCommas;
    std::string::size_type at = 0;
    while ((at = out.find(", ", at)) != std::string::npos) out.replace(at, 2, " ");
    return out;
}

// What follows an option: a word list, a file name, or free text (nothing offered).
std::string valueCompletion(const CLI::Option& option) {
    const std::string name = option.get_lnames().empty() ? "" : option.get_lnames().front();
    const std::string type = option.get_type_name();
    if (name == "scene")
        return "COMPREPLY=($(compgen -W \"" + words(simcore::sceneNames()) + "\" -- \"$cur\") $(compgen -f -X '!*.json' -- \"$cur\"))";
    if (name == "integrator" || name == "integrators")
        return "COMPREPLY=($(compgen -W \"" + words(simcore::integratorNames()) + "\" -- \"$cur\"))";
    if (name == "kernels") return "COMPREPLY=($(compgen -W \"portable avx2 avx512\" -- \"$cur\"))";
    if (type.find("FILE") != std::string::npos) return "COMPREPLY=($(compgen -f -- \"$cur\"))";
    return "COMPREPLY=()";
}

std::string script(const CLI::App& app) {
    std::string commands, perCommand, values;
    for (const CLI::App* sub : app.get_subcommands({})) {
        commands += (commands.empty() ? "" : " ") + sub->get_name();
        std::string options;
        for (const CLI::Option* o : sub->get_options()) {
            if (o->get_lnames().empty()) continue;
            const std::string flag = "--" + o->get_lnames().front();
            options += (options.empty() ? "" : " ") + flag;
            if (o->get_items_expected_max() > 0)  // takes a value (flags expect none)
                values += "        " + sub->get_name() + ":" + flag + ") " + valueCompletion(*o) + "; return ;;\n";
        }
        perCommand += "        " + sub->get_name() + ") opts=\"" + options + "\" ;;\n";
    }
    return "# bash completion for elastic-lab-cli; written by `elastic-lab-cli completion` from its own commands\n"
           "_elastic_lab_cli() {\n"
           "    local cur=\"${COMP_WORDS[COMP_CWORD]}\" prev=\"${COMP_WORDS[COMP_CWORD-1]}\" cmd=\"${COMP_WORDS[1]}\" opts\n"
           "    if [ \"$COMP_CWORD\" -le 1 ]; then\n"
           "        COMPREPLY=($(compgen -W \"" + commands + " --help --version\" -- \"$cur\"))\n"
           "        return\n"
           "    fi\n"
           "    case \"$cmd:$prev\" in\n" + values +
           "    esac\n"
           "    case \"$cmd\" in\n" + perCommand +
           "        *) opts=\"\" ;;\n"
           "    esac\n"
           "    COMPREPLY=($(compgen -W \"$opts --help\" -- \"$cur\"))\n"
           "}\n"
           "complete -o filenames -F _elastic_lab_cli elastic-lab-cli\n";
}

}  // namespace

Command addCompletionCommand(CLI::App& app) {
    CLI::App* sub = app.add_subcommand("completion", "print the bash completion script (installed as "
                                                     "share/bash-completion/completions/elastic-lab-cli)");
    return {sub, [] {}, [&app] {
                std::fputs(script(app).c_str(), stdout);
                return kExitOk;
            }};
}

}  // namespace cli
