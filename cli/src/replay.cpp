#include "replay.h"
#include "wording.h"

#include <rast/tri_format.h>

#include <algorithm>
#include <cerrno>
#include <fstream>
#include <optional>
#include <set>
#include <sstream>
#include <system_error>

namespace rast::cli {
namespace {

namespace fs = std::filesystem;
using properties::Failure;
using properties::Property;

// A problem with the case file itself rather than with an engine.
struct CaseError {
    std::int64_t line;  // 0: the file as a whole
    std::string message;
};

CaseReport error_report(const fs::path& file, const CaseError& e) {
    std::string line = "ERROR ";
    line += file.string();
    if (e.line > 0) {
        line += ':';
        line += std::to_string(e.line);
    }
    line += ": " + e.message;
    return {CaseReport::Status::error, std::move(line), {}};
}

// The whole file, read once: the parser gets it, and header problems are located in it.
std::string read_text(const fs::path& file) {
    std::error_code unseen;
    if (fs::is_directory(file, unseen)) throw CaseError{0, "is a folder, not a case"};
    std::ifstream in(file, std::ios::binary);
    if (!in) throw CaseError{0, "cannot open: " + std::generic_category().message(errno)};
    std::ostringstream text;
    text << in.rdbuf();
    if (in.bad()) throw CaseError{0, "cannot read"};
    return text.str();
}

// The line of the first "# key:" comment anywhere in the file, so that a bad header value is reported
// where it is written.
std::optional<std::int64_t> key_line(const std::string& text, std::string_view key) {
    std::istringstream lines(text);
    std::string line;
    for (std::int64_t number = 1; std::getline(lines, line); ++number) {
        std::string_view rest(line);
        const auto skip_blanks = [&rest] {
            while (!rest.empty() && (rest.front() == ' ' || rest.front() == '\t')) rest.remove_prefix(1);
        };
        skip_blanks();
        if (rest.empty() || rest.front() != '#') continue;
        rest.remove_prefix(1);
        skip_blanks();
        if (rest.starts_with(key) && rest.substr(key.size()).starts_with(':')) return number;
    }
    return std::nullopt;
}

// 1 when the key is missing: the header belongs at the top.
std::int64_t header_line(const std::string& text, std::string_view key) { return key_line(text, key).value_or(1); }

// The properties the header names, each once, all known.
std::vector<const Property*> named_properties(const TriDocument& doc, const std::string& text) {
    const std::vector<std::string> keys = [&] {
        std::vector<std::string> values;
        for (const auto& [key, value] : doc.header)
            if (key == "properties") values.push_back(value);
        return values;
    }();
    const std::int64_t line = header_line(text, "properties");
    if (keys.empty()) {
        // The header is the comments before the first statement (corpus/README.md); a key after it is a
        // plain comment.
        if (key_line(text, "properties"))
            throw CaseError{line, "the '# properties:' header must come before the first statement"};
        throw CaseError{line, "no '# properties:' header naming the properties that apply"};
    }
    if (keys.size() > 1) throw CaseError{line, "more than one '# properties:' header; name them all on one line"};

    std::vector<const Property*> selected;
    std::set<std::string> seen;
    std::istringstream names(keys.front());
    for (std::string name; names >> name;) {
        if (!seen.insert(name).second) throw CaseError{line, "property '" + name + "' is named twice"};
        try {
            selected.push_back(&properties::property(name));
        } catch (const std::invalid_argument& e) {
            throw CaseError{line, e.what()};
        }
    }
    if (selected.empty()) throw CaseError{line, "'# properties:' names no property"};
    return selected;
}

// Every property and engine pair is a check, not applicable to the scene, or outside the engine's contract
// (Property::applies_to): the three add up to the pairs.
std::string pass_line(const fs::path& file, std::size_t properties, std::size_t engines, std::size_t checks,
                      std::size_t not_applicable) {
    return "PASS " + file.string() + " (" + counted(properties, "property", "properties") + " x " +
           counted(engines, "engine", "engines") + ": " + counted(checks, "check", "checks") + ", " +
           std::to_string(not_applicable) + " not applicable, " +
           std::to_string(properties * engines - checks - not_applicable) + " outside a contract)";
}

std::string fail_line(const fs::path& file, const std::vector<Failure>& failures) {
    const Failure& first = failures.front();
    std::string line = "FAIL " + file.string() + " " + first.property + " [" + first.engine + "]: " + first.detail;
    if (failures.size() > 1) line += " (and " + std::to_string(failures.size() - 1) + " more failures)";
    return line;
}

// Every .tri file below `folder` (following links to files, not to folders, as recursive_directory_iterator
// does); a folder that cannot be listed is an entry of its own, with the reason. A .tri name whose file
// cannot be looked at (a link into a folder that cannot be entered, or to nothing) is a case too, which
// replay_case reports as unreadable; folders, and files that are not regular (a FIFO would block the
// read), are not cases.
void collect_cases(const fs::path& folder, std::vector<CorpusEntry>& found) {
    std::error_code error;
    fs::directory_iterator entries(folder, error);
    for (; !error && entries != fs::directory_iterator(); entries.increment(error)) {
        const fs::directory_entry& entry = *entries;
        std::error_code unseen;
        const fs::file_status status = entry.status(unseen);
        std::error_code unlinked;
        if (status.type() == fs::file_type::directory && !entry.is_symlink(unlinked)) collect_cases(entry.path(), found);
        else if (entry.path().extension() == ".tri" &&
                 (unseen || fs::is_regular_file(status) || status.type() == fs::file_type::not_found))
            found.push_back({entry.path(), {}});
    }
    if (error) found.push_back({folder, error.message()});
}

}  // namespace

std::vector<CorpusEntry> corpus_files(std::span<const fs::path> paths) {
    std::vector<CorpusEntry> entries;
    for (const fs::path& path : paths) {
        // Not the throwing overload: a file in a folder that may be listed but not entered cannot be
        // stat'ed, and replay_case reports it.
        std::error_code not_a_folder;
        if (!fs::is_directory(path, not_a_folder)) {
            entries.push_back({path, {}});
            continue;
        }
        std::vector<CorpusEntry> found;
        collect_cases(path, found);
        std::sort(found.begin(), found.end(), [](const CorpusEntry& a, const CorpusEntry& b) { return a.path < b.path; });
        entries.insert(entries.end(), found.begin(), found.end());
    }
    return entries;
}

CaseReport replay_entry(const CorpusEntry& entry, std::span<const Engine> engines, EngineScope scope) {
    if (entry.unlisted) return error_report(entry.path, {0, "cannot list the folder: " + *entry.unlisted});
    return replay_case(entry.path, engines, scope);
}

CaseReport replay_case(const fs::path& file, std::span<const Engine> engines, EngineScope scope) {
    std::string text;
    TriDocument doc;
    std::vector<const Property*> selected;
    try {
        text = read_text(file);
        std::istringstream in(text);
        doc = read_tri_document(in, file.string());
        selected = named_properties(doc, text);
    } catch (const CaseError& e) {
        return error_report(file, e);
    } catch (const ParseError& e) {
        return {CaseReport::Status::error, std::string("ERROR ") + e.what(), {}};
    }

    if (doc.scene.triangles.empty() && doc.scene.lines.empty())
        return error_report(file, {0, "has no triangle and no line: it tests nothing"});

    properties::CaseCheck result = properties::check_case(doc.scene, selected, engines);
    std::vector<Failure>& failures = result.failures;
    if (!failures.empty()) return {CaseReport::Status::fail, fail_line(file, failures), std::move(failures)};
    if (scope == EngineScope::chosen && result.checks == 0)
        return {CaseReport::Status::skip,
                "SKIP " + file.string() + ": " +
                    (result.unchecked.empty() ? "no named property applies to the engine" : result.unchecked),
                {}};
    // A property named in the header holds for the case by construction (corpus/README.md): one that no
    // engine can check here claims what the case does not test.
    if (!result.unchecked.empty())
        return error_report(file, {header_line(text, "properties"),
                                   "a named property checks nothing (" + result.unchecked + ")"});
    // Left: no named property applies to any of the engines replayed.
    if (result.checks == 0)
        return error_report(file,
                            {header_line(text, "properties"), "checks nothing: no named property applies to any engine"});
    return {CaseReport::Status::pass,
            pass_line(file, selected.size(), engines.size(), result.checks, result.not_applicable), {}};
}

}  // namespace rast::cli
