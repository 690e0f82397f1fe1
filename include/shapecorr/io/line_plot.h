// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file line_plot.h
/// Line plots into a picture (axes, ticks, curves, a legend in the 5x7 bitmap font of
/// draw_on_picture.h): the curves of the evaluations and of shape model reports.
#ifndef SHAPECORR_IO_LINE_PLOT_H
#define SHAPECORR_IO_LINE_PLOT_H

#include <shapecorr/io/draw_on_picture.h>
#include <shapecorr/io/write_png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrIO
/// One curve of `line_plot()`: its legend label and its points (x[i], y[i]).
struct Plot_curve {
  std::string label;        ///< the legend's text (the 5x7 font: upper case, digits, punctuation)
  std::vector<double> x; ///< the points' abscissae, in drawing order
  std::vector<double> y; ///< their ordinates
};

/// \ingroup PkgShapeCorrIO
/// Colour i of the plots (ten, repeating).
inline std::array<std::uint8_t, 3> plot_palette(std::size_t i) {
  static const std::array<std::array<std::uint8_t, 3>, 10> c = {{{{31, 119, 180}}, {{255, 127, 14}}, {{44, 160, 44}}, {{214, 39, 40}},
                                                                 {{148, 103, 189}}, {{140, 86, 75}}, {{227, 119, 194}}, {{127, 127, 127}},
                                                                 {{188, 189, 34}}, {{23, 190, 207}}}};
  return c[i % c.size()];
}

/// \ingroup PkgShapeCorrIO
/// A 640 × 480 picture of `curves` in [0, xmax] × [0, ymax] (values beyond are clipped), with
/// a grid, ticks, a title, axis labels and a legend, for `write_png()`.
inline Rgb_picture line_plot(const std::vector<Plot_curve>& curves, const std::string& title, const std::string& xlabel,
                                        const std::string& ylabel, double xmax = 1.0, double ymax = 1.0) {
  const std::size_t W = 640, H = 480, left = 60, right = 170, top = 30, bottom = 50;
  Rgb_picture p(W, H);
  const double pw = static_cast<double>(W - left - right), ph = static_cast<double>(H - top - bottom);
  auto X = [&](double x) { return static_cast<double>(left) + x / xmax * pw; };
  auto Y = [&](double y) { return static_cast<double>(H - bottom) - y / ymax * ph; };
  const std::array<std::uint8_t, 3> grey = {{215, 215, 215}}, black = {{0, 0, 0}};
  for(int t = 0; t <= 10; ++t) {
    const double fx = xmax * t / 10, fy = ymax * t / 10;
    draw_line(p, X(fx), Y(0), X(fx), Y(ymax), grey, 1);
    draw_line(p, X(0), Y(fy), X(xmax), Y(fy), grey, 1);
    if(t % 2 == 0) {
      char buf[16];
      std::snprintf(buf, sizeof buf, "%.3g", fx);
      draw_text(p, static_cast<std::size_t>(X(fx)) - 9, H - bottom + 6, buf);
      std::snprintf(buf, sizeof buf, "%.3g", fy);
      draw_text(p, left - 24, static_cast<std::size_t>(Y(fy)) - 3, buf);
    }
  }
  draw_line(p, X(0), Y(0), X(xmax), Y(0), black, 1);
  draw_line(p, X(0), Y(0), X(0), Y(ymax), black, 1);
  draw_text(p, left, 10, title);
  draw_text(p, left + static_cast<std::size_t>(pw / 2) - 3 * xlabel.size(), H - 20, xlabel);
  draw_text(p, 4, top - 14, ylabel);
  for(std::size_t i = 0; i < curves.size(); ++i) {
    const auto c = plot_palette(i);
    const Plot_curve& cv = curves[i];
    for(std::size_t k = 1; k < cv.x.size(); ++k)
      draw_line(p, X(std::min(cv.x[k - 1], xmax)), Y(std::min(cv.y[k - 1], ymax)), X(std::min(cv.x[k], xmax)), Y(std::min(cv.y[k], ymax)), c);
    const std::size_t ly = top + 10 + 16 * i;
    draw_line(p, static_cast<double>(W - right + 10), static_cast<double>(ly + 3), static_cast<double>(W - right + 30), static_cast<double>(ly + 3), c, 3);
    draw_text(p, W - right + 36, ly, cv.label);
  }
  return p;
}

} // namespace shapecorr

#endif
