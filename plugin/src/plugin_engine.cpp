#include <rast/plugin_engine.h>

#include <algorithm>
#include <filesystem>
#include <limits>
#include <memory>
#include <stdexcept>

#include "plugin_process.h"

namespace rast {

namespace {

// The most samples a plugin's framebuffer may hold: 1 GiB of ids through the socket.
constexpr std::size_t kMaxSamples = std::size_t{1} << 28;

std::string where(const Framebuffer& fb, std::size_t index) {
    const auto n = static_cast<std::size_t>(fb.samples), w = static_cast<std::size_t>(fb.viewport.width);
    return "pixel (" + std::to_string(index / n % w) + ", " + std::to_string(index / n / w) + ") sample " +
           std::to_string(index % n);
}

}  // namespace

Engine plugin_engine(const std::string& given, const PluginOptions& options) {
    // dlopen searches the library path for a name without a '/': a file that is there is meant, as given.
    std::error_code unseen;
    const std::string library = given.find('/') == std::string::npos && std::filesystem::is_regular_file(given, unseen)
                                    ? "./" + given
                                    : given;
    auto process = std::make_shared<plugin_host::PluginProcess>(library, options.timeout);
    Contract contract;
    try {
        contract = Contract::parse(process->contract_text());
    } catch (const std::invalid_argument& e) {
        throw EngineError("plugin " + library + ": rast_plugin_contract() \"" + process->contract_text() +
                          "\": " + e.what());
    }
    const auto draw = [process, contract, library](const Scene& scene, Framebuffer& fb) {
        if (!scene.lines.empty())
            throw EngineError("plugin " + library + " (" + contract.name + ") cannot draw the scene's " +
                              std::to_string(scene.lines.size()) + " lines: the plugin ABI (version 1) has triangles only");
        if (!contract.renders(scene.samples))
            throw EngineError("plugin " + library + " (" + contract.name + ") does not render " +
                              std::to_string(scene.samples) + " samples a pixel (its contract: " +
                              contract.text() + ")");
        // In 128 bits: a caller's viewport is not checked yet, and the product of its sides may wrap.
        const auto samples = static_cast<unsigned __int128>(std::max(scene.viewport.width, 0)) *
                             static_cast<unsigned __int128>(std::max(scene.viewport.height, 0)) *
                             static_cast<unsigned __int128>(std::max(scene.samples, 0));
        if (samples > kMaxSamples)
            throw EngineError("plugin " + library + ": a framebuffer of " + std::to_string(scene.viewport.width) +
                              "x" + std::to_string(scene.viewport.height) + " pixels and " +
                              std::to_string(scene.samples) + " samples is more than a plugin is sent (2^28 samples)");
        fb.viewport = scene.viewport;
        fb.samples = scene.samples;
        fb.ids = process->render(scene);
        // The ABI returns ids alone.
        fb.depth.assign(fb.ids.size(), std::numeric_limits<double>::quiet_NaN());
        const auto count = static_cast<std::int64_t>(scene.triangles.size());
        for (std::size_t k = 0; k < fb.ids.size(); ++k)
            if (fb.ids[k] < -1 || fb.ids[k] >= count)
                throw EngineError("plugin " + library + " wrote id " + std::to_string(fb.ids[k]) + " at " +
                                  where(fb, k) + " of a scene of " + std::to_string(count) +
                                  " triangles (ids are -1..triangles-1)");
    };
    const auto covered = [draw](const Triangle& t, Viewport vp, int samples) {
        Framebuffer fb;
        draw(Scene{vp, samples, {t}}, fb);
        std::vector<std::size_t> indices;
        for (std::size_t k = 0; k < fb.ids.size(); ++k)
            if (fb.ids[k] == 0) indices.push_back(k);
        return indices;
    };
    return {Engine::Kind::plugin, contract.name, "plugin " + contract.name + " (" + library + ")", std::nullopt,
            contract, draw, covered, nullptr};
}

}  // namespace rast
