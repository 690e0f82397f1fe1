#!/usr/bin/env python3
"""Prints the figures of benchmark/README.md from a bench_geodesics JSON file: times, errors and
ratios against the references measured in the same run."""
import json
import sys

# With --benchmark_repetitions the medians stand for each benchmark (this machine is noisy).
benchmarks = json.load(open(sys.argv[1]))["benchmarks"]
medians = {b["run_name"]: b for b in benchmarks if b.get("aggregate_name") == "median"}
runs = {}
for b in benchmarks:
    if b.get("run_type") == "aggregate":
        continue
    runs[b["name"]] = medians.get(b["run_name"], b)
if not runs:  # --benchmark_report_aggregates_only: the medians are all there is
    runs = {b["run_name"]: b for b in medians.values()}
ctx = json.load(open(sys.argv[1]))["context"]
def ms(b):
    t = b["real_time"]
    return {"ns": t / 1e6, "us": t / 1e3, "ms": t, "s": t * 1e3}[b["time_unit"]]
# (the mesh's size from the first benchmark that reports it: a reference may come first)
first = next((b for b in runs.values() if "vertices" in b or "faces" in b), next(iter(runs.values())))
n = int(first.get("vertices", 0))
if n:
    print(f"mesh: {n} vertices, {ctx.get('num_cpus')} cpus")
else:
    print(f"mesh: {int(first.get('faces', 0))} faces, {ctx.get('num_cpus')} cpus")
ref = runs.get("BM_Reference_CGAL_HeatMethod_PerSource/iterations:1/real_time")
cgal_all = None
if ref:
    per = ms(ref) / ref["sources"]
    threads = ctx.get("num_cpus", 1)
    cgal_loop = per * n              # a plain loop over all sources, as a user writes it
    cgal_all = cgal_loop / threads   # the same loop perfectly parallelized (one CGAL object per thread)
    print(f"CGAL Heat_method_3: {per:.2f} ms/source -> all pairs {cgal_loop/1e3:.2f} s looping, "
          f"{cgal_all/1e3:.2f} s if split over {threads} threads (mean |err| {ref['mean_abs_err_pct_D']:.3f}% D)")
for name, b in runs.items():
    if name.startswith("BM_AllPairs"):  # noqa: every all-pairs variant
        line = f"{name}: {ms(b)/1e3:.3f} s, mean |err| vs exact {b['mean_abs_err_pct_D']:.3f}% D"
        if cgal_all:
            line += (f", {cgal_loop / ms(b):.1f}x faster than looping CGAL's heat method"
                     f" ({cgal_all / ms(b):.1f}x against the loop split over all cores)")
        print(line)
r = runs.get("BM_RadiusLimited_PerSource")
if r:
    print(f"radius-limited r=0.15D: {ms(r):.4f} ms/source, {r['mean_ball_vertices']:.0f} vertices per ball")
a = runs.get("BM_LocalAgd_AllVertices/iterations:3/real_time")
if a:
    print(f"local agd r=0.15D, all vertices: {ms(a)/1e3:.3f} s")
e = runs.get("BM_Exact_SingleSource/iterations:10")
h = runs.get("BM_Heat_SingleSource")
if e and h:
    print(f"exact single source: {ms(e):.1f} ms; heat single source: {ms(h):.2f} ms; ratio exact/heat {ms(e)/ms(h):.0f}x")
# Spectral (bench_spectral): eigen-solve and descriptors separately, the ratio to one Spectra run.
s = runs.get("BM_Eigenbasis300_Sliced/iterations:3")
o = runs.get("BM_Reference_Eigenbasis300_OneSpectraRun/iterations:3")
if s and o:
    print(f"300 eigenpairs, sliced shift-invert: {ms(s)/1e3:.3f} s; one Spectra run: {ms(o)/1e3:.3f} s "
          f"({ms(o)/ms(s):.1f}x); max |eigenvalue difference| {o['max_abs_eigenvalue_diff']:.2e}")
for name in ("BM_HKS_AllVertices", "BM_WKS_AllVertices", "BM_SIHKS_AllVertices"):
    d = runs.get(name)
    if d:
        print(f"{name}: {ms(d):.1f} ms, {ms(d) * 1e3 / d['vertices']:.2f} us per vertex")
t = runs.get("BM_Total_EigenbasisHksWks/iterations:3")
if t:
    print(f"eigenbasis + HKS + WKS, all vertices: {ms(t)/1e3:.3f} s")
