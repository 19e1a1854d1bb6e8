#!/usr/bin/env python3
"""A two-cylinder engine as CAD tools export one: 67 parts, about 110k triangles, each part a mesh
of its own. Most parts are closed shells (block, pistons, rods, crankshaft, bolts, nuts, gears,
O-rings), some tessellated face by face as CAD exporters do (caps whose rims meet the sides in
T-junctions: closed to the eye, open by their edges); some are open (the cylinder liners, a fan shroud, a cover sheet); the bolts pass through
the block's top plate and the crank pins through the rods, as assembled parts do; the head sits
on the block face to face. Written as OBJ, one `o` per part.

    bench/results/engine_mesh.py OUT.obj [--scale S]   (S multiplies every part's resolution)
    /usr/bin/python3 bench/results/engine_mesh.py --truth [--samples N] [--seed K]

--truth estimates the volume of the engine as a user means it, independently of tetglow: a point
is inside where a closed part's own generalized winding number (Jacobson et al. 2013) exceeds 1/2
in size (every closed part solid, whatever the others do and however it is wound), or where the open parts' summed winding number
does (liners, shroud, cover, pipes, springs: what their winding number gives). The estimate is a
jittered grid (one uniform point in each cell) over the engine's bounds, in independent
replicates whose spread gives its standard error. It takes minutes (numpy), so its figure is kept
in TRUTH below; rerun the second command after changing the engine and paste its last line."""
import argparse
import math
import time

# The --truth estimate for engine() at scale 1 and its standard error: two runs of 40,000 points
# in 8 replicates, --seed 1 and 2, gave 62.789 +- 0.247 and 63.026 +- 0.179 (3 min of wall time
# each at load 20, about 40 s of CPU); their mean weighted by the inverse variances.
TRUTH = 62.95
TRUTH_ERROR = 0.15


