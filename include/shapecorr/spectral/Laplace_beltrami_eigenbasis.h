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
    std::ofstream out(path, std::ios::binary);
    if(!out) throw Output_error("eigenbasis: cannot write '" + path + "'");
    const std::uint64_t n = number_of_vertices(), k = number_of_eigenpairs();
    const std::uint32_t order = byte_order_mark;
    std::uint64_t hash = fnv_offset;
    auto put = [&](const void* data, std::uint64_t bytes) {
      out.write(static_cast<const char*>(data), static_cast<std::streamsize>(bytes));
      hash = fnv1a(hash, data, bytes);
    };
    put(magic(), 8);
    put(&order, sizeof order);
    put(&n, sizeof n);
    put(&k, sizeof k);
    put(&m_scale, sizeof m_scale);
    put(m_values.data(), sizeof(double) * k);
    put(m_mass.data(), sizeof(double) * n);
    put(m_vectors.data(), sizeof(double) * n * k);
    out.write(reinterpret_cast<const char*>(&hash), sizeof hash);
    if(!out) throw Output_error("eigenbasis: writing '" + path + "' failed");
  }

  /// Reads a basis written by `save` and checks it: format version, byte order, sizes against the
  /// file size (before allocating), checksum, eigenvalues finite, ascending and non-negative (down
  /// to -1e-8 times the operator scale, round-off of a zero eigenvalue), eigenvectors finite,
  /// masses finite and positive, operator scale finite and positive.
  /// \throws Invalid_input (`unreadable_file`) naming the file and the first problem found
  static Laplace_beltrami_eigenbasis load(const std::string& path) {
    auto fail = [&](const std::string& why) -> void {
      throw Invalid_input(Mesh_defect::unreadable_file, "eigenbasis: '" + path + "': " + why);
    };
    std::ifstream in(path, std::ios::binary);
    if(!in) fail("cannot open the file");
    in.seekg(0, std::ios::end);
    const std::streamoff end = in.tellg();
    if(end < 0) fail("cannot determine the file size (not a regular file?)");
    const std::uint64_t size = static_cast<std::uint64_t>(end);
    in.seekg(0);
    const std::uint64_t header = 8 + 4 + 8 + 8 + 8, trailer = 8;
    char head[8] = {0};
    std::uint32_t order = 0;
    std::uint64_t n = 0, k = 0;
    double scale = 0;
    in.read(head, 8);
    if(!in || std::memcmp(head, "SCLBEIG", 7) != 0) fail("not a ShapeCorr eigenbasis file");
    if(head[7] == '1') fail("format version 1 (no checksum), no longer read: compute the basis again and save it");
    if(head[7] != magic()[7]) fail(std::string("format version '") + head[7] + "' (this build reads version 2)");
    std::uint64_t hash = fnv1a(fnv_offset, head, 8);
    auto get = [&](void* data, std::uint64_t bytes) {
      in.read(static_cast<char*>(data), static_cast<std::streamsize>(bytes));
      if(!in) fail("truncated");
      hash = fnv1a(hash, data, bytes);
    };
    if(size < header + trailer) fail("truncated: " + std::to_string(size) + " bytes, shorter than the header");
    get(&order, sizeof order);
    if(order != byte_order_mark) fail("written on a machine of the other byte order");
    get(&n, sizeof n);
    get(&k, sizeof k);
    get(&scale, sizeof scale);
    // sizes by division: n + k + n k doubles must fill exactly the bytes between header and trailer
    const std::uint64_t doubles = (size - header - trailer) / sizeof(double);
    const std::string counts = " (n = " + std::to_string(n) + " vertices, k = " + std::to_string(k) + " eigenpairs, " + std::to_string(size) + " bytes)";
    if(n == 0 || k == 0 || k > n) fail("bad sizes" + counts + ": 1 <= k <= n is required");
    if(n > doubles || k > doubles / n || n * k > doubles - n || k > doubles - n - n * k ||
       header + trailer + sizeof(double) * (n + k + n * k) != size)
      fail("the sizes disagree with the file size" + counts);
    if(!(std::isfinite(scale) && scale > 0)) fail("operator scale " + std::to_string(scale) + " is not a positive number");
    Eigen::VectorXd values(static_cast<Eigen::Index>(k)), mass(static_cast<Eigen::Index>(n));
    Eigen::MatrixXd vectors(static_cast<Eigen::Index>(n), static_cast<Eigen::Index>(k));
    get(values.data(), sizeof(double) * k);
    get(mass.data(), sizeof(double) * n);
    get(vectors.data(), sizeof(double) * n * k);
    std::uint64_t stored = 0;
    in.read(reinterpret_cast<char*>(&stored), sizeof stored);
    if(!in) fail("truncated");
    if(stored != hash) fail("checksum mismatch (the file is corrupt)");
    for(Eigen::Index i = 0; i < values.size(); ++i) {
      const double v = values[i];
      if(!std::isfinite(v)) fail("eigenvalue " + std::to_string(i) + " is not finite");
      if(v < -1e-8 * scale) fail("eigenvalue " + std::to_string(i) + " = " + std::to_string(v) + " is negative");
      if(i > 0 && v < values[i - 1]) fail("eigenvalues not ascending at " + std::to_string(i));
    }
    for(Eigen::Index i = 0; i < mass.size(); ++i)
      if(!(std::isfinite(mass[i]) && mass[i] > 0)) fail("mass of vertex " + std::to_string(i) + " is not a positive number");
    if(!vectors.allFinite()) fail("an eigenvector has a non-finite entry");
    return Laplace_beltrami_eigenbasis(std::move(values), std::move(vectors), std::move(mass), scale);
  }

private:
  static const char* magic() { return "SCLBEIG2"; }
  static constexpr std::uint32_t byte_order_mark = 0x01020304u;
  static constexpr std::uint64_t fnv_offset = 14695981039346656037ull;
  static std::uint64_t fnv1a(std::uint64_t h, const void* data, std::uint64_t bytes) {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for(std::uint64_t i = 0; i < bytes; ++i) h = (h ^ p[i]) * 1099511628211ull;
    return h;
  }
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
