// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file write_spin_descriptor_plot.h
/// A picture of one spin descriptor: the spin image and its Spin Contour side by side (the view of
/// the thesis's Figure 3.3).
#ifndef SHAPECORR_IO_WRITE_SPIN_DESCRIPTOR_PLOT_H
#define SHAPECORR_IO_WRITE_SPIN_DESCRIPTOR_PLOT_H

#include <shapecorr/descriptors/Spin_contour.h>
#include <shapecorr/descriptors/Spin_image.h>
#include <shapecorr/io/write_colored_ply.h>
#include <shapecorr/io/write_png.h>

#include <algorithm>
#include <cmath>
#include <string>

namespace shapecorr {

/// \ingroup PkgShapeCorrDescriptors
/// The picture: left, the image (`scale` pixels per bin, viridis on the square root of the bin
/// values, empty bins white); right, the contour's points (black) on the same grid (alpha to the
/// right, beta up; light grey marks the bins the image touches). Either may be empty (its panel
/// stays blank); when both are given they must have the same number of rows.
inline Rgb_picture spin_descriptor_picture(const Spin_image& img, const Spin_contour& contour, std::size_t scale = 4) {
  const std::size_t rows = img.rows() ? img.rows() : contour.rows();
  const std::size_t cols = img.columns() ? img.columns() : std::max<std::size_t>(1, rows / 2);
  if(rows == 0) throw Invalid_argument("spin descriptor picture: nothing to draw");
  if(img.rows() && contour.rows() && img.rows() != contour.rows())
    throw Invalid_argument("spin descriptor picture: image and contour have different numbers of rows");
  const std::size_t gap = 2 * scale, W = cols * scale, H = rows * scale;
  Rgb_picture pic(2 * W + 3 * gap, H + 2 * gap);
  const std::array<std::uint8_t, 3> frame = {{160, 160, 160}};
  for(std::size_t panel = 0; panel < 2; ++panel) {
    const std::size_t x0 = gap + panel * (W + gap);
    for(std::size_t x = x0 - 1; x <= x0 + W; ++x) {
      pic.set(x, gap - 1, frame);
      pic.set(x, gap + H, frame);
    }
    for(std::size_t y = gap - 1; y <= gap + H; ++y) {
      pic.set(x0 - 1, y, frame);
      pic.set(x0 + W, y, frame);
    }
  }
  if(img.rows()) {
    float top = 0;
    for(float v : img.values()) top = std::max(top, v);
    for(std::size_t r = 0; r < rows; ++r)
      for(std::size_t c = 0; c < cols; ++c) {
        const float v = img.at(r, c);
        if(!(v > 0)) continue;
        const auto col = colormap_viridis(std::sqrt(static_cast<double>(v / top)));
        for(std::size_t dy = 0; dy < scale; ++dy)
          for(std::size_t dx = 0; dx < scale; ++dx) {
            pic.set(gap + c * scale + dx, gap + r * scale + dy, {{col[0], col[1], col[2]}});
            pic.set(2 * gap + W + c * scale + dx, gap + r * scale + dy, {{232, 232, 232}});
          }
      }
  }
  for(std::size_t r = 0; r < contour.rows(); ++r)
    for(std::size_t i = contour.row_begin(r); i < contour.row_end(r); ++i) {
      const double x = static_cast<double>(contour.alphas()[i]) * static_cast<double>(W);
      const std::size_t px = 2 * gap + W + std::min(W - 1, static_cast<std::size_t>(std::max(0.0, x)));
      const std::size_t py = gap + r * scale + scale / 2;
      for(std::size_t d = 0; d + 1 < std::max<std::size_t>(2, scale / 2 + 1); ++d) {
        pic.set(px + d, py, {{0, 0, 0}});
        pic.set(px, py + d, {{0, 0, 0}});
      }
    }
  return pic;
}

/// \ingroup PkgShapeCorrDescriptors
/// Writes `spin_descriptor_picture(img, contour, scale)` as a PNG file.
inline void write_spin_descriptor_plot(const std::string& path, const Spin_image& img, const Spin_contour& contour, std::size_t scale = 4) {
  write_png(path, spin_descriptor_picture(img, contour, scale));
}

} // namespace shapecorr

#endif
