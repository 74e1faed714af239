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

#include <iostream>

namespace {

// A command-line mistake as every message of m3055 is: one line starting
// "m3055:", naming the subcommand and where its usage is.
int usage_error(const CLI::App& app, const CLI::ParseError& error) {
    const std::vector<CLI::App*> used = app.get_subcommands();
    const std::string command = used.empty() ? "m3055" : "m3055 " + used.back()->get_name();
    std::cerr << "m3055: " << (used.empty() ? "" : used.back()->get_name() + ": ") << error.what() << " (" << command
              << " --help shows the usage)\n";
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
