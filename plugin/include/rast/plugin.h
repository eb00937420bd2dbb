/* rast — the plugin ABI, version 1: how any rasterizer is held to rast's contracts (docs/design.md).
 *
 * A plugin is a shared library that exports the three functions below with C linkage. rast loads it in
 * a separate process, so a plugin that crashes or hangs is reported, never fatal to rast.
 *
 * Screen space: x right, y up, the viewport [0, width] x [0, height]; pixel (i, j) covers [i, i+1] x
 * [j, j+1]; its samples are at the positions docs/design.md gives (the centre for 1 sample). */
#ifndef RAST_PLUGIN_H
#define RAST_PLUGIN_H

#include <stddef.h>
#include <stdint.h>

#define RAST_PLUGIN_ABI_VERSION 1

#ifdef __cplusplus
extern "C" {
#endif

typedef struct rast_plugin_scene {
    int32_t width, height;   /* the viewport [0, width] x [0, height], y up */
    int32_t samples;         /* 1, 4, 8 or 16, at the positions of docs/design.md */
    uint64_t triangle_count;
    const double *vertices;  /* 9 doubles a triangle: x0 y0 z0 x1 y1 z1 x2 y2 z2, screen space */
} rast_plugin_scene;

/* Returns RAST_PLUGIN_ABI_VERSION. */
int rast_plugin_abi_version(void);

/* What the engine promises, as space-separated key=value words; every key below that applies, no other:
 *   name=WORD                      what reports call the engine
 *   samples=LIST                   the sample counts it renders, comma-separated, from 1, 4, 8, 16
 *   snap=none|N                    x and y snapped to multiples of 2^-N pixel (N in 0..24) before coverage
 *   rounding=nearest-even|floor|any  how snapping rounds (any: either grid neighbour); needed with snap=N
 *   ties=top-left|none             samples on an edge follow the top-left rule, or no promise there
 *   depth=zid|none                 the exact (z, id) order decides each sample's id, or only coverage
 * For example "name=mine samples=1,4 snap=8 rounding=nearest-even ties=top-left depth=zid". */
const char *rast_plugin_contract(void);

/* Renders the scene: ids[((j * width) + i) * samples + s] (j = 0 the bottom row) receives the index of
 * the triangle that owns sample s of pixel (i, j), or -1. Returns 0; or non-zero, with a NUL-terminated
 * message of at most errlen bytes in err. */
int rast_plugin_render(const rast_plugin_scene *scene, int32_t *ids, char *err, size_t errlen);

#ifdef __cplusplus
}
#endif

#endif /* RAST_PLUGIN_H */
