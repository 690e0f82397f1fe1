// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Laplace_beltrami_eigenbasis.h
#ifndef SHAPECORR_SPECTRAL_LAPLACE_BELTRAMI_EIGENBASIS_H
#define SHAPECORR_SPECTRAL_LAPLACE_BELTRAMI_EIGENBASIS_H

#include <shapecorr/exceptions.h>
#include <shapecorr/parameters.h>
#include <shapecorr/spectral/Spectra_eigensolver.h>
#include <shapecorr/operators/laplacian.h>

#include <Eigen/Dense>

#include <cstdint>
#include <cstring>
#include <fstream>
#include <string>

namespace shapecorr {

/// \ingroup PkgShapeCorrSpectral
/// The k smallest eigenpairs of the Laplace-Beltrami operator of a mesh, `L phi_i = lambda_i M phi_i`
/// (L the positive semi-definite cotangent Laplacian, M the lumped mass; see `cotangent_laplacian`),
/// with `0 <= lambda_1 <= ... <= lambda_k` and M-orthonormal eigenvectors (`Phi^T M Phi = I`, so
/// `sum_x M_x phi_i(x)^2 = 1`). Row x of `eigenvectors()` belongs to the vertex of index x in the vertex
/// index map the basis was computed with. Neumann conditions on boundaries; each connected component
/// contributes one zero eigenvalue (its indicator function, normalized).
///
/// Computed once by `compute_laplace_beltrami_eigenbasis` and passed to every spectral descriptor
/// (named parameter `eigenbasis(&basis)`); `save` / `load` keep it in a binary file so large
/// experiments do not solve twice.
class Laplace_beltrami_eigenbasis {
public:
  Laplace_beltrami_eigenbasis() = default;
  /// \pre `vectors.rows() == mass.size()`, `vectors.cols() == values.size()`, values ascending.
  /// `operator_scale` (typically the mean of `L_ii / M_ii`, of the order of the largest eigenvalue of
  /// the mesh) sets what counts as a zero eigenvalue: at most 1e-8 times it; 0 = the largest value.
  Laplace_beltrami_eigenbasis(Eigen::VectorXd values, Eigen::MatrixXd vectors, Eigen::VectorXd mass, double operator_scale = 0)
    : m_values(std::move(values)), m_vectors(std::move(vectors)), m_mass(std::move(mass)), m_scale(operator_scale) {
    if(!(m_scale > 0)) m_scale = m_values.size() ? std::abs(m_values[m_values.size() - 1]) : 0.0;
    if(m_vectors.rows() != m_mass.size() || m_vectors.cols() != m_values.size())
      throw Invalid_argument("eigenbasis: sizes of eigenvalues, eigenvectors and mass disagree");
  }

  /// Number of vertices n.
  std::size_t number_of_vertices() const { return static_cast<std::size_t>(m_vectors.rows()); }
  /// Number of eigenpairs k.
  std::size_t number_of_eigenpairs() const { return static_cast<std::size_t>(m_values.size()); }
  /// The eigenvalues, ascending (k).
  const Eigen::VectorXd& eigenvalues() const { return m_values; }
  /// The eigenvectors as columns (n x k), M-orthonormal.
  const Eigen::MatrixXd& eigenvectors() const { return m_vectors; }
  /// The diagonal of the lumped mass matrix (n): the vertex areas.
  const Eigen::VectorXd& mass() const { return m_mass; }
  /// The operator scale (see the constructor).
  double operator_scale() const { return m_scale; }
  /// Number of eigenvalues that are zero up to `relative_tolerance` times the operator scale: the
  /// number of connected components when k exceeds it.
  std::size_t number_of_zero_eigenvalues(double relative_tolerance = 1e-8) const {
    if(m_values.size() == 0) return 0;
    const double tol = relative_tolerance * std::max(m_scale, 1e-300);
    std::size_t z = 0;
    while(z < number_of_eigenpairs() && m_values[static_cast<Eigen::Index>(z)] <= tol) ++z;
    return z;
  }

  /// Writes the basis to a binary file (native-endian; header "SCLBEIG1", n, k, operator scale, eigenvalues, mass, eigenvectors column-major).
  /// \throws Output_error when the file cannot be written
  void save(const std::string& path) const {
    std::ofstream out(path, std::ios::binary);
    if(!out) throw Output_error("eigenbasis: cannot write '" + path + "'");
    const std::uint64_t n = number_of_vertices(), k = number_of_eigenpairs();
    out.write(magic(), 8);
    out.write(reinterpret_cast<const char*>(&n), sizeof n);
    out.write(reinterpret_cast<const char*>(&k), sizeof k);
    out.write(reinterpret_cast<const char*>(&m_scale), sizeof m_scale);
    out.write(reinterpret_cast<const char*>(m_values.data()), static_cast<std::streamsize>(sizeof(double) * k));
    out.write(reinterpret_cast<const char*>(m_mass.data()), static_cast<std::streamsize>(sizeof(double) * n));
    out.write(reinterpret_cast<const char*>(m_vectors.data()), static_cast<std::streamsize>(sizeof(double) * n * k));
    if(!out) throw Output_error("eigenbasis: writing '" + path + "' failed");
  }

