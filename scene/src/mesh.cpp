// The one translation unit that includes OpenMesh.
#include <OpenMesh/Core/IO/MeshIO.hh>
#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <OpenMesh/Core/System/omstream.hh>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <fstream>
#include <mutex>
#include <sstream>
#include <string>

#include "mesh_text_check.h"
#include "rast/mesh.h"

namespace rast {

namespace {

struct DoubleTraits : OpenMesh::DefaultTraits {
    using Point = OpenMesh::Vec3d;
};
using OpenMeshTriMesh = OpenMesh::TriMesh_ArrayKernelT<DoubleTraits>;

// OpenMesh reports on its own global streams (omerr, omlog, omout), which go to the standard streams.
// While one file is read, they are pointed elsewhere: errors into a buffer for our message, the rest away.
// The streams and OpenMesh's reader registry are global, so reads are serialised.
class OpenMeshLogCapture {
public:
    OpenMeshLogCapture() : lock_(mutex()) {
        saved_err_ = omerr().rdbuf(errors_.rdbuf());
        saved_log_ = omlog().rdbuf(discarded_.rdbuf());
        saved_out_ = omout().rdbuf(discarded_.rdbuf());
    }
    OpenMeshLogCapture(const OpenMeshLogCapture&) = delete;
    OpenMeshLogCapture& operator=(const OpenMeshLogCapture&) = delete;
    ~OpenMeshLogCapture() {
        omerr().rdbuf(saved_err_);
        omlog().rdbuf(saved_log_);
        omout().rdbuf(saved_out_);
    }

    // What OpenMesh said on omerr, on one line.
    std::string errors() const {
        std::string text = errors_.str();
        std::replace(text.begin(), text.end(), '\n', ' ');
        while (!text.empty() && text.back() == ' ') text.pop_back();
        return text;
    }

private:
    static std::mutex& mutex() {
        static std::mutex m;
        return m;
    }
    std::lock_guard<std::mutex> lock_;
    std::ostringstream errors_, discarded_;
    std::streambuf *saved_err_, *saved_log_, *saved_out_;
};

std::string lower_extension(const std::filesystem::path& path) {
    std::string ext = path.extension().string();
    if (!ext.empty()) ext.erase(0, 1);
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    return ext;
}

}  // namespace

Mesh read_mesh(const std::filesystem::path& path) {
    const std::string file = path.string();
    const std::string ext = lower_extension(path);
    if (ext != "obj" && ext != "off" && ext != "ply" && ext != "stl")
        throw ParseError(file, 0, "unknown mesh extension " + quote_token(path.extension().string()) +
                                      " (expected .obj, .off, .ply or .stl)");
    if (!std::ifstream(path)) throw ParseError(file, 0, "cannot open: " + std::generic_category().message(errno));
    if (std::filesystem::is_directory(path)) throw ParseError(file, 0, "is a directory");
    const detail::MeshFileCheck check = detail::check_mesh_file(path, ext);

    OpenMeshTriMesh om;
    {
        OpenMeshLogCapture capture;
        OpenMesh::IO::Options options;
        std::istringstream off(check.off_for_openmesh.value_or(""));
        const bool read = check.off_for_openmesh ? OpenMesh::IO::read_mesh(om, off, ".off", options)
                                                 : OpenMesh::IO::read_mesh(om, file, options);
        const std::string complaint = capture.errors().empty() ? "" : " (OpenMesh: " + capture.errors() + ")";
        if (!read) throw ParseError(file, 0, "OpenMesh cannot read it" + complaint);
        // Its other complaints change nothing we keep: a missing material, or a non-manifold face, which it
        // adds anyway on copies of its vertices (the mesh is then not closed).
        if (check.triangles && om.n_faces() != *check.triangles)
            throw ParseError(file, 0, "OpenMesh made " + std::to_string(om.n_faces()) + " triangles of the " +
                                          std::to_string(*check.triangles) + " in the file" + complaint);
    }
    if (om.n_faces() == 0) throw ParseError(file, 0, "the mesh has no faces");

    Mesh mesh;
    mesh.positions.reserve(om.n_vertices());
    for (const auto vh : om.vertices()) {
        const auto& p = om.point(vh);
        if (!std::isfinite(p[0]) || !std::isfinite(p[1]) || !std::isfinite(p[2]))
            throw ParseError(file, 0, "vertex " + std::to_string(vh.idx()) + " has a non-finite coordinate");
        mesh.positions.push_back({p[0], p[1], p[2]});
    }
    mesh.faces.reserve(om.n_faces());
    for (const auto fh : om.faces()) {
        std::array<std::uint32_t, 3> face{};
        std::size_t k = 0;
        for (const auto vh : om.fv_range(fh)) face[k++] = static_cast<std::uint32_t>(vh.idx());
        mesh.faces.push_back(face);
    }
    mesh.closed = std::none_of(om.halfedges().begin(), om.halfedges().end(),
                               [&](OpenMesh::SmartHalfedgeHandle h) { return h.is_boundary(); });
    return mesh;
}

}  // namespace rast
