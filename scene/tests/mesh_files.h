// rast — the test fixture for mesh files: each test writes its files into a directory of its own.
#pragma once

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "rast/mesh.h"

namespace rast {

class MeshFiles : public ::testing::Test {
protected:
    void SetUp() override {
        const auto* info = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() /
               ("rast-mesh-" + std::to_string(::getpid()) + "-" + info->test_suite_name() + "-" + info->name());
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    std::filesystem::path write(const std::string& name, const std::string& bytes) const {
        const std::filesystem::path p = dir_ / name;
        std::ofstream(p, std::ios::binary) << bytes;
        return p;
    }
    // The what() of the ParseError that reading the file throws, with the directory taken out; "" if it reads.
    std::string error_of(const std::string& name, const std::string& bytes) const {
        try {
            read_mesh(write(name, bytes));
        } catch (const ParseError& e) {
            std::string what = e.what();
            const std::string prefix = (dir_ / "").string();
            if (what.rfind(prefix, 0) == 0) what.erase(0, prefix.size());
            return what;
        }
        return "";
    }
    std::filesystem::path dir_;
};

}  // namespace rast
