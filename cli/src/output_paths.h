// rast — checking a command's output paths before it does any work, so that a bad path costs no time and
// cannot leave some outputs written and others not, and so that no output overwrites an input.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace rast::cli {

// An output the user may have asked for: the option that names it, and the path if the option was given.
struct OutputPath {
    std::string option;               // as the user typed it, e.g. "--ids-out"
    std::optional<std::string> path;  // absent: not asked for
    bool makes_folders = false;       // its missing folders are made when it is written
    bool is_folder = false;           // a folder the command writes its files in, made (and its own) if missing
};

// Throws std::runtime_error naming the option and the path unless every output asked for can be written:
// the path is not empty and names a regular file or nothing yet, its folder exists (or, if it makes_folders,
// the nearest one that does is a folder) and may be written in, and it is neither the same file as one of
// `inputs` nor as another output (the error then names both). An output that is_folder names a folder or
// nothing yet, and may be written in (or the nearest folder that exists, where it would be made).
void check_output_paths(const std::vector<std::filesystem::path>& inputs, const std::vector<OutputPath>& outputs);

}  // namespace rast::cli
