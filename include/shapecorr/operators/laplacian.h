// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file laplacian.h
/// Discrete Laplace operators of a triangle mesh: the cotangent Laplacian, its lumped mass
/// matrices, and the combinatorial (graph) Laplacian.
#ifndef SHAPECORR_OPERATORS_LAPLACIAN_H
#define SHAPECORR_OPERATORS_LAPLACIAN_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/internal/intrinsic_triangulation.h>
#include <shapecorr/parameters.h>
#include <shapecorr/internal/cotangent_operators.h>

#include <Eigen/Sparse>

namespace shapecorr {

/// \ingroup PkgShapeCorrOperators
/// How vertex areas (the diagonal of the lumped mass matrix) are computed.
enum class Mass_matrix_type {
  BARYCENTRIC,   ///< a third of the area of every incident triangle
  MIXED_VORONOI  ///< Meyer et al. 2003: Voronoi regions, with the obtuse-triangle rule
};

/// \ingroup PkgShapeCorrOperators
/// The cotangent Laplacian and the lumped mass matrix of one mesh, built together (one pass over
/// the triangles), in the order of its vertex index map.
struct Laplace_operators {
  Eigen::SparseMatrix<double> L; ///< cotangent Laplacian, positive semi-definite (see `cotangent_laplacian`)
  Eigen::VectorXd mass;          ///< lumped mass: the diagonal of M, vertex areas summing to the surface area
  std::size_t flips = 0;         ///< edge flips done to reach the intrinsic Delaunay triangulation (0 without it)
};

namespace internal {

inline void require_usable_arrays(const Triangle_arrays& a, const char* what) {
  if(a.number_of_vertices() == 0 || a.number_of_faces() == 0)
    throw Invalid_input(Mesh_defect::empty_mesh, std::string(what) + ": the mesh has no vertex or no face");
  if(!a.V.allFinite())
    throw Invalid_input(Mesh_defect::non_finite_coordinate, std::string(what) + ": the mesh has NaN or infinite coordinates");
}

inline Laplace_operators laplace_operators(const Triangle_arrays& a, bool intrinsic_delaunay, Mass_matrix_type mass_type) {
  require_usable_arrays(a, "Laplace-Beltrami operator");
  Intrinsic_triangulation tri = Intrinsic_triangulation::from_arrays(a);
  Laplace_operators op;
  if(intrinsic_delaunay) op.flips = tri.make_delaunay();
  op.L = cotangent_laplacian(tri);
  op.mass = mass_type == Mass_matrix_type::MIXED_VORONOI ? mixed_voronoi_mass(tri) : lumped_mass(tri);
  return op;
}

} // namespace internal

/// \ingroup PkgShapeCorrOperators
/// The cotangent Laplacian and the lumped mass matrix of `tm` at once (cheaper than calling
/// `cotangent_laplacian` and `lumped_mass_matrix` separately: the triangulation is read once).
/// \param np optional named parameters: those of `cotangent_laplacian` and `mass_matrix_type`
/// (`Mass_matrix_type`, default `BARYCENTRIC`).
/// \throws Invalid_input for an empty mesh, non-triangle faces or non-finite coordinates
/// \code
///   const shapecorr::Laplace_operators op = shapecorr::laplace_operators(tm);
///   // op.L * u, op.mass.asDiagonal() * u, ...
/// \endcode
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Laplace_operators laplace_operators(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const internal::Indexed_mesh<TriangleMesh> mesh(tm, np);
  return internal::laplace_operators(mesh.arrays(), choose_parameter(get_parameter(np, internal_np::use_intrinsic_delaunay), false),
                                     choose_parameter(get_parameter(np, internal_np::mass_matrix_type), Mass_matrix_type::BARYCENTRIC));
}

/// \ingroup PkgShapeCorrOperators
/// The cotangent Laplacian of `tm`, **positive semi-definite**:
/// `(L u)_i = 1/2 sum_j (cot a_ij + cot b_ij) (u_i - u_j)`, so `L 1 = 0` and `u^T L u >= 0` on a
/// Delaunay mesh. Rows and columns follow the vertex index map. Boundary edges have one cotangent
/// (natural, Neumann, boundary conditions). Faces of zero area contribute nothing.
/// \param np optional named parameters:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `vertex_point_map` | positions | `ReadablePropertyMap<vertex_descriptor, Point_3>` | `get(CGAL::vertex_point, tm)` |
/// | `vertex_index_map` | 0-based vertex indices | `ReadablePropertyMap<vertex_descriptor, size_t>` | the mesh's own, or a fresh one |
/// | `use_intrinsic_delaunay` | build it on the intrinsic Delaunay triangulation (Bobenko & Springborn 2007): non-negative weights, robust to obtuse and needle triangles | `bool` | `false` |
/// \throws Invalid_input for an empty mesh, non-triangle faces or non-finite coordinates
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Eigen::SparseMatrix<double> cotangent_laplacian(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values()) {
  return laplace_operators(tm, np).L;
}

/// \ingroup PkgShapeCorrOperators
/// The diagonal of the lumped mass matrix M of `tm` (vertex areas; they sum to the surface area),
/// in the order of the vertex index map. Isolated vertices get 0.
/// \param np as `cotangent_laplacian`, plus `mass_matrix_type` (`Mass_matrix_type`, default
/// `BARYCENTRIC`).
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Eigen::VectorXd lumped_mass_matrix(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values()) {
  return laplace_operators(tm, np).mass;
}

/// \ingroup PkgShapeCorrOperators
/// The combinatorial (graph) Laplacian `L = D - A` of the edges of `tm` (weight 1 per edge), positive
/// semi-definite, `L 1 = 0`; rows follow the vertex index map. Used by the Laplacian regularization of
/// non-rigid ICP (thesis chapter 6) where the geometry is still to be found.
/// \param np `vertex_index_map` (optional)
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Eigen::SparseMatrix<double> combinatorial_laplacian(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values()) {
  const internal::Indexed_mesh<TriangleMesh> mesh(tm, np);
  if(mesh.number_of_vertices() == 0) throw Invalid_input(Mesh_defect::empty_mesh, "combinatorial Laplacian: the mesh has no vertex");
  return internal::combinatorial_laplacian(mesh.arrays());
}

} // namespace shapecorr

#endif
