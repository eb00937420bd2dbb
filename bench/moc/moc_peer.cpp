// Intel's Masked Occlusion Culling (MOC) timed beside rast::fast (fixed8, one thread) in one process: the
// same screen-space triangles for both, 1024x1024, random depth, repetitions interleaved, medians. MOC is
// a benchmark peer, not a dependency: scripts/moc-peer builds this file against a MOC checkout and an
// installed rast, outside the project. It also checks that MOC draws what rast draws (its per-pixel
// depth against rast's framebuffer) unless told `noverify`.
#include <rast/fast.h>
#include <rast/scene.h>

#include "MaskedOcclusionCulling.h"

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>
#include <random>
#include <string>
#include <vector>

namespace {

constexpr int W = 1024, H = 1024;

struct SceneDef {
    const char* name;
    std::size_t n;
    double rmin, rmax;
    const char* note;
};

// The triangles in screen space (pixels); depth per vertex uniform in [0.1, 1), stored as float so that
// both engines see the same value. x, y snapped to the 1/256 grid (what rast fixed8 and MOC's
// PRECISE_COVERAGE both snap to), so the two get identical snapped vertices.
struct Tri {
    double x[3], y[3];
    float z[3];
};

double snap256(double c) { return std::nearbyint(c * 256) / 256; }

std::vector<Tri> make_tris(const SceneDef& d, std::uint64_t seed) {
    std::mt19937_64 eng(seed);
    auto unit = [&] { return static_cast<double>(eng() >> 11) * 0x1p-53; };
    auto uni = [&](double lo, double hi) { return lo + (hi - lo) * unit(); };
    constexpr double pi = std::numbers::pi;
    std::vector<Tri> out;
    out.reserve(d.n);
    for (std::size_t k = 0; k < d.n; ++k) {
        const double cx = uni(0, W), cy = uni(0, H), start = uni(0, 2 * pi);
        Tri t;
        for (int m = 0; m < 3; ++m) {
            const double a = start + m * 2 * pi / 3 + uni(-pi / 6, pi / 6);
            const double r = uni(d.rmin, d.rmax);
            t.x[m] = snap256(cx + r * std::cos(a));
            t.y[m] = snap256(cy + r * std::sin(a));
            t.z[m] = static_cast<float>(uni(0.1, 1.0));
        }
        if (unit() < 0.5) {  // random winding: must not matter (backface culling off in MOC)
            std::swap(t.x[1], t.x[2]);
            std::swap(t.y[1], t.y[2]);
            std::swap(t.z[1], t.z[2]);
        }
        out.push_back(t);
    }
    return out;
}

rast::Scene to_rast(const std::vector<Tri>& tris) {
    rast::Scene s{{W, H}, 1, {}};
    s.triangles.reserve(tris.size());
    for (const Tri& t : tris) {
        rast::Triangle rt;
        for (int m = 0; m < 3; ++m) rt.v[m] = rast::Vertex{t.x[m], t.y[m], static_cast<double>(t.z[m])};
        s.triangles.push_back(rt);
    }
    return s;
}

// MOC input: clip-space (x, y, z(unused), w), stride 16, y at 4, w at 12 (its fast layout). MOC projects
// screenX = x/w * W/2 + W/2 and (USE_D3D=1, its default) screenY = -y/w * H/2 + H/2, so these clip
// coordinates land on exactly the screen points (x_s, y_s) above; its depth is 1/w (reversed: larger is
// nearer), so w = the vertex's depth keeps "smaller depth is nearer" at the vertices.
struct MocMesh {
    std::vector<float> vtx;
    std::vector<unsigned> idx;
};

MocMesh to_moc(const std::vector<Tri>& tris) {
    MocMesh m;
    m.vtx.reserve(tris.size() * 12);
    m.idx.reserve(tris.size() * 3);
    unsigned i = 0;
    for (const Tri& t : tris) {
        for (int k = 0; k < 3; ++k) {
            const double w = t.z[k];
            const double ndcx = t.x[k] * 2.0 / W - 1.0, ndcy = 1.0 - t.y[k] * 2.0 / H;
            m.vtx.push_back(static_cast<float>(ndcx * w));
            m.vtx.push_back(static_cast<float>(ndcy * w));
            m.vtx.push_back(0.0f);
            m.vtx.push_back(static_cast<float>(w));
            m.idx.push_back(i++);
        }
    }
    return m;
}

const char* impl_name(MaskedOcclusionCulling::Implementation i) {
    switch (i) {
        case MaskedOcclusionCulling::SSE2: return "SSE2";
        case MaskedOcclusionCulling::SSE41: return "SSE4.1";
        case MaskedOcclusionCulling::AVX2: return "AVX2";
        case MaskedOcclusionCulling::AVX512: return "AVX-512";
    }
    return "?";
}

// The q-quantile of v (0 < q < 1), interpolated between neighbours.
double quantile(std::vector<double> v, double q) {
    std::sort(v.begin(), v.end());
    const double at = q * static_cast<double>(v.size() - 1);
    const auto lo = static_cast<std::size_t>(at);
    const std::size_t hi = std::min(lo + 1, v.size() - 1);
    return v[lo] + (at - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

double median(const std::vector<double>& v) { return quantile(v, 0.5); }

// rast's time over MOC's within each repetition: the machine's speed drifts over a run, and a ratio of
// two times taken moments apart cancels most of that drift, where the ratio of the medians does not.
std::vector<double> paired_ratios(const std::vector<double>& rast, const std::vector<double>& moc) {
    std::vector<double> out;
    for (std::size_t k = 0; k < rast.size(); ++k) out.push_back(rast[k] / moc[k]);
    return out;
}

using Clock = std::chrono::steady_clock;
double ms_since(Clock::time_point t0) {
    return std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
}

MaskedOcclusionCulling::CullingResult moc_draw(MaskedOcclusionCulling* moc, const MocMesh& m, int n) {
    moc->ClearBuffer();
    return moc->RenderTriangles(m.vtx.data(), m.idx.data(), n, nullptr, MaskedOcclusionCulling::BACKFACE_NONE,
                                MaskedOcclusionCulling::CLIP_PLANE_ALL);
}

// Verification: MOC's per-pixel depth (ComputePixelDepthBuffer; -1 = cleared, else 1/w of a layer) against
// rast's framebuffer. MOC buffer row y holds screen y in [y, y+1) (checked: compared unflipped), rast row j
// holds pixel centre y = j + 0.5, so the two index the same pixel.
struct Check {
    long rast_cov = 0, moc_cov = 0, both = 0, moc_only = 0, rast_only = 0;
    long depth_violations = 0;  // flat scenes: MOC depth (1/w) nearer than rast's visible depth allows
};

Check compare(MaskedOcclusionCulling* moc, const rast::Framebuffer& fb, bool flat, const std::vector<Tri>* tris = nullptr) {
    std::vector<float> d(static_cast<std::size_t>(W) * H);
    moc->ComputePixelDepthBuffer(d.data(), false);
    Check c;
    c.depth_violations = flat ? 0 : -1;
    for (int y = 0; y < H; ++y)
        for (int x = 0; x < W; ++x) {
            const float md = d[static_cast<std::size_t>(y) * W + x];
            const bool mc = md > 0, rc = fb.id(x, y) != rast::Framebuffer::kNoTriangle;
            c.rast_cov += rc;
            c.moc_cov += mc;
            c.both += mc && rc;
            c.moc_only += mc && !rc;
            c.rast_only += rc && !mc;
            if (flat && mc && rc) {
                // Conservative occluder depth: MOC's 1/w must not be nearer (larger) than the visible
                // triangle's 1/z (flat triangles: the same under both interpolations).
                const double vis = 1.0 / fb.depth[fb.index(x, y)];
                if (md > vis * (1 + 1e-5)) {
                    if (c.depth_violations++ < 3)
                        std::printf("    depth violation at pixel (%d, %d): MOC 1/w %.7g, rast visible 1/z %.7g (id %d)\n",
                                    x, y, md, vis, fb.id(x, y));
                    if (tris && c.depth_violations <= 3)
                        for (std::size_t k = 0; k < tris->size(); ++k) {
                            const Tri& t = (*tris)[k];
                            if (std::fabs(1.0 / t.z[0] - md) > 1e-4 * md) continue;
                            std::printf("      MOC's depth matches triangle %zu: (%.4f,%.4f) (%.4f,%.4f) (%.4f,%.4f)\n", k,
                                        t.x[0], t.y[0], t.x[1], t.y[1], t.x[2], t.y[2]);
                        }
                }
            }
        }
    return c;
}

void print_check(const char* label, const Check& c) {
    std::printf("  verify %-34s rast covered %8ld  MOC covered %8ld  both %8ld  MOC-only %6ld  rast-only %7ld",
                label, c.rast_cov, c.moc_cov, c.both, c.moc_only, c.rast_only);
    if (c.depth_violations >= 0) std::printf("  depth>1/z violations %ld", c.depth_violations);
    std::printf("\n");
}

}  // namespace

int main(int argc, char** argv) {
    const int reps = argc > 1 ? std::atoi(argv[1]) : 15;
    const bool verify = !(argc > 2 && std::string(argv[2]) == "noverify");

    MaskedOcclusionCulling* moc = MaskedOcclusionCulling::Create();  // default request: best available
    MaskedOcclusionCulling* moc2 = MaskedOcclusionCulling::Create(MaskedOcclusionCulling::AVX2);
    moc->SetResolution(W, H);
    moc2->SetResolution(W, H);
    const char* auto_impl = impl_name(moc->GetImplementation());
    std::printf("MOC implementation chosen at runtime (Create() default): %s; second instance requested AVX2: %s\n",
                auto_impl, impl_name(moc2->GetImplementation()));
    std::printf("rast: fixed8, threads = 1, one Renderer kept; max_threads() = %d\n", rast::fast::max_threads());
    std::printf("reps %d, interleaved (order rotated each rep), median of each\n\n", reps);

    const SceneDef defs[] = {
        {"tiny r[2,4]", 100000, 2, 4, "issue's tiny: radius ~4 px"},
        {"tiny r[1,2]", 100000, 1, 2, "rast bench tiny: 4 px across"},
        {"small r[8,16]", 20000, 8, 16, "radius ~16 px"},
        {"small r[4,8]", 20000, 4, 8, "rast bench small: 16 px across"},
        {"large r[64,128]", 1000, 64, 128, "radius ~128 px (rast bench large)"},
        {"empty (floor)", 0, 0, 0, "no triangles: per-frame fixed cost (clear / framebuffer write)"},
    };

    rast::fast::Renderer renderer;
    rast::fast::Options opt;
    opt.precision = rast::fast::Precision::fixed8;
    opt.threads = 1;
    rast::Framebuffer fb;

    struct Row {
        std::string name;
        std::size_t n;
        double moc, moc2, rast;
        std::vector<double> ratios;  // paired_ratios against MOC's default build
    };
    std::vector<Row> rows;

    std::uint64_t seed = 1;
    for (const SceneDef& d : defs) {
        const std::vector<Tri> tris = make_tris(d, seed++);
        const rast::Scene scene = to_rast(tris);
        const MocMesh mesh = to_moc(tris);
        const int n = static_cast<int>(tris.size());

        // Warm-up (first-touch of buffers, Renderer workspace) outside the timing.
        const auto res = moc_draw(moc, mesh, n);
        moc_draw(moc2, mesh, n);
        renderer.render(scene, fb, opt);

        std::vector<double> tm, tm2, tr;
        for (int r = 0; r < reps; ++r) {
            for (int e = 0; e < 3; ++e) {
                const int which = (e + r) % 3;
                const auto t0 = Clock::now();
                if (which == 0) {
                    moc_draw(moc, mesh, n);
                    tm.push_back(ms_since(t0));
                } else if (which == 1) {
                    moc_draw(moc2, mesh, n);
                    tm2.push_back(ms_since(t0));
                } else {
                    renderer.render(scene, fb, opt);
                    tr.push_back(ms_since(t0));
                }
            }
        }
        rows.push_back({d.name, d.n, median(tm), median(tm2), median(tr), paired_ratios(tr, tm)});
        std::printf("%-16s n=%-6zu (%s): MOC-%s %.3f ms, MOC-AVX2 %.3f ms, rast %.3f ms  [MOC RenderTriangles returned %s]\n",
                    d.name, d.n, d.note, auto_impl, rows.back().moc, rows.back().moc2, rows.back().rast,
                    res == MaskedOcclusionCulling::VISIBLE ? "VISIBLE" : "VIEW_CULLED/other");
        std::fflush(stdout);

        if (verify) {
            // (a) the timed scene, random depth per vertex. MOC's QUICK_MASK heuristic may discard a layer,
            // so MOC may cover fewer pixels than drawn, never more (up to tie-rule differences on edges).
            moc_draw(moc, mesh, n);
            renderer.render(scene, fb, opt);
            print_check("random depth (timed scene), MOC auto", compare(moc, fb, false));
            moc_draw(moc2, mesh, n);
            print_check("random depth (timed scene), MOC AVX2", compare(moc2, fb, false));
            // (b) same geometry, each triangle flat at its first vertex's depth: MOC's depth must be
            // conservative (never nearer than rast's visible depth).
            std::vector<Tri> flat = tris;
            for (Tri& t : flat) t.z[1] = t.z[2] = t.z[0];
            const MocMesh fm = to_moc(flat);
            const rast::Scene fs = to_rast(flat);
            moc_draw(moc, fm, n);
            renderer.render(fs, fb, opt);
            print_check("flat per triangle, MOC auto", compare(moc, fb, true, &flat));
            // (c) same geometry, all at w = z = 1: no depth effects, MOC's mask = exact coverage union.
            std::vector<Tri> one = tris;
            for (Tri& t : one) t.z[0] = t.z[1] = t.z[2] = 1.0f;
            const MocMesh om = to_moc(one);
            const rast::Scene os = to_rast(one);
            moc_draw(moc, om, n);
            renderer.render(os, fb, opt);
            print_check("all at depth 1 (pure coverage), MOC", compare(moc, fb, false));
            // (d) occlusion queries after the timed scene: a far rect over the whole screen.
            moc_draw(moc, mesh, n);
            const auto far_full = moc->TestRect(-1, -1, 1, 1, 1000.0f);
            const auto near_full = moc->TestRect(-1, -1, 1, 1, 0.01f);
            std::printf("  verify TestRect full screen: w=1000 -> %s, w=0.01 -> %s\n",
                        far_full == MaskedOcclusionCulling::OCCLUDED ? "OCCLUDED" : "VISIBLE",
                        near_full == MaskedOcclusionCulling::OCCLUDED ? "OCCLUDED" : "VISIBLE");
            // (e) an 8x8-pixel NDC rect that rast fully covers and MOC reports as covered: far -> OCCLUDED.
            std::vector<float> d2(static_cast<std::size_t>(W) * H);
            moc->ComputePixelDepthBuffer(d2.data(), false);
            int found = 0, occl = 0;
            for (int by = 0; by + 8 <= H && found < 20; by += 8)
                for (int bx = 0; bx + 8 <= W && found < 20; bx += 8) {
                    bool all = true;
                    for (int y = by; y < by + 8 && all; ++y)
                        for (int x = bx; x < bx + 8 && all; ++x) all = d2[static_cast<std::size_t>(y) * W + x] > 0;
                    if (!all) continue;
                    ++found;
                    // screen [bx, bx+8) x [by, by+8) (y down in MOC's D3D screen) -> NDC
                    // inset by a quarter pixel so the rect's rounding cannot reach a neighbouring pixel
                    const float x0 = (bx + 0.25f) * 2.0f / W - 1, x1 = (bx + 7.75f) * 2.0f / W - 1;
                    const float y0 = 1 - (by + 7.75f) * 2.0f / H, y1 = 1 - (by + 0.25f) * 2.0f / H;
                    occl += moc->TestRect(x0, y0, x1, y1, 1000.0f) == MaskedOcclusionCulling::OCCLUDED;
                }
            std::printf("  verify TestRect on %d fully covered 8x8 blocks at w=1000: %d OCCLUDED\n", found, occl);
        }
    }

    const std::string moc_column = std::string("MOC-").append(auto_impl);
    std::printf("\n%-16s %7s %12s %12s %10s %12s %12s   %s\n", "scene", "tris", moc_column.c_str(), "MOC-AVX2",
                "rast", "rast/MOC", "rast/AVX2", "rast/MOC paired: median [quartiles]");
    for (const Row& r : rows)
        std::printf("%-16s %7zu %9.3f ms %9.3f ms %7.3f ms %11.2fx %11.2fx   %.2fx [%.2f-%.2fx]\n", r.name.c_str(),
                    r.n, r.moc, r.moc2, r.rast, r.rast / r.moc, r.rast / r.moc2, median(r.ratios),
                    quantile(r.ratios, 0.25), quantile(r.ratios, 0.75));

    MaskedOcclusionCulling::Destroy(moc);
    MaskedOcclusionCulling::Destroy(moc2);
    return 0;
}
