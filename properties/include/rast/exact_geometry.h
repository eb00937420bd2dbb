// rast properties — the exact geometry the properties judge by, written independently of the engines
// under test: the sign of an edge function, where a sample lies relative to a triangle, the tie rule of
// docs/design.md, areas, and the fixed-point snapping of fast.h.
#pragma once

#include <rast/contract.h>
#include <rast/scene.h>

#include <boost/multiprecision/gmp.hpp>

namespace rast::properties {

using Rational = boost::multiprecision::mpq_rational;

// The edge function E(p) = (b - a) x (p - a), exactly: positive when p is left of a->b.
Rational edge_function(const Vertex& a, const Vertex& b, double px, double py);

// The sign of edge_function (-1, 0 or +1), decided in double arithmetic where Shewchuk's error bound
// allows and exactly where it does not.
int edge_sign(const Vertex& a, const Vertex& b, double px, double py);

// The sign of twice the signed area: +1 counter-clockwise, -1 clockwise, 0 degenerate.
int orientation(const Triangle& t);

// The same point set traversed counter-clockwise (a clockwise triangle with two vertices swapped).
Triangle counter_clockwise(const Triangle& t);

// Where a point lies relative to the closed triangle. A degenerate triangle has no inside: every point
// is outside, whatever its distance.
enum class Location { outside, inside, on_edge, on_vertex };
Location locate(const Triangle& t, double x, double y);

// The tie rule: strictly inside, or on a left or top edge (and, on a vertex, on two such edges).
bool rule_covers(const Triangle& t, double x, double y);

// Twice the absolute area, exactly.
Rational twice_area(const Triangle& t);

// fast.h's fixed-point input: x and y rounded to the nearest multiple of 2^-bits, ties to even; z kept.
// With Rounding::floor, rounded down instead (a plugin's contract may say so); Rounding::any is not one
// snapping, and throws std::invalid_argument.
double snap(double value, int bits, Contract::Rounding rounding = Contract::Rounding::nearest_even);
Triangle snap(const Triangle& t, int bits, Contract::Rounding rounding = Contract::Rounding::nearest_even);
Segment snap(const Segment& s, int bits, Contract::Rounding rounding = Contract::Rounding::nearest_even);

}  // namespace rast::properties
