#include "ply_check.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cmath>
#include <limits>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "number_token.h"
#include "rast/number_text.h"
#include "rast/parse_error.h"
#include "token_lines.h"

namespace rast::detail {

namespace {

struct PlyType {
    std::string_view name;
    int size;  // bytes in binary data
    bool integer;
    bool is_signed;
};

// The PLY scalar types, by their original and by their sized names.
constexpr std::array<PlyType, 16> kTypes{{{"char", 1, true, true},     {"uchar", 1, true, false},
                                          {"short", 2, true, true},    {"ushort", 2, true, false},
                                          {"int", 4, true, true},      {"uint", 4, true, false},
                                          {"float", 4, false, true},   {"double", 8, false, true},
                                          {"int8", 1, true, true},     {"uint8", 1, true, false},
                                          {"int16", 2, true, true},    {"uint16", 2, true, false},
                                          {"int32", 4, true, true},    {"uint32", 4, true, false},
                                          {"float32", 4, false, true}, {"float64", 8, false, true}}};

const PlyType* find_type(std::string_view name) {
    for (const PlyType& type : kTypes)
        if (type.name == name) return &type;
    return nullptr;
}

// The list count types OpenMesh's reader accepts.
constexpr std::array<std::string_view, 4> kCountTypes{"uchar", "uint8", "uint16", "int"};

// The vertex properties OpenMesh reads as float: from binary data, an integer there would be read as nothing
// and shift every value after it; from text, so would a number beyond float's range.
constexpr std::array<std::string_view, 10> kFloatVertexProperties{"x", "y", "z", "nx", "ny", "nz", "u", "v", "s", "t"};

struct PlyProperty {
    std::string name;
    const PlyType* type;
    const PlyType* count_type;  // a list's, or nullptr
};

struct PlyElement {
    std::string name;
    long long count;
    std::int64_t line;
    std::vector<PlyProperty> properties;
};

bool read_as_float(const PlyElement& e, std::string_view property) {
    return e.name == "vertex" &&
           std::find(kFloatVertexProperties.begin(), kFloatVertexProperties.end(), property) !=
               kFloatVertexProperties.end();
}

// The colors OpenMesh reads, of vertices (all seven names) and of faces (the first four): one of an integer
// type as an int (from text, a larger value fails the stream and shifts every value after it), a float as
// float, a double not at all.
constexpr std::array<std::string_view, 7> kColorProperties{"red",         "green",         "blue",        "alpha",
                                                           "diffuse_red", "diffuse_green", "diffuse_blue"};
constexpr std::size_t kFaceColorProperties = 4;

bool is_color(const PlyElement& e, std::string_view property) {
    const auto names = e.name == "vertex" ? std::span(kColorProperties)
                       : e.name == "face" ? std::span(kColorProperties).first(kFaceColorProperties)
                                          : std::span<const std::string_view>();
    return std::find(names.begin(), names.end(), property) != names.end();
}

enum class PlyFormat { ascii, binary_little_endian, binary_big_endian };

struct PlyHeader {
    PlyFormat format;
    std::vector<PlyElement> elements;
    std::int64_t lines;           // 'end_header' included
    std::uintmax_t data_offset;  // where the data starts, after the 'end_header' line
};

std::string bytes(std::uintmax_t n) { return std::to_string(n) + (n == 1 ? " byte" : " bytes"); }

// "face 3 of 5": a record of an element, as errors name it.
std::string record(const PlyElement& e, long long row) {
    return e.name + " " + std::to_string(row) + " of " + std::to_string(e.count);
}

long long vertex_count(const PlyHeader& header) {
    for (const PlyElement& e : header.elements)
        if (e.name == "vertex") return e.count;
    return 0;
}

// The header's lines with their byte offsets. Control characters are refused, so that OpenMesh, which
// reads the header as whitespace-separated words, sees the words and lines seen here.
class HeaderLines {
public:
    HeaderLines(std::istream& in, const std::string& file) : in_(in), file_(file) {}

