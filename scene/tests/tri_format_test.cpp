#include "rast/tri_format.h"

#include <gtest/gtest.h>

#include <bit>
#include <cfloat>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <cstdio>
#include <cstdlib>
#include <limits>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace rast {
namespace {

std::uint64_t bits(double d) { return std::bit_cast<std::uint64_t>(d); }

Scene parse(const std::string& text) {
    std::istringstream in(text);
    return read_tri(in, "s.tri");
}

// The what() of the ParseError that reading `text` throws, or "" if it reads.
std::string error_of(const std::string& text) {
    try {
        parse(text);
    } catch (const ParseError& e) {
        return e.what();
    }
    return "";
}

TEST(TriFormat, ReadsViewportSamplesAndTriangles) {
    const Scene s = parse("viewport 64 32\nsamples 4\ntri 0 0 0.5  8 0 0.5  0 8 0.25\n");
    EXPECT_EQ(s.viewport, (Viewport{64, 32}));
    EXPECT_EQ(s.samples, 4);
    ASSERT_EQ(s.triangles.size(), 1u);
    EXPECT_EQ(s.triangles[0], (Triangle{{{{0, 0, 0.5}, {8, 0, 0.5}, {0, 8, 0.25}}}}));
}

TEST(TriFormat, SamplesDefaultToOne) { EXPECT_EQ(parse("viewport 4 4\n").samples, 1); }

TEST(TriFormat, TrianglesMayPrecedeTheViewportAndKeepFileOrder) {
    const Scene s = parse("tri 1 0 0 0 1 0 0 0 1\nviewport 4 4\ntri 2 0 0 0 2 0 0 0 2\n");
    ASSERT_EQ(s.triangles.size(), 2u);
    EXPECT_EQ(s.triangles[0].v[0].x, 1.0);
    EXPECT_EQ(s.triangles[1].v[0].x, 2.0);
}

TEST(TriFormat, CommentsBlankLinesCrLfAndNoFinalNewline) {
    const Scene s = parse("# a scene\r\n\r\nviewport 4 4 # size\r\n   \t\n#tri 9 9 9 9 9 9 9 9 9\ntri 0 0 0 1 0 0 0 1 0#x");
    EXPECT_EQ(s.viewport, (Viewport{4, 4}));
    ASSERT_EQ(s.triangles.size(), 1u);
    EXPECT_EQ(s.triangles[0].v[2].y, 1.0);
}

TEST(TriFormat, NumbersReadAsStrtodDoes) {
    const Scene s = parse(
        "viewport 4 4\n"
        "tri 0.1 0x1.999999999999ap-4 0x1p60  1e-320 -0 0x1.fffffffffffffp+1023  1152921504606846976 -0x0p+0 1E2\n");
    const auto& v = s.triangles.at(0).v;
    EXPECT_EQ(bits(v[0].x), 0x3fb999999999999aULL);  // 0.1 rounded to nearest
    EXPECT_EQ(bits(v[0].y), 0x3fb999999999999aULL);
    EXPECT_EQ(v[0].z, std::ldexp(1.0, 60));
    EXPECT_EQ(bits(v[1].x), 0x7e8ULL);  // 1e-320 is the subnormal 2024 * 2^-1074
    EXPECT_EQ(bits(v[1].y), 0x8000000000000000ULL);
    EXPECT_EQ(v[1].z, DBL_MAX);
    EXPECT_EQ(v[2].x, std::ldexp(1.0, 60));
    EXPECT_EQ(bits(v[2].y), 0x8000000000000000ULL);
    EXPECT_EQ(v[2].z, 100.0);
}

// The reader takes a fast road (from_chars) and strtod's; whichever it takes, the value is strtod's. The
// hard spellings: exact midpoints between adjacent doubles (ties to even) and a hair either side of them,
// hundreds of digits long, and what only strtod reads ('+', hex floats, underflow to zero or a subnormal).
TEST(TriFormat, EverySpellingReadsAsStrtodReadsIt) {
    std::vector<std::string> spellings = {"+1.5", "+0x1p-3", "1e-400", "-1e-400", "2.4703282292062327e-324",
                                          "2.4703282292062328e-324", "2.2250738585072011e-308", ".5", "5.",
                                          "00000000000000000000000000001.25", "9007199254740993"};
    std::mt19937_64 random(20261126);
    char text[1400];
    for (int k = 0; k < 2000; ++k) {
        double d = std::bit_cast<double>(random());
        if (!std::isfinite(d)) continue;
        for (const char* format : {"%.17g", "%.16g", "%.25e", "%a"}) {
            std::snprintf(text, sizeof text, format, d);
            spellings.emplace_back(text);
        }
        // The midpoint to the next double up fits a long double's 64-bit significand exactly; "%.1100Le"
        // writes it in full (a double's exact expansion ends within 1100 digits), with trailing zeros.
        const long double mid = (static_cast<long double>(d) + std::nextafter(d, INFINITY)) / 2;
        if (!std::isfinite(static_cast<double>(std::nextafter(d, INFINITY)))) continue;
        std::snprintf(text, sizeof text, "%.1100Le", mid);
        std::string exact(text);
        spellings.push_back(exact);
        const std::size_t e = exact.find('e');
        const std::size_t last = exact.find_last_not_of('0', e - 1);
        ASSERT_LT(last + 1, e) << "the expansion of " << exact.substr(0, 40) << " has no trailing zero";
        exact[last + 1] = '1';  // a hair above the midpoint
        spellings.push_back(exact);
        exact[last] = static_cast<char>(exact[last] - 1);  // a hair below: ...d000 becomes ...(d-1)900
        exact[last + 1] = '9';
        spellings.push_back(exact);
    }
    std::string tri = "viewport 4 4\n";
    for (std::size_t k = 0; k < spellings.size(); ++k) tri += "tri " + spellings[k] + " 0 0 0 0 0 0 0 0\n";
    const Scene s = parse(tri);
    ASSERT_EQ(s.triangles.size(), spellings.size());
    for (std::size_t k = 0; k < spellings.size(); ++k)
        EXPECT_EQ(bits(s.triangles[k].v[0].x), bits(std::strtod(spellings[k].c_str(), nullptr)))
            << spellings[k].substr(0, 60) << " (" << spellings[k].size() << " characters)";
}

TEST(TriFormat, HeaderValueMakesAnyTextOneLine) {
    EXPECT_EQ(header_value("a\nb\r\nc"), "a b  c");
    EXPECT_EQ(header_value("  two words \t"), "two words");
    EXPECT_EQ(header_value(""), "-");
    EXPECT_EQ(header_value("\r\n "), "-");
    // What it gives, write_tri takes.
    std::ostringstream out;
    write_tri(out, Scene{{1, 1}, 1, {}}, {{"why", header_value(" a\nb ")}});
    EXPECT_EQ(out.str().substr(0, 11), "# why: a b\n");
}

TEST(TriFormat, HexFloatIsC99) {
    EXPECT_EQ(hex_float(12.0), "0x1.8p+3");
    EXPECT_EQ(hex_float(1.0), "0x1p+0");
    EXPECT_EQ(hex_float(-0.5), "-0x1p-1");
    EXPECT_EQ(hex_float(0.0), "0x0p+0");
    EXPECT_EQ(hex_float(-0.0), "-0x0p+0");
    EXPECT_EQ(hex_float(0.1), "0x1.999999999999ap-4");
}

TEST(TriFormat, WriteReadRoundTripIsBitExact) {
    const double values[] = {-0.0, std::numeric_limits<double>::denorm_min(), 1e-320, DBL_MIN, DBL_MAX, -DBL_MAX,
                             std::ldexp(1.0, 60), 0.1, 1.0 / 3.0, -7.25, std::nextafter(1.0, 2.0)};
    Scene scene;
    scene.viewport = {640, 480};
    scene.samples = 16;
    for (double a : values)
        for (double b : values) scene.triangles.push_back(Triangle{{{{a, b, a}, {b, a, b}, {a, a, b}}}});
    std::stringstream text;
    write_tri(text, scene, {{"why", "round trip"}});
    const TriDocument back = read_tri_document(text, "round.tri");
    EXPECT_EQ(back.scene.viewport, scene.viewport);
    EXPECT_EQ(back.scene.samples, 16);
    EXPECT_EQ(back.header, (TriHeader{{"why", "round trip"}}));
    ASSERT_EQ(back.scene.triangles.size(), scene.triangles.size());
    for (std::size_t t = 0; t < scene.triangles.size(); ++t)
        for (int k = 0; k < 3; ++k) {
            const Vertex& a = scene.triangles[t].v[k];
            const Vertex& b = back.scene.triangles[t].v[k];
            EXPECT_EQ(bits(a.x), bits(b.x));
            EXPECT_EQ(bits(a.y), bits(b.y));
            EXPECT_EQ(bits(a.z), bits(b.z));
        }
}

TEST(TriFormat, WritesTheDocumentedText) {
    Scene scene;
    scene.viewport = {8, 4};
    scene.triangles.push_back(Triangle{{{{0, 0, 0.5}, {12, 0, -0.0}, {0, 2, 1}}}});
    std::ostringstream out;
    write_tri(out, scene, {{"properties", "watertight order_independence"}, {"seed", ""}});
    EXPECT_EQ(out.str(),
              "# properties: watertight order_independence\n"
              "# seed:\n"
              "viewport 8 4\n"
              "samples 1\n"
              "tri  0x0p+0 0x0p+0 0x1p-1  0x1.8p+3 0x0p+0 -0x0p+0  0x0p+0 0x1p+1 0x1p+0\n");
}

TEST(TriFormat, WriteRefusesWhatWouldNotReadBack) {
    Scene scene;
    scene.viewport = {8, 4};
    std::ostringstream out;
    EXPECT_THROW(write_tri(out, scene, {{"bad key", "v"}}), std::invalid_argument);
    EXPECT_THROW(write_tri(out, scene, {{"why", "two\nlines"}}), std::invalid_argument);
    EXPECT_THROW(write_tri(out, scene, {{"why", " padded"}}), std::invalid_argument);
    EXPECT_THROW(write_tri(out, scene, {{"why", "a\rb"}}), std::invalid_argument);
    scene.triangles.push_back(Triangle{{{{0, 0, 0}, {1, 0, std::nan("")}, {0, 1, 0}}}});
    EXPECT_THROW(write_tri(out, scene), std::invalid_argument);
    scene.triangles.clear();
    scene.samples = 3;
    EXPECT_THROW(write_tri(out, scene), std::invalid_argument);
    EXPECT_EQ(out.str(), "");
}

// The fuzzer's finding: "a\rb" was read as a header value that write_tri then refused.
TEST(TriFormat, RejectsACarriageReturnInsideALine) {
    EXPECT_EQ(error_of("# why: a\rb\nviewport 1 1\n"),
              "s.tri:1: a carriage return inside the line (a line ends with '\\n' or '\\r\\n')");
    EXPECT_EQ(error_of("viewport 1 1\r\nviewport\r1 1\r\n"),
              "s.tri:2: a carriage return inside the line (a line ends with '\\n' or '\\r\\n')");
    EXPECT_EQ(error_of("viewport 1 1\r\r\n"),
              "s.tri:1: a carriage return inside the line (a line ends with '\\n' or '\\r\\n')");
}

TEST(TriFormat, CrLfHeaderWritesBackAndReadsBackEqual) {
    std::istringstream crlf("# why: a b\r\n#seed:\r\nviewport 2 1\r\ntri 0 0 0 2 0 0 0 1 0");
    const TriDocument doc = read_tri_document(crlf, "crlf.tri");
    EXPECT_EQ(doc.header, (TriHeader{{"why", "a b"}, {"seed", ""}}));
    std::stringstream text;
    write_tri(text, doc.scene, doc.header);
    const TriDocument back = read_tri_document(text, "back.tri");
    EXPECT_EQ(back.header, doc.header);
    EXPECT_EQ(back.scene.viewport, (Viewport{2, 1}));
    EXPECT_EQ(back.scene.triangles, doc.scene.triangles);
}

TEST(TriFormat, HeaderIsTheLeadingKeyValueComments) {
    std::istringstream in(
        "# properties: watertight order_independence\n"
        "# a free comment, not metadata\n"
        "\n"
        "#why:  shared edge: bit-identical  \n"
        "#  seed: 42\n"
        "viewport 4 4\n"
        "# late: not header\n");
    const TriDocument doc = read_tri_document(in, "h.tri");
    EXPECT_EQ(doc.header, (TriHeader{{"properties", "watertight order_independence"},
                                     {"why", "shared edge: bit-identical"},
                                     {"seed", "42"}}));
}

TEST(TriFormat, RejectsUnknownKeyword) {
    EXPECT_EQ(error_of("viewport 4 4\ntriangle 0 0 0 1 0 0 0 1 0\n"),
              "s.tri:2: unknown keyword 'triangle' (expected viewport, samples, tri or line)");
    EXPECT_EQ(error_of(std::string("viewport 4 4\n\x01\x00z\n", 16)),
              "s.tri:2: unknown keyword '\\x01\\x00z' (expected viewport, samples, tri or line)");
}

// Ids count tri and line statements together in file order; the writer gives every one its id back.
TEST(TriFormat, LinesShareIdsWithTrianglesInFileOrder) {
    const Scene s = parse("viewport 4 4\nline 0 0 1  4 4 2\ntri 0 0 0 1 0 0 0 1 0\nline 0.5 0x1p-1 0 1e0 3 -2\n"
                          "tri 1 1 1 2 1 1 1 2 1\n");
    ASSERT_EQ(s.lines.size(), 2u);
    EXPECT_EQ(s.lines[0], (Line{Segment{{{{0, 0, 1}, {4, 4, 2}}}}, 0}));
    EXPECT_EQ(s.lines[1], (Line{Segment{{{{0.5, 0.5, 0}, {1, 3, -2}}}}, 2}));
    EXPECT_EQ(triangle_ids(s), (std::vector<std::int32_t>{1, 3}));
    std::ostringstream out;
    write_tri(out, s);
    EXPECT_EQ(out.str(),
              "viewport 4 4\n"
              "samples 1\n"
              "line  0x0p+0 0x0p+0 0x1p+0  0x1p+2 0x1p+2 0x1p+1\n"
              "tri  0x0p+0 0x0p+0 0x0p+0  0x1p+0 0x0p+0 0x0p+0  0x0p+0 0x1p+0 0x0p+0\n"
              "line  0x1p-1 0x1p-1 0x0p+0  0x1p+0 0x1.8p+1 -0x1p+1\n"
              "tri  0x1p+0 0x1p+0 0x1p+0  0x1p+1 0x1p+0 0x1p+0  0x1p+0 0x1p+1 0x1p+0\n");
    std::istringstream back(out.str());
    const Scene again = read_tri(back, "back.tri");
    EXPECT_EQ(again.lines, s.lines);
    EXPECT_EQ(again.triangles, s.triangles);
}

TEST(TriFormat, TriangleIdsRejectLinesOutOfOrder) {
    Scene s;
    s.triangles.resize(2);
    s.lines = {{Segment{}, 1}, {Segment{}, 1}};
    EXPECT_THROW(triangle_ids(s), std::invalid_argument);
    s.lines = {{Segment{}, 0}, {Segment{}, 4}};
    EXPECT_THROW(triangle_ids(s), std::invalid_argument);
    s.lines = {{Segment{}, -1}};
    EXPECT_THROW(triangle_ids(s), std::invalid_argument);
    s.lines = {{Segment{}, 3}, {Segment{}, 1}};
    EXPECT_THROW(triangle_ids(s), std::invalid_argument);
    s.lines = {{Segment{}, 2}, {Segment{}, 3}};
    EXPECT_EQ(triangle_ids(s), (std::vector<std::int32_t>{0, 1}));
    s.viewport = {4, 4};
    s.lines = {{Segment{}, 3}, {Segment{}, 1}};
    std::ostringstream out;
    EXPECT_THROW(write_tri(out, s), std::invalid_argument);
    EXPECT_EQ(out.str(), "");
}

TEST(TriFormat, RejectsWrongArity) {
    EXPECT_EQ(error_of("viewport 4 4\nline 0 0 0 1 0\n"), "s.tri:2: 'line' expects 6 numbers (two ends x y z), got 5 values");
    EXPECT_EQ(error_of("viewport 4 4\nline 0 0 0 1 0 0 0\n"), "s.tri:2: 'line' expects 6 numbers (two ends x y z), got 7 values");
    EXPECT_EQ(error_of("viewport 4 4\ntri 0 0 0 1 0 0 0 1\n"),
              "s.tri:2: 'tri' expects 9 numbers (three vertices x y z), got 8 values");
    EXPECT_EQ(error_of("viewport 4 4\ntri 0 0 0 1 0 0 0 1 0 7\n"),
              "s.tri:2: 'tri' expects 9 numbers (three vertices x y z), got 10 values");
    EXPECT_EQ(error_of("viewport 4\n"), "s.tri:1: 'viewport' expects 2 integers (width height), got 1 value");
    EXPECT_EQ(error_of("viewport 4 4\nsamples\n"), "s.tri:2: 'samples' expects 1 integer (1, 4, 8 or 16), got 0 values");
}

TEST(TriFormat, RejectsBadNumbers) {
    EXPECT_EQ(error_of("viewport 4 4\ntri 0 0 0 1.5abc 0 0 0 1 0\n"),
              "s.tri:2: bad number '1.5abc': trailing characters 'abc'");
    EXPECT_EQ(error_of("viewport 4 4\ntri 0 0 0 x 0 0 0 1 0\n"), "s.tri:2: expected a number, got 'x'");
    EXPECT_EQ(error_of("viewport 4 4\ntri 0 0 0 1,5 0 0 0 1 0\n"),
              "s.tri:2: bad number '1,5': trailing characters ',5'");
    EXPECT_EQ(error_of("viewport 4.0 4\n"), "s.tri:1: expected an integer, got '4.0'");
    EXPECT_EQ(error_of("viewport 99999999999 4\n"), "s.tri:1: integer '99999999999' is out of range");
}

TEST(TriFormat, RejectsNanAndInfinity) {
    EXPECT_EQ(error_of("viewport 4 4\ntri 0 0 nan 1 0 0 0 1 0\n"), "s.tri:2: NaN is not allowed: 'nan'");
    EXPECT_EQ(error_of("viewport 4 4\ntri 0 0 0 1 0 0 0 1 -NAN(12)\n"), "s.tri:2: NaN is not allowed: '-NAN(12)'");
    EXPECT_EQ(error_of("viewport 4 4\ntri 0 0 0 inf 0 0 0 1 0\n"), "s.tri:2: infinity is not allowed: 'inf'");
    EXPECT_EQ(error_of("viewport 4 4\nline 0 0 0 1 -inf 0\n"), "s.tri:2: infinity is not allowed: '-inf'");
    EXPECT_EQ(error_of("viewport 4 4\ntri 0 0 0 1 -Infinity 0 0 1 0\n"),
              "s.tri:2: infinity is not allowed: '-Infinity'");
    EXPECT_EQ(error_of("viewport 4 4\ntri 0 0 0 1 0 0 0 1e999 0\n"), "s.tri:2: number '1e999' overflows to infinity");
    EXPECT_EQ(error_of("viewport 4 4\ntri 0 0 0 1 0 0 0 1 -0x1p1024\n"),
              "s.tri:2: number '-0x1p1024' overflows to infinity");
}

TEST(TriFormat, RejectsMissingOrRepeatedViewportAndSamples) {
    EXPECT_EQ(error_of("tri 0 0 0 1 0 0 0 1 0\n"), "s.tri: missing 'viewport W H' line");
    EXPECT_EQ(error_of(""), "s.tri: missing 'viewport W H' line");
    EXPECT_EQ(error_of("viewport 4 4\n\nviewport 4 4\n"), "s.tri:3: second 'viewport' line (the first is line 1)");
    EXPECT_EQ(error_of("samples 4\nviewport 4 4\nsamples 4\n"), "s.tri:3: second 'samples' line (the first is line 1)");
}

TEST(TriFormat, RejectsBadSizes) {
    EXPECT_EQ(error_of("viewport 0 4\n"), "s.tri:1: viewport width must be positive, got 0");
    EXPECT_EQ(error_of("viewport 4 -3\n"), "s.tri:1: viewport height must be positive, got -3");
    EXPECT_EQ(error_of("viewport 32769 4\n"), "s.tri:1: viewport width 32769 exceeds the limit 32768");
    EXPECT_EQ(error_of("viewport 4 4\nsamples 2\n"), "s.tri:2: samples must be 1, 4, 8 or 16, got 2");
    EXPECT_EQ(error_of("viewport 32768 32768\n"),
              "s.tri:1: viewport 32768x32768 with 1 samples per pixel has 1073741824 samples, above the limit 268435456");
    // 8192^2 fits with one sample; the samples line on line 3 makes it too large.
    EXPECT_EQ(error_of("viewport 8192 8192\n\nsamples 16\n"),
              "s.tri:3: viewport 8192x8192 with 16 samples per pixel has 1073741824 samples, above the limit 268435456");
    EXPECT_EQ(parse("viewport 16384 16384\n").viewport, (Viewport{16384, 16384}));
}

TEST(TriFormat, RejectsUnreadableFile) {
    const std::filesystem::path missing = std::filesystem::temp_directory_path() / "rast-no-such-dir" / "x.tri";
    try {
        read_tri_file(missing);
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(std::string(e.what()), missing.string() + ": cannot open: No such file or directory");
        EXPECT_EQ(e.line, 0);
    }
}

TEST(TriFormat, ParseErrorCarriesItsParts) {
    try {
        parse("viewport 4 4\ntri 0 0 0 1 0 0 0 1 zz\n");
        FAIL() << "no error";
    } catch (const ParseError& e) {
        EXPECT_EQ(e.file, "s.tri");
        EXPECT_EQ(e.line, 2);
        EXPECT_EQ(e.message, "expected a number, got 'zz'");
    }
}

}  // namespace
}  // namespace rast
