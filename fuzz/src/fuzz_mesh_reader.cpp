// libFuzzer harness: the mesh reader path. Every input is written to a file with each of the four
// extensions (.obj, .off, .ply, .stl) and read with read_mesh, then projected with the framed camera, as
// `rast render mesh.obj` does. Oracles:
//   - read_mesh accepts, or rejects with ParseError naming the file; project accepts, or rejects with
//     std::invalid_argument; any other exception escapes and is a finding, as is a crash, a hang or UB;
//   - an accepted mesh has faces, finite positions, and face indices that are in range and distinct;
//   - a projected scene has finite coordinates and a valid source face for each triangle.
#include <rast/mesh.h>
#include <rast/parse_error.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <string>
#include <system_error>
#include <unistd.h>

namespace {

namespace fs = std::filesystem;

[[noreturn]] void finding(const fs::path& file, const std::string& what) {
    std::cerr << "fuzz_mesh_reader: " << file.string() << ": " << what << '\n';
    std::abort();
}

// One private directory per fuzzing process (libFuzzer may run several jobs side by side).
class Scratch {
public:
    Scratch() {
        std::string pattern = (fs::temp_directory_path() / "rast-fuzz-mesh-XXXXXX").string();
        if (!mkdtemp(pattern.data())) throw std::system_error(errno, std::generic_category(), "mkdtemp " + pattern);
        dir_ = pattern;
    }
    ~Scratch() {
        std::error_code ignored;
        fs::remove_all(dir_, ignored);
    }
    Scratch(const Scratch&) = delete;
    Scratch& operator=(const Scratch&) = delete;

    fs::path write(const char* extension, const std::uint8_t* data, std::size_t size) const {
        const fs::path path = dir_ / (std::string("input.") + extension);
        std::ofstream out(path, std::ios::binary | std::ios::trunc);
        out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
        if (!out.flush()) throw std::system_error(errno, std::generic_category(), "write " + path.string());
        return path;
    }

private:
    fs::path dir_;
};

void check_mesh(const fs::path& file, const rast::Mesh& mesh) {
    if (mesh.faces.empty()) finding(file, "accepted a mesh without faces");
    for (const rast::Vec3& p : mesh.positions)
        if (!std::isfinite(p.x) || !std::isfinite(p.y) || !std::isfinite(p.z))
            finding(file, "accepted a non-finite position");
    for (const auto& f : mesh.faces) {
        for (std::uint32_t index : f)
            if (index >= mesh.positions.size()) finding(file, "a face index is out of range");
        if (f[0] == f[1] || f[1] == f[2] || f[2] == f[0]) finding(file, "a face repeats a vertex");
    }
}

void check_projection(const fs::path& file, const rast::Mesh& mesh, const rast::Projection& projection) {
    if (projection.source_face.size() != projection.scene.triangles.size())
        finding(file, "one source face per projected triangle expected");
    for (std::size_t face : projection.source_face)
        if (face >= mesh.faces.size()) finding(file, "a projected triangle names a face that does not exist");
    for (const rast::Triangle& t : projection.scene.triangles)
        for (const rast::Vertex& v : t.v)
            if (!std::isfinite(v.x) || !std::isfinite(v.y) || !std::isfinite(v.z))
                finding(file, "projection produced a non-finite coordinate");
}

void read_and_project(const fs::path& file) {
    rast::Mesh mesh;
    try {
        mesh = rast::read_mesh(file);
    } catch (const rast::ParseError& e) {
        if (e.file != file.string()) finding(file, std::string("an error that does not name the file: ") + e.what());
        return;
    }
    check_mesh(file, mesh);
    const rast::Viewport viewport{16, 12};
    try {
        const rast::Camera camera = rast::frame(mesh, viewport);
        check_projection(file, mesh, rast::project_with_sources(mesh, camera, viewport, 1));
    } catch (const std::invalid_argument&) {
        // A degenerate or overflowing framing: rejected with a message, as the command line reports it.
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    static const Scratch scratch;
    for (const char* extension : {"obj", "off", "ply", "stl"}) read_and_project(scratch.write(extension, data, size));
    return 0;
}
