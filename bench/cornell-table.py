#!/usr/bin/env python3
"""Markdown tables of a cornell-compare.sh TSV (standard library only).

    python3 bench/cornell-table.py RESULTS.tsv [RESULTS2.tsv ...]

Prints the mean radiance against the reference, error and time per sample count, and the time each
renderer needs to reach the error levels below (log-log interpolation between the two measured sample
counts around the level; "–" where the series does not reach it), and the Monte Carlo efficiency
1/(time × RMSE²) of ours over Cycles' at each sample count both rendered. Several files are read as one table
(e.g. one run per variant with different reference sample counts).
"""
import csv
import math
import sys

# (variant, RMSE level, column): all pixels ("rmse") and pixels whose reference is at most 1 ("rmse_le1").
LEVELS = [
    ("diffuse", 0.02, "rmse"), ("diffuse", 0.01, "rmse"), ("diffuse", 0.005, "rmse"),
    ("diffuse", 0.01, "rmse_le1"), ("diffuse", 0.005, "rmse_le1"),
    ("spheres", 0.05, "rmse"), ("spheres", 0.025, "rmse"), ("spheres", 0.0125, "rmse"),
    ("spheres", 0.05, "rmse_le1"), ("spheres", 0.025, "rmse_le1"), ("spheres", 0.0125, "rmse_le1"),
]
PIXELS = {"rmse": "all", "rmse_le1": "ref ≤ 1"}


def time_to(points, level):
    """Seconds to reach `level` on the (seconds, error) points, or None outside the measured range."""
    points = sorted(points)
    for (t1, e1), (t2, e2) in zip(points, points[1:]):
        if e1 >= level >= e2 and e1 != e2:
            a = (math.log(level) - math.log(e1)) / (math.log(e2) - math.log(e1))
            return math.exp(math.log(t1) + a * (math.log(t2) - math.log(t1)))
    return None


def fmt(x, digits):
    return "–" if x is None else f"{x:.{digits}f}"


def main(paths):
    rows = []
    for path in paths:
        with open(path, newline="") as f:
            rows += list(csv.DictReader(f, delimiter="\t"))
    variants = list(dict.fromkeys(r["variant"] for r in rows))

    def series(variant, renderer):
        return sorted((r for r in rows if r["variant"] == variant and r["renderer"] == renderer), key=lambda r: int(r["spp"]))

    def with_cycles(variant):
        """Each of our rows of the variant with Cycles' row of the same sample count (None when Cycles has none)."""
        cycles = {r["spp"]: r for r in series(variant, "cycles")}
        return [(o, cycles.get(o["spp"])) for o in series(variant, "ours")]

    print("## Mean radiance (Rec.709 luminance, all pixels)\n")
    print("| variant | Cycles reference | ours, most samples | difference |\n|---|---|---|---|")
    for v in variants:
        ref = next(r for r in rows if r["variant"] == v and r["renderer"] == "reference")
        ours = series(v, "ours")[-1]
        m_ref, m_ours = float(ref["mean_lum"]), float(ours["mean_lum"])
        print(f"| {v} | {m_ref:.6f} ({ref['spp']} spp) | {m_ours:.6f} ({ours['spp']} spp) | {100 * (m_ours / m_ref - 1):+.2f} % |")

    print("\n## Error and time per sample count\n")
    print("| variant | spp | Cycles s | ours s | Cycles RMSE | ours RMSE | Cycles RMSE ref ≤ 1 | ours RMSE ref ≤ 1 |\n|---|---|---|---|---|---|---|---|")
    for v in variants:
        for o, c in with_cycles(v):
            cs = lambda k: c[k] if c else "–"
            print(f"| {v} | {o['spp']} | {cs('render_s')} | {o['render_s']} | {cs('rmse')} | {o['rmse']} | {cs('rmse_le1')} | {o['rmse_le1']} |")

    print("\n## Time to reach an RMSE (log-log interpolation between the measured points)\n")
    print("| variant | RMSE | pixels | Cycles s | ours s | ours / Cycles |\n|---|---|---|---|---|---|")
    for v, level, column in LEVELS:
        if v not in variants:
            continue
        t = {}
        for renderer in ("cycles", "ours"):
            pts = [(float(r["render_s"]), float(r[column])) for r in series(v, renderer) if r["render_s"] not in ("", "-")]
            t[renderer] = time_to(pts, level)
        ratio = t["ours"] / t["cycles"] if t["ours"] and t["cycles"] else None
        print(f"| {v} | {level} | {PIXELS[column]} | {fmt(t['cycles'], 1)} | {fmt(t['ours'], 1)} | {fmt(ratio, 2)} |")

    print("\n## Monte Carlo efficiency 1/(time × RMSE²), ours ÷ Cycles, at equal sample counts\n")
    print("| variant | spp | all pixels | pixels with ref ≤ 1 |\n|---|---|---|---|")
    for v in variants:
        for o, c in with_cycles(v):
            if not c or c["render_s"] in ("", "-") or o["render_s"] in ("", "-"):
                continue
            def eff(column):
                return (float(c["render_s"]) * float(c[column]) ** 2) / (float(o["render_s"]) * float(o[column]) ** 2)
            print(f"| {v} | {o['spp']} | {eff('rmse'):.2f} | {eff('rmse_le1'):.2f} |")


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    main(sys.argv[1:])
