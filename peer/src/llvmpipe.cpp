// The llvmpipe peer: an OSMesa context, the scene converted for GL, the id buffer read back.
#include <rast/llvmpipe.h>

#define GL_GLEXT_PROTOTYPES
#include <GL/gl.h>
#include <GL/glext.h>
#include <GL/osmesa.h>

#include <algorithm>
#include <bit>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace rast::peer {
namespace {

// One vertex as GL reads it from the vertex buffer: position, then the triangle's flat colour.
struct GlVertex {
    float x, y, z;
    std::uint8_t rgba[4];
};
static_assert(sizeof(GlVertex) == 16);

constexpr std::uint32_t kMaxTriangles = (1u << 24) - 1;  // id + 1 must fit in 24 bits of RGB

[[noreturn]] void fail(const std::string& what) { throw std::runtime_error("llvmpipe: " + what); }

void check_gl(const char* step) {
    if (const GLenum e = glGetError(); e != GL_NO_ERROR) {
        char code[16];
        std::snprintf(code, sizeof code, "0x%04X", e);
        fail(std::string(step) + " raised GL error " + code);
    }
}

// llvmpipe names its rasterizer threads "llvmpipe-<n>"; counting them is how we know which
// LP_NUM_THREADS the process's llvmpipe was really created with.
int count_llvmpipe_threads() {
    int n = 0;
    for (const auto& task : std::filesystem::directory_iterator("/proc/self/task")) {
        std::ifstream comm(task.path() / "comm");
        std::string name;
        std::getline(comm, name);
        n += name.starts_with("llvmpipe-");
    }
    return n;
}

// The rasterizer threads llvmpipe runs once they have started: each names itself as it starts, so on a
// loaded machine a count taken right after context creation can come up short. Waits up to a second for
// `expected` of them; more than that is final at once.
int settled_llvmpipe_threads(int expected) {
    int running = count_llvmpipe_threads();
    for (int wait = 0; running < expected && wait < 100; ++wait) {
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
        running = count_llvmpipe_threads();
    }
    return running;
}

// The monotone map of the scene's z onto NDC [-1/2, 1/2], written so that no step overflows for
// any finite doubles: q = (z/2 - mid) / half lies in [-1, 1].
struct DepthMap {
    double lo = 0, half = 0;  // the scene's smallest z, and half the width of its z range

    DepthMap() = default;
    explicit DepthMap(const Scene& scene) {
        double low = std::numeric_limits<double>::infinity(), high = -low;
        for (const Triangle& t : scene.triangles) {
            for (const Vertex& v : t.v) {
                low = std::min(low, v.z);
                high = std::max(high, v.z);
            }
        }
        if (low <= high) {
            lo = low;
            half = high / 2 - low / 2;  // halves: the width itself may overflow
        }
    }
    // [lo, hi] onto [-1/2, 1/2], monotone, lo and hi exactly to the ends: measured from lo, not from the
    // midpoint, whose rounding can be as large as a narrow range's width.
    double to_ndc(double z) const { return half > 0 ? (z / 2 - lo / 2) / half - 0.5 : 0.0; }
    double from_ndc(double ndc) const { return 2 * (lo / 2 + (ndc + 0.5) * half); }
};

void check_coordinate(double c, std::size_t id, const char* axis, double limit) {
    if (!(std::abs(c) <= limit)) {
        throw std::invalid_argument("llvmpipe: triangle " + std::to_string(id) + ": " + axis + " = " +
                                    std::to_string(c) + " is not finite or out of range");
    }
}

}  // namespace

struct Llvmpipe::State {
    OSMesaContext context = nullptr;
    int threads = 0;
    std::string renderer;
    GLuint vertex_buffer = 0;
    // The GL viewport: the square [-half, half]^2 with half a power of two, as large as GL allows.
    int half = 0;
    int max_size = 0;  // the largest framebuffer side: OSMesa's limit, and at most `half`
    std::vector<std::uint8_t> colour;  // the OSMesa colour buffer, RGBA8
    Viewport viewport{1, 1};
    GLsizei vertices = 0;
    DepthMap depth_map;

    ~State() {
        if (!context) return;
        if (vertex_buffer != 0 && bind()) glDeleteBuffers(1, &vertex_buffer);
        OSMesaDestroyContext(context);
    }

    bool bind() {
        return OSMesaMakeCurrent(context, colour.data(), GL_UNSIGNED_BYTE, viewport.width,
                                 viewport.height);
    }

