/* A whole rasterizer plugin: README.md's "Testing your own rasterizer" shows this file. */
#include <rast/plugin.h>

int rast_plugin_abi_version(void) { return RAST_PLUGIN_ABI_VERSION; }

const char *rast_plugin_contract(void) {
    return "name=example samples=1 snap=none ties=none depth=none";
}

static double edge(const double *a, const double *b, double x, double y) {
    return (b[0] - a[0]) * (y - a[1]) - (b[1] - a[1]) * (x - a[0]);
}

int rast_plugin_render(const rast_plugin_scene *scene, int32_t *ids, char *err, size_t errlen) {
    for (int32_t j = 0; j < scene->height; ++j)
        for (int32_t i = 0; i < scene->width; ++i) {
            int32_t *id = &ids[(size_t)j * scene->width + i];
            *id = -1;
            for (uint64_t t = 0; t < scene->triangle_count && *id < 0; ++t) {
                const double *v = scene->vertices + 9 * t, x = i + 0.5, y = j + 0.5;
                const double e0 = edge(v, v + 3, x, y), e1 = edge(v + 3, v + 6, x, y), e2 = edge(v + 6, v, x, y);
                if ((e0 > 0 && e1 > 0 && e2 > 0) || (e0 < 0 && e1 < 0 && e2 < 0)) *id = (int32_t)t;
            }
        }
    (void)err, (void)errlen;
    return 0;
}
