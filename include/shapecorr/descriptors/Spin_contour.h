// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Spin_contour.h
/// The Spin Contour value type (thesis chapter 3, also the Geodesic Spin Contour of chapter 4) and
/// the symmetric normalized L1 contour distance.
#ifndef SHAPECORR_DESCRIPTORS_SPIN_CONTOUR_H
#define SHAPECORR_DESCRIPTORS_SPIN_CONTOUR_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/kd_tree.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrDescriptors
/// A spin contour: a set of 2-D points (alpha, beta) in normalized coordinates lying on `rows`
/// horizontal lines `beta_r = beta_first + (r + 1/2) (beta_last - beta_first) / rows`. The Spin
/// Contour (chapter 3) has beta in [-1, 1] (`beta_first` 1: row 0 on top) and alpha in [0, 1], both
/// divided by the support length L; the Geodesic Spin Contour (chapter 4) has beta = gd / L in
/// [0, 1] (row 0 nearest to the point) and alpha = agd divided by its scale. The points of a row
/// are kept sorted by alpha.
class Spin_contour {
public:
  Spin_contour() = default;
  /// An empty contour of `rows` rows (beta of row r: `beta(r)`, from `beta_first` to `beta_last` over the rows).
  explicit Spin_contour(std::size_t rows, double support_length = 1.0, double beta_first = 1.0, double beta_last = -1.0)
    : m_rows(rows), m_support(support_length), m_beta0(beta_first),
      m_step(rows > 0 ? (beta_last - beta_first) / static_cast<double>(rows) : 0.0), m_begin(rows + 1, 0u) {}

  /// Number of rows (beta samples).
  std::size_t rows() const { return m_rows; }
  /// The support length L the coordinates were divided by (mesh units).
  double support_length() const { return m_support; }
  /// Number of points.
  std::size_t size() const { return m_alpha.size(); }
  /// Whether the contour has no point.
  bool empty() const { return m_alpha.empty(); }
  /// Normalized beta of row r.
  double beta(std::size_t r) const { return m_beta0 + (static_cast<double>(r) + 0.5) * m_step; }
  /// Distance between two neighbouring rows, in normalized units.
  double row_spacing() const { return std::abs(m_step); }
  /// The alphas of row r, ascending: [row_begin(r), row_end(r)) of `alphas()`.
  std::size_t row_begin(std::size_t r) const { return m_begin[r]; }
  /// End of row r in `alphas()`.
  std::size_t row_end(std::size_t r) const { return m_begin[r + 1]; }
  /// The alphas of all points, row after row.
  const std::vector<float>& alphas() const { return m_alpha; }
  /// All points as (alpha, beta), rows top to bottom.
  std::vector<std::array<double, 2>> points() const {
    std::vector<std::array<double, 2>> p;
    p.reserve(size());
    for(std::size_t r = 0; r < m_rows; ++r)
      for(std::size_t i = row_begin(r); i < row_end(r); ++i) p.push_back({static_cast<double>(m_alpha[i]), beta(r)});
    return p;
  }
  /// Reserves room for `points` points in all (appending then does not reallocate).
  void reserve(std::size_t points) { m_alpha.reserve(points); }
  /// Appends the (sorted) alphas of the next row; rows are appended in order 0, 1, ...
  template <typename Iterator>
  void append_row(std::size_t r, Iterator first, Iterator last) {
    m_alpha.insert(m_alpha.end(), first, last);
    m_begin[r + 1] = static_cast<std::uint32_t>(m_alpha.size());
  }

private:
  std::size_t m_rows = 0;
  double m_support = 1.0;
  double m_beta0 = 1.0, m_step = -2.0;
  std::vector<std::uint32_t> m_begin{0u};
  std::vector<float> m_alpha;
};