    void make_current() {
        if (!bind()) {
            fail("OSMesaMakeCurrent failed for a " + std::to_string(viewport.width) + "x" +
                 std::to_string(viewport.height) + " buffer");
        }
    }
};

Llvmpipe::Llvmpipe(int threads) : state_(std::make_unique<State>()) {
    if (threads < 0) throw std::invalid_argument("llvmpipe: negative thread count");
    state_->threads = threads;
    setenv("GALLIUM_DRIVER", "llvmpipe", 1);
    setenv("LP_NUM_THREADS", std::to_string(threads).c_str(), 1);

    // RGBA8 colour, 24-bit depth, no stencil or accumulation buffer.
    state_->context = OSMesaCreateContextExt(OSMESA_RGBA, 24, 0, 0, nullptr);
    if (!state_->context) fail("OSMesaCreateContextExt failed");
    state_->colour.assign(4, 0);
    state_->make_current();

    const auto* renderer = reinterpret_cast<const char*>(glGetString(GL_RENDERER));
    state_->renderer = renderer ? renderer : "";
    if (!state_->renderer.starts_with("llvmpipe")) {
        fail("OSMesa renders with \"" + state_->renderer + "\", not llvmpipe");
    }
    if (const int running = settled_llvmpipe_threads(threads); running != threads) {
        fail("asked for " + std::to_string(threads) + " rasterizer threads, but llvmpipe runs " +
             std::to_string(running) +
             ": OSMesa creates llvmpipe once per process and reads LP_NUM_THREADS only then, "
             "so one process can use only one thread count");
    }
    GLint depth_bits = 0;
    glGetIntegerv(GL_DEPTH_BITS, &depth_bits);
    if (depth_bits != 24) {
        fail("expected a 24-bit depth buffer, got " + std::to_string(depth_bits) + " bits");
    }
    GLint osmesa_w = 0, osmesa_h = 0, dims[2] = {0, 0}, bounds[2] = {0, 0};
    OSMesaGetIntegerv(OSMESA_MAX_WIDTH, &osmesa_w);
    OSMesaGetIntegerv(OSMESA_MAX_HEIGHT, &osmesa_h);
    glGetIntegerv(GL_MAX_VIEWPORT_DIMS, dims);
    glGetIntegerv(GL_VIEWPORT_BOUNDS_RANGE, bounds);
    const GLint reach = std::min({dims[0] / 2, dims[1] / 2, -bounds[0], bounds[1]});
    if (reach < 1) fail("no usable viewport range");
    state_->half = static_cast<int>(std::bit_floor(static_cast<unsigned>(reach)));
    state_->max_size = std::min({osmesa_w, osmesa_h, state_->half});

    glDisable(GL_DITHER);
    glShadeModel(GL_FLAT);
    glEnable(GL_DEPTH_TEST);
    glDepthFunc(GL_LESS);
    glClearColor(0, 0, 0, 0);
    glClearDepth(1.0);
    glGenBuffers(1, &state_->vertex_buffer);
    glBindBuffer(GL_ARRAY_BUFFER, state_->vertex_buffer);
    glEnableClientState(GL_VERTEX_ARRAY);
    glEnableClientState(GL_COLOR_ARRAY);
    glVertexPointer(3, GL_FLOAT, sizeof(GlVertex), nullptr);
    glColorPointer(4, GL_UNSIGNED_BYTE, sizeof(GlVertex),
                   reinterpret_cast<const void*>(offsetof(GlVertex, rgba)));
    check_gl("context setup");
}

// State's destructor releases the context, also when the constructor throws.
Llvmpipe::~Llvmpipe() = default;

