// rast — what a rasterizer promises, in the words of the plugin ABI's contract string (docs/design.md):
// the sample counts it renders, how it snaps vertices, whether it keeps the tie rule and the (z, id)
// order. Every engine has one: the reference's and the fixed modes' are exact promises, a plugin's is
// what it declares, and the conformance verdict holds an engine to its own.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace rast {

struct Contract {
    enum class Rounding { nearest_even, floor, any };

    std::string name;
    std::vector<int> samples{1, 4, 8, 16};  // ascending, from 1, 4, 8, 16
    std::optional<int> snap;                // bits, 0..24; none: coverage decided on the input coordinates
    Rounding rounding = Rounding::nearest_even;  // meaningful with snap only
    bool top_left = true;                   // ties=top-left; false: ties=none
    bool zid = true;                        // depth=zid; false: depth=none

    bool renders(int sample_count) const;
    // One snapping only (none, nearest-even or floor): every sample's verdict is required or forbidden
    // where ties=top-left.
    bool deterministic() const { return !snap || rounding != Rounding::any; }

    // The contract string, keys in the order of docs/design.md (rounding only with a snap); parse reads it back.
    std::string text() const;
    // Reads a contract string. Throws std::invalid_argument naming the key and what is wrong with it: an
    // unknown or repeated key, a missing one that applies, a bad value, rounding without a snap.
    static Contract parse(const std::string& text);
};

bool operator==(const Contract& a, const Contract& b);

const char* name(Contract::Rounding rounding);

}  // namespace rast
