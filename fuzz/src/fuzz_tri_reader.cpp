// libFuzzer harness: the .tri reader. Bytes are a .tri document. Oracles:
//   - it is accepted, or rejected with ParseError naming the file (std::invalid_argument from a limit
//     check is allowed too); any other exception escapes and is a finding, as is a crash or UB;
//   - what is accepted holds only finite coordinates and a viewport and sample count within the limits;
//   - what is accepted, written with write_tri, reads back bit-exact: scene and header.
#include <rast/parse_error.h>
#include <rast/scene_limits.h>
#include <rast/tri_format.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <iostream>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {

const std::string kName = "fuzz.tri";

[[noreturn]] void finding(const std::string& what, const std::string& text) {
    std::cerr << "fuzz_tri_reader: " << what << "\n--- written document ---\n" << text << "---\n";
    std::abort();
}

bool same_bits(double a, double b) { return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b); }

bool same_vertex(const rast::Vertex& u, const rast::Vertex& v) {
    return same_bits(u.x, v.x) && same_bits(u.y, v.y) && same_bits(u.z, v.z);
}

bool same_scene(const rast::Scene& a, const rast::Scene& b) {
    if (a.viewport != b.viewport || a.samples != b.samples || a.triangles.size() != b.triangles.size() ||
        a.lines.size() != b.lines.size())
        return false;
    for (std::size_t t = 0; t < a.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k)
            if (!same_vertex(a.triangles[t].v[k], b.triangles[t].v[k])) return false;
    for (std::size_t l = 0; l < a.lines.size(); ++l) {
        if (a.lines[l].id != b.lines[l].id) return false;
        for (int k = 0; k < 2; ++k)
            if (!same_vertex(a.lines[l].segment.v[k], b.lines[l].segment.v[k])) return false;
    }
    return true;
}

void check_accepted(const rast::Scene& scene) {
    try {
        rast::check_scene_size(scene.viewport, scene.samples);
    } catch (const std::invalid_argument& e) {
        finding(std::string("the reader accepted a scene beyond the limits: ") + e.what(), "");
    }
    const auto finite = [](const rast::Vertex& v) { return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z); };
    for (const rast::Triangle& t : scene.triangles)
        for (const rast::Vertex& v : t.v)
            if (!finite(v)) finding("the reader accepted a non-finite coordinate", "");
    for (const rast::Line& l : scene.lines)
        for (const rast::Vertex& v : l.segment.v)
            if (!finite(v)) finding("the reader accepted a non-finite coordinate", "");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
    rast::TriDocument doc;
    try {
        doc = rast::read_tri_document(in, kName);
    } catch (const rast::ParseError& e) {
        if (e.file != kName || std::string(e.what()).rfind(kName + ":", 0) != 0)
            finding(std::string("an error that does not name the file: ") + e.what(), "");
        return 0;
    } catch (const std::invalid_argument&) {
        return 0;
    }
    check_accepted(doc.scene);

    std::ostringstream out;
    rast::write_tri(out, doc.scene, doc.header);
    std::istringstream again(out.str());
    rast::TriDocument back;
    try {
        back = rast::read_tri_document(again, kName);
    } catch (const rast::ParseError& e) {
        finding(std::string("the written document does not read back: ") + e.what(), out.str());
    }
    if (!same_scene(doc.scene, back.scene)) finding("the scene read back differs", out.str());
    if (doc.header != back.header) finding("the header read back differs", out.str());
    return 0;
}
