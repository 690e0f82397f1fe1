#!/usr/bin/env python3
# Copyright (c) 2026 ShapeCorr contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The tables of doc/shape_models.md from a workflow's results folder: per fit the surface (and
landmark) distances after the rigid alignment and after NICPS, with the poor fits flagged; the
model's explained variance per mode; compactness, generalization and specificity for the first
modes; each training shape's largest score and its own leave-one-out error (a poor fit shows as an outlier there).

usage: workflow/summary.py RESULTS_DIR [--poor-l2 X] [--poor-landmarks Y]
"""
import argparse
import glob
import json
import os


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("results")
    ap.add_argument("--poor-l2", type=float, default=None, help="flag fits whose l2 after NICPS exceeds this (default: 3x the median)")
    ap.add_argument("--poor-landmarks", type=float, default=None, help="flag fits whose mean landmark distance exceeds this")
    a = ap.parse_args()
    fits = []
    for path in sorted(glob.glob(os.path.join(a.results, "fits", "*.json"))):
        with open(path) as f:
            r = json.load(f)
        lm = r.get("landmark_distances_after")
        fits.append((os.path.splitext(os.path.basename(path))[0], r, sum(lm) / len(lm) if lm else None))
    l2s = sorted(r["distance_after"]["l2"] for _, r, _ in fits)
    poor_l2 = a.poor_l2 if a.poor_l2 is not None else 3 * l2s[len(l2s) // 2]
    with open(os.path.join(a.results, "report", "summary.json")) as f:
        s = json.load(f)
    names = [os.path.splitext(n)[0] for n in s.get("training_names", [])]
    scores = {names[i]: max(abs(c) for c in col) for i, col in enumerate(s.get("training_scores", [])) if i < len(names)}
    # each shape's leave-one-out error with all modes of the others (N - 2)
    loo = {names[i]: row[-1] for i, row in enumerate(s["generalization"].get("per_shape", [])) if i < len(names) and row}
    print("| specimen | l2 rigid | l2 NICPS | lmax NICPS |" + (" landmarks NICPS |" if any(m is not None for _, _, m in fits) else "") +
          " largest score (SD) | leave-one-out error | iterations | time (s) | |")
    print("|---|---|---|---|" + ("---|" if any(m is not None for _, _, m in fits) else "") + "---|---|---|---|---|")
    for name, r, lm in fits:
        poor = r["distance_after"]["l2"] > poor_l2 or (a.poor_landmarks is not None and lm is not None and lm > a.poor_landmarks)
        cells = [name, f"{r['distance_after_rigid']['l2']:.3f}", f"{r['distance_after']['l2']:.3f}", f"{r['distance_after']['lmax']:.2f}"]
        if lm is not None:
            cells.append(f"{lm:.2f}")
        cells += [f"{scores.get(name, float('nan')):.2f}", f"{loo.get(name, float('nan')):.3f}", str(r["nicps_iterations"]), f"{r['seconds']:.1f}",
                  "**poor**" if poor else ""]
        print("| " + " | ".join(cells) + " |")
    print()
    ratios = s["explained_variance_ratios"]
    cumulative = 0
    print(f"{s['training_shapes']} shapes of {s['vertices']} vertices, {s['modes']} modes, total variance {s['total_variance']:.4g} (mesh units squared)\n")
    print("| M | explained by mode M | compactness C(M) (cumulative) | generalization G(M) ± SE | specificity S(M) ± SE |")
    print("|---|---|---|---|---|")
    G, S = s["generalization"], s["specificity"]
    for m in range(min(8, s["modes"])):
        cumulative += ratios[m]
        g = f"{G['value'][m]:.3f} ± {G['standard_error'][m]:.3f}" if m < len(G["value"]) else "–"
        sp = f"{S['value'][m]:.3f} ± {S['standard_error'][m]:.3f}" if m < len(S["value"]) else "–"
        print(f"| {m + 1} | {100 * ratios[m]:.1f} % | {100 * cumulative:.1f} % | {g} | {sp} |")


if __name__ == "__main__":
    main()
