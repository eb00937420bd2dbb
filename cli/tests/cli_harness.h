// Running the rast binary from a test: command line in, exit status and output back, in a fresh temporary
// directory per test.
#pragma once

#include <rast/shell_word.h>

#include <gtest/gtest.h>

#include <sys/wait.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace rast::cli::testing {

struct Result {
    int status = -1;  // the exit status, or -1 when a signal ended the process
    std::string out;  // stdout and stderr together
    bool crashed() const { return status < 0; }
};

// Runs a shell command line.
inline Result run(const std::string& command) {
    FILE* pipe = popen(command.c_str(), "r");
    if (!pipe) throw std::runtime_error("popen failed");
    std::string out;
    char buffer[4096];
    while (std::size_t n = fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
    const int raw = pclose(pipe);
    return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, out};
}

inline Result rast(const std::string& args) { return run(std::string(RAST_BINARY) + " " + args + " 2>&1"); }

// rast with `text` piped into its standard input, as `cat scene.tri | rast ...` does.
inline Result rast_piped(const std::string& text, const std::string& args) {
    return run("printf '%s' " + shell_word(text) + " | " + RAST_BINARY + " " + args + " 2>&1");
}

inline std::string slurp(const std::filesystem::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream s;
    s << in.rdbuf();
    return s.str();
}

inline bool contains(const std::string& text, const std::string& part) {
    return text.find(part) != std::string::npos;
}

// A test with its own empty directory, removed afterwards.
class TempDirTest : public ::testing::Test {
protected:
    std::filesystem::path dir;

    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir = std::filesystem::temp_directory_path() /
              ("rast_" + std::string(info->test_suite_name()) + "_" + info->name());
        std::filesystem::remove_all(dir);
        std::filesystem::create_directories(dir);
    }
    void TearDown() override { std::filesystem::remove_all(dir); }

    // Writes `bytes` to dir/name (creating folders) and returns its path.
    std::string file(const std::string& name, const std::string& bytes) {
        std::filesystem::create_directories((dir / name).parent_path());
        std::ofstream(dir / name, std::ios::binary) << bytes;
        return out(name);
    }
    std::string read(const std::string& name) { return slurp(dir / name); }
    // The path of dir/name, for a file the binary is to write.
    std::string out(const std::string& name) { return (dir / name).string(); }
};

}  // namespace rast::cli::testing
