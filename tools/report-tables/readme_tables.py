#!/usr/bin/env python3
"""Regenerates the tables under "## Measured figures" in README.md from a
report's report.json (`cargo run --release --example report`), in the
README's own format, and prints the ratios its prose quotes (with the
report's "Targets", read from the report.md beside the json) so that a
person can update the prose by hand. Prose, headings, table headers and
the set and order of each table's rows are left as they are: only the
cells of the table bodies are rewritten.

    python3 tools/report-tables/readme_tables.py target/report/report.json README.md
    python3 tools/report-tables/readme_tables.py --check target/report/report.json README.md
    python3 tools/report-tables/readme_tables.py --ratios target/report/report.json

Without an option it rewrites README.md and prints the ratios; `--check`
prints a diff and exits 1 if the README's tables differ from the json's
(0 if not); `--ratios` only prints the ratios. `--report-md PATH` names the
report.md (default: beside the json). Standard library only.
"""

import argparse
import difflib
import json
import math
import re
import sys
from pathlib import Path

# --- number formats (as in the README's cells) ----------------------------


def _fixed(v, sig):
    """`v` to `sig` significant digits, as a fixed-point string."""
    if v == 0 or not math.isfinite(v):
        return "0" if v == 0 else str(v)
    mag = math.floor(math.log10(abs(v)))
    digits = max(sig - 1 - mag, 0)
    s = f"{v:.{digits}f}"
    # Rounding up may add a digit (9.996 -> 10.00): one decimal fewer.
    if digits > 0 and abs(float(s)) >= 10 ** (mag + 1):
        s = f"{v:.{digits - 1}f}"
    return s


def _strip(s):
    return s.rstrip("0").rstrip(".") if "." in s else s


def sig(v, n):
    """`n` significant digits, trailing zeros dropped: 4.1, 53, 0.081."""
    return _strip(_fixed(v, n))


def ns(v):
    """A time: 3 significant digits below 1,000 (3.03, 26.7, 53, 520),
    whole with thousands separators from 1,000 on (1,063; 19,308)."""
    if v is None:
        return "-"
    s = sig(v, 3)
    if float(s) >= 1000:
        return f"{round(v):,}"
    return s


def ratio(a, b, decimals=2):
    """`a / b` with fixed decimals and an `x`: 0.97x, 40.0x; `-` if either
    is missing."""
    if a is None or b is None or b == 0:
        return "-"
    return f"{a / b:.{decimals}f}x"


def ratio_sig(a, b, n=3):
    """`a / b` to `n` significant digits: 1.07x, 10.9x, 101x."""
    if a is None or b is None or b == 0:
        return "-"
    return _fixed(a / b, n) + "x"


def pct(errors, cases):
    return 100.0 * errors / cases if cases else float("nan")


def wrong_pct1(row):
    """`0`, or the wrong share with one decimal (17.8%, 100.0%); under
    0.1%, two significant digits (0.035%)."""
    if row["errors"] == 0:
        return "0"
    p = pct(row["errors"], row["cases"])
    return f"{p:.1f}%" if p >= 0.1 else sig(p, 2) + "%"


def wrong_pct2(row):
    """`0`, or the wrong share to two significant digits: 5.8%, 0.035%,
    50%."""
    if row["errors"] == 0:
        return "0"
    return sig(pct(row["errors"], row["cases"]), 2) + "%"


def wrong_count(row):
    """`0`; under 0.1% the count itself (2); else one decimal (16.2%)."""
    e = row["errors"]
    if e == 0:
        return "0"
    p = pct(e, row["cases"])
    return f"{e:,}" if p < 0.1 else f"{p:.1f}%"


def wrong_of(row):
    """`0`, or `1,024 of 19,564: 5.2%`."""
    e = row["errors"]
    if e == 0:
        return "0"
    p = pct(e, row["cases"])
    share = f"{p:.1f}%" if p >= 0.1 else sig(p, 2) + "%"
    return f"{e:,} of {row['cases']:,}: {share}"


