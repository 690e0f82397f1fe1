// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Contour_nearest_point_index.h
/// A spin contour prepared for fast exact comparisons: per row, the lower envelope of the squared
/// distances to all its points, and a grid of cells listing the (at most two) points that can be
/// nearest inside each cell.
#ifndef SHAPECORR_DESCRIPTORS_CONTOUR_NEAREST_POINT_INDEX_H
#define SHAPECORR_DESCRIPTORS_CONTOUR_NEAREST_POINT_INDEX_H

#include <shapecorr/descriptors/Spin_contour.h>
#include <shapecorr/exceptions.h>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrDescriptors
/// A spin contour (rigid or geodesic) prepared for nearest-point queries on its own rows: the
/// symmetric normalized L1 distance of two prepared contours (the `contour_l1_distance` overload)
/// is the exact distance of the two contours, computed with the same arithmetic, without any
/// search.
///
/// A point of another contour with the same rows lies on a row line r; its squared distance to
/// point j of this contour is `(alpha - alpha_j)^2 + (h k_j)^2`, h the row spacing and k_j the row
/// gap. Along the line the nearest point is given by the lower envelope of these parabolas
/// (Felzenszwalb & Huttenlocher's 1-D construction over the points in alpha order). Each row line
/// is cut into `cells_per_row` equal cells over [min(0, min alpha), max(1, max alpha)], plus one
/// cell for everything below and one for everything above, and each cell stores the first envelope
/// piece it meets. When a cell meets at most two pieces (the common case) the squared distance
/// from a point in it is the smaller of two candidates, evaluated as `contour_l1_distance`
/// evaluates it; cells meeting more pieces are marked and their points take the row search
/// (`slow_cell_fraction()`). The candidates are found with the envelope's breakpoints widened by a
/// margin against their rounding, so the result equals `contour_l1_distance` bit for bit whenever
/// that margin covers the rounding (all 64 x 64 pairs of the benchmark; in general, up to the
/// rounding of a breakpoint between points a few ulps apart in alpha).
///
/// Cost: preparing is O(points + rows x cells) (less than building the contour); memory is one
/// byte per cell and 6 bytes per envelope piece (a few tens of KB for 120 rows); a comparison is
/// one cell lookup and a few envelope pieces per point, O(points), instead of the row search's
/// binary searches. Worth it when each contour is compared many times (matching N sources against
/// M targets prepares N + M contours for N x M comparisons). benchmark/README.md has the measured
/// ratios.
class Contour_nearest_point_index {
public:
  Contour_nearest_point_index() = default;
  /// \throws Invalid_argument when `cells_per_row` is 0 or above 65536, or the contour has no rows or
  /// more than 65535
  explicit Contour_nearest_point_index(const Spin_contour& contour, std::size_t cells_per_row = 128)
    : m_contour(contour), m_cells(cells_per_row) {
    if(cells_per_row == 0 || cells_per_row > 65536)
      throw Invalid_argument("contour nearest-point index: cells_per_row must be in [1, 65536]");
    if(contour.rows() == 0 || contour.rows() > 65535)
      throw Invalid_argument("contour nearest-point index: the contour has " + std::to_string(contour.rows()) + " rows (1 to 65535 supported)");
    if(contour.empty()) return;
    const auto range = std::minmax_element(contour.alphas().begin(), contour.alphas().end());
    m_lo = std::min(0.0, static_cast<double>(*range.first));
    const double hi = std::max(1.0, static_cast<double>(*range.second));
    m_inv_width = static_cast<double>(m_cells) / (hi - m_lo);
    build();
    // the own points as queries, in the order of contour_l1_distance's sums
    m_query.reserve(contour.size());
    for(std::size_t r = 0; r < contour.rows(); ++r)
      for(std::size_t i = contour.row_begin(r); i < contour.row_end(r); ++i) {
        const std::uint32_t r32 = static_cast<std::uint32_t>(r);
        m_query.push_back({static_cast<double>(contour.alphas()[i]), r32, cell_of(r32, contour.alphas()[i])});
      }
  }

