// Timing llvmpipe draws in a child process.
#pragma once

#include <rast/scene.h>

#include <cstddef>
#include <vector>

namespace rast::bench {

struct LlvmpipeDraws {
    std::vector<double> seconds;
    Framebuffer result;  // what the last draw left, read back (rast::peer::Llvmpipe::read_ids)
};

// The wall time in seconds of each of `iterations` draws of `scene` by llvmpipe with `threads`
// rasterizer threads, each including glFinish, excluding upload and readback, after one untimed
// warm-up draw (llvmpipe compiles its shaders on first use). OSMesa creates llvmpipe once per process
// and reads LP_NUM_THREADS only then, so every measurement runs in a forked child process; the caller
// must never create an OSMesa context itself. Throws std::runtime_error with the child's message.
LlvmpipeDraws time_llvmpipe_draws(const Scene& scene, int threads, std::size_t iterations);

}  // namespace rast::bench
