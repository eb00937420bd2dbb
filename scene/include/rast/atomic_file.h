// rast — writing an output file so that a reader sees either the old content or all of the new one.
#pragma once

#include <filesystem>
#include <span>
#include <string_view>
#include <utility>

namespace rast {

// Writes `bytes` to a new temporary file next to `target`, flushes and fsyncs it, renames it over `target`
// and fsyncs the directory. On failure throws std::system_error naming the path and the step that failed,
// worded for a user ("cannot write 'PATH': STEP: REASON"), removes the temporary and leaves `target` as it
// was; the one exception is a failed fsync of the directory, after the rename: the new content is then in
// place but might not survive a crash, and the error says so. The new file gets the permissions of a newly
// created file (0666 minus the umask).
void write_file_atomic(const std::filesystem::path& target, std::string_view bytes);

// A file to write: where, and its bytes.
using FileContent = std::pair<std::filesystem::path, std::string_view>;

// write_file_atomic for several files at once, all or nothing: every file's temporary is written, flushed
// and fsynced before any of them is renamed into place, so that a failure while writing one (a full disk, a
// name too long, a folder not writable) leaves every target as it was. A rename that fails after others
// succeeded cannot be undone; the error then names the targets already replaced.
void write_files_atomic(std::span<const FileContent> files);

}  // namespace rast
