// Test helpers: building small scenes and drawing id buffers as pictures.
#pragma once

#include <rast/reference.h>

#include <initializer_list>
#include <string>

namespace rast::reference::testing {

// A triangle at depth z = 0, from its screen-space vertices.
inline Triangle flat(double x0, double y0, double x1, double y1, double x2, double y2) {
    return Triangle{{Vertex{x0, y0, 0}, Vertex{x1, y1, 0}, Vertex{x2, y2, 0}}};
}

// The same point set traversed the other way.
inline Triangle reversed(Triangle t) {
    std::swap(t.v[1], t.v[2]);
    return t;
}

inline Scene scene(int width, int height, std::initializer_list<Triangle> triangles, int samples = 1) {
    return Scene{Viewport{width, height}, samples, triangles};
}

// The id buffer drawn as the image looks (top row first), sample 0 of each pixel, one character per
// pixel: '.' for no triangle, '0'..'9' for an id. Starts and ends with a newline, so an expected
// picture reads naturally as a raw string literal.
inline std::string picture(const Framebuffer& fb) {
    std::string out = "\n";
    for (int j = fb.viewport.height - 1; j >= 0; --j) {
        for (int i = 0; i < fb.viewport.width; ++i) {
            const auto id = fb.id(i, j);
            out += id == Framebuffer::kNoTriangle ? '.' : id < 10 ? static_cast<char>('0' + id) : '#';
        }
        out += '\n';
    }
    return out;
}

}  // namespace rast::reference::testing