SCI_FROM = 1e6


def ulps(v, commas):
    """Largest ulps: whole below 10^6 (2066, or 16,587 with `commas`),
    else two significant digits in e-notation (1.4e+08); `-` for null."""
    if v is None:
        return "-"
    if v < SCI_FROM:
        n = round(v)
        return f"{n:,}" if commas else str(n)
    return f"{v:.1e}"


# --- the report -----------------------------------------------------------


class Report:
    def __init__(self, rows):
        self.rows = rows
        self.by_key = {(r["family"], r["method"], r["inputs"]): r for r in rows}
        self.used = set()

    def row(self, family, method, inputs):
        r = self.by_key.get((family, method, inputs))
        if r is not None:
            self.used.add((family, inputs))
        return r

    def ns(self, family, method, inputs):
        r = self.row(family, method, inputs)
        return None if r is None else r["ns_per_op"]

    def has(self, family, inputs):
        return any(f == family and i == inputs for (f, _, i) in self.by_key)


def cell(r, fmt):
    """`ns (fmt(row))`, or `-` for a missing method."""
    return "-" if r is None else f"{ns(r['ns_per_op'])} ({fmt(r)})"


# --- the tables: header line, key from a body line, cells from the key ----

PREDICATE_FAMILIES = ["orient2d", "orient3d", "incircle", "insphere", "plane_side"]
QUADRIC_FAMILIES = ["ray_sphere", "ray_cylinder", "ray_cone", "ray_quadric"]
TRIANGLE_METHODS = [
    "exactray-mt",
    "exactray-watertight",
    "exactray-exact",
    "exactray-exact-prepared",
    "exactray-exact-bounded",
    "naive",
    "parry3d",
]


def predicates(rep, cells):
    family, inputs = cells[0], cells[1]
    g = lambda m: rep.row(family, m, inputs)
    t = lambda m: rep.ns(family, m, inputs)
    batch = g("exactray-batch")
    if batch is None:
        batch_cell = "-"
    elif t("naive") is None:
        batch_cell = ns(batch["ns_per_op"])
    else:
        batch_cell = f"{ns(batch['ns_per_op'])} ({ratio(t('exactray-batch'), t('naive'))} naive)"
    keys = [(family, inputs)]
    return keys, [
        family,
        inputs,
        ns(t("exactray")),
        batch_cell,
        cell(g("naive"), wrong_pct1),
        cell(g("robust"), wrong_pct1),
        cell(g("geometry-predicates"), wrong_pct1),
        ratio(t("exactray"), t("naive")),
        ratio(t("exactray"), t("robust")),
    ]


def nearest(rep, cells):
    inputs = cells[0]
    g = lambda m: rep.row("nearest", m, inputs)
    t = lambda m: rep.ns("nearest", m, inputs)
    return [("nearest", inputs)], [
        inputs,
        ns(t("exactray")),
        ns(t("exactray-batch")),
        cell(g("kiddo"), wrong_pct1),
        cell(g("rstar"), wrong_pct1),
        ns(t("brute-force")),
        ratio(t("exactray"), t("kiddo")),
        ratio(t("exactray"), t("rstar")),
    ]


def nearest_build(rep, cells):
    inputs = cells[0]
    t = lambda m: rep.ns("nearest_build", m, inputs)
    return [("nearest_build", inputs)], [
        inputs,
        ns(t("exactray")),
        ns(t("kiddo")),
        ns(t("rstar")),
        ratio(t("exactray"), t("kiddo")),
    ]


def quadrics(rep, cells):
    family, inputs = cells[0], cells[1]
    q = lambda r: f"{wrong_pct2(r)}; {ulps(r['max_ulps'], commas=False)}"
    g = lambda m: rep.row(family, m, inputs)
    t = lambda m: rep.ns(family, m, inputs)
    bound = g("exactray")
    return [(family, inputs)], [
        family,
        inputs,
        cell(g("exactray"), q),
        "-" if bound is None else ulps(bound.get("max_bound_ulps"), commas=False),
        cell(g("exactray-precise"), q),
        cell(g("naive"), q),
        cell(g("naive-stable"), q),
        cell(g("parry3d"), q),
        ratio(t("exactray"), t("naive-stable"), decimals=2),
        ratio(t("exactray"), t("parry3d"), decimals=2),
    ]


