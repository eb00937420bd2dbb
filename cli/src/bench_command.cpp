// rast bench: every engine and precision mode on the same scenes in one run — speed (median and spread),
// error against the exact reference, hard cases, and the antialiasing error of the sample patterns.
#include "commands.h"
#include "data_paths.h"
#include "output_paths.h"
#include <rast/shell_word.h>

#include <rast/atomic_file.h>
#include <rast/bench_run.h>

#include <rast/plugin_engine.h>

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rast::cli {
namespace {

// The bunny: installed beside the program (data_paths.h), else the source tree's, for a build that is run
// where it was built.
std::string default_mesh() {
    if (auto installed = installed_data("bunny.off", DataKind::file)) return installed->string();
    return RAST_DEFAULT_MESH;
}

struct BenchOptions {
    bool quick = false;
    std::vector<std::string> only;
    std::string mesh = default_mesh();
    std::optional<std::string> json_out, plot_out, aa_plot_out, markdown_out;
    std::vector<std::string> notes;
    std::vector<std::string> plugins;  // --engine plugin:PATH, each
    double plugin_timeout = 60;
};

// The command as it could be typed again, for the report.
std::string bench_command_line(const BenchOptions& o) {
    std::string command = "rast bench";
    if (o.quick) command += " --quick";
    for (const std::string& section : o.only) command += " --only " + section;
    if (o.mesh != default_mesh()) command += " --mesh " + shell_word(o.mesh);
    if (o.json_out) command += " --json " + shell_word(*o.json_out);
    if (o.plot_out) command += " --plot " + shell_word(*o.plot_out);
    if (o.aa_plot_out) command += " --aa-plot " + shell_word(*o.aa_plot_out);
    if (o.markdown_out) command += " --markdown " + shell_word(*o.markdown_out);
    for (const std::string& note : o.notes) command += " --note " + shell_word(note);
    for (const std::string& plugin : o.plugins) command += " --engine " + shell_word(plugin);
    return command;
}

std::string markdown(const bench::Report& report, const BenchOptions& o) {
    std::string out = "# rast bench: speed against error\n\n"
                      "Every figure below comes from one run of the command shown under the machine.\n\n";
    const auto beside = [&](const std::string& path) {
        return std::filesystem::relative(std::filesystem::absolute(path),
                                         std::filesystem::absolute(*o.markdown_out).parent_path())
            .generic_string();
    };
    if (o.plot_out) out += "![speed against error: one point per engine and scene](" + beside(*o.plot_out) + ")\n\n";
    if (o.aa_plot_out)
        out += "![antialiasing error against samples per pixel](" + beside(*o.aa_plot_out) + ")\n\n";
    return out + bench::format_table(report);
}

void run_bench_command(const BenchOptions& o) {
    check_output_paths({o.mesh}, {{"--json", o.json_out},
                                  {"--plot", o.plot_out},
                                  {"--aa-plot", o.aa_plot_out},
                                  {"--markdown", o.markdown_out}});
    bench::Config config;
    config.quick = o.quick;
    if (!o.only.empty()) {
        const auto chosen = [&](const char* section) {
            for (const std::string& s : o.only) if (s == section) return true;
            return false;
        };
        config.speed = chosen("speed");
        config.hard = chosen("hard");
        config.aa = chosen("aa");
        config.lines = chosen("lines");
    }
    config.mesh = o.mesh;
    config.command = bench_command_line(o);
    for (const std::string& plugin : o.plugins) config.plugins.push_back(plugin_engine(plugin.substr(7), {o.plugin_timeout}));
    bench::Report report = bench::run_bench(config, std::cerr);
    report.notes.insert(report.notes.end(), o.notes.begin(), o.notes.end());
    std::cout << bench::format_table(report);
    // Every file's bytes first, so that nothing is written unless all of them could be made.
    std::vector<std::pair<std::string, std::string>> files;
    if (o.json_out) files.emplace_back(*o.json_out, bench::format_json(report));
    if (o.plot_out) files.emplace_back(*o.plot_out, bench::format_svg(report));
    if (o.aa_plot_out) files.emplace_back(*o.aa_plot_out, bench::format_aa_svg(report));
    if (o.markdown_out) files.emplace_back(*o.markdown_out, markdown(report, o));
    write_files_atomic(std::vector<FileContent>(files.begin(), files.end()));
}

}  // namespace

void add_bench_command(CLI::App& app) {
    auto options = std::make_shared<BenchOptions>();
    CLI::App* bench = app.add_subcommand(
        "bench",
        "Time every engine (reference; fast fixed4/8/16, float32/64 on 1 and 2 threads; llvmpipe) on the\n"
        "same scenes and measure each one's error against the exact reference; hard-case families; the\n"
        "antialiasing error of 1/4/8/16 samples against the exact area and, z-buffered, against the exact\n"
        "visible area; lines by the exact diamond-exit rule, Bresenham and the DDA. Progress on stderr,\n"
        "tables on stdout.");
    bench->add_flag("--quick", options->quick, "Small scenes and few runs: under a minute (CI smoke test)");
    CLI::Option* only = bench->add_option("--only", options->only, "Run only these sections")
                            ->check(CLI::IsMember({"speed", "hard", "aa", "lines"}));
    // Only the speed and antialiasing sections render the mesh: with neither, it would be ignored. Parsing
    // has read every argument before any option is checked, so --only's values are there to look at.
    const auto rendered = [only](const std::string&) -> std::string {
        if (only->count() == 0) return {};
        for (const std::string& section : only->results())
            if (section == "speed" || section == "aa") return {};
        return "no section chosen with --only renders a mesh (speed and aa do)";
    };
    bench->add_option("--mesh", options->mesh, "The real mesh to render (by the speed and aa sections)")
        ->check(CLI::ExistingFile)
        ->check(rendered)
        ->capture_default_str();
    bench->add_option("--json", options->json_out, "Write every figure as JSON");
    bench->add_option("--plot", options->plot_out, "Write the speed-against-error plot as SVG");
    bench->add_option("--aa-plot", options->aa_plot_out,
                      "Write the antialiasing plot as SVG: mean error against samples per pixel, against the "
                      "exact visible area and depth ignored")
        ->check([only](const std::string&) -> std::string {
            if (only->count() == 0) return {};
            for (const std::string& section : only->results())
                if (section == "aa") return {};
            return "no section chosen with --only measures antialiasing (aa does)";
        });
    bench->add_option("--markdown", options->markdown_out, "Write the tables as Markdown, with the plots");
    bench->add_option("--note", options->notes, "A remark for the report, e.g. about the machine");
    CLI::Option* engine =
        bench->add_option("--engine", options->plugins,
                          "Also time and measure plugin:PATH, a rasterizer plugin (repeatable), on the speed and "
                          "hard-case scenes its contract renders")
            ->type_name("plugin:PATH")
            ->check([](const std::string& s) {
                return s.starts_with("plugin:") && s.size() > 7 ? std::string{} : "expected plugin:PATH";
            });
    bench->add_option("--plugin-timeout", options->plugin_timeout,
                      "Seconds a plugin may take to load, and to render one scene, before it is stopped")
        ->check(CLI::Range(0.001, 86400.0))
        ->needs(engine)
        ->capture_default_str();
    bench->callback([options] { run_bench_command(*options); });
}

}  // namespace rast::cli
