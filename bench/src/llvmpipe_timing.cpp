#include "llvmpipe_timing.h"

#include <rast/llvmpipe.h>

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>

namespace rast::bench {
namespace {

// The child's reply on the pipe: 'T' and the raw doubles, or 'E' and an error message.
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
        std::string reply(1 + seconds.size() * sizeof(double), 'T');
        std::memcpy(reply.data() + 1, seconds.data(), seconds.size() * sizeof(double));
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

std::vector<double> time_llvmpipe_draws(const Scene& scene, int threads, std::size_t iterations) {
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
    if (reply.size() != 1 + iterations * sizeof(double)) fail("truncated reply from the child process");
    std::vector<double> seconds(iterations);
    std::memcpy(seconds.data(), reply.data() + 1, iterations * sizeof(double));
    return seconds;
}

}  // namespace rast::bench