def triangle(rep, cells):
    label = cells[0]
    inputs = label.split(" (")[0]
    fmt = wrong_of if inputs == "shared-edges" else wrong_count
    return [("ray_triangle", inputs)], [label] + [
        cell(rep.row("ray_triangle", m, inputs), fmt) for m in TRIANGLE_METHODS
    ]


def triangle_ulps(rep, cells):
    inputs = cells[0]
    out = [inputs]
    for m in TRIANGLE_METHODS:
        r = rep.row("ray_triangle", m, inputs)
        out.append("-" if r is None else ulps(r["max_ulps"], commas=True))
    return [("ray_triangle", inputs)], out


def raster(rep, cells):
    n = int(cells[0].replace(",", ""))
    inputs = f"pixels:{n}"
    t = lambda m: rep.ns("raster_triangle", m, inputs)
    r, rays = t("exactray"), t("exactray-rays")
    return [("raster_triangle", inputs)], [
        f"{n:,}",
        ns(r),
        ns(rays),
        ns(t("naive")),
        ratio_sig(rays, r),
        "-" if r is None else sig(r / n, 2),
        "-" if rays is None else sig(rays / n, 3),
    ]


def render_frame(rep, cells):
    inputs = cells[0]
    size, n = inputs.split(":")
    w, h = (int(x) for x in size.split("x"))
    t = lambda m: rep.ns("render", m, inputs)
    r, rays = t("exactray-raster"), t("exactray-rays")
    row = rep.row("render", "exactray-raster", inputs)
    ms = lambda v: "-" if v is None else sig(v / 1e6, 3)
    return [("render", inputs)], [
        inputs,
        ms(r),
        ms(rays),
        ratio(rays, r),
        "-" if r is None else sig(r / int(n), 3),
        "-" if rays is None else sig(rays / (w * h), 3),
        "-" if row is None else f"{row['errors']:,}",
    ]


SCENE_CLOSEST_METHODS = ["exactray", "exactray-exact", "exactray-ploc", "obvhs", "obvhs-bvh2", "parry3d", "embree"]
SCENE_ANY_METHODS = ["exactray", "exactray-closest", "exactray-exact", "obvhs", "obvhs-bvh2", "parry3d", "embree"]


def scene_closest(rep, cells):
    inputs = cells[0]
    g = lambda m: rep.row("closest_hit", m, inputs)
    t = lambda m: rep.ns("closest_hit", m, inputs)
    return [("closest_hit", inputs)], [inputs] + [
        cell(g(m), wrong_pct1) for m in SCENE_CLOSEST_METHODS
    ] + [
        "-" if g("exactray-batch") is None else ns(t("exactray-batch")),
        "-" if g("exactray-rayon") is None else ns(t("exactray-rayon")),
        ratio(t("exactray"), t("obvhs")),
        ratio(t("exactray"), t("parry3d")),
    ]


def scene_any(rep, cells):
    inputs = cells[0]
    g = lambda m: rep.row("any_hit", m, inputs)
    t = lambda m: rep.ns("any_hit", m, inputs)
    return [("any_hit", inputs)], [inputs] + [cell(g(m), wrong_pct1) for m in SCENE_ANY_METHODS] + [
        ratio(t("exactray"), t("exactray-closest")),
    ]


def scene_spawn(rep, cells):
    inputs = cells[0]
    g = lambda m: rep.row("spawn", m, inputs)
    e = g("exactray")
    return [("spawn", inputs)], [
        inputs,
        "-" if e is None else f"{e['cases']:,}",
    ] + [
        "-" if g(m) is None else f"{g(m)['errors']:,}" for m in ["exactray", "epsilon-1e-4", "epsilon-1e-8"]
    ] + [
        "-" if g(m) is None else ns(g(m)["ns_per_op"]) for m in ["exactray", "epsilon-1e-8"]
    ]


