#include <bit>
#include <cmath>
#include <cstdint>

#include "checks.h"
#include "samples.h"

namespace rast::properties {

std::optional<std::string> first_difference(const std::vector<std::size_t>& a, const std::string& a_name,
                                            const std::vector<std::size_t>& b, const std::string& b_name,
                                            Viewport vp, int samples) {
    std::size_t ia = 0, ib = 0;
    while (ia < a.size() || ib < b.size()) {
        if (ia < a.size() && ib < b.size() && a[ia] == b[ib]) {
            ++ia, ++ib;
            continue;
        }
        const bool in_a = ib == b.size() || (ia < a.size() && a[ia] < b[ib]);
        const std::size_t index = in_a ? a[ia] : b[ib];
        return describe(sample_at(vp, samples, index)) + ": " + a_name + (in_a ? " covers" : " does not cover") +
               ", " + b_name + (in_a ? " does not" : " does");
    }
    return std::nullopt;
}

namespace {
// A plugin returns no depths (NaN): its fragment is its id.
std::string fragment(const Framebuffer& f, std::size_t k) {
    const std::string id = "id " + std::to_string(f.ids[k]);
    return std::isnan(f.depth[k]) ? id : id + " depth " + shortest(f.depth[k]);
}
}  // namespace

std::optional<std::string> first_difference(const Framebuffer& a, const std::string& a_name,
                                            const Framebuffer& b, const std::string& b_name, bool depths) {
    for (std::size_t k = 0; k < a.ids.size(); ++k) {
        const bool same = a.ids[k] == b.ids[k] &&
                          (!depths || std::bit_cast<std::uint64_t>(a.depth[k]) ==
                                          std::bit_cast<std::uint64_t>(b.depth[k]));
        if (!same)
            return describe(sample_at(a.viewport, a.samples, k)) + ": " + a_name + " has " + fragment(a, k) +
                   ", " + b_name + " has " + fragment(b, k);
    }
    return std::nullopt;
}

}  // namespace rast::properties
