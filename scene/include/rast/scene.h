// rast — the scene model: only what rasterization needs.
//
// Screen space (docs/design.md): x right, y up, the viewport covers [0, W] x [0, H]; pixel (i, j)
// covers [i, i+1] x [j, j+1]. z is depth: smaller is nearer. Ids count triangles and lines together,
// 0-based, in file order; in a scene without lines a triangle's id is its index in Scene::triangles.
// Header-only, so that the installed fast library carries no other dependency.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <new>
#include <span>
#include <stdexcept>
#include <string>
#include <vector>

namespace rast {

struct Vertex {
    double x = 0, y = 0, z = 0;
    friend bool operator==(const Vertex&, const Vertex&) = default;
};

struct Triangle {
    std::array<Vertex, 3> v;
    friend bool operator==(const Triangle&, const Triangle&) = default;
};

// A zero-width line segment from v[0] to v[1] (the `.tri` format's `line`); its direction matters only at
// its ends (docs/design.md).
struct Segment {
    std::array<Vertex, 2> v;
    friend bool operator==(const Segment&, const Segment&) = default;
};

struct Viewport {
    int width = 0;
    int height = 0;
    friend bool operator==(const Viewport&, const Viewport&) = default;
};

// A sample position inside the unit pixel square, y up: pixel (i, j) samples at (i + x, j + y).
struct SamplePoint {
    double x, y;
};

namespace detail {
// The Vulkan standard sample locations, given there with y down, mirrored here into y up (y -> 1 - y).
// Every coordinate is a multiple of 1/16, so i + x and j + y are exact doubles for any pixel index.
inline constexpr SamplePoint kSamples1[] = {{0.5, 0.5}};
inline constexpr SamplePoint kSamples4[] = {
    {0.375, 1 - 0.125}, {0.875, 1 - 0.375}, {0.125, 1 - 0.625}, {0.625, 1 - 0.875}};
inline constexpr SamplePoint kSamples8[] = {
    {0.5625, 1 - 0.3125}, {0.4375, 1 - 0.6875}, {0.8125, 1 - 0.5625}, {0.3125, 1 - 0.1875},
    {0.1875, 1 - 0.8125}, {0.0625, 1 - 0.4375}, {0.6875, 1 - 0.9375}, {0.9375, 1 - 0.0625}};
inline constexpr SamplePoint kSamples16[] = {
    {0.5625, 1 - 0.5625}, {0.4375, 1 - 0.3125}, {0.3125, 1 - 0.625},  {0.75, 1 - 0.4375},
    {0.1875, 1 - 0.375},  {0.625, 1 - 0.8125},  {0.8125, 1 - 0.6875}, {0.6875, 1 - 0.1875},
    {0.375, 1 - 0.875},   {0.5, 1 - 0.0625},    {0.25, 1 - 0.125},    {0.125, 1 - 0.75},
    {0.0, 1 - 0.5},       {0.9375, 1 - 0.25},   {0.875, 1 - 0.9375},  {0.0625, 1 - 0.0}};
}  // namespace detail

constexpr bool is_supported_sample_count(int n) { return n == 1 || n == 4 || n == 8 || n == 16; }

// The sample positions for 1, 4, 8 or 16 samples per pixel; throws std::invalid_argument otherwise.
inline std::span<const SamplePoint> sample_pattern(int count) {
    switch (count) {
        case 1: return detail::kSamples1;
        case 4: return detail::kSamples4;
        case 8: return detail::kSamples8;
        case 16: return detail::kSamples16;
        default:
            throw std::invalid_argument("unsupported sample count " + std::to_string(count) +
                                        " (expected 1, 4, 8 or 16)");
    }
}

// A line of a scene: its segment and its id among the scene's triangles and lines.
struct Line {
    Segment segment;
    std::int32_t id = 0;
    friend bool operator==(const Line&, const Line&) = default;
};

struct Scene {
    Viewport viewport;
    int samples = 1;
    std::vector<Triangle> triangles;
    std::vector<Line> lines{};  // ids ascending; the triangles take the ids the lines leave, in order
};

// The scene's ids: triangles and lines.
inline std::size_t id_count(const Scene& scene) { return scene.triangles.size() + scene.lines.size(); }

// Appends a line after everything the scene holds so far: its id is the next one.
inline void append_line(Scene& scene, const Segment& segment) {
    scene.lines.push_back({segment, static_cast<std::int32_t>(id_count(scene))});
}

// The id of each triangle, in the order of Scene::triangles: the ids the lines leave, ascending. Throws
// std::invalid_argument when the scene has more than 2^31 - 1 ids or its lines' ids are not ascending
// within [0, id_count).
inline std::vector<std::int32_t> triangle_ids(const Scene& scene) {
    const std::size_t count = id_count(scene);
    if (count > static_cast<std::size_t>(std::numeric_limits<std::int32_t>::max()))
        throw std::invalid_argument("the scene has " + std::to_string(count) + " triangles and lines, more than 2^31 - 1");
    std::vector<std::int32_t> ids;
    ids.reserve(scene.triangles.size());
    std::int64_t next = 0;
    for (std::size_t k = 0; k < scene.lines.size(); ++k) {
        const std::int64_t line_id = scene.lines[k].id;
        if (line_id < next || line_id >= static_cast<std::int64_t>(count))
            throw std::invalid_argument("line " + std::to_string(k) + " has id " + std::to_string(line_id) +
                                        ": the lines' ids must ascend within 0.." + std::to_string(count - 1));
        while (next < line_id) ids.push_back(static_cast<std::int32_t>(next++));
        ++next;
    }
    while (next < static_cast<std::int64_t>(count)) ids.push_back(static_cast<std::int32_t>(next++));
    return ids;
}

// What an id names: triangle `index` of Scene::triangles, or line `index` of Scene::lines.
struct Primitive {
    bool line = false;
    std::size_t index = 0;
};

// What each id of the scene names, by id; `ids` is triangle_ids(scene).
inline std::vector<Primitive> primitives_by_id(const Scene& scene, const std::vector<std::int32_t>& ids) {
    std::vector<Primitive> named(id_count(scene));
    for (std::size_t k = 0; k < ids.size(); ++k) named[static_cast<std::size_t>(ids[k])] = {false, k};
    for (std::size_t k = 0; k < scene.lines.size(); ++k) named[static_cast<std::size_t>(scene.lines[k].id)] = {true, k};
    return named;
}

// Allocates on cache-line (64-byte) boundaries: at one sample per pixel the fast path writes the
// framebuffer's rows in whole lines, streamed past the cache, and a row that began mid-line had its ends
// stored the ordinary way, each such line first read from memory (at 1024 x 1024, a tenth of a render of
// 20 000 small triangles).
template <class T>
struct CacheLineAllocator {
    static_assert(alignof(T) <= 64, "a line holds whole elements");
    using value_type = T;
    static constexpr std::align_val_t kLine{64};
    CacheLineAllocator() = default;
    template <class U>
    CacheLineAllocator(const CacheLineAllocator<U>&) noexcept {}
    T* allocate(std::size_t n) { return static_cast<T*>(::operator new(n * sizeof(T), kLine)); }
    void deallocate(T* p, std::size_t) noexcept { ::operator delete(p, kLine); }
    template <class U>
    friend bool operator==(const CacheLineAllocator&, const CacheLineAllocator<U>&) noexcept {
        return true;
    }
};

// A framebuffer's per-sample storage.
template <class T>
using Samples = std::vector<T, CacheLineAllocator<T>>;

// The z-buffer's content after rendering: per sample, the id of the owning triangle or line (-1 for none) and
// its depth (+infinity for none). Rows are stored bottom row first (j = 0), matching y up; writers of
// images and id files flip to top row first.
struct Framebuffer {
    static constexpr std::int32_t kNoTriangle = -1;

