// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file compute_wave_kernel_signature.h
#ifndef SHAPECORR_SPECTRAL_COMPUTE_WAVE_KERNEL_SIGNATURE_H
#define SHAPECORR_SPECTRAL_COMPUTE_WAVE_KERNEL_SIGNATURE_H

#include <shapecorr/spectral/internal/spectral_signatures.h>

#include <Eigen/Core>
namespace shapecorr {

/// \ingroup PkgShapeCorrSpectral
/// The log-energies of the wave kernel signature of a basis: `number_of_scales` (default 100)
/// values evenly spaced in `energy_range`, by default `[log lambda_2, log lambda_k]`.
template <typename NamedParameters = parameters::Default_named_parameters>
std::vector<double> wave_kernel_signature_energies(const Laplace_beltrami_eigenbasis& basis,
                                                   const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::size_t count = choose_parameter(get_parameter(np, internal_np::number_of_scales), std::size_t(100));
  internal::require_scales(count, "wave kernel signature");
  const std::size_t z = internal::first_nonzero_eigenvalue(basis, "wave kernel signature");
  const std::pair<double, double> dflt(std::log(basis.eigenvalues()[static_cast<Eigen::Index>(z)]),
                                       std::log(basis.eigenvalues()[basis.eigenvalues().size() - 1]));
  const auto range = choose_parameter(get_parameter(np, internal_np::energy_range), dflt);
  if(!(range.second >= range.first) || !std::isfinite(range.first) || !std::isfinite(range.second))
    throw Invalid_argument("wave kernel signature: energy_range must be finite with first <= second");
  std::vector<double> e(count);
  for(std::size_t j = 0; j < count; ++j)
    e[j] = count == 1 ? range.first : range.first + (range.second - range.first) * static_cast<double>(j) / static_cast<double>(count - 1);
  return e;
}

/// \ingroup PkgShapeCorrSpectral
/// Wave kernel signatures of all vertices as an n x E matrix (row x = vertex of index x):
/// `w(x, e) = sum_i phi_i(x)^2 g_i(e) / sum_i g_i(e)`, `g_i(e) = exp(-(e - log lambda_i)^2 / 2 sigma^2)`
/// over the nonzero eigenvalues, `sigma = wks_sigma_factor` (default 6) times the energy increment;
/// columns divided by their area-weighted mean when `normalize_per_scale`.
template <typename NamedParameters = parameters::Default_named_parameters>
Eigen::MatrixXd wave_kernel_signature_matrix(const Laplace_beltrami_eigenbasis& basis,
                                             const NamedParameters& np = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const std::vector<double> e = wave_kernel_signature_energies(basis, np);
  const double increment = e.size() > 1 ? (e.back() - e.front()) / static_cast<double>(e.size() - 1) : 0.0;
  const double factor = choose_parameter(get_parameter(np, internal_np::wks_sigma_factor), 6.0);
  double sigma = factor * increment;
  if(!(sigma > 0)) sigma = factor * 0.01; // a single energy (or an empty range): a narrow band
  Eigen::MatrixXd W = internal::wave_kernel_signature_matrix(basis, e, sigma);
  if(choose_parameter(get_parameter(np, internal_np::normalize_per_scale), true)) internal::normalize_columns_per_scale(W, basis.mass());
  return W;
}

/// \ingroup PkgShapeCorrSpectral
/// The wave kernel signature (WKS; Aubry, Schlickewei & Cremers 2011) of every vertex of `tm`,
/// written into `wks` as a `std::vector<double>` of `number_of_scales` values (energies ascending).
/// \param np optional named parameters: those of `compute_heat_kernel_signature` but `time_range`, and
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `energy_range` | smallest and largest log-energy | `std::pair<double, double>` | `[log lambda_2, log lambda_k]` |
/// | `wks_sigma_factor` | band width sigma in energy increments | `double` | 6 |
/// \sa thesis chapter 4 (the WKS baseline)
template <typename TriangleMesh, typename VertexDescriptorMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_wave_kernel_signature(const TriangleMesh& tm, VertexDescriptorMap wks,
                                   const NamedParameters& np = CGAL::parameters::default_values()) {
  std::unique_ptr<Laplace_beltrami_eigenbasis> owned;
  const Laplace_beltrami_eigenbasis& basis = internal::eigenbasis_of(tm, np, owned);
  internal::write_rows(tm, np, wave_kernel_signature_matrix(basis, np), wks);
}

} // namespace shapecorr

#endif