DELAUNAY_METHODS = ["exactray", "robust", "spade"]


def delaunay(rep, cells):
    inputs = cells[0]
    g = lambda m: rep.row("delaunay", m, inputs)
    t = lambda m: rep.ns("delaunay", m, inputs)
    # No ratio to a peer that failed on every point: its time is the time
    # it took to give up.
    failed = lambda m: g(m) is None or g(m)["errors"] >= g(m)["cases"]
    against = lambda m: "-" if failed(m) else ratio(t("exactray"), t(m))
    return [("delaunay", inputs)], [inputs] + [cell(g(m), wrong_pct1) for m in DELAUNAY_METHODS] + [
        against("robust"),
        against("spade"),
    ]


TABLES = [
    (
        "Predicates",
        "| family | inputs | exactray ns | exactray-batch ns | naive ns (wrong) | robust ns (wrong) "
        "| geometry-predicates ns (wrong) | exactray / naive | exactray / robust |",
        predicates,
        PREDICATE_FAMILIES,
    ),
    (
        "Nearest points: queries",
        "| inputs | exactray ns | exactray-batch ns | kiddo ns (wrong) | rstar ns (wrong) | brute force ns "
        "| exactray / kiddo | exactray / rstar |",
        nearest,
        ["nearest"],
    ),
    (
        "Nearest points: build",
        "| inputs | exactray ns/point | kiddo ns/point | rstar ns/point | exactray / kiddo |",
        nearest_build,
        ["nearest_build"],
    ),
    (
        "Ray casts against quadrics",
        "| family | inputs | exactray | exactray bound ulps | exactray-precise | naive | naive-stable | parry3d "
        "| exactray / naive-stable | exactray / parry3d |",
        quadrics,
        QUADRIC_FAMILIES,
    ),
    (
        "Ray–triangle: time and wrong",
        "| inputs | MT ns (wrong) | watertight ns (wrong) | exact ns (wrong) | exact prepared ns (wrong) "
        "| exact bounded ns (wrong) | naive ns (wrong) | parry3d ns (wrong) |",
        triangle,
        ["ray_triangle"],
    ),
    (
        "Ray–triangle: largest ulps",
        "| inputs | MT | watertight | exact | exact prepared | exact bounded | naive | parry3d |",
        triangle_ulps,
        ["ray_triangle"],
    ),
    (
        "Scenes: closest hit",
        "| inputs | exactray ns (wrong) | exactray-exact ns (wrong) | exactray-ploc ns (wrong) | obvhs ns (wrong) "
        "| obvhs-bvh2 ns (wrong) | parry3d ns (wrong) | embree ns (wrong) | exactray-batch ns | exactray-rayon ns "
        "| exactray / obvhs | exactray / parry3d |",
        scene_closest,
        ["closest_hit"],
    ),
    (
        "Scenes: shadow rays",
        "| inputs | exactray ns (wrong) | exactray-closest ns (wrong) | exactray-exact ns (wrong) | obvhs ns (wrong) "
        "| obvhs-bvh2 ns (wrong) | parry3d ns (wrong) | embree ns (wrong) | exactray / exactray-closest |",
        scene_any,
        ["any_hit"],
    ),
    (
        "Scenes: spawned rays",
        "| situation | secondary rays | exactray self-hits | epsilon-1e-4 self-hits | epsilon-1e-8 self-hits "
        "| exactray ns | epsilon-1e-8 ns |",
        scene_spawn,
        ["spawn"],
    ),
    (
        "Q2 rasterizing",
        "| pixels | rasterize ns | one ray per pixel ns | textbook raster ns | rays / rasterize "
        "| rasterize ns per pixel | rays ns per pixel |",
        raster,
        ["raster_triangle"],
    ),
    (
        "Q2 at frame scale",
        "| inputs | Z-buffer ms | rays ms | rays / Z-buffer | Z-buffer ns per triangle | rays ns per pixel "
        "| pixels differing |",
        render_frame,
        ["render"],
    ),
    (
        "Delaunay triangulation",
        "| inputs | exactray ns/point (wrong) | robust ns/point (wrong) | spade ns/point (wrong) "
        "| exactray / robust | exactray / spade |",
        delaunay,
        ["delaunay"],
    ),
]


