// m3055: the M3055 material explorer's command line.
//   m3055 --version
//   m3055 render  --scene S.json --out O.png [--raw O.pfm] [--backend auto|egl|osmesa] [--set path=value]...
//   m3055 figures --out screenshots/
//   m3055 batch MANIFEST.json [--backend ...]
//   m3055 bench [--out DIR] [--quick]
//   m3055 compare A B [--fail-levels N] [--diff D.png] [--json]   (A, B: images, scenes, or two folders of PNGs)
//   m3055 grade ASSIGNMENT.json SUBMISSIONS/ --out DIR [--shard K/N] | grade --merge DIR... --out DIR
//   m3055 explore [--scene S.json]     (also plain `m3055` when $DISPLAY is set;
//                                       not in a -DM3055_BUILD_EXPLORER=OFF build)
#include "commands.h"

#include "io/message_text.h"

#include <iostream>

namespace {

// The parse error's text; for arguments no command or option took, those arguments in the
// order typed (CLI11 lists them last first) and, for the first, the command or option a
// typo away ("rendr": "render", "--fail-level": "--fail-levels").
std::string what_went_wrong(const CLI::App& app, const CLI::ParseError& error) {
    if (!dynamic_cast<const CLI::ExtrasError*>(&error)) return error.what();
    const std::vector<CLI::App*> used = app.get_subcommands();
    const CLI::App& where = used.empty() ? app : *used.back();
    const std::vector<std::string> extras = where.remaining();
    if (extras.empty()) return error.what();
    std::string text = "not expected:";
    for (const std::string& extra : extras) text += " " + m3055::text::quote_name(extra);
    std::vector<std::string> names;
    if (used.empty())
        for (const CLI::App* sub : app.get_subcommands([](const CLI::App*) { return true; })) names.push_back(sub->get_name());
    for (const CLI::Option* option : where.get_options())
        for (const std::string& name : option->get_lnames()) names.push_back("--" + name);
    const std::string first = extras.front().substr(0, extras.front().find('='));
    const std::string near = m3055::text::closest_name(first, names);
    return near.empty() ? text : text + " (did you mean \"" + near + "\"?)";
}

// A command-line mistake as every message of m3055 is: one line starting
// "m3055:", naming the subcommand and where its usage is.
int usage_error(const CLI::App& app, const CLI::ParseError& error) {
    const std::vector<CLI::App*> used = app.get_subcommands();
    const std::string command = used.empty() ? "m3055" : "m3055 " + used.back()->get_name();
    std::cerr << "m3055: " << (used.empty() ? "" : used.back()->get_name() + ": ") << what_went_wrong(app, error)
              << " (" << command << " --help shows the usage)\n";
    return m3055::kExitUsage;
}

}  // namespace

int main(int argc, char** argv) {
    CLI::App app{"M3055 material explorer: the reflection models of Yokoi et al. on an emulated 512x320, 5-bit display"};
    app.set_version_flag("--version", std::string("m3055 ") + M3055_VERSION);
    app.require_subcommand(0, 1);
    m3055::add_render_command(app);
    m3055::add_figures_command(app);
    m3055::add_batch_command(app);
    m3055::add_bench_command(app);
    m3055::add_explore_command(app);
    m3055::add_compare_command(app);
    m3055::add_grade_command(app);
    m3055::add_brdf_check_command(app);
    m3055::add_plot_command(app);
    m3055::add_models_command(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::RuntimeError& error) {
        return error.get_exit_code();  // a subcommand failed; it has said why on stderr
    } catch (const CLI::CallForHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForAllHelp& help) {
        return app.exit(help);
    } catch (const CLI::CallForVersion& version) {
        return app.exit(version);
    } catch (const CLI::ParseError& error) {
        return usage_error(app, error);
    }
    if (app.get_subcommands().empty()) return m3055::run_without_subcommand(app);
    return m3055::kExitOk;
}
