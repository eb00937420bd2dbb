// rast — how the command line words what it counts.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace rast::cli {

// "n things", or "1 thing".
inline std::string counted(std::size_t n, std::string_view one, std::string_view many) {
    return std::to_string(n) + " " + std::string(n == 1 ? one : many);
}

}  // namespace rast::cli
