// rast conform PLUGIN [SCENE...]: the exact verdict on a rasterizer plugin against the contract it
// declares, on the scenes given or on the battery, each failure shrunk, kept and drawn.
#include <rast/atomic_file.h>
#include <rast/conform.h>
#include <rast/plugin_engine.h>

#include <CLI/CLI.hpp>

#include <charconv>
#include <limits>
#include <filesystem>
#include <iostream>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "commands.h"
#include "conform_reports.h"
#include "data_paths.h"
#include "option_checks.h"
#include "output_paths.h"
#include "progress_meter.h"
#include "replay.h"
#include "wording.h"

namespace rast::cli {
namespace {

namespace fs = std::filesystem;

struct ConformOptions {
    std::string library;
    std::vector<std::string> scenes;
    int cases = 100;
    std::uint64_t seed = 1;
    std::string shard = "1/1";
    std::optional<std::string> corpus;
    std::string found = "corpus/found";
    bool found_given = false;  // --found on the command line
    std::optional<std::string> json, markdown;
    double timeout = 60;
};

// "K/N" with 1 <= K <= N: shard K - 1 of N.
std::pair<int, int> parse_shard(const std::string& text) {
    const auto slash = text.find('/');
    int k = 0, n = 0;
    const auto read = [](std::string_view s, int& v) {
        const auto [end, error] = std::from_chars(s.data(), s.data() + s.size(), v);
        return error == std::errc{} && end == s.data() + s.size();
    };
    if (slash == std::string::npos || !read(std::string_view(text).substr(0, slash), k) ||
        !read(std::string_view(text).substr(slash + 1), n) || n < 1 || k < 1 || k > n)
        throw std::invalid_argument("--shard " + text + ": expected K/N with 1 <= K <= N (this run is shard K of N)");
    return {k - 1, n};
}

// The corpus the battery starts with: --corpus, else the default one (data_paths.h).
std::optional<fs::path> corpus_folder(const ConformOptions& o) {
    if (o.corpus) return fs::path(*o.corpus);
    return default_corpus();
}

std::vector<conform::Case> read_cases(const std::vector<fs::path>& paths) {
    std::vector<conform::Case> cases;
    for (const CorpusEntry& entry : corpus_files(paths)) {
        if (entry.unlisted)
            throw std::runtime_error("cannot list " + entry.path.string() + ": " + *entry.unlisted);
        // The cases this battery keeps are findings about engines, not part of the battery.
        if (entry.path.parent_path().filename() == "found") continue;
        cases.push_back(conform::read_case(entry.path));
    }
    return cases;
}

// The plugin as --engine names it in a kept case's replay command: absolute, so that it replays from
// anywhere.
std::string engine_path(const std::string& library) {
    std::error_code unseen;
    const fs::path absolute = fs::absolute(library, unseen);
    return unseen ? library : absolute.string();
}

int run_conform(const ConformOptions& o) {
    const auto [shard, shards] = parse_shard(o.shard);
    // A --found the user named is checked before the work (made if missing); the default is not: most runs
    // keep nothing.
    const std::optional<std::string> found = o.found_given ? std::optional(o.found) : std::nullopt;
    check_output_paths({o.scenes.begin(), o.scenes.end()},
                       {{"--json", o.json}, {"--markdown", o.markdown}, {"--found", found, false, true}});

    const Engine engine = plugin_engine(o.library, {o.timeout});
    std::vector<conform::Case> cases;
    ConformRun run{o.library, ""};
    if (!o.scenes.empty()) {
        for (const auto& scene : o.scenes) cases.push_back(conform::read_case(scene));
        run.battery = counted(cases.size(), "scene", "scenes") + " given";
    } else {
        const auto corpus = corpus_folder(o);
        if (corpus) cases = read_cases({*corpus});
        run.battery = "the battery: " + counted(cases.size(), "corpus case", "corpus cases") +
                      (corpus ? " (" + corpus->string() + ")" : " (no corpus found: --corpus DIR)") + ", then " +
                      counted(o.cases, "generated case", "generated cases") + " a property, seed " +
                      std::to_string(o.seed) + ", shard " + std::to_string(shard + 1) + "/" + std::to_string(shards);
    }
    std::cout << "engine:   " << engine.description << "\ncontract: " << engine.contract->text() << "\njudged:   "
              << run.battery << '\n';

    conform::Options options;
    options.cases = o.cases;
    options.seed = o.seed;
    options.shard = shard;
    options.shards = shards;
    options.found = fs::path(o.found);
    options.engine_option = "plugin:" + engine_path(o.library);
    std::unique_ptr<ProgressMeter> meter;
    std::string metered;
    options.progress = [&](const std::string& property, std::size_t done, std::size_t total) {
        if (!meter || property != metered) {
            meter = stderr_meter("conform " + property, "cases");
            metered = property;
        }
        meter->update(done, total);
    };

    conform::Verdict verdict;
    try {
        verdict = o.scenes.empty() ? conform::battery(engine, cases, options) : conform::judge(engine, cases, options);
    } catch (const conform::EngineFailure& e) {
        meter.reset();
        throw EngineError(std::string(e.what()) +
                          (e.kept.empty() ? "" : "; the scene is kept in " + e.kept.string() + " (rast replay --engine " +
                                                     options.engine_option + " " + e.kept.string() + ")"));
    }
    meter.reset();

    // Pictures and reports are written together at the end. A picture renders the case again: an engine
    // that fails then costs the picture, not the verdict.
    std::vector<std::pair<std::string, std::string>> files;
    std::size_t passed = 0, failed = 0, skipped = 0;
    for (const auto& p : verdict.properties) {
        if (!p.failure) {
            if (p.checked == 0) {
                ++skipped;
                std::cout << "SKIP " << p.property << " (no scene it applies to";
                if (p.not_applicable > 0) std::cout << ": " << p.not_applicable << " outside its precondition here";
                std::cout << ")\n";
            } else {
                ++passed;
                std::cout << "PASS " << p.property << " (" << counted(p.checked, "scene", "scenes") << ")\n";
            }
            continue;
        }
        ++failed;
        const conform::Finding& f = *p.failure;
        std::cout << "FAIL " << p.property << ": " << f.detail << "\n     shrunk from " << f.original_triangles
                  << " to " << counted(f.scene.triangles.size(), "triangle", "triangles") << " (" << f.origin << ")";
        if (!f.kept.empty()) {
            fs::path picture = f.kept;
            picture.replace_extension(".png");
            std::cout << "\n     kept: " << f.kept.string();
            try {
                files.emplace_back(picture.string(), counterexample_png(engine, f));
                std::cout << " and " << picture.filename().string() << " (demanded | engine | reference)";
            } catch (const EngineError& e) {
                std::cout << " (no picture: " << e.what() << ")";
            }
        }
        std::cout << '\n';
    }
    std::cout << passed << " passed, " << failed << " failed";
    if (skipped > 0) std::cout << ", " << skipped << " skipped";
    std::cout << '\n';
    if (o.json) files.emplace_back(*o.json, conform_json(run, verdict));
    if (o.markdown) files.emplace_back(*o.markdown, conform_markdown(run, verdict));
    write_files_atomic(std::vector<FileContent>(files.begin(), files.end()));
    if (o.json) std::cout << "wrote " << *o.json << '\n';
    if (o.markdown) std::cout << "wrote " << *o.markdown << '\n';
    return failed > 0 ? 1 : 0;
}

}  // namespace

void add_conform_command(CLI::App& app, int& status) {
    auto o = std::make_shared<ConformOptions>();
    CLI::App* cmd = app.add_subcommand(
        "conform",
        "Judge a rasterizer plugin (rast/plugin.h) against the contract it declares, exactly: every sample\n"
        "required, forbidden or free as the contract allows, ids in the (z, id) order, and every property\n"
        "the contract implies. With scenes, judges those (conforms on each, and the properties each one's\n"
        "'# properties:' header names); without, runs the battery: the corpus, then --cases generated scenes\n"
        "for each property. Each failure is shrunk to a minimal scene, kept under --found with a picture, and\n"
        "replays with 'rast replay --engine plugin:PLUGIN CASE'. One line per property, PASS or FAIL with the\n"
        "first violating sample, then 'N passed, M failed'. Exit status 0 when the engine conforms, 1 on a\n"
        "violation, 2 on bad usage or a plugin that fails (loads, crashes, hangs, returns an error or a bad id).");
    cmd->add_option("PLUGIN", o->library, "The plugin: a shared library with the plugin ABI")->required();
    CLI::Option* scenes =
        cmd->add_option("SCENE", o->scenes, "Scenes (.tri) to judge instead of the battery")->check(CLI::ExistingFile);
    // The battery's own options: with scenes they would be ignored.
    CLI::Option* const battery[] = {
        cmd->add_option("--cases", o->cases, "Generated scenes a property (the battery only)")
            ->transform(decimal_number("a count of cases", 100000000))
            ->capture_default_str(),
        cmd->add_option("--seed", o->seed, "The battery's seed: the same seed, shard and cases give the same scenes")
            ->transform(decimal_number("a seed", std::numeric_limits<std::uint64_t>::max()))
            ->capture_default_str(),
        cmd->add_option("--shard", o->shard,
                        "Run shard K of N (K/N): each shard's generated scenes come from seeds of its own, and kept "
                        "cases are named by their content, so shards share a --found folder")
            ->capture_default_str(),
        cmd->add_option("--corpus", o->corpus,
                        "The corpus the battery starts with (default: corpus/ here, else the installed one, else the\n"
                        "source tree's the program was built from)")
            ->check(CLI::ExistingDirectory)};
    for (CLI::Option* option : battery) scenes->excludes(option);
    CLI::Option* found =
        cmd->add_option("--found", o->found, "Where shrunk counterexamples are kept (made if missing)")
            ->check(nonempty_folder)
            ->capture_default_str();
    cmd->add_option("--json", o->json, "Write the verdict as JSON");
    cmd->add_option("--markdown", o->markdown, "Write the verdict as a Markdown report");
    cmd->add_option("--plugin-timeout", o->timeout,
                    "Seconds the plugin may take to load, and to render one scene, before it is stopped")
        ->check(CLI::Range(0.001, 86400.0))
        ->capture_default_str();
    cmd->callback([o, found, &status] {
        o->found_given = found->count() > 0;
        status = run_conform(*o);
    });
}

}  // namespace rast::cli
