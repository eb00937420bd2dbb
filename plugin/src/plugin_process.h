// rast — a plugin running in its own process (rast-plugin-host), as rast's side sees it: started, asked to
// render, and reported on when it fails. Every failure, including a crash or a hang, is an EngineError
// naming the library; the process is then gone and every later render repeats the error.
#pragma once

#include <rast/scene.h>

#include <sys/types.h>

#include <cstdint>
#include <string>
#include <vector>

namespace rast::plugin_host {

class PluginProcess {
public:
    // Starts the host on `library` and reads its contract string; `timeout` bounds the start and
    // each render, in seconds.
    PluginProcess(std::string library, double timeout);
    ~PluginProcess();
    PluginProcess(const PluginProcess&) = delete;
    PluginProcess& operator=(const PluginProcess&) = delete;

    const std::string& contract_text() const { return contract_; }
    // The ids the plugin wrote, width·height·samples of them in the ABI's order, unchecked.
    Samples<std::int32_t> render(const Scene& scene);

private:
    [[noreturn]] void fail(const std::string& what);
    // The socket closed while `doing`: reports how the host ended (waiting for it until the deadline).
    [[noreturn]] void host_gone(double deadline, const std::string& doing);
    // Reads exactly `size` bytes before the deadline, or fails saying what was being read.
    void read_reply(void* data, std::size_t size, double deadline, const std::string& doing);
    std::string read_text(std::uint32_t length, double deadline, const std::string& doing);

    std::string library_;
    double timeout_;
    pid_t pid_ = -1;
    int socket_ = -1;
    std::string contract_;
    bool loaded_ = false;  // the host has sent the contract: it runs, and an exit is the plugin's
    std::string broken_;  // the failure that ended the process; empty while it runs
};

// The rast-plugin-host executable: $RAST_PLUGIN_HOST, else beside this executable, else in
// ../libexec/rast beside it (installed), else where the build put it.
std::string host_path();

}  // namespace rast::plugin_host
