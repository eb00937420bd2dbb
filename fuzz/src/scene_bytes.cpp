#include "scene_bytes.h"

#include <array>
#include <bit>
#include <cfloat>
#include <cmath>
#include <stdexcept>
#include <string>

namespace rast::fuzz {

namespace {

// The coordinates where rasterizers break: signed zeros, the subnormal and normal limits, a tie just off a
// pixel centre, the fixed-point ranges of fixed16 / fixed8 / fixed4 (2^13, 2^21, 2^25), 2^60, DBL_MAX.
constexpr std::array<double, kSpecialCount> kSpecials = {
    0.0,     -0.0,     0x0.0000000000001p-1022, -0x0.0000000000001p-1022,
    DBL_MIN, -DBL_MIN, 0.5,                     0x1.0000000000001p-1,
    0x1p13,  0x1p21,   -0x1p21,                 0x1p25,
    0x1p60,  -0x1p60,  DBL_MAX,                 -DBL_MAX};

constexpr int kSampleCounts[] = {1, 4, 8, 16};

class ByteReader {
public:
    explicit ByteReader(std::span<const std::uint8_t> bytes) : bytes_(bytes) {}
    bool empty() const { return next_ >= bytes_.size(); }
    std::uint8_t byte() { return empty() ? 0 : bytes_[next_++]; }

private:
    std::span<const std::uint8_t> bytes_;
    std::size_t next_ = 0;
};

double decode_coordinate(ByteReader& in) {
    const std::uint8_t tag = in.byte();
    if (tag < kSpecialCount) return kSpecials[tag];
    if (tag < kGridTagEnd) return std::ldexp(static_cast<std::int8_t>(in.byte()), -(tag % 5));
    std::uint64_t bits = 0;
    for (int k = 0; k < 8; ++k) bits |= std::uint64_t{in.byte()} << (8 * k);
    return std::bit_cast<double>(bits);
}

void encode_coordinate(double value, std::vector<std::uint8_t>& out) {
    const auto bits = std::bit_cast<std::uint64_t>(value);
    for (std::uint8_t tag = 0; tag < kSpecialCount; ++tag)
        if (std::bit_cast<std::uint64_t>(kSpecials[tag]) == bits) {
            out.push_back(tag);
            return;
        }
    for (int shift = 0; shift < 5; ++shift) {
        const double k = std::ldexp(value, shift);
        if (k == std::trunc(k) && k >= -128 && k <= 127) {
            // The first grid tag t with t % 5 == shift.
            out.push_back(static_cast<std::uint8_t>(kSpecialCount + (shift + 5 - kSpecialCount % 5) % 5));
            out.push_back(static_cast<std::uint8_t>(static_cast<std::int8_t>(k)));
            return;
        }
    }
    out.push_back(kRawTag);
    for (int k = 0; k < 8; ++k) out.push_back(static_cast<std::uint8_t>(bits >> (8 * k)));
}

int decode_side(std::uint8_t b) { return b < kWideSideByte ? 1 + b % kSmallSide : kWideSide + (b - kWideSideByte); }

std::uint8_t side_byte(int side, const char* which) {
    if (side >= 1 && side <= kSmallSide) return static_cast<std::uint8_t>(side - 1);
    if (side >= kWideSide && side < kWideSide + (256 - kWideSideByte))
        return static_cast<std::uint8_t>(kWideSideByte + (side - kWideSide));
    throw std::invalid_argument(std::string("encode_scene: viewport ") + which + " " + std::to_string(side) +
                                " is neither 1.." + std::to_string(kSmallSide) + " nor " + std::to_string(kWideSide) +
                                ".." + std::to_string(kWideSide + 255 - kWideSideByte));
}

}  // namespace

Scene decode_scene(std::span<const std::uint8_t> bytes) {
    ByteReader in(bytes);
    Scene scene;
    scene.viewport.width = decode_side(in.byte());
    scene.viewport.height = decode_side(in.byte());
    scene.samples = kSampleCounts[in.byte() & 3];
    while (!in.empty() && scene.triangles.size() < kMaxTriangles) {
        Triangle t;
        for (Vertex& v : t.v) {
            v.x = decode_coordinate(in);
            v.y = decode_coordinate(in);
            v.z = decode_coordinate(in);
        }
        scene.triangles.push_back(t);
    }
    return scene;
}

std::vector<std::uint8_t> encode_scene(const Scene& scene) {
    if (scene.triangles.size() > kMaxTriangles)
        throw std::invalid_argument("encode_scene: " + std::to_string(scene.triangles.size()) +
                                    " triangles, at most " + std::to_string(kMaxTriangles));
    std::vector<std::uint8_t> out = {side_byte(scene.viewport.width, "width"),
                                     side_byte(scene.viewport.height, "height")};
    switch (scene.samples) {
        case 1: out.push_back(0); break;
        case 4: out.push_back(1); break;
        case 8: out.push_back(2); break;
        case 16: out.push_back(3); break;
        default: throw std::invalid_argument("encode_scene: unsupported sample count " + std::to_string(scene.samples));
    }
    for (const Triangle& t : scene.triangles)
        for (const Vertex& v : t.v) {
            encode_coordinate(v.x, out);
            encode_coordinate(v.y, out);
            encode_coordinate(v.z, out);
        }
    return out;
}

}  // namespace rast::fuzz
