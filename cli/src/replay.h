// rast — replaying corpus cases: every property a case's header names, on every engine it applies to.
// The core of `rast replay`, kept apart from the command so that it can be run on other engines (a
// deliberately broken fast path in the tests). Replay only reads: files are opened for reading, never
// rewritten, reordered or touched.
#pragma once

#include <rast/properties.h>

#include <filesystem>
#include <optional>
#include <span>
#include <string>
#include <vector>

namespace rast::cli {

// One entry of the cases to replay: a .tri file, or a folder that could not be listed, with the reason.
struct CorpusEntry {
    std::filesystem::path path;
    std::optional<std::string> unlisted;  // a folder: why it could not be listed
    bool operator==(const CorpusEntry&) const = default;
};

// The cases to replay: a file is taken as given; a folder contributes every .tri file below it, in path
// order, so that a run's output is the same everywhere. A folder that cannot be listed is an entry of
// its own: replay_entry reports it as an error, and the other cases still run.
std::vector<CorpusEntry> corpus_files(std::span<const std::filesystem::path> paths);

struct CaseReport {
    enum class Status { pass, fail, error, skip };
    Status status = Status::pass;
    // The one line printed for the case:
    //   PASS path (P properties x E engines: C checks, N not applicable)
    //   FAIL path property [engine]: what differs, at which sample (and K more failures)
    //   ERROR path:line: what is wrong with the file
    //   SKIP path: why nothing applies to the one engine chosen
    std::string line;
    std::vector<properties::Failure> failures;  // in property then engine order
};

// Which engines replay runs: rast's own (every case must check something on them), or one the user chose,
// which may promise less than a case needs (a plugin with fewer sample counts or a weaker contract).
enum class EngineScope { built_in, chosen };

// Reads the case, runs each property of its "# properties:" header on each engine it applies to. A file
// that cannot be read, is malformed, names no property, an unknown one or one twice is an error; so is one
// whose properties check nothing on the built-in engines. On a chosen engine, that case is skipped.
CaseReport replay_case(const std::filesystem::path& file, std::span<const Engine> engines,
                       EngineScope scope = EngineScope::built_in);

// replay_case for a file; for a folder that could not be listed, an error that says why.
CaseReport replay_entry(const CorpusEntry& entry, std::span<const Engine> engines,
                        EngineScope scope = EngineScope::built_in);

}  // namespace rast::cli
