// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Laplace_beltrami_eigenbasis.h
#ifndef SHAPECORR_SPECTRAL_LAPLACE_BELTRAMI_EIGENBASIS_H
#define SHAPECORR_SPECTRAL_LAPLACE_BELTRAMI_EIGENBASIS_H

#include <shapecorr/exceptions.h>
#include <shapecorr/parameters.h>
#include <shapecorr/internal/binary_file.h>
#include <shapecorr/spectral/Spectra_eigensolver.h>
#include <shapecorr/operators/laplacian.h>

#include <Eigen/Dense>

#include <cmath>
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

  /// Writes the basis to a binary file, format version 2 (native byte order, marked):
  /// "SCLBEIG2", the 32-bit byte-order mark 0x01020304, n and k (64-bit), the operator scale,
  /// the k eigenvalues, the n masses, the n x k eigenvectors column-major (doubles), and the
  /// 64-bit FNV-1a checksum of everything before it.
  /// \throws Output_error when the file cannot be written
  void save(const std::string& path) const {
    internal::Checked_binary_writer out(path, magic(), "eigenbasis");
    const std::uint64_t n = number_of_vertices(), k = number_of_eigenpairs();
    out.put_u64(n);
    out.put_u64(k);
    out.put_double(m_scale);
    out.put(m_values.data(), sizeof(double) * k);
    out.put(m_mass.data(), sizeof(double) * n);
    out.put(m_vectors.data(), sizeof(double) * n * k);
    out.finish();
  }

  /// Reads a basis written by `save` and checks it: format version, byte order, sizes against the
  /// file size (before allocating), checksum, eigenvalues finite, ascending and non-negative (down
  /// to -1e-8 times the operator scale, round-off of a zero eigenvalue), eigenvectors finite,
  /// masses finite and positive, operator scale finite and positive.
  /// \throws Invalid_input (`unreadable_file`) naming the file and the first problem found
  static Laplace_beltrami_eigenbasis load(const std::string& path) {
    internal::Checked_binary_reader in(path, magic(), 7, "eigenbasis");
    const std::string version = in.version(7);
    if(version == "1") in.fail("format version 1 (no checksum), no longer read: compute the basis again and save it");
    if(version != "2") in.fail("format version '" + version + "' (this build reads version 2)");
    const std::uint64_t n = in.get_u64(), k = in.get_u64();
    const double scale = in.get_double();
    const std::string counts = " (n = " + std::to_string(n) + " vertices, k = " + std::to_string(k) + " eigenpairs)";
    if(n == 0 || k == 0 || k > n) in.fail("bad sizes" + counts + ": 1 <= k <= n is required");
    // n + k + n k doubles must fill exactly the bytes before the checksum
    const std::uint64_t doubles = in.bytes_left() / sizeof(double);
    if(in.bytes_left() % sizeof(double) != 0 || n > doubles || k > doubles / n || n * k > doubles - n || k != doubles - n - n * k)
      in.fail("the sizes disagree with the file size" + counts);
    if(!(std::isfinite(scale) && scale > 0)) in.fail("operator scale " + std::to_string(scale) + " is not a positive number");
    Eigen::VectorXd values(static_cast<Eigen::Index>(k)), mass(static_cast<Eigen::Index>(n));
    Eigen::MatrixXd vectors(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(k));
    in.get(values.data(), sizeof(double) * k);
    in.get(mass.data(), sizeof(double) * n);
    in.get(vectors.data(), sizeof(double) * n * k);
    in.finish();
    for(Eigen::Index i = 0; i < values.size(); ++i) {
      const double v = values[i];
      if(!std::isfinite(v)) in.fail("eigenvalue " + std::to_string(i) + " is not finite");
      if(v < -1e-8 * scale) in.fail("eigenvalue " + std::to_string(i) + " = " + std::to_string(v) + " is negative");
      if(i > 0 && v < values[i - 1]) in.fail("eigenvalues not ascending at " + std::to_string(i));
    }
    for(Eigen::Index i = 0; i < mass.size(); ++i)
      if(!(std::isfinite(mass[i]) && mass[i] > 0)) in.fail("mass of vertex " + std::to_string(i) + " is not a positive number");
    if(!vectors.allFinite()) in.fail("an eigenvector has a non-finite entry");
    return Laplace_beltrami_eigenbasis(std::move(values), std::move(vectors), std::move(mass), scale);
  }

private:
  static const char* magic() { return "SCLBEIG2"; }
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
