// The library's entry points: the engine instantiated without any injected fault.
#include "engine.h"

#include <rast/fast.h>

namespace rast::fast {

Framebuffer render(const Scene& scene, const Options& options) {
    Framebuffer fb;
    render(scene, fb, options);
    return fb;
}

void render(const Scene& scene, Framebuffer& target, const Options& options) {
    Renderer().render(scene, target, options);
}

Renderer::Renderer() = default;
Renderer::Renderer(Renderer&&) noexcept = default;
Renderer& Renderer::operator=(Renderer&&) noexcept = default;
Renderer::~Renderer() = default;

void Renderer::render(const Scene& scene, Framebuffer& target, const Options& options) {
    // Made at the first render, and again after a move took it.
    if (!workspace_) workspace_ = std::make_unique<detail::Workspace>();
    detail::render_scene<Fault::none>(scene, options, target, *workspace_);
}

int max_threads() { return detail::thread_limit(); }

std::vector<std::size_t> covered_samples(const Triangle& t, Viewport vp, int samples, Precision precision) {
    return detail::covered_by<Fault::none>(t, vp, samples, precision);
}

}  // namespace rast::fast
