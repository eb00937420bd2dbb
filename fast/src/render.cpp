// The library's entry points: the engine instantiated without any injected fault.
#include "engine.h"

#include <rast/fast.h>

namespace rast::fast {

Framebuffer render(const Scene& scene, const Options& options) {
    Framebuffer fb;
    detail::render_scene<Fault::none>(scene, options, fb);
    return fb;
}

void render(const Scene& scene, Framebuffer& target, const Options& options) {
    detail::render_scene<Fault::none>(scene, options, target);
}

std::vector<std::size_t> covered_samples(const Triangle& t, Viewport vp, int samples, Precision precision) {
    return detail::covered_by<Fault::none>(t, vp, samples, precision);
}

}  // namespace rast::fast
