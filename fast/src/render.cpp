// The library's entry points: the engine instantiated without any injected fault.
#include "engine.h"

#include <rast/fast.h>

namespace rast::fast {

Framebuffer render(const Scene& scene, const Options& options) {
    return detail::render_scene<Fault::none>(scene, options);
}

std::vector<std::size_t> covered_samples(const Triangle& t, Viewport vp, int samples, Precision precision) {
    return detail::covered_by<Fault::none>(t, vp, samples, precision);
}

}  // namespace rast::fast
