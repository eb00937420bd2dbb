// rast — the .tri scene format (docs/design.md): reading with errors that name file and line, and
// writing with hex-floats so that every double reads back bit-exact.
//
//   # key: value                 header metadata: leading comment lines of this form
//   viewport W H                 exactly once, anywhere in the file
//   samples N                    at most once; 1, 4, 8 or 16; default 1
//   tri x0 y0 z0  x1 y1 z1  x2 y2 z2
//   line x0 y0 z0  x1 y1 z1      a zero-width segment; ids count tri and line statements together
//
// '#' starts a comment anywhere. A line ends with '\n' or "\r\n" (the last may end the file instead); a
// carriage return anywhere else is an error, so every value read writes back. Numbers are read exactly as strtod reads them in the C locale, hex-float
// or decimal, and must be finite. Sizes are bounded by rast/scene_limits.h.
#pragma once

#include <filesystem>
#include <iosfwd>
#include <string>
#include <utility>
#include <vector>

#include "rast/parse_error.h"
#include "rast/scene.h"

namespace rast {

// The metadata the corpus keeps in a file's leading comments, in file order ("properties", "why",
// "seed", ...). A header line is '#', optional blanks, a key of letters, digits, '_', '-' or '.', a colon,
// then the value (surrounding blanks trimmed). The header ends at the first statement; other comment
// lines are not metadata.
using TriHeader = std::vector<std::pair<std::string, std::string>>;

struct TriDocument {
    Scene scene;
    TriHeader header;
};

// Throws ParseError naming `name`, the line and what is wrong.
TriDocument read_tri_document(std::istream& in, const std::string& name);
TriDocument read_tri_document_file(const std::filesystem::path& path);
Scene read_tri(std::istream& in, const std::string& name);
Scene read_tri_file(const std::filesystem::path& path);

// Writes the header as "# key: value" lines, then viewport, samples and one tri or line statement per
// triangle or line in id order, every coordinate as a C99 hex-float. Throws std::invalid_argument,
// writing nothing, for what would not read back the same: a non-finite coordinate, a size outside the
// limits, lines' ids that triangle_ids rejects, a header key that is not a key or a value with a line
// break or surrounding blanks.
void write_tri(std::ostream& out, const Scene& scene, const TriHeader& header = {});

// Any text as a header value write_tri takes: line breaks become blanks, surrounding blanks go, and an
// empty text becomes "-".
std::string header_value(std::string text);

// write_tri into a file, atomically (rast/atomic_file.h).
void write_tri_file(const std::filesystem::path& path, const Scene& scene, const TriHeader& header = {});

// A double as a C99 hex-float ("0x1.8p+3", "-0x0p+0"), exact and independent of the locale.
std::string hex_float(double value);

}  // namespace rast
