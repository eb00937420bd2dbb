#include "output_paths.h"

#include <unistd.h>

#include <cerrno>
#include <stdexcept>
#include <system_error>

namespace rast::cli {
namespace {

namespace fs = std::filesystem;

// Two existing paths are the same file when they reach the same inode (through hard or symbolic links), and
// an existing path is never the same file as one not yet there (an input piped in as /dev/stdin resolves
// to no name at all); two paths not yet there are the same when both resolve to one name. Made absolute
// first: weakly_canonical leaves a bare relative name that does not exist as it is ("x" against "./x").
bool same_file(const fs::path& a, const fs::path& b) {
    const bool a_exists = fs::exists(a);
    if (a_exists != fs::exists(b)) return false;
    if (a_exists) return fs::equivalent(a, b);
    return fs::weakly_canonical(fs::absolute(a)) == fs::weakly_canonical(fs::absolute(b));
}

// Why `output` cannot be written, or nothing if it can.
std::optional<std::string> unwritable(const OutputPath& output) {
    const fs::path path = *output.path;
    if (path.empty()) return "the path is empty";
    const fs::file_status status = fs::status(path);
    // The folder its files are made in: the path itself for a folder, else the file's.
    fs::path own = path;
    if (output.is_folder) {
        if (fs::exists(status) && !fs::is_directory(status)) return "exists and is not a folder";
    } else {
        if (!path.has_filename()) return "the path names a folder, not a file";
        if (fs::is_directory(status)) return "is a folder";
        // The file is replaced by renaming a new one over it: that would replace a device or a pipe, not write
        // to it.
        if (fs::exists(status) && !fs::is_regular_file(status)) return "exists and is not a regular file";
        own = path.has_parent_path() ? path.parent_path() : fs::path(".");
    }
    fs::path folder = own;
    // The missing folders would be made in the nearest one that exists.
    if (output.makes_folders || output.is_folder)
        while (!fs::exists(folder) && folder != ".") folder = folder.has_parent_path() ? folder.parent_path() : ".";
    if (!fs::exists(folder)) return "its folder '" + folder.string() + "' does not exist";
    if (!fs::is_directory(folder)) return "its parent '" + folder.string() + "' is not a folder";
    // A new file is made in the folder (and renamed into place), which needs write and search permission.
    if (::access(folder.c_str(), W_OK | X_OK) != 0)
        return (folder == path ? std::string("cannot write in it")
                : folder == own ? "cannot write in its folder '" + folder.string() + "'"
                                : "cannot make its folder in '" + folder.string() + "'") +
               ": " + std::error_code(errno, std::generic_category()).message();
    return std::nullopt;
}

}  // namespace

void check_output_paths(const std::vector<fs::path>& inputs, const std::vector<OutputPath>& outputs) {
    std::vector<const OutputPath*> earlier;
    for (const OutputPath& output : outputs) {
        if (!output.path) continue;
        const std::string named = output.option + " '" + *output.path + "'";
        try {
            if (const auto why = unwritable(output))
                throw std::runtime_error(named + ": " + *why);
            for (const fs::path& input : inputs)
                if (same_file(*output.path, input))
                    throw std::runtime_error(named + " is the same file as the input '" + input.string() +
                                             "': refusing to overwrite it");
            for (const OutputPath* other : earlier)
                if (same_file(*output.path, *other->path))
                    throw std::runtime_error(named + " is the same file as " + other->option + " '" + *other->path +
                                             "': give each output its own path");
        } catch (const fs::filesystem_error& e) {
            throw std::runtime_error(named + ": cannot check the path: " + e.code().message());
        }
        earlier.push_back(&output);
    }
}

}  // namespace rast::cli