    bool next() {
        start_ = end_;
        if (!std::getline(in_, raw_)) {
            if (in_.bad()) throw ParseError(file_, 0, "read error after line " + std::to_string(line_));
            return false;
        }
        ++line_;
        end_ = start_ + raw_.size() + (in_.eof() ? 0 : 1);
        std::string_view text(raw_);
        if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
        for (std::size_t k = 0; k < text.size(); ++k) {
            const auto c = static_cast<unsigned char>(text[k]);
            if ((c < 0x20 && c != '\t') || c == 0x7f)
                fail("control character " + quote_token(std::string(1, text[k])) + " in the header (column " +
                     std::to_string(k + 1) + ")");
        }
        tokens_ = split_tokens(text);
        const std::size_t last = raw_.find_last_not_of(" \t\r");
        words_end_ = start_ + (last == std::string::npos ? 0 : last + 1);
        return true;
    }

    const std::vector<std::string>& tokens() const { return tokens_; }
    std::size_t size() const { return tokens_.size(); }
    const std::string& operator[](std::size_t k) const { return tokens_[k]; }
    std::int64_t line() const { return line_; }
    std::uintmax_t end() const { return end_; }              // the offset after the line break
    std::uintmax_t words_end() const { return words_end_; }  // the offset after the last word
    [[noreturn]] void fail(const std::string& what) const { throw ParseError(file_, line_, what); }

private:
    std::istream& in_;
    const std::string& file_;
    std::string raw_;
    std::vector<std::string> tokens_;
    std::int64_t line_ = 0;
    std::uintmax_t start_ = 0, end_ = 0, words_end_ = 0;
};

const PlyType& type_named(const HeaderLines& h, const std::string& name) {
    if (const PlyType* type = find_type(name)) return *type;
    h.fail("unknown property type " + quote_token(name));
}

void add_element(const HeaderLines& h, const std::string& file, PlyHeader& header) {
    if (h.size() != 3) h.fail("expected 'element NAME COUNT'");
    const long long count = parse_integer(h[2], file, h.line());
    // OpenMesh reads the count into an unsigned int; a larger one stops its reader in a loop.
    if (count < 0 || count > std::numeric_limits<std::uint32_t>::max())
        h.fail("element count " + h[2] + " is out of range (0 to 4294967295)");
    bool has_vertex = false;
    for (const PlyElement& e : header.elements) {
        if (e.name == h[1])
            h.fail("second element " + quote_token(h[1]) + " (the first is line " + std::to_string(e.line) + ")");
        has_vertex = has_vertex || e.name == "vertex";
    }
    if (h[1] == "face" && !has_vertex)
        h.fail("the 'face' element must follow the 'vertex' element (OpenMesh reads faces after vertices)");
    header.elements.push_back({h[1], count, h.line(), {}});
}

void add_property(const HeaderLines& h, PlyHeader& header) {
    if (header.elements.empty()) h.fail("'property' before any 'element'");
    PlyElement& e = header.elements.back();
    PlyProperty p;
    if (h.size() == 5 && h[1] == "list") {
        p = {h[4], &type_named(h, h[3]), &type_named(h, h[2])};
        if (e.name != "face" || (p.name != "vertex_indices" && p.name != "vertex_index"))
            h.fail("list property " + quote_token(e.name + "." + p.name) +
                   ": OpenMesh reads no list but the face's 'vertex_indices'");
        if (std::find(kCountTypes.begin(), kCountTypes.end(), h[2]) == kCountTypes.end())
            h.fail("list count type " + quote_token(h[2]) + ": OpenMesh reads uchar, uint8, uint16 or int");
        if (!p.type->integer) h.fail("vertex indices of type " + quote_token(h[3]) + ": they must be integers");
        // OpenMesh drops the face properties before the list, then reads their values as the list's.
        if (!e.properties.empty())
            h.fail("face property " + quote_token(e.properties.front().name) + " before '" + p.name +
                   "': OpenMesh skips it and misreads every face; put the list first");
    } else if (h.size() == 3) {
        p = {h[2], &type_named(h, h[1]), nullptr};
        // OpenMesh takes either word for the type, so a name that is a type name can swap them.
        if (find_type(p.name)) h.fail("property name " + quote_token(p.name) + " is a type name");
        if (header.format != PlyFormat::ascii && read_as_float(e, p.name) && p.type->integer)
            h.fail("vertex property '" + p.name + "' of type " + quote_token(h[1]) +
                   ": OpenMesh reads it from binary data only as float or double");
        // A double color is read as nothing from binary data and as an int from text, shifting what follows.
        if (is_color(e, p.name) && !p.type->integer && p.type->size == 8)
            h.fail(e.name + " color '" + p.name + "' of type " + quote_token(h[1]) +
                   ": OpenMesh reads a color only as float or as an integer type");
    } else {
        h.fail("expected 'property TYPE NAME' or 'property list COUNT_TYPE TYPE NAME'");
    }
    for (const PlyProperty& q : e.properties)
        if (q.name == p.name) h.fail("second property " + quote_token(p.name) + " of element " + quote_token(e.name));
    e.properties.push_back(std::move(p));
}

// obj_info is free text to the PLY format, but OpenMesh reads its words as keywords.
void check_obj_info(const HeaderLines& h) {
    for (std::size_t k = 1; k < h.size(); ++k)
        if (h[k] == "element" || h[k] == "property" || h[k] == "end_header")
            h.fail("'obj_info' with the word " + quote_token(h[k]) + ", which OpenMesh reads as a keyword");
}

// The smallest size in bytes of one record: every list empty.
std::uintmax_t smallest_record(const PlyElement& e) {
    std::uintmax_t size = 0;
    for (const PlyProperty& p : e.properties) size += static_cast<std::uintmax_t>((p.count_type ? p.count_type : p.type)->size);
    return size;
}

// OpenMesh does not read on after the 'end_header' line: it goes back to the end of the last word before
// it (the start of the next line after a comment, which it skips as a line), then skips 12 bytes
// ("\nend_header\n"), or 14 if "\r\n" follows there. The data must start where it then looks.
void check_binary_data_start(std::istream& in, const HeaderLines& h, std::uintmax_t mark) {
    std::array<char, 2> pair{};
    in.seekg(static_cast<std::streamoff>(mark));
    in.read(pair.data(), pair.size());
    in.clear();
    in.seekg(static_cast<std::streamoff>(h.end()));
    const std::uintmax_t openmesh_start = mark + (pair[0] == '\r' && pair[1] == '\n' ? 14 : 12);
    if (openmesh_start != h.end())
        h.fail("OpenMesh would read the binary data from byte " + std::to_string(openmesh_start) + ", not " +
               std::to_string(h.end()) +
               ": 'end_header' must be alone on its line, after a line with no trailing blanks and the same line "
               "break that is not a comment");
}

// Reads the header; leaves `in` at the start of the data.
PlyHeader read_header(std::istream& in, const std::string& file, std::uintmax_t size) {
    HeaderLines h(in, file);
    if (!h.next() || h.tokens() != std::vector<std::string>{"ply"}) h.fail("expected 'ply' on the first line");
    if (!h.next() || h.size() != 3 || h[0] != "format")
        h.fail("expected 'format ascii|binary_little_endian|binary_big_endian 1.0' on line 2");
    PlyHeader header;
    if (h[1] == "ascii")
        header.format = PlyFormat::ascii;
    else if (h[1] == "binary_little_endian")
        header.format = PlyFormat::binary_little_endian;
    else if (h[1] == "binary_big_endian")
        header.format = PlyFormat::binary_big_endian;
    else
        h.fail("unknown PLY format " + quote_token(h[1]) + " (expected ascii, binary_little_endian or binary_big_endian)");
    if (h[2] != "1.0") h.fail("unknown PLY version " + quote_token(h[2]) + " (expected 1.0)");

    std::uintmax_t mark = h.words_end();
    for (;;) {
        if (!h.next()) h.fail("the file ends before 'end_header'");
        if (h.size() == 0) continue;
        if (h[0] == "end_header") break;
        mark = h[0] == "comment" ? h.end() : h.words_end();
        if (h[0] == "element")
            add_element(h, file, header);
        else if (h[0] == "property")
            add_property(h, header);
        else if (h[0] == "obj_info")
            check_obj_info(h);
        else if (h[0] != "comment")
            h.fail("unknown PLY header keyword " + quote_token(h[0]));
    }
    if (h.size() != 1) h.fail("expected 'end_header' alone on its line");
    header.lines = h.line();
    header.data_offset = h.end();

    for (const PlyElement& e : header.elements) {
        if (e.count > 0 && e.properties.empty())
            throw ParseError(file, e.line, "element '" + e.name + "' has " + std::to_string(e.count) +
                                               " records but no properties");
        if (e.name != "vertex") continue;
        for (const char* axis : {"x", "y", "z"})
            if (std::none_of(e.properties.begin(), e.properties.end(), [&](const PlyProperty& p) { return p.name == axis; }))
                throw ParseError(file, e.line, std::string("the 'vertex' element has no property '") + axis + "'");
    }
    if (header.format == PlyFormat::ascii) return header;

    check_binary_data_start(in, h, mark);
    // Before OpenMesh reserves memory for the counts: each element must fit in the data at all.
    const std::uintmax_t data = size - std::min(size, header.data_offset);
    for (const PlyElement& e : header.elements) {
        const std::uintmax_t smallest = smallest_record(e);
        if (smallest > 0 && static_cast<std::uintmax_t>(e.count) > data / smallest)
            throw ParseError(file, e.line, std::to_string(e.count) + " records of at least " + bytes(smallest) +
                                               " do not fit in the " + bytes(data) + " of binary data");
    }
    return header;
}

// Token k as a value of the integer type `type`, of what `kind` and `name` say ("property", "x"): an
// integer within the type's range, and within int's if `as_int`. Else ParseError with the line.
long long integer_of_type(const TokenLines& in, std::size_t k, const PlyType& type, const char* kind,
                          const std::string& name, bool as_int = false) {
    const auto fail = [&](const std::string& why) {
        in.fail(std::string(kind) + " '" + name + "' of type '" + std::string(type.name) + "': " + why);
    };
    long long value = 0;
    try {
        value = in.integer(k);
    } catch (const ParseError& e) {
        fail(e.message);
    }
    const int bits = 8 * type.size;
    const long long low = type.is_signed ? -(1LL << (bits - 1)) : 0;
    const long long type_high = type.is_signed ? (1LL << (bits - 1)) - 1 : (1LL << bits) - 1;
    const bool capped = as_int && type_high > std::numeric_limits<int>::max();
    const long long high = capped ? std::numeric_limits<int>::max() : type_high;
    if (value < low || value > high)
        fail(in[k] + " is out of range (" + std::to_string(low) + " to " + std::to_string(high) +
             (capped ? ": OpenMesh reads colors as int)" : ")"));
    return value;
}

// Token k as a value of the property p that is not a list: a number its type holds, and one OpenMesh reads
// as written where it reads it.
void check_ascii_value(const TokenLines& in, std::size_t k, const PlyElement& e, const PlyProperty& p) {
    if (p.type->integer)
        integer_of_type(in, k, *p.type, "property", p.name, is_color(e, p.name));
    else if (p.type->size == 4 || read_as_float(e, p.name))
        float_coordinate(in, k);
    else
        in.number(k);
}

MeshFileCheck check_ascii_data(TokenLines& in, const PlyHeader& header) {
    MeshFileCheck result{0, std::nullopt};
    const long long vertices = vertex_count(header);
    for (const PlyElement& e : header.elements)
        for (long long row = 0; row < e.count; ++row) {
            in.expect(record(e, row));
            std::size_t at = 0;
            for (const PlyProperty& p : e.properties) {
                if (at >= in.size()) in.fail("too few values for element '" + e.name + "': " + values(in.size()));
                if (!p.count_type) {
                    check_ascii_value(in, at++, e, p);
                    continue;
                }
                const long long n = integer_of_type(in, at++, *p.count_type, "count of list", p.name);
                if (n < 3) in.fail("a face needs at least 3 vertices, got " + std::to_string(n));
                if (n > static_cast<long long>(in.size() - at))
                    in.fail("list '" + p.name + "' of " + std::to_string(n) + " items does not fit the line");
                FaceCheck face(in.file(), in.line(), vertices);
                for (long long k = 0; k < n; ++k, ++at)
                    face.add(integer_of_type(in, at, *p.type, "item of list", p.name), in[at]);
                *result.triangles += static_cast<std::size_t>(n) - 2;
            }
            if (at != in.size())
                in.fail("too many values for element '" + e.name + "': " + values(in.size()) + ", expected " +
                        std::to_string(at));
        }
    // OpenMesh stops reading where the header's counts end: a line more would be dropped unseen.
    if (in.next()) in.fail("a line after the last element the header declares");
    return result;
}

// Binary data value by value, in the byte order of the format.
class BinaryData {
public:
    BinaryData(std::istream& in, const std::string& file, bool big_endian, std::uintmax_t remaining)
        : in_(in), file_(file), big_endian_(big_endian), remaining_(remaining) {}

