#!/usr/bin/env python3
# Copyright (c) 2026 ShapeCorr contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The shape-model workflow, run locally by Snakemake on generated specimens: every rule ran (a fit
per specimen with its report, the model, the report's files), the model's summary is sane (modes,
explained fractions adding up, generalization and specificity curves), and a second run has
nothing to do. Exit 77 (skipped) without snakemake.

usage: test_workflow.py SOURCE_DIR SHAPECORR WORK_DIR
"""
import json
import os
import shutil
import subprocess
import sys


def main():
    source, shapecorr, work = sys.argv[1:4]
    snakemake = shutil.which("snakemake")
    if not snakemake:
        print("workflow test skipped: snakemake is not installed (apt-get install snakemake; scripts/setup does)")
        return 77
    shutil.rmtree(work, ignore_errors=True)
    config = subprocess.run([sys.executable, os.path.join(source, "workflow", "demo_config.py"), work, "--shapecorr", shapecorr, "--count", "4",
                             "--subdivisions", "3"], check=True, capture_output=True, text=True).stdout.strip()
    command = [snakemake, "-s", os.path.join(source, "workflow", "Snakefile"), "--configfile", config, "--cores", "2", "--directory", work]
    run = subprocess.run(command, capture_output=True, text=True)
    if run.returncode != 0:
        print(run.stdout, run.stderr)
        return 1
    results = os.path.join(work, "results")
    failures = []
    for i in range(1, 5):
        for ext in ("ply", "json"):
            if not os.path.isfile(os.path.join(results, "fits", f"specimen_{i:02d}.{ext}")):
                failures.append(f"fits/specimen_{i:02d}.{ext} missing")
        with open(os.path.join(results, "fits", f"specimen_{i:02d}.json")) as f:
            fit = json.load(f)
        # NICPS never moves the template away; specimen 2 is the template's own surface, finer (nothing to do)
        if not fit["distance_after"]["l2"] <= fit["distance_after_rigid"]["l2"] or (i != 2 and not fit["distance_after"]["l2"] < 0.8 * fit["distance_after_rigid"]["l2"]):
            failures.append(f"specimen {i}: NICPS did not bring the template closer: {fit['distance_after_rigid']} -> {fit['distance_after']}")
    for name in ("model.ssm", "report/summary.json", "report/quality.csv", "report/compactness.png", "report/mode1_plus3sd.ply"):
        if not os.path.isfile(os.path.join(results, name)):
            failures.append(f"{name} missing")
    with open(os.path.join(results, "report", "summary.json")) as f:
        s = json.load(f)
    if s["training_shapes"] != 4 or s["modes"] != 3:
        failures.append(f"summary: {s['training_shapes']} shapes, {s['modes']} modes (expected 4 and 3)")
    if abs(sum(s["explained_variance_ratios"]) - 1) > 1e-6:
        failures.append(f"explained fractions add up to {sum(s['explained_variance_ratios'])}")
    if len(s["generalization"]["value"]) != 2 or len(s["specificity"]["value"]) != 3:
        failures.append(f"curves: {s['generalization']}, {s['specificity']}")
    again = subprocess.run(command + ["--dry-run", "--quiet"], capture_output=True, text=True)
    if again.returncode != 0 or "fit" in again.stdout:
        failures.append(f"a second run would redo work: {again.stdout}")
    for f in failures:
        print("FAILED:", f)
    if not failures:
        print(f"workflow: 4 fits, model and report; explained {[round(r, 3) for r in s['explained_variance_ratios']]}")
    return 1 if failures else 0


if __name__ == "__main__":
    sys.exit(main())
