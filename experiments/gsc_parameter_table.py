#!/usr/bin/env python3
# The tables of the GSC parameter study (doc/geodesic_spin_contour.md) from the summary.json files
# that scripts/gsc-parameter-study writes under DIR/L<support>_r<radius>/; with --combine FILE also
# writes them into one JSON file (doc/figures/geodesic/parameter_study.json).
import glob
import json
import os
import sys


def load(root):
    runs = []
    for path in sorted(glob.glob(os.path.join(root, 'L*_r*', 'summary.json'))):
        name = os.path.basename(os.path.dirname(path))
        support, radius = name[1:].split('_r')
        with open(path) as f:
            runs.append((support, radius, json.load(f)['cases']))
    return runs


def mean(values):
    return sum(values) / len(values) if values else float('nan')


def main():
    args = sys.argv[1:]
    combine = None
    if '--combine' in args:
        i = args.index('--combine')
        combine = args[i + 1]
        del args[i:i + 2]
    root = args[0] if args else 'experiments/results/gsc-parameters'
    runs = load(root)
    if not runs:
        sys.exit('no L*_r*/summary.json under ' + root)
    keys = ['hit_rate_1pct', 'geodesic_error_k1', 'geodesic_error_k1_sym']
    print('| L / D | r / D | whole: hit rate at 1% | whole: error k=1 | whole: error k=1, symmetric counted '
          '| partial: hit rate at 1% | partial: error k=1 | partial: error k=1, symmetric counted |')
    print('|---|---|---|---|---|---|---|---|')
    for support, radius, cases in runs:
        cells = []
        for whole in (True, False):
            chosen = [c['GSC'] for n, c in cases.items() if n.endswith('-whole') == whole]
            cells += ['%.3f' % mean([c[k] for c in chosen]) for k in keys]
        print('| %s | %s | %s |' % (support, radius, ' | '.join(cells)))
    pairs = sorted({n.rsplit('-', 1)[0] for _, _, cases in runs for n in cases})
    print()
    print('Per pair (mean over its variants): hit rate at 1% / error at k=1 with the symmetric match counted')
    print()
    print('| L / D | r / D | ' + ' | '.join(pairs) + ' |')
    print('|---|---|' + '---|' * len(pairs))
    for support, radius, cases in runs:
        cells = []
        for p in pairs:
            chosen = [c['GSC'] for n, c in cases.items() if n.rsplit('-', 1)[0] == p]
            cells.append('%.2f / %.3f' % (mean([c['hit_rate_1pct'] for c in chosen]), mean([c['geodesic_error_k1_sym'] for c in chosen])))
        print('| %s | %s | %s |' % (support, radius, ' | '.join(cells)))
    if combine:
        with open(combine, 'w') as f:
            json.dump({'L%s_r%s' % (s, r): cases for s, r, cases in runs}, f, indent=1, sort_keys=True)


if __name__ == '__main__':
    main()
