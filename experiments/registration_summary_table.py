#!/usr/bin/python3
# Copyright (c) 2026 ShapeCorr contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The Markdown tables of doc/registration.md from evaluate_registration's output (summary.json and
the CSV of each case beside it): per case, each method's mean l1/l2/lmax, mean landmark distance,
divergences, time (and for tosca the geodesic errors); the vertebrae per specimen (the thesis's
Tables 6.1 and 6.2); the rigid stage against Open3D.

usage: registration_summary_table.py OUT/summary.json
"""
import csv
import json
import math
import pathlib
import sys

ORDER = ["rigid", "nicps", "andresen", "pauly", "cpd", "gmm-l2", "bcpd"]


def number(x, digits=3):
    return "–" if x is None or (isinstance(x, float) and math.isnan(x)) else f"{x:.{digits}f}"


def mean(v):
    v = [x for x in v if x is not None and not math.isnan(x)]
    return sum(v) / len(v) if v else None


def main():
    summary_path = pathlib.Path(sys.argv[1])
    summary = json.loads(summary_path.read_text())
    for case, data in summary.get("cases", {}).items():
        rows = list(csv.DictReader(open(summary_path.parent / f"{case}.csv")))
        if not rows:
            continue
        f = lambda r, k: float(r[k]) if r[k] not in ("", "nan") else float("nan")
        methods = [m for m in ORDER if any(r["method"] == m for r in rows)]
        specimens = list(dict.fromkeys(r["specimen"] for r in rows))
        has_lm = any(not math.isnan(f(r, "landmarks")) for r in rows)
        has_ge = any(not math.isnan(f(r, "geodesic_error")) for r in rows)
        print(f"\n### {case} ({len(specimens)} instances)\n")
        cols = ["method", "l1", "l2", "lmax"] + (["landmarks"] if has_lm else []) + \
            (["geodesic error", "symmetric"] if has_ge else []) + ["diverged", "time (s)"]
        print("| " + " | ".join(cols) + " |")
        print("|" + "---|" * len(cols))
        for m in methods:
            mr = [r for r in rows if r["method"] == m]
            cells = [m] + [number(mean([f(r, k) for r in mr])) for k in ("l1", "l2", "lmax")]
            if has_lm:
                cells.append(number(mean([f(r, "landmarks") for r in mr]), 2))
            if has_ge:
                ms = data["methods"].get(m, {})
                cells += [number(ms.get("mean_geodesic_error")), number(ms.get("mean_geodesic_error_sym"))]
            cells.append("–" if m == "rigid" else f"{sum(int(r['diverged']) for r in mr)}/{len(mr)}")
            cells.append(number(mean([f(r, "seconds") for r in mr]), 1))
            print("| " + " | ".join(cells) + " |")
        if case == "vertebrae":
            for key, title, digits in (("l2", "l2 distance (mm) per specimen (Table 6.1)", 3),
                                       ("landmarks", "mean landmark distance (mm) per specimen (Table 6.2)", 2)):
                print(f"\n{title}:\n")
                print("| specimen | " + " | ".join(methods) + " |")
                print("|" + "---|" * (len(methods) + 1))
                for s in specimens:
                    by = {r["method"]: f(r, key) for r in rows if r["specimen"] == s}
                    print(f"| {s} | " + " | ".join(number(by.get(m), digits) for m in methods) + " |")
        rigid = data.get("rigid_stage", [])
        if rigid and any("open3d_l2" in r for r in rigid):
            print(f"\nrigid stage, {case}: mean l2 at the start {number(mean([r['start_l2'] for r in rigid]))}, after ShapeCorr's trimmed "
                  f"ICP {number(mean([r['shapecorr_l2'] for r in rigid]))} ({number(mean([r['shapecorr_seconds'] for r in rigid]), 2)} s), after "
                  f"Open3D's point-to-plane ICP {number(mean([r.get('open3d_l2', float('nan')) for r in rigid]))} "
                  f"({number(mean([r.get('open3d_seconds', float('nan')) for r in rigid]), 2)} s, with Python's start)")
    return 0


if __name__ == "__main__":
    sys.exit(main())