class Parts:
    def __init__(self, scale=1.0):
        self.scale = scale
        self.parts = []  # (name, vertices, faces)

    def res(self, n, least=3):
        return max(least, int(round(n * self.scale)))

    def add(self, name, vs, fs):
        self.parts.append((name, vs, fs))

    def box(self, name, lo, hi, n):
        """A closed box, each face an n x n grid (outward)."""
        n = self.res(n, 1)
        vs, fs, index = [], [], {}

        def vertex(p):
            key = tuple(round(c, 12) for c in p)
            if key not in index:
                index[key] = len(vs)
                vs.append(p)
            return index[key]

        for axis in range(3):
            u, v = (axis + 1) % 3, (axis + 2) % 3
            for side in (0, 1):
                for i in range(n):
                    for j in range(n):
                        quad = []
                        for di, dj in ((0, 0), (1, 0), (1, 1), (0, 1)):
                            p = [0.0] * 3
                            p[axis] = hi[axis] if side else lo[axis]
                            p[u] = lo[u] + (hi[u] - lo[u]) * (i + di) / n
                            p[v] = lo[v] + (hi[v] - lo[v]) * (j + dj) / n
                            quad.append(vertex(tuple(p)))
                        if not side:
                            quad.reverse()
                        fs += [(quad[0], quad[1], quad[2]), (quad[0], quad[2], quad[3])]
        self.add(name, vs, fs)

    def cylinder(self, name, centre, axis, radius, length, sides, rings, caps=True, inward=False):
        """A cylinder along axis 0, 1 or 2 from centre (its base) up `length`; open without caps."""
        sides, rings = self.res(sides), self.res(rings, 1)
        u, v = (axis + 1) % 3, (axis + 2) % 3

        def at(h, a, r=radius):
            p = list(centre)
            p[axis] += h
            p[u] += r * math.cos(a)
            p[v] += r * math.sin(a)
            return tuple(p)

        vs = [at(length * i / rings, 2 * math.pi * k / sides) for i in range(rings + 1) for k in range(sides)]
        fs = []
        for i in range(rings):
            for k in range(sides):
                a, b = i * sides + k, i * sides + (k + 1) % sides
                fs += [(a, b, b + sides), (a, b + sides, a + sides)]
        if caps == "cad":
            # Each cap tessellated on its own, as CAD exporters do face by face: twice the side's
            # corners around, so half its rim vertices meet the side's edges in T-junctions.
            for h, up in ((0, False), (length, True)):
                c = len(vs)
                vs.append(at(h, 0, 0))
                vs += [at(h, math.pi * k / sides) for k in range(2 * sides)]
                for k in range(2 * sides):
                    a, b = c + 1 + k, c + 1 + (k + 1) % (2 * sides)
                    fs.append((c, a, b) if up else (c, b, a))
        elif caps:
            for h, ring, up in ((0, 0, False), (length, rings, True)):
                c = len(vs)
                vs.append(at(h, 0, 0))
                for k in range(sides):
                    a, b = ring * sides + k, ring * sides + (k + 1) % sides
                    fs.append((c, a, b) if up else (c, b, a))
        if inward:
            fs = [(a, c, b) for a, b, c in fs]
        self.add(name, vs, fs)

    def torus(self, name, centre, major, minor, sides, rings):
        """A ring about the z axis."""
        sides, rings = self.res(sides), self.res(rings)
        vs = []
        for i in range(rings):
            a = 2 * math.pi * i / rings
            for k in range(sides):
                b = 2 * math.pi * k / sides
                r = major + minor * math.cos(b)
                vs.append((centre[0] + r * math.cos(a), centre[1] + r * math.sin(a), centre[2] + minor * math.sin(b)))
        fs = []
        for i in range(rings):
            for k in range(sides):
                a, b = i * sides + k, i * sides + (k + 1) % sides
                c, d = ((i + 1) % rings) * sides + k, ((i + 1) % rings) * sides + (k + 1) % sides
                fs += [(a, c, d), (a, d, b)]
        self.add(name, vs, fs)

    def gear(self, name, centre, radius, teeth, width, rings):
        """A spur gear about the x axis: a closed prism over a toothed outline, capped by fans."""
        rings = self.res(rings, 1)
        outline = []
        per = 8
        for t in range(teeth):
            for s in range(per):
                a = 2 * math.pi * (t + s / per) / teeth
                outline.append((a, radius * (1.08 if s in (2, 3, 4, 5) else 0.96)))
        n = len(outline)
        vs = []
        for i in range(rings + 1):
            x = centre[0] + width * i / rings
            vs += [(x, centre[1] + r * math.cos(a), centre[2] + r * math.sin(a)) for a, r in outline]
        fs = []
        for i in range(rings):
            for k in range(n):
                a, b = i * n + k, i * n + (k + 1) % n
                fs += [(a, b + n, b), (a, a + n, b + n)]
        for x, ring, up in ((centre[0], 0, False), (centre[0] + width, rings, True)):
            c = len(vs)
            vs.append((x, centre[1], centre[2]))
            for k in range(n):
                a, b = ring * n + k, ring * n + (k + 1) % n
                fs.append((c, b, a) if up else (c, a, b))
        self.add(name, vs, fs)


