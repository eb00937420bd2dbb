#include "rast/tri_format.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <fstream>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <stdexcept>
#include <string_view>
#include <system_error>

#include "number_token.h"
#include "rast/atomic_file.h"
#include "rast/scene_limits.h"

namespace rast {

namespace {

// A line ends at '\n' or "\r\n", for the reader and the writer alike; a carriage return anywhere else is
// neither a line break nor a blank, so it is rejected rather than kept in a value that would not write back.
bool is_blank(char c) { return c == ' ' || c == '\t' || c == '\v' || c == '\f'; }

// The line as std::getline gave it, without the '\r' of a "\r\n" line break.
std::string_view line_content(const std::string& line, const std::string& file, std::int64_t line_number) {
    std::string_view text(line);
    if (!text.empty() && text.back() == '\r') text.remove_suffix(1);
    if (text.find('\r') != std::string_view::npos)
        throw ParseError(file, line_number, "a carriage return inside the line (a line ends with '\\n' or '\\r\\n')");
    return text;
}

bool is_key_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
           c == '-' || c == '.';
}

bool is_key(std::string_view key) {
    if (key.empty()) return false;
    for (char c : key)
        if (!is_key_char(c)) return false;
    return true;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_blank(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_blank(s.back())) s.remove_suffix(1);
    return s;
}

// "# key: value" on a line that is only a comment; anything else is an ordinary comment.
std::optional<std::pair<std::string, std::string>> header_entry(std::string_view line) {
    line = trim(line);
    if (line.empty() || line.front() != '#') return std::nullopt;
    line = trim(line.substr(1));
    const std::size_t colon = line.find(':');
    if (colon == std::string_view::npos || !is_key(line.substr(0, colon))) return std::nullopt;
    return std::pair{std::string(line.substr(0, colon)), std::string(trim(line.substr(colon + 1)))};
}

int parse_int(std::string_view token, const std::string& file, std::int64_t line) {
    const long long value = detail::parse_integer(token, file, line);
    if (value < std::numeric_limits<int>::min() || value > std::numeric_limits<int>::max())
        throw ParseError(file, line, "integer " + quote_token(token) + " is out of range");
    return static_cast<int>(value);
}

void expect_arity(const std::vector<std::string_view>& tokens, std::size_t count, const char* what,
                  const std::string& file, std::int64_t line) {
    const std::size_t got = tokens.size() - 1;
    if (got != count)
        throw ParseError(file, line, "'" + std::string(tokens[0]) + "' expects " + what + ", got " +
                                         std::to_string(got) + (got == 1 ? " value" : " values"));
}

// x, y and z from tokens[first], tokens[first + 1] and tokens[first + 2].
Vertex parse_vertex(const std::vector<std::string_view>& tokens, std::size_t first, const std::string& file,
                    std::int64_t line) {
    return {detail::parse_finite_double(tokens[first], file, line),
            detail::parse_finite_double(tokens[first + 1], file, line),
            detail::parse_finite_double(tokens[first + 2], file, line)};
}

// Runs a check from scene_limits.h and reports its complaint at the given line.
template <class Check>
void at_line(const std::string& file, std::int64_t line, Check check) {
    try {
        check();
    } catch (const std::invalid_argument& e) {
        throw ParseError(file, line, e.what());
    }
}

}  // namespace

TriDocument read_tri_document(std::istream& in, const std::string& name) {
    TriDocument doc;
    std::int64_t line_number = 0, viewport_line = 0, samples_line = 0;
    bool in_header = true;
    std::string line;
    std::vector<std::string_view> tokens;
    while (std::getline(in, line)) {
        ++line_number;
        const std::string_view content = line_content(line, name, line_number);
        detail::split_tokens(content.substr(0, content.find('#')), tokens);
        if (tokens.empty()) {
            if (in_header)
                if (auto entry = header_entry(content)) doc.header.push_back(std::move(*entry));
            continue;
        }
        in_header = false;
        const std::string keyword(tokens[0]);
        if (keyword == "tri") {
            expect_arity(tokens, 9, "9 numbers (three vertices x y z)", name, line_number);
            Triangle t;
            for (std::size_t k = 0; k < 3; ++k) t.v[k] = parse_vertex(tokens, 1 + 3 * k, name, line_number);
            doc.scene.triangles.push_back(t);
        } else if (keyword == "line") {
            expect_arity(tokens, 6, "6 numbers (two ends x y z)", name, line_number);
            Segment segment;
            for (std::size_t k = 0; k < 2; ++k) segment.v[k] = parse_vertex(tokens, 1 + 3 * k, name, line_number);
            append_line(doc.scene, segment);
        } else if (keyword == "viewport") {
            if (viewport_line != 0)
                throw ParseError(name, line_number,
                                 "second 'viewport' line (the first is line " + std::to_string(viewport_line) + ")");
            expect_arity(tokens, 2, "2 integers (width height)", name, line_number);
            doc.scene.viewport = {parse_int(tokens[1], name, line_number), parse_int(tokens[2], name, line_number)};
            at_line(name, line_number, [&] { check_viewport(doc.scene.viewport); });
            viewport_line = line_number;
        } else if (keyword == "samples") {
            if (samples_line != 0)
                throw ParseError(name, line_number,
                                 "second 'samples' line (the first is line " + std::to_string(samples_line) + ")");
            expect_arity(tokens, 1, "1 integer (1, 4, 8 or 16)", name, line_number);
            doc.scene.samples = parse_int(tokens[1], name, line_number);
            at_line(name, line_number, [&] { check_sample_count(doc.scene.samples); });
            samples_line = line_number;
        } else {
            throw ParseError(name, line_number,
                             "unknown keyword " + quote_token(keyword) + " (expected viewport, samples, tri or line)");
        }
    }
    if (in.bad()) throw ParseError(name, 0, "read error after line " + std::to_string(line_number));
    if (viewport_line == 0) throw ParseError(name, 0, "missing 'viewport W H' line");
    // The product of the sizes is the later line's fault: that is where the scene became too large.
    at_line(name, std::max(viewport_line, samples_line),
            [&] { check_scene_size(doc.scene.viewport, doc.scene.samples); });
    return doc;
}

