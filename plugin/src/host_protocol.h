// rast — the messages between rast and rast-plugin-host, the process that loads a plugin and runs it, so
// that a plugin that crashes or hangs takes only that process down. They travel over one Unix stream
// socket (fd 3 in the host), in the machine's own byte order: both ends are built together.
//
//   host → rast, once:  Status, then the contract string (ok) or the message (error)
//   rast → host:        a SceneHeader, then 9 doubles a triangle
//   host → rast:        Status, then width·height·samples int32 ids (ok) or the message (error)
#pragma once

#include <cstdint>
#include <string>

namespace rast::plugin_host {

constexpr int kSocketFd = 3;
constexpr std::uint32_t kSceneMagic = 0x52535451;  // "RSTQ"
// A contract or a message longer than this is cut (the contract is then refused as malformed).
constexpr std::uint32_t kMaxText = 4096;

struct Status {
    std::uint32_t ok;      // 1: what follows is the contract or the ids; 0: a message of `length` bytes
    std::uint32_t length;  // of the text that follows, for the contract and for a message
};

struct SceneHeader {
    std::uint32_t magic;
    std::int32_t width, height, samples;
    std::uint64_t triangle_count;
};

// Every byte of [data, data + size) written to (read from) fd, across short writes (reads) and EINTR.
// False on an error or, for reads, the end of the stream before `size` bytes.
bool write_all(int fd, const void* data, std::size_t size);
bool read_all(int fd, void* data, std::size_t size);

}  // namespace rast::plugin_host
