#!/usr/bin/env python3
"""Writes the fixed-grid family: for each fixed-point precision (1/16, 1/256, 1/65536 pixel), scenes whose
vertices sit on that grid, exactly halfway between two grid points (where rounding must go to even),
and one ulp either side of halfway. Run from corpus/fixed-grid; the output is committed, this records how."""
import math

PROPERTIES = ("watertight tie_rule winding_invariance translation_invariance order_independence "
              "fixed_matches_reference float_within_bound area_tiling")


def h(value):
    return float.hex(value) if value != int(value) or abs(value) > 2**53 else str(int(value))


def write(name, why, width, height, triangles):
    with open(name, "w") as out:
        out.write(f"# properties: {PROPERTIES}\n# why: {why}\n")
        out.write("# found-by: hand, corpus/fixed-grid/generate.py\n")
        out.write(f"viewport {width} {height}\n")
        for t in triangles:
            out.write("tri " + "  ".join(f"{h(x)} {h(y)} 0" for x, y in t) + "\n")


def fan(centre, rim):
    return [(centre, rim[k], rim[(k + 1) % len(rim)]) for k in range(len(rim))]


RIM = [(4.5, 0.5), (4.5, 4.5), (0.5, 4.5), (0.5, 0.5)]

for bits in (4, 8, 16):
    g = 2.0**-bits
    lo, hi = 0.5 - g, 5.5 + g
    write(f"on-grid-{bits}.tri",
          f"a square with corners one grid step (2^-{bits}) outside the centres (0.5, 0.5) and (5.5, 5.5), split on "
          f"the diagonal y = x through six centres: fixed{bits} keeps every vertex, coarser modes move them onto the "
          f"centres, and the diagonal must be owned once either way",
          6, 6, [((lo, lo), (hi, lo), (hi, hi)), ((lo, lo), (hi, hi), (lo, hi))])

    # 2.5 is an even multiple of every grid step, 2.5 +- g odd ones: a halfway point beside 2.5 rounds to 2.5.
    write(f"halfway-{bits}.tri",
          f"a closed fan whose centre (2.5 + 2^-{bits + 1}, 2.5 - 2^-{bits + 1}) is halfway between grid points of "
          f"fixed{bits} in x and in y: ties to even snap it exactly onto the sample (2.5, 2.5), which then is a vertex "
          f"of all four triangles and owned by one; rounding half up would leave it at (2.5 + 2^-{bits}, 2.5)",
          5, 5, fan((2.5 + g / 2, 2.5 - g / 2), RIM))

    up = math.nextafter(2.5 + g / 2, math.inf)
    down = math.nextafter(2.5 + g / 2, -math.inf)
    write(f"off-halfway-{bits}.tri",
          f"a closed fan whose centre is one ulp right of and one ulp below the halfway point 2.5 + 2^-{bits + 1}: "
          f"fixed{bits} must round x up to 2.5 + 2^-{bits} and y down to 2.5, a grid step from the sample "
          f"(2.5, 2.5), where ties-to-even would have put it on the sample",
          5, 5, fan((up, down), RIM))
