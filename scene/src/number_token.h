// rast — reading numbers from text tokens, shared by the .tri reader and the mesh text checker.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace rast::detail {

// The whitespace-separated tokens of a line (space, tab, CR, VT, FF).
std::vector<std::string> split_tokens(std::string_view line);
// The same tokens as views into the line, into `tokens` (cleared first): reused from line to line, it
// allocates nothing once it has held the longest line's tokens.
void split_tokens(std::string_view line, std::vector<std::string_view>& tokens);

// The whole token read exactly as strtod reads it in the C locale (decimal or hex-float), whatever the
// process locale. Throws ParseError(file, line, ...) for anything but a finite number: no digits,
// trailing characters, NaN, infinity, or a value that overflows to infinity (1e999).
double parse_finite_double(std::string_view token, const std::string& file, std::int64_t line);

// The token, one that parse_finite_double accepts, as strtof reads it in the C locale: rounded once to the
// nearest float, so to infinity from FLT_MAX + half an ulp on (that tie goes to the even infinity). Read as
// a double and then narrowed, it is rounded twice: 3.4028235677973366e38 is FLT_MAX to strtof, but the
// double nearest to it is FLT_MAX + half an ulp exactly, which narrows to infinity.
float read_float(const std::string& token);

// The whole token as a decimal integer with an optional '-'; throws ParseError if it is not one or if
// it does not fit in a long long.
long long parse_integer(std::string_view token, const std::string& file, std::int64_t line);

}  // namespace rast::detail
