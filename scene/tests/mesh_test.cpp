#include "rast/mesh.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "mesh_files.h"

namespace rast {
namespace {

// A unit cube: 8 corners, 6 quads wound counter-clockwise seen from outside.
const char* const kCubeObj =
    "# cube\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 3 4 8 7\nf 2 3 7 6\nf 4 1 5 8\n";

// Twice the signed area of every face, summed as vectors: zero exactly for a closed surface.
Vec3 summed_area_vectors(const Mesh& m) {
    Vec3 sum;
    for (const auto& f : m.faces)
        sum = sum + cross(m.positions[f[1]] - m.positions[f[0]], m.positions[f[2]] - m.positions[f[0]]);
    return sum;
}

void expect_unit_cube(const Mesh& m) {
    EXPECT_EQ(m.positions.size(), 8u);
    EXPECT_EQ(m.faces.size(), 12u);  // 6 quads, triangulated
    EXPECT_TRUE(m.closed);
    EXPECT_EQ(summed_area_vectors(m), (Vec3{0, 0, 0}));
    for (const Vec3& p : m.positions)
        for (double c : {p.x, p.y, p.z}) EXPECT_TRUE(c == 0 || c == 1);
}

TEST_F(MeshFiles, ReadsObjTriangulatingQuads) { expect_unit_cube(read_mesh(write("cube.obj", kCubeObj))); }

TEST_F(MeshFiles, ExtensionIsCaseInsensitive) { expect_unit_cube(read_mesh(write("CUBE.OBJ", kCubeObj))); }

TEST_F(MeshFiles, ObjNegativeIndicesAndSlashes) {
    const Mesh m = read_mesh(write("t.obj", "v 0 0 0\nv 1 0 0\nvt 0 0\nv 0 1 0\nf -3/1 -2/1/1 3//1\n"));
    ASSERT_EQ(m.faces.size(), 1u);
    EXPECT_FALSE(m.closed);
    const auto& f = m.faces[0];
    EXPECT_EQ(m.positions[f[0]], (Vec3{0, 0, 0}));
    EXPECT_EQ(m.positions[f[1]], (Vec3{1, 0, 0}));
    EXPECT_EQ(m.positions[f[2]], (Vec3{0, 1, 0}));
}

TEST_F(MeshFiles, CoordinatesAreFloat32) {
    const Mesh m = read_mesh(write("t.obj", "v 0.1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
    EXPECT_EQ(m.positions.at(0).x, static_cast<double>(0.1f));
}

TEST_F(MeshFiles, ReadsOff) {
    expect_unit_cube(read_mesh(write("cube.off",
                                     "OFF\n# a cube\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                                     "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 3 0 4 7\n")));
}

TEST_F(MeshFiles, ReadsAsciiPly) {
    expect_unit_cube(read_mesh(write("cube.ply",
                                     "ply\nformat ascii 1.0\ncomment a cube\nelement vertex 8\n"
                                     "property float x\nproperty float y\nproperty float z\n"
                                     "element face 6\nproperty list uchar int vertex_indices\nend_header\n"
                                     "0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n"
                                     "4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 2 3 7 6\n4 1 2 6 5\n4 3 0 4 7\n")));
}

TEST_F(MeshFiles, OffCountsOnTheHeaderLine) {
    const Mesh m = read_mesh(write("t.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"));
    EXPECT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.faces.size(), 1u);
}

// A missing material and a non-manifold edge (three faces on edge 1-2) change no geometry: the mesh reads,
// every face is kept, it is not closed, and OpenMesh's complaints do not reach stderr.
TEST_F(MeshFiles, HarmlessOpenMeshComplaintsAreSilenced) {
    ::testing::internal::CaptureStderr();
    const Mesh m = read_mesh(write("nm.obj",
                                   "mtllib absent.mtl\nusemtl none\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nv 1 1 1\n"
                                   "f 1 2 3\nf 2 1 4\nf 1 2 5\n"));
    EXPECT_EQ(::testing::internal::GetCapturedStderr(), "");
    EXPECT_EQ(m.faces.size(), 3u);
    EXPECT_FALSE(m.closed);
}

TEST_F(MeshFiles, BinaryPlyWithInfinityIsRejected) {
    std::string ply =
        "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
        "property float z\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const float corners[9] = {0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::infinity(), 0};
    ply.append(reinterpret_cast<const char*>(corners), sizeof corners);
    ply += '\3';
    const std::int32_t face[3] = {0, 1, 2};
    ply.append(reinterpret_cast<const char*>(face), sizeof face);
    EXPECT_EQ(error_of("inf.ply", ply), "inf.ply: vertex 2 has a non-finite coordinate");
}

// The cube as 12 triangles (corner indices into the unit cube above, 0-based).
const int kCubeTriangles[12][3] = {{0, 3, 2}, {0, 2, 1}, {4, 5, 6}, {4, 6, 7}, {0, 1, 5}, {0, 5, 4},
                                   {2, 3, 7}, {2, 7, 6}, {1, 2, 6}, {1, 6, 5}, {3, 0, 4}, {3, 4, 7}};
const float kCubeCorners[8][3] = {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0},
                                  {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}};

TEST_F(MeshFiles, ReadsAsciiStlMergingCorners) {
    std::string stl = "solid cube\n";
    for (const auto& t : kCubeTriangles) {
        stl += "facet normal 0 0 0\nouter loop\n";
        for (int c : t)
            stl += "vertex " + std::to_string(kCubeCorners[c][0]) + " " + std::to_string(kCubeCorners[c][1]) + " " +
                   std::to_string(kCubeCorners[c][2]) + "\n";
        stl += "endloop\nendfacet\n";
    }
    expect_unit_cube(read_mesh(write("cube.stl", stl + "endsolid cube\n")));
}

TEST_F(MeshFiles, ReadsBinaryStlEvenWithASolidHeader) {
    std::string stl(80, ' ');
    stl.replace(0, 5, "solid");
    const std::uint32_t count = 12;
    stl.append(reinterpret_cast<const char*>(&count), 4);  // little endian on the machines we build for
    for (const auto& t : kCubeTriangles) {
        stl.append(12, '\0');  // normal
        for (int c : t) stl.append(reinterpret_cast<const char*>(kCubeCorners[c]), 12);
        stl.append(2, '\0');  // attribute byte count
    }
    expect_unit_cube(read_mesh(write("cube.stl", stl)));
}

TEST_F(MeshFiles, BinaryStlWithNanIsRejected) {
    std::string stl(80, ' ');
    const std::uint32_t count = 1;
    stl.append(reinterpret_cast<const char*>(&count), 4);
    const float tri[12] = {0, 0, 0, 0, 0, 0, 1, 0, 0, 0, std::numeric_limits<float>::quiet_NaN(), 0};
    stl.append(reinterpret_cast<const char*>(tri), sizeof tri);
    stl.append(2, '\0');
    EXPECT_EQ(error_of("nan.stl", stl), "nan.stl: triangle 0 has a non-finite coordinate");
}

TEST_F(MeshFiles, RejectsUnknownExtensionMissingFileAndNoFaces) {
    EXPECT_EQ(error_of("cube.xyz", kCubeObj), "cube.xyz: unknown mesh extension '.xyz' (expected .obj, .off, .ply or .stl)");
    EXPECT_EQ(error_of("noext", kCubeObj), "noext: unknown mesh extension '' (expected .obj, .off, .ply or .stl)");
    try {
        read_mesh(dir_ / "absent.obj");
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.message, "cannot open: No such file or directory");
    }
    EXPECT_EQ(error_of("points.obj", "v 0 0 0\nv 1 0 0\n"), "points.obj: the mesh has no faces");
}

TEST_F(MeshFiles, RejectsMalformedObjWithLine) {
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nv 1 0 0\nv 0 nan 0\nf 1 2 3\n"), "a.obj:3: NaN is not allowed: 'nan'");
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nv 1 0 1e999\n"), "a.obj:2: number '1e999' overflows to infinity");
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nv 1 0 0x\n"), "a.obj:2: bad number '0x': trailing characters 'x'");
    EXPECT_EQ(error_of("a.obj", "v 0 0\n"), "a.obj:1: 'v' expects at least 3 numbers (x y z), got 2 values");
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\n\nf 1 2 4\n"),
              "a.obj:5: vertex index 4 is out of range (3 vertices)");
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"),
              "a.obj:4: vertex index 0 is out of range (3 vertices)");
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -4 1 2\n"),
              "a.obj:4: vertex index -4 is out of range (3 vertices)");
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 -3\n"), "a.obj:4: the face uses vertex -3 twice");
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n"), "a.obj:4: 'f' expects at least 3 vertices, got 2 values");
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 x/1\n"), "a.obj:4: expected an integer, got 'x'");
}

TEST_F(MeshFiles, RejectsMalformedOffWithLine) {
    EXPECT_EQ(error_of("a.off", "PFF\n"), "a.off:1: expected an OFF header, got 'PFF'");
    EXPECT_EQ(error_of("a.off", "OFF\n3 1\n"), "a.off:2: expected the counts 'vertices faces edges', got 2 values");
    EXPECT_EQ(error_of("a.off", "OFF\n3 1 0\n0 0 0\n1 0 inf\n"), "a.off:4: infinity is not allowed: 'inf'");
    EXPECT_EQ(error_of("a.off", "OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 3\n"),
              "a.off:5: vertex index 3 is out of range (3 vertices)");
    EXPECT_EQ(error_of("a.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n4 0 1 2\n"),
              "a.off:6: the face lists 4 vertices but gives 3 values");
    EXPECT_EQ(error_of("a.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"), "a.off:6: the file ends before face 1 of 2");
    EXPECT_EQ(error_of("a.off", "# binary\nOFF BINARY\n" + std::string("\xff\xff\xff\xfb\0\0\0\0", 8)),
              "a.off:2: binary OFF is not supported (OpenMesh misreads it); write it as ASCII OFF or as PLY");
}

TEST_F(MeshFiles, RejectsMalformedPlyWithLine) {
    const std::string header =
        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
        "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    EXPECT_EQ(error_of("a.ply", header + "0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n"),
              "a.ply:13: vertex index 7 is out of range (3 vertices)");
    EXPECT_EQ(error_of("a.ply", header + "0 0 0\n1 0 0 5\n0 1 0\n3 0 1 2\n"),
              "a.ply:11: too many values for element 'vertex': 4 values, expected 3");
    EXPECT_EQ(error_of("a.ply", header + "0 0 0\n1 0\n"), "a.ply:11: too few values for element 'vertex': 2 values");
    EXPECT_EQ(error_of("a.ply", header + "0 0 0\n1 0 nan\n"), "a.ply:11: NaN is not allowed: 'nan'");
    EXPECT_EQ(error_of("a.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nwhat\n"),
              "a.ply:5: unknown PLY header keyword 'what'");
}

