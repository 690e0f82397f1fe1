#!/usr/bin/env python3
"""Prints the Markdown tables of doc/rigid_descriptors.md from an evaluation summary.json:
AUC (final recall) per experiment and descriptor, best per row in bold, and the summed distance of
the incorrect matches. Usage: experiments/summary_table.py experiments/results/rigid/summary.json"""
import json
import sys

ex = json.load(open(sys.argv[1]))["experiments"]
descs = list(next(iter(ex.values())).keys())
head = ["| experiment | " + " | ".join(descs) + " |", "|---|" + "---|" * len(descs)]
print("\n".join(head))
for name, v in ex.items():
    best = max(v[k]["auc"] for k in descs)
    cells = []
    for k in descs:
        c = f"{v[k]['auc']:.3f} ({v[k]['final_recall']:.2f})"
        cells.append(f"**{c}**" if v[k]["auc"] == best else c)
    print(f"| {name} | " + " | ".join(cells) + " |")
print()
print("\n".join(head))
for name, v in ex.items():
    print(f"| {name} | " + " | ".join(f"{v[k]['wrong_summed_distance_mr']:.0f}" for k in descs) + " |")