  /// The contour the index was built from.
  const Spin_contour& contour() const { return m_contour; }
  /// Number of rows.
  std::size_t rows() const { return m_contour.rows(); }
  /// Number of alpha cells per row line.
  std::size_t cells_per_row() const { return m_cells; }
  /// Number of envelope pieces over all rows.
  std::size_t number_of_pieces() const { return m_piece_alpha.size() - rows(); }
  /// Fraction of the cells whose points take the row search (more than two envelope pieces).
  double slow_cell_fraction() const { return m_cell.empty() ? 0.0 : static_cast<double>(m_slow_cells) / static_cast<double>(m_cell.size()); }
  /// Bytes of the cells, the envelope pieces and the own points.
  std::size_t memory_bytes() const {
    return m_cell.size() + m_piece_alpha.size() * (sizeof(float) + sizeof(std::uint16_t)) + m_row_piece.size() * sizeof(std::uint32_t) +
           m_query.size() * sizeof(Query);
  }

  /// The distance from the point (alpha, beta of row r) to the contour (+infinity for an empty
  /// contour).
  /// \throws Invalid_argument when r is not a row
  double distance(std::size_t r, float alpha) const {
    if(r >= rows()) throw Invalid_argument("contour nearest-point index: row " + std::to_string(r) + " of " + std::to_string(rows()));
    if(m_contour.empty()) return std::numeric_limits<double>::infinity();
    const std::uint32_t r32 = static_cast<std::uint32_t>(r);
    return std::sqrt(nearest2(r32, static_cast<double>(alpha), cell_of(r32, alpha)));
  }

  /// The sum over the points of `other` (a contour on the same rows) of their distances to this
  /// contour, equal to the sum of `contour_l1_distance`; stops early, returning a value > `bound`,
  /// once the sum exceeds `bound`.
  /// \throws Invalid_argument when the numbers of rows differ
  double sum_of_distances(const Contour_nearest_point_index& other, double bound = std::numeric_limits<double>::infinity()) const {
    if(other.rows() != rows())
      throw Invalid_argument("contour nearest-point index: " + std::to_string(other.rows()) + " rows against " + std::to_string(rows()));
    if(other.m_query.empty()) return 0.0;
    if(m_contour.empty()) return std::numeric_limits<double>::infinity();
    const Query* q = other.m_query.data();
    const std::size_t n = other.m_query.size();
    const bool same_grid = other.m_cells == m_cells && other.m_lo == m_lo && other.m_inv_width == m_inv_width;
    double s = 0;
    for(std::size_t i0 = 0; i0 < n; i0 += 32) { // the bound is checked every 32 points
      const std::size_t i1 = std::min(n, i0 + 32);
      if(same_grid)
        add_roots(s, i0, i1, [&](std::size_t i) { return nearest2(q[i].row, q[i].x, q[i].cell); });
      else
        add_roots(s, i0, i1, [&](std::size_t i) { return nearest2(q[i].row, q[i].x, cell_of(q[i].row, static_cast<float>(q[i].x))); });
      if(s > bound) break;
    }
    return s;
  }

private:
  static constexpr std::uint8_t kSlow = 0xFF; // a cell meeting more than two pieces (or a piece beyond 254)
  struct Query {
    double x;                // alpha
    std::uint32_t row, cell; // the cell on the index's own grid
  };

