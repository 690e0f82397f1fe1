#!/usr/bin/env python3
# Copyright (c) 2026 ShapeCorr contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Tables and figures of doc/isometric_registration.md from the case files of evaluate_isometric.

usage: isometric_summary.py RESULTS [FIGURES]
RESULTS holds cases/*.json; prints Markdown tables; writes summary.json into RESULTS and the PNG
figures into FIGURES (default RESULTS). A case *fails* when fewer than half of its sampled
correspondences are within 0.25 sqrt(area), symmetry-aware.
"""
import glob
import json
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

LABEL = {"ours-gsc": "ours (GSC trim)", "ours-wks": "ours (WKS trim)", "ours-isc": "ours (ISC trim)", "pyfm": "pyFM WKS + ZoomOut"}
GROUPS = [("tosca", "TOSCA test pairs (tosca5k)"), ("cut", "cut sources (TOSCA, one pair per class)"),
          ("camel", "camel_gallop frames"), ("lion", "lion -> cat (non-isometric)")]
THRESHOLDS = [0.25 * i / 50 for i in range(51)]


def mean(xs):
    xs = list(xs)
    return sum(xs) / len(xs) if xs else float("nan")


def failed(m):
    return m.get("failed", False) or m["dense_symmetric"]["within_0.25"] < 0.5


def curve_mean(cases, method, key):
    curves = [c["methods"][method][key] for c in cases if method in c["methods"] and not c["methods"][method].get("failed")]
    return [mean(c[i] for c in curves) for i in range(51)] if curves else None


def finish_figure(title, xlabel, ylabel, path, curves=False):
    plt.xlabel(xlabel)
    plt.ylabel(ylabel)
    plt.title(title)
    if curves:
        plt.xlim(0, 0.25)
        plt.ylim(0, 1)
    plt.grid(alpha=0.3)
    plt.legend(fontsize=7, loc="lower right" if curves else "best")
    plt.tight_layout()
    plt.savefig(path, dpi=100)
    plt.close()


def finish_curve_figure(title, path):
    finish_figure(title, "geodesic error / sqrt(area)", "fraction of correspondences", path, curves=True)


def cumulative(errors):
    errors = sorted(errors)
    out, j = [], 0
    for t in THRESHOLDS:
        while j < len(errors) and errors[j] <= t:
            j += 1
        out.append(j / len(errors) if errors else 0.0)
    return out


def main():
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    results = sys.argv[1]
    figures = sys.argv[2] if len(sys.argv) > 2 else results
    os.makedirs(figures, exist_ok=True)
    cases = [json.load(open(p)) for p in sorted(glob.glob(os.path.join(results, "cases", "*.json")))]
    summary = {}
    print("Dense maps: mean geodesic error / sqrt(area) (direct; symmetry-aware), % of correspondences "
          "within 0.25 (symmetry-aware), failures, mean seconds per pair:\n")
    print("| cases | method | pairs | mean error, direct | mean error, symmetry-aware | % < 0.25, symmetry-aware | failures | seconds |")
    print("|---|---|---|---|---|---|---|---|")
    for kind, title in GROUPS:
        group = [c for c in cases if c["kind"] == kind]
        if not group:
            continue
        for method in ("ours-gsc", "ours-wks", "ours-isc", "pyfm"):
            runs = [c["methods"][method] for c in group if method in c["methods"]]
            if not runs:
                continue
            ok = [m for m in runs if not m.get("failed")]
            row = {"pairs": len(runs),
                   "mean_direct": mean(m["dense_direct"]["mean"] for m in ok),
                   "mean_symmetric": mean(m["dense_symmetric"]["mean"] for m in ok),
                   "within_0.25_symmetric": mean(m["dense_symmetric"]["within_0.25"] for m in ok),
                   "failures": sum(1 for m in runs if failed(m)),
                   "seconds": mean(m["seconds"] for m in ok)}
            summary.setdefault(kind, {})[method] = row
            print(f"| {title} | {LABEL[method]} | {row['pairs']} | {row['mean_direct']:.3f} | {row['mean_symmetric']:.3f} | "
                  f"{100 * row['within_0.25_symmetric']:.2f} | {row['failures']} | {row['seconds']:.1f} |")
    # the trims side by side on the pairs where all three ran
    trio = [c for c in cases if c["kind"] == "tosca" and all(m in c["methods"] for m in ("ours-gsc", "ours-wks", "ours-isc", "pyfm"))]
    if trio:
        print(f"\nThe three trims and pyFM on the {len(trio)} TOSCA pairs where all ran (mean error symmetry-aware; failures):\n")
        print("| method | mean error, direct | mean error, symmetry-aware | % < 0.25 | failures | seconds |")
        print("|---|---|---|---|---|---|")
        for method in ("ours-gsc", "ours-wks", "ours-isc", "pyfm"):
            runs = [c["methods"][method] for c in trio]
            ok = [m for m in runs if not m.get("failed")]
            print(f"| {LABEL[method]} | {mean(m['dense_direct']['mean'] for m in ok):.3f} | {mean(m['dense_symmetric']['mean'] for m in ok):.3f} | "
                  f"{100 * mean(m['dense_symmetric']['within_0.25'] for m in ok):.1f} | {sum(1 for m in runs if failed(m))} | "
                  f"{mean(m['seconds'] for m in ok):.1f} |")
    # per TOSCA class
    tosca_all = [c for c in cases if c["kind"] == "tosca"]
    classes = sorted({c["name"].split("-")[0].rstrip("0123456789") for c in tosca_all})
    if classes:
        print("\nPer TOSCA class (dense maps, symmetry-aware mean error and % < 0.25; direct mean error):\n")
        print("| class | pairs | ours (GSC trim) | pyFM WKS + ZoomOut |")
        print("|---|---|---|---|")
        for cls in classes:
            group = [c for c in tosca_all if c["name"].split("-")[0].rstrip("0123456789") == cls]
            cells = []
            for method in ("ours-gsc", "pyfm"):
                ok = [c["methods"][method] for c in group if method in c["methods"] and not c["methods"][method].get("failed")]
                cells.append(f"{mean(m['dense_symmetric']['mean'] for m in ok):.3f}, {100 * mean(m['dense_symmetric']['within_0.25'] for m in ok):.1f} %; "
                             f"direct {mean(m['dense_direct']['mean'] for m in ok):.3f}")
            print(f"| {cls} | {len(group)} | " + " | ".join(cells) + " |")
    # sparse matches per level (ours, GSC trim)
    tosca = [c for c in cases if c["kind"] == "tosca" and "ours-gsc" in c["methods"]]
    if tosca:
        levels = max(len(c["methods"]["ours-gsc"]["sparse_symmetric"]) for c in tosca)
        print("\nSparse matches of each level (ours, GSC trim, TOSCA): matches with ground truth, mean error "
              "(direct; symmetry-aware), % within 0.25 (symmetry-aware), seconds of the level:\n")
        print("| level | matches | mean error, direct | mean error, symmetry-aware | % < 0.25 | seconds |")
        print("|---|---|---|---|---|---|")
        per_level = []
        for level in range(levels):
            d = [e for c in tosca for e in c["methods"]["ours-gsc"]["sparse_direct"][level]]
            s = [e for c in tosca for e in c["methods"]["ours-gsc"]["sparse_symmetric"][level]]
            secs = mean(c["methods"]["ours-gsc"]["levels"][level]["matching_seconds"] + c["methods"]["ours-gsc"]["levels"][level]["local_seconds"]
                        for c in tosca)
            per_level.append(s)
            print(f"| {level} | {len(s)} | {mean(d):.3f} | {mean(s):.3f} | {100 * mean(1.0 if e <= 0.25 else 0.0 for e in s):.1f} | {secs:.2f} |")
        summary["tosca_sparse_levels"] = [{"matches": len(s), "mean_symmetric": mean(s)} for s in per_level]
        # figure: cumulative curves of the levels' sparse matches and of the dense maps
        plt.figure(figsize=(6.4, 4.8))
        for level, s in enumerate(per_level):
            plt.plot(THRESHOLDS, cumulative(s), label=f"ours, sparse level {level}")
        for method, style in (("ours-gsc", "-"), ("pyfm", "--")):
            for key, width in (("curve_symmetric", 2.5), ("curve_direct", 1.0)):
                cm = curve_mean(tosca, method, key)
                if cm:
                    plt.plot(THRESHOLDS, cm, style, linewidth=width, color="k" if method == "pyfm" else "tab:red",
                             label=f"{LABEL[method]}, dense, {'symmetry-aware' if key == 'curve_symmetric' else 'direct'}")
        finish_curve_figure(f"TOSCA test pairs ({len(tosca)})", os.path.join(figures, "isometric_tosca_curves.png"))
        # figure 5.6: time of each level against its number of new matches
        plt.figure(figsize=(6.4, 4.8))
        for level in range(levels):
            xs = [c["methods"]["ours-gsc"]["levels"][level]["new_matches"] for c in tosca]
            ys = [c["methods"]["ours-gsc"]["levels"][level]["matching_seconds"] + c["methods"]["ours-gsc"]["levels"][level]["local_seconds"] for c in tosca]
            plt.scatter(xs, ys, s=10, label=f"level {level}" + (" (coarse program)" if level == 0 else ""))
        finish_figure("time against new matches (thesis fig. 5.6)", "new matches of the level", "seconds (matching + local optimization)",
                      os.path.join(figures, "isometric_time_per_level.png"))
        # figure 5.7: mean error of all matches against the local-optimization sweep, per level
        plt.figure(figsize=(6.4, 4.8))
        for level in range(levels):
            runs = [c["methods"]["ours-gsc"]["sweeps_symmetric"][level] for c in tosca if c["methods"]["ours-gsc"]["sweeps_symmetric"][level]]
            n = max(len(r) for r in runs)
            padded = [r + [r[-1]] * (n - len(r)) for r in runs]  # a level that stopped keeps its last value
            plt.plot(range(n), [mean(p[i] for p in padded) for i in range(n)], marker="o", markersize=3, label=f"level {level}")
        finish_figure("error per level against local optimization (thesis fig. 5.7)", "local optimization sweep (0: before)",
                      "mean geodesic error / sqrt(area), symmetry-aware", os.path.join(figures, "isometric_local_optimization.png"))
    # the other groups' dense curves
    for kind, title in GROUPS[1:]:
        group = [c for c in cases if c["kind"] == kind]
        if not group:
            continue
        plt.figure(figsize=(6.4, 4.8))
        for method, color in (("ours-gsc", "tab:red"), ("ours-wks", "tab:blue"), ("ours-isc", "tab:green"), ("pyfm", "k")):
            for key, style in (("curve_symmetric", "-"), ("curve_direct", ":")):
                cm = curve_mean(group, method, key)
                if cm:
                    plt.plot(THRESHOLDS, cm, style, color=color, label=f"{LABEL[method]}, {'symmetry-aware' if key == 'curve_symmetric' else 'direct'}")
        finish_curve_figure(f"{title} ({len(group)})", os.path.join(figures, f"isometric_{kind}_curves.png"))
    with open(os.path.join(results, "summary.json"), "w") as f:
        json.dump(summary, f, indent=1)


if __name__ == "__main__":
    main()
