// Repeated wall-clock timing: the median and the spread of a run.
#pragma once

#include <chrono>
#include <cstddef>
#include <vector>

namespace rast::bench {

// Seconds over repeated runs. The median is what ratios use; min and max show how noisy the machine was.
struct Spread {
    double median = 0, min = 0, max = 0;
    std::size_t runs = 0;
};

// Throws std::invalid_argument for an empty list.
Spread spread(std::vector<double> seconds);

// The wall time of one call of `run`.
template <typename Run>
double seconds_of(Run&& run) {
    const auto start = std::chrono::steady_clock::now();
    run();
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace rast::bench
