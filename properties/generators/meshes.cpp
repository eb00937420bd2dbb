// The front of a closed convex mesh (an icosphere, once subdivided) read through rast::scene from an
// OFF file and projected by a random camera outside it: its front faces tile the silhouette, the
// projected vertices shared bit for bit.
#include <rast/exact_geometry.h>
#include <rast/mesh.h>
#include <rast/property_generators.h>

#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <map>
#include <numbers>
#include <unistd.h>

namespace rast::gen::detail {

namespace {

// The icosahedron, each face cut in four, every vertex pushed out to the unit sphere and rounded to
// float (what an OFF file holds). The faces are counter-clockwise seen from outside.
Mesh icosphere() {
    const double g = (1 + std::sqrt(5.0)) / 2;
    std::vector<Vec3> p{{-1, g, 0}, {1, g, 0}, {-1, -g, 0}, {1, -g, 0}, {0, -1, g}, {0, 1, g},
                        {0, -1, -g}, {0, 1, -g}, {g, 0, -1}, {g, 0, 1}, {-g, 0, -1}, {-g, 0, 1}};
    const std::vector<std::array<std::uint32_t, 3>> coarse{
        {0, 11, 5}, {0, 5, 1}, {0, 1, 7}, {0, 7, 10}, {0, 10, 11}, {1, 5, 9}, {5, 11, 4},
        {11, 10, 2}, {10, 7, 6}, {7, 1, 8}, {3, 9, 4}, {3, 4, 2}, {3, 2, 6}, {3, 6, 8},
        {3, 8, 9}, {4, 9, 5}, {2, 4, 11}, {6, 2, 10}, {8, 6, 7}, {9, 8, 1}};
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> midpoints;
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
        const auto key = std::minmax(a, b);
        if (auto it = midpoints.find(key); it != midpoints.end()) return it->second;
        p.push_back(0.5 * (p[a] + p[b]));
        return midpoints[key] = static_cast<std::uint32_t>(p.size() - 1);
    };
    Mesh mesh;
    for (const auto& [a, b, c] : coarse) {
        const auto ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
        mesh.faces.insert(mesh.faces.end(), {{a, ab, ca}, {b, bc, ab}, {c, ca, bc}, {ab, bc, ca}});
    }
    for (Vec3 v : p) {
        v = normalized(v);
        mesh.positions.push_back({static_cast<float>(v.x), static_cast<float>(v.y), static_cast<float>(v.z)});
    }
    return mesh;
}

// Written to a temporary OFF file once and read back with rast::read_mesh, as a user's mesh would be.
const Mesh& sphere_from_file() {
    static const Mesh mesh = [] {
        const Mesh made = icosphere();
        const auto path = std::filesystem::temp_directory_path() /
                          ("rast-icosphere-" + std::to_string(::getpid()) + ".off");
        {
            std::ofstream out(path);
            out.precision(9);  // enough digits for a float to read back exactly
            out << "OFF\n" << made.positions.size() << ' ' << made.faces.size() << " 0\n";
            for (const Vec3& v : made.positions) out << v.x << ' ' << v.y << ' ' << v.z << '\n';
            for (const auto& [a, b, c] : made.faces) out << "3 " << a << ' ' << b << ' ' << c << '\n';
        }
        Mesh read = read_mesh(path);
        std::filesystem::remove(path);
        return read;
    }();
    return mesh;
}

Vec3 direction(double turn, double rise) {
    const double a = 2 * std::numbers::pi * turn, b = std::numbers::pi * (rise - 0.5);
    return {std::cos(b) * std::cos(a), std::sin(b), std::cos(b) * std::sin(a)};
}

}  // namespace

rc::Gen<std::vector<Triangle>> mesh_front(Viewport vp) {
    return rc::gen::exec([vp] {
        const Mesh& mesh = sphere_from_file();
        Camera camera;
        const double distance = *rc::gen::inRange(25, 80) / 10.0;
        camera.eye = distance * direction(*rc::gen::inRange(0, 1000) / 1000.0, *rc::gen::inRange(50, 950) / 1000.0);
        camera.target = {*rc::gen::inRange(-5, 6) / 10.0, *rc::gen::inRange(-5, 6) / 10.0, 0};
        camera.up = direction(*rc::gen::inRange(0, 1000) / 1000.0, *rc::gen::inRange(50, 950) / 1000.0);
        camera.fov_y_degrees = *rc::gen::inRange(20, 90);
        if (length(cross(camera.up, camera.target - camera.eye)) < 0.1 * distance) return std::vector<Triangle>{};
        const Projection seen = project_with_sources(mesh, camera, vp, 1);
        std::vector<Triangle> front;
        for (std::size_t k = 0; k < seen.scene.triangles.size(); ++k) {
            // Faces nearly edge-on are left out too: rounding could fold one over its neighbour. What
            // remains still tiles a region, with the left-out faces' edges on its boundary.
            const auto& f = mesh.faces[seen.source_face[k]];
            const Vec3 a = mesh.positions[f[0]], b = mesh.positions[f[1]], c = mesh.positions[f[2]];
            const Vec3 normal = normalized(cross(b - a, c - a));
            if (dot(normal, normalized(camera.eye - a)) > 0.05) front.push_back(seen.scene.triangles[k]);
        }
        return front;
    });
}

}  // namespace rast::gen::detail
