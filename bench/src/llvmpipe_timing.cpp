#include "llvmpipe_timing.h"

#include "timing.h"

#include <rast/llvmpipe.h>

#include <sys/socket.h>
#include <sys/time.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <csignal>
#include <cstdint>
#include <cstring>
#include <exception>
#include <stdexcept>
#include <string>

namespace rast::bench {
namespace {

// The conversation on the socket: the parent sends one byte per request, the child answers each with
// its first byte and what follows it. On any failure the child answers 'E' and its message, and exits.
constexpr char kDraw = 'D', kRead = 'I';
constexpr char kReady = 'R', kTimed = 'T', kIds = 'I', kError = 'E';

template <typename T>
void append_raw(std::string& bytes, const Samples<T>& values) {
    bytes.append(reinterpret_cast<const char*>(values.data()), values.size() * sizeof(T));
}

void write_all(int fd, const std::string& bytes) {
    for (std::size_t done = 0; done < bytes.size();) {
        const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) return;
        done += static_cast<std::size_t>(n);
    }
}

// Up to `size` bytes, fewer only where the other end closed.
std::size_t read_up_to(int fd, char* to, std::size_t size) {
    std::size_t done = 0;
    while (done < size) {
        const ssize_t n = read(fd, to + done, size - done);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) break;
        done += static_cast<std::size_t>(n);
    }
    return done;
}

std::string read_to_end(int fd) {
    std::string bytes;
    char chunk[4096];
    while (const std::size_t n = read_up_to(fd, chunk, sizeof chunk)) bytes.append(chunk, n);
    return bytes;
}

// In the child: every descriptor from 3 up closed but `keep`, among them the parent's ends of other
// children's sockets (a child holding one would keep that child from ever seeing its parent close it).
// close_range where the kernel has it (Linux 5.9 on), one by one where it does not.
void close_all_but(int keep) {
    const auto close_from = [](unsigned first, unsigned last) {
        if (first > last || close_range(first, last, 0) == 0) return;
        const long open_max = sysconf(_SC_OPEN_MAX);
        for (long fd = first; fd <= std::min<long>(last, open_max - 1); ++fd) close(static_cast<int>(fd));
    };
    const unsigned k = static_cast<unsigned>(keep);
    if (k > 3) close_from(3, k - 1);
    close_from(std::max(k + 1, 3U), ~0U);
}

// The child's side, until the parent closes the socket.
[[noreturn]] void serve(int fd, const Scene& scene, int threads) {
    try {
        peer::Llvmpipe llvmpipe(threads);
        llvmpipe.load(scene);
        llvmpipe.draw();
        write_all(fd, std::string(1, kReady));
        char request = 0;
        while (read_up_to(fd, &request, 1) == 1) {
            std::string reply;
            if (request == kDraw) {
                const double seconds = seconds_of([&llvmpipe] { llvmpipe.draw(); });
                reply = std::string(1, kTimed) + std::string(reinterpret_cast<const char*>(&seconds), sizeof seconds);
            } else if (request == kRead) {
                const Framebuffer result = llvmpipe.read_ids();
                reply = std::string(1, kIds);
                append_raw(reply, result.ids);
                append_raw(reply, result.depth);
            } else {
                throw std::runtime_error("unknown request " + std::to_string(request));
            }
            write_all(fd, reply);
        }
    } catch (const std::exception& e) {
        write_all(fd, std::string(1, kError) + e.what());
    }
    _exit(0);  // no atexit handlers or destructors of the parent's state in the child
}

}  // namespace

LlvmpipeChild::LlvmpipeChild(const Scene& scene, int threads, int reply_seconds)
    : viewport_(scene.viewport), reply_seconds_(reply_seconds) {
    int fds[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, fds) != 0)
        fail(std::string("socketpair: ") + std::strerror(errno));
    pid_ = fork();
    if (pid_ < 0) {
        close(fds[0]);
        close(fds[1]);
        fail(std::string("fork: ") + std::strerror(errno));
    }
    if (pid_ == 0) {
        close(fds[0]);
        close_all_but(fds[1]);
        serve(fds[1], scene, threads);
    }
    close(fds[1]);
    socket_ = fds[0];
    const timeval limit{reply_seconds, 0};
    if (setsockopt(socket_, SOL_SOCKET, SO_RCVTIMEO, &limit, sizeof limit) != 0)
        fail(std::string("setsockopt: ") + std::strerror(errno));
    char reply = 0;
    receive(&reply, 1);
    if (reply == kError) fail(read_to_end(socket_));
    if (reply != kReady) fail("unexpected reply from the child process");
}

LlvmpipeChild::~LlvmpipeChild() { end(); }

void LlvmpipeChild::end() {
    if (socket_ >= 0) close(socket_);  // the child sees the end of its requests and exits
    socket_ = -1;
    if (pid_ > 0) {
        int status = 0;
        while (waitpid(pid_, &status, 0) < 0 && errno == EINTR) {
        }
    }
    pid_ = -1;
}

void LlvmpipeChild::fail(const std::string& what) {
    // A child that failed may be stuck, and one that reported an error exits anyway.
    if (pid_ > 0) kill(pid_, SIGKILL);
    end();
    throw std::runtime_error("llvmpipe timing: " + what);
}

void LlvmpipeChild::ask(char request, char expected, char* to, std::size_t size) {
    if (socket_ < 0) fail("the child process has ended");
    // MSG_NOSIGNAL: a child that died must not take the parent with it (SIGPIPE).
    if (send(socket_, &request, 1, MSG_NOSIGNAL) != 1) fail("the child process died");
    char reply = 0;
    receive(&reply, 1);
    if (reply == kError) fail(read_to_end(socket_));
    if (reply != expected) fail("unexpected reply from the child process");
    receive(to, size);
}

void LlvmpipeChild::receive(char* to, std::size_t size) {
    errno = 0;
    if (read_up_to(socket_, to, size) == size) return;
    if (errno == EAGAIN || errno == EWOULDBLOCK)
        fail("no reply from the child process in " + std::to_string(reply_seconds_) + " s");
    fail("the child process died");
}

double LlvmpipeChild::draw() {
    double seconds = 0;
    ask(kDraw, kTimed, reinterpret_cast<char*>(&seconds), sizeof seconds);
    return seconds;
}

Framebuffer LlvmpipeChild::result() {
    Framebuffer result(viewport_, 1);
    const std::size_t n = result.ids.size();
    std::string bytes(n * (sizeof(std::int32_t) + sizeof(double)), '\0');
    ask(kRead, kIds, bytes.data(), bytes.size());
    std::memcpy(result.ids.data(), bytes.data(), n * sizeof(std::int32_t));
    std::memcpy(result.depth.data(), bytes.data() + n * sizeof(std::int32_t), n * sizeof(double));
    return result;
}

LlvmpipeDraws time_llvmpipe_draws(const Scene& scene, int threads, std::size_t iterations) {
    LlvmpipeChild llvmpipe(scene, threads);
    LlvmpipeDraws draws;
    for (std::size_t k = 0; k < iterations; ++k) draws.seconds.push_back(llvmpipe.draw());
    draws.result = llvmpipe.result();
    return draws;
}

}  // namespace rast::bench
