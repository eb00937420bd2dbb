#include "rast/atomic_file.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <atomic>
#include <cerrno>
#include <optional>
#include <string>
#include <system_error>
#include <vector>

namespace rast {

namespace {

[[noreturn]] void fail(int error, const std::string& what) {
    throw std::system_error(error, std::generic_category(), what);
}

// The error of a step that left `target` as it was.
[[noreturn]] void cannot_write(int error, const std::filesystem::path& target, const std::string& step) {
    fail(error, "cannot write '" + target.string() + "': " + step);
}

// Closes the descriptor and removes the temporary unless the rename has taken it over.
class Temporary {
public:
    Temporary(std::string path, int fd) : path_(std::move(path)), fd_(fd) {}
    Temporary(Temporary&& other) noexcept : path_(std::move(other.path_)), fd_(other.fd_) {
        other.path_.clear();
        other.fd_ = -1;
    }
    Temporary(const Temporary&) = delete;
    Temporary& operator=(const Temporary&) = delete;
    Temporary& operator=(Temporary&&) = delete;
    ~Temporary() {
        if (fd_ >= 0) ::close(fd_);
        if (!path_.empty()) ::unlink(path_.c_str());
    }

    const std::string& path() const { return path_; }
    int fd() const { return fd_; }

    // close() can report a deferred write error (NFS, quotas), so its result matters.
    int close() {
        const int result = ::close(fd_);
        fd_ = -1;
        return result;
    }
    void committed() { path_.clear(); }

private:
    std::string path_;
    int fd_;
};

std::filesystem::path directory_of(const std::filesystem::path& target) {
    return target.has_parent_path() ? target.parent_path() : std::filesystem::path(".");
}

// A name unique among this process's calls (counter) and other processes (pid); a leftover from a
// crashed process with the same pid is skipped by O_EXCL and the next counter value.
Temporary create_temporary(const std::filesystem::path& target) {
    static std::atomic<unsigned long> counter{0};
    const std::filesystem::path dir = directory_of(target);
    // The target's name cut short: a name near the 255 bytes most file systems allow is a legal target,
    // and its temporary, longer by the pid, counter and suffix, must be legal too. Built by appending:
    // GCC 12 warns falsely (-Wrestrict) on "." + std::string.
    constexpr std::size_t kNameKept = 200;
    const std::string name = target.filename().string();
    std::size_t kept = std::min(name.size(), kNameKept);
    // Not inside a UTF-8 character (a continuation byte is 10xxxxxx, at most three follow a first byte):
    // a file system that checks names' encoding would refuse half of one.
    const auto continues = [&name](std::size_t at) { return (static_cast<unsigned char>(name[at]) & 0xC0) == 0x80; };
    for (int back = 0; back < 3 && kept > 0 && kept < name.size() && continues(kept); ++back) --kept;
    std::string stem = ".";
    stem += name.substr(0, kept);
    stem += '.';
    stem += std::to_string(::getpid());
    stem += '.';
    for (int attempt = 0; attempt < 100; ++attempt) {
        std::string temporary = stem;
        temporary += std::to_string(counter++);
        temporary += ".tmp";
        const std::string path = (dir / temporary).string();
        const int fd = ::open(path.c_str(), O_WRONLY | O_CREAT | O_EXCL | O_CLOEXEC, 0666);
        if (fd >= 0) return Temporary(path, fd);
        if (errno != EEXIST) cannot_write(errno, target, "cannot create a temporary file in '" + dir.string() + "'");
    }
    cannot_write(EEXIST, target, "no free temporary file name in '" + dir.string() + "'");
}

// The temporary of `target` with all of `bytes` written, flushed and closed: ready to be renamed.
Temporary staged(const std::filesystem::path& target, std::string_view bytes) {
    if (target.filename().empty()) cannot_write(EISDIR, target, "the path does not name a file");
    Temporary temp = create_temporary(target);
    const char* data = bytes.data();
    std::size_t left = bytes.size();
    while (left > 0) {
        const ssize_t written = ::write(temp.fd(), data, left);
        if (written < 0) {
            if (errno == EINTR) continue;
            cannot_write(errno, target, "cannot write the temporary file '" + temp.path() + "'");
        }
        data += written;
        left -= static_cast<std::size_t>(written);
    }
    if (::fsync(temp.fd()) != 0) cannot_write(errno, target, "cannot fsync the temporary file '" + temp.path() + "'");
    if (temp.close() != 0) cannot_write(errno, target, "cannot close the temporary file '" + temp.path() + "'");
    return temp;
}

// A failed fsync of a replaced file's directory: the file is in place, but its rename might not survive
// a crash.
struct UnsyncedDirectory {
    int error;
    std::filesystem::path target, dir;
};

// Renames are durable only once their directory entries are: fsyncs the directory of each of `files`,
// each distinct one once, all of them even after one fails. Answers the first failure.
std::optional<UnsyncedDirectory> sync_directories(std::span<const FileContent> files) {
    std::optional<UnsyncedDirectory> failure;
    std::vector<std::filesystem::path> synced;
    for (const auto& file : files) {
        std::filesystem::path dir = directory_of(file.first);
        if (std::find(synced.begin(), synced.end(), dir) != synced.end()) continue;
        const int dir_fd = ::open(dir.c_str(), O_RDONLY | O_DIRECTORY | O_CLOEXEC);
        const int error = dir_fd < 0 ? errno : (::fsync(dir_fd) != 0 ? errno : 0);
        if (dir_fd >= 0) ::close(dir_fd);
        if (error != 0 && !failure) failure = UnsyncedDirectory{error, file.first, dir};
        synced.push_back(std::move(dir));
    }
    return failure;
}

}  // namespace

void write_files_atomic(std::span<const FileContent> files) {
    std::vector<Temporary> temps;
    temps.reserve(files.size());
    for (const auto& [target, bytes] : files) temps.push_back(staged(target, bytes));
    std::string replaced;  // the targets renamed into place so far, for the error of a later rename
    for (std::size_t k = 0; k < files.size(); ++k) {
        const std::filesystem::path& target = files[k].first;
        if (::rename(temps[k].path().c_str(), target.c_str()) != 0) {
            const int error = errno;
            const std::string step = "cannot rename the temporary file '" + temps[k].path() + "' over it";
            if (replaced.empty()) cannot_write(error, target, step);
            // The files already replaced stay so: their renames are made as durable as they can be first,
            // and this error, not one of theirs, is the one reported.
            sync_directories(files.first(k));
            fail(error, "cannot write '" + target.string() + "': " + step + "; already replaced: " + replaced);
        }
        temps[k].committed();
        replaced += replaced.empty() ? "'" : ", '";
        replaced += target.string();
        replaced += '\'';
    }
    if (const auto unsynced = sync_directories(files)) {
        std::string what = "'";  // appended, as the temporary's name is, for GCC 12's -Wrestrict
        what += unsynced->target.string();
        what += "' was replaced, but fsync of its directory '" + unsynced->dir.string() +
                "' failed, so the change might not survive a crash";
        fail(unsynced->error, what);
    }
}

void write_file_atomic(const std::filesystem::path& target, std::string_view bytes) {
    const FileContent file{target, bytes};
    write_files_atomic({&file, 1});
}

}  // namespace rast
