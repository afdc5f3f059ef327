#!/usr/bin/env python3
"""Rewrites the report's figures in README.md, docs/benchmarks.md and
docs/pictures.md from one run's report.json (and the report.md beside it:
the run's provenance, its targets and notes).

    python3 tools/report-tables/readme_tables.py target/report/report.json
    python3 tools/report-tables/readme_tables.py --check target/report/report.json

Rewriting also copies the json, the report.md and its plots into
docs/report-run/,
the run the pages quote, which `.ci/run` checks them against.

The pages mark what is generated with comment pairs,
`<!-- report:NAME -->` ... `<!-- /report:NAME -->`; everything between a
pair is rewritten, everything else is left as it is. Without an option it
rewrites the pages; `--check` prints a diff and exits 1 if a page differs
from what the json gives (0 if none does). A quick run (`--quick`) is
refused: its figures are not a full run's. Standard library only.
"""

import argparse
import difflib
import json
import math
import re
import sys
import textwrap
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
KEPT = ROOT / "docs/report-run"
PAGES = ["README.md", "docs/benchmarks.md", "docs/pictures.md"]

# --- number formats --------------------------------------------------------


def _fixed(v, sig):
    """`v` to `sig` significant digits, as a fixed-point string."""
    if v == 0 or not math.isfinite(v):
        return "0" if v == 0 else str(v)
    mag = math.floor(math.log10(abs(v)))
    digits = max(sig - 1 - mag, 0)
    s = f"{v:.{digits}f}"
    if digits > 0 and abs(float(s)) >= 10 ** (mag + 1):
        s = f"{v:.{digits - 1}f}"
    return s


def _strip(s):
    return s.rstrip("0").rstrip(".") if "." in s else s


def sig(v, n):
    """`n` significant digits, trailing zeros dropped: 4.1, 53, 0.081."""
    return _strip(_fixed(v, n))


def ns(v):
    """A time: 3 significant digits below 1,000, whole with thousands
    separators from 1,000 on; `-` for none."""
    if v is None:
        return "-"
    s = sig(v, 3)
    if float(s) >= 1000:
        return f"{round(v):,}"
    return s


def ratio(a, b, decimals=2):
    if a is None or b is None or b == 0:
        return "-"
    return f"{a / b:.{decimals}f}x"


def ratio_sig(a, b, n=3):
    if a is None or b is None or b == 0:
        return "-"
    return _fixed(a / b, n) + "x"


def share(errors, cases):
    """`0`, or the wrong share: one decimal from 0.1%, else two significant
    digits (0.035%); `>99.9%` for nearly all but not all."""
    if errors == 0:
        return "0"
    p = 100.0 * errors / cases
    if errors < cases and p >= 99.95:
        return ">99.9%"  # not all: one decimal would round it to 100.0%
    return f"{p:.1f}%" if p >= 0.1 else sig(p, 2) + "%"


def wrong(row):
    return share(row["errors"], row["cases"])


def wrong_count(row):
    """`0`; under 0.1% the count itself; else one decimal."""
    e = row["errors"]
    if e == 0:
        return "0"
    p = 100.0 * e / row["cases"]
    return f"{e:,}" if p < 0.1 else f"{p:.1f}%"


def wrong_of(row):
    e = row["errors"]
    if e == 0:
        return "0"
    return f"{e:,} of {row['cases']:,}: {share(e, row['cases'])}"


def ulps(v, commas):
    if v is None:
        return "-"
    if v < 1e6:
        n = round(v)
        return f"{n:,}" if commas else str(n)
    return f"{v:.1e}"


def table(header, rows):
    out = ["| " + " | ".join(header) + " |", "|" + "---|" * len(header)]
    out += ["| " + " | ".join(r) + " |" for r in rows]
    return "\n".join(out)


# --- the report --------------------------------------------------------------


