#include "plugin_process.h"

#include <rast/engine.h>

#include <fcntl.h>
#include <poll.h>
#include <sys/prctl.h>
#include <signal.h>
#include <sys/socket.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>

#include "host_protocol.h"

namespace rast::plugin_host {

namespace {

double now() { return std::chrono::duration<double>(std::chrono::steady_clock::now().time_since_epoch()).count(); }

// How a finished host ended, in words.
std::string ending(int status) {
    if (WIFSIGNALED(status)) {
        const int signal = WTERMSIG(status);
        return "crashed (signal " + std::to_string(signal) + ", " + strsignal(signal) + ")";
    }
    if (WIFEXITED(status)) return "exited with status " + std::to_string(WEXITSTATUS(status));
    return "ended";
}

}  // namespace

std::string host_path() {
    if (const char* given = std::getenv("RAST_PLUGIN_HOST"); given && *given) return given;
    std::error_code error;
    const auto self = std::filesystem::read_symlink("/proc/self/exe", error);
    if (!error)
        for (const auto& candidate : {self.parent_path() / "rast-plugin-host",
                                      self.parent_path() / ".." / "libexec" / "rast" / "rast-plugin-host"})
            if (access(candidate.c_str(), X_OK) == 0) return candidate.string();
    return RAST_PLUGIN_HOST_BUILT;
}

PluginProcess::PluginProcess(std::string library, double timeout) : library_(std::move(library)), timeout_(timeout) {
    const std::string host = host_path();
    int sockets[2];
    if (socketpair(AF_UNIX, SOCK_STREAM | SOCK_CLOEXEC, 0, sockets) != 0)
        fail(std::string("cannot make a socket for it: ") + std::strerror(errno));
    socket_ = sockets[0];
    pid_ = fork();
    if (pid_ < 0) {
        close(sockets[1]);
        fail(std::string("cannot start a process for it: ") + std::strerror(errno));
    }
    if (pid_ == 0) {
        // The child: only async-signal-safe calls until exec. It ends with rast, even one killed outright
        // (a batch job's time limit), rather than spin on in a hung plugin.
        if (prctl(PR_SET_PDEATHSIG, SIGKILL) != 0) _exit(126);
        // dup2 clears close-on-exec on fd 3, unless the socket already is fd 3 (rast started with a
        // standard stream closed): then fcntl does.
        if (sockets[1] == kSocketFd ? fcntl(kSocketFd, F_SETFD, 0) < 0 : dup2(sockets[1], kSocketFd) < 0) _exit(126);
        const char* argv[] = {host.c_str(), library_.c_str(), nullptr};
        execv(host.c_str(), const_cast<char* const*>(argv));
        _exit(127);
    }
    close(sockets[1]);
    const double deadline = now() + timeout_;
    Status status{};
    read_reply(&status, sizeof status, deadline, "loading it (" + host + ")");
    std::string text = read_text(status.length, deadline, "loading it");
    if (!status.ok) fail(text);
    contract_ = std::move(text);
    loaded_ = true;
}

PluginProcess::~PluginProcess() {
    if (socket_ >= 0) close(socket_);  // the host reads the end of the stream and exits
    if (pid_ > 0) {
        // A host stuck in its plugin would not notice: give it a moment, then end it.
        for (int k = 0; k < 100 && waitpid(pid_, nullptr, WNOHANG) == 0; ++k) usleep(1000);
        if (waitpid(pid_, nullptr, WNOHANG) == 0) {
            kill(pid_, SIGKILL);
            waitpid(pid_, nullptr, 0);
        }
    }
}

void PluginProcess::fail(const std::string& what) {
    broken_ = "plugin " + library_ + ": " + what;
    if (socket_ >= 0) {
        close(socket_);
        socket_ = -1;
    }
    if (pid_ > 0) {
        kill(pid_, SIGKILL);
        waitpid(pid_, nullptr, 0);
        pid_ = -1;
    }
    throw EngineError(broken_);
}

void PluginProcess::read_reply(void* data, std::size_t size, double deadline, const std::string& doing) {
    char* p = static_cast<char*>(data);
    while (size > 0) {
        const double left = deadline - now();
        pollfd ready{socket_, POLLIN, 0};
        // At most a day a poll, so that any timeout a caller gives fits an int of milliseconds.
        const int polled = left > 0 ? poll(&ready, 1, static_cast<int>(std::ceil(std::min(left, 86400.0) * 1000))) : 0;
        if (polled < 0 && errno == EINTR) continue;
        if (polled == 0) {
            char seconds[32];
            std::snprintf(seconds, sizeof seconds, "%g", timeout_);
            fail("no answer within " + std::string(seconds) + " s " + doing + "; stopped it (--plugin-timeout)");
        }
        const ssize_t n = polled < 0 ? -1 : read(socket_, p, size);
        if (n < 0 && errno == EINTR) continue;
        if (n <= 0) host_gone(deadline, doing);
        p += n;
        size -= static_cast<std::size_t>(n);
    }
}

void PluginProcess::host_gone(double deadline, const std::string& doing) {
    // The socket has closed: the host has ended, or is about to. Wait for it until the deadline (a plugin
    // may close the socket and go on running), then say how it ended.
    int status = 0;
    bool ended = false;
    while (!ended && now() < deadline) {
        ended = waitpid(pid_, &status, WNOHANG) == pid_;
        if (!ended) usleep(1000);
    }
    if (!ended) fail("closed its socket " + doing + " and did not end; stopped it");
    pid_ = -1;
    // 127: execv failed in the child, before the host ran (a plugin that exits 127 later is a plugin).
    if (!loaded_ && WIFEXITED(status) && WEXITSTATUS(status) == 127)
        fail("cannot run " + host_path() + " (set RAST_PLUGIN_HOST to where rast-plugin-host is)");
    fail(ending(status) + " " + doing);
}

std::string PluginProcess::read_text(std::uint32_t length, double deadline, const std::string& doing) {
    if (length > kMaxText) fail("sent a text of " + std::to_string(length) + " bytes " + doing);
    std::string text(length, '\0');
    read_reply(text.data(), length, deadline, doing);
    return text;
}

Samples<std::int32_t> PluginProcess::render(const Scene& scene) {
    if (!broken_.empty()) throw EngineError(broken_);
    const std::string doing = "rendering a scene of " + std::to_string(scene.triangles.size()) + " triangles, " +
                              std::to_string(scene.viewport.width) + "x" + std::to_string(scene.viewport.height) +
                              ", " + std::to_string(scene.samples) + " sample(s)";
    const SceneHeader header{kSceneMagic, scene.viewport.width, scene.viewport.height, scene.samples,
                             scene.triangles.size()};
    static_assert(sizeof(Triangle) == 9 * sizeof(double), "a Triangle is the ABI's 9 doubles");
    const double deadline = now() + timeout_;
    if (!write_all(socket_, &header, sizeof header) ||
        !write_all(socket_, scene.triangles.data(), scene.triangles.size() * sizeof(Triangle)))
        host_gone(deadline, doing);
    Status status{};
    read_reply(&status, sizeof status, deadline, doing);
    if (!status.ok) {
        const std::string message = read_text(status.length, deadline, doing);
        throw EngineError("plugin " + library_ + " returned an error " + doing + ": " +
                          (message.empty() ? "(no message)" : message));
    }
    Samples<std::int32_t> ids(static_cast<std::size_t>(scene.viewport.width) *
                              static_cast<std::size_t>(scene.viewport.height) *
                              static_cast<std::size_t>(scene.samples));
    read_reply(ids.data(), ids.size() * sizeof(std::int32_t), deadline, doing);
    return ids;
}

}  // namespace rast::plugin_host