def engine(scale=1.0):
    p = Parts(scale)
    # Block and head: the head sits on the block's top face (face to face, not crossing).
    p.box("block", (-3.0, -1.5, -2.0), (3.0, 1.5, 0.0), 40)
    p.box("head", (-3.0, -1.5, 0.0), (3.0, 1.5, 0.8), 24)
    for c, x in enumerate((-1.5, 1.5)):
        # Liners: open tubes standing in the block and head; pistons, pins and rods inside them.
        p.cylinder(f"liner{c}", (x, 0.0, -1.8), 2, 1.0, 2.4, 160, 24, caps=False)
        p.cylinder(f"piston{c}", (x, 0.0, -0.9), 2, 0.97, 0.8, 160, 8, caps="cad")
        p.cylinder(f"pin{c}", (x - 1.05, 0.0, -0.6), 0, 0.18, 2.1, 48, 4)
        p.box(f"rod{c}", (x - 0.15, -0.2, -3.2), (x + 0.15, 0.2, -0.4), 10)
        p.torus(f"ring{c}a", (x, 0.0, -0.3), 0.97, 0.03, 12, 160)
        p.torus(f"ring{c}b", (x, 0.0, -0.45), 0.97, 0.03, 12, 160)
        p.cylinder(f"valve{c}", (x + 0.4, 0.0, -0.2), 2, 0.2, 1.4, 48, 6)
        p.cylinder(f"spring{c}", (x + 0.4, 0.0, 0.6), 2, 0.3, 0.6, 48, 6, caps=False)
    # Crankshaft: journals along x through the webs, crank pins through the rods.
    p.cylinder("crank", (-4.0, 0.0, -3.0), 0, 0.3, 8.0, 96, 40, caps="cad")
    for c, x in enumerate((-1.5, 1.5)):
        p.box(f"web{c}a", (x - 0.5, -0.6, -3.6), (x - 0.3, 0.6, -2.4), 8)
        p.box(f"web{c}b", (x + 0.3, -0.6, -3.6), (x + 0.5, 0.6, -2.4), 8)
        p.cylinder(f"crankpin{c}", (x - 0.55, 0.0, -3.0), 0, 0.2, 1.1, 64, 6)
    p.gear("flywheel", (4.2, 0.0, -3.0), 1.6, 60, 0.3, 4)
    p.gear("timing", (-4.5, 0.0, -3.0), 0.8, 30, 0.2, 2)
    # Head bolts through the head into the block, each with a hex nut on the head.
    for b in range(10):
        x, y = -2.6 + 5.2 * (b % 5) / 4, (-1.2 if b < 5 else 1.2)
        p.cylinder(f"bolt{b}", (x, y, -0.6), 2, 0.08, 1.7, 32, 12, caps="cad")
        p.cylinder(f"nut{b}", (x, y, 0.8), 2, 0.16, 0.12, 6, 1)
    # Sump bolts along the bottom, crossing the block's floor.
    for b in range(12):
        x, y = -2.7 + 5.4 * (b % 6) / 5, (-1.3 if b < 6 else 1.3)
        p.cylinder(f"sumpbolt{b}", (x, y, -2.3), 2, 0.06, 0.6, 24, 4)
    # A fan shroud (open tube), a cover sheet (open half tube) and a closed air filter.
    p.cylinder("shroud", (-5.2, 0.0, -3.0), 0, 1.2, 0.6, 128, 6, caps=False)
    p.cylinder("cover", (-3.2, 0.0, 1.5), 0, 0.5, 6.4, 64, 30, caps=False)
    p.cylinder("filter", (0.0, 0.0, 1.2), 2, 0.6, 0.5, 96, 4, caps="cad")
    # Exhaust and intake pipes (open), a camshaft with two lobes crossing it.
    p.cylinder("exhaust", (-3.0, 1.5, 0.4), 0, 0.15, 6.0, 32, 20, caps=False)
    p.cylinder("intake", (-3.0, -1.5, 0.4), 0, 0.15, 6.0, 32, 20, caps=False)
    p.cylinder("camshaft", (-3.2, 0.0, -1.0), 0, 0.12, 6.4, 32, 20)
    p.box("lobe0", (-1.6, -0.2, -1.2), (-1.4, 0.2, -0.8), 4)
    p.box("lobe1", (1.4, -0.2, -1.2), (1.6, 0.2, -0.8), 4)
    return p.parts


def write_obj(path, parts):
    with open(path, "w") as f:
        base = 1
        for name, vs, fs in parts:
            f.write(f"o {name}\n")
            for v in vs:
                f.write("v %.9g %.9g %.9g\n" % v)
            for t in fs:
                f.write("f %d %d %d\n" % tuple(base + i for i in t))
            base += len(vs)


# The open parts (cylinders without caps); every other part is a solid, the cad-capped ones too,
# which are closed to the eye though their caps meet their sides in T-junctions.
OPEN = ("liner", "spring", "shroud", "cover", "exhaust", "intake")


def closed(name):
    return not name.startswith(OPEN)


def winding(np, tris, points):
    """The generalized winding number of triangles tris (T x 3 x 3) at points (P x 3): the signed
    solid angle of each triangle (Van Oosterom and Strackee 1983) summed, over 4 pi."""
    total = np.zeros(len(points))
    for lo in range(0, len(tris), 2048):
        t = tris[lo:lo + 2048]
        a, b, c = (t[None, :, k, :] - points[:, None, :] for k in range(3))
        la, lb, lc = (np.sqrt((v * v).sum(-1)) for v in (a, b, c))
        det = (a * np.cross(b, c)).sum(-1)
        den = la * lb * lc + (a * b).sum(-1) * lc + (b * c).sum(-1) * la + (c * a).sum(-1) * lb
        total += 2 * np.arctan2(det, den).sum(1)
    return total / (4 * math.pi)


