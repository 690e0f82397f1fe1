// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Contour_distance_field.h
/// A spin contour prepared for fast comparisons: its distance field sampled on its own rows, and
/// the approximate symmetric normalized L1 distance computed from two such fields.
#ifndef SHAPECORR_DESCRIPTORS_CONTOUR_DISTANCE_FIELD_H
#define SHAPECORR_DESCRIPTORS_CONTOUR_DISTANCE_FIELD_H

#include <shapecorr/descriptors/Spin_contour.h>
#include <shapecorr/exceptions.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrDescriptors
/// A spin contour (rigid or geodesic) together with its distance field: for every row r of the
/// contour and `alpha_samples` equispaced alphas a_c covering [min(0, min alpha), max(1, max alpha)],
/// the Euclidean distance from (a_c, beta_r) to the nearest point of the contour (exact, by a
/// per-row nearest-alpha sweep and Felzenszwalb & Huttenlocher's lower envelope along each column;
/// stored as 16-bit fractions of the largest value).
///
/// The points of any contour with the same rows lie on those rows, so the distance from one of them
/// to this contour is read from its row by linear interpolation: O(1) per point instead of a search.
/// The distance is 1-Lipschitz in alpha, so the interpolated value differs from the exact one by at
/// most `error_bound()` = half the sample spacing plus half a quantization step (inside the sampled
/// range; outside it the value is the Lipschitz extension from the nearest end, an upper bound).
///
/// Each field also lists its own points with their cells and fractions on its grid; two fields on
/// the same grid (the same sample count and alpha range, as for all contours with alphas in [0, 1])
/// are compared with one lookup and one multiply-add per point.
///
/// Cost: preparing is O(rows x alpha_samples + points) and takes rows x alpha_samples x 2 bytes;
/// comparing two prepared contours is one lookup and one multiply-add per point, O(points). Worth
/// it when each contour is compared many times (matching N sources against M targets prepares
/// N + M fields for N x M comparisons). benchmark/README.md has the measured ratios.
class Contour_distance_field {
public:
  Contour_distance_field() = default;
  /// \throws Invalid_argument when `alpha_samples` < 2 or the contour has no rows
  explicit Contour_distance_field(const Spin_contour& contour, std::size_t alpha_samples = 121)
    : m_contour(contour), m_samples(alpha_samples) {
    if(alpha_samples < 2) throw Invalid_argument("contour distance field: need at least 2 alpha samples");
    if(contour.rows() == 0) throw Invalid_argument("contour distance field: the contour has no rows");
    if(contour.empty()) return;
    const auto& a = contour.alphas();
    const auto range = std::minmax_element(a.begin(), a.end());
    m_lo = std::min(0.0, static_cast<double>(*range.first));
    m_hi = std::max(1.0, static_cast<double>(*range.second));
    m_step = (m_hi - m_lo) / static_cast<double>(m_samples - 1);
    build();
    // the contour's own points as queries into other fields on the same grid (the common case:
    // alphas in [0, 1]), in one flat list: each point's cell and fraction on this grid
    m_query.reserve(contour.size());
    const double cmax = static_cast<double>(m_samples - 1);
    for(std::size_t r = 0; r < contour.rows(); ++r)
      for(std::size_t i = contour.row_begin(r); i < contour.row_end(r); ++i) {
        const double x = std::min(std::max((static_cast<double>(a[i]) - m_lo) / m_step, 0.0), cmax);
        const std::size_t c = static_cast<std::size_t>(std::min(x, cmax - 1.0));
        m_query.push_back({static_cast<float>(x - static_cast<double>(c)), static_cast<std::uint32_t>(r * m_samples + c)});
      }
  }

  /// The contour the field was built from.
  const Spin_contour& contour() const { return m_contour; }
  /// Number of rows.
  std::size_t rows() const { return m_contour.rows(); }
  /// Number of alpha samples per row.
  std::size_t alpha_samples() const { return m_samples; }
  /// The sampled alpha range [alpha_min(), alpha_max()] and the spacing of the samples.
  double alpha_min() const { return m_lo; }
  /// The largest sampled alpha.
  double alpha_max() const { return m_hi; }
  /// Distance between two alpha samples.
  double sample_spacing() const { return m_step; }
  /// Largest difference between `distance(r, alpha)` and the exact distance, for alpha in the
  /// sampled range (normalized units).
  double error_bound() const { return 0.5 * m_step + 0.5 * m_scale; }
  /// Bytes of the sampled field.
  std::size_t memory_bytes() const { return m_field.size() * sizeof(std::uint16_t); }
  /// The sampled distance at (alpha sample c, row r).
  double sample(std::size_t r, std::size_t c) const { return m_scale * static_cast<double>(m_field[r * m_samples + c]); }