    std::uintmax_t remaining() const { return remaining_; }

    void skip(const PlyType& type, const PlyElement& e, long long row) { bits(type, e, row); }

    // A float or a double.
    double real(const PlyType& type, const PlyElement& e, long long row) {
        const std::uint64_t value = bits(type, e, row);
        return type.size == 8 ? std::bit_cast<double>(value)
                              : std::bit_cast<float>(static_cast<std::uint32_t>(value));
    }

    long long integer(const PlyType& type, const PlyElement& e, long long row) {
        const std::uint64_t value = bits(type, e, row);
        if (!type.is_signed) return static_cast<long long>(value);
        const int unused = 64 - 8 * type.size;  // sign-extend from the type's width
        return static_cast<long long>(value << unused) >> unused;
    }

private:
    std::uint64_t bits(const PlyType& type, const PlyElement& e, long long row) {
        const auto size = static_cast<std::size_t>(type.size);
        std::array<unsigned char, 8> bytes{};
        if (remaining_ < size || !in_.read(reinterpret_cast<char*>(bytes.data()), type.size)) {
            if (in_.bad()) throw ParseError(file_, 0, "read error in " + record(e, row));
            throw ParseError(file_, 0, "the binary data ends in " + record(e, row));
        }
        remaining_ -= size;
        std::uint64_t value = 0;
        for (std::size_t k = 0; k < size; ++k) value |= std::uint64_t{bytes[big_endian_ ? size - 1 - k : k]} << (8 * k);
        return value;
    }