  /// Reads a basis written by `save`.
  /// \throws Invalid_input (`unreadable_file`) for a missing, truncated or foreign file
  static Laplace_beltrami_eigenbasis load(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if(!in) throw Invalid_input(Mesh_defect::unreadable_file, "eigenbasis: cannot open '" + path + "'");
    char head[8];
    std::uint64_t n = 0, k = 0;
    in.read(head, 8);
    in.read(reinterpret_cast<char*>(&n), sizeof n);
    in.read(reinterpret_cast<char*>(&k), sizeof k);
    double scale = 0;
    in.read(reinterpret_cast<char*>(&scale), sizeof scale);
    if(!in || std::memcmp(head, magic(), 8) != 0)
      throw Invalid_input(Mesh_defect::unreadable_file, "eigenbasis: '" + path + "' is not a ShapeCorr eigenbasis file");
    in.seekg(0, std::ios::end);
    const auto size = static_cast<std::uint64_t>(in.tellg());
    const std::uint64_t expected = 8 + 2 * sizeof(std::uint64_t) + sizeof(double) * (1 + k + n + n * k);
    if(n == 0 || k == 0 || k > n || size != expected)
      throw Invalid_input(Mesh_defect::unreadable_file, "eigenbasis: '" + path + "' is truncated or corrupt (" + std::to_string(size) +
                                                            " bytes for n = " + std::to_string(n) + ", k = " + std::to_string(k) + ")");
    in.seekg(8 + 2 * sizeof(std::uint64_t) + sizeof(double));
    Eigen::VectorXd values(static_cast<Eigen::Index>(k)), mass(static_cast<Eigen::Index>(n));
    Eigen::MatrixXd vectors(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(k));
    in.read(reinterpret_cast<char*>(values.data()), static_cast<std::streamsize>(sizeof(double) * k));
    in.read(reinterpret_cast<char*>(mass.data()), static_cast<std::streamsize>(sizeof(double) * n));
    in.read(reinterpret_cast<char*>(vectors.data()), static_cast<std::streamsize>(sizeof(double) * n * k));
    if(!in) throw Invalid_input(Mesh_defect::unreadable_file, "eigenbasis: reading '" + path + "' failed");
    return Laplace_beltrami_eigenbasis(std::move(values), std::move(vectors), std::move(mass), scale);
  }

private:
  static const char* magic() { return "SCLBEIG1"; }
  Eigen::VectorXd m_values;
  Eigen::MatrixXd m_vectors;
  Eigen::VectorXd m_mass;
  double m_scale = 0;
};

/// \ingroup PkgShapeCorrSpectral
/// The `k` smallest eigenpairs of the Laplace-Beltrami operator of `tm` (see
/// `Laplace_beltrami_eigenbasis` for the conventions).
/// \tparam TriangleMesh a model of `FaceListGraph` with triangle faces
/// \param k number of eigenpairs (thesis: 300), `1 <= k <= num_vertices(tm)`
/// \param np optional named parameters:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `vertex_point_map` | positions | `ReadablePropertyMap<vertex_descriptor, Point_3>` | `get(CGAL::vertex_point, tm)` |
/// | `vertex_index_map` | 0-based vertex indices (row order of the eigenvectors) | `ReadablePropertyMap<vertex_descriptor, size_t>` | the mesh's own, or a fresh one |
/// | `use_intrinsic_delaunay` | operators on the intrinsic Delaunay triangulation | `bool` | `false` |
/// | `mass_matrix_type` | vertex areas | `Mass_matrix_type` | `BARYCENTRIC` |
/// | `eigensolver` | a model of `LaplaceBeltramiEigensolver` | e.g. `Spectra_eigensolver<>` | `Spectra_eigensolver<>()` |
/// \throws Invalid_input for an empty mesh, non-triangle faces, non-finite coordinates, isolated
///         vertices (zero area), or k out of range
/// \throws Solver_failure when the factorization or the eigensolver fails, with the reason
/// \sa `compute_heat_kernel_signature`, `compute_wave_kernel_signature`
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Laplace_beltrami_eigenbasis compute_laplace_beltrami_eigenbasis(const TriangleMesh& tm, std::size_t k,
                                                                const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const Laplace_operators op = laplace_operators(tm, np);
  const auto solver = choose_parameter(get_parameter(np, internal_np::eigensolver), Spectra_eigensolver<>());
  Eigen::VectorXd values;
  Eigen::MatrixXd vectors;
  solver.solve(op.L, op.mass, k, values, vectors);
  if(static_cast<std::size_t>(values.size()) != k || vectors.rows() != op.L.rows() || static_cast<std::size_t>(vectors.cols()) != k)
    throw Solver_failure("eigensolver returned " + std::to_string(values.size()) + " eigenpairs of " + std::to_string(k) + " asked");
  const double scale = (op.L.diagonal().array() / op.mass.array().max(1e-300)).mean();
  return Laplace_beltrami_eigenbasis(std::move(values), std::move(vectors), op.mass, scale);
}

} // namespace shapecorr

#endif
