// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: the fast Gauss sum of the point-set methods (CPD, GMM-L2):
//   S(q) = Σ_j w_j exp(−|q − p_j|² / (2 s²))  and  V(q) = Σ_j v_j exp(−|q − p_j|² / (2 s²))
// for scalar weights w_j ≥ 0 and vector weights v_j (3 values), without the n × m matrix.
// Two approximations, each with a stated error:
// * truncation: only sources within r = s √(2 ln(1/ε)) of q count (a k-d tree); each dropped
//   term is below ε of its weight;
// * clustering, when the bandwidth is wide against the point spacing: the sources of one cubic
//   cell of side s/4 are replaced by one source at their w-weighted centroid with their summed
//   weights (and, for the vector sums, the first-order term D (q − c) k / s², D = Σ v_j (p_j − c)ᵀ).
//   The first-order error cancels at the centroid; the second order is below
//   (|p − c|² / (2 s²)) (1 + |q − c|² / s²) of a term, |p − c| ≤ (√3/8) s: a few per mille for a
//   query one bandwidth away, and the terms far away weigh little. Used only where it reduces the
//   sources by 2× or more; measured against the exact sum in the tests (below 1 %).
#ifndef SHAPECORR_INTERNAL_GAUSS_SUM_H
#define SHAPECORR_INTERNAL_GAUSS_SUM_H

#include <shapecorr/internal/kd_tree.h>

#include <Eigen/Core>

#include <cmath>
#include <cstdint>
#include <map>
#include <tuple>
#include <vector>

namespace shapecorr {
namespace internal {

class Gauss_sum {
public:
  /// Sources: the rows of `P` (n × 3) with weights `w` (n) and, optionally, vector weights `V`
  /// (n × 3; empty: V(q) = 0). `s` > 0 the bandwidth, `epsilon` in (0, 1) the truncation.
  /// With `allow_clustering` false, the sum is exact up to truncation.
  Gauss_sum(const Eigen::MatrixXd& P, const Eigen::VectorXd& w, const Eigen::MatrixXd& V, double s, double epsilon = 1e-6,
            bool allow_clustering = true)
      : m_inverse_two_s2(1.0 / (2 * s * s)), m_radius(s * std::sqrt(2 * std::log(1 / epsilon))), m_has_vector(V.rows() == P.rows() && V.rows() > 0) {
    const Eigen::Index n = P.rows();
    bool clustered = false;
    if(allow_clustering && n > 0) {
      const double h = s / 4;
      std::map<std::tuple<long long, long long, long long>, std::size_t> cell;
      std::vector<std::size_t> of(static_cast<std::size_t>(n));
      const Eigen::RowVector3d lo = P.colwise().minCoeff();
      const double span = (P.colwise().maxCoeff() - lo).maxCoeff();
      if(std::isfinite(span) && span / h < 1e6) { // cell indices fit comfortably
        for(Eigen::Index j = 0; j < n; ++j) {
          const auto key = std::make_tuple(static_cast<long long>(std::floor((P(j, 0) - lo(0)) / h)), static_cast<long long>(std::floor((P(j, 1) - lo(1)) / h)),
                                           static_cast<long long>(std::floor((P(j, 2) - lo(2)) / h)));
          of[static_cast<std::size_t>(j)] = cell.emplace(key, cell.size()).first->second;
        }
        if(2 * cell.size() <= static_cast<std::size_t>(n)) {
          clustered = true;
          const std::size_t c = cell.size();
          Eigen::MatrixXd centroid = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(c), 3), plain = centroid;
          std::vector<double> count(c, 0.0);
          m_w.assign(c, 0.0);
          m_v.assign(c, Eigen::Vector3d::Zero());
          for(Eigen::Index j = 0; j < n; ++j) {
            const std::size_t k = of[static_cast<std::size_t>(j)];
            m_w[k] += w(j);
            centroid.row(static_cast<Eigen::Index>(k)) += w(j) * P.row(j);
            plain.row(static_cast<Eigen::Index>(k)) += P.row(j);
            count[k] += 1;
            if(m_has_vector) m_v[k] += V.row(j).transpose();
          }
          std::vector<Kd_tree<3>::Point> pts(c);
          std::vector<Eigen::Vector3d> at(c);
          for(std::size_t k = 0; k < c; ++k) {
            const Eigen::Index r = static_cast<Eigen::Index>(k);
            at[k] = m_w[k] > 0 ? Eigen::Vector3d(centroid.row(r).transpose() / m_w[k]) : Eigen::Vector3d(plain.row(r).transpose() / count[k]);
            pts[k] = {at[k](0), at[k](1), at[k](2)};
          }
          m_point = at;
          if(m_has_vector) {
            m_d.assign(c, Eigen::Matrix3d::Zero());
            for(Eigen::Index j = 0; j < n; ++j) {
              const std::size_t k = of[static_cast<std::size_t>(j)];
              m_d[k] += V.row(j).transpose() * (P.row(j).transpose() - at[k]).transpose();
            }
            for(auto& d : m_d) d *= 2 * m_inverse_two_s2; // D / s²
          }
          m_tree = Kd_tree<3>(std::move(pts));
        }
      }
    }
    if(!clustered) {
      std::vector<Kd_tree<3>::Point> pts(static_cast<std::size_t>(n));
      m_w.resize(static_cast<std::size_t>(n));
      if(m_has_vector) m_v.resize(static_cast<std::size_t>(n));
      for(Eigen::Index j = 0; j < n; ++j) {
        pts[static_cast<std::size_t>(j)] = {P(j, 0), P(j, 1), P(j, 2)};
        m_w[static_cast<std::size_t>(j)] = w(j);
        if(m_has_vector) m_v[static_cast<std::size_t>(j)] = V.row(j).transpose();
      }
      m_tree = Kd_tree<3>(std::move(pts));
    }
    m_clustered = clustered;
  }

  /// S(q), and V(q) into `vector` when given.
  double operator()(const Eigen::Vector3d& q, Eigen::Vector3d* vector = nullptr) const {
    double s = 0;
    Eigen::Vector3d v = Eigen::Vector3d::Zero();
    m_tree.for_each_within({q.x(), q.y(), q.z()}, m_radius, [&](std::size_t j, double d2) {
      const double k = std::exp(-d2 * m_inverse_two_s2);
      s += m_w[j] * k;
      if(m_has_vector) {
        v += k * m_v[j];
        if(!m_d.empty()) v += k * (m_d[j] * (q - m_point[j]));
      }
    });
    if(vector) *vector = v;
    return s;
  }

  /// Whether the sources were clustered (for tests and reports).
  bool clustered() const { return m_clustered; }
  /// The number of (possibly clustered) sources.
  std::size_t size() const { return m_tree.size(); }

private:
  double m_inverse_two_s2, m_radius;
  bool m_has_vector, m_clustered = false;
  Kd_tree<3> m_tree;
  std::vector<double> m_w;
  std::vector<Eigen::Vector3d> m_v;
  std::vector<Eigen::Matrix3d> m_d;       // clustered vector sums: first-order term per cell (D / s²)
  std::vector<Eigen::Vector3d> m_point;   // clustered: the cells' centroids
};

} // namespace internal
} // namespace shapecorr

#endif
