#include "data_paths.h"

#include <string>
#include <system_error>

namespace rast::cli {

namespace fs = std::filesystem;

std::optional<fs::path> installed_data(std::string_view name, DataKind kind) {
    std::error_code unseen;
    const fs::path program = fs::read_symlink("/proc/self/exe", unseen);
    if (unseen) return std::nullopt;
    const fs::path data = (program.parent_path() / RAST_DATA_FROM_BIN / "rast" / name).lexically_normal();
    const bool found = kind == DataKind::folder ? fs::is_directory(data, unseen) : fs::is_regular_file(data, unseen);
    if (!found) return std::nullopt;
    return data;
}

std::optional<fs::path> default_corpus() {
    std::error_code unseen;
    if (fs::is_directory("corpus", unseen)) return fs::path("corpus");
    if (auto installed = installed_data("corpus", DataKind::folder)) return installed;
    if (fs::is_directory(RAST_SOURCE_CORPUS, unseen)) return fs::path(RAST_SOURCE_CORPUS);
    return std::nullopt;
}

}  // namespace rast::cli