def caps(vs, fs):
    """Fans closing every boundary loop of an open part, each wound against the part's rim: the
    part with them is closed, so its winding number is whole, and the part's own is that whole
    number minus the fans' winding number (which costs the fans' few triangles, not the part's)."""
    edges = {(t[k], t[(k + 1) % 3]) for t in fs for k in range(3)}
    following = {a: b for a, b in edges if (b, a) not in edges}
    fans = []
    while following:
        loop = [next(iter(following))]
        while following.get(loop[-1]) in following and following[loop[-1]] != loop[0]:
            loop.append(following.pop(loop[-1]))
        following.pop(loop[-1])
        c = [sum(vs[i][k] for i in loop) / len(loop) for k in range(3)]
        fans += [(c, vs[b], vs[a]) for a, b in zip(loop, loop[1:] + loop[:1])]
    return fans


def union_volume(parts, samples, seed, replicates=8):
    """The inside's volume (see --truth) and its standard error over the replicates."""
    import numpy as np
    rng = np.random.default_rng(seed)
    solids, sheets, fans = [], [], []
    for name, vs, fs in parts:
        tris = np.array(vs, dtype=float)[np.array(fs)]
        if closed(name):
            solids.append(tris)
        else:
            fans.append(np.array(caps(vs, fs), dtype=float))
            sheets.append(np.concatenate([tris, fans[-1]]))
    fans = np.concatenate(fans)
    corners = np.concatenate([t.reshape(-1, 3) for t in solids + sheets])
    lo, hi = corners.min(0) - 0.05, corners.max(0) + 0.05
    cells = np.maximum(1, np.round((hi - lo) / ((hi - lo).prod() / (samples / replicates)) ** (1 / 3))).astype(int)
    size = (hi - lo) / cells
    grid = np.stack(np.meshgrid(*(np.arange(n) for n in cells), indexing="ij"), -1).reshape(-1, 3)

    def whole(tris, points, skip):
        """The winding number of closed triangles tris, 0 outside their bounds and where skip."""
        w = np.zeros(len(points))
        where = np.flatnonzero(~skip & np.all((points >= tris.reshape(-1, 3).min(0)) &
                                              (points <= tris.reshape(-1, 3).max(0)), 1))
        for k in range(0, len(where), 512):
            w[where[k:k + 512]] = winding(np, tris, points[where[k:k + 512]])
        return w

    volumes = []
    for _ in range(replicates):
        points = lo + (grid + rng.random(grid.shape)) * size
        inside = np.zeros(len(points), bool)
        for tris in solids:
            inside |= np.abs(whole(tris, points, inside)) > 0.5  # the gears are wound inward
        rest = np.flatnonzero(~inside)
        open_winding = np.zeros(len(rest))
        for k in range(0, len(rest), 512):
            open_winding[k:k + 512] = -winding(np, fans, points[rest[k:k + 512]])
        for tris in sheets:
            open_winding += np.round(whole(tris, points[rest], np.zeros(len(rest), bool)))
        inside[rest] = open_winding > 0.5
        volumes.append(inside.mean() * (hi - lo).prod())
    v = np.array(volumes)
    return v.mean(), v.std(ddof=1) / math.sqrt(len(v))


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("out", nargs="?")
    ap.add_argument("--scale", type=float, default=1.0)
    ap.add_argument("--truth", action="store_true", help="estimate the engine's volume (minutes)")
    ap.add_argument("--samples", type=int, default=40000)
    ap.add_argument("--seed", type=int, default=1)
    a = ap.parse_args()
    if a.truth:
        start = time.time()
        parts = engine(a.scale)
        print(f"{sum(closed(n) for n, _, _ in parts)} solid parts, open: {[n for n, _, _ in parts if not closed(n)]}")
        v, e = union_volume(parts, a.samples, a.seed)
        print(f"{time.time() - start:.0f} s")
        print(f"TRUTH = {v:.4f}\nTRUTH_ERROR = {e:.4f}")
        return
    if not a.out:
        ap.error("the output file is required")
    parts = engine(a.scale)
    write_obj(a.out, parts)
    print(f"{a.out}: {len(parts)} parts, {sum(len(fs) for _, _, fs in parts)} triangles")


if __name__ == "__main__":
    main()