// An ASCII PLY header of 3 vertices (x, y, z, nx; x a double) and 1 face: data starts on line 11.
const std::string kPlyHeader = "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\nproperty float y\n"
                               "property float z\nproperty float nx\nelement face 1\n"
                               "property list uchar int vertex_indices\nend_header\n";

// OpenMesh reads coordinates as float and drops a vertex whose coordinate overflows, so every later index
// shifts and it blamed a face: "Face contains invalid vertex index" (OBJ), "Face has equal vertices" (OFF).
// A vertex that no face uses counts too, as it shifts the others all the same.
TEST_F(MeshFiles, RejectsCoordinatesBeyondFloatRangeWithLine) {
    const std::string reason = " exceeds float range: meshes are read as float";
    EXPECT_EQ(error_of("a.obj", "v 1e39 0 0\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 2 3 4\n"), "a.obj:1: number '1e39'" + reason);
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nv 1 0 0\nv 0 -3.4028236e38 0\nf 1 2 3\n"),
              "a.obj:3: number '-3.4028236e38'" + reason);
    EXPECT_EQ(error_of("a.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n# unused\n0 0 1e39\n3 0 1 2\n"),
              "a.off:7: number '1e39'" + reason);
    EXPECT_EQ(error_of("a.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 0 3.5e38 0\n"),
              "a.stl:5: number '3.5e38'" + reason);
    EXPECT_EQ(error_of("a.ply", kPlyHeader + "0 0 0 0\n1e39 0 0 0\n"), "a.ply:12: number '1e39'" + reason);
    EXPECT_EQ(error_of("a.ply", kPlyHeader + "0 0 0 -1e39\n"), "a.ply:11: number '-1e39'" + reason);
}

