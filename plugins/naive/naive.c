/* The rasterizer of a first graphics course, as a plugin: a bounding box, float barycentric weights, a
 * sample inside when all three are >= 0, and a float z-buffer that lets a later triangle win a tie (<=).
 * Its contract claims what a careful engine keeps (the tie rule and the exact (z, id) order), so that
 * rast conform can show each place where the code falls short of the claim:
 *   - ">= 0" covers a sample on a shared edge by both triangles, and one on a vertex by all of them;
 *   - float weights misjudge samples near an edge, and float depths misorder close surfaces;
 *   - "<=" in draw order breaks the (z, id) order where depths tie. */
#include <rast/plugin.h>

#include <math.h>
#include <stdlib.h>
#include <string.h>

int rast_plugin_abi_version(void) { return RAST_PLUGIN_ABI_VERSION; }

const char *rast_plugin_contract(void) {
    return "name=naive samples=1 snap=none ties=top-left depth=zid";
}

static float edge(float ax, float ay, float bx, float by, float px, float py) {
    return (bx - ax) * (py - ay) - (by - ay) * (px - ax);
}

int rast_plugin_render(const rast_plugin_scene *scene, int32_t *ids, char *err, size_t errlen) {
    const int w = scene->width, h = scene->height;
    float *depth = malloc(sizeof(float) * (size_t)w * (size_t)h);
    if (!depth) {
        strncpy(err, "out of memory", errlen);
        return 1;
    }
    for (size_t k = 0; k < (size_t)w * (size_t)h; ++k) {
        depth[k] = INFINITY;
        ids[k] = -1;
    }
    for (uint64_t t = 0; t < scene->triangle_count; ++t) {
        const double *v = scene->vertices + 9 * t;
        const float x0 = (float)v[0], y0 = (float)v[1], z0 = (float)v[2];
        const float x1 = (float)v[3], y1 = (float)v[4], z1 = (float)v[5];
        const float x2 = (float)v[6], y2 = (float)v[7], z2 = (float)v[8];
        const float area = edge(x0, y0, x1, y1, x2, y2);
        int i0 = (int)floorf(fminf(x0, fminf(x1, x2))), i1 = (int)ceilf(fmaxf(x0, fmaxf(x1, x2)));
        int j0 = (int)floorf(fminf(y0, fminf(y1, y2))), j1 = (int)ceilf(fmaxf(y0, fmaxf(y1, y2)));
        if (i0 < 0) i0 = 0;
        if (j0 < 0) j0 = 0;
        if (i1 > w - 1) i1 = w - 1;
        if (j1 > h - 1) j1 = h - 1;
        for (int j = j0; j <= j1; ++j)
            for (int i = i0; i <= i1; ++i) {
                const float px = i + 0.5f, py = j + 0.5f;
                const float b0 = edge(x1, y1, x2, y2, px, py) / area;
                const float b1 = edge(x2, y2, x0, y0, px, py) / area;
                const float b2 = edge(x0, y0, x1, y1, px, py) / area;
                if (b0 >= 0 && b1 >= 0 && b2 >= 0) {
                    const float z = b0 * z0 + b1 * z1 + b2 * z2;
                    const size_t k = (size_t)j * (size_t)w + (size_t)i;
                    if (z <= depth[k]) {
                        depth[k] = z;
                        ids[k] = (int32_t)t;
                    }
                }
            }
    }
    free(depth);
    return 0;
}
