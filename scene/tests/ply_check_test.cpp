// PLY files, ASCII and binary, as read_mesh checks them before OpenMesh reads them. The malformed inputs
// are the essence of fuzzer findings: OpenMesh looped forever on a header without 'end_header', crashed on a
// 'property' before any 'element', and reserved gigabytes for a lying element count.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>

#include "mesh_files.h"
#include "rast/mesh.h"

namespace rast {
namespace {

using PlyFiles = MeshFiles;

const std::string kLittle = "ply\nformat binary_little_endian 1.0\n";
const std::string kAscii = "ply\nformat ascii 1.0\n";
const std::string kTriangleElements =
    "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
    "element face 1\nproperty list uchar int vertex_indices\n";

// Binary PLY data in either byte order.
class Data {
public:
    explicit Data(bool big_endian = false) : big_endian_(big_endian) {}
    Data& f32(float v) { return put(std::bit_cast<std::uint32_t>(v), 4); }
    Data& f64(double v) { return put(std::bit_cast<std::uint64_t>(v), 8); }
    Data& i32(std::int32_t v) { return put(static_cast<std::uint32_t>(v), 4); }
    Data& u8(std::uint8_t v) { return put(v, 1); }
    const std::string& bytes() const { return bytes_; }

private:
    Data& put(std::uint64_t v, int size) {
        for (int k = 0; k < size; ++k) bytes_ += static_cast<char>(v >> 8 * (big_endian_ ? size - 1 - k : k));
        return *this;
    }
    bool big_endian_;
    std::string bytes_;
};

// The corners (0,0,0), (1,0,0), (0,1,0), then a face of the given indices.
std::string triangle_data(std::array<std::int32_t, 3> face) {
    Data d;
    d.f32(0).f32(0).f32(0).f32(1).f32(0).f32(0).f32(0).f32(1).f32(0).u8(3);
    for (std::int32_t index : face) d.i32(index);
    return d.bytes();
}

const std::array<std::array<float, 3>, 8> kCorners{
    {{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 0, 1}, {1, 0, 1}, {1, 1, 1}, {0, 1, 1}}};
const std::array<std::array<int, 4>, 6> kQuads{
    {{0, 3, 2, 1}, {4, 5, 6, 7}, {0, 1, 5, 4}, {2, 3, 7, 6}, {1, 2, 6, 5}, {3, 0, 4, 7}}};

// The unit cube as a binary PLY of 6 quads, each header line ended by `line_break`.
std::string binary_cube(bool big_endian, const std::string& line_break) {
    std::string text;
    for (const char* line : {"ply", big_endian ? "format binary_big_endian 1.0" : "format binary_little_endian 1.0",
                             "comment a cube", "element vertex 8", "property float x", "property float y",
                             "property float z", "element face 6", "property list uchar int vertex_indices",
                             "end_header"})
        text += line + line_break;
    Data d(big_endian);
    for (const auto& c : kCorners) d.f32(c[0]).f32(c[1]).f32(c[2]);
    for (const auto& q : kQuads) d.u8(4).i32(q[0]).i32(q[1]).i32(q[2]).i32(q[3]);
    return text + d.bytes();
}

void expect_cube(const Mesh& m) {
    ASSERT_EQ(m.positions.size(), 8u);
    for (std::size_t k = 0; k < 8; ++k) EXPECT_EQ(m.positions[k], (Vec3{kCorners[k][0], kCorners[k][1], kCorners[k][2]}));
    EXPECT_EQ(m.faces.size(), 12u);  // 6 quads, triangulated
    EXPECT_TRUE(m.closed);
}

TEST_F(PlyFiles, ReadsBinaryLittleAndBigEndianAndCrLfHeaders) {
    expect_cube(read_mesh(write("le.ply", binary_cube(false, "\n"))));
    expect_cube(read_mesh(write("be.ply", binary_cube(true, "\n"))));
    expect_cube(read_mesh(write("crlf.ply", binary_cube(false, "\r\n"))));
}

TEST_F(PlyFiles, RejectsAHeaderThatEndsBeforeEndHeader) {
    EXPECT_EQ(error_of("a.ply", kLittle + "element vertex 3\nproperty float x\n"),
              "a.ply:4: the file ends before 'end_header'");
    EXPECT_EQ(error_of("a.ply", ""), "a.ply: expected 'ply' on the first line");
}

TEST_F(PlyFiles, RejectsControlCharactersInTheHeader) {
    EXPECT_EQ(error_of("a.ply", kLittle + "comment c\n" + std::string("\0\0\x0f", 3) + "element vertex 3\n"),
              "a.ply:4: control character '\\x00' in the header (column 1)");
    // A '\r' ends a line only as part of "\r\n".
    EXPECT_EQ(error_of("a.ply", kAscii + "comment a\rb\n"), "a.ply:3: control character '\\x0d' in the header (column 10)");
}

TEST_F(PlyFiles, RejectsABadFirstOrFormatLine) {
    EXPECT_EQ(error_of("a.ply", "PLY\n"), "a.ply:1: expected 'ply' on the first line");
    EXPECT_EQ(error_of("a.ply", "ply\ncomment first\nformat ascii 1.0\n"),
              "a.ply:2: expected 'format ascii|binary_little_endian|binary_big_endian 1.0' on line 2");
    EXPECT_EQ(error_of("a.ply", "ply\nformat binary 1.0\n"),
              "a.ply:2: unknown PLY format 'binary' (expected ascii, binary_little_endian or binary_big_endian)");
    EXPECT_EQ(error_of("a.ply", "ply\nformat ascii 2.0\n"), "a.ply:2: unknown PLY version '2.0' (expected 1.0)");
}

TEST_F(PlyFiles, RejectsMalformedElements) {
    EXPECT_EQ(error_of("a.ply", kLittle + "property float x\nend_header\n"), "a.ply:3: 'property' before any 'element'");
    EXPECT_EQ(error_of("a.ply", kLittle + "element vertex 4294967296\n"),
              "a.ply:3: element count 4294967296 is out of range (0 to 4294967295)");
    EXPECT_EQ(error_of("a.ply", kLittle + "element vertex -1\n"), "a.ply:3: element count -1 is out of range (0 to 4294967295)");
    EXPECT_EQ(error_of("a.ply", kLittle + "element vertex 3 x\n"), "a.ply:3: expected 'element NAME COUNT'");
    EXPECT_EQ(error_of("a.ply", kLittle + "element vertex 0\nelement vertex 0\n"),
              "a.ply:4: second element 'vertex' (the first is line 3)");
    EXPECT_EQ(error_of("a.ply", kLittle + "element face 0\n"),
              "a.ply:3: the 'face' element must follow the 'vertex' element (OpenMesh reads faces after vertices)");
    EXPECT_EQ(error_of("a.ply", kLittle + "element extra 5\nend_header\n"),
              "a.ply:3: element 'extra' has 5 records but no properties");
    EXPECT_EQ(error_of("a.ply", kAscii + "element vertex 1\nproperty float x\nproperty float y\nend_header\n0 0\n"),
              "a.ply:3: the 'vertex' element has no property 'z'");
    EXPECT_EQ(error_of("a.ply", kLittle + "obj_info element vertex\n"),
              "a.ply:3: 'obj_info' with the word 'element', which OpenMesh reads as a keyword");
}

TEST_F(PlyFiles, RejectsPropertiesOpenMeshMisreads) {
    const std::string vertex = "element vertex 3\nproperty float x\nproperty float y\n";
    EXPECT_EQ(error_of("a.ply", kLittle + vertex + "property float3 z\n"), "a.ply:6: unknown property type 'float3'");
    EXPECT_EQ(error_of("a.ply", kLittle + vertex + "property int float\n"), "a.ply:6: property name 'float' is a type name");
    EXPECT_EQ(error_of("a.ply", kLittle + vertex + "property float x\n"), "a.ply:6: second property 'x' of element 'vertex'");
    EXPECT_EQ(error_of("a.ply", kLittle + vertex + "property int z\n"),
              "a.ply:6: vertex property 'z' of type 'int': OpenMesh reads it from binary data only as float or double");
    EXPECT_EQ(error_of("a.ply", kLittle + vertex + "property list uchar float z\n"),
              "a.ply:6: list property 'vertex.z': OpenMesh reads no list but the face's 'vertex_indices'");
    const std::string triangle = kLittle + vertex + "property float z\nelement face 1\n";
    EXPECT_EQ(error_of("a.ply", triangle + "property list uchar float texcoord\n"),
              "a.ply:8: list property 'face.texcoord': OpenMesh reads no list but the face's 'vertex_indices'");
    EXPECT_EQ(error_of("a.ply", triangle + "property list uint int vertex_indices\n"),
              "a.ply:8: list count type 'uint': OpenMesh reads uchar, uint8, uint16 or int");
    EXPECT_EQ(error_of("a.ply", triangle + "property list uchar float vertex_indices\n"),
              "a.ply:8: vertex indices of type 'float': they must be integers");
    EXPECT_EQ(error_of("a.ply", triangle + "property list uchar int vertex_indices extra\n"),
              "a.ply:8: expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
}

// OpenMesh reads a double color from binary data as nothing (printing to stderr) and from text as an int; it
// drops the face properties declared before the vertex list and reads their values as the list's: the ASCII
// face "3 3 0 1 2" (flags 3, then the triangle 0 1 2) became the triangle 3 0 1, silently.
TEST_F(PlyFiles, RejectsADoubleColorAndAFacePropertyBeforeTheVertexList) {
    const std::string vertex = "element vertex 4\nproperty float x\nproperty float y\nproperty float z\n";
    for (const std::string& format : {kAscii, kLittle})
        for (const char* type : {"double", "float64"}) {
            EXPECT_EQ(error_of("a.ply", format + vertex + "property " + type + " green\n"),
                      "a.ply:7: vertex color 'green' of type '" + std::string(type) +
                          "': OpenMesh reads a color only as float or as an integer type");
            // Faces have colors too (red, green, blue, alpha): a double one made the next face a copy of
            // the first one's corners.
            EXPECT_EQ(error_of("a.ply", format + vertex + "element face 2\nproperty list uchar int vertex_indices\n" +
                                            "property " + type + " alpha\n"),
                      "a.ply:9: face color 'alpha' of type '" + std::string(type) +
                          "': OpenMesh reads a color only as float or as an integer type");
        }
    const std::string flags_first = vertex + "element face 1\nproperty uchar flags\nproperty list uchar int vertex_indices\n";
    const std::string reason = "a.ply:9: face property 'flags' before 'vertex_indices': OpenMesh skips it and misreads "
                               "every face; put the list first";
    EXPECT_EQ(error_of("a.ply", kAscii + flags_first + "end_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 3 0 1 2\n"), reason);
    EXPECT_EQ(error_of("a.ply", kLittle + flags_first + "end_header\n"), reason);
    // After the list, a face property is read past.
    const Mesh m = read_mesh(write("b.ply", kAscii + vertex +
                                                "property uchar red\nproperty float blue\nelement face 1\n"
                                                "property list uchar int vertex_indices\nproperty uchar flags\n"
                                                "end_header\n0 0 0 1 0.5\n1 0 0 2 0.5\n0 1 0 3 0.5\n0 0 1 4 0.5\n"
                                                "3 0 1 2 3\n"));
    ASSERT_EQ(m.faces.size(), 1u);
    EXPECT_EQ(m.faces[0], (std::array<std::uint32_t, 3>{0, 1, 2}));
}

// In ASCII, OpenMesh reads values as text, so integer coordinates are fine there.
TEST_F(PlyFiles, AsciiIntegerCoordinatesRead) {
    const Mesh m = read_mesh(write("a.ply", kAscii +
                                                "element vertex 3\nproperty int x\nproperty int y\nproperty int z\n"
                                                "element face 1\nproperty list uchar int vertex_indices\nend_header\n"
                                                "0 0 0\n2 0 0\n0 2 0\n3 0 1 2\n"));
    ASSERT_EQ(m.positions.size(), 3u);
    EXPECT_EQ(m.positions[1], (Vec3{2, 0, 0}));
    EXPECT_EQ(m.faces.size(), 1u);
}

// OpenMesh narrows a binary double coordinate to float. FLT_MAX + half an ulp (0x1.ffffffp127), a tie,
// narrows to infinity, and was refused as "vertex 1 has a non-finite coordinate"; the double below it
// narrows to FLT_MAX and reads. Infinity itself is non-finite, as it says.
TEST_F(PlyFiles, RejectsBinaryDoubleCoordinatesBeyondFloatRangeAsSuch) {
    const std::string header = kLittle +
                               "element vertex 3\nproperty double x\nproperty double y\nproperty double z\n"
                               "property double nx\nelement face 1\nproperty list uchar int vertex_indices\nend_header\n";
    const auto ply = [&](double x, double nx) {
        Data d;
        d.f64(0).f64(0).f64(0).f64(0).f64(x).f64(0).f64(0).f64(nx).f64(0).f64(1).f64(0).f64(0).u8(3).i32(0).i32(1).i32(2);
        return header + d.bytes();
    };
    const double tie = 0x1.ffffffp127, below = 0x1.fffffefffffffp127, inf = std::numeric_limits<double>::infinity();
    EXPECT_EQ(error_of("a.ply", ply(1e39, 0)), "a.ply: vertex 1 of 3: x = 1e+39 exceeds float range: meshes are read as float");
    EXPECT_EQ(error_of("a.ply", ply(-tie, 0)),
              "a.ply: vertex 1 of 3: x = -3.4028235677973366e+38 exceeds float range: meshes are read as float");
    EXPECT_EQ(error_of("a.ply", ply(0, tie)),
              "a.ply: vertex 1 of 3: nx = 3.4028235677973366e+38 exceeds float range: meshes are read as float");
    EXPECT_EQ(error_of("a.ply", ply(inf, 0)), "a.ply: vertex 1 has a non-finite coordinate");
    const Mesh m = read_mesh(write("b.ply", ply(-below, below)));
    EXPECT_EQ(m.positions.at(1), (Vec3{-std::numeric_limits<float>::max(), 0, 0}));
}

// In ASCII a value must be one its declared type holds. OpenMesh reads x as float whatever its type, so
// 'property int x' with 1.5 had read 1.5; it reads a color of an integer type as int, so 1.5 or a value
// beyond int's range failed its stream and shifted every value after it.
TEST_F(PlyFiles, RejectsAsciiValuesTheirTypeDoesNotHold) {
    const std::string header = kAscii +
                               "element vertex 3\nproperty int x\nproperty float y\nproperty float z\n"
                               "property uchar red\nproperty uint green\nproperty float quality\n"
                               "element face 1\nproperty list uchar int vertex_indices\nend_header\n";
    // Vertex 1 (line 14), then the face (line 16).
    const auto ply = [&](const std::string& vertex, const std::string& face = "3 0 1 2") {
        return header + "0 0 0 0 0 0\n" + vertex + "\n0 1 0 0 0 0\n" + face + "\n";
    };
    const Mesh m = read_mesh(write("b.ply", ply("-2147483648 0 0 255 2147483647 3.4e38")));
    EXPECT_EQ(m.positions.at(1), (Vec3{-2147483648.0, 0, 0}));
    const std::pair<std::string, std::string> bad[] = {
        {ply("1.5 0 0 0 0 0"), "a.ply:14: property 'x' of type 'int': expected an integer, got '1.5'"},
        {ply("1e39 0 0 0 0 0"), "a.ply:14: property 'x' of type 'int': expected an integer, got '1e39'"},
        {ply("2147483648 0 0 0 0 0"),
         "a.ply:14: property 'x' of type 'int': 2147483648 is out of range (-2147483648 to 2147483647)"},
        {ply("1 0 0 1.5 0 0"), "a.ply:14: property 'red' of type 'uchar': expected an integer, got '1.5'"},
        {ply("1 0 0 256 0 0"), "a.ply:14: property 'red' of type 'uchar': 256 is out of range (0 to 255)"},
        {ply("1 0 0 -1 0 0"), "a.ply:14: property 'red' of type 'uchar': -1 is out of range (0 to 255)"},
        {ply("1 0 0 0 2147483648 0"), "a.ply:14: property 'green' of type 'uint': 2147483648 is out of range "
                                      "(0 to 2147483647: OpenMesh reads colors as int)"},
        {ply("1 0 0 0 0 1e39"), "a.ply:14: number '1e39' exceeds float range: meshes are read as float"},
        {ply("1 0 0 0 0 0", "3.0 0 1 2"),
         "a.ply:16: count of list 'vertex_indices' of type 'uchar': expected an integer, got '3.0'"},
        {ply("1 0 0 0 0 0", "256 0 1 2"),
         "a.ply:16: count of list 'vertex_indices' of type 'uchar': 256 is out of range (0 to 255)"},
        {ply("1 0 0 0 0 0", "3 0 1 2.5"),
         "a.ply:16: item of list 'vertex_indices' of type 'int': expected an integer, got '2.5'"}};
    for (const auto& [file, message] : bad) EXPECT_EQ(error_of("a.ply", file), message);
    // A face's color as well: 3000000000 failed OpenMesh's stream, and the next face became a copy of this
    // one's corners.
    EXPECT_EQ(error_of("a.ply", kAscii + "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                         "element face 1\nproperty list uchar int vertex_indices\nproperty uint red\n"
                                         "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 3000000000\n"),
              "a.ply:14: property 'red' of type 'uint': 3000000000 is out of range (0 to 2147483647: OpenMesh "
              "reads colors as int)");
}

TEST_F(PlyFiles, RejectsACountThatDoesNotFitTheFile) {
    // 36 bytes hold 3 vertices of 12 bytes, not a million: OpenMesh would reserve memory for them all.
    EXPECT_EQ(error_of("a.ply", kLittle + "element vertex 1000000\nproperty float x\nproperty float y\n"
                                          "property float z\nend_header\n" + std::string(36, '\0')),
              "a.ply:3: 1000000 records of at least 12 bytes do not fit in the 36 bytes of binary data");
    // A face takes at least its count byte; 49 bytes follow the header.
    EXPECT_EQ(error_of("a.ply", kLittle + "element vertex 3\nproperty float x\nproperty float y\nproperty float z\n"
                                          "element face 50\nproperty list uchar int vertex_indices\nend_header\n" +
                                          triangle_data({0, 1, 2})),
              "a.ply:7: 50 records of at least 1 byte do not fit in the 49 bytes of binary data");
}

// OpenMesh finds the binary data by going back to the end of the last word before 'end_header' and
// skipping "\nend_header\n"; after a comment line (which it reads to its end) or a trailing blank, the
// data it reads starts one byte late or early.
TEST_F(PlyFiles, RejectsAHeaderWhoseDataOpenMeshWouldMisplace) {
    const std::string commented = kLittle + kTriangleElements + "comment last\nend_header\n";
    EXPECT_EQ(error_of("a.ply", commented + triangle_data({0, 1, 2})),
              "a.ply:10: OpenMesh would read the binary data from byte " + std::to_string(commented.size() + 1) +
                  ", not " + std::to_string(commented.size()) +
                  ": 'end_header' must be alone on its line, after a line with no trailing blanks and the same line "
                  "break that is not a comment");
    const std::string blank = kLittle + kTriangleElements + "property uchar flags \nend_header\n";
    EXPECT_EQ(error_of("a.ply", blank + triangle_data({0, 1, 2}) + "\x07"),
              "a.ply:10: OpenMesh would read the binary data from byte " + std::to_string(blank.size() - 1) + ", not " +
                  std::to_string(blank.size()) +
                  ": 'end_header' must be alone on its line, after a line with no trailing blanks and the same line "
                  "break that is not a comment");
    // ASCII data is read as words, wherever it starts.
    EXPECT_EQ(read_mesh(write("b.ply", kAscii + kTriangleElements + "comment last\nend_header \n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n"))
                  .faces.size(),
              1u);
}

TEST_F(PlyFiles, RejectsBadBinaryFaces) {
    const std::string header = kLittle + kTriangleElements + "end_header\n";
    EXPECT_EQ(error_of("a.ply", header + triangle_data({0, 1, 3})),
              "a.ply: face 0 of 1: vertex index 3 is out of range (3 vertices)");
    EXPECT_EQ(error_of("a.ply", header + triangle_data({0, -1, 2})),
              "a.ply: face 0 of 1: vertex index -1 is out of range (3 vertices)");
    EXPECT_EQ(error_of("a.ply", header + triangle_data({0, 1, 1})), "a.ply: face 0 of 1: the face uses vertex 1 twice");
    std::string two_corners = triangle_data({0, 1, 2});
    two_corners[36] = 2;  // the list count, after 3 vertices of 12 bytes
    EXPECT_EQ(error_of("a.ply", header + two_corners.substr(0, 45)),
              "a.ply: face 0 of 1: a face needs at least 3 vertices, got 2");
    std::string long_list = triangle_data({0, 1, 2});
    long_list[36] = static_cast<char>(200);
    EXPECT_EQ(error_of("a.ply", header + long_list), "a.ply: face 0 of 1: a list of 200 vertices runs past the end of the file");
}

TEST_F(PlyFiles, RejectsBinaryDataThatEndsEarlyOrGoesOn) {
    const std::string header = kLittle + kTriangleElements + "end_header\n";
    EXPECT_EQ(error_of("a.ply", header + triangle_data({0, 1, 2}) + std::string(2, '\0')), "a.ply: 2 bytes after the data of the last element");
    // Two faces, each a list and a flag byte: the second face's flag is missing.
    const std::string flagged = kLittle + kTriangleElements.substr(0, kTriangleElements.find("element face")) +
                                "element face 2\nproperty list uchar int vertex_indices\nproperty uchar flags\nend_header\n";
    std::string data = triangle_data({0, 1, 2}) + "\x01";
    data += data.substr(36, 13);
    EXPECT_EQ(error_of("a.ply", flagged + data), "a.ply: the binary data ends in face 1 of 2");
}

}  // namespace
}  // namespace rast
