// rast — the one error type for bad input files (.tri scenes, meshes).
#pragma once

#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>

namespace rast {

// A file that cannot be read or is malformed. what() is "file:line: message", or "file: message" when the
// problem belongs to no single line (line == 0), the form compilers use so editors can jump to it.
struct ParseError : std::runtime_error {
    ParseError(std::string file, std::int64_t line, std::string message);

    std::string file;
    std::int64_t line;  // 1-based; 0 when not line-specific
    std::string message;
};

// A token quoted for an error message: at most 40 characters, non-printable bytes escaped, so a binary
// file fed to a text reader gives a readable message.
std::string quote_token(std::string_view token);

}  // namespace rast