// 3.4028235e38 is below FLT_MAX + half an ulp, so it rounds to FLT_MAX and reads. Values OpenMesh does not keep
// as float may be larger: an OBJ vertex's w, a PLY vertex property of its own.
TEST_F(MeshFiles, ReadsCoordinatesUpToFloatMaxAndLargerValuesThatAreNotCoordinates) {
    const float max = std::numeric_limits<float>::max();
    Mesh m = read_mesh(write("t.obj", "v 0 0 0\nv 3.4028235e38 0 0\nv 0 -3.4028235e38 0 1e300\nf 1 2 3\n"));
    EXPECT_EQ(m.positions.at(1), (Vec3{max, 0, 0}));
    EXPECT_EQ(m.positions.at(2), (Vec3{0, -max, 0}));
    m = read_mesh(write("t.ply",
                        "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                        "property float z\nproperty double quality\nelement face 1\n"
                        "property list uchar int vertex_indices\nend_header\n"
                        "0 0 0 1e300\n1 0 0 0\n0 1 0 -1e300\n3 0 1 2\n"));
    EXPECT_EQ(m.positions.at(2), (Vec3{0, 1, 0}));
}

// OpenMesh reads numbers with C++ streams, which read a hex float's "0" and stop at the 'x': it had dropped
// the OBJ vertex (shifting every later index: the face below became (0,0,0) (1,0,0) (0,1,0)), zeroed the
// STL vertex, y and z too, and made garbage of the OFF file. A hex float is refused wherever a number is.
TEST_F(MeshFiles, RejectsHexFloatsWithLine) {
    const std::string reason = ": mesh files take decimal numbers (OpenMesh misreads hex floats)";
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nv 0x1p-2 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"), "a.obj:2: hex float '0x1p-2'" + reason);
    EXPECT_EQ(error_of("a.obj", "v 0 0 0 -0X1P0\n"), "a.obj:1: hex float '-0X1P0'" + reason);
    EXPECT_EQ(error_of("a.off", "OFF\n3 1 0\n0 0 0\n1 0 0x1.8p1\n"), "a.off:4: hex float '0x1.8p1'" + reason);
    const std::string facet = "solid s\nfacet normal 0 0 1\nouter loop\n";
    EXPECT_EQ(error_of("a.stl", facet + "vertex 1 0 0\nvertex +0x1p-2 5 6\nvertex 0 1 0\nendloop\nendfacet\nendsolid s\n"),
              "a.stl:5: hex float '+0x1p-2'" + reason);
    EXPECT_EQ(error_of("a.stl", "solid s\nfacet normal 0x0p0 0 1\n"), "a.stl:2: hex float '0x0p0'" + reason);
    EXPECT_EQ(error_of("a.ply", kPlyHeader + "0 0 0 0\n0x1p-2 0 0 0\n"), "a.ply:12: hex float '0x1p-2'" + reason);
    EXPECT_EQ(error_of("a.ply", kPlyHeader + "0 0 0 0x10\n"), "a.ply:11: hex float '0x10'" + reason);
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nvt 0x1p-1 0\n"), "a.obj:2: hex float '0x1p-1'" + reason);
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nvn 0 0 0x1p0\n"), "a.obj:2: hex float '0x1p0'" + reason);
}

