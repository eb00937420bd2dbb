#include "llvmpipe_timing.h"

#include <rast/llvmpipe.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdint>
#include <chrono>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>

namespace rast::bench {
namespace {

template <typename T>
void append_raw(std::string& bytes, const std::vector<T>& values) {
    bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

template <typename T>
std::size_t take_raw(const std::string& bytes, std::size_t at, std::vector<T>& values) {
    std::memcpy(values.data(), bytes.data() + at, values.size() * sizeof(T));
    return at + values.size() * sizeof(T);
}

// The child's reply on the pipe: 'T', the raw seconds, ids and depths, or 'E' and an error message.
std::string measure(const Scene& scene, int threads, std::size_t iterations) {
    try {
        peer::Llvmpipe llvmpipe(threads);
        llvmpipe.load(scene);
        llvmpipe.draw();
        std::vector<double> seconds(iterations);
        for (double& s : seconds) {
            const auto start = std::chrono::steady_clock::now();
            llvmpipe.draw();
            s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
        }
        const Framebuffer result = llvmpipe.read_ids();
        std::string reply("T");
        append_raw(reply, seconds);
        append_raw(reply, result.ids);
        append_raw(reply, result.depth);
        return reply;
    } catch (const std::exception& e) {
        return std::string("E") + e.what();
    }
}

void write_all(int fd, const std::string& bytes) {
    for (std::size_t done = 0; done < bytes.size();) {
        const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += static_cast<std::size_t>(n);
    }
}

std::string read_all(int fd) {
    std::string bytes;
    char chunk[65536];
    while (true) {
        const ssize_t n = read(fd, chunk, sizeof chunk);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return bytes;
        bytes.append(chunk, static_cast<std::size_t>(n));
    }
}

[[noreturn]] void fail(const std::string& what) {
    throw std::runtime_error("llvmpipe timing: " + what);
}

}  // namespace

LlvmpipeDraws time_llvmpipe_draws(const Scene& scene, int threads, std::size_t iterations) {
    int fds[2];
    if (pipe(fds) != 0) fail(std::string("pipe: ") + std::strerror(errno));
    const pid_t child = fork();
    if (child < 0) {
        close(fds[0]);
        close(fds[1]);
        fail(std::string("fork: ") + std::strerror(errno));
    }
    if (child == 0) {
        close(fds[0]);
        write_all(fds[1], measure(scene, threads, iterations));
        _exit(0);  // no atexit handlers or destructors of the parent's state in the child
    }
    close(fds[1]);
    const std::string reply = read_all(fds[0]);
    close(fds[0]);
    int status = 0;
    while (waitpid(child, &status, 0) < 0 && errno == EINTR) {
    }
    if (!WIFEXITED(status) || WEXITSTATUS(status) != 0) fail("the child process died");
    if (reply.empty()) fail("no reply from the child process");
    if (reply[0] == 'E') fail(reply.substr(1));
    LlvmpipeDraws draws{std::vector<double>(iterations), Framebuffer(scene.viewport, 1)};
    const std::size_t expected =
        1 + iterations * sizeof(double) + draws.result.ids.size() * (sizeof(std::int32_t) + sizeof(double));
    if (reply.size() != expected) fail("truncated reply from the child process");
    std::size_t at = take_raw(reply, 1, draws.seconds);
    at = take_raw(reply, at, draws.result.ids);
    take_raw(reply, at, draws.result.depth);
    return draws;
}

}  // namespace rast::bench
