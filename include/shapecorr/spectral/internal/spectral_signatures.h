// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: HKS, WKS and SI-HKS as dense n x d matrices computed from an eigenbasis (one matrix
// product each), and the shared plumbing of the public functions (basis from the named parameters,
// writing rows into a vertex property map).
#ifndef SHAPECORR_SPECTRAL_INTERNAL_SPECTRAL_SIGNATURES_H
#define SHAPECORR_SPECTRAL_INTERNAL_SPECTRAL_SIGNATURES_H

#include <shapecorr/exceptions.h>
#include <shapecorr/parameters.h>
#include <shapecorr/spectral/Laplace_beltrami_eigenbasis.h>

#include <CGAL/boost/graph/named_params_helper.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
#include <complex>
#include <memory>
#include <utility>
#include <vector>

namespace shapecorr {
namespace internal {

/// Index of the first nonzero eigenvalue; throws when the basis has none.
inline std::size_t first_nonzero_eigenvalue(const Laplace_beltrami_eigenbasis& b, const char* what) {
  const std::size_t z = b.number_of_zero_eigenvalues();
  if(z >= b.number_of_eigenpairs())
    throw Invalid_argument(std::string(what) + ": the eigenbasis has no nonzero eigenvalue (" +
                                                           std::to_string(b.number_of_eigenpairs()) + " eigenpairs, " +
                                                           std::to_string(z) + " components): ask for more eigenpairs");
  return z;
}

inline std::vector<double> log_uniform(double lo, double hi, std::size_t count) {
  std::vector<double> v(count);
  for(std::size_t j = 0; j < count; ++j)
    v[j] = count == 1 ? lo : std::exp(std::log(lo) + (std::log(hi) - std::log(lo)) * static_cast<double>(j) / static_cast<double>(count - 1));
  return v;
}

inline void require_scales(std::size_t count, const char* what) {
  if(count == 0) throw Invalid_argument(std::string(what) + ": number_of_scales must be positive");
}

/// h(x, t) = sum_i exp(-lambda_i t) phi_i(x)^2 for each t: n x T.
inline Eigen::MatrixXd heat_kernel_signature_matrix(const Laplace_beltrami_eigenbasis& b, const std::vector<double>& times) {
  const Eigen::Index k = static_cast<Eigen::Index>(b.number_of_eigenpairs()), T = static_cast<Eigen::Index>(times.size());
  Eigen::MatrixXd E(k, T);
  for(Eigen::Index j = 0; j < T; ++j) {
    if(!(times[static_cast<std::size_t>(j)] > 0) || !std::isfinite(times[static_cast<std::size_t>(j)]))
      throw Invalid_argument("heat kernel signature: times must be positive and finite");
    E.col(j) = (-b.eigenvalues().array().max(0.0) * times[static_cast<std::size_t>(j)]).exp();
  }
  return b.eigenvectors().array().square().matrix() * E;
}

/// w(x, e) = sum_i phi_i(x)^2 g_i(e) / sum_i g_i(e), g_i(e) = exp(-(e - log lambda_i)^2 / 2 sigma^2),
/// over the nonzero eigenvalues: n x E.
inline Eigen::MatrixXd wave_kernel_signature_matrix(const Laplace_beltrami_eigenbasis& b, const std::vector<double>& energies, double sigma) {
  if(!(sigma > 0)) throw Invalid_argument("wave kernel signature: sigma must be positive");
  const std::size_t z = first_nonzero_eigenvalue(b, "wave kernel signature");
  const Eigen::Index k = static_cast<Eigen::Index>(b.number_of_eigenpairs() - z), E = static_cast<Eigen::Index>(energies.size());
  const Eigen::ArrayXd loglambda = b.eigenvalues().tail(k).array().log();
  Eigen::MatrixXd G(k, E);
  for(Eigen::Index j = 0; j < E; ++j) {
    const Eigen::ArrayXd g = (-(energies[static_cast<std::size_t>(j)] - loglambda).square() / (2 * sigma * sigma)).exp();
    const double sum = g.sum();
    G.col(j) = sum > 0 ? Eigen::VectorXd(g / sum) : Eigen::VectorXd::Zero(k);
  }
  return b.eigenvectors().rightCols(k).array().square().matrix() * G;
}

/// Divides each column by its area-weighted mean over the surface (per-scale normalization).
inline void normalize_columns_per_scale(Eigen::MatrixXd& D, const Eigen::VectorXd& mass) {
  const double area = mass.sum();
  for(Eigen::Index j = 0; j < D.cols(); ++j) {
    const double mean = D.col(j).dot(mass) / area;
    if(mean > 0) D.col(j) /= mean;
  }
}

/// SI-HKS (Bronstein & Kokkinos 2010): HKS at t_j = t0 alpha^tau_j on a uniform tau grid, log,
/// forward difference in tau, magnitude of the discrete Fourier transform at the chosen frequencies.
struct Si_hks_options {
  double alpha = 2.0;
  double tau_begin = 1.0, tau_end = 20.0, tau_step = 1.0 / 16.0;
  double time_unit = 0.0; // t0; 0 = 1 / lambda_k
  int frequency_begin = 2, frequency_end = 20;
};

inline Eigen::MatrixXd scale_invariant_hks_matrix(const Laplace_beltrami_eigenbasis& b, const Si_hks_options& o) {
  if(!(o.alpha > 1) || !(o.tau_step > 0) || !(o.tau_end > o.tau_begin))
    throw Invalid_argument("SI-HKS: needs log_time_base > 1, log_time_step > 0 and a non-empty log_time_range");
  const std::size_t J = static_cast<std::size_t>(std::llround((o.tau_end - o.tau_begin) / o.tau_step)); // differences
  if(J < 2) throw Invalid_argument("SI-HKS: the log-time range holds fewer than three samples");
  if(o.frequency_begin < 0 || o.frequency_end < o.frequency_begin || static_cast<std::size_t>(o.frequency_end) >= J)
    throw Invalid_argument("SI-HKS: frequency_range must satisfy 0 <= first <= last < number of log-time samples - 1");
  const std::size_t z = first_nonzero_eigenvalue(b, "SI-HKS");
  (void)z;
  const double lambda_k = b.eigenvalues()[b.eigenvalues().size() - 1];
  const double t0 = o.time_unit > 0 ? o.time_unit : 1.0 / lambda_k;
  std::vector<double> times(J + 1);
  for(std::size_t j = 0; j <= J; ++j) times[j] = t0 * std::pow(o.alpha, o.tau_begin + o.tau_step * static_cast<double>(j));
  const Eigen::MatrixXd H = heat_kernel_signature_matrix(b, times);
  const Eigen::MatrixXd logH = H.array().max(std::numeric_limits<double>::min()).log().matrix();
  const Eigen::MatrixXd dH = logH.rightCols(static_cast<Eigen::Index>(J)) - logH.leftCols(static_cast<Eigen::Index>(J)); // n x J
  const Eigen::Index F = o.frequency_end - o.frequency_begin + 1;
  Eigen::MatrixXd C(static_cast<Eigen::Index>(J), F), S(static_cast<Eigen::Index>(J), F);
  const double two_pi = 6.283185307179586476925286766559;
  for(Eigen::Index f = 0; f < F; ++f)
    for(Eigen::Index j = 0; j < static_cast<Eigen::Index>(J); ++j) {
      const double a = two_pi * static_cast<double>((o.frequency_begin + f) * j) / static_cast<double>(J);
      C(j, f) = std::cos(a);
      S(j, f) = -std::sin(a);
    }
  const Eigen::MatrixXd re = dH * C, im = dH * S;
  return (re.array().square() + im.array().square()).sqrt().matrix();
}

/// The basis of the named parameters (`eigenbasis`), or a fresh one with `number_of_eigenpairs`
/// (default min(300, n)) held by `owned`.
template <typename TriangleMesh, typename NamedParameters>
const Laplace_beltrami_eigenbasis& eigenbasis_of(const TriangleMesh& tm, const NamedParameters& np,
                                                 std::unique_ptr<Laplace_beltrami_eigenbasis>& owned) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  const Laplace_beltrami_eigenbasis* given =
      choose_parameter(get_parameter(np, internal_np::eigenbasis), static_cast<const Laplace_beltrami_eigenbasis*>(nullptr));
  const std::size_t n = static_cast<std::size_t>(num_vertices(tm));
  if(given) {
    if(given->number_of_vertices() != n)
      throw Invalid_argument("spectral descriptor: the eigenbasis has " +
                                                             std::to_string(given->number_of_vertices()) + " vertices, the mesh " +
                                                             std::to_string(n));
    return *given;
  }
  const std::size_t k = choose_parameter(get_parameter(np, internal_np::number_of_eigenpairs), std::min<std::size_t>(300, n));
  owned = std::make_unique<Laplace_beltrami_eigenbasis>(compute_laplace_beltrami_eigenbasis(tm, k, np));
  return *owned;
}

/// put(map, v, row of D) for every vertex, rows in the order of the vertex index map.
template <typename TriangleMesh, typename NamedParameters, typename VertexDescriptorMap>
void write_rows(const TriangleMesh& tm, const NamedParameters& np, const Eigen::MatrixXd& D, VertexDescriptorMap map) {
  auto vim = CGAL::get_initialized_vertex_index_map(tm, np);
  for(auto v : vertices(tm)) {
    const Eigen::Index i = static_cast<Eigen::Index>(get(vim, v));
    std::vector<double> row(static_cast<std::size_t>(D.cols()));
    for(Eigen::Index j = 0; j < D.cols(); ++j) row[static_cast<std::size_t>(j)] = D(i, j);
    put(map, v, std::move(row));
  }
}

} // namespace internal
} // namespace shapecorr

#endif
