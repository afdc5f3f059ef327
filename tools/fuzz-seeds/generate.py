#!/usr/bin/env python3
"""Writes the committed seed corpora under fuzz/corpus/<target>/, so that
short fuzz runs (CI's 30 seconds) start from the hard regions: cases that
mix exponents from the subnormal range to 1e300 inside one case, exact
degeneracies (rays through vertices and along edges, tangent and
on-surface lines), and every fuzzer finding kept as a regression test.

Deterministic (a fixed seed), so re-running it rewrites the same files:

    python3 tools/fuzz-seeds/generate.py            # write
    python3 tools/fuzz-seeds/generate.py --check    # fail if not up to date

Byte layouts, as each target decodes its input with `arbitrary` (integers
little-endian, fields in order):
- ray_triangle: a mode byte (even: raw bit patterns), then 15 u64 bit
  patterns: origin, direction, v0, v1, v2.
- ray_quadrics: a mode byte (0 sphere, 1 cylinder, 5 quadric: bit 1 clear
  means raw bit patterns), then 16 u64 bit patterns.
- roots: 3 u64 bit patterns (a, b, c).
- ray_mesh: a mode byte (mode % 8 == 7: raw bit patterns; 3 + mode / 8 % 6
  vertices), a scale byte (i8: 2^(4k)), the vertices (3 i8 each, or 3 u64
  bit patterns), a triangle-count byte (1 + b % 8), 3 index bytes per
  triangle, an edit byte and a pick byte, the origin and direction (as the
  vertices), two i8 for the in-plane edit.
- mesh_closest: a mode byte (as ray_mesh's), an i16 `k` (scale `2^(k %
  1001)`), the vertices (as ray_mesh's), a triangle-count byte (1 + b % 8),
  3 index bytes per triangle, an edit byte (% 5: 0 the point halved, 1 at
  a vertex, 2 at an edge's midpoint, 4 raw bit patterns) and a pick byte,
  then the query point (as the vertices, or raw).
- mesh_side: a mode byte (mode % 16 == 15: raw bit patterns; bit 16: the
  cube, else the octahedron), a scale i16 (2^(k % 1001)), the 6 or 8
  vertices (3 i8 each, or 3 u64 bit patterns), an edit byte and a pick
  byte, the point (as the vertices), a nudge i8, the ray's target.
- predicates: a selector byte (predicate = selector % 5, mode = selector / 5
  % 4: 2 takes a case from the library's hard generators, 3 the same with
  edits that may plant a NaN or an infinity), an input-class byte (% 6:
  uniform, near-degenerate, degenerate, tiny, huge, mixed), a u64 generator
  seed, then an edit-count byte and the edits' bytes.
- implicit: a selector byte (predicate = selector % 7: orient3d, orient2d,
  projected orient2d, 3D axis, 2D axis, 3D along a line, 2D along a line;
  mode = selector / 7 % 3: 0 raw bit patterns, 1 the generators' cases of an
  input class, 2 the same with edits that may plant a NaN or an infinity);
  for mode 0 a pool-size byte and the pool's u64 patterns, otherwise an
  input-class byte, a u64 seed, an edit-count byte and 6 bytes per edit;
  then per argument a kind byte (3D: % 4, 0-1 explicit, 2 Lpi, 3 Tpi; 2D: %
  3, 0 explicit, else Ssi) and one index byte per input point, and an axis
  byte.
"""
import hashlib
import random
import struct
import sys
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2] / "fuzz" / "corpus"
PER_TARGET = 200


def bits(x: float) -> int:
    return struct.unpack("<Q", struct.pack("<d", x))[0]


def mixed(rng: random.Random) -> float:
    """A value from anywhere between the subnormals and 1e300, or an
    exact small one, with a random sign."""
    kind = rng.randrange(6)
    if kind == 0:
        v = struct.unpack("<d", struct.pack("<Q", rng.randrange(1, 1 << 52)))[0]  # subnormal
    elif kind == 1:
        v = float(rng.randrange(-8, 9))
    else:
        v = rng.uniform(1.0, 2.0) * 2.0 ** rng.randrange(-1074, 997)
    return -v if rng.random() < 0.5 else v


def vec(rng, f=None):
    f = f or mixed
    return [f(rng) for _ in range(3)]


def packed(mode: int, values) -> bytes:
    return bytes([mode]) + b"".join(struct.pack("<Q", v if isinstance(v, int) else bits(v)) for v in values)


