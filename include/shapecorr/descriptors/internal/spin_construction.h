// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: the spin image (vertex splatting), the face-based spin image (area sampling) and the
// Spin Contour (fast construction from triangle-plane intersections) of one oriented point.
#ifndef SHAPECORR_DESCRIPTORS_INTERNAL_SPIN_CONSTRUCTION_H
#define SHAPECORR_DESCRIPTORS_INTERNAL_SPIN_CONSTRUCTION_H

#include <shapecorr/descriptors/Spin_contour.h>
#include <shapecorr/descriptors/Spin_image.h>
#include <shapecorr/descriptors/internal/spin_geometry.h>

#include <Eigen/Dense>

#include <algorithm>
#include <cmath>
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

// Adds weight w at spin coordinates (alpha, beta) with bilinear interpolation between bin centres.
inline void splat(Spin_image& img, double alpha, double beta, double w, const Spin_options& o) {
  const double L = o.support;
  const double u = alpha / L * static_cast<double>(o.cols) - 0.5;
  const double v = (L - beta) / (2.0 * L) * static_cast<double>(o.rows) - 0.5;
  const double fu = std::floor(u), fv = std::floor(v);
  const double du = u - fu, dv = v - fv;
  const long c0 = static_cast<long>(fu), r0 = static_cast<long>(fv);
  const long C = static_cast<long>(o.cols), R = static_cast<long>(o.rows);
  const double ws[4] = {(1 - du) * (1 - dv), du * (1 - dv), (1 - du) * dv, du * dv};
  const long rs[4] = {r0, r0, r0 + 1, r0 + 1}, cs[4] = {c0, c0 + 1, c0, c0 + 1};
  for(int k = 0; k < 4; ++k)
    if(rs[k] >= 0 && rs[k] < R && cs[k] >= 0 && cs[k] < C && ws[k] > 0)
      img.at(static_cast<std::size_t>(rs[k]), static_cast<std::size_t>(cs[k])) += static_cast<float>(w * ws[k]);
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

// Distance from the origin to the segment [a, b].
inline double origin_to_segment(const Eigen::Vector3d& a, const Eigen::Vector3d& b) {
  const Eigen::Vector3d d = b - a;
  const double l2 = d.squaredNorm();
  const double t = l2 > 0 ? std::clamp(-a.dot(d) / l2, 0.0, 1.0) : 0.0;
  return (a + t * d).norm();
}

struct Contour_workspace {
  std::vector<std::vector<std::pair<double, double>>> intervals; // per row
  std::vector<std::vector<std::pair<double, double>>> merged;
  std::vector<float> row;
};

/// The Spin Contour by the thesis's fast construction: the alpha ranges of the intersections of
/// every triangle with the planes beta = beta_r, their union per row, the interval end points, and
/// the closing samples (alpha on the column grid) of I_r \ I_{r-1} and I_r \ I_{r+1}.
inline Spin_contour spin_contour(const Spin_geometry& g, const Oriented_point& op, const Spin_options& o, Contour_workspace& ws) {
  const double L = o.support;
  const std::size_t R = o.rows;
  const double h = 2.0 * L / static_cast<double>(R);
  ws.intervals.resize(R);
  ws.merged.resize(R);
  for(auto& v : ws.intervals) v.clear();
  const Eigen::Vector3d n = op.axis;
  const std::size_t m = g.a.number_of_faces();
  for_each_candidate(g.face_tree, m, op.point, std::sqrt(2.0) * L + g.max_face_radius, g.bbox_diagonal, [&](std::size_t f) {
    const Eigen::Index fi = static_cast<Eigen::Index>(f);
    Eigen::Vector3d w[3];
    double b[3];
    for(int k = 0; k < 3; ++k) {
      w[k] = g.a.V.row(g.a.F(fi, k)).transpose() - op.point;
      b[k] = n.dot(w[k]);
    }
    const double lo = std::min({b[0], b[1], b[2]}), hi = std::max({b[0], b[1], b[2]});
    const double first = std::ceil((L - hi) / h - 0.5), last = std::floor((L - lo) / h - 0.5);
    const long r0 = std::max(0L, static_cast<long>(first)), r1 = std::min(static_cast<long>(R) - 1, static_cast<long>(last));
    for(long r = r0; r <= r1; ++r) {
      const double t = L - (static_cast<double>(r) + 0.5) * h;
      // Intersection points with the plane beta = t, as radial vectors (their beta component removed).
      Eigen::Vector3d pts[6];
      int np = 0;
      for(int k = 0; k < 3; ++k) {
        const int k2 = (k + 1) % 3;
        const double s0 = b[k] - t, s1 = b[k2] - t;
        if(s0 == 0) pts[np++] = w[k];
        if((s0 < 0 && s1 > 0) || (s0 > 0 && s1 < 0)) pts[np++] = w[k] + (s0 / (s0 - s1)) * (w[k2] - w[k]);
      }
      if(np == 0) continue;
      double u = 0, l;
      for(int i = 0; i < np; ++i) {
        pts[i] -= n.dot(pts[i]) * n;
        u = std::max(u, pts[i].norm());
      }
      if(np == 3 && b[0] == t && b[1] == t && b[2] == t) { // the triangle lies in the plane
        const Eigen::Vector3d c0 = pts[1].cross(pts[2]), c1 = pts[2].cross(pts[0]), c2 = pts[0].cross(pts[1]);
        const double s0 = n.dot(c0), s1 = n.dot(c1), s2 = n.dot(c2);
        const bool inside = (s0 >= 0 && s1 >= 0 && s2 >= 0) || (s0 <= 0 && s1 <= 0 && s2 <= 0);
        l = inside ? 0.0 : std::min({origin_to_segment(pts[0], pts[1]), origin_to_segment(pts[1], pts[2]), origin_to_segment(pts[2], pts[0])});
      } else {
        int ia = 0, ib = 0;
        double far = -1;
        for(int i = 0; i < np; ++i)
          for(int j = i + 1; j < np; ++j) {
            const double d = (pts[i] - pts[j]).squaredNorm();
            if(d > far) { far = d; ia = i; ib = j; }
          }
        l = origin_to_segment(pts[ia], pts[ib]);
      }
      if(l > L) continue;
      ws.intervals[static_cast<std::size_t>(r)].emplace_back(l, std::min(u, L));
    }
  });
  // Union per row.
  const double eps = 1e-9 * L;
  for(std::size_t r = 0; r < R; ++r) {
    auto& in = ws.intervals[r];
    auto& out = ws.merged[r];
    out.clear();
    std::sort(in.begin(), in.end());
    for(const auto& iv : in) {
      if(!out.empty() && iv.first <= out.back().second + eps) out.back().second = std::max(out.back().second, iv.second);
      else out.push_back(iv);
    }
  }
  auto contains = [&](std::size_t r, long s, double a) {
    if(s < 0 || s >= static_cast<long>(R)) return false;
    const auto& iv = ws.merged[static_cast<std::size_t>(s)];
    auto it = std::upper_bound(iv.begin(), iv.end(), std::make_pair(a, std::numeric_limits<double>::infinity()));
    (void)r;
    return it != iv.begin() && a <= std::prev(it)->second;
  };
  Spin_contour c(R, L);
  const double dc = L / static_cast<double>(o.cols);
  for(std::size_t r = 0; r < R; ++r) {
    ws.row.clear();
    const auto& iv = ws.merged[r];
    for(const auto& seg : iv) {
      ws.row.push_back(static_cast<float>(seg.first / L));
      if(seg.second > seg.first) ws.row.push_back(static_cast<float>(seg.second / L));
      const long c0 = std::max(0L, static_cast<long>(std::ceil(seg.first / dc - 0.5)));
      const long c1 = std::min(static_cast<long>(o.cols) - 1, static_cast<long>(std::floor(seg.second / dc - 0.5)));
      for(long k = c0; k <= c1; ++k) {
        const double a = (static_cast<double>(k) + 0.5) * dc;
        if(!contains(r, static_cast<long>(r) - 1, a) || !contains(r, static_cast<long>(r) + 1, a)) ws.row.push_back(static_cast<float>(a / L));
      }
    }
    std::sort(ws.row.begin(), ws.row.end());
    ws.row.erase(std::unique(ws.row.begin(), ws.row.end()), ws.row.end());
    c.append_row(r, ws.row.begin(), ws.row.end());
  }
  return c;
}

} // namespace internal
} // namespace shapecorr

#endif