# Rigid descriptors (bench_descriptors): per-point construction and per-pair comparison ratios.
sc = runs.get("BM_SpinContour")
fsi = runs.get("BM_Reference_FaceSpinImage")
if sc and fsi:
    print(f"Spin Contour: {ms(sc)*1e3:.0f} us ({sc['mean_points']:.0f} points); face-based spin image: {ms(fsi)*1e3:.0f} us "
          f"-> contour {ms(fsi)/ms(sc):.1f}x faster")
fx = runs.get("BM_ExactFaceSpinImage")
if fx and fsi:
    print(f"exact face-based spin image: {ms(fx)*1e3:.0f} us ({ms(fx)/ms(fsi):.2f}x the sampled one)")
si = runs.get("BM_SpinImage")
if si:
    print(f"spin image (vertices): {ms(si)*1e3:.0f} us")
cc = runs.get("BM_CompareContours")
ci = runs.get("BM_Reference_CompareImages")
if cc and ci:
    print(f"compare two contours: {ms(cc)*1e3:.1f} us; two images (correlation): {ms(ci)*1e3:.1f} us -> ratio {ms(ci)/ms(cc):.2f}")
ck = runs.get("BM_CompareContours_KdTree")
if ck and cc:
    print(f"compare two contours with kd-trees: {ms(ck)*1e3:.1f} us ({ms(ck)/ms(cc):.1f}x the row search)")
cf = runs.get("BM_CompareContours_DistanceField")
if cf and ci and cc:
    print(f"compare two prepared contours (distance fields, approximate L1): {ms(cf)*1e3:.2f} us -> {ms(ci)/ms(cf):.1f}x faster than two images, "
          f"{ms(cc)/ms(cf):.1f}x than the exact L1; largest error {cf['max_abs_error']:.2g} ({100*cf['max_rel_error']:.1f}% relative, bound {cf['error_bound']:.2g}), "
          f"{cf['field_bytes']/1024:.1f} KB per field")
cp = runs.get("BM_ContourDistanceField_Prepare")
if cp and sc:
    print(f"prepare a distance field: {ms(cp)*1e3:.0f} us ({ms(cp)/ms(sc):.2f}x building the contour)")
cn = runs.get("BM_CompareContours_NearestPointIndex")
if cn and ci and cc:
    print(f"compare two prepared contours (nearest-point indices, exact L1): {ms(cn)*1e3:.2f} us -> {ms(ci)/ms(cn):.1f}x faster than two images, "
          f"{ms(cc)/ms(cn):.1f}x than the row search; largest difference from it {cn['max_abs_difference']:.2g}, "
          f"{cn['index_bytes']/1024:.1f} KB per index, {100*cn['slow_cells']:.2f}% slow cells, {cn['pieces']:.0f} envelope pieces")
cnp = runs.get("BM_ContourNearestPointIndex_Prepare")
if cnp and sc:
    print(f"prepare a nearest-point index: {ms(cnp)*1e3:.0f} us ({ms(cnp)/ms(sc):.2f}x building the contour)")
mn = runs.get("BM_MatchNearestPointIndex_PerComparison")
mf = runs.get("BM_MatchDistanceField_PerComparison")
mc = runs.get("BM_MatchContour_PerComparison")
mi = runs.get("BM_Reference_MatchImage_PerComparison")
if mc and mi:
    print(f"matching, per comparison: contour {ms(mc)*1e3/64:.2f} us (early exit), image {ms(mi)*1e3/64:.2f} us -> {ms(mi)/ms(mc):.1f}x")
if mn and mi:
    print(f"matching, per comparison: nearest-point indices {ms(mn)*1e3/64:.2f} us (early exit, exact) -> {ms(mi)/ms(mn):.1f}x an image")
if mf and mi:
    print(f"matching, per comparison: distance fields {ms(mf)*1e3/64:.2f} us (early exit) -> {ms(mi)/ms(mf):.1f}x an image")
for name in ("BM_PCL_SpinImage", "BM_PCL_SHOT352"):
    p = runs.get(name)
    if p and sc:
        print(f"{name}: {ms(p)*1e3:.0f} us per point ({ms(p)/ms(sc):.2f}x the Spin Contour)")
# Geodesic Spin Contour (bench_geodesic_spin): one contour from given distances, all vertices with
# every geodesic computation, against the geodesic spin image and all-pairs fast marching.
g = runs.get("BM_GSC_FromDistances")
gi = runs.get("BM_Reference_GeodesicSpinImage_FromDistances")
if g:
    line = f"GSC from distances: {ms(g)*1e3:.0f} us ({g['mean_points']:.0f} points, ball of {g['mean_ball']:.0f} vertices)"
    if gi:
        line += f"; geodesic spin image from the same ball: {ms(gi)*1e3:.1f} us (GSC/GSI {ms(g)/ms(gi):.1f}x)"
    print(line)
