// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file write_colored_ply.h
#ifndef SHAPECORR_IO_WRITE_COLORED_PLY_H
#define SHAPECORR_IO_WRITE_COLORED_PLY_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/indexed_mesh.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <cmath>
#include <fstream>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrIO
/// Maps t in [0,1] to a perceptually ordered RGB colour (a 5-stop approximation of viridis:
/// dark blue at 0, yellow at 1). Non-finite t gives grey.
inline std::array<unsigned char, 3> colormap_viridis(double t) {
  if(!std::isfinite(t)) return {128, 128, 128};
  static const double stops[5][3] = {{68, 1, 84}, {59, 82, 139}, {33, 145, 140}, {94, 201, 98}, {253, 231, 37}};
  t = std::min(1.0, std::max(0.0, t)) * 4.0;
  const int i = std::min(3, static_cast<int>(t));
  const double u = t - i;
  std::array<unsigned char, 3> c;
  for(int k = 0; k < 3; ++k) c[static_cast<std::size_t>(k)] = static_cast<unsigned char>(std::lround(stops[i][k] * (1 - u) + stops[i + 1][k] * u));
  return c;
}

/// \ingroup PkgShapeCorrIO
/// Writes `tm` as an ASCII PLY whose vertices are coloured by `values` (one per vertex, in the
/// order of the vertex index map of `np`; linearly scaled from their finite min to max, viridis)
/// and carry the raw value as a `quality` property (MeshLab shows it). The vertices listed in
/// `highlight` (indices) are painted red, e.g. furthest-point samples or sources.
/// \throws Output_error when the file cannot be written
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void write_colored_ply(const std::string& path, const TriangleMesh& tm, const std::vector<double>& values,
                       const std::vector<std::size_t>& highlight = {},
                       const NamedParameters& np = CGAL::parameters::default_values()) {
  const internal::Indexed_mesh<TriangleMesh> im(tm, np);
  const auto& a = im.arrays();
  const std::size_t n = a.number_of_vertices();
  if(values.size() != n)
    throw Invalid_argument("write_colored_ply: " + std::to_string(values.size()) +
                                                           " values for " + std::to_string(n) + " vertices");
  double lo = INFINITY, hi = -INFINITY;
  for(double v : values) if(std::isfinite(v)) { lo = std::min(lo, v); hi = std::max(hi, v); }
  const double span = (hi > lo) ? hi - lo : 1.0;
  std::vector<char> red(n, 0);
  for(std::size_t h : highlight) if(h < n) red[h] = 1;
  std::ofstream out(path);
  if(!out) throw Output_error(path + ": cannot open for writing");
  out << "ply\nformat ascii 1.0\ncomment written by ShapeCorr; quality = value per vertex\nelement vertex " << n
      << "\nproperty float x\nproperty float y\nproperty float z\nproperty uchar red\nproperty uchar green\nproperty uchar blue\n"
         "property float quality\nelement face "
      << a.number_of_faces() << "\nproperty list uchar int vertex_indices\nend_header\n";
  out.precision(9);
  for(std::size_t i = 0; i < n; ++i) {
    const auto c = red[i] ? std::array<unsigned char, 3>{230, 20, 20} : colormap_viridis((values[i] - lo) / span);
    out << a.V(static_cast<Eigen::Index>(i), 0) << ' ' << a.V(static_cast<Eigen::Index>(i), 1) << ' ' << a.V(static_cast<Eigen::Index>(i), 2)
        << ' ' << int(c[0]) << ' ' << int(c[1]) << ' ' << int(c[2]) << ' ' << (std::isfinite(values[i]) ? values[i] : -1.0) << '\n';
  }
  for(Eigen::Index f = 0; f < a.F.rows(); ++f) out << "3 " << a.F(f, 0) << ' ' << a.F(f, 1) << ' ' << a.F(f, 2) << '\n';
  if(!out) throw Output_error(path + ": write failed");
}

} // namespace shapecorr

#endif
