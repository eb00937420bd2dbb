// rast — writing an output file so that a reader sees either the old content or all of the new one.
#pragma once

#include <filesystem>
#include <string_view>

namespace rast {

// Writes `bytes` to a new temporary file next to `target`, flushes and fsyncs it, renames it over `target`
// and fsyncs the directory. On failure throws std::system_error naming the path and the step that failed,
// worded for a user ("cannot write 'PATH': STEP: REASON"), removes the temporary and leaves `target` as it
// was; the one exception is a failed fsync of the directory, after the rename: the new content is then in
// place but might not survive a crash, and the error says so. The new file gets the permissions of a newly
// created file (0666 minus the umask).
void write_file_atomic(const std::filesystem::path& target, std::string_view bytes);

}  // namespace rast
