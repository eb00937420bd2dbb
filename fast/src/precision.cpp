// Precision names for the command line, and the snapped triangle a fixed mode rasterizes.
#include "snap.h"
#include "validate.h"

#include <rast/fast.h>

#include <array>

namespace rast::fast {
namespace {
constexpr std::array<std::pair<Precision, std::string_view>, 5> kNames = {{
    {Precision::fixed4, "fixed4"},
    {Precision::fixed8, "fixed8"},
    {Precision::fixed16, "fixed16"},
    {Precision::float32, "float32"},
    {Precision::float64, "float64"},
}};
}  // namespace

std::string_view name(Precision p) {
    for (const auto& [precision, text] : kNames)
        if (precision == p) return text;
    return "unknown";
}

std::optional<Precision> parse_precision(std::string_view s) {
    for (const auto& [precision, text] : kNames)
        if (text == s) return precision;
    return std::nullopt;
}

Triangle snap(const Triangle& t, Precision precision) {
    detail::validate(precision);
    detail::validate(t, 0);
    return detail::snapped(t, precision);
}

}  // namespace rast::fast