def split_cells(line):
    return [c.strip() for c in line.strip().strip("|").split("|")]


def join_cells(cells):
    return "| " + " | ".join(cells) + " |"


def section_bounds(lines):
    start = next((i for i, l in enumerate(lines) if l.rstrip("\n") == "## Measured figures"), None)
    if start is None:
        sys.exit("README has no '## Measured figures' section")
    end = next((i for i in range(start + 1, len(lines)) if lines[i].startswith("## ")), len(lines))
    return start, end


# Tables of the section that other programs' output fills, left as they
# are: the CGAL comparison (tools/cgal-timing prints its rows).
FOREIGN = {
    "| family | inputs | exactray ns | CGAL ns | exactray / CGAL | streamed: exactray ns | CGAL ns | exactray / CGAL |",
}


def regenerate(readme, rep, warn):
    """The README's text with every table of the section rewritten, and the
    tables' new rows by name (for the ratios)."""
    lines = readme.splitlines(keepends=True)
    start, end = section_bounds(lines)
    specs = {h: (name, fn) for name, h, fn, _ in TABLES}
    found = {}
    i = start
    while i < end:
        line = lines[i].rstrip("\n")
        if not line.startswith("|"):
            i += 1
            continue
        if line in FOREIGN:
            while i < end and lines[i].startswith("|"):
                i += 1
            continue
        if line not in specs:
            sys.exit(f"README line {i + 1}: a table this script does not know: {line}")
        name, fn = specs[line]
        if name in found:
            sys.exit(f"README line {i + 1}: table '{name}' appears twice")
        found[name] = []
        i += 2  # the header and its |---| line stay as they are
        while i < end and lines[i].startswith("|"):
            old = split_cells(lines[i])
            keys, new = fn(rep, old)
            for family, inputs in keys:
                if not rep.has(family, inputs):
                    warn(f"{name}: report.json has no rows for {family}/{inputs}: its cells are '-'")
            nl = "\n" if lines[i].endswith("\n") else ""
            lines[i] = join_cells(new) + nl
            found[name].append(new)
            i += 1
    for name, _, _, _ in TABLES:
        if name not in found:
            warn(f"README has no table '{name}'")
    # Rows of the tables' families that no table shows.
    shown = rep.used
    families = {f for _, _, _, fs in TABLES for f in fs}
    extra = sorted({(r["family"], r["inputs"]) for r in rep.rows if r["family"] in families} - shown)
    for family, inputs in extra:
        warn(f"report.json has {family}/{inputs}, which no README table shows (rows are kept as the README lists them)")
    return "".join(lines), found


# --- report.md: run header, targets, notes --------------------------------


def md_tables(text):
    """Every markdown table in `text` as (the paragraph before it, header
    cells, body rows)."""
    out = []
    lines = text.splitlines()
    i = 0
    while i < len(lines):
        if lines[i].startswith("|") and i + 1 < len(lines) and re.match(r"^\|[\s|:-]+\|$", lines[i + 1]):
            j = i - 1
            while j >= 0 and not lines[j].strip():
                j -= 1
            before = lines[j] if j >= 0 else ""
            header = split_cells(lines[i])
            body = []
            i += 2
            while i < len(lines) and lines[i].startswith("|"):
                body.append(split_cells(lines[i]))
                i += 1
            out.append((before, header, body))
        else:
            i += 1
    return out


def group_of(family):
    if family in PREDICATE_FAMILIES:
        return "predicates"
    if family.startswith("nearest"):
        return "nearest"
    if family in QUADRIC_FAMILIES:
        return "quadrics"
    return family


