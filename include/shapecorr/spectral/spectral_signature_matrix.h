// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file spectral_signature_matrix.h
/// One entry point for the three spectral signatures, chosen at run time.
#ifndef SHAPECORR_SPECTRAL_SPECTRAL_SIGNATURE_MATRIX_H
#define SHAPECORR_SPECTRAL_SPECTRAL_SIGNATURE_MATRIX_H

#include <shapecorr/exceptions.h>
#include <shapecorr/spectral/compute_heat_kernel_signature.h>
#include <shapecorr/spectral/compute_scale_invariant_heat_kernel_signature.h>
#include <shapecorr/spectral/compute_wave_kernel_signature.h>

#include <Eigen/Core>

#include <string>

namespace shapecorr {

/// \ingroup PkgShapeCorrSpectral
/// The spectral signatures of a vertex computed from a Laplace-Beltrami eigenbasis.
enum class Spectral_signature {
  HKS,   ///< heat kernel signature (Sun, Ovsjanikov & Guibas 2009): `heat_kernel_signature_matrix`
  WKS,   ///< wave kernel signature (Aubry, Schlickewei & Cremers 2011): `wave_kernel_signature_matrix`
  SIHKS  ///< scale-invariant HKS (Bronstein & Kokkinos 2010): `scale_invariant_heat_kernel_signature_matrix`
};

/// \ingroup PkgShapeCorrSpectral
/// The name of a signature as the command line spells it: "hks", "wks" or "sihks".
inline const char* to_string(Spectral_signature s) {
  switch(s) {
    case Spectral_signature::HKS: return "hks";
    case Spectral_signature::WKS: return "wks";
    case Spectral_signature::SIHKS: return "sihks";
  }
  return "unknown";
}

/// \ingroup PkgShapeCorrSpectral
/// Parses "hks", "wks" or "sihks".
/// \throws Invalid_argument for any other name
inline Spectral_signature spectral_signature_from_string(const std::string& s) {
  if(s == "hks") return Spectral_signature::HKS;
  if(s == "wks") return Spectral_signature::WKS;
  if(s == "sihks") return Spectral_signature::SIHKS;
  throw Invalid_argument("unknown spectral signature '" + s + "' (expected hks, wks or sihks)");
}

/// \ingroup PkgShapeCorrSpectral
/// The signature `which` of every vertex of the basis's mesh as an n x T matrix (row x = vertex of
/// index x), exactly as the function of that signature computes it with the same `np`: parameters
/// that do not apply to the chosen signature are ignored (`number_of_scales` by SI-HKS,
/// `log_time_range` by HKS and WKS...). Compare rows with `spectral_descriptor_distance`.
/// \param np the named parameters of `heat_kernel_signature_matrix`, `wave_kernel_signature_matrix`
///   or `scale_invariant_heat_kernel_signature_matrix`
/// \throws Invalid_argument for parameters out of range
/// \code
///   const auto basis = shapecorr::compute_laplace_beltrami_eigenbasis(tm, 300);
///   Eigen::MatrixXd D = shapecorr::spectral_signature_matrix(basis, shapecorr::spectral_signature_from_string("wks"),
///                                                           SP::number_of_scales(100));
/// \endcode
template <typename NamedParameters = parameters::Default_named_parameters>
Eigen::MatrixXd spectral_signature_matrix(const Laplace_beltrami_eigenbasis& basis, Spectral_signature which,
                                          const NamedParameters& np = CGAL::parameters::default_values()) {
  switch(which) {
    case Spectral_signature::HKS: return heat_kernel_signature_matrix(basis, np);
    case Spectral_signature::WKS: return wave_kernel_signature_matrix(basis, np);
    case Spectral_signature::SIHKS: return scale_invariant_heat_kernel_signature_matrix(basis, np);
  }
  throw Invalid_argument("spectral_signature_matrix: unknown signature");
}

} // namespace shapecorr

#endif
