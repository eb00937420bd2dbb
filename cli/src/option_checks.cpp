#include "option_checks.h"

#include <charconv>
#include <system_error>

namespace rast::cli {

std::string nonempty_folder(const std::string& folder) { return folder.empty() ? "the path is empty" : ""; }

CLI::Validator decimal_number(const std::string& what, std::uint64_t most) {
    return CLI::Validator(
        [what, most](std::string& text) -> std::string {
            std::uint64_t value = 0;
            const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
            if (text.empty() || error != std::errc{} || end != text.data() + text.size() || value > most)
                return what + " is a whole number from 0 to " + std::to_string(most) + " in decimal digits, got " +
                       text;
            text = std::to_string(value);
            return "";
        },
        "");
}

}  // namespace rast::cli
