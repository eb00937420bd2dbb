/* A careful rasterizer written for these tests from the lecture and the specifications alone, without
 * rast's code: the independent engine that rast conform must pass, and the base of the seeded defects.
 *
 *   - x and y snapped to 1/256 of a pixel, to nearest with ties to even (the FPU's default rounding);
 *   - edge functions on the snapped integers, as GMP integers: exact at any magnitude;
 *   - the top-left rule: counter-clockwise, a sample on an edge belongs to a left (dy < 0) or top
 *     (dy == 0, dx < 0) edge; on a vertex, to both of its edges or not at all;
 *   - the Vulkan standard sample positions (y mirrored: rast's y points up);
 *   - depth z interpolated on the snapped triangle, compared exactly as GMP rationals, ties to the lower id.
 *
 * Built with one DEFECT_... macro, it goes wrong in that one way, and its contract does not say so:
 *   DEFECT_TIES_BOTTOM_RIGHT  samples on right and bottom edges owned instead of left and top
 *   DEFECT_SNAP_TRUNCATE      coordinates cut toward zero instead of rounded to nearest
 *   DEFECT_LAST_WINS_TIE      equal depths go to the later triangle
 *   DEFECT_IDS_OFF_BY_ONE     each sample gets the id one below its triangle's
 *   DEFECT_TOP_ROW_UNWRITTEN  the top row of pixels is never written (left as rast set it, -1)
 *   DEFECT_CULLS_CLOCKWISE    clockwise triangles are dropped, as by back-face culling left on */
#include <rast/plugin.h>

#include <gmp.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

int rast_plugin_abi_version(void) { return RAST_PLUGIN_ABI_VERSION; }

const char *rast_plugin_contract(void) {
    return "name=careful samples=1,4,8,16 snap=8 rounding=nearest-even ties=top-left depth=zid";
}

/* Vulkan's standard sample locations, in the spec's y-down pixel; mirrored below. */
static const double kPattern1[] = {0.5, 0.5};
static const double kPattern4[] = {0.375, 0.125, 0.875, 0.375, 0.125, 0.625, 0.625, 0.875};
static const double kPattern8[] = {0.5625, 0.3125, 0.4375, 0.6875, 0.8125, 0.5625, 0.3125, 0.1875,
                                   0.1875, 0.8125, 0.0625, 0.4375, 0.6875, 0.9375, 0.9375, 0.0625};
static const double kPattern16[] = {0.5625, 0.5625, 0.4375, 0.3125, 0.3125, 0.625, 0.75,   0.4375,
                                    0.1875, 0.375,  0.625,  0.8125, 0.8125, 0.6875, 0.6875, 0.1875,
                                    0.375,  0.875,  0.5,    0.0625, 0.25,   0.125,  0.125,  0.75,
                                    0.0,    0.5,    0.9375, 0.25,   0.875,  0.9375, 0.0625, 0.0};

/* A snapped coordinate, in units of 1/256 pixel: exact, as a GMP integer. */
static void snap(mpz_t out, double v) {
#ifdef DEFECT_SNAP_TRUNCATE
    const double scaled = trunc(ldexp(v, 8));
#else
    const double scaled = nearbyint(ldexp(v, 8));  /* exact: a power-of-two scale, then one rounding */
#endif
    if (isfinite(scaled)) {
        mpz_set_d(out, scaled);
        return;
    }
    /* Past 2^1016 pixels v * 256 overflows a double; v is an integer there, so v * 256 exactly. */
    mpz_set_d(out, v);
    mpz_mul_2exp(out, out, 8);
}

typedef struct {
    mpz_t x[3], y[3];
    mpq_t z[3];
    int ok;  /* non-zero area */
} Tri;

/* e = (b - a) x (p - a), exactly. */
static void edge(mpz_t e, const mpz_t ax, const mpz_t ay, const mpz_t bx, const mpz_t by, const mpz_t px,
                 const mpz_t py, mpz_t t1, mpz_t t2) {
    mpz_sub(t1, bx, ax);
    mpz_sub(t2, py, ay);
    mpz_mul(e, t1, t2);
    mpz_sub(t1, by, ay);
    mpz_sub(t2, px, ax);
    mpz_submul(e, t1, t2);
}

/* Whether the edge a -> b of a counter-clockwise triangle owns the samples on it. */
static int owns(const mpz_t ax, const mpz_t ay, const mpz_t bx, const mpz_t by) {
    const int dy = mpz_cmp(by, ay), dx = mpz_cmp(bx, ax);
#ifdef DEFECT_TIES_BOTTOM_RIGHT
    return dy > 0 || (dy == 0 && dx > 0);
#else
    return dy < 0 || (dy == 0 && dx < 0);
#endif
}

