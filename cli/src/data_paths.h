// rast — where the command line finds the data it ships with: the corpus and the bunny.
#pragma once

#include <filesystem>
#include <optional>
#include <string_view>

namespace rast::cli {

// PREFIX/share/rast/NAME for the program installed as PREFIX/bin/rast, where that exists.
std::optional<std::filesystem::path> installed_data(std::string_view name);

// The corpus a command takes when none is named: corpus/ in the working directory, else the one installed
// beside the program, else the source tree's that the program was built from (a build run in its build
// tree, anywhere); none where none of them exists.
std::optional<std::filesystem::path> default_corpus();

}  // namespace rast::cli
