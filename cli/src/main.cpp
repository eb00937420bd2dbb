// rast — the command line: render, and the verification commands built on the two rasterizers.
#include "commands.h"

#include <CLI/CLI.hpp>

#include <exception>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
    CLI::App app{
        "rast: a verified triangle rasterizer. An exact reference (CGAL orientation predicates, rational\n"
        "depth) and a fast path (fixed point or float; tiles, SIMD, threads), held against each other.\n"
        "Screen space is y up, pixel centres at (i + 1/2, j + 1/2), the top-left tie rule, smaller z nearer.\n"
        "Exit status: 0 nothing found, 1 a verdict failed (replay, check, conform), 2 bad usage, bad input or an\n"
        "engine error."};
    app.require_subcommand(1);
    app.set_version_flag("--version", "rast " RAST_VERSION);
    int status = 0;
    rast::cli::add_render_command(app);
    rast::cli::add_replay_command(app, status);
    rast::cli::add_check_command(app, status);
    rast::cli::add_diff_command(app);
    rast::cli::add_conform_command(app, status);
#ifdef RAST_WITH_BENCH
    rast::cli::add_bench_command(app);
#endif
    // CLI11 would take an unknown first word for a missing command: name it, and the commands there are.
    if (argc > 1 && argv[1][0] != '-') {
        std::string known;
        bool found = false;
        for (const CLI::App* command : app.get_subcommands({})) {
            known += (known.empty() ? "" : ", ") + command->get_name();
            found = found || command->get_name() == argv[1];
        }
        if (!found) {
            std::cerr << "rast: error: unknown command '" << argv[1] << "' (the commands: " << known << ")\n";
            return 2;
        }
    }
    // docs/design.md's exit status: 0 nothing found, 1 a verdict failed, 2 the command could not do its job
    // (bad usage, bad input, an engine's error).
    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        return app.exit(e) == 0 ? 0 : 2;  // --help is no error
    } catch (const std::exception& e) {
        std::cerr << "rast: error: " << e.what() << '\n';
        return 2;
    }
    return status;
}