clk = runs.get("BM_Reference_ClockCycles")
if clk:
    ghz = clk["adds"] / (ms(clk) * 1e6)  # one dependent addition per cycle
    line = f"clock reference: {ghz:.2f} GHz effective (a chain of dependent additions)"
    if g:
        line += f"; one GSC = {ms(g) * 1e6 * ghz / 1e3:.0f} k cycles"
    if gi:
        line += f", geodesic spin image = {ms(gi) * 1e6 * ghz / 1e3:.0f} k cycles"
    print(line)
gt = runs.get("BM_GSC_AllVertices_FromDistances/iterations:3/manual_time")
if gt:
    per = ms(gt) * 1e3 / gt["vertices"]
    line = f"GSCs of all {int(gt['vertices'])} vertices from given distances on {int(gt['threads'])} threads: {ms(gt):.0f} ms, {per:.0f} us of wall time per contour"
    if g:
        line += f" ({ms(g)*1e3/per:.2f}x the one-contour time)"
    print(line)
gb = runs.get("BM_GSC_SupportBall")
if gb:
    print(f"radius-limited march to L + longest edge: {ms(gb)*1e3:.0f} us per point")
ga = runs.get("BM_GSC_AllVertices/iterations:1/real_time")
ap = runs.get("BM_Reference_AllPairsFastMarching/iterations:1/real_time")
if ga:
    line = f"GSC of all {int(ga['vertices'])} vertices incl. diameter, local agd and every march: {ms(ga)/1e3:.2f} s"
    if ap:
        line += f"; all-pairs fast marching alone: {ms(ap)/1e3:.2f} s (ratio {ms(ga)/ms(ap):.2f})"
    print(line)
# Registration (bench_registration): a NICPS iteration against its own numeric factorization.
nv = runs.get("BM_Nicps_Vertebra/iterations:1/real_time")
if nv:
    print(f"NICPS {int(nv['template_vertices'])} -> {int(nv['target_vertices'])} vertices: {int(nv['iterations'])} iterations, {ms(nv)/1e3:.2f} s; "
          f"per iteration {nv['iteration_ms']:.1f} ms = {nv['iteration_over_factorization']:.2f}x its factorization ({nv['factorization_ms']:.1f} ms), "
          f"search {nv['search_ms']:.1f} ms; peak RSS {nv['peak_rss_mb']:.0f} MB")
ra = runs.get("BM_RigidAlignment_Vertebra/iterations:3/real_time")
if ra:
    print(f"rigid ICP (no initialization), same meshes: {ms(ra):.0f} ms")
# Automatic correspondence (bench_isometric): the coarse program's two solvers, the pipeline
# against all-pairs geodesics of both shapes.
bb = runs.get("BM_CoarseProgram_BranchAndBound/real_time")
gl = runs.get("BM_Reference_CoarseProgram_Glpk/real_time")
if bb and gl:
    print(f"coarse program ({bb['features']:.0f} features, {bb['candidates']:.0f} candidate pairs): branch and bound {ms(bb):.3f} ms "
          f"({bb['nodes']:.0f} nodes, optimal {bb['optimal']:.0f}), GLPK {ms(gl):.1f} ms (optimal {gl['optimal']:.0f}) -> {ms(gl)/ms(bb):.0f}x; "
          f"objectives {bb['objective']:.6g} / {gl['objective']:.6g}")
pl = runs.get("BM_Pipeline/iterations:1/real_time")
ap = runs.get("BM_Reference_AllPairsGeodesics_BothShapes/iterations:1/real_time")
if pl and ap:
    print(f"pipeline: {ms(pl)/1e3:.2f} s; all-pairs geodesics of both shapes: {ms(ap)/1e3:.2f} s -> ratio {ms(pl)/ms(ap):.2f}")
# Shape model (bench_shape_model): the Gram route against the dense SVD of the same data matrix.
gm = runs.get("BM_Pca_GramMatrix/real_time")
sv = runs.get("BM_Reference_Pca_DenseSvd/real_time")
bm = runs.get("BM_BuildModel/real_time")
if gm and sv:
    print(f"PCA of {gm['shapes']:.0f} shapes x {gm['vertices']:.0f} vertices: Gram matrix {ms(gm):.1f} ms, dense SVD {ms(sv):.1f} ms -> "
          f"{ms(sv)/ms(gm):.1f}x; variances agree to {gm['variance_rel_diff']:.1e} (relative)" + (f"; whole build (Procrustes + PCA) {ms(bm):.0f} ms" if bm else ""))
