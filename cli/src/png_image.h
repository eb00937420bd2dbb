// rast — pictures of a framebuffer: one colour per triangle id, samples resolved by averaging.
#pragma once

#include <rast/scene.h>
#include <rast/visible_area.h>

#include <array>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace rast::cli {

// 8-bit RGB, top row first, as an image is written.
struct Image {
    int width = 0;
    int height = 0;
    std::vector<std::uint8_t> rgb;

    Image(int w, int h) : width(w), height(h), rgb(static_cast<std::size_t>(w) * h * 3, 0) {}
    std::uint8_t* at(int x, int row) { return &rgb[(static_cast<std::size_t>(row) * width + x) * 3]; }
};

// A stable, well-separated colour for an id, paler for a line's; the background (-1) is near-black.
std::array<std::uint8_t, 3> id_colour(std::int32_t id, bool line = false);

// The framebuffer as a picture: each pixel the average of its samples' id colours (`lines` says which ids
// are lines), rows flipped so the top row (j = H - 1) comes first.
Image resolve_ids(const Framebuffer& fb, std::span<const Line> lines = {});

// The ideal antialiased picture: each pixel the id colours weighted by the exact visible areas, the
// background's colour where nothing is seen.
Image visible_image(const reference::VisibleArea& visible);

// How far each resolved pixel of `fb` is from the visible ideal (reference::resolve_error, in [0, 1]) as a
// grey on a square-root scale: 0 black, 1/16 a quarter, 1/4 half, 1 white.
Image resolve_error_image(const reference::VisibleArea& visible, const Framebuffer& fb);

// The most --magnify takes: a larger scale shows nothing more of a pixel.
inline constexpr int kMaxMagnify = 64;

// Equally sized panels left to right, each magnified by `scale` (nearest neighbour, so single pixels stay
// sharp), with a grey separator `scale` pixels wide between them. One panel: just the magnification.
Image side_by_side(const std::vector<Image>& panels, int scale);

// Throws std::invalid_argument saying why unless a picture of width x height pixels can be made and written:
// libpng writes at most PNG_USER_WIDTH_MAX x PNG_USER_HEIGHT_MAX (10^6 each way), and a picture of more pixels
// than the largest scene has samples (kMaxSamplesPerImage) would not fit in memory.
void check_picture_size(std::int64_t width, std::int64_t height);

// The image encoded as PNG: the bytes of the file.
std::string encode_png(const Image& image);

// A CLI11 check for a picture's path: rast writes PNG only, so a name that says otherwise (x.jpg) is
// refused rather than given PNG bytes under it. Any letter case of .png passes, and so does an empty path,
// which check_output_paths refuses as such.
std::string png_name(const std::string& path);

}  // namespace rast::cli