  // s += sqrt(f(i)) for i in [i0, i1), in this order; the square roots two at a time (the same
  // correctly rounded results, half the square-root instructions)
  template <typename F>
  static void add_roots(double& s, std::size_t i0, std::size_t i1, F&& f) {
    std::size_t i = i0;
#if defined(__SSE2__)
    for(; i + 1 < i1; i += 2) {
      const double v0 = f(i), v1 = f(i + 1);
      const __m128d r = _mm_sqrt_pd(_mm_set_pd(v1, v0));
      s += _mm_cvtsd_f64(r);
      s += _mm_cvtsd_f64(_mm_unpackhi_pd(r, r));
    }
#endif
    for(; i < i1; ++i) s += std::sqrt(f(i));
  }
  // cells 1..C of a row cover [lo, hi), cell 0 everything below, cell C + 1 everything above
  std::uint32_t cell_of(std::uint32_t r, float alpha) const {
    const double cx = std::min(std::max((static_cast<double>(alpha) - m_lo) * m_inv_width + 1.0, 0.0), static_cast<double>(m_cells + 1));
    return static_cast<std::uint32_t>(r * (m_cells + 2) + static_cast<std::size_t>(cx));
  }
  // Squared distance from (x, row r) to the nearest point: the smaller of the cell's two
  // candidates (pieces e and e + 1 of the row: the arrays hold them side by side), or the row
  // search in a marked cell.
  double nearest2(std::uint32_t r, double x, std::uint32_t cell) const {
    const std::uint8_t e = m_cell[cell];
    if(e == kSlow) return internal::nearest_contour_point2(m_contour, r, static_cast<float>(x));
    const std::size_t j = m_row_piece[r] + e;
#if defined(__SSE2__)
    // both candidates at once (the same IEEE operations as the scalar code below)
    std::int32_t gaps;
    std::memcpy(&gaps, m_piece_gap.data() + j, sizeof gaps);
    double alphas; // the two floats, copied (not loaded through a double*: j may be odd, and the load misaligned)
    std::memcpy(&alphas, m_piece_alpha.data() + j, sizeof alphas);
    const __m128d hk = _mm_mul_pd(_mm_set1_pd(m_h), _mm_cvtepi32_pd(_mm_unpacklo_epi16(_mm_cvtsi32_si128(gaps), _mm_setzero_si128())));
    const __m128d d = _mm_sub_pd(_mm_cvtps_pd(_mm_castpd_ps(_mm_set_sd(alphas))), _mm_set1_pd(x));
    const __m128d v = _mm_add_pd(_mm_mul_pd(hk, hk), _mm_mul_pd(d, d));
    return std::min(_mm_cvtsd_f64(v), _mm_cvtsd_f64(_mm_unpackhi_pd(v, v)));
#else
    const double h0 = m_h * static_cast<double>(m_piece_gap[j]), h1 = m_h * static_cast<double>(m_piece_gap[j + 1]);
    const double d0 = static_cast<double>(m_piece_alpha[j]) - x, d1 = static_cast<double>(m_piece_alpha[j + 1]) - x;
    return std::min(h0 * h0 + d0 * d0, h1 * h1 + d1 * d1);
#endif
  }

