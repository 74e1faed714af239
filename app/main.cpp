// m3055: the M3055 material explorer's command line.
//   m3055 render  --scene S.json --out O.png [--raw O.pfm] [--backend auto|egl|osmesa] [--set path=value]...
//   m3055 figures --out screenshots/
//   m3055 batch MANIFEST.json [--backend ...]
//   m3055 bench [--out DIR] [--quick]
#include "commands.h"

#include <cstdio>

namespace m3055 { void add_explore_command(CLI::App& app); }  // app/cmd_explore.cpp

int main(int argc, char** argv) {
    CLI::App app{"M3055 material explorer: the reflection models of Yokoi et al. on an emulated 512x320, 5-bit display"};
    app.require_subcommand(1);
    m3055::add_render_command(app);
    m3055::add_figures_command(app);
    m3055::add_batch_command(app);
    m3055::add_bench_command(app);
    m3055::add_explore_command(app);
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& error) {
        return app.exit(error) == 0 ? m3055::kExitOk : m3055::kExitUsage;
    }
    return m3055::kExitOk;
}
