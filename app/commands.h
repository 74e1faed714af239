// Each subcommand registers itself on the CLI11 app from its own file.
#pragma once

#include <CLI/CLI.hpp>

namespace m3055 {

void add_render_command(CLI::App& app);   // app/cmd_render.cpp
void add_figures_command(CLI::App& app);  // app/cmd_figures.cpp
void add_batch_command(CLI::App& app);    // app/cmd_batch.cpp
void add_bench_command(CLI::App& app);    // app/cmd_bench.cpp
void add_explore_command(CLI::App& app);  // app/cmd_explore.cpp
void add_compare_command(CLI::App& app);  // app/cmd_compare.cpp
void add_grade_command(CLI::App& app);    // app/cmd_grade.cpp
void add_brdf_check_command(CLI::App& app);  // app/cmd_brdf_check.cpp
void add_plot_command(CLI::App& app);        // app/cmd_plot.cpp
void add_models_command(CLI::App& app);      // app/cmd_models.cpp

// Plain `m3055` (app/cmd_explore.cpp): the explorer when this build has one and
// $DISPLAY is set; otherwise the usage and one line saying why, kExitUsage.
int run_without_subcommand(const CLI::App& app);

// Exit codes shared by the subcommands.
inline constexpr int kExitOk = 0;
inline constexpr int kExitFailure = 1;  // bad input, render or write failure
inline constexpr int kExitUsage = 2;    // command-line usage error (CLI11)

}  // namespace m3055