def triangle_cases(rng):
    # The ray-triangle fuzzer's finding (testing::ray_triangle_finding), as reported.
    finding = [0x0000000000001348, 0x482B488EB0A3BF00, 0x0000000025000048,
               0x0000000012000000, 0x0000000000000000, 0x000000D100000000,
               0x060000000A000000, 0x25FD166CFFD81300, 0x4848486840C729FE,
               0x0000545454544848, 0x0000000000393B00, 0x00250600002F0000,
               0x5454545454000000, 0x5454545054545454, 0x4854000CCF0A5454]
    yield packed(0, finding)
    while True:
        o, d, v = vec(rng), vec(rng), [vec(rng) for _ in range(3)]
        edit = rng.randrange(5)
        k = rng.randrange(3)
        if edit == 0:  # aimed at a vertex
            d = [v[k][i] - o[i] for i in range(3)]
        elif edit == 1:  # along an edge
            o, d = v[k], [v[(k + 1) % 3][i] - v[k][i] for i in range(3)]
        elif edit == 2:  # two vertices merged
            v[(k + 1) % 3] = v[k]
        if any(abs(x) == float("inf") or x != x for x in d + o):
            continue
        yield packed(2 * rng.randrange(128), o + d + [x for p in v for x in p])


def quadric_cases(rng):
    # A fuzzer finding: partial products that underflow (mode 8: a quadric
    # from raw bit patterns).
    yield packed(8, [-1.7976922809928584e308, -1.7959812927113727e308, 6.392894393e-314,
                     5.014105033036297e-293, -2.3159452160917045e289, 9.75167e-319,
                     0.0, 0.0, 0.0, 0.0, 5.529727790709637e-10, 8.442919566090597e-15,
                     2.0970311356e-314, 0.0, 0.0, 0.0])
    while True:
        mode = rng.choice([0, 1, 5])
        values = [mixed(rng) for _ in range(16)]
        if mode == 0 and rng.random() < 0.5:
            # A ray through the centre: a sphere of radius |o - c|.
            values[6:9] = values[0:3]
        yield packed(mode, values)


def roots_cases(rng):
    while True:
        a, b, c = mixed(rng), mixed(rng), mixed(rng)
        if rng.random() < 0.3:
            c = b * b / (4 * a) if a != 0 and abs(b) < 1e150 else c  # near-double roots
        yield b"".join(struct.pack("<Q", bits(x)) for x in (a, b, c))


def predicate_cases(rng):
    # Every predicate and input class from the library's generators, plain
    # and with a few random edits (ulp nudges, shared coordinates, points on
    # the line or plane of others, scalings), sometimes with NaN edits.
    while True:
        pred, cls = rng.randrange(5), rng.randrange(6)
        mode = rng.choice([2, 2, 2, 3])
        edits = rng.randrange(4)
        tail = bytes(rng.randrange(256) for _ in range(12 * edits))
        yield bytes([pred + 5 * mode, cls]) + struct.pack("<Q", rng.getrandbits(64)) + bytes([edits]) + tail


def implicit_cases(rng):
    # Every predicate and mode; points drawn from the pool by index bytes,
    # which repeat often so that arguments share inputs.
    while True:
        pred, mode = rng.randrange(7), rng.choice([0, 1, 1, 1, 2])
        three = pred in (0, 2, 3, 5)
        out = bytes([pred + 7 * mode])
        if mode == 0:
            n = rng.randrange(8)
            dim = 3 if three else 2
            out += bytes([n]) + b"".join(struct.pack("<Q", bits(mixed(rng))) for _ in range((4 + n) * dim))
            pool = 4 + n
        else:
            edits = rng.randrange(4)
            out += bytes([rng.randrange(6)]) + struct.pack("<Q", rng.getrandbits(64)) + bytes([edits])
            out += bytes(rng.randrange(256) for _ in range(6 * edits))
            pool = 20 if three else 12
        index = lambda: rng.randrange(min(pool, 6)) if rng.random() < 0.5 else rng.randrange(256)
        for _ in range(4 if three else 3):
            kind = rng.randrange(4 if three else 3)
            count = {0: 1, 1: 1, 2: 5, 3: 9}[kind] if three else (1 if kind == 0 else 4)
            out += bytes([kind]) + bytes(index() for _ in range(count))
        out += bytes([rng.randrange(256)])
        yield out


def mesh_body(rng, nv, point):
    """The vertices (`point()` each) and the triangles of a small mesh: a
    triangle-count byte, then three index bytes per triangle, fans around
    vertex 0 (shared edges) or random index triples."""
    out = b""
    for _ in range(nv):
        out += point()
    nt = rng.randrange(8)
    out += bytes([nt])
    for j in range(nt + 1):
        if rng.random() < 0.7:
            out += bytes([0, 1 + j % (nv - 1), 1 + (j + 1) % (nv - 1)])
        else:
            out += bytes(rng.randrange(nv) for _ in range(3))
    return out


