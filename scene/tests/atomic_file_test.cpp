#include "rast/atomic_file.h"

#include <gtest/gtest.h>
#include <sys/resource.h>
#include <sys/stat.h>
#include <unistd.h>

#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <span>
#include <sstream>
#include <system_error>

namespace rast {
namespace {

namespace fs = std::filesystem;

std::string slurp(const fs::path& p) {
    std::ifstream in(p, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

// A fresh directory per test, removed afterwards.
class AtomicFile : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = fs::temp_directory_path() / ("rast-atomic-" + std::to_string(::getpid()) + "-" + info->name());
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        fs::permissions(dir_, fs::perms::owner_all, fs::perm_options::add);
        fs::remove_all(dir_);
    }
    std::size_t entries() const {
        return static_cast<std::size_t>(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()));
    }
    fs::path dir_;
};

TEST_F(AtomicFile, WritesAndReplacesLeavingNoTemporary) {
    const fs::path target = dir_ / "out.txt";
    write_file_atomic(target, "first");
    EXPECT_EQ(slurp(target), "first");
    write_file_atomic(target, std::string("sec\0nd", 6));
    EXPECT_EQ(slurp(target), std::string("sec\0nd", 6));
    write_file_atomic(target, "");
    EXPECT_EQ(slurp(target), "");
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFile, NewFileHasOrdinaryPermissions) {
    const mode_t mask = ::umask(022);
    ::umask(mask);
    const fs::path target = dir_ / "perm.txt";
    write_file_atomic(target, "x");
    struct stat st {};
    ASSERT_EQ(::stat(target.c_str(), &st), 0);
    EXPECT_EQ(st.st_mode & 0777, 0666 & ~mask);
}

TEST_F(AtomicFile, MissingDirectoryThrowsNamingPathAndStepAndCreatesNothing) {
    const fs::path target = dir_ / "absent" / "out.txt";
    try {
        write_file_atomic(target, "x");
        FAIL() << "no error";
    } catch (const std::system_error& e) {
        EXPECT_EQ(e.code(), std::errc::no_such_file_or_directory);
        EXPECT_EQ(std::string(e.what()), "cannot write '" + target.string() + "': cannot create a temporary file in '" +
                                             (dir_ / "absent").string() + "': No such file or directory");
    }
    EXPECT_FALSE(fs::exists(dir_ / "absent"));
    EXPECT_EQ(entries(), 0u);
}

TEST_F(AtomicFile, TargetThatIsADirectoryIsUntouchedAndTemporaryRemoved) {
    const fs::path target = dir_ / "sub";
    fs::create_directories(target);
    std::ofstream(target / "keep") << "kept";
    try {
        write_file_atomic(target, "x");
        FAIL() << "no error";
    } catch (const std::system_error& e) {
        const std::string prefix = "cannot write '" + target.string() + "': cannot rename the temporary file '";
        EXPECT_EQ(std::string(e.what()).substr(0, prefix.size()), prefix);
    }
    EXPECT_TRUE(fs::is_directory(target));
    EXPECT_EQ(slurp(target / "keep"), "kept");
    EXPECT_EQ(entries(), 1u);
}

// In a child process, which drops root (root may write anywhere) to the user nobody: a directory it may
// not write to must give an error and leave the target. Exit code 0 means all of that held.
void write_into_read_only_directory(const fs::path& target) {
    if (::geteuid() == 0 && ::setuid(65534) != 0) std::_Exit(3);
    try {
        write_file_atomic(target, "new");
    } catch (const std::system_error& e) {
        std::_Exit(slurp(target) == "old" && e.code() == std::errc::permission_denied ? 0 : 2);
    }
    std::_Exit(1);
}

TEST_F(AtomicFile, ReadOnlyDirectoryLeavesTargetUntouched) {
    const fs::path target = dir_ / "out.txt";
    write_file_atomic(target, "old");
    fs::permissions(target, fs::perms::owner_read | fs::perms::group_read | fs::perms::others_read);
    fs::permissions(dir_, fs::perms::owner_read | fs::perms::owner_exec | fs::perms::group_read |
                              fs::perms::group_exec | fs::perms::others_read | fs::perms::others_exec);
    EXPECT_EXIT(write_into_read_only_directory(target), ::testing::ExitedWithCode(0), "");
    EXPECT_EQ(slurp(target), "old");
    EXPECT_EQ(entries(), 1u);
}

// A directory anyone but root may write to and enter but not read: files are created and renamed there,
// but the directory cannot be opened to fsync it.
void write_and_enter_only(const fs::path& dir) {
    using fs::perms;
    fs::permissions(dir, perms::owner_write | perms::owner_exec | perms::group_write | perms::group_exec |
                             perms::others_write | perms::others_exec);
}

// In a child process that drops root to the user nobody: files written into such a directory. Exit code 0
// means the error was the one expected (`expected`, with errno EACCES) and every file holds its new content.
void write_into_unreadable_directory(std::span<const FileContent> files, const std::string& expected) {
    if (::geteuid() == 0 && ::setuid(65534) != 0) std::_Exit(3);
    try {
        write_files_atomic(files);
    } catch (const std::system_error& e) {
        bool replaced = true;
        for (const auto& [target, bytes] : files) replaced = replaced && slurp(target) == bytes;
        std::_Exit(replaced && e.code() == std::errc::permission_denied && e.what() == expected ? 0 : 2);
    }
    std::_Exit(1);
}

// Two such folders: the first one's failure is the one reported.
TEST_F(AtomicFile, DirectoryThatCannotBeSyncedIsReportedAfterTheFilesAreInPlace) {
    const fs::path one = dir_ / "one", two = dir_ / "two";
    fs::create_directories(one);
    fs::create_directories(two);
    write_file_atomic(one / "a.txt", "old");
    write_and_enter_only(one);
    write_and_enter_only(two);
    const FileContent files[] = {{one / "a.txt", "new"}, {two / "b.txt", "other"}, {one / "c.txt", "third"}};
    std::string expected = "'";  // appended: GCC 12 warns falsely (-Wrestrict) on "'" + std::string
    expected += (one / "a.txt").string() + "' was replaced, but fsync of its directory '" + one.string() +
                "' failed, so the change might not survive a crash: Permission denied";
    EXPECT_EXIT(write_into_unreadable_directory(files, expected), ::testing::ExitedWithCode(0), "");
    for (const fs::path& folder : {one, two}) fs::permissions(folder, fs::perms::owner_all, fs::perm_options::add);
    EXPECT_EQ(slurp(one / "a.txt"), "new");
    EXPECT_EQ(slurp(two / "b.txt"), "other");
    EXPECT_EQ(slurp(one / "c.txt"), "third");
}

// A rename that fails after another succeeded is the error reported, not the fsync of the directory of
// the file already replaced, which fails too here.
TEST_F(AtomicFile, FailedLaterRenameIsReportedRatherThanTheEarlierFilesUnsyncedDirectory) {
    fs::create_directories(dir_ / "sub");
    write_and_enter_only(dir_);
    const FileContent files[] = {{dir_ / "a.txt", "new"}, {dir_ / "sub", "x"}};
    EXPECT_EXIT(
        {
            if (::geteuid() == 0 && ::setuid(65534) != 0) std::_Exit(3);
            try {
                write_files_atomic(files);
            } catch (const std::system_error& e) {
                const std::string what = e.what();
                const bool named = what.find("cannot rename the temporary file") != std::string::npos &&
                                   what.find("already replaced: '" + (dir_ / "a.txt").string() + "'") != std::string::npos;
                std::_Exit(named && e.code() == std::errc::is_a_directory && slurp(dir_ / "a.txt") == "new" ? 0 : 2);
            }
            std::_Exit(1);
        },
        ::testing::ExitedWithCode(0), "");
    EXPECT_TRUE(fs::is_directory(dir_ / "sub"));
}

// Run in a child process, so that the file size limit stays there: a write that fails half way must leave
// the old target and no temporary. Exit code 0 means all of that held.
void write_beyond_size_limit(const fs::path& target, const fs::path& dir) {
    std::signal(SIGXFSZ, SIG_IGN);
    const rlimit limit{4096, 4096};
    ::setrlimit(RLIMIT_FSIZE, &limit);
    try {
        write_file_atomic(target, std::string(1 << 16, 'n'));
    } catch (const std::system_error& e) {
        const bool alone = std::distance(fs::directory_iterator(dir), fs::directory_iterator()) == 1;
        std::_Exit(slurp(target) == "old" && alone && e.code() == std::errc::file_too_large ? 0 : 2);
    }
    std::_Exit(1);
}

TEST_F(AtomicFile, FailedWriteLeavesTargetUntouched) {
    const fs::path target = dir_ / "out.txt";
    write_file_atomic(target, "old");
    EXPECT_EXIT(write_beyond_size_limit(target, dir_), ::testing::ExitedWithCode(0), "");
    EXPECT_EQ(slurp(target), "old");
}

TEST_F(AtomicFile, NameAsLongAsTheFileSystemAllowsIsWritten) {
    const fs::path target = dir_ / std::string(255, 'n');
    write_file_atomic(target, "long");
    EXPECT_EQ(slurp(target), "long");
    EXPECT_EQ(entries(), 1u);
}

// The temporary keeps the first 200 bytes of a long name, less the start of a UTF-8 character cut there
// ("é" is C3 A9, at bytes 199 and 200). Seen through the error of a target that is a folder, which names
// the temporary.
TEST_F(AtomicFile, TemporaryOfALongNameKeepsWholeCharacters) {
    const fs::path target = dir_ / (std::string(199, 'n') + "\xC3\xA9" + std::string(40, 'n'));
    fs::create_directories(target);
    try {
        write_file_atomic(target, "x");
        FAIL() << "no error";
    } catch (const std::system_error& e) {
        const std::string temporary = (dir_ / ("." + std::string(199, 'n') + ".")).string();
        EXPECT_NE(std::string(e.what()).find("the temporary file '" + temporary), std::string::npos) << e.what();
    }
    EXPECT_EQ(entries(), 1u);
}

TEST_F(AtomicFile, SeveralFilesAreAllWritten) {
    const FileContent files[] = {{dir_ / "a.txt", "first"}, {dir_ / "b.txt", "second"}};
    write_files_atomic(files);
    EXPECT_EQ(slurp(dir_ / "a.txt"), "first");
    EXPECT_EQ(slurp(dir_ / "b.txt"), "second");
    EXPECT_EQ(entries(), 2u);
}

// The second file cannot be made: the first, written before it in the list, must not be replaced either.
TEST_F(AtomicFile, OneFileThatCannotBeWrittenLeavesEveryTargetUntouched) {
    write_file_atomic(dir_ / "a.txt", "old");
    const FileContent files[] = {{dir_ / "a.txt", "new"}, {dir_ / "absent" / "b.txt", "new"}};
    try {
        write_files_atomic(files);
        FAIL() << "no error";
    } catch (const std::system_error& e) {
        EXPECT_EQ(e.code(), std::errc::no_such_file_or_directory);
        EXPECT_NE(std::string(e.what()).find((dir_ / "absent" / "b.txt").string()), std::string::npos) << e.what();
    }
    EXPECT_EQ(slurp(dir_ / "a.txt"), "old");
    EXPECT_EQ(entries(), 1u);
}

}  // namespace
}  // namespace rast
