#include "token_lines.h"

#include <algorithm>

#include "number_token.h"
#include "rast/parse_error.h"

namespace rast::detail {

TokenLines::TokenLines(std::istream& in, std::string file, bool hash_comments, std::int64_t lines_before)
    : in_(in), file_(std::move(file)), hash_comments_(hash_comments), line_(lines_before) {}

bool TokenLines::next() {
    std::string text;
    while (std::getline(in_, text)) {
        ++line_;
        if (hash_comments_) text.erase(std::min(text.find('#'), text.size()));
        tokens_ = split_tokens(text);
        if (!tokens_.empty()) return true;
    }
    if (in_.bad()) throw ParseError(file_, 0, "read error after line " + std::to_string(line_));
    tokens_.clear();
    return false;
}

void TokenLines::expect(const std::string& what) {
    if (!next()) fail("the file ends before " + what);
}

double TokenLines::number(std::size_t k) const {
    const double value = parse_finite_double(tokens_[k], file_, line_);
    // Of what parse_finite_double accepts, only a hex float holds an 'x'. OpenMesh reads numbers with C++
    // streams, which read a hex float's leading "0" and stop at the 'x'.
    if (tokens_[k].find_first_of("xX") != std::string::npos)
        fail("hex float " + quote_token(tokens_[k]) + ": mesh files take decimal numbers (OpenMesh misreads hex floats)");
    return value;
}

long long TokenLines::integer(const std::string& text) const { return parse_integer(text, file_, line_); }

void TokenLines::fail(const std::string& what) const { throw ParseError(file_, line_, what); }

std::string values(std::size_t n) { return std::to_string(n) + (n == 1 ? " value" : " values"); }

FaceCheck::FaceCheck(const std::string& file, std::int64_t line, long long vertex_count, std::string where)
    : file_(file), line_(line), vertex_count_(vertex_count), where_(std::move(where)) {}

void FaceCheck::add(long long index, const std::string& as_written) {
    if (index < 0 || index >= vertex_count_)
        throw ParseError(file_, line_, where_ + "vertex index " + as_written + " is out of range (" +
                                           std::to_string(vertex_count_) + " vertices)");
    if (std::find(used_.begin(), used_.end(), index) != used_.end())
        throw ParseError(file_, line_, where_ + "the face uses vertex " + as_written + " twice");
    used_.push_back(index);
}

}  // namespace rast::detail