  /// The distance from the point (alpha, beta of row r) to the contour, interpolated (+infinity
  /// for an empty contour).
  /// \throws Invalid_argument when r is not a row
  double distance(std::size_t r, double alpha) const {
    if(r >= rows()) throw Invalid_argument("contour distance field: row " + std::to_string(r) + " of " + std::to_string(rows()));
    if(m_contour.empty()) return std::numeric_limits<double>::infinity();
    const std::uint16_t* row = m_field.data() + r * m_samples;
    const double inv = 1.0 / m_step, cmax = static_cast<double>(m_samples - 1);
    return m_scale * interpolate(row, (alpha - m_lo) * inv, cmax) + outside(alpha);
  }

  /// The sum over the points of `other` (a contour on the same rows) of their distances to this
  /// contour; stops early, returning a value > `bound`, once the sum exceeds `bound`.
  /// \throws Invalid_argument when the numbers of rows differ
  double sum_of_distances(const Spin_contour& other, double bound = std::numeric_limits<double>::infinity()) const {
    require_rows(other.rows());
    if(other.empty()) return 0.0;
    if(m_contour.empty()) return std::numeric_limits<double>::infinity();
    const float* a = other.alphas().data();
    const double inv = 1.0 / m_step, cmax = static_cast<double>(m_samples - 1);
    const double limit = bound / m_scale; // the field's units
    double s = 0, out = 0;
    for(std::size_t r = 0; r < m_contour.rows(); ++r) {
      const std::uint16_t* row = m_field.data() + r * m_samples;
      for(std::size_t i = other.row_begin(r); i < other.row_end(r); ++i) {
        const double x = static_cast<double>(a[i]);
        s += interpolate(row, (x - m_lo) * inv, cmax);
        out += outside(x);
      }
      if(s + out / m_scale > limit) break;
    }
    return m_scale * s + out;
  }

  /// The same sum for the points of another prepared contour: on the same grid (equal samples
  /// and alpha range) one lookup and one multiply-add per point from the other's cells and
  /// fractions, otherwise as for its contour.
  double sum_of_distances(const Contour_distance_field& other, double bound = std::numeric_limits<double>::infinity()) const {
    require_rows(other.rows());
    if(other.m_samples != m_samples || other.m_lo != m_lo || other.m_step != m_step || m_contour.empty())
      return sum_of_distances(other.m_contour, bound);
    const double limit = bound / m_scale;
    const std::uint16_t* field = m_field.data();
    const Query* q = other.m_query.data();
    const std::size_t n = other.m_query.size();
    double s = 0;
    for(std::size_t i0 = 0; i0 < n; i0 += 32) { // the bound is checked every 32 points
      const std::size_t i1 = std::min(n, i0 + 32);
      for(std::size_t i = i0; i < i1; ++i) {
        const double v0 = field[q[i].cell], v1 = field[q[i].cell + 1];
        s += v0 + static_cast<double>(q[i].frac) * (v1 - v0);
      }
      if(s > limit) break;
    }
    return m_scale * s;
  }

private:
  void require_rows(std::size_t r) const {
    if(r != rows())
      throw Invalid_argument("contour distance field: " + std::to_string(r) + " rows against " + std::to_string(rows()));
  }
  struct Query {
    float frac;
    std::uint32_t cell;
  };
  // linear interpolation of a row at fractional sample x, clamped to [0, cmax]
  static double interpolate(const std::uint16_t* row, double x, double cmax) {
    x = std::min(std::max(x, 0.0), cmax);
    const std::size_t c = static_cast<std::size_t>(std::min(x, cmax - 1.0)); // the last cell holds x = cmax
    const double f = x - static_cast<double>(c);
    const double v0 = row[c], v1 = row[c + 1];
    return v0 + f * (v1 - v0);
  }
  // distance from alpha to the sampled range (0 inside)
  double outside(double alpha) const { return std::max(0.0, m_lo - alpha) + std::max(0.0, alpha - m_hi); }