int rast_plugin_render(const rast_plugin_scene *scene, int32_t *ids, char *err, size_t errlen) {
    const int w = scene->width, h = scene->height, n = scene->samples;
    const double *pattern = n == 1 ? kPattern1 : n == 4 ? kPattern4 : n == 8 ? kPattern8 : n == 16 ? kPattern16 : NULL;
    if (!pattern) {
        snprintf(err, errlen, "%d samples a pixel: this engine renders 1, 4, 8 or 16", n);
        return 1;
    }
    const size_t count = (size_t)w * (size_t)h * (size_t)n;
    mpq_t *depth = malloc(sizeof(mpq_t) * count);
    int32_t *owner = malloc(sizeof(int32_t) * count);
    if (!depth || !owner) {
        free(depth);
        free(owner);
        snprintf(err, errlen, "out of memory for %zu samples", count);
        return 1;
    }
    for (size_t k = 0; k < count; ++k) {
        mpq_init(depth[k]);
        owner[k] = -1;
    }
    mpz_t px, py, e[3], t1, t2, area;
    mpq_t z, q;
    mpz_inits(px, py, e[0], e[1], e[2], t1, t2, area, NULL);
    mpq_init(z);
    mpq_init(q);
    Tri t;
    for (int k = 0; k < 3; ++k) {
        mpz_init(t.x[k]);
        mpz_init(t.y[k]);
        mpq_init(t.z[k]);
    }
    for (uint64_t id = 0; id < scene->triangle_count; ++id) {
        const double *v = scene->vertices + 9 * id;
        for (int k = 0; k < 3; ++k) {
            snap(t.x[k], v[3 * k]);
            snap(t.y[k], v[3 * k + 1]);
            mpq_set_d(t.z[k], v[3 * k + 2]);
        }
        edge(area, t.x[0], t.y[0], t.x[1], t.y[1], t.x[2], t.y[2], t1, t2);
        if (mpz_sgn(area) == 0) continue;
        if (mpz_sgn(area) < 0) { /* the same point set, counter-clockwise */
#ifdef DEFECT_CULLS_CLOCKWISE
            continue;
#endif
            mpz_swap(t.x[1], t.x[2]);
            mpz_swap(t.y[1], t.y[2]);
            mpq_swap(t.z[1], t.z[2]);
            mpz_neg(area, area);
        }
        /* The pixels the snapped bounding box reaches, in the viewport. */
        double lo_x = INFINITY, hi_x = -INFINITY, lo_y = INFINITY, hi_y = -INFINITY;
        for (int k = 0; k < 3; ++k) {
            const double sx = ldexp(mpz_get_d(t.x[k]), -8), sy = ldexp(mpz_get_d(t.y[k]), -8);
            lo_x = fmin(lo_x, sx), hi_x = fmax(hi_x, sx), lo_y = fmin(lo_y, sy), hi_y = fmax(hi_y, sy);
        }
        const int i0 = lo_x < 0 ? 0 : lo_x > w ? w : (int)floor(lo_x) - 1;
        const int i1 = hi_x >= w ? w - 1 : hi_x < 0 ? -1 : (int)ceil(hi_x);
        const int j0 = lo_y < 0 ? 0 : lo_y > h ? h : (int)floor(lo_y) - 1;
        const int j1 = hi_y >= h ? h - 1 : hi_y < 0 ? -1 : (int)ceil(hi_y);
        for (int j = j0 < 0 ? 0 : j0; j <= j1; ++j)
            for (int i = i0 < 0 ? 0 : i0; i <= i1; ++i)
                for (int s = 0; s < n; ++s) {
                    /* Sample positions are multiples of 1/16: exact in units of 1/256. */
                    mpz_set_si(px, (long)((i + pattern[2 * s]) * 256));
                    mpz_set_si(py, (long)((j + 1 - pattern[2 * s + 1]) * 256));
                    int inside = 1;
                    for (int k = 0; k < 3 && inside; ++k) {
                        const int a = (k + 1) % 3, b = (k + 2) % 3; /* edge opposite vertex k */
                        edge(e[k], t.x[a], t.y[a], t.x[b], t.y[b], px, py, t1, t2);
                        const int sign = mpz_sgn(e[k]);
                        inside = sign > 0 || (sign == 0 && owns(t.x[a], t.y[a], t.x[b], t.y[b]));
                    }
                    if (!inside) continue;
                    /* z = (e0 z0 + e1 z1 + e2 z2) / area: e_k weighs the vertex opposite its edge. */
                    mpq_set_ui(z, 0, 1);
                    for (int k = 0; k < 3; ++k) {
                        mpq_set_z(q, e[k]);
                        mpq_mul(q, q, t.z[k]);
                        mpq_add(z, z, q);
                    }
                    mpq_set_z(q, area);
                    mpq_div(z, z, q);
                    const size_t index = ((size_t)j * (size_t)w + (size_t)i) * (size_t)n + (size_t)s;
                    const int order = owner[index] < 0 ? -1 : mpq_cmp(z, depth[index]);
#ifdef DEFECT_LAST_WINS_TIE
                    if (order <= 0) {
#else
                    if (order < 0) { /* drawn in id order: an equal depth keeps the lower id */
#endif
                        mpq_set(depth[index], z);
                        owner[index] = (int32_t)id;
                    }
                }
    }
    for (size_t k = 0; k < count; ++k) {
        mpq_clear(depth[k]);
#ifdef DEFECT_TOP_ROW_UNWRITTEN
        if (k / ((size_t)w * (size_t)n) == (size_t)h - 1) continue;
#endif
#ifdef DEFECT_IDS_OFF_BY_ONE
        ids[k] = owner[k] < 0 ? -1 : owner[k] - 1;
#else
        ids[k] = owner[k];
#endif
    }
    for (int k = 0; k < 3; ++k) {
        mpz_clear(t.x[k]);
        mpz_clear(t.y[k]);
        mpq_clear(t.z[k]);
    }
    mpz_clears(px, py, e[0], e[1], e[2], t1, t2, area, NULL);
    mpq_clear(z);
    mpq_clear(q);
    free(depth);
    free(owner);
    return 0;
}