// OBJ texture coordinates and normals are floats to OpenMesh as well: a 'vt' it could not read ended the
// whole file without a line, and a normal beyond float range was kept as infinity.
TEST_F(MeshFiles, ChecksObjTextureCoordinatesAndNormalsWithLine) {
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nvt 0.5\n"), "a.obj:2: 'vt' expects at least 2 numbers, got 1 value");
    EXPECT_EQ(error_of("a.obj", "v 0 0 0\nvn 0 1\n"), "a.obj:2: 'vn' expects at least 3 numbers, got 2 values");
    EXPECT_EQ(error_of("a.obj", "vt 1e39 0\n"), "a.obj:1: number '1e39' exceeds float range: meshes are read as float");
    EXPECT_EQ(error_of("a.obj", "vn 0 0 -1e39\n"), "a.obj:1: number '-1e39' exceeds float range: meshes are read as float");
    const Mesh m = read_mesh(write("t.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nvn 0 0 1\nf 1/1/1 2/1/1 3/1/1\n"));
    EXPECT_EQ(m.faces.size(), 1u);
}

// The decimal spellings that strtod and C++ streams both read, read as strtof reads them (once rounded, where
// a double read and narrowed rounds twice: the last spelling is just above a tie between two floats) in OBJ,
// OFF and ASCII PLY: the checker lets through only what OpenMesh reads as written.
TEST_F(MeshFiles, ReadsEveryDecimalSpellingAsStrtofDoes) {
    const std::vector<std::string> spellings = {".5",    "5.",    "+1",  "-0",       "1E2", "-2.5e-1",
                                                "1e-46", "1e-40", "0.1", "16777217", "1.00000005960464477539062500000001"};
    std::string vertices, obj;
    for (const std::string& x : spellings) {
        vertices += x + " 0 1\n";
        obj += "v " + x + " 0 1\n";
    }
    const std::string n = std::to_string(spellings.size());
    const std::pair<std::string, std::string> files[] = {
        {"t.obj", obj + "f 1 2 3\n"},
        {"t.off", "OFF\n" + n + " 1 0\n" + vertices + "3 0 1 2\n"},
        {"t.ply", "ply\nformat ascii 1.0\nelement vertex " + n +
                      "\nproperty float x\nproperty float y\nproperty float z\nelement face 1\n"
                      "property list uchar int vertex_indices\nend_header\n" + vertices + "3 0 1 2\n"}};
    for (const auto& [name, text] : files) {
        const Mesh m = read_mesh(write(name, text));
        ASSERT_EQ(m.positions.size(), spellings.size()) << name;
        for (std::size_t k = 0; k < spellings.size(); ++k) {
            const float expected = std::strtof(spellings[k].c_str(), nullptr);
            EXPECT_EQ(m.positions[k].x, expected) << name << " " << spellings[k];
            EXPECT_EQ(std::signbit(m.positions[k].x), std::signbit(expected)) << name << " " << spellings[k];
        }
    }
}

