#!/usr/bin/python3
# Copyright (c) 2026 ShapeCorr contributors.
# SPDX-License-Identifier: GPL-3.0-or-later
"""Open3D's point-to-plane ICP (the peer of ShapeCorr's rigid stage), run by evaluate_registration
as a separate process: the vertices of START registered to the vertices of TARGET (normals from the
target's triangles), at most 50 iterations within MAX_DISTANCE. Writes the 4x4 transform to OUT.

usage: open3d_icp.py START.ply TARGET.ply MAX_DISTANCE OUT.txt
"""
import sys

import numpy as np
import open3d as o3d


def main():
    start, target, distance, out = sys.argv[1], sys.argv[2], float(sys.argv[3]), sys.argv[4]
    s = o3d.io.read_triangle_mesh(start)
    t = o3d.io.read_triangle_mesh(target)
    t.compute_vertex_normals()
    src = o3d.geometry.PointCloud(s.vertices)
    dst = o3d.geometry.PointCloud(t.vertices)
    dst.normals = t.vertex_normals
    result = o3d.pipelines.registration.registration_icp(
        src, dst, distance, np.eye(4), o3d.pipelines.registration.TransformationEstimationPointToPlane(),
        o3d.pipelines.registration.ICPConvergenceCriteria(max_iteration=50))
    np.savetxt(out, result.transformation)
    return 0


if __name__ == "__main__":
    sys.exit(main())
