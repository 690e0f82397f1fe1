// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Spin_image.h
/// The spin image value type and its comparison (Johnson & Hebert 1999).
#ifndef SHAPECORR_DESCRIPTORS_SPIN_IMAGE_H
#define SHAPECORR_DESCRIPTORS_SPIN_IMAGE_H

#include <shapecorr/exceptions.h>

#include <cmath>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrDescriptors
/// A spin image: `rows x columns` bins over the spin coordinates of an oriented point (P, n),
/// alpha (distance to the axis) in [0, L] along the columns (column 0 at alpha = 0) and beta
/// (signed height above the tangent plane) in [-L, L] along the rows (row 0 at beta = +L), L the
/// support length. Bin c of a row covers alpha in [c, c+1] L / columns, row r covers beta in
/// [L - (r+1) 2L/rows, L - r 2L/rows]. Values are vertex counts (spin image) or areas (face-based).
class Spin_image {
public:
  Spin_image() = default;
  /// An image of zeros.
  Spin_image(std::size_t rows, std::size_t columns, double support_length)
    : m_rows(rows), m_cols(columns), m_support(support_length), m_values(rows * columns, 0.0f) {}
  /// Number of rows (beta bins).
  std::size_t rows() const { return m_rows; }
  /// Number of columns (alpha bins).
  std::size_t columns() const { return m_cols; }
  /// The support length L (mesh units).
  double support_length() const { return m_support; }
  /// Bin (r, c).
  float& at(std::size_t r, std::size_t c) { return m_values[r * m_cols + c]; }
  /// Bin (r, c).
  float at(std::size_t r, std::size_t c) const { return m_values[r * m_cols + c]; }
  /// The bins, row-major.
  const std::vector<float>& values() const { return m_values; }
  /// The bins, row-major (writable).
  std::vector<float>& values() { return m_values; }

private:
  std::size_t m_rows = 0, m_cols = 0;
  double m_support = 0;
  std::vector<float> m_values;
};

/// \ingroup PkgShapeCorrDescriptors
/// The linear correlation coefficient R of two spin images over their overlap (the bins where both
/// are nonzero; Johnson & Hebert 1999, eq. 2), and the size N of the overlap. R = 0 when N < 2 or a
/// side is constant on the overlap.
/// \throws Invalid_argument when the sizes differ
inline std::pair<double, std::size_t> spin_image_correlation(const Spin_image& a, const Spin_image& b) {
  if(a.rows() != b.rows() || a.columns() != b.columns())
    throw Invalid_argument("spin image comparison: sizes differ (" + std::to_string(a.rows()) + "x" +
                                                           std::to_string(a.columns()) + " vs " + std::to_string(b.rows()) + "x" +
                                                           std::to_string(b.columns()) + ")");
  const float* p = a.values().data();
  const float* q = b.values().data();
  const std::size_t m = a.values().size();
  double sp = 0, sq = 0, spp = 0, sqq = 0, spq = 0;
  std::size_t n = 0;
  for(std::size_t i = 0; i < m; ++i) {
    const double x = p[i], y = q[i];
    const bool both = (x != 0) & (y != 0);
    const double w = both ? 1.0 : 0.0;
    n += both;
    sp += w * x;
    sq += w * y;
    spp += w * x * x;
    sqq += w * y * y;
    spq += w * x * y;
  }
  if(n < 2) return {0.0, n};
  const double N = static_cast<double>(n);
  const double den = (N * spp - sp * sp) * (N * sqq - sq * sq);
  if(!(den > 0)) return {0.0, n};
  return {(N * spq - sp * sq) / std::sqrt(den), n};
}

/// \ingroup PkgShapeCorrDescriptors
/// Johnson & Hebert's similarity measure `C = atanh(R)^2 - lambda / (N - 3)` (eq. 3): larger is
/// more similar; the second term penalizes small overlaps. -infinity when N <= 3 or R <= 0
/// (anti-correlated images are not similar).
inline double spin_image_similarity(const Spin_image& a, const Spin_image& b, double lambda = 3.0) {
  const auto rn = spin_image_correlation(a, b);
  if(rn.second <= 3 || !(rn.first > 0)) return -std::numeric_limits<double>::infinity();
  const double r = std::min(rn.first, 1.0 - 1e-12);
  const double z = std::atanh(r);
  return z * z - lambda / static_cast<double>(rn.second - 3);
}

/// \ingroup PkgShapeCorrDescriptors
/// The distance of two spin images used by the matchers: `1 - R` (in [0, 2]; 0 for proportional
/// images), R from `spin_image_correlation`. Ranking by it equals ranking by Johnson & Hebert's
/// correlation; use `spin_image_similarity` for their overlap-penalized measure.
struct Spin_image_distance {
  /// The distance of two images (see the struct).
  double operator()(const Spin_image& a, const Spin_image& b) const { return 1.0 - spin_image_correlation(a, b).first; }
};

} // namespace shapecorr

#endif
