#include "png_image.h"

#include <png.h>
#include <rast/scene_limits.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <filesystem>
#include <span>
#include <stdexcept>
#include <string>

namespace rast::cli {

std::array<std::uint8_t, 3> id_colour(std::int32_t id, bool line) {
    if (id < 0) return {16, 16, 24};
    // Golden-ratio hue steps keep neighbouring ids apart; fixed saturation and value keep them readable.
    // A line's colour is a pale tint, to stand out on triangles and on the background alike.
    const double hue = std::fmod(0.13 + 0.6180339887498949 * id, 1.0) * 6.0;
    const double s = line ? 0.3 : 0.65, v = line ? 1.0 : 0.95;
    const int sector = static_cast<int>(hue);
    const double f = hue - sector;
    const double p = v * (1 - s), q = v * (1 - s * f), t = v * (1 - s * (1 - f));
    std::array<double, 3> c;
    switch (sector % 6) {
        case 0: c = {v, t, p}; break;
        case 1: c = {q, v, p}; break;
        case 2: c = {p, v, t}; break;
        case 3: c = {p, q, v}; break;
        case 4: c = {t, p, v}; break;
        default: c = {v, p, q}; break;
    }
    return {static_cast<std::uint8_t>(c[0] * 255 + 0.5), static_cast<std::uint8_t>(c[1] * 255 + 0.5),
            static_cast<std::uint8_t>(c[2] * 255 + 0.5)};
}

Image resolve_ids(const Framebuffer& fb, std::span<const Line> lines) {
    const int w = fb.viewport.width, h = fb.viewport.height;
    Image image(w, h);
    std::vector<bool> is_line;
    for (const Line& line : lines) {
        if (line.id < 0) continue;
        if (is_line.size() <= static_cast<std::size_t>(line.id)) is_line.resize(static_cast<std::size_t>(line.id) + 1);
        is_line[static_cast<std::size_t>(line.id)] = true;
    }
    const auto drawn_line = [&](std::int32_t id) { return id >= 0 && static_cast<std::size_t>(id) < is_line.size() && is_line[static_cast<std::size_t>(id)]; };
    for (int j = 0; j < h; ++j) {
        for (int i = 0; i < w; ++i) {
            std::array<int, 3> sum{};
            for (int s = 0; s < fb.samples; ++s) {
                const std::int32_t id = fb.id(i, j, s);
                const auto c = id_colour(id, drawn_line(id));
                for (int k = 0; k < 3; ++k) sum[k] += c[k];
            }
            std::uint8_t* out = image.at(i, h - 1 - j);
            for (int k = 0; k < 3; ++k)
                out[k] = static_cast<std::uint8_t>((sum[k] + fb.samples / 2) / fb.samples);
        }
    }
    return image;
}

Image visible_image(const reference::VisibleArea& visible) {
    const Viewport vp = visible.viewport();
    Image image(vp.width, vp.height);
    const auto background = id_colour(Framebuffer::kNoTriangle);
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) {
            std::array<double, 3> sum{};
            double seen = 0;
            for (const auto& p : visible.at(i, j)) {
                const double a = p.area.convert_to<double>();
                const auto c = id_colour(static_cast<std::int32_t>(p.id));
                for (int k = 0; k < 3; ++k) sum[k] += a * c[k];
                seen += a;
            }
            std::uint8_t* out = image.at(i, vp.height - 1 - j);
            for (int k = 0; k < 3; ++k)
                out[k] = static_cast<std::uint8_t>(std::clamp(sum[k] + (1 - seen) * background[k] + 0.5, 0.0, 255.0));
        }
    return image;
}

Image resolve_error_image(const reference::VisibleArea& visible, const Framebuffer& fb) {
    const Viewport vp = fb.viewport;
    Image image(vp.width, vp.height);
    for (int j = 0; j < vp.height; ++j)
        for (int i = 0; i < vp.width; ++i) {
            const auto ids = std::span(fb.ids).subspan(fb.index(i, j, 0), static_cast<std::size_t>(fb.samples));
            const double error = reference::resolve_error(visible.at(i, j), ids).convert_to<double>();
            std::uint8_t* out = image.at(i, vp.height - 1 - j);
            std::fill(out, out + 3, static_cast<std::uint8_t>(std::sqrt(error) * 255 + 0.5));
        }
    return image;
}

// The panels left to right, each magnified by `scale`, with a separator of `scale` pixels between.
Image side_by_side(const std::vector<Image>& panels, int scale) {
    const int w = panels.front().width, h = panels.front().height;
    const int n = static_cast<int>(panels.size());
    Image out(n * w * scale + (n - 1) * scale, h * scale);
    for (int y = 0; y < out.height; ++y)
        for (int x = 0; x < out.width; ++x) {
            const int panel = x / ((w + 1) * scale), inside = x % ((w + 1) * scale);
            std::uint8_t* px = out.at(x, y);
            if (inside >= w * scale) {
                std::fill(px, px + 3, std::uint8_t{128});
                continue;
            }
            const auto& from = panels[panel];
            const std::uint8_t* src = &from.rgb[(static_cast<std::size_t>(y / scale) * w + inside / scale) * 3];
            std::copy(src, src + 3, px);
        }
    return out;
}

void check_picture_size(std::int64_t width, std::int64_t height) {
    const std::string size = std::to_string(width) + "x" + std::to_string(height) + " pixels";
    if (width > PNG_USER_WIDTH_MAX || height > PNG_USER_HEIGHT_MAX)
        throw std::invalid_argument("the picture would be " + size + ", and PNG pictures are written at most " +
                                    std::to_string(PNG_USER_WIDTH_MAX) + "x" + std::to_string(PNG_USER_HEIGHT_MAX));
    if (width * height > kMaxSamplesPerImage)
        throw std::invalid_argument("the picture would be " + size + ", more than the " +
                                    std::to_string(kMaxSamplesPerImage) + " a picture may have");
}

std::string encode_png(const Image& image) {
    png_image png{};
    png.version = PNG_IMAGE_VERSION;
    png.width = static_cast<png_uint_32>(image.width);
    png.height = static_cast<png_uint_32>(image.height);
    png.format = PNG_FORMAT_RGB;
    const png_int_32 stride = image.width * 3;
    // The first call sizes the buffer, the second fills it.
    png_alloc_size_t size = 0;
    if (!png_image_write_to_memory(&png, nullptr, &size, 0, image.rgb.data(), stride, nullptr))
        throw std::runtime_error(std::string("cannot encode PNG: ") + png.message);
    std::string bytes(size, '\0');
    if (!png_image_write_to_memory(&png, bytes.data(), &size, 0, image.rgb.data(), stride, nullptr))
        throw std::runtime_error(std::string("cannot encode PNG: ") + png.message);
    bytes.resize(size);
    return bytes;
}

std::string png_name(const std::string& path) {
    std::string extension = std::filesystem::path(path).extension().string();
    std::transform(extension.begin(), extension.end(), extension.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    if (extension == ".png" || path.empty()) return {};  // an empty path is refused as such, later
    return "'" + path + "': rast writes PNG pictures only; name the file .png";
}

}  // namespace rast::cli
