// Writes the near-plane family: a cube projected by a camera whose near plane cuts through it, as rast::scene
// clips it (rast/mesh.h), saved as .tri. Build the target corpus_generate_near_plane and run it from
// corpus/near-plane; the output is committed, this records how it was made.
#include <rast/exact_geometry.h>
#include <rast/mesh.h>
#include <rast/tri_format.h>

#include <string>

namespace {

rast::Mesh cube() {
    rast::Mesh mesh;
    for (int k = 0; k < 8; ++k) mesh.positions.push_back({k & 1 ? 1.0 : -1.0, k & 2 ? 1.0 : -1.0, k & 4 ? 1.0 : -1.0});
    // Two counter-clockwise triangles (seen from outside) per face.
    mesh.faces = {{0, 2, 1}, {1, 2, 3}, {4, 5, 6}, {5, 7, 6}, {0, 1, 4}, {1, 5, 4},
                  {2, 6, 3}, {3, 6, 7}, {0, 4, 2}, {2, 4, 6}, {1, 3, 5}, {3, 7, 5}};
    mesh.closed = true;
    return mesh;
}

const std::string kProperties =
    "tie_rule winding_invariance translation_invariance order_independence fixed_matches_reference "
    "float_within_bound";

}  // namespace

int main() {
    const rast::Viewport vp{12, 12};
    rast::Camera camera;
    camera.eye = {2.2, 1.7, 2.6};  // looking at a corner; the near plane cuts the three faces around it
    camera.target = {0, 0, 0};
    camera.near_plane = 2.6;
    camera.far_plane = 10;
    const rast::Scene all = rast::project(cube(), camera, vp, 1);
    const std::string camera_text = "eye (2.2, 1.7, 2.6), target the origin, fov 45, near 2.6, far 10";

    rast::write_tri_file("cube-cut-all.tri", all,
                         {{"properties", kProperties},
                          {"why", "a cube cut open by the near plane (" + camera_text +
                                      "): clipped faces become one or two triangles with new vertices at z = -1 "
                                      "shared bit for bit between neighbours; front and back faces overlap"},
                          {"found-by", "hand, corpus/near-plane/generate.cpp"}});

    rast::Scene front = all;
    front.triangles.clear();
    for (const rast::Triangle& t : all.triangles)
        if (rast::properties::orientation(t) > 0) front.triangles.push_back(t);
    rast::write_tri_file("cube-cut-front.tri", front,
                         {{"properties", "watertight area_tiling " + kProperties},
                          {"why", "the front faces of the same cut cube: a convex surface's front faces tile its "
                                  "outline, so the clipped triangles and their neighbours must meet without cracks "
                                  "along edges whose new vertices the clipper computed"},
                          {"found-by", "hand, corpus/near-plane/generate.cpp"}});
}