void Llvmpipe::load(const Scene& scene) {
    const Viewport vp = scene.viewport;
    if (!scene.lines.empty())
        throw std::invalid_argument("llvmpipe: draws triangles only, the scene has " +
                                    std::to_string(scene.lines.size()) + " lines");
    if (scene.samples != 1) {
        throw std::invalid_argument("llvmpipe: renders 1 sample per pixel, the scene asks for " +
                                    std::to_string(scene.samples));
    }
    if (vp.width <= 0 || vp.height <= 0) {
        throw std::invalid_argument("llvmpipe: viewport " + std::to_string(vp.width) + "x" +
                                    std::to_string(vp.height) + " is empty");
    }
    if (std::max(vp.width, vp.height) > state_->max_size) {
        throw std::invalid_argument("llvmpipe: viewport " + std::to_string(vp.width) + "x" +
                                    std::to_string(vp.height) + " exceeds llvmpipe's " +
                                    std::to_string(state_->max_size) + " pixels");
    }
    if (scene.triangles.size() > kMaxTriangles) {
        throw std::invalid_argument("llvmpipe: " + std::to_string(scene.triangles.size()) +
                                    " triangles, but ids are encoded as 24-bit colours (at most " +
                                    std::to_string(kMaxTriangles) + ")");
    }

    const DepthMap depth_map(scene);
    std::vector<GlVertex> vertices;
    vertices.reserve(3 * scene.triangles.size());
    for (std::size_t id = 0; id < scene.triangles.size(); ++id) {
        const auto code = static_cast<std::uint32_t>(id + 1);
        for (const Vertex& v : scene.triangles[id].v) {
            // GL takes float coordinates; the mirrored y must fit as well.
            constexpr double kFloatMax = std::numeric_limits<float>::max();
            check_coordinate(v.x, id, "x", kFloatMax);
            check_coordinate(v.y, id, "y", kFloatMax - vp.height);
            check_coordinate(v.z, id, "z", std::numeric_limits<double>::max());
            vertices.push_back({static_cast<float>(v.x), static_cast<float>(vp.height - v.y),
                                static_cast<float>(depth_map.to_ndc(v.z)),
                                {static_cast<std::uint8_t>(code), static_cast<std::uint8_t>(code >> 8),
                                 static_cast<std::uint8_t>(code >> 16), 255}});
        }
    }

    state_->viewport = vp;
    state_->depth_map = depth_map;
    state_->colour.assign(4 * static_cast<std::size_t>(vp.width) * static_cast<std::size_t>(vp.height), 0);
    state_->make_current();
    // Viewport and projection span the same power-of-two square centred on the origin: x and y are
    // only ever multiplied by powers of two, never offset. near = 1, far = -1 makes the projection's
    // z row the identity: the vertex z is already NDC.
    const int half = state_->half;
    glViewport(-half, -half, 2 * half, 2 * half);
    glMatrixMode(GL_PROJECTION);
    glLoadIdentity();
    glOrtho(-half, half, -half, half, 1, -1);
    glMatrixMode(GL_MODELVIEW);
    glLoadIdentity();
    glBufferData(GL_ARRAY_BUFFER, static_cast<GLsizeiptr>(vertices.size() * sizeof(GlVertex)),
                 vertices.data(), GL_STATIC_DRAW);
    state_->vertices = static_cast<GLsizei>(vertices.size());
    check_gl("uploading the scene");
}

void Llvmpipe::draw() {
    state_->make_current();
    glClear(GL_COLOR_BUFFER_BIT | GL_DEPTH_BUFFER_BIT);
    if (state_->vertices > 0) glDrawArrays(GL_TRIANGLES, 0, state_->vertices);
    glFinish();
    check_gl("drawing");
}

Framebuffer Llvmpipe::read_ids() const {
    const Viewport vp = state_->viewport;
    const auto pixels = static_cast<std::size_t>(vp.width) * static_cast<std::size_t>(vp.height);
    std::vector<std::uint8_t> rgba(4 * pixels);
    std::vector<float> depth(pixels);
    state_->make_current();
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glReadPixels(0, 0, vp.width, vp.height, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    glReadPixels(0, 0, vp.width, vp.height, GL_DEPTH_COMPONENT, GL_FLOAT, depth.data());
    check_gl("reading back");

    Framebuffer fb(vp, 1);
    for (int row = 0; row < vp.height; ++row) {
        const int j = vp.height - 1 - row;  // GL's row `row` (bottom first) is our mirrored row j
        for (int i = 0; i < vp.width; ++i) {
            const std::size_t p = static_cast<std::size_t>(row) * static_cast<std::size_t>(vp.width) +
                                  static_cast<std::size_t>(i);
            const std::uint32_t code = rgba[4 * p] | (rgba[4 * p + 1] << 8) | (rgba[4 * p + 2] << 16);
            if (code == 0) continue;
            fb.ids[fb.index(i, j)] = static_cast<std::int32_t>(code) - 1;
            fb.depth[fb.index(i, j)] = state_->depth_map.from_ndc(2.0 * depth[p] - 1.0);
        }
    }
    return fb;
}

int Llvmpipe::threads() const { return state_->threads; }

const std::string& Llvmpipe::renderer() const { return state_->renderer; }

Framebuffer render_llvmpipe(const Scene& scene, int threads) {
    Llvmpipe llvmpipe(threads);
    llvmpipe.load(scene);
    llvmpipe.draw();
    return llvmpipe.read_ids();
}

}  // namespace rast::peer
