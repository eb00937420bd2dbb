// rast — where the command line finds the data it ships with: the corpus and the bunny.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace rast::cli {

// What installed_data looks for.
enum class DataKind { file, folder };

// PREFIX/DATADIR/rast/NAME for the program installed as PREFIX/BINDIR/rast (the install's own BINDIR and
// DATADIR: bin and share by default), where it exists and is a file or a folder as `kind` says.
std::optional<std::filesystem::path> installed_data(std::string_view name, DataKind kind);

// The corpus a command takes when none is named: corpus/ in the working directory, else the one installed
// beside the program, else the source tree's that the program was built from (a build run in its build
// tree, anywhere); none where none of them exists.
std::optional<std::filesystem::path> default_corpus();

}  // namespace rast::cli
