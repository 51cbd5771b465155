#!/usr/bin/env python3
"""Checks layout_stats.py on hand-made two-triangle OBJ files whose answers are known by hand.

    /usr/bin/python3 bench/atlas_peers/check_layout_stats.py

Prints one line per case and 'N passed, N failed'; exits 1 on a failure.
The mesh is the unit square (0,0)-(1,0)-(1,1)-(0,1) in z = 0, split along the diagonal 1-3 into
the faces (1,2,3) and (1,3,4), both counter-clockwise seen from +z.
"""
import json
import math
import os
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
SQUARE = "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"

CASES = {
    # One chart filling [0,1]^2: occupancy 1, no seam, no gutter (one chart), no overlap, although
    # the two faces share the diagonal (the raster's fill rule must not count it twice).
    "one_chart": (SQUARE + "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nf 1/1 2/2 3/3\nf 1/1 3/3 4/4\n",
                  {"charts": 1, "occupancy": 1.0, "flipped_faces": 0, "seam_length": 0.0,
                   "boundary_length": 4.0, "gutter_texels": None, "overlap_fraction": 0.0,
                   "covered_texels": 2048 * 2048}),
    # Cut along the diagonal: face 1 at (0,0),(.5,0),(.5,.5) (area .125), face 2 at (.6,0),(1,.4),
    # (.6,.4) (area .08, CCW). Seam = the diagonal, sqrt 2 long. Gutter: x = .5 to x = .6, i.e.
    # 0.1 * 1024 = 102.4 texels.
    "two_charts": (SQUARE + "vt 0 0\nvt .5 0\nvt .5 .5\nvt .6 0\nvt 1 .4\nvt .6 .4\n"
                   "f 1/1 2/2 3/3\nf 1/4 3/5 4/6\n",
                   {"charts": 2, "occupancy": 0.205, "flipped_faces": 0, "seam_length": math.sqrt(2),
                    "gutter_texels": 102.4, "overlap_fraction": 0.0}),
    # Face 2 mirrored about u = .6: (.6,0),(.2,.4),(.6,.4) is clockwise (flipped, area .08) and
    # overlaps face 1 on an area of .035 (x in [.3,.5] between y = .6 - x and min(x, .4)), so
    # the overlap fraction is .035 / (.205 - .035) = .20588; gutter 0.
    "flipped": (SQUARE + "vt 0 0\nvt .5 0\nvt .5 .5\nvt .6 0\nvt .2 .4\nvt .6 .4\n"
                "f 1/1 2/2 3/3\nf 1/4 3/5 4/6\n",
                {"charts": 2, "flipped_faces": 1, "flipped_uv_area": 0.08, "gutter_texels": 0.0,
                 "overlap_fraction": (0.035 / 0.17, 2e-3)}),
    # Face 2 at (.1,0),(.6,.5),(.1,.5): overlaps face 1 on x in [.1,.5], y in [x - .1, x]: area .04;
    # fraction .04 / (.25 - .04) = .190476.
    "overlapping": (SQUARE + "vt 0 0\nvt .5 0\nvt .5 .5\nvt .1 0\nvt .6 .5\nvt .1 .5\n"
                    "f 1/1 2/2 3/3\nf 1/4 3/5 4/6\n",
                    {"charts": 2, "occupancy": 0.25, "gutter_texels": 0.0,
                     "overlap_fraction": (0.04 / 0.21, 2e-3)}),
    # Two separate triangles, the small one wholly inside the big one (no edges cross): the gutter
    # is 0 by the containment test; overlap .005 / .5 = .01; no shared edge, so no seam.
    "inside": ("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 0\nv 6 5 0\nv 5 6 0\n"
               "vt 0 0\nvt 1 0\nvt 0 1\nvt .1 .1\nvt .2 .1\nvt .1 .2\nf 1/1 2/2 3/3\nf 4/4 5/5 6/6\n",
               {"charts": 2, "occupancy": 0.505, "seam_length": 0.0, "gutter_texels": 0.0,
                "overlap_fraction": (0.01, 5e-4)}),
}


def close(got, want):
    if isinstance(want, tuple):
        want, tol = want
        return got is not None and abs(got - want) <= tol
    if want is None or isinstance(want, int):
        return got == want
    return got is not None and abs(got - want) <= 1e-9 * max(1.0, abs(want))


def main():
    passed = failed = 0
    with tempfile.TemporaryDirectory() as tmp:
        for name, (text, want) in CASES.items():
            path = os.path.join(tmp, name + ".obj")
            with open(path, "w") as f:
                f.write(text)
            out = subprocess.run([sys.executable, os.path.join(HERE, "layout_stats.py"), path],
                                 check=True, stdout=subprocess.PIPE, text=True).stdout
            got = json.loads(out)
            bad = {k: (got.get(k), v) for k, v in want.items() if not close(got.get(k), v)}
            if bad:
                failed += 1
                print("FAIL %s: %s" % (name, bad))
            else:
                passed += 1
                print("ok   %s" % name)
    print("%d passed, %d failed" % (passed, failed))
    sys.exit(1 if failed else 0)


if __name__ == "__main__":
    main()