class Report:
    def __init__(self, rows, md):
        self.rows = rows
        self.md = md or ""
        self.by_key = {(r["family"], r["method"], r["inputs"]): r for r in rows}

    def row(self, family, method, inputs):
        return self.by_key.get((family, method, inputs))

    def ns(self, family, method, inputs):
        r = self.row(family, method, inputs)
        return None if r is None else r["ns_per_op"]

    def inputs(self, family):
        """The family's input classes, in report order."""
        seen = []
        for r in self.rows:
            if r["family"] == family and r["inputs"] not in seen:
                seen.append(r["inputs"])
        return seen

    def total(self, family, method):
        """(errors, cases) over every class of a family."""
        rs = [r for r in self.rows if r["family"] == family and r["method"] == method]
        return sum(r["errors"] for r in rs), sum(r["cases"] for r in rs)

    def provenance(self):
        m = re.search(r"^Run: (.*)$", self.md, re.M)
        return m.group(1) if m else None

    def section(self, title):
        """The body of a `## title` section of report.md."""
        m = re.search(rf"^## {re.escape(title)}\n(.*?)(?=^## |\Z)", self.md, re.M | re.S)
        return m.group(1).strip() if m else None


def cell(r, fmt=wrong):
    return "-" if r is None else f"{ns(r['ns_per_op'])} ({fmt(r)})"


# --- the blocks ----------------------------------------------------------------

PREDICATES = ["orient2d", "orient3d", "incircle", "insphere", "plane_side"]
PREDICATE_PEERS = ["robust", "geometry-predicates", "arithmetica", "axiolid-predicates", "apfp"]
QUADRICS = ["ray_sphere", "ray_cylinder", "ray_cone", "ray_quadric"]
TRIANGLE_METHODS = [
    "exactray-mt",
    "exactray-watertight",
    "exactray-exact",
    "exactray-exact-prepared",
    "exactray-exact-bounded",
    "naive",
    "parry3d",
]


def run_header(rep):
    p = rep.provenance()
    m = re.search(r"^(Full|Quick) run: (.*?)\n\n", rep.md, re.M | re.S)
    out = []
    if p:
        out.append(f"Every figure below is from one run of the report, `cargo run --release -p exactray-bench --bin "
                   f"report`: {p}")
    if m:
        # The run's sizes, without report.md's words on its own columns.
        out.append(" ".join(m.group(0).split()).split(" `vs naive`")[0])
    return "\n\n".join(out)


# The predicates' input classes in two groups: inputs whose products stay
# in f64's range (where Shewchuk's adaptive arithmetic, robust's, is exact)
# and inputs whose products underflow or overflow.
IN_RANGE = ["uniform", "near-degenerate", "degenerate"]
OUT_OF_RANGE = ["tiny", "huge", "mixed"]


def readme_predicates(rep):
    """One row per predicate: exactray's wrong answers over every class,
    robust's per class in each group, and the other peers' per group."""

    def per_class(family, method, classes):
        return " / ".join(share(r["errors"], r["cases"]) if r else "-"
                          for r in (rep.row(family, method, c) for c in classes))

    def group(family, methods, classes, only_wrong):
        parts = []
        for m in methods:
            rs = [r for r in (rep.row(family, m, c) for c in classes) if r]
            e, c = sum(r["errors"] for r in rs), sum(r["cases"] for r in rs)
            if c and (e or not only_wrong):
                parts.append(f"{m} {share(e, c)}")
        return ", ".join(parts) if parts else "none wrong"

    others = [m for m in PREDICATE_PEERS if m != "robust"] + ["naive"]
    rows = []
    for f in PREDICATES:
        e, c = rep.total(f, "exactray")
        if not c:
            continue
        rows.append([f"`{f}`", share(e, c), per_class(f, "robust", IN_RANGE), per_class(f, "robust", OUT_OF_RANGE),
                     group(f, others, IN_RANGE, only_wrong=True), group(f, others, OUT_OF_RANGE, only_wrong=False)])
    return table(["predicate", "exactray, every class", "robust: ordinary / near-degenerate / degenerate",
                  "robust: tiny / huge / mixed", "others wrong: ordinary, near-degenerate, degenerate",
                  "others wrong: tiny, huge, mixed"], rows)


