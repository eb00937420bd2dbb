// rast — checks of option values that several commands share, as CLI11 validators.
#pragma once

#include <CLI/CLI.hpp>

#include <cstdint>
#include <string>

namespace rast::cli {

// An empty folder name is refused (it would mean the current folder).
std::string nonempty_folder(const std::string& folder);

// A whole number in decimal digits from 0 to `most`, handed on without leading zeros: CLI11 alone reads 010
// as octal 8, takes +5 and 0x10, wraps a negative value into an unsigned option and saturates one too large.
// `what` names the value in a refusal, e.g. "a seed".
CLI::Validator decimal_number(const std::string& what, std::uint64_t most);

}  // namespace rast::cli
