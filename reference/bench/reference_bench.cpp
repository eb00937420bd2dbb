// Throughput of the exact reference on seeded random scenes, with the counts of exact fallbacks. Prints
// one line per scene and sample count; the best of several runs, since the machine is shared. Rates are
// per second of this process's CPU time, which other load on the machine disturbs less than wall time.
//
//   reference_bench [--runs N] [--only random|tiny|large] [--samples 1|16] [--area]
#include <rast/reference.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <numbers>
#include <random>
#include <string>

namespace {

using rast::Scene;
using rast::Triangle;
using rast::Vertex;
using rast::Viewport;

// n triangles, each with its vertices on a circle of radius drawn from [r0, r1) (a quarter of them from
// [big0, big1) when those are given) around a centre uniform in the viewport; every vertex its own z.
Scene random_scene(Viewport vp, std::size_t n, double r0, double r1, double big0, double big1, int samples) {
    std::mt19937_64 rng(1);
    std::uniform_real_distribution<double> unit(0, 1);
    Scene scene{vp, samples, {}};
    for (std::size_t k = 0; k < n; ++k) {
        const bool big = big1 > 0 && k % 4 == 0;
        const double r = big ? big0 + (big1 - big0) * unit(rng) : r0 + (r1 - r0) * unit(rng);
        const double cx = vp.width * unit(rng), cy = vp.height * unit(rng);
        Triangle t;
        for (Vertex& v : t.v) {
            const double angle = 2 * std::numbers::pi * unit(rng);
            v = Vertex{cx + r * std::cos(angle), cy + r * std::sin(angle), unit(rng)};
        }
        scene.triangles.push_back(t);
    }
    return scene;
}

double cpu_seconds_since(std::clock_t start) { return static_cast<double>(std::clock() - start) / CLOCKS_PER_SEC; }

void bench_render(const char* name, const Scene& scene, int runs) {
    double best = INFINITY;
    rast::reference::Stats stats;
    for (int r = 0; r < runs; ++r) {
        const std::clock_t start = std::clock();
        rast::reference::render(scene, &stats);
        best = std::min(best, cpu_seconds_since(start));
    }
    std::printf("%-8s samples %2d: %8.3f s cpu  %9.0f triangles/s  %7.2f M samples/s | triangles %llu degenerate %llu "
                "orientation %llu exact %llu | covered %llu depth tests %llu exact %llu nearest exact %llu\n",
                name, scene.samples, best, static_cast<double>(scene.triangles.size()) / best,
                static_cast<double>(stats.samples_covered) / best / 1e6,
                static_cast<unsigned long long>(stats.triangles),
                static_cast<unsigned long long>(stats.degenerate_triangles),
                static_cast<unsigned long long>(stats.orientation_tests),
                static_cast<unsigned long long>(stats.orientation_exact),
                static_cast<unsigned long long>(stats.samples_covered),
                static_cast<unsigned long long>(stats.depth_tests), static_cast<unsigned long long>(stats.depth_exact),
                static_cast<unsigned long long>(stats.depth_nearest_exact));
    std::fflush(stdout);
}

}  // namespace

int main(int argc, char** argv) {
    int runs = 3, only_samples = 0;
    std::string only;
    bool area = false;
    for (int k = 1; k < argc; ++k) {
        if (!std::strcmp(argv[k], "--runs") && k + 1 < argc)
            runs = std::max(1, std::atoi(argv[++k]));
        else if (!std::strcmp(argv[k], "--only") && k + 1 < argc)
            only = argv[++k];
        else if (!std::strcmp(argv[k], "--samples") && k + 1 < argc)
            only_samples = std::atoi(argv[++k]);
        else if (!std::strcmp(argv[k], "--area"))
            area = true;
        else {
            std::fprintf(stderr, "usage: %s [--runs N] [--only random|tiny|large] [--samples 1|16] [--area]\n",
                         argv[0]);
            return 2;
        }
    }
    const auto wanted = [&](const char* name, int samples) {
        return (only.empty() || only == name) && (only_samples == 0 || only_samples == samples);
    };
    for (const int samples : {1, 16}) {
        // The reference's own benchmark scene: radius 1-8, a quarter 8-48, 512x512.
        if (wanted("random", samples))
            bench_render("random", random_scene({512, 512}, 20000, 1, 8, 8, 48, samples), runs);
        // The fast path's two targets: 4 px triangles (radius 2) and large ones (256 px across).
        if (wanted("tiny", samples))
            bench_render("tiny", random_scene({1024, 1024}, 100000, 2, 2, 0, 0, samples), runs);
        if (wanted("large", samples))
            bench_render("large", random_scene({1024, 1024}, samples == 1 ? 200 : 20, 128, 128, 0, 0, samples), runs);
    }
    if (area) {
        const Scene scene = random_scene({512, 512}, 20000, 1, 8, 8, 48, 1);
        const std::clock_t start = std::clock();
        const auto coverage = rast::reference::coverage_area(scene);
        const double seconds = cpu_seconds_since(start);
        rast::reference::Rational total(0);
        for (const auto& a : coverage) total += a;
        std::printf("coverage_area random: %.3f s  %.0f triangles/s, total area %.6f\n", seconds,
                    static_cast<double>(scene.triangles.size()) / seconds, total.convert_to<double>());
    }
}
