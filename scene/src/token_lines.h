// rast — what the validating passes over text mesh files share: their lines as tokens, and the check of a
// face's vertex indices.
#pragma once

#include <cstdint>
#include <istream>
#include <string>
#include <vector>

namespace rast::detail {

// The non-blank lines of a text file as tokens, with their line numbers.
class TokenLines {
public:
    // lines_before: lines already read from `in` (a header read another way), so that numbers stay true.
    TokenLines(std::istream& in, std::string file, bool hash_comments, std::int64_t lines_before = 0);

    // The next non-blank line; false at the end of the file.
    bool next();
    // Like next(), but the end of the file is an error: it ends before `what`.
    void expect(const std::string& what);

    const std::vector<std::string>& tokens() const { return tokens_; }
    std::size_t size() const { return tokens_.size(); }
    const std::string& operator[](std::size_t k) const { return tokens_[k]; }
    // Token k as a decimal number (see parse_finite_double), else ParseError with the line: also for a hex
    // float, which OpenMesh does not read as written.
    double number(std::size_t k) const;
    long long integer(std::size_t k) const { return integer(tokens_[k]); }
    long long integer(const std::string& text) const;
    [[noreturn]] void fail(const std::string& what) const;

    const std::string& file() const { return file_; }
    std::int64_t line() const { return line_; }

private:
    std::istream& in_;
    std::string file_;
    bool hash_comments_;
    std::int64_t line_;
    std::vector<std::string> tokens_;
};

// "1 value", "3 values".
std::string values(std::size_t n);

// The vertex indices of one face: each in [0, vertex_count) and used once (OpenMesh drops other faces).
// A problem throws ParseError at `line` of `file` (0: no line, as in binary data), `where` before the message.
class FaceCheck {
public:
    FaceCheck(const std::string& file, std::int64_t line, long long vertex_count, std::string where = "");
    void add(long long index, const std::string& as_written);

private:
    const std::string& file_;
    std::int64_t line_;
    long long vertex_count_;
    std::string where_;
    std::vector<long long> used_;
};

}  // namespace rast::detail
