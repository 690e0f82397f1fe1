// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: connected components of the vertices of a triangle array (union-find).
#ifndef SHAPECORR_INTERNAL_COMPONENTS_H
#define SHAPECORR_INTERNAL_COMPONENTS_H

#include <shapecorr/internal/indexed_mesh.h>

#include <Eigen/Core>

#include <numeric>
#include <vector>

namespace shapecorr {
namespace internal {

/// Component id per vertex (0..k-1, ordered by smallest vertex index); isolated vertices get their
/// own component. Returns k.
inline std::size_t vertex_components(std::size_t n, const Eigen::Matrix<int, Eigen::Dynamic, 3, Eigen::RowMajor>& F,
                                     std::vector<int>& component) {
  std::vector<int> parent(n);
  std::iota(parent.begin(), parent.end(), 0);
  auto find = [&](int x) {
    while(parent[static_cast<std::size_t>(x)] != x) {
      parent[static_cast<std::size_t>(x)] = parent[static_cast<std::size_t>(parent[static_cast<std::size_t>(x)])];
      x = parent[static_cast<std::size_t>(x)];
    }
    return x;
  };
  for(Eigen::Index f = 0; f < F.rows(); ++f)
    for(int k = 1; k < 3; ++k) {
      const int a = find(F(f, 0)), b = find(F(f, k));
      if(a != b) parent[static_cast<std::size_t>(std::max(a, b))] = std::min(a, b);
    }
  component.assign(n, -1);
  std::size_t count = 0;
  std::vector<int> root_id(n, -1);
  for(std::size_t v = 0; v < n; ++v) {
    const int r = find(static_cast<int>(v));
    if(root_id[static_cast<std::size_t>(r)] < 0) root_id[static_cast<std::size_t>(r)] = static_cast<int>(count++);
    component[v] = root_id[static_cast<std::size_t>(r)];
  }
  return count;
}

} // namespace internal
} // namespace shapecorr

#endif
