// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: the spin image (vertex splatting), the face-based spin image (area sampling) and the
// Spin Contour (fast construction from triangle-plane intersections) of one oriented point.
#ifndef SHAPECORR_DESCRIPTORS_INTERNAL_SPIN_CONSTRUCTION_H
#define SHAPECORR_DESCRIPTORS_INTERNAL_SPIN_CONSTRUCTION_H

#include <shapecorr/descriptors/Spin_contour.h>
#include <shapecorr/descriptors/Spin_image.h>
#include <shapecorr/descriptors/internal/contour_construction.h>
#include <shapecorr/descriptors/internal/spin_geometry.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

namespace shapecorr {
namespace internal {

struct Spin_options {
  double support = 0;              // L
  std::size_t rows = 120, cols = 60;
  double cos_support_angle = -1.0; // cos of the support angle (-1: no limit)
  double samples_per_bin = 2.0;    // face-based image: samples per bin width along a triangle edge
};

// Candidate elements (faces or vertices) whose spin coordinates may fall in the support: a ball of
// radius sqrt(2) L (+ slack) around P when it is smaller than the mesh, else all.
template <typename Fn>
void for_each_candidate(const Kd_tree<3>& tree, std::size_t count, const Eigen::Vector3d& p, double radius, double diagonal, Fn&& fn) {
  if(radius >= diagonal) {
    for(std::size_t i = 0; i < count; ++i) fn(i);
    return;
  }
  tree.for_each_within({p.x(), p.y(), p.z()}, radius, [&](std::size_t i, double) { fn(i); });
}

// Adds weight w at the continuous bin position (u, v) = (column, row), bin centres at integers,
// with bilinear interpolation between the four nearest bin centres (those inside the image).
inline void splat_bilinear(Spin_image& img, double u, double v, double w) {
  const double fu = std::floor(u), fv = std::floor(v);
  const double du = u - fu, dv = v - fv;
  const long c0 = static_cast<long>(fu), r0 = static_cast<long>(fv);
  const long C = static_cast<long>(img.columns()), R = static_cast<long>(img.rows());
  const double ws[4] = {(1 - du) * (1 - dv), du * (1 - dv), (1 - du) * dv, du * dv};
  const long rs[4] = {r0, r0, r0 + 1, r0 + 1}, cs[4] = {c0, c0 + 1, c0, c0 + 1};
  for(int k = 0; k < 4; ++k)
    if(rs[k] >= 0 && rs[k] < R && cs[k] >= 0 && cs[k] < C && ws[k] > 0)
      img.at(static_cast<std::size_t>(rs[k]), static_cast<std::size_t>(cs[k])) += static_cast<float>(w * ws[k]);
}

// Adds weight w at spin coordinates (alpha, beta).
inline void splat(Spin_image& img, double alpha, double beta, double w, const Spin_options& o) {
  const double L = o.support;
  splat_bilinear(img, alpha / L * static_cast<double>(o.cols) - 0.5, (L - beta) / (2.0 * L) * static_cast<double>(o.rows) - 0.5, w);
}

inline bool spin_coordinates(const Oriented_point& op, const Eigen::Vector3d& q, double L, double& alpha, double& beta) {
  const Eigen::Vector3d d = q - op.point;
  beta = op.axis.dot(d);
  alpha = std::sqrt(std::max(0.0, d.squaredNorm() - beta * beta));
  return alpha <= L && std::abs(beta) <= L;
}

/// Johnson & Hebert's spin image: every vertex in the support splatted with weight 1.
inline Spin_image vertex_spin_image(const Spin_geometry& g, const Oriented_point& op, const Spin_options& o) {
  Spin_image img(o.rows, o.cols, o.support);
  const std::size_t n = g.a.number_of_vertices();
  for_each_candidate(g.vertex_tree, n, op.point, std::sqrt(2.0) * o.support * (1 + 1e-9), g.bbox_diagonal, [&](std::size_t v) {
    double alpha, beta;
    if(!spin_coordinates(op, g.a.point(v), o.support, alpha, beta)) return;
    if(o.cos_support_angle > -1 && g.vertex_normal.row(static_cast<Eigen::Index>(v)).dot(op.axis) < o.cos_support_angle) return;
    splat(img, alpha, beta, 1.0, o);
  });
  return img;
}

/// The face-based spin image (Carmichael et al. 1999), approximate method: each triangle is cut
/// into k x k similar sub-triangles, k such that their edges are at most 1 / samples_per_bin of a
/// bin, and each sub-triangle's area is splatted at its centroid.
inline Spin_image face_spin_image(const Spin_geometry& g, const Oriented_point& op, const Spin_options& o) {
  Spin_image img(o.rows, o.cols, o.support);
  const double bin = std::min(o.support / static_cast<double>(o.cols), 2.0 * o.support / static_cast<double>(o.rows));
  const double step = bin / o.samples_per_bin;
  const std::size_t m = g.a.number_of_faces();
  for_each_candidate(g.face_tree, m, op.point, std::sqrt(2.0) * o.support + g.max_face_radius, g.bbox_diagonal, [&](std::size_t f) {
    const Eigen::Index fi = static_cast<Eigen::Index>(f);
    const double A = g.face_area[fi];
    if(!(A > 0)) return;
    if(o.cos_support_angle > -1 && g.face_normal.row(fi).dot(op.axis) < o.cos_support_angle) return;
    const Eigen::Vector3d p0 = g.a.V.row(g.a.F(fi, 0)), p1 = g.a.V.row(g.a.F(fi, 1)), p2 = g.a.V.row(g.a.F(fi, 2));
    const double longest = std::max({(p1 - p0).norm(), (p2 - p1).norm(), (p0 - p2).norm()});
    const int k = std::max(1, static_cast<int>(std::ceil(longest / step)));
    const double w = A / (static_cast<double>(k) * k);
    const Eigen::Vector3d e1 = (p1 - p0) / k, e2 = (p2 - p0) / k;
    for(int i = 0; i < k; ++i)
      for(int j = 0; i + j < k; ++j) {
        for(int down = 0; down < (i + j + 1 < k ? 2 : 1); ++down) {
          const double s = down ? (3.0 * i + 2) / 3.0 : (3.0 * i + 1) / 3.0;
          const double t = down ? (3.0 * j + 2) / 3.0 : (3.0 * j + 1) / 3.0;
          double alpha, beta;
          if(spin_coordinates(op, p0 + s * e1 + t * e2, o.support, alpha, beta)) splat(img, alpha, beta, w, o);
        }
      }
  });
  return img;
}

// Signed area of the triangle (0, p, q) inside the disc of radius r centred at the origin (the
// pieces of the segment outside the disc contribute circular sectors).
inline double origin_triangle_in_disc(const Eigen::Vector2d& p, const Eigen::Vector2d& q, double r) {
  auto cross = [](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return u.x() * v.y() - u.y() * v.x(); };
  auto sector = [&](const Eigen::Vector2d& u, const Eigen::Vector2d& v) { return 0.5 * r * r * std::atan2(cross(u, v), u.dot(v)); };
  const Eigen::Vector2d d = q - p;
  const double A = d.squaredNorm();
  if(!(A > 0)) return 0.0;
  const double B = p.dot(d), C = p.squaredNorm() - r * r;
  const double disc = B * B - A * C;
  if(disc <= 0) return sector(p, q); // the line misses the disc
  const double sq = std::sqrt(disc);
  const double t1 = (-B - sq) / A, t2 = (-B + sq) / A;
  if(t2 <= 0 || t1 >= 1) return sector(p, q); // the segment lies outside
  const Eigen::Vector2d a = t1 > 0 ? Eigen::Vector2d(p + t1 * d) : p, b = t2 < 1 ? Eigen::Vector2d(p + t2 * d) : q;
  return (t1 > 0 ? sector(p, a) : 0.0) + 0.5 * cross(a, b) + (t2 < 1 ? sector(b, q) : 0.0);
}

inline double signed_polygon_area_2(const Eigen::Vector2d* v, int n) {
  double a = 0;
  for(int k = 0; k < n; ++k) {
    const Eigen::Vector2d& p = v[k];
    const Eigen::Vector2d& q = v[(k + 1) % n];
    a += p.x() * q.y() - p.y() * q.x();
  }
  return 0.5 * a;
}

// Clips the convex polygon (v, n), n <= 7, to the half-plane f(x) >= 0 (f affine); returns the
// new number of vertices (at most n + 1; out must not alias v).
template <typename F>
int clip_polygon(const Eigen::Vector2d* v, int n, F&& f, Eigen::Vector2d* out) {
  double fv[7];
  for(int k = 0; k < n; ++k) fv[k] = f(v[k]);
  int m = 0;
  for(int k = 0; k < n; ++k) {
    const int k2 = (k + 1) % n;
    if(fv[k] >= 0) out[m++] = v[k];
    if((fv[k] >= 0) != (fv[k2] >= 0)) out[m++] = v[k] + fv[k] / (fv[k] - fv[k2]) * (v[k2] - v[k]);
  }
  return m;
}

/// The face-based spin image, exact method (Carmichael et al. 1999): bin (row i, column j) holds
/// the area of the surface inside the volume between the planes beta = beta_i, beta_{i+1} and the
/// cylinders alpha = alpha_j, alpha_{j+1} (box bins, no interpolation). In a triangle's plane, with
/// e1 along the axis's projection, e2 = N x e1, s, t the coordinates and h the plane's offset from P,
/// alpha^2 = (nu s - sigma mu h)^2 + t^2 (nu = |n.N|, mu = sqrt(1 - nu^2), sigma = sign(n.N)):
/// {alpha <= a} is an ellipse that the map (s, t) -> (nu s - sigma mu h, t) turns into the disc of
/// radius a (areas times nu). Each triangle is clipped to the rows' slabs (beta is linear in it)
/// and the area of each piece inside the discs of the column boundaries is summed edge by edge
/// (triangle with the origin, inside a disc). Faces within 1e-6 of parallel to the axis (nu <
/// 1e-6) use the limit nu = 0: the strip |t| <= sqrt(a^2 - h^2).
inline Spin_image exact_face_spin_image(const Spin_geometry& g, const Oriented_point& op, const Spin_options& o) {
  Spin_image img(o.rows, o.cols, o.support);
  const double L = o.support;
  const double row_h = 2.0 * L / static_cast<double>(o.rows), col_w = L / static_cast<double>(o.cols);
  const long R = static_cast<long>(o.rows), C = static_cast<long>(o.cols);
  const std::size_t m = g.a.number_of_faces();
  std::vector<double> cum(static_cast<std::size_t>(C) + 1);
  for_each_candidate(g.face_tree, m, op.point, std::sqrt(2.0) * L + g.max_face_radius, g.bbox_diagonal, [&](std::size_t f) {
    const Eigen::Index fi = static_cast<Eigen::Index>(f);
    if(!(g.face_area[fi] > 0)) return;
    const Eigen::Vector3d N = g.face_normal.row(fi);
    if(o.cos_support_angle > -1 && N.dot(op.axis) < o.cos_support_angle) return;
    const Eigen::Vector3d p[3] = {g.a.V.row(g.a.F(fi, 0)), g.a.V.row(g.a.F(fi, 1)), g.a.V.row(g.a.F(fi, 2))};
    double beta[3];
    for(int k = 0; k < 3; ++k) beta[k] = op.axis.dot(p[k] - op.point);
    const double bmin = std::min({beta[0], beta[1], beta[2]}), bmax = std::max({beta[0], beta[1], beta[2]});
    if(bmin >= L || bmax <= -L) return;
    // the in-plane frame
    const double nN = op.axis.dot(N);
    const double nu = std::min(1.0, std::abs(nN)), mu = std::sqrt(std::max(0.0, 1.0 - nu * nu));
    Eigen::Vector3d e1 = op.axis - nN * N;
    if(e1.norm() > 1e-300) e1.normalize();
    else e1 = N.unitOrthogonal();
    const Eigen::Vector3d e2 = N.cross(e1);
    const double h = N.dot(p[0] - op.point), x0 = -(nN < 0 ? -1.0 : 1.0) * mu * h;
    const bool strip = nu < 1e-6;
    // beta on the plane: (n . e1) s + (n . N) h (n has no e2 component)
    const double ne1 = op.axis.dot(e1), beta0 = nN * h;
    auto beta_at = [&](const Eigen::Vector2d& q) { return ne1 * q.x() + beta0; };
    Eigen::Vector2d tri[3];
    for(int k = 0; k < 3; ++k) {
      const Eigen::Vector3d w = p[k] - op.point;
      tri[k] = {e1.dot(w), e2.dot(w)};
    }
    // rows (slabs) the triangle spans: row i covers beta in [L - (i + 1) row_h, L - i row_h]
    const long i0 = std::max(0L, static_cast<long>(std::floor((L - bmax) / row_h)));
    const long i1 = std::min(R - 1, static_cast<long>(std::floor((L - bmin) / row_h)));
    for(long i = i0; i <= i1; ++i) {
      const double top = L - static_cast<double>(i) * row_h, bottom = top - row_h;
      Eigen::Vector2d q1[4], q2[5];
      const int n1 = clip_polygon(tri, 3, [&](const Eigen::Vector2d& q) { return top - beta_at(q); }, q1);
      if(n1 < 3) continue;
      const int n2 = clip_polygon(q1, n1, [&](const Eigen::Vector2d& q) { return beta_at(q) - bottom; }, q2);
      if(n2 < 3) continue;
      // the piece in disc coordinates (X, Y) = (nu s + x0, t); its area in the plane
      Eigen::Vector2d d[5];
      double r2max = 0, r2min = std::numeric_limits<double>::infinity();
      for(int k = 0; k < n2; ++k) {
        d[k] = {(strip ? 0.0 : nu * q2[k].x()) + x0, q2[k].y()};
        r2max = std::max(r2max, d[k].squaredNorm());
      }
      const double signed_area = signed_polygon_area_2(q2, n2), area = std::abs(signed_area);
      if(!(area > 0)) continue;
      const double sign = signed_area > 0 ? 1.0 : -1.0;
      // the smallest alpha on the piece: in the strip limit from its t range; else 0 when the
      // piece contains the disc's centre, the distance to its nearest edge otherwise
      if(strip) {
        double tlo = std::numeric_limits<double>::infinity(), thi = -tlo;
        for(int k = 0; k < n2; ++k) {
          tlo = std::min(tlo, q2[k].y());
          thi = std::max(thi, q2[k].y());
        }
        r2min = x0 * x0 + (tlo > 0 ? tlo * tlo : (thi < 0 ? thi * thi : 0.0));
      } else {
        bool inside = true;
        for(int k = 0; k < n2; ++k) {
          const Eigen::Vector2d& a = d[k];
          const Eigen::Vector2d e = d[(k + 1) % n2] - a;
          if(sign * (a.x() * e.y() - a.y() * e.x()) < 0) inside = false;
          const double len2 = e.squaredNorm();
          const double t = len2 > 0 ? std::min(1.0, std::max(0.0, -a.dot(e) / len2)) : 0.0;
          r2min = std::min(r2min, (a + t * e).squaredNorm());
        }
        if(inside) r2min = 0;
      }
      const long j0 = std::max(0L, static_cast<long>(std::floor(std::sqrt(r2min) / col_w)));
      if(j0 >= C) continue;
      const long j1 = std::min(C, static_cast<long>(std::ceil(std::sqrt(r2max) / col_w)));
      // cum[j]: the piece's area within alpha <= j col_w, for j0 <= j <= j1
      cum[static_cast<std::size_t>(j0)] = 0;
      for(long j = j0 + 1; j <= j1; ++j) {
        const double a = static_cast<double>(j) * col_w;
        double in;
        if(a * a >= r2max) in = area;
        else if(strip) {
          // the strip |t| <= w clips the piece: two half-planes
          const double w2 = a * a - x0 * x0;
          if(w2 <= 0) in = 0;
          else {
            const double w = std::sqrt(w2);
            Eigen::Vector2d c1[6], c2[7];
            const int m1 = clip_polygon(q2, n2, [w](const Eigen::Vector2d& q) { return w - q.y(); }, c1);
            const int m2 = m1 >= 3 ? clip_polygon(c1, m1, [w](const Eigen::Vector2d& q) { return q.y() + w; }, c2) : 0;
            in = m2 >= 3 ? std::abs(signed_polygon_area_2(c2, m2)) : 0.0;
          }
        } else {
          double s = 0;
          for(int k = 0; k < n2; ++k) s += origin_triangle_in_disc(d[k], d[(k + 1) % n2], a);
          in = std::min(area, std::max(0.0, sign * s / nu));
        }
        cum[static_cast<std::size_t>(j)] = in;
      }
      for(long j = j0; j < std::min(j1, C); ++j) {
        const double v = cum[static_cast<std::size_t>(j + 1)] - cum[static_cast<std::size_t>(j)];
        if(v > 0) img.at(static_cast<std::size_t>(i), static_cast<std::size_t>(j)) += static_cast<float>(v);
      }
    }
  });
  return img;
}


// The section policy of the Spin Contour (see build_level_set_contour): a vertex is its 2-D
// offset from the axis and its row coordinate; on a plane beta = const both are linear along an
// edge, so a triangle's section is a 2-D segment whose alpha range is [distance from the origin
// to the segment, largest end-point norm], kept squared until the union.
struct Rigid_section {
  struct alignas(32) Vertex {
    double x, y, t;
  };
  struct Point {
    double x, y;
  };
  static constexpr bool linear = false; // the distance to the axis is not linear along a segment
  // the point where t crosses the level on the edge a b (offsets sa, sb of opposite signs)
  static Point cross(const Vertex& a, const Vertex& b, double sa, double sb) {
    const double c = sa / (sa - sb);
    return {a.x + c * (b.x - a.x), a.y + c * (b.y - a.y)};
  }
  static Point at(const Vertex& a) { return {a.x, a.y}; }
  static double norm2(const Point& a) { return a.x * a.x + a.y * a.y; }
  // Squared distance from the origin to the segment [a, b] whose end points have squared norms
  // a2, b2 (one division at most).
  static double origin_to_segment2(const Point& a, const Point& b, double a2, double b2) {
    const double dx = b.x - a.x, dy = b.y - a.y;
    if(a.x * dx + a.y * dy >= 0) return a2;
    if(b.x * dx + b.y * dy <= 0) return b2;
    const double c = a.x * dy - a.y * dx;
    return c * c / (dx * dx + dy * dy);
  }
  static double origin_to_segment2(const Point& a, const Point& b) { return origin_to_segment2(a, b, norm2(a), norm2(b)); }
  double L2 = 0, merge_eps = 0;
  void segment(const Point& a, const Point& b, double& l, double& u) const {
    const double a2 = norm2(a), b2 = norm2(b);
    l = origin_to_segment2(a, b, a2, b2);
    u = std::max(a2, b2);
  }
  void polygon(const Point* p, int np, bool in_plane, double& l, double& u) const {
    u = 0;
    for(int i = 0; i < np; ++i) u = std::max(u, norm2(p[i]));
    if(in_plane) { // the triangle lies in the plane: 0 when it contains the axis
      const auto cross = [](const Point& x, const Point& z) { return x.x * z.y - x.y * z.x; };
      const double c0 = cross(p[1], p[2]), c1 = cross(p[2], p[0]), c2 = cross(p[0], p[1]);
      const bool inside = (c0 >= 0 && c1 >= 0 && c2 >= 0) || (c0 <= 0 && c1 <= 0 && c2 <= 0);
      l = inside ? 0.0 : std::min({origin_to_segment2(p[0], p[1]), origin_to_segment2(p[1], p[2]), origin_to_segment2(p[2], p[0])});
      return;
    }
    int ia = 0, ib = 0; // the section is the segment between the two points farthest apart
    double far = -1;
    for(int i = 0; i < np; ++i)
      for(int j = i + 1; j < np; ++j) {
        const double d = norm2({p[i].x - p[j].x, p[i].y - p[j].y});
        if(d > far) { far = d; ia = i; ib = j; }
      }
    l = origin_to_segment2(p[ia], p[ib]);
  }
  bool keep(double& l, double& u) const {
    if(l > L2) return false; // the piece lies outside the support
    u = std::min(u, L2);
    return true;
  }
  double finish(double x) const { return std::sqrt(x); }
};

typedef Contour_workspace<Rigid_section::Vertex> Spin_contour_workspace;

/// The Spin Contour by the thesis's fast construction: the alpha ranges of the intersections of
/// every triangle with the planes beta = beta_r, their union per row, the interval end points, and
/// the closing samples (alpha on the column grid) of I_r \ I_{r-1} and I_r \ I_{r+1}.
/// Every vertex is first written in the frame of the oriented point: its row coordinate and its
/// 2-D offset from the axis (`Rigid_section`).
inline Spin_contour spin_contour(const Spin_geometry& g, const Oriented_point& op, const Spin_options& o, Spin_contour_workspace& ws) {
  const double L = o.support;
  const std::size_t R = o.rows;
  const double h = 2.0 * L / static_cast<double>(R);
  const Eigen::Vector3d n = op.axis;
  Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  const std::size_t nv = g.a.number_of_vertices(), m = g.a.number_of_faces();
  ws.resize(nv);
  const double* V = g.a.V.data();
  const double inv = 1.0 / h;
  for(std::size_t i = 0; i < nv; ++i) {
    const Eigen::Vector3d w(V[3 * i] - op.point.x(), V[3 * i + 1] - op.point.y(), V[3 * i + 2] - op.point.z());
    const double t = (L - n.dot(w)) * inv - 0.5;
    ws.vx[i] = {e1.dot(w), e2.dot(w), t};
    ws.set_rows(i, t, R);
  }
  Rigid_section sec;
  sec.L2 = L * L;
  sec.merge_eps = 1e-9 * sec.L2; // touching intervals (shared edge points, rounded differently) merge
  Spin_contour c(R, L);
  build_level_set_contour(g.face_links, g.half_edges, g.a.F.data(), sec, R, o.cols, L, [&](auto&& visit) {
    // for_each_candidate's test, written out: through that helper the classification lambda is
    // not inlined and the contour takes about 5% longer (measured, bench_descriptors)
    if(std::sqrt(2.0) * L + g.max_face_radius >= g.bbox_diagonal)
      for(std::size_t f = 0; f < m; ++f) visit(f);
    else
      g.face_tree.for_each_within({op.point.x(), op.point.y(), op.point.z()}, std::sqrt(2.0) * L + g.max_face_radius,
                                  [&](std::size_t f, double) { visit(f); });
  }, ws, c);
  return c;
}

} // namespace internal
} // namespace shapecorr

#endif
