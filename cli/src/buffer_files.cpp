#include "buffer_files.h"

#include <charconv>
#include <cmath>

namespace rast::cli {
namespace {

template <class Cell>
std::string format_grid(const Framebuffer& fb, Cell cell) {
    std::string out;
    char buffer[32];
    for (int j = fb.viewport.height - 1; j >= 0; --j) {
        for (int i = 0; i < fb.viewport.width; ++i)
            for (int s = 0; s < fb.samples; ++s) {
                if (i > 0 || s > 0) out += ' ';
                out.append(buffer, cell(fb.index(i, j, s), buffer));
            }
        out += '\n';
    }
    return out;
}

}  // namespace

std::string format_ids(const Framebuffer& fb) {
    return format_grid(fb, [&](std::size_t k, char* buf) {
        return static_cast<std::size_t>(std::to_chars(buf, buf + 32, fb.ids[k]).ptr - buf);
    });
}

std::string format_depth(const Framebuffer& fb) {
    return format_grid(fb, [&](std::size_t k, char* buf) {
        // Shortest round-trip decimal; std::to_chars writes "inf" for an empty pixel.
        return static_cast<std::size_t>(std::to_chars(buf, buf + 32, fb.depth[k]).ptr - buf);
    });
}

std::string format_area(Viewport vp, const std::vector<reference::Rational>& area) {
    std::string out;
    for (int j = vp.height - 1; j >= 0; --j) {
        for (int i = 0; i < vp.width; ++i) {
            if (i > 0) out += ' ';
            out += area[std::size_t(j) * vp.width + i].str();
        }
        out += '\n';
    }
    return out;
}

std::string format_visible(const reference::VisibleArea& visible) {
    const Viewport vp = visible.viewport();
    std::string out;
    for (int j = vp.height - 1; j >= 0; --j) {
        for (int i = 0; i < vp.width; ++i) {
            if (i > 0) out += ' ';
            const auto pieces = visible.at(i, j);
            if (pieces.empty()) out += '-';
            for (std::size_t k = 0; k < pieces.size(); ++k) {
                if (k > 0) out += ',';
                out += std::to_string(pieces[k].id) + ':' + pieces[k].area.str();
            }
        }
        out += '\n';
    }
    return out;
}

}  // namespace rast::cli
