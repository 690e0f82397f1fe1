// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file compute_scale_invariant_heat_kernel_signature.h
#ifndef SHAPECORR_SPECTRAL_COMPUTE_SCALE_INVARIANT_HEAT_KERNEL_SIGNATURE_H
#define SHAPECORR_SPECTRAL_COMPUTE_SCALE_INVARIANT_HEAT_KERNEL_SIGNATURE_H

#include <shapecorr/spectral/internal/spectral_signatures.h>

#include <Eigen/Core>
namespace shapecorr {

namespace internal {
template <typename NamedParameters>
Si_hks_options si_hks_options(const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  Si_hks_options o;
  o.alpha = choose_parameter(get_parameter(np, internal_np::log_time_base), o.alpha);
  const auto tau = choose_parameter(get_parameter(np, internal_np::log_time_range), std::make_pair(o.tau_begin, o.tau_end));
  o.tau_begin = tau.first;
  o.tau_end = tau.second;
  o.tau_step = choose_parameter(get_parameter(np, internal_np::log_time_step), o.tau_step);
  o.time_unit = choose_parameter(get_parameter(np, internal_np::time_unit), 0.0);
  const auto f = choose_parameter(get_parameter(np, internal_np::frequency_range), std::make_pair(o.frequency_begin, o.frequency_end));
  o.frequency_begin = f.first;
  o.frequency_end = f.second;
  return o;
}
} // namespace internal

/// \ingroup PkgShapeCorrSpectral
/// Scale-invariant heat kernel signatures of all vertices as an n x F matrix (Bronstein & Kokkinos
/// 2010): the HKS is sampled at `t = t0 alpha^tau` for tau on a uniform grid, its logarithm is
/// differentiated in tau (a uniform scaling of the shape by s multiplies h by s^-2 and shifts tau by
/// 2 log_alpha s: the log removes the factor, the difference the constant), and the magnitude of
/// the discrete Fourier transform of the result (shift-invariant) is kept at frequencies
/// `frequency_range` (thesis: [2, 20]). Invariance to a scaling holds when the window of tau holds
/// the whole decay of the HKS at both scales.
///
/// `time_unit` t0: by default `1 / lambda_k`, which moves with the shape's scale and makes the
/// descriptor exactly invariant to a uniform scaling of the whole shape; give a fixed t0 to compare
/// shapes in one absolute time frame (the scale invariance then comes from the log-derivative and
/// the Fourier magnitude, as in the paper).
template <typename NamedParameters = parameters::Default_named_parameters>
Eigen::MatrixXd scale_invariant_heat_kernel_signature_matrix(const Laplace_beltrami_eigenbasis& basis,
                                                             const NamedParameters& np = CGAL::parameters::default_values()) {
  return internal::scale_invariant_hks_matrix(basis, internal::si_hks_options(np));
}

/// \ingroup PkgShapeCorrSpectral
/// The scale-invariant heat kernel signature (SI-HKS) of every vertex of `tm`, written into `sihks`
/// as a `std::vector<double>` of `frequency_range.second - frequency_range.first + 1` values.
/// \param np optional named parameters: the basis parameters of `compute_heat_kernel_signature`, and
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `log_time_base` | alpha | `double` | 2 |
/// | `log_time_range` | first and last tau | `std::pair<double, double>` | [1, 20] |
/// | `log_time_step` | tau increment | `double` | 1/16 |
/// | `time_unit` | t0 | `double` | 1 / lambda_k |
/// | `frequency_range` | kept DFT frequencies, inclusive | `std::pair<int, int>` | [2, 20] |
template <typename TriangleMesh, typename VertexDescriptorMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_scale_invariant_heat_kernel_signature(const TriangleMesh& tm, VertexDescriptorMap sihks,
                                                   const NamedParameters& np = CGAL::parameters::default_values()) {
  std::unique_ptr<Laplace_beltrami_eigenbasis> owned;
  const Laplace_beltrami_eigenbasis& basis = internal::eigenbasis_of(tm, np, owned);
  internal::write_rows(tm, np, scale_invariant_heat_kernel_signature_matrix(basis, np), sihks);
}

} // namespace shapecorr

#endif
