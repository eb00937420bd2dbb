// Renders two triangles that split a 4 x 4 square along its diagonal and checks who owns which pixel,
// with render() and with a Renderer.
#include <rast/fast.h>

#include <cstdio>

int main() {
    rast::Scene scene;
    scene.viewport = {4, 4};
    // Lower-right half (id 0) and upper-left half (id 1) of the square, sharing the diagonal.
    scene.triangles.push_back({{{{0, 0, 0.5}, {4, 0, 0.5}, {4, 4, 0.5}}}});
    scene.triangles.push_back({{{{0, 0, 0.5}, {4, 4, 0.5}, {0, 4, 0.5}}}});
    const rast::Framebuffer fb = rast::fast::render(scene);
    // Pixel centres below the diagonal y = x belong to 0, above to 1. The centres (i + 1/2, i + 1/2) lie on
    // it; traversed counter-clockwise it runs down in triangle 0 (a left edge, which owns them) and up
    // in triangle 1: they belong to 0.
    const struct {
        int i, j, id;
    } expected[] = {{3, 0, 0}, {0, 3, 1}, {2, 1, 0}, {1, 2, 1}, {0, 0, 0}, {3, 3, 0}};
    int failures = 0;
    for (const auto& e : expected) {
        if (fb.id(e.i, e.j) != e.id) {
            std::printf("pixel (%d, %d): id %d, expected %d\n", e.i, e.j, fb.id(e.i, e.j), e.id);
            ++failures;
        }
    }
    // The same frame again, from a Renderer that keeps its working memory.
    rast::fast::Renderer renderer;
    rast::Framebuffer again;
    renderer.render(scene, again, {.threads = 2});
    if (again.ids != fb.ids) {
        std::printf("a Renderer's frame differs from render()'s\n");
        ++failures;
    }
    std::printf("%s\n", failures == 0 ? "consumer: ok" : "consumer: FAILED");
    return failures == 0 ? 0 : 1;
}
