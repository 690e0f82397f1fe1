#!/usr/bin/env python3
# Copyright (c) 2026 ShapeCorr contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""The peer of the chapter-5 evaluation: pyFM's functional map with WKS descriptors refined by
ZoomOut (the call of ../shared/peers/README.md), run as a separate process.

usage: pyfm_map.py PEERS SOURCE TARGET MAP [W_ORIENT]
W_ORIENT (default 0): the weight of pyFM's orientation-preserving term (Ren et al. 2018), which
its README recommends for direct maps: `fit(..., w_orient=W_ORIENT, orient_reversing=False)`
(pyFM rescales it internally against the descriptor term).
Writes MAP: a comment line, then for each source vertex (0-based) its target vertex, the format
of `shapecorr correspond --output`; prints the seconds of the work (loading, spectra, fit,
ZoomOut; not the Python start-up) on stdout as `seconds S`.
"""
import os
import sys
import time


def main():
    if len(sys.argv) not in (5, 6):
        sys.exit(__doc__)
    peers, source, target, out = sys.argv[1:5]
    w_orient = float(sys.argv[5]) if len(sys.argv) == 6 else 0.0
    sys.path[:0] = [os.path.join(peers, 'pyFM'), os.path.join(peers, 'python-shims')]
    from pyFM.mesh import TriMesh
    from pyFM.functional import FunctionalMapping
    t0 = time.perf_counter()
    # pyFM's p2p sends each vertex of its second mesh to one of its first: the target goes first
    m1, m2 = TriMesh(target), TriMesh(source)
    fm = FunctionalMapping(m1, m2)
    fm.preprocess(n_ev=(35, 35), subsample_step=5, descr_type='WKS', n_descr=100, verbose=False)
    fm.fit(w_descr=1e0, w_lap=1e-2, w_dcomm=1e-1, w_orient=w_orient, orient_reversing=False, optinit='zeros', verbose=False)
    fm.zoomout_refine(nit=15, step=1, verbose=False)
    p2p = fm.get_p2p()
    seconds = time.perf_counter() - t0
    if len(p2p) != m2.n_vertices:
        sys.exit(f'pyfm_map: {len(p2p)} matches for {m2.n_vertices} source vertices')
    with open(out, 'w') as f:
        f.write(f'# pyFM WKS + ZoomOut (w_orient {w_orient:g}): line i (after the comments) is the target vertex (0-based) of source vertex i\n')
        f.writelines(f'{int(t)}\n' for t in p2p)
    print(f'seconds {seconds:.3f}')


if __name__ == '__main__':
    main()
