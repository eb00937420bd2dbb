#include "kept_case.h"

#include <rast/shell_word.h>
#include <rast/tri_format.h>

#include <cstdint>
#include <cstdio>
#include <sstream>

namespace rast::conform::detail {

namespace {

// FNV-1a, 64 bits: a name that depends on the scene alone, the same on every machine.
std::uint64_t fnv1a(const std::string& text) {
    std::uint64_t h = 0xcbf29ce484222325ULL;
    for (const char c : text) {
        h ^= static_cast<unsigned char>(c);
        h *= 0x100000001b3ULL;
    }
    return h;
}

}  // namespace

std::filesystem::path keep_case(const std::filesystem::path& folder, const Scene& scene, const KeptCase& what) {
    std::ostringstream body;
    write_tri(body, scene, {});
    char digits[17];
    std::snprintf(digits, sizeof digits, "%016llx", static_cast<unsigned long long>(fnv1a(body.str())));
    const auto path = folder / (what.engine + "-" + what.property + "-" + digits + ".tri");
    TriHeader header;
    // A case the engine failed outright on replays through the property that was running and conforms,
    // which renders the case itself.
    const bool engine_error = what.property == "engine-error";
    header.push_back({"properties", !engine_error              ? what.property
                                    : what.running == "conforms" ? "conforms"
                                                                 : what.running + " conforms"});
    header.push_back({"why", header_value("rast conform [" + what.engine + "]: " + what.why)});
    header.push_back({"found-by", "rast conform"});
    if (!what.contract.empty()) header.push_back({"contract", what.contract});
    header.push_back({"reproduce", "rast replay --engine " + shell_word(what.engine_option) + " " + shell_word(path.string())});
    std::filesystem::create_directories(folder);
    write_tri_file(path, scene, header);
    return path;
}

}  // namespace rast::conform::detail
