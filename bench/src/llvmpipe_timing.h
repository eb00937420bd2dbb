// Timing llvmpipe draws in a child process.
#pragma once

#include <rast/scene.h>

#include <sys/types.h>

#include <cstddef>
#include <string>
#include <vector>

namespace rast::bench {

// llvmpipe drawing one scene with `threads` rasterizer threads, in a child process of its own: OSMesa
// creates llvmpipe once per process and reads LP_NUM_THREADS only then, so each thread count needs a
// process, and keeping it lets its draws be timed in turns with other engines' renders. The constructor
// loads the scene and draws it once untimed (llvmpipe compiles its shaders on first use). The caller must
// never create an OSMesa context itself. Every member throws std::runtime_error with the child's message
// when it fails; the destructor ends the child.
class LlvmpipeChild {
public:
    // A child that sends no reply for `reply_seconds` (one that deadlocked: it is forked from a process
    // with threads and starts Mesa's) is killed, and the call throws, rather than hang the bench.
    static constexpr int kReplySeconds = 120;
    LlvmpipeChild(const Scene& scene, int threads, int reply_seconds = kReplySeconds);
    ~LlvmpipeChild();
    LlvmpipeChild(const LlvmpipeChild&) = delete;
    LlvmpipeChild& operator=(const LlvmpipeChild&) = delete;

    // The wall time in seconds of one draw, glFinish included, upload and readback excluded, taken in the
    // child.
    double draw();

    // What the last draw left, read back (rast::peer::Llvmpipe::read_ids).
    Framebuffer result();

    pid_t pid() const { return pid_; }  // the child's, for tests that stop it

private:
    // Sends `request` and reads the reply `expected`, with `size` bytes after it, into `to`.
    void ask(char request, char expected, char* to, std::size_t size);
    // `size` bytes of a reply, else fails: the child died, or sent nothing for reply_seconds.
    void receive(char* to, std::size_t size);
    [[noreturn]] void fail(const std::string& what);  // ends the child, then throws
    void end();
    Viewport viewport_;
    int reply_seconds_;
    pid_t pid_ = -1;
    int socket_ = -1;
};

struct LlvmpipeDraws {
    std::vector<double> seconds;
    Framebuffer result;  // what the last draw left
};

// `iterations` timed draws in a row, after the untimed one (LlvmpipeChild).
LlvmpipeDraws time_llvmpipe_draws(const Scene& scene, int threads, std::size_t iterations);

}  // namespace rast::bench
