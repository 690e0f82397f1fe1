// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file render_mesh.h
/// A picture of a mesh coloured by a value per vertex (a distance map, a descriptor distance, a
/// geodesic distance): views from opposite sides, a colour bar with the value range, a title.
/// A small software renderer (orthographic, z-buffered, Gouraud-shaded, 2x2 supersampled) so that
/// reports and docs carry pictures without a display or an OpenGL context.
#ifndef SHAPECORR_IO_RENDER_MESH_H
#define SHAPECORR_IO_RENDER_MESH_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/io/draw_on_picture.h>
#include <shapecorr/io/write_colored_ply.h>
#include <shapecorr/io/write_png.h>

#include <Eigen/Core>
#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrIO
/// How `colored_mesh_picture()` draws.
struct Mesh_picture_options {
  std::size_t view_size = 400; ///< pixels of each (square) view, 16 to 4096
  bool both_sides = true;      ///< two views, from the front and from the back; false: the front only
  /// The direction the camera looks along, and the direction that is up in the picture. Zero (the
  /// default): from the mesh's principal axes, up the axis of largest extent, looking along the
  /// axis of least (so that the views show the largest silhouette), signs fixed by the mesh's
  /// third moments (the same mesh gives the same views).
  Eigen::Vector3d view_direction = Eigen::Vector3d::Zero();
  Eigen::Vector3d view_up = Eigen::Vector3d::Zero(); ///< see `view_direction`
  double min_value = std::numeric_limits<double>::quiet_NaN(); ///< the value coloured dark blue; NaN: the smallest finite value
  double max_value = std::numeric_limits<double>::quiet_NaN(); ///< the value coloured yellow; NaN: the largest finite value
  std::string title;                                           ///< drawn above the views (5x7 capitals)
};

