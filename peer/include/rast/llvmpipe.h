// rast — the outside peer: the same scene rasterized by Mesa's llvmpipe (through OSMesa).
//
// llvmpipe snaps vertices to 1/256 pixel and then decides coverage exactly, so on scenes whose
// vertices are already on that grid its id buffer is a third, independent witness for the reference
// and the fast path. How the scene is handed to GL, and why it keeps our conventions
// (docs/design.md):
//   - y is mirrored (y -> H - y): llvmpipe's tie rule is left + bottom in GL's y-up window coordinates,
//     which under the mirror is exactly our left + top rule. Rows are mirrored back on readback.
//   - x and the mirrored y reach llvmpipe's window coordinates unchanged: the GL viewport is the
//     largest power-of-two square GL allows, [-8192, 8192]^2 here, centred on the origin, under an
//     orthographic projection of the same extent, so coordinates are only ever scaled by powers of
//     two: a coordinate that is exact as a float (any 1/256-grid value below 2^15) stays bit-exact.
//     Coordinates are rounded to float, as in any GL; GL's clipper cuts off parts of a triangle
//     outside that square, which introduces off-grid vertices. The framebuffer lies in [0, 8192]^2.
//   - z is mapped monotonically (affine, then rounded to float) from the scene's [z_min, z_max] onto
//     the middle half of the depth range, [-1/2, 1/2] in NDC, so no vertex comes near the near or far
//     plane, however narrow the range and however far from zero.
//   - Depth buffer: 24-bit fixed point (OSMesa's window buffer offers no float depth), GL_LESS.
//     Depths closer than about (z_max - z_min) / 2^23 compare equal; llvmpipe also interpolates z in
//     float. Triangles are drawn in id order, so a tie keeps the lower id, as our (z, id) order does,
//     but near-equal depths may resolve differently from the exact order.
//   - Each triangle is drawn in one flat colour encoding id + 1 in RGB (24 bits; 0 is "no triangle"),
//     so a scene may hold at most 2^24 - 1 triangles.
#pragma once

#include <rast/scene.h>

#include <memory>
#include <string>

namespace rast::peer {

// An OSMesa context on llvmpipe with `threads` rasterizer threads (LP_NUM_THREADS, set before the
// context is created; 0 rasterizes on the calling thread). OSMesa creates llvmpipe once per process
// and reads LP_NUM_THREADS only then, so a process can use one thread count only: the constructor
// counts llvmpipe's threads and throws if they are not the ones asked for. It also throws if the
// renderer is not llvmpipe.
class Llvmpipe {
public:
    explicit Llvmpipe(int threads);
    ~Llvmpipe();
    Llvmpipe(const Llvmpipe&) = delete;
    Llvmpipe& operator=(const Llvmpipe&) = delete;

    // Converts the scene for GL as described above and uploads it into a vertex buffer; throws
    // std::invalid_argument for a scene llvmpipe cannot render faithfully (samples != 1, too many
    // triangles, a coordinate that is not finite or not a finite float, a viewport too large).
    void load(const Scene& scene);

    // Clears colour and depth, draws the loaded triangles in id order, and waits for llvmpipe to
    // finish (glFinish). Repeatable: this is what a benchmark times.
    void draw();

    // The result of the last draw(), read back with glReadPixels: ids, and depths mapped back to the
    // scene's z (so quantized as described above); +infinity where no triangle is.
    Framebuffer read_ids() const;

    int threads() const;
    const std::string& renderer() const;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"

private:
    struct State;
    std::unique_ptr<State> state_;
};

// One scene, one context: load, draw, read back.
Framebuffer render_llvmpipe(const Scene& scene, int threads);

}  // namespace rast::peer
