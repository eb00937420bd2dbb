// A word as a POSIX shell reads it back, for the commands rast writes into reports and corpus cases so that
// they can be typed again: as it is when every character is one no shell treats specially, otherwise in
// single quotes, a quote inside written '\''. (A path with a space or a quote, or a note with an
// apostrophe, broke the command it was written into.)
#pragma once

#include <string>
#include <string_view>

namespace rast {

inline std::string shell_word(std::string_view word) {
    const auto plain = [](char c) {
        return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
               std::string_view("_./:=@%+,-").find(c) != std::string_view::npos;
    };
    bool all_plain = !word.empty();
    for (const char c : word) all_plain = all_plain && plain(c);
    if (all_plain) return std::string(word);
    std::string quoted = "'";
    for (const char c : word) quoted += c == '\'' ? std::string("'\\''") : std::string(1, c);
    quoted += '\'';
    return quoted;
}

}  // namespace rast