// FLT_MAX + half an ulp is 340282356779733661637539395458142568448 (2^128 - 2^103): strtof, as OpenMesh
// reads, rounds anything below it to FLT_MAX and it, a tie, to the even neighbour, infinity. The check agrees
// to the last digit, also where the nearest double is that tie: read as a double first, one below it and
// 3.4028235677973366e38 (1.6e22 below it) had narrowed to infinity and were refused.
TEST_F(MeshFiles, FloatRangeEndsExactlyWhereStrtofsDoes) {
    const float max = std::numeric_limits<float>::max();
    for (const std::string below : {"340282356779733661637539395458142568447", "3.4028235677973366e38"}) {
        const Mesh m = read_mesh(write("t.obj", "v 0 0 0\nv " + below + " 0 0\nv 0 -" + below + " 0\nf 1 2 3\n"));
        EXPECT_EQ(m.positions.at(1), (Vec3{max, 0, 0})) << below;
        EXPECT_EQ(m.positions.at(2), (Vec3{0, -max, 0})) << below;
    }
    EXPECT_EQ(error_of("a.obj", "v 0 -340282356779733661637539395458142568448 0\n"),
              "a.obj:1: number '-340282356779733661637539395458142568448' exceeds float range: meshes are read as float");
}

TEST_F(MeshFiles, RejectsMalformedAsciiStlWithLine) {
    EXPECT_EQ(error_of("a.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nendloop\n"),
              "a.stl:6: a facet has 2 vertices; STL facets are triangles");
    EXPECT_EQ(error_of("a.stl", "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0,5\n"),
              "a.stl:5: bad number '0,5': trailing characters ',5'");
    EXPECT_EQ(error_of("a.stl", "not an stl at all\n"), "a.stl:1: expected 'solid' (and the size does not fit a binary STL)");
}

// A facet cut short, or its keywords out of order, is an error: it was read as one triangle fewer.
TEST_F(MeshFiles, RejectsAnAsciiStlFacetCutShort) {
    const std::string loop = "solid s\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n";
    EXPECT_EQ(error_of("a.stl", loop), "a.stl:6: the file ends inside a facet, before 'vertex' or 'endloop'");
    EXPECT_EQ(error_of("a.stl", loop + "endloop\n"), "a.stl:7: the file ends inside a facet, before 'endfacet'");
    EXPECT_EQ(error_of("a.stl", loop + "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"),
              "a.stl:11: the file ends inside a facet, before 'vertex' or 'endloop'");
    EXPECT_EQ(error_of("a.stl", loop + "endloop\nfacet normal 0 0 1\n"), "a.stl:8: expected 'endfacet', got 'facet'");
    EXPECT_EQ(error_of("a.stl", "solid s\nfacet normal 0 0 1\nvertex 0 0 0\n"),
              "a.stl:3: expected 'outer loop', got 'vertex'");
    EXPECT_EQ(error_of("a.stl", "solid s\nvertex 0 0 0\n"), "a.stl:2: expected 'facet' or 'endsolid', got 'vertex'");
    EXPECT_EQ(error_of("a.stl", loop + "endloop endfacet\n"),
              "a.stl:7: expected 'endloop' alone on its line, got 1 value after it");
}

// OpenMesh reads as many faces as an OFF or ASCII PLY header declares: one more line was dropped unseen.
TEST_F(MeshFiles, RejectsLinesAfterTheDeclaredFaces) {
    const std::string vertices = "0 0 0\n1 0 0\n0 1 0\n";
    EXPECT_EQ(error_of("a.off", "OFF\n3 1 0\n" + vertices + "3 0 1 2\n3 0 2 1\n"),
              "a.off:7: a line after the last face the header declares");
    EXPECT_EQ(error_of("a.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
                                "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
                                "end_header\n" + vertices + "3 0 1 2\n3 0 2 1\n"),
              "a.ply:14: a line after the last element the header declares");
}

}  // namespace
}  // namespace rast
