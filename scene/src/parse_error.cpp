#include "rast/parse_error.h"

#include <cstdio>

namespace rast {

namespace {
std::string where(const std::string& file, std::int64_t line) {
    return line > 0 ? file + ":" + std::to_string(line) : file;
}
}  // namespace

ParseError::ParseError(std::string file_, std::int64_t line_, std::string message_)
    : std::runtime_error(where(file_, line_) + ": " + message_),
      file(std::move(file_)),
      line(line_),
      message(std::move(message_)) {}

std::string quote_token(std::string_view token) {
    constexpr std::size_t kMaxShown = 40;
    std::string out = "'";
    for (std::size_t k = 0; k < token.size() && k < kMaxShown; ++k) {
        const auto c = static_cast<unsigned char>(token[k]);
        if (c >= 0x20 && c < 0x7f) {
            out += static_cast<char>(c);
        } else {
            char hex[5];
            std::snprintf(hex, sizeof hex, "\\x%02x", c);
            out += hex;
        }
    }
    if (token.size() > kMaxShown) out += "...";
    return out + "'";
}

}  // namespace rast