TriDocument read_tri_document_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) throw ParseError(path.string(), 0, "cannot open: " + std::generic_category().message(errno));
    return read_tri_document(in, path.string());
}

Scene read_tri(std::istream& in, const std::string& name) { return read_tri_document(in, name).scene; }

Scene read_tri_file(const std::filesystem::path& path) { return read_tri_document_file(path).scene; }

std::string header_value(std::string text) {
    std::replace(text.begin(), text.end(), '\n', ' ');
    std::replace(text.begin(), text.end(), '\r', ' ');
    const std::string_view value = trim(text);
    return value.empty() ? "-" : std::string(value);
}

std::string hex_float(double value) {
    char digits[64];
    const auto [end, error] = std::to_chars(digits, digits + sizeof digits, value, std::chars_format::hex);
    if (error != std::errc{}) throw std::logic_error("hex_float: buffer too small");
    // to_chars omits the "0x" that C99 (and strtod) expect.
    const std::string_view body(digits, static_cast<std::size_t>(end - digits));
    return body.front() == '-' ? "-0x" + std::string(body.substr(1)) : "0x" + std::string(body);
}

void write_tri(std::ostream& out, const Scene& scene, const TriHeader& header) {
    check_scene_size(scene.viewport, scene.samples);
    for (const auto& [key, value] : header) {
        if (!is_key(key))
            throw std::invalid_argument("write_tri: header key " + quote_token(key) +
                                        " must be letters, digits, '_', '-' or '.'");
        if (value.find_first_of("\n\r") != std::string::npos || trim(value) != value)
            throw std::invalid_argument("write_tri: the value of header key '" + key +
                                        "' has a line feed, a carriage return or surrounding blanks");
    }
    const std::vector<std::int32_t> ids = triangle_ids(scene);
    const auto finite = [](const auto& vertices, const char* what, std::size_t index) {
        for (const Vertex& v : vertices)
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                throw std::invalid_argument(std::string("write_tri: ") + what + " " + std::to_string(index) +
                                            " has a non-finite coordinate");
    };
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) finite(scene.triangles[k].v, "triangle", k);
    for (std::size_t k = 0; k < scene.lines.size(); ++k) finite(scene.lines[k].segment.v, "line", k);

    std::string text;
    for (const auto& [key, value] : header) text += "# " + key + ":" + (value.empty() ? "" : " " + value) + "\n";
    text += "viewport " + std::to_string(scene.viewport.width) + " " + std::to_string(scene.viewport.height) + "\n";
    text += "samples " + std::to_string(scene.samples) + "\n";
    const auto statement = [&text](const char* keyword, const auto& vertices) {
        text += keyword;
        for (const Vertex& v : vertices) text += "  " + hex_float(v.x) + " " + hex_float(v.y) + " " + hex_float(v.z);
        text += "\n";
    };
    // In id order, so that the file gives every triangle and line its id back.
    std::size_t line = 0;
    for (std::size_t k = 0; k < scene.triangles.size(); ++k) {
        for (; line < scene.lines.size() && scene.lines[line].id < ids[k]; ++line)
            statement("line", scene.lines[line].segment.v);
        statement("tri", scene.triangles[k].v);
    }
    for (; line < scene.lines.size(); ++line) statement("line", scene.lines[line].segment.v);
    if (!(out << text)) throw std::runtime_error("write_tri: the output stream failed");
}

void write_tri_file(const std::filesystem::path& path, const Scene& scene, const TriHeader& header) {
    std::ostringstream text;
    write_tri(text, scene, header);
    write_file_atomic(path, text.str());
}

}  // namespace rast
