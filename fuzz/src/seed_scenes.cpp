// fuzz_seed_scenes OUT_DIR SCENE.tri... — turns .tri scenes (the corpus) into seeds for the rasterizer
// fuzzer: each scene's viewport is cropped to the fuzzer's small sides (its corner at the origin) and its triangles are taken four
// at a time, each group one seed file (scene_bytes.h), written atomically. Bad input is reported with
// its file and line, and the exit status is 1.
#include "scene_bytes.h"

#include <rast/atomic_file.h>
#include <rast/parse_error.h>
#include <rast/tri_format.h>

#include <algorithm>
#include <exception>
#include <filesystem>
#include <iostream>
#include <string>

namespace {

// Writes the seeds of one scene, named after its position in the argument list and its chunk; returns how many.
std::size_t write_seeds(const std::filesystem::path& scene_file, int position, const std::filesystem::path& out_dir) {
    const rast::Scene scene = rast::read_tri_file(scene_file);
    rast::Scene part;
    part.viewport = {std::min(scene.viewport.width, rast::fuzz::kSmallSide),
                     std::min(scene.viewport.height, rast::fuzz::kSmallSide)};
    part.samples = scene.samples;
    constexpr std::size_t group = rast::fuzz::kMaxTriangles;
    std::size_t written = 0;
    do {
        const auto first = scene.triangles.begin() + static_cast<std::ptrdiff_t>(written * group);
        part.triangles.assign(first, first + static_cast<std::ptrdiff_t>(
                                                 std::min(group, scene.triangles.size() - written * group)));
        const std::vector<std::uint8_t> bytes = rast::fuzz::encode_scene(part);
        const std::string name = std::to_string(position) + "-" + scene_file.stem().string() + "-" + std::to_string(written);
        rast::write_file_atomic(out_dir / name,
                                std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
        ++written;
    } while (written * group < scene.triangles.size());
    return written;
}

}  // namespace

int main(int argc, char** argv) {
    if (argc < 2) {
        std::cerr << "usage: fuzz_seed_scenes OUT_DIR SCENE.tri...\n";
        return 2;
    }
    try {
        std::size_t seeds = 0;
        for (int k = 2; k < argc; ++k) seeds += write_seeds(argv[k], k - 1, argv[1]);
        std::cout << "fuzz_seed_scenes: " << seeds << " seeds from " << argc - 2 << " scenes in " << argv[1] << '\n';
    } catch (const std::exception& e) {
        std::cerr << "fuzz_seed_scenes: " << e.what() << '\n';
        return 1;
    }
    return 0;
}