# --- the ratios the prose quotes ------------------------------------------


def print_ratios(rep, found, md, json_path, out):
    p = lambda s="": print(s, file=out)
    p(f"Figures the prose under '## Measured figures' quotes, from {json_path}:")
    if md is not None:
        m = re.search(r"^(Quick|Full) run: .*?timed loops over \d+ cases", md, re.M | re.S)
        if m:
            p("  " + " ".join(m.group(0).split()))
        if m and m.group(1) == "Quick":
            p("  NOTE: a quick run: its figures are not a full run's; do not commit them to README.md.")

    def exact_total(families, method="exactray"):
        rs = [r for r in rep.rows if r["family"] in families and r["method"] == method]
        return sum(r["errors"] for r in rs), sum(r["cases"] for r in rs)

    p()
    p("exactray wrong answers (intro):")
    for label, fams, method in [
        ("predicates", PREDICATE_FAMILIES, "exactray"),
        ("nearest (checked queries)", ["nearest"], "exactray"),
        ("ray_sphere, ray_cylinder, ray_quadric", ["ray_sphere", "ray_cylinder", "ray_quadric"], "exactray"),
        ("ray_cone", ["ray_cone"], "exactray"),
        ("ray_triangle exactray-exact", ["ray_triangle"], "exactray-exact"),
    ]:
        e, c = exact_total(fams, method)
        p(f"  {label}: {e:,} wrong of {c:,}")

    # The ratio columns of each table.
    ratio_cols = {
        "Predicates": ([3, 7, 8], ["batch vs naive", "exactray / naive", "exactray / robust"], 2),
        "Nearest points: queries": ([6, 7], ["exactray / kiddo", "exactray / rstar"], 1),
        "Nearest points: build": ([4], ["exactray / kiddo"], 1),
        "Ray casts against quadrics": ([6], ["exactray / naive"], 2),
        "Q2 rasterizing": ([4], ["rays / rasterize"], 1),
    }
    for name, (cols, labels, key_cells) in ratio_cols.items():
        rows = found.get(name)
        if not rows:
            continue
        p()
        p(f"{name} ({', '.join(labels)}):")
        for r in rows:
            vals = []
            for c in cols:
                v = r[c]
                if c == 3 and name == "Predicates":
                    m = re.search(r"\(([^)]*) naive\)", v)
                    v = m.group(1) if m else "-"
                vals.append(v)
            p(f"  {' '.join(r[:key_cells])}: {', '.join(vals)}")

    p()
    p("Other figures:")
    t = rep.ns
    k = t("nearest", "kiddo", "off-distribution:1000000")
    if k is not None:
        p(f"  nearest: kiddo at off-distribution:1000000 takes {sig(k / 1000, 3)} µs per query")
    for family, inputs, a, b in [
        ("ray_sphere", "uniform", "exactray", "parry3d"),
        ("ray_cylinder", "uniform", "exactray", "parry3d"),
        ("ray_cone", "uniform", "exactray", "parry3d"),
        ("ray_triangle", "uniform", "exactray-watertight", "exactray-mt"),
        ("ray_triangle", "uniform", "exactray-exact", "exactray-mt"),
        ("ray_triangle", "uniform", "parry3d", "exactray-watertight"),
    ]:
        p(f"  {family}/{inputs}: {a} / {b} {ratio(t(family, a, inputs), t(family, b, inputs))}")
    for m in TRIANGLE_METHODS:
        r = rep.row("ray_triangle", m, "shared-edges")
        if r is not None and r["errors"]:
            p(f"  ray_triangle/shared-edges: {m} lets {wrong_of(r)} through")
    rows = [r for r in rep.rows if r["family"] == "raster_triangle" and r["method"] == "exactray"]
    per = []
    for r in rows:
        n = int(r["inputs"].split(":")[1])
        rays = t("raster_triangle", "exactray-rays", r["inputs"])
        naive = t("raster_triangle", "naive", r["inputs"])
        per.append((n, rays / naive if rays and naive else None, rays / n if rays else None))
    if per:
        p("  raster_triangle: rays / textbook raster: "
          + ", ".join(f"{n:,} px {'-' if v is None else f'{v:.2f}x'}" for n, v, _ in per))
        p("  raster_triangle: rays ns per pixel: "
          + ", ".join(f"{n:,} px {'-' if v is None else sig(v, 3)}" for n, _, v in per))

    if md is None:
        p()
        p("Targets: no report.md beside the json (the targets are not in report.json).")
        return
    tables = md_tables(md)
    for before, header, body in tables:
        if header[:2] == ["inputs", "exactray ns"] and "batch speed-up" in header:
            col = {h: i for i, h in enumerate(header)}
            for r in body:
                p(f"  nearest {r[0]}: batch speed-up {r[col['batch speed-up']]}, nodes {r[col['nodes']]}, "
                  f"distances {r[col['distances']]}, exact cmp {r[col['exact cmp']]} (report.md notes)")
        if header[:4] == ["inputs", "exactray", "kiddo", "rstar"] and "exactray own" in header:
            ranges = []
            for c, m in enumerate(header[1:4], start=1):
                bs = [float(x) for x in (re.search(r"([\d.]+) B", r[c]).group(1) for r in body)]
                ranges.append(f"{m} {min(bs):.1f}–{max(bs):.1f}")
            p(f"  nearest_build: heap bytes per point: {', '.join(ranges)} (report.md notes)")

    m = re.search(r"^## Targets\s*\n\s*(\d+) of (\d+) met\.", md, re.M)
    target = next((t for t in tables if t[1][:3] == ["exactray on", "target", "measured"]), None)
    if m is None or target is None:
        p()
        p("Targets: report.md has no '## Targets' table.")
        return
    p()
    p(f"Targets (report.md): {m.group(1)} of {m.group(2)} met")
    groups = {}
    for r in target[2]:
        groups.setdefault(group_of(r[0].split("/")[0]), []).append(r)
    for g, rs in groups.items():
        met = sum(r[3] == "met" for r in rs)
        p(f"  {g}: {met} of {len(rs)} met")
        for r in rs:
            p(f"    {r[3]:<6} {r[0]}: {r[1]}; measured {r[2]}")


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("json", nargs="?", default="target/report/report.json")
    ap.add_argument("readme", nargs="?", default="README.md")
    mode = ap.add_mutually_exclusive_group()
    mode.add_argument("--check", action="store_true", help="exit 1 with a diff if the tables are stale")
    mode.add_argument("--ratios", action="store_true", help="only print the prose's figures")
    ap.add_argument("--report-md", help="the report.md with the Targets (default: beside the json)")
    args = ap.parse_args()

    json_path = Path(args.json)
    rep = Report(json.loads(json_path.read_text()))
    md_path = Path(args.report_md) if args.report_md else json_path.with_name("report.md")
    md = md_path.read_text() if md_path.exists() else None
    readme_path = Path(args.readme)
    old = readme_path.read_text()
    warn = lambda s: print(f"warning: {s}", file=sys.stderr)
    new, found = regenerate(old, rep, warn)

    if args.check:
        if new == old:
            print(f"{readme_path}: the tables under '## Measured figures' match {json_path}")
            return 0
        sys.stdout.writelines(
            difflib.unified_diff(
                old.splitlines(keepends=True),
                new.splitlines(keepends=True),
                f"{readme_path} (now)",
                f"{readme_path} (from {json_path})",
            )
        )
        return 1
    if not args.ratios:
        if new != old:
            readme_path.write_text(new)
            changed = sum(a != b for a, b in zip(old.splitlines(), new.splitlines()))
            print(f"{readme_path}: rewrote {changed} table rows from {json_path}")
        else:
            print(f"{readme_path}: tables already match {json_path}")
        print()
    print_ratios(rep, found, md, json_path, sys.stdout)
    return 0


if __name__ == "__main__":
    sys.exit(main())
