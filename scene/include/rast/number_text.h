// rast — a double as rast writes it for people and in files: the shortest decimal that reads back (strtod)
// as the same double; "inf" and "-inf" for the infinities.
#pragma once

#include <charconv>
#include <string>

namespace rast {

inline std::string shortest(double value) {
    char text[32];
    return {text, std::to_chars(text, text + sizeof text, value).ptr};
}

}  // namespace rast
