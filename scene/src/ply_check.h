// rast — the validating pass over PLY files, ASCII and binary, before OpenMesh reads them. OpenMesh's PLY
// reader trusts its input: a header that ends before 'end_header' makes it loop forever, a 'property'
// before any 'element' crashes it, a lying element count makes it reserve gigabytes, and a list it does not
// expect, or a comment line right before 'end_header' of a binary file, shifts every value after it.
#pragma once

#include <cstdint>
#include <istream>
#include <string>

#include "mesh_text_check.h"

namespace rast::detail {

// `in` is the file `file`, opened in binary mode, at its start; `size` is its size in bytes.
// The header must be what OpenMesh reads as written: 'ply', then 'format ascii|binary_little_endian|
// binary_big_endian 1.0', then lines of 'comment', 'obj_info', 'element NAME COUNT' (each name once, the
// face after the vertex), 'property TYPE NAME' (a known type; x, y, z, nx, ny, nz, u, v, s, t of a binary
// vertex as float or double; a color, red, green, blue, alpha or a vertex's diffuse_*, not as double) and
// 'property list COUNT_TYPE TYPE vertex_indices' of the face (the one list OpenMesh reads, before any other
// face property; counts as uchar, uint8, uint16 or int, integer indices), then 'end_header'; no control
// characters but tabs and the "\r" of "\r\n"; a vertex with x, y and z. Binary data must start where
// OpenMesh looks for it, hold at least COUNT times the smallest record of each element, and end with the
// last element. Every face, in either format, has at least 3 vertex indices, each in range and used once; a
// vertex's x, y, z, nx, ny, nz, u, v, s, t, when finite, are within float's range (in ASCII, see
// float_coordinate; in binary, a double that narrows to infinity is refused). An ASCII value is one its type
// holds: an integer within the type's range (a color's also within int's, as OpenMesh reads it), a float
// within float's range.
// Throws ParseError: with the line for the header and the ASCII data, with the record for binary data.
MeshFileCheck check_ply(std::istream& in, const std::string& file, std::uintmax_t size);

}  // namespace rast::detail
