#!/usr/bin/env python3
"""Prints the Markdown tables of doc/geodesic_spin_contour.md from the summary.json of
evaluate_geodesic_descriptors: per case and descriptor the hit rate at k = 1 and at 1% of the
targets, and the mean geodesic error (/ sqrt(area)) at k = 1; the best per row in bold.
Usage: experiments/geodesic_summary_table.py experiments/results/geodesic/summary.json"""
import json
import sys

cases = json.load(open(sys.argv[1]))["cases"]
meta = {"source_vertices", "target_vertices", "points", "support", "agd_radius"}
descs = [k for k in next(iter(cases.values())).keys() if k not in meta]
for title, key, better in (("hit rate at k = 1", "hit_rate_k1", max), ("hit rate at 1% of N", "hit_rate_1pct", max),
                           ("mean geodesic error at k = 1 (/ sqrt(area))", "geodesic_error_k1", min),
                           ("hit rate at 1% of N, the symmetric match counted (TOSCA)", "hit_rate_1pct_sym", max),
                           ("mean geodesic error at k = 1 to the nearer of the match and its symmetric counterpart (TOSCA)",
                            "geodesic_error_k1_sym", min)):
    rows = {name: v for name, v in cases.items() if all(key in v[d] for d in descs)}
    if not rows:
        continue
    print(f"{title}:\n")
    print("| case | " + " | ".join(descs) + " |")
    print("|---|" + "---|" * len(descs))
    for name, v in rows.items():
        best = better(v[d][key] for d in descs)
        cells = [f"**{v[d][key]:.2f}**" if v[d][key] == best else f"{v[d][key]:.2f}" for d in descs]
        print(f"| {name} | " + " | ".join(cells) + " |")
    print()