def readme_exactness(rep):
    """The predicates per input class, then one row per other question:
    exactray's wrong answers and the peers'."""
    rows = []

    def others(family, methods, inputs=None):
        parts = []
        for m in methods:
            if inputs is None:
                e, c = rep.total(family, m)
            else:
                r = rep.row(family, m, inputs)
                e, c = (r["errors"], r["cases"]) if r else (0, 0)
            if c:
                parts.append(f"{m} {share(e, c)}")
        return ", ".join(parts)

    for label, family, inputs, ours, peers in [
        ("nearest point, near-ties", "nearest", "near-ties:10000", "exactray", ["kiddo", "rstar"]),
        ("ray–sphere, far origins", "ray_sphere", "far", "exactray", ["parry3d", "naive"]),
        ("ray–cone, far origins", "ray_cone", "far", "exactray", ["naive-stable", "parry3d"]),
        ("ray–triangle, rays near an edge", "ray_triangle", "near-edge", "exactray-exact",
         ["exactray-watertight", "exactray-mt", "parry3d"]),
        ("mesh closest hit, rays at vertices", "closest_hit", "vertices:99224", "exactray-exact",
         ["exactray", "obvhs", "parry3d", "embree"]),
        ("secondary rays re-hitting their surface, mesh at 1e30", "spawn", "huge", "exactray",
         ["epsilon-1e-4", "epsilon-1e-8"]),
    ]:
        r = rep.row(family, ours, inputs)
        if r is None:
            continue
        rows.append([label, f"{share(r['errors'], r['cases'])} ({ours})", others(family, peers, inputs)])
    e, c = rep.total("delaunay", "exactray")
    if c:
        fails = [m for m in ["robust", "spade"]
                 if any(r["errors"] >= r["cases"] for r in rep.rows if r["family"] == "delaunay" and r["method"] == m)]
        rows.append(["Delaunay triangulation, tiny/huge/mixed magnitudes", share(e, c),
                     ", ".join(f"{m}: no valid output on some sets" for m in fails)])
    return readme_predicates(rep) + "\n\n" + table(["question", "exactray wrong", "others wrong"], rows)


def readme_speed(rep):
    rows = []

    def peers(family, inputs, methods):
        return ", ".join(f"{m} {ns(rep.ns(family, m, inputs))}" for m in methods if rep.ns(family, m, inputs) is not None)

    for label, family, inputs, ours, others in [
        ("orient2d, ordinary points", "orient2d", "uniform", "exactray", PREDICATE_PEERS),
        ("orient3d, ordinary points", "orient3d", "uniform", "exactray", PREDICATE_PEERS),
        ("orient3d, near-degenerate", "orient3d", "near-degenerate", "exactray", PREDICATE_PEERS),
        ("insphere, ordinary points", "insphere", "uniform", "exactray", PREDICATE_PEERS),
        ("insphere, near-degenerate", "insphere", "near-degenerate", "exactray", PREDICATE_PEERS),
        ("nearest point among 10^6", "nearest", "uniform:1000000", "exactray", ["kiddo", "rstar"]),
        ("ray–sphere", "ray_sphere", "uniform", "exactray", ["naive-stable", "parry3d"]),
        ("ray–triangle, exact (ray prepared)", "ray_triangle", "uniform", "exactray-exact-prepared",
         ["exactray-mt", "parry3d"]),
        ("closest hit, 10^6-triangle mesh", "closest_hit", "primary:998000", "exactray",
         ["obvhs", "parry3d", "embree"]),
    ]:
        t = rep.ns(family, ours, inputs)
        if t is None:
            continue
        rows.append([label, ns(t), peers(family, inputs, others)])
    return table(["ns per operation", "exactray", "others"], rows)


def faster_peers(rep):
    """Every class where a peer that was exact on it took less time than
    exactray's default method: the sentences the README and the benchmarks
    page owe the reader."""
    lines = []
    for f in PREDICATES:
        for inputs in rep.inputs(f):
            ours = rep.row(f, "exactray", inputs)
            if ours is None or ours["errors"]:
                continue
            faster = [r for r in (rep.row(f, m, inputs) for m in PREDICATE_PEERS)
                      if r and r["errors"] == 0 and r["ns_per_op"] < ours["ns_per_op"]]
            if faster:
                peers = ", ".join(f"{r['method']} {ns(r['ns_per_op'])} ns" for r in faster)
                lines.append(f"- `{f}` on `{inputs}` inputs: {peers}, against exactray's "
                             f"{ns(ours['ns_per_op'])} ns.")
    if not lines:
        return "No peer was both exact and faster than exactray on any predicate class of this run."
    ours = sum(rep.total(f, "exactray")[0] for f in PREDICATES)
    on_ours = " (exactray made none on any class)" if ours == 0 else f" (exactray made {ours:,} in all)"
    return ("Where a peer made no wrong answer on a class and was faster than exactray there" + on_ours + ":\n\n"
            + "\n".join(lines))


