// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file write_correspondences.h
/// Two meshes side by side with lines between corresponding vertices, for viewing matches
/// (MeshLab, Blender, ParaView).
#ifndef SHAPECORR_IO_WRITE_CORRESPONDENCES_H
#define SHAPECORR_IO_WRITE_CORRESPONDENCES_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/parameters.h>

#include <Eigen/Core>

#include <fstream>
#include <string>
#include <utility>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrIO
/// Writes `source` and `target` into one file, the target shifted along +x so that the two
/// bounding boxes are side by side with a gap of 20% of the source's width, and one line per pair
/// (source vertex index, target vertex index; indices of the meshes' vertex index maps).
/// `.obj`: vertices, faces and `l` line elements. `.ply` (ASCII): vertices, faces and an `edge`
/// element with colours: black for pairs flagged correct in `correct` (same length as `pairs`),
/// red for the others, black for all when `correct` is empty.
/// \throws Invalid_input for an unknown extension, indices out of range, or a file that cannot be written
template <typename SourceMesh, typename TargetMesh>
void write_correspondences(const std::string& path, const SourceMesh& source, const TargetMesh& target,
                           const std::vector<std::pair<std::size_t, std::size_t>>& pairs, const std::vector<bool>& correct = {}) {
  const internal::Indexed_mesh<SourceMesh> s(source, CGAL::parameters::default_values());
  const internal::Indexed_mesh<TargetMesh> t(target, CGAL::parameters::default_values());
  const auto& A = s.arrays();
  const auto& B = t.arrays();
  const std::size_t ns = A.number_of_vertices(), nt = B.number_of_vertices();
  for(const auto& p : pairs)
    if(p.first >= ns || p.second >= nt)
      throw Invalid_argument("write_correspondences: pair (" + std::to_string(p.first) + ", " +
                                                             std::to_string(p.second) + ") out of range");
  if(!correct.empty() && correct.size() != pairs.size())
    throw Invalid_argument("write_correspondences: one correctness flag per pair expected");
  const double shift = (A.V.col(0).maxCoeff() - B.V.col(0).minCoeff()) + 0.2 * (A.V.col(0).maxCoeff() - A.V.col(0).minCoeff());
  const std::string ext = path.size() > 4 ? path.substr(path.size() - 4) : "";
  std::ofstream out(path);
  if(!out) throw Output_error("write_correspondences: cannot write '" + path + "'");
  out.precision(9);
  auto vertex = [&](std::size_t i) {
    if(i < ns) out << A.V(static_cast<Eigen::Index>(i), 0) << ' ' << A.V(static_cast<Eigen::Index>(i), 1) << ' ' << A.V(static_cast<Eigen::Index>(i), 2);
    else {
      const Eigen::Index j = static_cast<Eigen::Index>(i - ns);
      out << B.V(j, 0) + shift << ' ' << B.V(j, 1) << ' ' << B.V(j, 2);
    }
  };
  if(ext == ".obj") {
    out << "# shapecorr: source (first " << ns << " vertices), target shifted by " << shift << " along x, " << pairs.size() << " correspondence lines\n";
    for(std::size_t i = 0; i < ns + nt; ++i) {
      out << "v ";
      vertex(i);
      out << '\n';
    }
    for(Eigen::Index f = 0; f < A.F.rows(); ++f) out << "f " << A.F(f, 0) + 1 << ' ' << A.F(f, 1) + 1 << ' ' << A.F(f, 2) + 1 << '\n';
    for(Eigen::Index f = 0; f < B.F.rows(); ++f)
      out << "f " << B.F(f, 0) + 1 + static_cast<long>(ns) << ' ' << B.F(f, 1) + 1 + static_cast<long>(ns) << ' ' << B.F(f, 2) + 1 + static_cast<long>(ns) << '\n';
    for(const auto& p : pairs) out << "l " << p.first + 1 << ' ' << p.second + 1 + ns << '\n';
  } else if(ext == ".ply") {
    out << "ply\nformat ascii 1.0\ncomment shapecorr correspondences: source, then target shifted along x\n"
        << "element vertex " << ns + nt << "\nproperty float x\nproperty float y\nproperty float z\n"
        << "element face " << A.F.rows() + B.F.rows() << "\nproperty list uchar int vertex_indices\n"
        << "element edge " << pairs.size() << "\nproperty int vertex1\nproperty int vertex2\n"
        << "property uchar red\nproperty uchar green\nproperty uchar blue\nend_header\n";
    for(std::size_t i = 0; i < ns + nt; ++i) {
      vertex(i);
      out << '\n';
    }
    for(Eigen::Index f = 0; f < A.F.rows(); ++f) out << "3 " << A.F(f, 0) << ' ' << A.F(f, 1) << ' ' << A.F(f, 2) << '\n';
    for(Eigen::Index f = 0; f < B.F.rows(); ++f)
      out << "3 " << B.F(f, 0) + static_cast<long>(ns) << ' ' << B.F(f, 1) + static_cast<long>(ns) << ' ' << B.F(f, 2) + static_cast<long>(ns) << '\n';
    for(std::size_t k = 0; k < pairs.size(); ++k)
      out << pairs[k].first << ' ' << pairs[k].second + ns << (correct.empty() || correct[k] ? " 0 0 0\n" : " 230 20 20\n");
  } else {
    throw Invalid_argument("write_correspondences: the file must end in .obj or .ply: " + path);
  }
  if(!out) throw Output_error("write_correspondences: writing '" + path + "' failed");
}

} // namespace shapecorr

#endif
