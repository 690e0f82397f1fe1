// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file compute_heat_kernel_signature.h
#ifndef SHAPECORR_SPECTRAL_COMPUTE_HEAT_KERNEL_SIGNATURE_H
#define SHAPECORR_SPECTRAL_COMPUTE_HEAT_KERNEL_SIGNATURE_H

#include <shapecorr/spectral/internal/spectral_signatures.h>

#include <Eigen/Core>
namespace shapecorr {

/// \ingroup PkgShapeCorrSpectral
/// The diffusion times of the heat kernel signature of a basis: `number_of_scales` (default 100)
/// times log-uniform in `time_range`, by default `[4 ln 10 / lambda_k, 4 ln 10 / lambda_2]` (Sun et
/// al. 2009; lambda_2 the first nonzero eigenvalue, lambda_k the largest of the basis).
template <typename NamedParameters = parameters::Default_named_parameters>
std::vector<double> heat_kernel_signature_times(const Laplace_beltrami_eigenbasis& basis,
                                                const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::size_t count = choose_parameter(get_parameter(np, internal_np::number_of_scales), std::size_t(100));
  internal::require_scales(count, "heat kernel signature");
  const double c = 4.0 * std::log(10.0);
  const std::size_t z = internal::first_nonzero_eigenvalue(basis, "heat kernel signature");
  const std::pair<double, double> dflt(c / basis.eigenvalues()[basis.eigenvalues().size() - 1],
                                       c / basis.eigenvalues()[static_cast<Eigen::Index>(z)]);
  const auto range = choose_parameter(get_parameter(np, internal_np::time_range), dflt);
  if(!(range.first > 0) || !(range.second >= range.first))
    throw Invalid_argument("heat kernel signature: time_range must satisfy 0 < first <= second");
  return internal::log_uniform(range.first, range.second, count);
}

/// \ingroup PkgShapeCorrSpectral
/// Heat kernel signatures of all vertices as an n x T matrix (row x = vertex of index x):
/// `h(x, t) = sum_i exp(-lambda_i t) phi_i(x)^2` at the times of `heat_kernel_signature_times`,
/// each column divided by its area-weighted mean when `normalize_per_scale` (the scaled HKS of Sun
/// et al., which compares shapes of different areas).
/// \param np `number_of_scales`, `time_range`, `normalize_per_scale` (`bool`, default `true`)
template <typename NamedParameters = parameters::Default_named_parameters>
Eigen::MatrixXd heat_kernel_signature_matrix(const Laplace_beltrami_eigenbasis& basis,
                                             const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Eigen::MatrixXd H = internal::heat_kernel_signature_matrix(basis, heat_kernel_signature_times(basis, np));
  if(choose_parameter(get_parameter(np, internal_np::normalize_per_scale), true)) internal::normalize_columns_per_scale(H, basis.mass());
  return H;
}

/// \ingroup PkgShapeCorrSpectral
/// The heat kernel signature (HKS; Sun, Ovsjanikov & Guibas 2009) of every vertex of `tm`, written
/// into `hks` as a `std::vector<double>` of `number_of_scales` values (times ascending).
/// Compare two signatures with `spectral_descriptor_distance`.
/// \tparam VertexDescriptorMap a `WritablePropertyMap` from `vertex_descriptor` to `std::vector<double>`
/// \param np optional named parameters:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `eigenbasis` | a precomputed basis of `tm` (same vertex index map) | `const Laplace_beltrami_eigenbasis*` | computed here |
/// | `number_of_eigenpairs` | k when the basis is computed here | `std::size_t` | min(300, n) |
/// | `number_of_scales` | number of times T | `std::size_t` | 100 |
/// | `time_range` | smallest and largest time (log-uniform between) | `std::pair<double, double>` | `[4 ln10 / lambda_k, 4 ln10 / lambda_2]` |
/// | `normalize_per_scale` | divide each time's values by their area-weighted mean | `bool` | `true` |
/// | (basis parameters) | `vertex_point_map`, `vertex_index_map`, `use_intrinsic_delaunay`, `mass_matrix_type`, `eigensolver` | see `compute_laplace_beltrami_eigenbasis` | |
/// \throws Invalid_input, Solver_failure as `compute_laplace_beltrami_eigenbasis`; Invalid_input for
///         parameters out of range or a basis of another mesh
/// \sa thesis chapter 4 (the HKS baseline), `compute_wave_kernel_signature`
template <typename TriangleMesh, typename VertexDescriptorMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_heat_kernel_signature(const TriangleMesh& tm, VertexDescriptorMap hks,
                                   const NamedParameters& np = CGAL::parameters::default_values()) {
  std::unique_ptr<Laplace_beltrami_eigenbasis> owned;
  const Laplace_beltrami_eigenbasis& basis = internal::eigenbasis_of(tm, np, owned);
  internal::write_rows(tm, np, heat_kernel_signature_matrix(basis, np), hks);
}

} // namespace shapecorr

#endif
