#include "mesh_text_check.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <vector>

#include "number_token.h"
#include "ply_check.h"
#include "rast/parse_error.h"
#include "token_lines.h"

namespace rast::detail {

namespace {

MeshFileCheck check_obj(TokenLines& in) {
    MeshFileCheck result{0, std::nullopt};
    long long vertices = 0;
    while (in.next()) {
        if (in[0] == "v") {
            if (in.size() < 4) in.fail("'v' expects at least 3 numbers (x y z), got " + values(in.size() - 1));
            for (std::size_t k = 1; k < 4; ++k) float_coordinate(in, k);
            for (std::size_t k = 4; k < in.size(); ++k) in.number(k);
            ++vertices;
        } else if (in[0] == "vt" || in[0] == "vn") {
            // Texture coordinates and normals are read as floats too: OpenMesh gives up on the whole file
            // at a 'vt' it cannot read, without a line.
            const std::size_t least = in[0] == "vt" ? 2 : 3;
            if (in.size() < least + 1)
                in.fail("'" + in[0] + "' expects at least " + std::to_string(least) + " numbers, got " +
                        values(in.size() - 1));
            for (std::size_t k = 1; k < in.size(); ++k) float_coordinate(in, k);
        } else if (in[0] == "f") {
            if (in.size() < 4) in.fail("'f' expects at least 3 vertices, got " + values(in.size() - 1));
            // OBJ counts from 1; a negative index counts back from the last vertex so far.
            FaceCheck face(in.file(), in.line(), vertices);
            for (std::size_t k = 1; k < in.size(); ++k) {
                const std::string written = in[k].substr(0, in[k].find('/'));
                const long long index = in.integer(written);
                face.add(index > 0 ? index - 1 : index < 0 ? vertices + index : -1, written);
            }
            *result.triangles += in.size() - 3;
        }
    }
    return result;
}

// The tokens of the current line, as one line of text.
std::string joined(const TokenLines& in, std::size_t first = 0) {
    std::string line;
    for (std::size_t k = first; k < in.size(); ++k) line += (k > first ? " " : "") + in[k];
    return line + "\n";
}

MeshFileCheck check_off(TokenLines& in) {
    in.expect("the OFF header");
    const std::string keyword = in[0];
    if (keyword.size() < 3 || keyword.compare(keyword.size() - 3, 3, "OFF") != 0)
        in.fail("expected an OFF header, got " + quote_token(keyword));
    // OpenMesh's binary OFF reader trusts its counts: negative ones throw std::bad_alloc, and a small
    // well-formed file came back without faces.
    if (std::find(in.tokens().begin(), in.tokens().end(), "BINARY") != in.tokens().end())
        in.fail("binary OFF is not supported (OpenMesh misreads it); write it as ASCII OFF or as PLY");
    MeshFileCheck result{0, keyword + "\n"};
    std::string& text = *result.off_for_openmesh;
    std::size_t first = 1;
    if (in.size() == 1) {
        in.expect("the counts 'vertices faces edges'");
        first = 0;
    }
    if (in.size() - first != 3)
        in.fail("expected the counts 'vertices faces edges', got " + values(in.size() - first));
    const long long vertex_count = in.integer(first), face_count = in.integer(first + 1);
    in.integer(first + 2);
    if (vertex_count < 0 || face_count < 0) in.fail("negative vertex or face count");
    text += joined(in, first);
    for (long long v = 0; v < vertex_count; ++v) {
        in.expect("vertex " + std::to_string(v) + " of " + std::to_string(vertex_count));
        if (in.size() < 3) in.fail("a vertex needs at least 3 numbers (x y z), got " + values(in.size()));
        for (std::size_t k = 0; k < 3; ++k) float_coordinate(in, k);
        for (std::size_t k = 3; k < in.size(); ++k) in.number(k);
        text += joined(in);
    }
    for (long long f = 0; f < face_count; ++f) {
        in.expect("face " + std::to_string(f) + " of " + std::to_string(face_count));
        const long long n = in.integer(0);
        if (n < 3) in.fail("a face needs at least 3 vertices, got " + std::to_string(n));
        if (static_cast<long long>(in.size()) - 1 < n)
            in.fail("the face lists " + std::to_string(n) + " vertices but gives " + values(in.size() - 1));
        FaceCheck face(in.file(), in.line(), vertex_count);
        for (long long k = 1; k <= n; ++k) face.add(in.integer(static_cast<std::size_t>(k)), in[static_cast<std::size_t>(k)]);
        for (std::size_t k = static_cast<std::size_t>(n) + 1; k < in.size(); ++k) in.number(k);
        *result.triangles += static_cast<std::size_t>(n) - 2;
        text += joined(in);
    }
    // OpenMesh reads as many faces as the header declares: a line more would be dropped unseen.
    if (in.next()) in.fail("a line after the last face the header declares");
    return result;
}

// Each facet is 'facet normal NX NY NZ', 'outer loop', three 'vertex X Y Z', 'endloop', 'endfacet', in that
// order; a facet cut short (a file that ends inside one) is an error, not a triangle fewer.
void check_ascii_stl(TokenLines& in) {
    in.expect("'solid'");
    if (in[0] != "solid") in.fail("expected 'solid' (and the size does not fit a binary STL)");
    enum class At { between_facets, facet, loop, loop_ended };
    At at = At::between_facets;
    const auto next_keyword = [&at] {
        switch (at) {
            case At::between_facets: return "'facet' or 'endsolid'";
            case At::facet: return "'outer loop'";
            case At::loop: return "'vertex' or 'endloop'";
            case At::loop_ended: return "'endfacet'";
        }
        return "";
    };
    // The keyword on this line may come only `where`.
    const auto allowed = [&](At where) {
        if (at != where) in.fail("expected " + std::string(next_keyword()) + ", got " + quote_token(in[0]));
    };
    // 'endloop' and 'endfacet' stand alone on their lines: a keyword after one went unchecked.
    const auto alone = [&in] {
        if (in.size() != 1)
            in.fail("expected " + quote_token(in[0]) + " alone on its line, got " + values(in.size() - 1) + " after it");
    };
    int loop_vertices = 0;
    while (in.next()) {
        const std::string& keyword = in[0];
        if (keyword == "facet") {
            allowed(At::between_facets);
            if (in.size() != 5 || in[1] != "normal") in.fail("expected 'facet normal NX NY NZ'");
            for (std::size_t k = 2; k < 5; ++k) in.number(k);
            at = At::facet;
        } else if (keyword == "outer") {
            allowed(At::facet);
            if (in.size() != 2 || in[1] != "loop") in.fail("expected 'outer loop'");
            loop_vertices = 0;
            at = At::loop;
        } else if (keyword == "vertex") {
            allowed(At::loop);
            if (in.size() != 4) in.fail("'vertex' expects 3 numbers (x y z), got " + values(in.size() - 1));
            for (std::size_t k = 1; k < 4; ++k) float_coordinate(in, k);
            ++loop_vertices;
        } else if (keyword == "endloop") {
            allowed(At::loop);
            alone();
            if (loop_vertices != 3)
                in.fail("a facet has " + std::to_string(loop_vertices) + " vertices; STL facets are triangles");
            at = At::loop_ended;
        } else if (keyword == "endfacet") {
            allowed(At::loop_ended);
            alone();
            at = At::between_facets;
        } else if (keyword == "endsolid" || keyword == "solid") {
            allowed(At::between_facets);
        } else {
            in.fail("unknown STL keyword " + quote_token(keyword));
        }
    }
    if (at != At::between_facets) in.fail("the file ends inside a facet, before " + std::string(next_keyword()));
}

// A binary STL is an 80-byte header, a 32-bit little-endian triangle count and 50 bytes per triangle
// (normal, three corners, as little-endian float32, and 2 attribute bytes); a file whose size matches
// that is binary even if its header starts with "solid", as many do. Returns the count if binary.
std::optional<std::uint32_t> binary_stl_triangles(std::istream& in, std::uintmax_t size) {
    std::array<unsigned char, 84> head{};
    if (size < head.size() || !in.read(reinterpret_cast<char*>(head.data()), head.size())) return std::nullopt;
    const std::uint32_t count = head[80] | head[81] << 8 | head[82] << 16 | std::uint32_t{head[83]} << 24;
    if (size != 84 + 50 * std::uintmax_t{count}) return std::nullopt;
    return count;
}

void check_binary_stl(std::istream& in, std::uint32_t count, const std::string& file) {
    std::array<unsigned char, 50> record{};
    for (std::uint32_t t = 0; t < count; ++t) {
        if (!in.read(reinterpret_cast<char*>(record.data()), record.size()))
            throw ParseError(file, 0, "read error in triangle " + std::to_string(t));
        for (std::size_t c = 3; c < 12; ++c) {
            const std::uint32_t bits = record[4 * c] | record[4 * c + 1] << 8 | record[4 * c + 2] << 16 |
                                       std::uint32_t{record[4 * c + 3]} << 24;
            if ((bits & 0x7f800000u) == 0x7f800000u)  // exponent all ones: infinity or NaN
                throw ParseError(file, 0, "triangle " + std::to_string(t) + " has a non-finite coordinate");
        }
    }
}

}  // namespace

float float_coordinate(const TokenLines& in, std::size_t k) {
    in.number(k);
    // OpenMesh reads it with strtof.
    const float value = read_float(in[k]);
    if (std::isinf(value)) in.fail("number " + quote_token(in[k]) + " exceeds float range: meshes are read as float");
    return value;
}

MeshFileCheck check_mesh_file(const std::filesystem::path& path, const std::string& extension) {
    const std::string file = path.string();
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ParseError(file, 0, "cannot open");
    const std::uintmax_t size = std::filesystem::file_size(path);
    if (extension == "ply") return check_ply(in, file, size);
    if (extension == "stl") {
        if (const auto count = binary_stl_triangles(in, size)) {
            check_binary_stl(in, *count, file);
            return {};
        }
        in.clear();
        in.seekg(0);
        TokenLines lines(in, file, false);
        check_ascii_stl(lines);
        return {};
    }
    TokenLines lines(in, file, true);
    return extension == "obj" ? check_obj(lines) : check_off(lines);
}

}  // namespace rast::detail