namespace internal {

// The camera frame (right, up, towards the viewer) of `options` for the vertices V.
inline Eigen::Matrix3d picture_frame(const Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor>& V, const Mesh_picture_options& options) {
  Eigen::Vector3d d = options.view_direction, up = options.view_up;
  if(d.squaredNorm() == 0 || up.squaredNorm() == 0) {
    const Eigen::RowVector3d c = V.colwise().mean();
    const Eigen::MatrixXd X = V.rowwise() - c;
    const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> es(X.transpose() * X);
    auto oriented = [&](Eigen::Vector3d e) {
      const double third = (X * e).array().cube().sum();
      return third < 0 ? Eigen::Vector3d(-e) : e;
    };
    if(up.squaredNorm() == 0) up = oriented(es.eigenvectors().col(2));
    if(d.squaredNorm() == 0) d = -oriented(es.eigenvectors().col(0));
  }
  if(!d.allFinite() || !up.allFinite()) throw Invalid_argument("colored_mesh_picture: the view direction and up vector must be finite");
  d.normalize();
  Eigen::Vector3d u = up - up.dot(d) * d; // up, made orthogonal to the view direction
  if(u.norm() < 1e-9 * up.norm()) throw Invalid_argument("colored_mesh_picture: the up vector is parallel to the view direction");
  u.normalize();
  Eigen::Matrix3d frame;
  frame.col(2) = -d;               // towards the viewer
  frame.col(1) = u;                // up
  frame.col(0) = u.cross(frame.col(2)); // right
  return frame;
}

inline std::string format_value(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

} // namespace internal

/// \ingroup PkgShapeCorrIO
/// A picture of `tm` with each vertex coloured by its value (viridis from `min_value`, dark blue,
/// to `max_value`, yellow, linear inside and clamped outside; non-finite values grey) and
/// interpolated across the triangles, shaded by the light of a lamp at the camera (both faces lit).
/// Views: orthographic, the whole mesh fitted into each square view with a margin; with
/// `both_sides` the second view looks from the opposite side (mirror of the first's silhouette).
/// On the right a colour bar labelled with the range, above the views the title.
///
/// \param values one per vertex, in the order of the vertex index map of `np`
/// \throws Invalid_argument for a wrong number of values, a view size out of range, an up vector
///         parallel to the view direction; Invalid_input for a mesh without triangles or with a
///         non-finite coordinate
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
Rgb_picture colored_mesh_picture(const TriangleMesh& tm, const std::vector<double>& values, const Mesh_picture_options& options = Mesh_picture_options(),
                                 const NamedParameters& np = CGAL::parameters::default_values()) {
  const internal::Triangle_arrays a = internal::finite_triangle_arrays(tm, np, "colored_mesh_picture", "the mesh");
  const std::size_t n = a.number_of_vertices();
  if(values.size() != n)
    throw Invalid_argument("colored_mesh_picture: " + std::to_string(values.size()) + " values for " + std::to_string(n) + " vertices");
  if(options.view_size < 16 || options.view_size > 4096) throw Invalid_argument("colored_mesh_picture: view_size must be in [16, 4096]");
  double lo = options.min_value, hi = options.max_value;
  if(std::isnan(lo) || std::isnan(hi)) {
    double flo = std::numeric_limits<double>::infinity(), fhi = -flo;
    for(double v : values)
      if(std::isfinite(v)) flo = std::min(flo, v), fhi = std::max(fhi, v);
    if(!(flo <= fhi)) flo = 0, fhi = 1; // no finite value: everything grey
    if(std::isnan(lo)) lo = flo;
    if(std::isnan(hi)) hi = fhi;
  }
  if(!std::isfinite(lo) || !std::isfinite(hi)) throw Invalid_argument("colored_mesh_picture: min_value and max_value must be finite or NaN");
  const double span = hi > lo ? hi - lo : 1.0;

  const Eigen::Matrix3d frame = internal::picture_frame(a.V, options);
  const Eigen::MatrixXd P = a.V * frame; // (right, up, towards the viewer) of every vertex
  Eigen::MatrixXd N = Eigen::MatrixXd::Zero(static_cast<Eigen::Index>(n), 3); // area-weighted vertex normals, in the frame
  for(Eigen::Index f = 0; f < a.F.rows(); ++f) {
    const Eigen::Vector3d p0 = P.row(a.F(f, 0)).transpose(), p1 = P.row(a.F(f, 1)).transpose(), p2 = P.row(a.F(f, 2)).transpose();
    const Eigen::RowVector3d w = (p1 - p0).cross(p2 - p0).transpose();
    for(int k = 0; k < 3; ++k) N.row(a.F(f, k)) += w;
  }
  const Eigen::RowVector2d pmin = P.leftCols<2>().colwise().minCoeff(), pmax = P.leftCols<2>().colwise().maxCoeff();
  const Eigen::RowVector2d centre = (pmin + pmax) / 2;
  const double extent = std::max(1e-300, (pmax - pmin).maxCoeff());
  const int ss = 2; // supersampling
  const std::size_t S = options.view_size * ss;
  const double scale = 0.92 * static_cast<double>(S) / extent;
  const std::size_t views = options.both_sides ? 2 : 1;
  const std::size_t top = options.title.empty() ? 0 : 20, bar = 100;
  Rgb_picture picture(views * options.view_size + bar, options.view_size + top);

  std::vector<double> depth(S * S);
  std::vector<std::array<double, 3>> colour(S * S);
  for(std::size_t view = 0; view < views; ++view) {
    const double flip = view == 0 ? 1.0 : -1.0; // the back view: x and depth mirrored
    std::fill(depth.begin(), depth.end(), -std::numeric_limits<double>::infinity());
    std::fill(colour.begin(), colour.end(), std::array<double, 3>{{255, 255, 255}});
    auto screen = [&](int v) {
      return Eigen::Vector3d(static_cast<double>(S) / 2 + flip * (P(v, 0) - centre(0)) * scale, static_cast<double>(S) / 2 - (P(v, 1) - centre(1)) * scale,
                             flip * P(v, 2));
    };
    for(Eigen::Index f = 0; f < a.F.rows(); ++f) {
      const Eigen::Vector3d q[3] = {screen(a.F(f, 0)), screen(a.F(f, 1)), screen(a.F(f, 2))};
      const double area = (q[1].x() - q[0].x()) * (q[2].y() - q[0].y()) - (q[2].x() - q[0].x()) * (q[1].y() - q[0].y());
      if(area == 0) continue;
      const double x0 = std::max(0.0, std::floor(std::min({q[0].x(), q[1].x(), q[2].x()})));
      const double x1 = std::min(static_cast<double>(S) - 1, std::ceil(std::max({q[0].x(), q[1].x(), q[2].x()})));
      const double y0 = std::max(0.0, std::floor(std::min({q[0].y(), q[1].y(), q[2].y()})));
      const double y1 = std::min(static_cast<double>(S) - 1, std::ceil(std::max({q[0].y(), q[1].y(), q[2].y()})));
      for(double y = y0; y <= y1; ++y)
        for(double x = x0; x <= x1; ++x) {
          const double px = x + 0.5, py = y + 0.5;
          double l[3];
          for(int k = 0; k < 3; ++k) {
            const Eigen::Vector3d& b = q[(k + 1) % 3];
            const Eigen::Vector3d& c = q[(k + 2) % 3];
            l[k] = ((c.x() - b.x()) * (py - b.y()) - (px - b.x()) * (c.y() - b.y())) / area;
          }
          if(l[0] < 0 || l[1] < 0 || l[2] < 0) continue;
          const double z = l[0] * q[0].z() + l[1] * q[1].z() + l[2] * q[2].z();
          const std::size_t pixel = static_cast<std::size_t>(y) * S + static_cast<std::size_t>(x);
          if(z <= depth[pixel]) continue;
          depth[pixel] = z;
          double value = 0;
          Eigen::Vector3d normal = Eigen::Vector3d::Zero();
          for(int k = 0; k < 3; ++k) {
            const auto vi = static_cast<std::size_t>(a.F(f, k));
            value += l[k] * values[vi];
            normal += l[k] * N.row(static_cast<Eigen::Index>(vi)).transpose();
          }
          const double nn = normal.norm();
          const double light = 0.35 + 0.65 * (nn > 0 ? std::abs(normal.z()) / nn : 1.0);
          const auto c = colormap_viridis((value - lo) / span);
          for(int k = 0; k < 3; ++k) colour[pixel][static_cast<std::size_t>(k)] = light * c[static_cast<std::size_t>(k)];
        }
    }
    for(std::size_t y = 0; y < options.view_size; ++y)
      for(std::size_t x = 0; x < options.view_size; ++x) {
        std::array<double, 3> sum{{0, 0, 0}};
        for(int dy = 0; dy < ss; ++dy)
          for(int dx = 0; dx < ss; ++dx)
            for(std::size_t k = 0; k < 3; ++k) sum[k] += colour[(y * ss + static_cast<std::size_t>(dy)) * S + x * ss + static_cast<std::size_t>(dx)][k];
        std::array<std::uint8_t, 3> c;
        for(std::size_t k = 0; k < 3; ++k) c[k] = static_cast<std::uint8_t>(std::lround(sum[k] / (ss * ss)));
        picture.set(view * options.view_size + x, top + y, c);
      }
  }

  // the colour bar: hi at the top, lo at the bottom
  const std::size_t bx = views * options.view_size + 12, by0 = top + options.view_size / 8, by1 = top + options.view_size * 7 / 8;
  for(std::size_t y = by0; y <= by1; ++y) {
    const auto c = colormap_viridis(static_cast<double>(by1 - y) / static_cast<double>(by1 - by0));
    for(std::size_t x = bx; x < bx + 16; ++x) picture.set(x, y, {{c[0], c[1], c[2]}});
  }
  draw_text(picture, bx + 20, by0 - 3, internal::format_value(hi));
  draw_text(picture, bx + 20, (by0 + by1) / 2 - 3, internal::format_value((lo + hi) / 2));
  draw_text(picture, bx + 20, by1 - 3, internal::format_value(lo));
  if(!options.title.empty()) draw_text(picture, 6, 6, options.title);
  return picture;
}

/// \ingroup PkgShapeCorrIO
/// Writes `colored_mesh_picture(tm, values, options, np)` as a PNG file.
/// \throws as `colored_mesh_picture()`; Output_error when the file cannot be written
template <typename TriangleMesh, typename NamedParameters = parameters::Default_named_parameters>
void write_colored_mesh_png(const std::string& path, const TriangleMesh& tm, const std::vector<double>& values,
                            const Mesh_picture_options& options = Mesh_picture_options(),
                            const NamedParameters& np = CGAL::parameters::default_values()) {
  write_png(path, colored_mesh_picture(tm, values, options, np));
}

} // namespace shapecorr

#endif