def predicates_table(rep):
    methods = ["exactray", "exactray-batch", "naive"] + PREDICATE_PEERS
    rows = []
    for f in PREDICATES:
        for inputs in rep.inputs(f):
            cells = [f, inputs]
            for m in methods:
                r = rep.row(f, m, inputs)
                cells.append("-" if r is None else (ns(r["ns_per_op"]) if m == "exactray" and not r["errors"]
                                                    else cell(r)))
            rows.append(cells)
    header = ["family", "inputs", "exactray", "exactray-batch", "naive"] + PREDICATE_PEERS
    return table(header, rows)


def predicates_checked(rep):
    """Rows that checked fewer cases than the class holds."""
    full = max((r["cases"] for r in rep.rows if r["family"] in PREDICATES), default=0)
    short = [r for r in rep.rows if r["family"] in PREDICATES and r["cases"] < full]
    if not short:
        return f"Every method answered all {full:,} cases of every class."
    parts = [f"{r['method']} on {r['family']}/{r['inputs']} ({r['cases']:,})" for r in short]
    return (f"Each class holds {full:,} cases; a method that took longer than the report's budget answered fewer, "
            f"and its share of wrong answers is over those: " + ", ".join(parts) + ".")


def nearest_table(rep):
    rows = []
    for inputs in rep.inputs("nearest"):
        g = lambda m: rep.row("nearest", m, inputs)
        t = lambda m: rep.ns("nearest", m, inputs)
        rows.append([inputs, ns(t("exactray")), ns(t("exactray-batch")), cell(g("kiddo")), cell(g("rstar")),
                     ns(t("brute-force")), ratio(t("exactray"), t("kiddo")), ratio(t("exactray"), t("rstar"))])
    return table(["inputs", "exactray ns", "exactray-batch ns", "kiddo ns (wrong)", "rstar ns (wrong)",
                  "brute force ns", "exactray / kiddo", "exactray / rstar"], rows)


def nearest_build_table(rep):
    rows = []
    for inputs in rep.inputs("nearest_build"):
        t = lambda m: rep.ns("nearest_build", m, inputs)
        rows.append([inputs, ns(t("exactray")), ns(t("kiddo")), ns(t("rstar")), ratio(t("exactray"), t("kiddo"))])
    return table(["inputs", "exactray ns/point", "kiddo ns/point", "rstar ns/point", "exactray / kiddo"], rows)


def quadrics_table(rep):
    q = lambda r: f"{wrong(r)}; {ulps(r['max_ulps'], commas=False)}"
    rows = []
    for f in QUADRICS:
        for inputs in rep.inputs(f):
            g = lambda m: rep.row(f, m, inputs)
            t = lambda m: rep.ns(f, m, inputs)
            b = g("exactray")
            rows.append([f, inputs, cell(g("exactray"), q),
                         "-" if b is None else ulps(b.get("max_bound_ulps"), commas=False),
                         cell(g("exactray-precise"), q), cell(g("naive"), q), cell(g("naive-stable"), q),
                         cell(g("parry3d"), q), ratio(t("exactray"), t("naive-stable")),
                         ratio(t("exactray"), t("parry3d"))])
    return table(["family", "inputs", "exactray ns (wrong; ulps)", "exactray bound ulps", "exactray-precise",
                  "naive", "naive-stable", "parry3d", "exactray / naive-stable", "exactray / parry3d"], rows)


def triangle_table(rep):
    rows = []
    for inputs in rep.inputs("ray_triangle"):
        if all(rep.row("ray_triangle", m, inputs) is None for m in TRIANGLE_METHODS):
            continue
        fmt = wrong_of if inputs == "shared-edges" else wrong_count
        label = "shared-edges (false misses)" if inputs == "shared-edges" else inputs
        rows.append([label] + [cell(rep.row("ray_triangle", m, inputs), fmt) for m in TRIANGLE_METHODS])
    return table(["inputs", "MT ns (wrong)", "watertight ns (wrong)", "exact ns (wrong)", "exact prepared ns (wrong)",
                  "exact bounded ns (wrong)", "naive ns (wrong)", "parry3d ns (wrong)"], rows)


def triangle_ulps_table(rep):
    rows = []
    for inputs in rep.inputs("ray_triangle"):
        rs = [rep.row("ray_triangle", m, inputs) for m in TRIANGLE_METHODS]
        if all(r is None or r["max_ulps"] is None for r in rs):
            continue
        rows.append([inputs] + ["-" if r is None else ulps(r["max_ulps"], commas=True) for r in rs])
    return table(["inputs", "MT", "watertight", "exact", "exact prepared", "exact bounded", "naive", "parry3d"], rows)


