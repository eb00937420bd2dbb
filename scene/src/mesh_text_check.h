// rast — a validating pass over text mesh files, before OpenMesh reads them: OpenMesh reports no line
// numbers, reads numbers leniently and skips faces it cannot use.
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>

namespace rast::detail {

class TokenLines;

struct MeshFileCheck {
    // For OBJ, OFF and PLY, the faces OpenMesh must produce: the sum of (corners - 2) over the
    // polygons, which it triangulates as a fan. Then a face it dropped is noticed.
    std::optional<std::size_t> triangles;
    // For ASCII OFF, the file rewritten for OpenMesh's OFF reader, which reads nothing from a file with
    // comments or with the counts on the header line (and still reports success).
    std::optional<std::string> off_for_openmesh;
};

// For OBJ, OFF, ASCII PLY and ASCII STL (extension lower case, without the dot): throws ParseError with
// file and line for a malformed or non-finite number, a hex float (see TokenLines::number), a vertex
// coordinate, OBJ texture coordinate or normal beyond float's range (see float_coordinate), a wrong count
// of values, a face index out of range or repeated within a face, or a file that ends early. For PLY,
// ASCII or binary, see ply_check.h. For binary STL: a non-finite coordinate (OpenMesh merges STL corners by
// position, and NaN would merge with anything). Binary OFF is refused.
MeshFileCheck check_mesh_file(const std::filesystem::path& path, const std::string& extension);

// Token k of the current line as a number OpenMesh reads as a float (a coordinate): a number (see
// TokenLines::number) that strtof reads as a finite float (see read_float: 3.4028235e38 becomes FLT_MAX;
// 3.4028236e38 is refused), else ParseError with the line. OpenMesh drops a vertex it cannot read, which
// shifts the index of every vertex after it, and blames a face.
float float_coordinate(const TokenLines& in, std::size_t k);

}  // namespace rast::detail
