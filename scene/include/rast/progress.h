// rast — how far a long computation has come, for a caller that shows it.
#pragma once

#include <cstddef>
#include <functional>

namespace rast {

// Called from the computing thread with `done` of `total` units (triangles, for a render): with done == 0
// at the start, then now and then with done rising, and with done == total at the end. An empty Progress
// is never called.
using Progress = std::function<void(std::size_t done, std::size_t total)>;

// Reports `done` of `total` at the start (0), at the end, and after every `every` units between.
inline void report_progress(const Progress& progress, std::size_t done, std::size_t total, std::size_t every = 256) {
    if (progress && (done % every == 0 || done == total)) progress(done, total);
}

}  // namespace rast
