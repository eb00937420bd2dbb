// rast's fast path in one precision (RAST_PLUGIN_PRECISION) behind the plugin ABI: the interface proven on
// engines that keep their contracts. The fixed modes promise what the reference decides on vertices snapped
// to nearest, ties to even; the float modes promise coverage decided on the input, within their error
// bound of an edge, which the contract cannot say: they claim ties=none, and rast conform shows where
// floating point still misses.
#include <rast/fast.h>
#include <rast/plugin.h>

#include <string>

#include "../abi_scene.h"

namespace {

constexpr rast::fast::Precision kPrecision = rast::fast::Precision::RAST_PLUGIN_PRECISION;

std::string contract_text() {
    const std::string name(rast::fast::name(kPrecision));
    const char* common = " samples=1,4,8,16";
    switch (kPrecision) {
        case rast::fast::Precision::fixed4: return "name=" + name + common + " snap=4 rounding=nearest-even ties=top-left depth=zid";
        case rast::fast::Precision::fixed8: return "name=" + name + common + " snap=8 rounding=nearest-even ties=top-left depth=zid";
        case rast::fast::Precision::fixed16: return "name=" + name + common + " snap=16 rounding=nearest-even ties=top-left depth=zid";
        case rast::fast::Precision::float32:
        case rast::fast::Precision::float64: return "name=" + name + common + " snap=none ties=none depth=zid";
    }
    return {};
}

}  // namespace

extern "C" {

int rast_plugin_abi_version(void) { return RAST_PLUGIN_ABI_VERSION; }

const char* rast_plugin_contract(void) {
    static const std::string text = contract_text();
    return text.c_str();
}

int rast_plugin_render(const rast_plugin_scene* scene, int32_t* ids, char* err, size_t errlen) {
    return rast::plugins::answer(ids, err, errlen, [scene] {
        static rast::fast::Renderer renderer;  // the host renders one scene at a time
        rast::Framebuffer fb;
        renderer.render(rast::plugins::scene_of(*scene), fb, {kPrecision, 1});
        return fb;
    });
}

}  // extern "C"
