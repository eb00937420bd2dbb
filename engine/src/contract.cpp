#include <rast/contract.h>

#include <algorithm>
#include <charconv>
#include <map>
#include <stdexcept>
#include <string_view>

namespace rast {

namespace {

constexpr std::size_t kMaxName = 64;

bool is_name_char(char c) {
    return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' || c == '-' ||
           c == '.' || c == '+';
}

[[noreturn]] void bad(const std::string& key, const std::string& what) {
    throw std::invalid_argument("contract key '" + key + "': " + what);
}

int small_integer(const std::string& key, std::string_view text, int low, int high) {
    int value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc{} || end != text.data() + text.size() || value < low || value > high)
        bad(key, "'" + std::string(text) + "' is not an integer in " + std::to_string(low) + ".." + std::to_string(high));
    return value;
}

std::vector<int> sample_list(std::string_view text) {
    std::vector<int> counts;
    std::size_t begin = 0;
    while (true) {
        const std::size_t comma = std::min(text.find(',', begin), text.size());
        const std::string_view item = text.substr(begin, comma - begin);
        const int n = small_integer("samples", item, 1, 16);
        if (n != 1 && n != 4 && n != 8 && n != 16) bad("samples", "'" + std::string(item) + "' is not 1, 4, 8 or 16");
        if (std::find(counts.begin(), counts.end(), n) != counts.end()) bad("samples", std::to_string(n) + " twice");
        counts.push_back(n);
        if (comma == text.size()) break;
        begin = comma + 1;
    }
    std::sort(counts.begin(), counts.end());
    return counts;
}

}  // namespace

const char* name(Contract::Rounding rounding) {
    switch (rounding) {
        case Contract::Rounding::nearest_even: return "nearest-even";
        case Contract::Rounding::floor: return "floor";
        case Contract::Rounding::any: return "any";
    }
    return "?";
}

bool Contract::renders(int sample_count) const {
    return std::find(samples.begin(), samples.end(), sample_count) != samples.end();
}

std::string Contract::text() const {
    std::string list;
    for (int n : samples) list += (list.empty() ? "" : ",") + std::to_string(n);
    std::string out = "name=" + name + " samples=" + list + " snap=" + (snap ? std::to_string(*snap) : "none");
    if (snap) out += std::string(" rounding=") + rast::name(rounding);
    out += std::string(" ties=") + (top_left ? "top-left" : "none") + " depth=" + (zid ? "zid" : "none");
    return out;
}

Contract Contract::parse(const std::string& text) {
    std::map<std::string, std::string> words;
    std::size_t k = 0;
    while (k < text.size()) {
        if (text[k] == ' ') {
            ++k;
            continue;
        }
        const std::size_t end = std::min(text.find(' ', k), text.size());
        const std::string word = text.substr(k, end - k);
        k = end;
        const std::size_t equals = word.find('=');
        if (equals == std::string::npos) throw std::invalid_argument("contract word '" + word + "' is not key=value");
        const std::string key = word.substr(0, equals);
        if (key != "name" && key != "samples" && key != "snap" && key != "rounding" && key != "ties" && key != "depth")
            bad(key, "unknown (known: name, samples, snap, rounding, ties, depth)");
        if (!words.emplace(key, word.substr(equals + 1)).second) bad(key, "given twice");
    }
    const auto take = [&words](const std::string& key) -> std::optional<std::string> {
        const auto found = words.find(key);
        if (found == words.end()) return std::nullopt;
        std::string value = found->second;
        words.erase(found);
        return value;
    };
    const auto need = [&take](const std::string& key) {
        auto value = take(key);
        if (!value) bad(key, "missing");
        return *value;
    };

    Contract c;
    c.name = need("name");
    if (c.name.empty() || c.name.size() > kMaxName || !std::all_of(c.name.begin(), c.name.end(), is_name_char))
        bad("name", "'" + c.name + "' is not a word of at most 64 letters, digits, '_', '-', '.' or '+'");
    c.samples = sample_list(need("samples"));
    const std::string snap = need("snap");
    if (snap != "none") c.snap = small_integer("snap", snap, 0, 24);
    if (const auto rounding = take("rounding")) {
        if (!c.snap) bad("rounding", "applies only with snap=N");
        if (*rounding == "nearest-even") c.rounding = Rounding::nearest_even;
        else if (*rounding == "floor") c.rounding = Rounding::floor;
        else if (*rounding == "any") c.rounding = Rounding::any;
        else bad("rounding", "'" + *rounding + "' is not nearest-even, floor or any");
    } else if (c.snap) {
        bad("rounding", "missing (snap=" + snap + " needs it)");
    }
    const std::string ties = need("ties");
    if (ties != "top-left" && ties != "none") bad("ties", "'" + ties + "' is not top-left or none");
    c.top_left = ties == "top-left";
    const std::string depth = need("depth");
    if (depth != "zid" && depth != "none") bad("depth", "'" + depth + "' is not zid or none");
    c.zid = depth == "zid";
    return c;
}

bool operator==(const Contract& a, const Contract& b) {
    return a.name == b.name && a.samples == b.samples && a.snap == b.snap &&
           (!a.snap || a.rounding == b.rounding) && a.top_left == b.top_left && a.zid == b.zid;
}

}  // namespace rast