SCENE_CLOSEST = ["exactray", "exactray-exact", "exactray-ploc", "obvhs", "obvhs-bvh2", "parry3d", "embree"]
SCENE_ANY = ["exactray", "exactray-closest", "exactray-exact", "obvhs", "obvhs-bvh2", "parry3d", "embree"]


def closest_table(rep):
    rows = []
    for inputs in rep.inputs("closest_hit"):
        g = lambda m: rep.row("closest_hit", m, inputs)
        t = lambda m: rep.ns("closest_hit", m, inputs)
        rows.append([inputs] + [cell(g(m)) for m in SCENE_CLOSEST]
                    + [ns(t("exactray-batch")), ns(t("exactray-rayon")),
                       ratio(t("exactray"), t("obvhs")), ratio(t("exactray"), t("parry3d"))])
    return table(["inputs"] + [f"{m} ns (wrong)" for m in SCENE_CLOSEST]
                 + ["exactray-batch ns", "exactray-rayon ns", "exactray / obvhs", "exactray / parry3d"], rows)


def any_table(rep):
    rows = []
    for inputs in rep.inputs("any_hit"):
        g = lambda m: rep.row("any_hit", m, inputs)
        t = lambda m: rep.ns("any_hit", m, inputs)
        rows.append([inputs] + [cell(g(m)) for m in SCENE_ANY]
                    + [ratio(t("exactray"), t("exactray-closest"))])
    return table(["inputs"] + [f"{m} ns (wrong)" for m in SCENE_ANY] + ["exactray / exactray-closest"], rows)


def spawn_table(rep):
    rows = []
    for inputs in rep.inputs("spawn"):
        g = lambda m: rep.row("spawn", m, inputs)
        e = g("exactray")
        rows.append([inputs, "-" if e is None else f"{e['cases']:,}"]
                    + ["-" if g(m) is None else f"{g(m)['errors']:,}" for m in ["exactray", "epsilon-1e-4", "epsilon-1e-8"]]
                    + [ns(rep.ns("spawn", m, inputs)) for m in ["exactray", "epsilon-1e-8"]])
    return table(["situation", "secondary rays", "exactray self-hits", "epsilon-1e-4 self-hits",
                  "epsilon-1e-8 self-hits", "exactray ns", "epsilon-1e-8 ns"], rows)


def raster_rows(rep):
    out = []
    for inputs in rep.inputs("raster_triangle"):
        n = int(inputs.split(":")[1])
        t = lambda m: rep.ns("raster_triangle", m, inputs)
        out.append((n, t("exactray"), t("exactray-rays"), t("naive")))
    return out


def raster_table(rep):
    rows = [[f"{n:,}", ns(r), ns(rays), ns(naive), ratio_sig(rays, r),
             "-" if r is None else sig(r / n, 2), "-" if rays is None else sig(rays / n, 3)]
            for n, r, rays, naive in raster_rows(rep)]
    return table(["pixels", "rasterize ns", "one ray per pixel ns", "textbook raster ns", "rays / rasterize",
                  "rasterize ns per pixel", "rays ns per pixel"], rows)


def render_rows(rep):
    out = []
    for inputs in rep.inputs("render"):
        size, n = inputs.split(":")
        w, h = (int(x) for x in size.split("x"))
        r = rep.ns("render", "exactray-raster", inputs)
        rays = rep.ns("render", "exactray-rays", inputs)
        row = rep.row("render", "exactray-raster", inputs)
        out.append((inputs, w, h, int(n), r, rays, row))
    return out


def render_table(rep):
    ms = lambda v: "-" if v is None else sig(v / 1e6, 3)
    rows = [[inputs, ms(r), ms(rays), ratio(rays, r), "-" if r is None else sig(r / n, 3),
             "-" if rays is None else sig(rays / (w * h), 3), "-" if row is None else f"{row['errors']:,}"]
            for inputs, w, h, n, r, rays, row in render_rows(rep)]
    return table(["inputs", "Z-buffer ms", "rays ms", "rays / Z-buffer", "Z-buffer ns per triangle",
                  "rays ns per pixel", "pixels differing"], rows)