  void build() {
    const std::size_t R = m_contour.rows(), C = m_samples;
    const double h = m_contour.row_spacing();
    const double inf = std::numeric_limits<double>::infinity();
    const float* a = m_contour.alphas().data();
    // 1. per row: squared alpha distance from each sample to the row's nearest point (column-major)
    std::vector<double> g(C * R, inf);
    std::vector<std::size_t> filled;
    for(std::size_t r = 0; r < R; ++r) {
      const std::size_t b = m_contour.row_begin(r), e = m_contour.row_end(r);
      if(b == e) continue;
      filled.push_back(r);
      std::size_t j = b;
      for(std::size_t c = 0; c < C; ++c) {
        const double x = m_lo + static_cast<double>(c) * m_step;
        while(j + 1 < e && static_cast<double>(a[j + 1]) <= x) ++j;
        double d = std::abs(x - static_cast<double>(a[j]));
        if(j + 1 < e) d = std::min(d, static_cast<double>(a[j + 1]) - x);
        g[c * R + r] = d * d;
      }
    }
    // 2. per column: the lower envelope of the parabolas g(q) + (y - y_q)^2 over the filled rows q
    std::vector<double> dist(R * C);
    std::vector<std::size_t> v(filled.size());
    std::vector<double> z(filled.size() + 1);
    double largest = 0;
    for(std::size_t c = 0; c < C; ++c) {
      const double* gc = g.data() + c * R;
      std::size_t k = 0;
      v[0] = filled[0];
      z[0] = -inf;
      z[1] = inf;
      // the parabola of row q lies below the envelope from z[k] on; z[0] = -infinity stops the pops
      auto crossing = [&](std::size_t q, std::size_t p) {
        const double yq = static_cast<double>(q) * h, yp = static_cast<double>(p) * h;
        return ((gc[q] + yq * yq) - (gc[p] + yp * yp)) / (2.0 * (yq - yp));
      };
      for(std::size_t i = 1; i < filled.size(); ++i) {
        const std::size_t q = filled[i];
        double s = crossing(q, v[k]);
        while(s <= z[k]) s = crossing(q, v[--k]);
        ++k;
        v[k] = q;
        z[k] = s;
        z[k + 1] = inf;
      }
      std::size_t j = 0;
      for(std::size_t r = 0; r < R; ++r) {
        const double y = static_cast<double>(r) * h;
        while(z[j + 1] < y) ++j;
        const double dy = y - static_cast<double>(v[j]) * h;
        const double d = std::sqrt(dy * dy + gc[v[j]]);
        dist[r * C + c] = d;
        largest = std::max(largest, d);
      }
    }
    // 3. 16-bit fractions of the largest distance, rounded to nearest
    m_scale = largest > 0 ? largest / 65535.0 : 1.0 / 65535.0;
    m_field.resize(R * C);
    for(std::size_t i = 0; i < R * C; ++i) m_field[i] = static_cast<std::uint16_t>(std::lround(dist[i] / m_scale));
  }

  Spin_contour m_contour;
  std::size_t m_samples = 0;
  double m_lo = 0, m_hi = 1, m_step = 1, m_scale = 1.0 / 65535.0;
  std::vector<std::uint16_t> m_field;
  std::vector<Query> m_query;
};

/// \ingroup PkgShapeCorrDescriptors
/// The symmetric normalized L1 distance of two contours (as `contour_l1_distance`) read from their
/// distance fields: `(sum_{x in X} d_Y(x) + sum_{y in Y} d_X(y)) / (|X| + |Y|)` with the
/// interpolated distances; differs from the exact value by at most the larger `error_bound()` of
/// the two fields. Symmetric; 0 for two empty contours, +infinity when only one is empty. With
/// `bound`: stops once the result is known to exceed it and returns some value > `bound`.
/// \throws Invalid_argument when the numbers of rows differ or the rows lie on different lines
inline double approximate_contour_l1_distance(const Contour_distance_field& X, const Contour_distance_field& Y,
                                              double bound = std::numeric_limits<double>::infinity()) {
  return internal::symmetric_contour_l1(X.contour(), Y.contour(), bound, [&](double limit) { return Y.sum_of_distances(X, limit); },
                                        [&](double limit) { return X.sum_of_distances(Y, limit); });
}

/// \ingroup PkgShapeCorrDescriptors
/// The distance functor of prepared contours for the matchers (`approximate_contour_l1_distance`).
struct Approximate_contour_l1_distance {
  /// `approximate_contour_l1_distance(a, b)`
  double operator()(const Contour_distance_field& a, const Contour_distance_field& b) const { return approximate_contour_l1_distance(a, b); }
  /// early-exit form used by `match_descriptors`
  double operator()(const Contour_distance_field& a, const Contour_distance_field& b, double bound) const {
    return approximate_contour_l1_distance(a, b, bound);
  }
};

} // namespace shapecorr

#endif
