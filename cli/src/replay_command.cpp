// rast replay: every corpus case, every property its header names, every engine; one line per case.
#include "commands.h"
#include "data_paths.h"
#include "engine_choice.h"
#include "replay.h"

#include <CLI/CLI.hpp>

#include <filesystem>
#include <iostream>
#include <memory>
#include <stdexcept>
#include <vector>

namespace rast::cli {

void add_replay_command(CLI::App& app, int& status) {
    auto paths = std::make_shared<std::vector<std::filesystem::path>>();
    auto choice = std::make_shared<EngineChoice>();
    CLI::App* cmd = app.add_subcommand(
        "replay",
        "Replay corpus cases (.tri files, or folders of them; default: corpus/ here, else the installed corpus,\n"
        "else the source tree's). Each case's '# properties:' header names the properties that apply; each runs\n"
        "on the reference and on every fast precision it applies to, or on the one engine --engine names (a\n"
        "plugin, say). One line per case: PASS, FAIL with the property, engine and first differing sample, or\n"
        "ERROR path:line for a malformed file (the other cases still run), or SKIP where nothing applies to the\n"
        "chosen engine. Then 'N passed, M failed' (errors count as failed). Exit status 0 when every case\n"
        "passed, 1 when a case failed, 2 when a case could not be read or is malformed, or the engine failed.\n"
        "Files are only read.");
    cmd->add_option("PATH", *paths, "Case files or folders")->default_str("corpus");
    add_engine_options(*cmd, *choice);
    CLI::Option* engine = cmd->get_option("--engine");
    engine->default_str("every built-in engine");
    cmd->callback([paths, choice, engine, &status] {
        if (paths->empty()) {
            const auto corpus = default_corpus();
            if (!corpus)
                throw std::runtime_error("no case given, and no corpus to replay (none here, installed or in the "
                                         "source tree): name the cases or folders (rast replay PATH...)");
            paths->push_back(*corpus);
        }
        const bool chosen = engine->count() > 0;
        const auto engines = chosen ? std::vector<Engine>{choice->make()} : all_engines();
        const auto files = corpus_files(*paths);
        if (files.empty()) throw std::runtime_error("no .tri case found: nothing to replay");
        std::size_t passed = 0, failed = 0, skipped = 0;
        bool unusable = false;  // a case that is malformed or cannot be read: bad input, not a verdict
        for (const auto& entry : files) {
            const CaseReport report =
                replay_entry(entry, engines, chosen ? EngineScope::chosen : EngineScope::built_in);
            std::cout << report.line << std::endl;
            (report.status == CaseReport::Status::pass   ? passed
             : report.status == CaseReport::Status::skip ? skipped
                                                         : failed) += 1;
            unusable = unusable || report.status == CaseReport::Status::error;
        }
        std::cout << passed << " passed, " << failed << " failed";
        if (skipped > 0) std::cout << ", " << skipped << " skipped (nothing in them applies to the engine)";
        std::cout << '\n';
        status = unusable ? 2 : failed > 0 ? 1 : 0;
    });
}

}  // namespace rast::cli
