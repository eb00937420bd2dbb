#include "number_token.h"

#include <cerrno>
#include <charconv>
#include <clocale>
#include <cmath>
#include <cstdlib>
#include <locale.h>

#include "rast/parse_error.h"

namespace rast::detail {

namespace {
bool is_space(char c) { return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f'; }

// strtod honours LC_NUMERIC (a German locale would want "0,5"); the file format does not.
locale_t c_locale() {
    static const locale_t locale = newlocale(LC_ALL_MASK, "C", locale_t{});
    return locale;
}
}  // namespace

void split_tokens(std::string_view line, std::vector<std::string_view>& tokens) {
    tokens.clear();
    std::size_t k = 0;
    while (k < line.size()) {
        while (k < line.size() && is_space(line[k])) ++k;
        const std::size_t begin = k;
        while (k < line.size() && !is_space(line[k])) ++k;
        if (k > begin) tokens.push_back(line.substr(begin, k - begin));
    }
}

std::vector<std::string> split_tokens(std::string_view line) {
    std::vector<std::string_view> views;
    split_tokens(line, views);
    return {views.begin(), views.end()};
}

double parse_finite_double(std::string_view token, const std::string& file, std::int64_t line) {
    // The fast road: from_chars rounds correctly, as glibc's strtod does, so where it reads the whole token
    // as a finite number the two agree. It takes no '+' and no "0x", and calls a number out of range where
    // strtod rounds it (to zero, or to infinity); those, and every error, take strtod's road.
    double fast = 0;
    const char* last = token.data() + token.size();
    if (const auto [end, error] = std::from_chars(token.data(), last, fast);
        error == std::errc{} && end == last && std::isfinite(fast))
        return fast;

    // Tokens hold no whitespace, so strtod's skipping of leading blanks never applies; c_str() stops at
    // an embedded NUL, which the length check below then reports as trailing characters.
    const std::string text(token);
    const char* begin = text.c_str();
    char* end = nullptr;
    errno = 0;
    const double value = strtod_l(begin, &end, c_locale());
    const bool overflow = errno == ERANGE && std::isinf(value);
    if (end == begin)
        throw ParseError(file, line, "expected a number, got " + quote_token(text));
    if (static_cast<std::size_t>(end - begin) != text.size())
        throw ParseError(file, line, "bad number " + quote_token(text) + ": trailing characters " +
                                         quote_token(text.substr(static_cast<std::size_t>(end - begin))));
    if (std::isnan(value)) throw ParseError(file, line, "NaN is not allowed: " + quote_token(text));
    if (overflow) throw ParseError(file, line, "number " + quote_token(text) + " overflows to infinity");
    if (std::isinf(value)) throw ParseError(file, line, "infinity is not allowed: " + quote_token(text));
    return value;
}

float read_float(const std::string& token) { return strtof_l(token.c_str(), nullptr, c_locale()); }

long long parse_integer(std::string_view token, const std::string& file, std::int64_t line) {
    long long value = 0;
    const char* last = token.data() + token.size();
    const auto [end, error] = std::from_chars(token.data(), last, value);
    if (error == std::errc::result_out_of_range)
        throw ParseError(file, line, "integer " + quote_token(token) + " is out of range");
    if (error != std::errc{} || end != last)
        throw ParseError(file, line, "expected an integer, got " + quote_token(token));
    return value;
}

}  // namespace rast::detail