    std::istream& in_;
    const std::string& file_;
    bool big_endian_;
    std::uintmax_t remaining_;
};

// OpenMesh narrows a double it reads as float: a finite one from FLT_MAX + half an ulp on becomes infinity
// (a position would then be blamed as non-finite, a normal kept so). Refused as in ASCII; a non-finite
// position is reported as such after the read.
void check_float_range(double value, const PlyElement& e, long long row, const PlyProperty& p,
                       const std::string& file) {
    if (!std::isfinite(value) || !std::isinf(static_cast<float>(value))) return;
    throw ParseError(file, 0, record(e, row) + ": " + p.name + " = " + shortest(value) +
                                  " exceeds float range: meshes are read as float");
}

MeshFileCheck check_binary_data(std::istream& in, const PlyHeader& header, const std::string& file,
                                std::uintmax_t remaining) {
    MeshFileCheck result{0, std::nullopt};
    BinaryData data(in, file, header.format == PlyFormat::binary_big_endian, remaining);
    const long long vertices = vertex_count(header);
    for (const PlyElement& e : header.elements)
        for (long long row = 0; row < e.count; ++row)
            for (const PlyProperty& p : e.properties) {
                if (!p.count_type) {
                    if (read_as_float(e, p.name))
                        check_float_range(data.real(*p.type, e, row), e, row, p, file);
                    else
                        data.skip(*p.type, e, row);
                    continue;
                }
                const long long n = data.integer(*p.count_type, e, row);
                const std::string where = record(e, row) + ": ";
                if (n < 3) throw ParseError(file, 0, where + "a face needs at least 3 vertices, got " + std::to_string(n));
                if (static_cast<std::uintmax_t>(n) > data.remaining() / static_cast<std::uintmax_t>(p.type->size))
                    throw ParseError(file, 0, where + "a list of " + std::to_string(n) + " vertices runs past the end of the file");
                FaceCheck face(file, 0, vertices, where);
                for (long long k = 0; k < n; ++k) {
                    const long long index = data.integer(*p.type, e, row);
                    face.add(index, std::to_string(index));
                }
                *result.triangles += static_cast<std::size_t>(n) - 2;
            }
    if (data.remaining() != 0)
        throw ParseError(file, 0, bytes(data.remaining()) + " after the data of the last element");
    return result;
}

}  // namespace

MeshFileCheck check_ply(std::istream& in, const std::string& file, std::uintmax_t size) {
    const PlyHeader header = read_header(in, file, size);
    if (header.format != PlyFormat::ascii)
        return check_binary_data(in, header, file, size - std::min(size, header.data_offset));
    TokenLines lines(in, file, false, header.lines);
    return check_ascii_data(lines, header);
}

}  // namespace rast::detail