def q2_summary(rep):
    lines = []
    tri = [(n, rays / r) for n, r, rays, _ in raster_rows(rep) if r and rays]
    if tri:
        lines.append("- One triangle, one ray per pixel against the rasterizer's time: "
                     + ", ".join(f"{x:.2g}x at {n:,} pixels" for n, x in tri) + ".")
    frames = [(inputs, n / (w * h), rays / r) for inputs, w, h, n, r, rays, _ in render_rows(rep) if r and rays]
    if frames:
        win = [f"`{i}` ({t:.2g} triangles per pixel) {x:.2f}x" for i, t, x in frames]
        lines.append("- One frame (`W`x`H`:triangles), one ray per pixel against the Z-buffer's time: "
                     + "; ".join(win) + ".")
    differ = sum(row["errors"] for *_, row in render_rows(rep) if row)
    if frames:
        lines.append(f"- Pixels whose visible triangle differs between the two: {differ:,}.")
    return "\n".join(lines)


def delaunay_table(rep):
    rows = []
    for inputs in rep.inputs("delaunay"):
        g = lambda m: rep.row("delaunay", m, inputs)
        t = lambda m: rep.ns("delaunay", m, inputs)
        failed = lambda m: g(m) is None or g(m)["errors"] >= g(m)["cases"]
        against = lambda m: "-" if failed(m) else ratio(t("exactray"), t(m))
        rows.append([inputs] + [cell(g(m)) for m in ["exactray", "robust", "spade"]]
                    + [against("robust"), against("spade")])
    return table(["inputs", "exactray ns/point (wrong)", "robust ns/point (wrong)", "spade ns/point (wrong)",
                  "exactray / robust", "exactray / spade"], rows)


def targets(rep):
    body = rep.section("Targets")
    if body is None:
        return "report.md has no targets."
    return body


BUDGET_NOTE = re.compile(r"^`([^`]+)` on `([^`]+)`(:| is timed)")


def name_families(rep, paragraphs):
    """The sign families' budget notes with their family named, where a run
    wrote `method on `class`` only: a note that a method checked N cases
    belongs to the family whose row has that method, class and count; a
    note on its timing, to the family of the count note after it."""
    out = list(paragraphs)
    family_at = [None] * len(out)
    for i, p in enumerate(out):
        m = BUDGET_NOTE.match(p)
        n = re.search(r": ([\d,]+) of ", p)
        if m and n:
            cases = int(n.group(1).replace(",", ""))
            fams = {r["family"] for r in rep.rows if r["method"] == m.group(1) and r["inputs"] == m.group(2)
                    and r["cases"] == cases and r["family"] in PREDICATES}
            if len(fams) == 1:
                family_at[i] = fams.pop()
    for i in range(len(out) - 2, -1, -1):
        m, nxt = BUDGET_NOTE.match(out[i]), BUDGET_NOTE.match(out[i + 1])
        if m and nxt and family_at[i] is None and m.group(1, 2) == nxt.group(1, 2):
            family_at[i] = family_at[i + 1]
    for i, f in enumerate(family_at):
        if f:
            out[i] = BUDGET_NOTE.sub(lambda m: f"`{m.group(1)}` on {f}/`{m.group(2)}`{m.group(3)}", out[i], count=1)
    return out


def notes(rep):
    body = rep.section("Notes")
    if body is None:
        return "report.md has no notes."
    body = "\n\n".join(name_families(rep, body.split("\n\n")))
    # The notes' own headings go one level down the page's.
    return re.sub(r"^(#+) ", lambda m: "#" * (len(m.group(1)) + 2) + " ", body, flags=re.M)


def implicit_table(rep):
    """Predicates on constructed points: exactray, round-then-exact, and
    the explicit predicate timed in the same loops (uniform rows)."""
    rows = []
    for inputs in rep.inputs("implicit"):
        g = lambda m: rep.row("implicit", m, inputs)
        ex = g("exactray")
        explicit = g("explicit-orient3d") or g("explicit-orient2d")
        rows.append([inputs, cell(ex), cell(g("round-then-exact")),
                     "-" if explicit is None else ns(explicit["ns_per_op"]),
                     "-" if explicit is None or ex is None else ratio(ex["ns_per_op"], explicit["ns_per_op"])])
    return table(["inputs", "exactray ns (wrong)", "round-then-exact ns (wrong)",
                  "explicit predicate ns, same loops", "exactray / explicit"], rows)


