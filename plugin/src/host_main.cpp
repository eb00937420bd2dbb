// rast-plugin-host LIBRARY: loads a rasterizer plugin (rast/plugin.h) and renders the scenes rast sends
// it over fd 3 (host_protocol.h), until rast closes the socket. rast starts one per plugin engine; a
// plugin that crashes or hangs here is reported by rast, which goes on.
#include <rast/plugin.h>

#include <dlfcn.h>
#include <unistd.h>

#include <cstdio>
#include <cstring>
#include <string>
#include <vector>

#include "host_protocol.h"

namespace {

using namespace rast::plugin_host;

bool send_text(bool ok, const std::string& text) {
    const std::string cut = text.substr(0, kMaxText);
    const Status status{ok ? 1u : 0u, static_cast<std::uint32_t>(cut.size())};
    return write_all(kSocketFd, &status, sizeof status) && write_all(kSocketFd, cut.data(), cut.size());
}

using AbiVersion = int (*)();
using ContractText = const char* (*)();
using Render = int (*)(const rast_plugin_scene*, int32_t*, char*, size_t);

// The symbol, or null with its name added to `missing`.
void* symbol(void* library, const char* name, std::string& missing) {
    void* found = dlsym(library, name);
    if (!found) missing += (missing.empty() ? "" : ", ") + std::string(name);
    return found;
}

// Serves render requests until rast closes the socket; false if the socket failed.
bool serve(Render render) {
    std::vector<double> vertices;
    std::vector<std::int32_t> ids;
    while (true) {
        SceneHeader header{};
        if (!read_all(kSocketFd, &header, sizeof header)) return true;  // rast is done
        if (header.magic != kSceneMagic) return false;
        vertices.resize(header.triangle_count * 9);
        ids.assign(static_cast<std::size_t>(header.width) * static_cast<std::size_t>(header.height) *
                       static_cast<std::size_t>(header.samples),
                   -1);
        if (!read_all(kSocketFd, vertices.data(), vertices.size() * sizeof(double))) return false;
        const rast_plugin_scene scene{header.width, header.height, header.samples, header.triangle_count,
                                      vertices.data()};
        // One byte more than the plugin may use, so that a message it leaves unterminated still ends.
        char message[kMaxText + 1] = {};
        if (render(&scene, ids.data(), message, kMaxText) != 0) {
            if (!send_text(false, std::string(message, strnlen(message, kMaxText)))) return false;
            continue;
        }
        const Status status{1, 0};
        if (!write_all(kSocketFd, &status, sizeof status) ||
            !write_all(kSocketFd, ids.data(), ids.size() * sizeof(std::int32_t)))
            return false;
    }
}

}  // namespace

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: rast-plugin-host LIBRARY (run by rast, with its socket on fd 3)\n");
        return 2;
    }
    // What a plugin prints goes to stderr, never into the socket or rast's own output.
    dup2(STDERR_FILENO, STDOUT_FILENO);

    void* library = dlopen(argv[1], RTLD_NOW | RTLD_LOCAL);
    if (!library) return send_text(false, std::string("cannot load it: ") + dlerror()) ? 0 : 1;
    std::string missing;
    const auto abi = reinterpret_cast<AbiVersion>(symbol(library, "rast_plugin_abi_version", missing));
    const auto contract = reinterpret_cast<ContractText>(symbol(library, "rast_plugin_contract", missing));
    const auto render = reinterpret_cast<Render>(symbol(library, "rast_plugin_render", missing));
    if (!missing.empty())
        return send_text(false, "it does not export " + missing + " (with C linkage: extern \"C\")") ? 0 : 1;
    if (const int version = abi(); version != RAST_PLUGIN_ABI_VERSION)
        return send_text(false, "rast_plugin_abi_version() returned " + std::to_string(version) +
                                    "; this rast speaks version " + std::to_string(RAST_PLUGIN_ABI_VERSION))
                   ? 0
                   : 1;
    const char* text = contract();
    if (!text) return send_text(false, "rast_plugin_contract() returned NULL") ? 0 : 1;
    const std::size_t length = strnlen(text, kMaxText + 1);
    if (length > kMaxText)
        return send_text(false, "rast_plugin_contract() is longer than " + std::to_string(kMaxText) + " bytes") ? 0 : 1;
    if (!send_text(true, std::string(text, length))) return 1;
    return serve(render) ? 0 : 1;
}
