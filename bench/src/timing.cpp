#include "timing.h"

#include <algorithm>
#include <stdexcept>

namespace rast::bench {

Spread spread(std::vector<double> seconds) {
    if (seconds.empty()) throw std::invalid_argument("spread: no runs");
    std::sort(seconds.begin(), seconds.end());
    const std::size_t n = seconds.size();
    const double median = n % 2 == 1 ? seconds[n / 2] : (seconds[n / 2 - 1] + seconds[n / 2]) / 2;
    return {median, seconds.front(), seconds.back(), n};
}

}  // namespace rast::bench