    Viewport viewport;
    int samples = 1;
    Samples<std::int32_t> ids;
    Samples<double> depth;

    Framebuffer() = default;
    Framebuffer(Viewport vp, int samples_per_pixel)
        : viewport(vp),
          samples(samples_per_pixel),
          ids(size(vp, samples_per_pixel), kNoTriangle),
          depth(size(vp, samples_per_pixel), std::numeric_limits<double>::infinity()) {}

    std::size_t index(int i, int j, int s = 0) const {
        return (static_cast<std::size_t>(j) * static_cast<std::size_t>(viewport.width) +
                static_cast<std::size_t>(i)) * static_cast<std::size_t>(samples) +
               static_cast<std::size_t>(s);
    }
    std::int32_t id(int i, int j, int s = 0) const { return ids[index(i, j, s)]; }

private:
    static std::size_t size(Viewport vp, int n) {
        return static_cast<std::size_t>(vp.width) * static_cast<std::size_t>(vp.height) *
               static_cast<std::size_t>(n);
    }
};

// Gives the triangles of a framebuffer drawn with each triangle's index in Scene::triangles as its id
// their ids in the scene (triangle_ids): the engines draw the triangles so, then the lines. Renaming keeps
// the (z, id) order among triangles, for their ids ascend with their indices.
inline void rename_triangles(Framebuffer& fb, const std::vector<std::int32_t>& ids) {
    for (std::int32_t& id : fb.ids)
        if (id != Framebuffer::kNoTriangle) id = ids[static_cast<std::size_t>(id)];
}

}  // namespace rast
