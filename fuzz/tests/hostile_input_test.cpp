// Hostile input end to end: malformed or non-finite files in every format the binary reads, and
// arguments out of range. Each must end in a clear message and a non-zero exit, never a crash or a
// picture of something that was not in the file.
#include "cli_harness.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <string>
#include <utility>

namespace rast::robustness {
namespace {

using cli::testing::Result;
using cli::testing::rast;
using CliTest = cli::testing::TempDirTest;

class HostileInput : public CliTest {
protected:
    // Renders `path` (with `args`) and expects a failure whose message contains `where`.
    void expect_rejected(const std::string& path, const std::string& where, const std::string& args = "") {
        const Result r = rast("render " + path + " " + args + " -o " + out("out.png"));
        EXPECT_FALSE(r.crashed()) << path << " " << args << "\n" << r.out;
        EXPECT_GT(r.status, 0) << path << " " << args << "\n" << r.out;
        EXPECT_NE(r.out.find(where), std::string::npos) << "expected '" << where << "' in:\n" << r.out;
        EXPECT_FALSE(std::filesystem::exists(dir / "out.png")) << "a picture was written for " << path;
    }
};

constexpr const char* kPlyHeader =
    "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\nend_header\n";

// Non-finite coordinates in each text format, named with their line.
TEST_F(HostileInput, NonFiniteCoordinatesInTextFilesNameTheLine) {
    std::string path = file("nan.obj", "v 0 0 0\nv 1 0 0\nv nan 1 0\nf 1 2 3\n");
    expect_rejected(path, path + ":3:");
    path = file("inf.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 inf 0\n3 0 1 2\n");
    expect_rejected(path, path + ":5:");
    path = file("overflow.ply", std::string(kPlyHeader) + "0 0 0\n1e999 0 0\n0 1 0\n3 0 1 2\n");
    expect_rejected(path, path + ":11:");
    path = file("nan.stl", "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 -nan 0\n"
                           "endloop\nendfacet\nendsolid t\n");
    expect_rejected(path, path + ":6:");
    path = file("inf.tri", "viewport 4 4\ntri 0 0 0  1 0 0  0 1 -inf\n");
    expect_rejected(path, path + ":2:");
    path = file("huge.tri", "viewport 4 4\ntri 0 0 0  1 0 0  0 0x1p+1024 0\n");
    expect_rejected(path, path + ":2:");
}

// Binary STL: an 80-byte header, a count, then per facet a normal, three corners (float32) and 2 bytes.
TEST_F(HostileInput, NonFiniteCoordinateInBinaryStl) {
    std::string bytes(80, ' ');
    const std::uint32_t count = 1;
    bytes.append(reinterpret_cast<const char*>(&count), 4);
    const float facet[12] = {0, 0, 1, 0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0};
    bytes.append(reinterpret_cast<const char*>(facet), sizeof facet);
    bytes.append(2, '\0');
    const std::string path = file("nan.stl", bytes);
    expect_rejected(path, path + ":");
}

// Binary PLY is checked before OpenMesh; the finite check after it rejects the infinity.
TEST_F(HostileInput, NonFiniteCoordinateInBinaryPly) {
    std::string bytes =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const float vertices[9] = {0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::infinity(), 0};
    bytes.append(reinterpret_cast<const char*>(vertices), sizeof vertices);
    bytes.push_back(3);
    const std::int32_t face[3] = {0, 1, 2};
    bytes.append(reinterpret_cast<const char*>(face), sizeof face);
    const std::string path = file("inf.ply", bytes);
    expect_rejected(path, path + ":");
}

TEST_F(HostileInput, BinaryGarbageAndTruncatedFiles) {
    std::string garbage;
    for (int k = 0; k < 256; ++k) garbage.push_back(static_cast<char>(k));
    for (const char* name : {"garbage.tri", "garbage.obj", "garbage.off", "garbage.ply", "garbage.stl"}) {
        const std::string path = file(name, garbage);
        expect_rejected(path, path + ":");
    }
    std::string path = file("empty.tri", "");
    expect_rejected(path, path + ": missing 'viewport");
    path = file("short.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n");
    expect_rejected(path, path + ":");
    path = file("index.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n");
    expect_rejected(path, path + ":4:");
}

// A scene whose buffers would not fit in memory is refused at the line that makes it too large.
TEST_F(HostileInput, OversizedSceneIsRefusedBeforeAllocating) {
    const std::string path = file("big.tri", "viewport 32768 32768\nsamples 16\n");
    expect_rejected(path, path + ":2:");
}

// Each refusal names the option, or says what is wrong with the camera the options make.
TEST_F(HostileInput, NonFiniteOrOutOfRangeArgumentsAreRefused) {
    const std::string mesh = file("tri.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
    const std::pair<const char*, const char*> cases[] = {
        {"--eye nan,0,1", "camera: eye, target and up must be finite"},
        {"--eye 1e999,0,1", "camera: eye, target and up must be finite"},
        {"--target 0,inf,0", "camera: eye, target and up must be finite"},
        {"--up 0,nan,0", "camera: eye, target and up must be finite"},
        {"--eye 0,0,0 --target 0,0,0", "camera: eye and target are the same point"},
        {"--fov nan", "camera: fov_y"},
        {"--near nan", "--near: a distance must be finite and at least 2^-1022"},
        {"--fov 180", "--fov"},
        {"--near inf", "--near"},
        {"--far -1", "--far"},
        {"--width 0", "--width"},
        {"--height 40000", "--height"},
        {"--samples 0", "--samples"},
        {"--threads 99999999999", "--threads"}};
    for (const auto& [args, message] : cases) expect_rejected(mesh, message, args);
}

}  // namespace
}  // namespace rast::robustness