namespace internal {
// Squared distance from a to the nearest of the sorted values [y, y + ny) (infinity when empty).
inline double nearest_in_row2(const float* y, std::size_t ny, float a) {
  if(ny == 0) return std::numeric_limits<double>::infinity();
  const float* it = std::lower_bound(y, y + ny, a);
  double d = std::numeric_limits<double>::infinity();
  if(it != y + ny) d = static_cast<double>(*it) - a;
  if(it != y) d = std::min(d, static_cast<double>(a) - *(it - 1));
  return d * d;
}

// Squared distance from the point (a, row r) to the nearest point of Y: rows of Y outwards from r
// until the row gap exceeds the best distance found.
inline double nearest_contour_point2(const Spin_contour& Y, std::size_t r, float a) {
  const std::size_t R = Y.rows();
  const double h = Y.row_spacing();
  const float* ya = Y.alphas().data();
  double best = nearest_in_row2(ya + Y.row_begin(r), Y.row_end(r) - Y.row_begin(r), a);
  for(std::size_t k = 1; k < R; ++k) {
    const double gap2 = (h * static_cast<double>(k)) * (h * static_cast<double>(k));
    if(gap2 >= best) break;
    if(r >= k) best = std::min(best, gap2 + nearest_in_row2(ya + Y.row_begin(r - k), Y.row_end(r - k) - Y.row_begin(r - k), a));
    if(r + k < R) best = std::min(best, gap2 + nearest_in_row2(ya + Y.row_begin(r + k), Y.row_end(r + k) - Y.row_begin(r + k), a));
  }
  return best;
}

// Sum over the points of X of the distance to the nearest point of Y (both row-structured, on
// the same rows). Stops early (returning a value >= bound) once the sum exceeds `bound`.
inline double directed_contour_sum(const Spin_contour& X, const Spin_contour& Y, double bound) {
  const float* xa = X.alphas().data();
  double sum = 0;
  for(std::size_t r = 0; r < X.rows(); ++r) {
    for(std::size_t i = X.row_begin(r); i < X.row_end(r); ++i) sum += std::sqrt(nearest_contour_point2(Y, r, xa[i]));
    if(sum > bound) return sum;
  }
  return sum;
}

// `(a + b) / (|X| + |Y|)` from the directed sums a = `xy(limit)` (the points of X against Y) and
// b = `yx(limit)`, each returning a value > limit once its sum exceeds it; checks that the
// contours share their rows; 0 for two empty contours, +infinity when only one is empty.
template <typename XY, typename YX>
double symmetric_contour_l1(const Spin_contour& X, const Spin_contour& Y, double bound, XY&& xy, YX&& yx) {
  if(X.rows() != Y.rows())
    throw Invalid_argument("contour distance: the contours have " + std::to_string(X.rows()) + " and " +
                                                           std::to_string(Y.rows()) + " rows");
  if(X.beta(0) != Y.beta(0) || X.row_spacing() != Y.row_spacing())
    throw Invalid_argument("contour distance: the contours' rows lie on different lines (a Spin Contour and a Geodesic Spin Contour?)");
  if(X.empty() || Y.empty()) return X.empty() && Y.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  const double total = static_cast<double>(X.size() + Y.size());
  const double limit = bound * total;
  const double a = xy(limit);
  if(a > limit) return a / total;
  return (a + yx(limit - a)) / total;
}
} // namespace internal

/// \ingroup PkgShapeCorrDescriptors
/// The symmetric normalized L1 distance of two spin contours (thesis section 3.4):
/// `L1(X, Y) = (sum_{x in X} d(x, Y) + sum_{y in Y} d(y, X)) / (|X| + |Y|)`, d the Euclidean distance
/// to the nearest point of the other set, in normalized coordinates. Exact; the points of a contour
/// lie on its rows, so each nearest point is found by binary searches in the rows outwards from the
/// row of x until the row gap exceeds the distance found (for general point sets see
/// `point_set_l1_distance`). 0 for two empty contours, +infinity when only one is empty.
/// With `bound`: the computation stops as soon as the result is known to exceed `bound` and then
/// returns some value > `bound` (matching only needs the distances below the second best).
/// \throws Invalid_argument when the numbers of rows differ or the rows lie on different lines
inline double contour_l1_distance(const Spin_contour& X, const Spin_contour& Y,
                                  double bound = std::numeric_limits<double>::infinity()) {
  return internal::symmetric_contour_l1(X, Y, bound, [&](double limit) { return internal::directed_contour_sum(X, Y, limit); },
                                        [&](double limit) { return internal::directed_contour_sum(Y, X, limit); });
}

/// \ingroup PkgShapeCorrDescriptors
/// The distance functor of spin contours for the matchers (`contour_l1_distance`).
struct Contour_l1_distance {
  /// `contour_l1_distance(a, b)`
  double operator()(const Spin_contour& a, const Spin_contour& b) const { return contour_l1_distance(a, b); }
  /// early-exit form used by `match_descriptors`
  double operator()(const Spin_contour& a, const Spin_contour& b, double bound) const { return contour_l1_distance(a, b, bound); }
};

/// \ingroup PkgShapeCorrDescriptors
/// The same symmetric normalized L1 distance for any two finite 2-D point sets (ranges of
/// `std::array<double, 2>`), by kd-trees: O(m log m). 0 for two empty sets, +infinity when one is.
template <typename PointRange1, typename PointRange2>
double point_set_l1_distance(const PointRange1& X, const PointRange2& Y) {
  std::vector<std::array<double, 2>> x(X.begin(), X.end()), y(Y.begin(), Y.end());
  if(x.empty() || y.empty()) return x.empty() && y.empty() ? 0.0 : std::numeric_limits<double>::infinity();
  const internal::Kd_tree<2> tx(x), ty(y);
  double s = 0;
  for(const auto& p : x) s += std::sqrt(ty.nearest(p).second);
  for(const auto& p : y) s += std::sqrt(tx.nearest(p).second);
  return s / static_cast<double>(x.size() + y.size());
}

} // namespace shapecorr

#endif