def mesh_cases(rng):
    # Small meshes: fans around vertex 0 (shared edges) or random index
    # triples, lattice coordinates (raw bit patterns one time in ten), and
    # each of the target's edits.
    while True:
        raw = rng.random() < 0.1
        nv_sel = rng.randrange(6)
        nv = 3 + nv_sel
        mode = (7 if raw else rng.randrange(7)) + 8 * nv_sel

        def point():
            if raw:
                return b"".join(struct.pack("<Q", bits(x)) for x in vec(rng))
            return struct.pack("<3b", *[rng.randrange(-20, 21) for _ in range(3)])

        out = bytes([mode]) + struct.pack("<b", rng.randrange(-8, 9))
        out += mesh_body(rng, nv, point)
        out += bytes([rng.randrange(6), rng.randrange(256)])
        out += point() + point()
        out += struct.pack("<2b", rng.randrange(-12, 13), rng.randrange(-12, 13))
        yield out


def closest_cases(rng):
    # Small meshes with shared vertices on a lattice (raw bit patterns one
    # time in ten) at scales 2^-1000..2^1000, degenerate triangles among
    # them, and each of the target's query edits.
    while True:
        raw = rng.random() < 0.1
        nv_sel = rng.randrange(6)
        nv = 3 + nv_sel
        mode = (7 if raw else rng.randrange(7)) + 8 * nv_sel
        edit = rng.randrange(5)

        def point(raw_point):
            if raw_point:
                return b"".join(struct.pack("<Q", bits(x)) for x in vec(rng))
            return struct.pack("<3b", *[rng.randrange(-6, 7) for _ in range(3)])

        out = bytes([mode]) + struct.pack("<h", rng.randrange(-1000, 1001))
        out += mesh_body(rng, nv, lambda: point(raw))
        out += bytes([edit, rng.randrange(256)])
        out += point(raw or edit == 4)
        yield out


def side_cases(rng):
    # The octahedron's or the cube's triangles over their own vertices
    # (radius or side up to 20 lattice steps, jittered one time in four;
    # raw bit patterns one time in ten), each point edit (a vertex, an edge's
    # midpoint, a face point, a lattice point), nudges of up to two units
    # of rounding, and rays aimed at a vertex, an edge's midpoint or a point.
    while True:
        raw = rng.random() < 0.1
        cube = rng.random() < 0.5
        mode = (15 if raw else rng.randrange(15)) + (16 if cube else 0)
        r = rng.randrange(1, 21)
        jitter = rng.random() < 0.25

        def lattice(p):
            if raw:
                return b"".join(struct.pack("<Q", bits(x)) for x in vec(rng))
            if jitter:
                p = [max(-128, min(127, c + rng.randrange(-2, 3))) for c in p]
            return struct.pack("<3b", *p)

        if cube:
            corners = [[(i >> k & 1) * r for k in range(3)] for i in range(8)]
        else:
            corners = []
            for k in range(3):
                for sign in (1, -1):
                    c = [0, 0, 0]
                    c[k] = sign * r
                    corners.append(c)
        out = bytes([mode]) + struct.pack("<h", rng.randrange(-1000, 1001))
        for c in corners:
            out += lattice(c)
        out += bytes([rng.randrange(256), rng.randrange(256)])
        out += lattice([rng.randrange(-24, 25) for _ in range(3)])
        out += struct.pack("<b", rng.randrange(-2, 3))
        out += lattice([rng.randrange(-24, 25) for _ in range(3)])
        yield out


def corpus(name, cases, seed):
    rng = random.Random(seed)
    out = {}
    for data in cases(rng):
        out[hashlib.sha1(data).hexdigest()] = data
        if len(out) == PER_TARGET:
            return name, out


def main() -> int:
    check = "--check" in sys.argv[1:]
    stale = 0
    for name, files in [corpus("ray_triangle", triangle_cases, 12),
                        corpus("ray_quadrics", quadric_cases, 13),
                        corpus("roots", roots_cases, 14),
                        corpus("predicates", predicate_cases, 15),
                        corpus("ray_mesh", mesh_cases, 16),
                        corpus("implicit", implicit_cases, 17),
                        corpus("mesh_side", side_cases, 18),
                        corpus("mesh_closest", closest_cases, 19)]:
        folder = ROOT / name
        have = {p.name: p.read_bytes() for p in folder.glob("*")} if folder.exists() else {}
        if check:
            if have != files:
                print(f"{folder}: not up to date")
                stale += 1
            continue
        folder.mkdir(parents=True, exist_ok=True)
        for p in folder.glob("*"):
            if p.name not in files:
                p.unlink()
        for k, data in files.items():
            (folder / k).write_bytes(data)
        print(f"{folder}: {len(files)} inputs")
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