BLOCKS = {
    "run": run_header,
    "readme-exactness": readme_exactness,
    "readme-speed": readme_speed,
    "faster-peers": faster_peers,
    "predicates": predicates_table,
    "predicates-checked": predicates_checked,
    "nearest": nearest_table,
    "nearest-build": nearest_build_table,
    "quadrics": quadrics_table,
    "triangle": triangle_table,
    "triangle-ulps": triangle_ulps_table,
    "closest-hit": closest_table,
    "any-hit": any_table,
    "spawn": spawn_table,
    "raster": raster_table,
    "render": render_table,
    "q2-summary": q2_summary,
    "delaunay": delaunay_table,
    "implicit": implicit_table,
    "targets": targets,
    "notes": notes,
}

BLOCK = re.compile(r"(<!-- report:([a-z0-9-]+) -->\n)(.*?)(<!-- /report:\2 -->)", re.S)

LONG_LINE = 300
# A line that Markdown would read as the start of a new block.
BLOCK_START = re.compile(r"^([-*+>#|]|\d+[.)])(\s|$)")


def wrap_long(text, width=72):
    """Prose lines longer than LONG_LINE characters (a run's notes, a
    summary) wrapped at `width`, list items with a hanging indent; tables,
    code and shorter lines as they are. No continuation line starts what
    Markdown would read as a new block."""
    out, code = [], False
    for line in text.split("\n"):
        if line.lstrip().startswith("```"):
            code = not code
        if code or line.lstrip().startswith("|") or len(line) <= LONG_LINE:
            out.append(line)
            continue
        lead = re.match(r"^(\s*)((?:[-*]|\d+\.)\s+)?", line)
        lead = lead.group(1) + (lead.group(2) or "")
        w = textwrap.TextWrapper(width=width, initial_indent=lead, subsequent_indent=" " * len(lead),
                                 break_long_words=False, break_on_hyphens=False)
        lines = w.wrap(line[len(lead):])
        while any(BLOCK_START.match(x.lstrip()) for x in lines[1:]):
            w.width += 1
            lines = w.wrap(line[len(lead):])
        out.extend(lines)
    return "\n".join(out)


def rewrite(text, rep, page):
    """`text` with every block regenerated; the names it holds."""
    names = []

    def fill(m):
        name = m.group(2)
        if name not in BLOCKS:
            sys.exit(f"{page}: unknown block '{name}' (known: {', '.join(BLOCKS)})")
        names.append(name)
        return m.group(1) + wrap_long(BLOCKS[name](rep).rstrip("\n")) + "\n" + m.group(4)

    return BLOCK.sub(fill, text), names


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("json", nargs="?", default=str(ROOT / "target/report/report.json"))
    ap.add_argument("--check", action="store_true", help="exit 1 with a diff if a page is stale")
    ap.add_argument("--report-md", help="the report.md (default: beside the json)")
    args = ap.parse_args()

    json_path = Path(args.json)
    md_path = Path(args.report_md) if args.report_md else json_path.with_name("report.md")
    md = md_path.read_text() if md_path.exists() else None
    if md and md.count("\nQuick run:"):
        sys.exit(f"{md_path}: a --quick run; the pages quote full runs only")
    rep = Report(json.loads(json_path.read_text()), md)

    stale = False
    seen = set()
    for page in PAGES:
        path = ROOT / page
        old = path.read_text()
        new, names = rewrite(old, rep, page)
        seen.update(names)
        if new == old:
            print(f"{page}: up to date with {json_path}")
            continue
        if args.check:
            stale = True
            sys.stdout.writelines(difflib.unified_diff(
                old.splitlines(keepends=True), new.splitlines(keepends=True),
                f"{page} (now)", f"{page} (from {json_path})"))
        else:
            path.write_text(new)
            print(f"{page}: rewrote {len(names)} blocks from {json_path}")
    if not args.check:
        KEPT.mkdir(exist_ok=True)
        plots = [(svg, svg.name) for svg in sorted(json_path.parent.glob("*.svg"))]
        for src, name in [(json_path, "report.json"), (md_path, "report.md")] + plots:
            dst = KEPT / name
            if src.exists() and src.resolve() != dst.resolve():
                dst.write_text(src.read_text())
                print(f"{dst.relative_to(ROOT)}: copied from {src}")
    for name in BLOCKS:
        if name not in seen:
            print(f"warning: no page holds the block '{name}'", file=sys.stderr)
    return 1 if stale else 0


if __name__ == "__main__":
    sys.exit(main())
