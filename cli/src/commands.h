// rast — the subcommands. Each registers its options and runs when chosen; errors are exceptions, and a
// command that finds a failure (a property, a check) sets the exit status instead.
#pragma once

#include <CLI/App.hpp>

namespace rast::cli {

void add_render_command(CLI::App& app);
void add_replay_command(CLI::App& app, int& status);
void add_check_command(CLI::App& app, int& status);
void add_diff_command(CLI::App& app);
void add_conform_command(CLI::App& app, int& status);
void add_bench_command(CLI::App& app);  // only with RAST_BUILD_BENCH (it needs the llvmpipe peer)

}  // namespace rast::cli
