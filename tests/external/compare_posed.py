"""Compares where the studio puts an imported body's vertices as its clip
plays (posed_vertices) with where Blender put them in the scene it was
exported from (make_rigify_rigs.py), at the same frames: linear blend
skinning on both sides, every vertex within 1% of the body's size, and
Blender's pose moving some vertex farther than that.

usage: python3 compare_posed.py POSED_JSON RIG_JSON
POSED_JSON holds times "+S" (S seconds after the clip's first key, Blender
frame 1). Exits 1 if a vertex is farther, 2 on bad arguments.
"""

import json
import sys

TOLERANCE = 0.01


def to_blender(p):
    """Our y-up coordinates in Blender's z-up world: (x, y, z) -> (x, -z, y)."""
    return (p[0], -p[2], p[1])


def main(arguments):
    if len(arguments) != 2:
        print(__doc__)
        return 2
    with open(arguments[0]) as file:
        ours = json.load(file)
    with open(arguments[1]) as file:
        rig = json.load(file)
    theirs_rest = rig["rest"]
    lo = [min(p[k] for p in theirs_rest) for k in range(3)]
    hi = [max(p[k] for p in theirs_rest) for k in range(3)]
    size = sum((hi[k] - lo[k]) ** 2 for k in range(3)) ** 0.5
    # Vertices by position: a grid of cells a hundredth of the size.
    cell = size / 100

    def key(p):
        return tuple(int(p[k] // cell) for k in range(3))

    grid = {}
    for index, p in enumerate(theirs_rest):
        grid.setdefault(key(p), []).append(index)

    def nearest(p):
        best, where = None, None
        c = key(p)
        for dx in (-1, 0, 1):
            for dy in (-1, 0, 1):
                for dz in (-1, 0, 1):
                    for index in grid.get((c[0] + dx, c[1] + dy, c[2] + dz), []):
                        q = theirs_rest[index]
                        d = sum((p[k] - q[k]) ** 2 for k in range(3))
                        if best is None or d < best:
                            best, where = d, index
        return where, (best or 0.0) ** 0.5

    ours_rest = [to_blender(p) for p in ours["rest"]]
    matched = [nearest(p) for p in ours_rest]
    failures = 0
    worst_rest = max((d for index, d in matched if index is not None), default=float("inf"))
    unmatched = sum(1 for index, _ in matched if index is None)
    print(f"compare_posed: {len(ours_rest)} vertices, rest within {worst_rest / size:.2g} of the "
          f"size, {unmatched} unmatched")
    if unmatched or worst_rest > 1e-4 * size:
        failures += 1
    # The comparison says something only if Blender's pose moved the body.
    moved = 0.0
    for frame in rig["checked_frames"]:
        time = "+%g" % ((frame - rig["frames"][0]) / rig["fps"])
        posed = ours["posed"].get(time)
        if posed is None:
            print(f"  [FAIL] no posed vertices at {time}")
            failures += 1
            continue
        expected = rig["posed"][str(frame)]
        moved = max([moved] + [sum((p[k] - q[k]) ** 2 for k in range(3)) ** 0.5
                               for p, q in zip(theirs_rest, expected)])
        worst = 0.0
        for v, (index, _) in enumerate(matched):
            if index is None:
                continue
            p, q = to_blender(posed[v]), expected[index]
            worst = max(worst, sum((p[k] - q[k]) ** 2 for k in range(3)) ** 0.5)
        ok = worst <= TOLERANCE * size
        failures += 0 if ok else 1
        print(f"  [{'PASS' if ok else 'FAIL'}] frame {frame}: largest distance "
              f"{worst / size:.3g} of the size")
    ok = moved > TOLERANCE * size
    failures += 0 if ok else 1
    print(f"  [{'PASS' if ok else 'FAIL'}] Blender's pose moves a vertex {moved / size:.3g} of "
          f"the size (more than the tolerance)")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
