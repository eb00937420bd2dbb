// rast — the scene's lines in the fast path's z-buffer (line_pass.h).
//
// A line is drawn after every triangle, into the framebuffer they left: the (z, id) order is total, so
// the result does not depend on when a fragment arrives. The framebuffer keeps depths but not their
// bounds, so a stored fragment's depth is evaluated again as the engine evaluated it, with its bound: a
// triangle's plane (make_plane, setup.h) at the sample, or another line's depth at the pixel.
#include "line_pass.h"

#include "line_depth.h"
#include "validate.h"

#include <rast/fast.h>

#include <cmath>
#include <limits>
#include <string>
#include <unordered_map>

namespace rast::fast::detail {

namespace {

// A depth in double and its bound, with what exact arithmetic needs to settle it.
struct Fragment {
    Bounded z;
    DepthAt exact;
};

bool bounded(const Bounded& z) { return std::isfinite(z.v) && z.e < std::numeric_limits<double>::infinity(); }

class LineZBuffer {
public:
    LineZBuffer(const Scene& scene, const Context& c, const std::vector<std::int32_t>& ids, Framebuffer& fb)
        : scene_(scene), c_(c), fb_(fb), named_(primitives_by_id(scene, ids)) {
        for (const Line& line : scene.lines) lines_.push_back(snapped(line.segment, c_.precision));
    }

    void draw(std::size_t k) {
        const Segment& segment = lines_[k];
        const std::int32_t id = scene_.lines[k].id;
        const auto width = static_cast<std::size_t>(c_.vp.width);
        const std::vector<std::size_t> lit = is_fixed(c_.precision) ? bresenham(scene_.lines[k].segment, c_.vp, c_.bits)
                                                                    : dda(segment, c_.vp, c_.precision);
        for (const std::size_t pixel : lit) {
            const int i = static_cast<int>(pixel % width), j = static_cast<int>(pixel / width);
            const double cx = i + 0.5, cy = j + 0.5;
            const Fragment line{line_depth(segment, cx, cy), DepthAt{nullptr, &segment, cx, cy}};
            // The depth stored, once for the pixel's samples (exactly rounded where the bound says nothing).
            const double written = bounded(line.z) ? line.z.v : nearest(line.exact);
            for (int s = 0; s < fb_.samples; ++s) {
                const std::size_t at = fb_.index(i, j, s);
                const std::int32_t stored = fb_.ids[at];
                if (stored != Framebuffer::kNoTriangle && !in_front(line, id, stored, i, j, s)) continue;
                fb_.ids[at] = id;
                fb_.depth[at] = written;
            }
        }
    }

private:
    // Whether the line's fragment comes before the stored one in the (z, id) order.
    bool in_front(const Fragment& line, std::int32_t id, std::int32_t stored, int i, int j, int s) {
        const Fragment other = stored_fragment(stored, i, j, s);
        if (bounded(line.z) && bounded(other.z)) {
            // As the depth kernels compare (kernels.h): a rounded gap against the rounded sum of the bounds.
            const double gap = line.z.v - other.z.v, margin = line.z.e + other.z.e;
            if (gap > margin) return false;
            if (-gap > margin) return true;
        }
        const int order = compare(line.exact, other.exact);
        return order < 0 || (order == 0 && id < stored);
    }

    Fragment stored_fragment(std::int32_t stored, int i, int j, int s) {
        const Primitive named = named_[static_cast<std::size_t>(stored)];
        if (named.line) {
            const Segment& other = lines_[named.index];
            const double cx = i + 0.5, cy = j + 0.5;
            return {line_depth(other, cx, cy), DepthAt{nullptr, &other, cx, cy}};
        }
        const Placed& t = placed(named.index);
        const Plane& p = planes_.at(named.index);
        const double px = i + c_.offsets[s].x, py = j + c_.offsets[s].y;
        // The engine's evaluation (engine.h, resolve), with the plane's bound over its bounding box.
        const Bounded z{p.z0 + (p.a * (px - p.x0) + p.b * (py - p.y0)), p.err};
        return {z, DepthAt{&t.v, nullptr, px, py}};
    }

    // Triangle k as the engine placed it (snapped, counter-clockwise) and its plane, made once. A stored
    // triangle covered a sample, so it was placed (value() throws rather than read nothing if not).
    const Placed& placed(std::size_t k) {
        auto found = placed_.find(k);
        if (found == placed_.end()) {
            found = placed_.emplace(k, place<Fault::none>(scene_.triangles[k], c_).value()).first;
            planes_.emplace(k, make_plane(found->second, c_));
        }
        return found->second;
    }

    const Scene& scene_;
    const Context& c_;
    Framebuffer& fb_;
    std::vector<Primitive> named_;
    std::vector<Segment> lines_;  // as the mode sees them: snapped in the fixed modes
    std::unordered_map<std::size_t, Placed> placed_;
    std::unordered_map<std::size_t, Plane> planes_;
};

}  // namespace

std::vector<std::int32_t> checked_lines(const Scene& scene) {
    std::vector<std::int32_t> ids;
    try {
        ids = triangle_ids(scene);
    } catch (const std::invalid_argument& e) {
        throw std::invalid_argument(std::string("rast::fast: ") + e.what());
    }
    for (std::size_t k = 0; k < scene.lines.size(); ++k)
        for (int e = 0; e < 2; ++e)
            if (!is_finite(scene.lines[k].segment.v[e]))
                throw std::invalid_argument("rast::fast: line " + std::to_string(k) + ", end " + std::to_string(e) +
                                            ": coordinate is not a finite number");
    return ids;
}

void draw_lines(const Scene& scene, const Context& c, const std::vector<std::int32_t>& ids, Framebuffer& fb) {
    rename_triangles(fb, ids);
    LineZBuffer zbuffer(scene, c, ids, fb);
    for (std::size_t k = 0; k < scene.lines.size(); ++k) zbuffer.draw(k);
}

}  // namespace rast::fast::detail
