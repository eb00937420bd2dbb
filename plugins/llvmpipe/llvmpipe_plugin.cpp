// Mesa's llvmpipe (through OSMesa, as peer/ drives it) behind the plugin ABI, one rasterizer thread. Its
// contract is the one it keeps on the battery, found by rast conform (README.md):
//   - one sample a pixel (peer/ reads back a single-sampled window buffer);
//   - snap=8, rounding=any: llvmpipe snaps to 1/256 pixel after GL has rounded each coordinate to float
//     (the mirrored y as H - y), so a coordinate goes to one of its two grid neighbours while a float
//     resolves 1/256, below 2^15 pixels; past that, float rounding alone moves it further;
//   - ties=top-left: llvmpipe's left-bottom rule in GL's window, under peer/'s mirror;
//   - depth=none: a 24-bit depth buffer cannot keep the exact (z, id) order.
// A coordinate that is not finite as a float (past 3.4e38) has no GL vertex: that triangle is drawn as a
// point (zero area), which covers nothing, and the verdict counts the samples it should have covered.
#include <rast/llvmpipe.h>
#include <rast/plugin.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

#include "../abi_scene.h"

namespace {

bool fits_float(double v) { return std::abs(v) <= static_cast<double>(std::numeric_limits<float>::max()) - 1e32; }

}  // namespace

extern "C" {

int rast_plugin_abi_version(void) { return RAST_PLUGIN_ABI_VERSION; }

const char* rast_plugin_contract(void) { return "name=llvmpipe samples=1 snap=8 rounding=any ties=top-left depth=none"; }

int rast_plugin_render(const rast_plugin_scene* scene, int32_t* ids, char* err, size_t errlen) {
    return rast::plugins::answer(ids, err, errlen, [scene] {
        static const auto llvmpipe = std::make_unique<rast::peer::Llvmpipe>(0);
        rast::Scene s = rast::plugins::scene_of(*scene);
        for (rast::Triangle& t : s.triangles) {
            const bool drawable = std::all_of(t.v.begin(), t.v.end(), [&](const rast::Vertex& c) {
                return fits_float(c.x) && fits_float(scene->height - c.y);
            });
            if (!drawable) t.v = {rast::Vertex{0, 0, t.v[0].z}, rast::Vertex{0, 0, t.v[0].z}, rast::Vertex{0, 0, t.v[0].z}};
        }
        llvmpipe->load(s);
        llvmpipe->draw();
        return llvmpipe->read_ids();
    });
}

}  // extern "C"