  void build() {
    const std::size_t R = m_contour.rows(), C = m_cells + 2, n = m_contour.size(); // with the two outer cells
    const double h = m_contour.row_spacing();
    const float* a = m_contour.alphas().data();
    // the points in alpha order (ties: by row), with their rows
    std::vector<std::uint32_t> row_of(n);
    for(std::size_t r = 0; r < R; ++r)
      for(std::size_t i = m_contour.row_begin(r); i < m_contour.row_end(r); ++i) row_of[i] = static_cast<std::uint32_t>(r);
    std::vector<std::uint32_t> order(n);
    std::iota(order.begin(), order.end(), 0u);
    std::sort(order.begin(), order.end(), [&](std::uint32_t i, std::uint32_t j) { return a[i] < a[j] || (a[i] == a[j] && row_of[i] < row_of[j]); });
    // the squared row gaps as contour_l1_distance computes them
    std::vector<double> gap2_of(R);
    for(std::size_t k = 0; k < R; ++k) gap2_of[k] = (h * static_cast<double>(k)) * (h * static_cast<double>(k));
    m_h = h;
    const double inf = std::numeric_limits<double>::infinity();
    const double width = 1.0 / m_inv_width;
    // widening of the cells when listing the pieces they meet: covers the rounding of the
    // breakpoints (a listed piece too many is harmless, one too few would not be)
    const double eps = 1e-9 * std::max(1.0, std::abs(m_lo) + static_cast<double>(m_cells) * width);
    std::vector<std::uint32_t> v(n); // envelope: point indices
    std::vector<double> z(n + 1);    // and the left ends of their pieces
    m_row_piece.assign(R, 0u);
    m_cell.assign(R * C, 0);
    m_slow_cells = 0;
    for(std::size_t r = 0; r < R; ++r) {
      auto gap = [&](std::uint32_t i) { return row_of[i] > r ? row_of[i] - r : static_cast<std::uint32_t>(r) - row_of[i]; };
      auto gap2 = [&](std::uint32_t i) { return gap2_of[gap(i)]; };
      // where parabola q gets below parabola p (a_q > a_p)
      auto crossing = [&](std::uint32_t q, std::uint32_t p) {
        const double aq = a[q], ap = a[p];
        return ((gap2(q) + aq * aq) - (gap2(p) + ap * ap)) / (2.0 * (aq - ap));
      };
      std::size_t k = 0;
      v[0] = order[0];
      z[0] = -inf;
      for(std::size_t t = 1; t < n; ++t) {
        const std::uint32_t q = order[t];
        // equal alphas: only the smaller gap can be nearest (equal gaps: the same distances)
        if(a[q] == a[v[k]]) {
          if(gap2(q) >= gap2(v[k])) continue;
          if(k == 0) {
            v[0] = q;
            continue;
          }
          --k;
        }
        double s = crossing(q, v[k]);
        while(s <= z[k]) s = crossing(q, v[--k]); // z[0] = -infinity stops the pops
        v[++k] = q;
        z[k] = s;
      }
      z[k + 1] = inf;
      // the pieces, with a copy of the last as a sentinel (a cell always reads two)
      m_row_piece[r] = static_cast<std::uint32_t>(m_piece_alpha.size());
      for(std::size_t j = 0; j <= k + 1; ++j) {
        m_piece_alpha.push_back(a[v[std::min(j, k)]]);
        m_piece_gap.push_back(static_cast<std::uint16_t>(gap(v[std::min(j, k)])));
      }
      // the pieces each cell meets: first .. last
      std::size_t first = 0, last = 0;
      for(std::size_t c = 0; c < C; ++c) {
        const double x0 = c == 0 ? -inf : m_lo + static_cast<double>(c - 1) * width - eps;
        const double x1 = c + 1 == C ? inf : m_lo + static_cast<double>(c) * width + eps;
        while(first < k && z[first + 1] <= x0) ++first;
        if(last < first) last = first;
        while(last < k && z[last + 1] < x1) ++last;
        if(last - first >= 2 || first >= kSlow) {
          m_cell[r * C + c] = kSlow;
          ++m_slow_cells;
        } else {
          m_cell[r * C + c] = static_cast<std::uint8_t>(first);
        }
      }
    }
  }

  Spin_contour m_contour;
  std::size_t m_cells = 0;
  double m_lo = 0, m_inv_width = 1;
  std::vector<std::uint8_t> m_cell;     // per row and cell: the first piece it meets (row-relative), or kSlow
  // per row: the envelope's parabolas (x - alpha)^2 + (h gap)^2 in alpha order, and a sentinel
  std::vector<float> m_piece_alpha;
  std::vector<std::uint16_t> m_piece_gap;
  double m_h = 0;                                  // row spacing
  std::vector<std::uint32_t> m_row_piece;          // each row's first piece
  std::vector<Query> m_query;
  std::size_t m_slow_cells = 0;
};

/// \ingroup PkgShapeCorrDescriptors
/// The symmetric normalized L1 distance of two prepared contours: the value of
/// `contour_l1_distance(X.contour(), Y.contour(), bound)`, from the nearest-point indices.
/// \throws Invalid_argument when the numbers of rows differ or the rows lie on different lines
inline double contour_l1_distance(const Contour_nearest_point_index& X, const Contour_nearest_point_index& Y,
                                  double bound = std::numeric_limits<double>::infinity()) {
  return internal::symmetric_contour_l1(X.contour(), Y.contour(), bound, [&](double limit) { return Y.sum_of_distances(X, limit); },
                                        [&](double limit) { return X.sum_of_distances(Y, limit); });
}

/// \ingroup PkgShapeCorrDescriptors
/// The distance functor of prepared contours for the matchers (`contour_l1_distance`).
struct Indexed_contour_l1_distance {
  /// `contour_l1_distance(a, b)`
  double operator()(const Contour_nearest_point_index& a, const Contour_nearest_point_index& b) const { return contour_l1_distance(a, b); }
  /// early-exit form used by `match_descriptors`
  double operator()(const Contour_nearest_point_index& a, const Contour_nearest_point_index& b, double bound) const {
    return contour_l1_distance(a, b, bound);
  }
};

} // namespace shapecorr

#endif
