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


// Counting sort of (row, value) pairs by row: out holds the values grouped by row, row r in
// [count[r], count[r + 1]).
template <typename Value>
void group_by_row(const std::pair<std::uint32_t, Value>* in, std::size_t n, std::size_t rows, std::vector<std::uint32_t>& count,
                  std::vector<std::uint32_t>& next, std::vector<Value>& out) {
  count.assign(rows + 1, 0u);
  for(std::size_t i = 0; i < n; ++i) ++count[in[i].first + 1];
  for(std::size_t r = 0; r < rows; ++r) count[r + 1] += count[r];
  out.resize(n);
  next.assign(count.begin(), count.end() - 1);
  for(std::size_t i = 0; i < n; ++i) out[next[in[i].first]++] = in[i].second;
}

// A hint to start loading the cache line at p (no effect where the compiler has no builtin).
inline void prefetch(const void* p) {
#if defined(__GNUC__) || defined(__clang__)
  __builtin_prefetch(p);
#else
  (void)p;
#endif
}

struct Contour_workspace {
  // per vertex: its component orthogonal to the axis in a 2-D basis (x, y) and its row coordinate
  // t = (L - beta) / h - 1/2 (row r lies at t = r), in one record (the walk reads them together)
  struct alignas(32) Vertex { double x, y, t; };
  std::vector<Vertex> vx;
  std::vector<std::array<int, 2>> rows;                    // per vertex: floor(y), ceil(y) (clamped to [-1, R])
  std::vector<std::pair<std::uint32_t, std::pair<double, double>>> entries; // (row, alpha interval)
  std::vector<std::pair<std::uint32_t, std::uint32_t>> face_rows; // (row, face) of every face a row plane crosses
  std::vector<std::uint32_t> bucket;                       // faces grouped by row
  std::vector<std::uint32_t> stamp;                        // per face: the row walk that visited it last
  std::uint32_t epoch = 0;
  std::vector<std::uint32_t> stack;
  std::vector<std::uint32_t> count, next;
  std::vector<std::pair<double, double>> sorted;           // intervals grouped by row
  std::vector<std::vector<std::pair<double, double>>> merged;
  std::vector<float> row;
};

// Squared distance from the origin to the 2-D segment [a, b] (one division at most).
inline double origin_to_segment2(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d d = b - a;
  const double ad = a.dot(d);
  if(ad >= 0) return a.squaredNorm();
  if(b.dot(d) <= 0) return b.squaredNorm();
  const double c = a.x() * d.y() - a.y() * d.x();
  return c * c / d.squaredNorm();
}

/// The Spin Contour by the thesis's fast construction: the alpha ranges of the intersections of
/// every triangle with the planes beta = beta_r, their union per row, the interval end points, and
/// the closing samples (alpha on the column grid) of I_r \ I_{r-1} and I_r \ I_{r+1}.
/// Every vertex is first written in the frame of the oriented point: its row coordinate and its
/// 2-D offset from the axis. On a plane beta = const both are linear along an edge, so a
/// triangle's section is the 2-D segment between two interpolated offsets: its alpha range is
/// [distance from the origin to the segment, largest end-point norm].
inline Spin_contour spin_contour(const Spin_geometry& g, const Oriented_point& op, const Spin_options& o, Contour_workspace& ws) {
  const double L = o.support;
  const std::size_t R = o.rows;
  const double h = 2.0 * L / static_cast<double>(R);
  ws.merged.resize(R);
  ws.entries.clear();
  const Eigen::Vector3d n = op.axis;
  Eigen::Vector3d e1 = n.unitOrthogonal(), e2 = n.cross(e1);
  const std::size_t nv = g.a.number_of_vertices(), m = g.a.number_of_faces();
  ws.vx.resize(nv);
  ws.rows.resize(nv);
  {
    const double ymax = static_cast<double>(R);
    const double* V = g.a.V.data();
    const double inv = 1.0 / h;
    for(std::size_t i = 0; i < nv; ++i) {
      const Eigen::Vector3d w(V[3 * i] - op.point.x(), V[3 * i + 1] - op.point.y(), V[3 * i + 2] - op.point.z());
      const double y = (L - n.dot(w)) * inv - 0.5;
      ws.vx[i] = {e1.dot(w), e2.dot(w), y};
      // floor and ceil by integer conversion (std::floor is a library call without SSE4.1)
      const double c = std::min(ymax, std::max(-1.0, y));
      const int t = static_cast<int>(c);
      const int fl = t - (static_cast<double>(t) > c ? 1 : 0);
      ws.rows[i] = {{fl, fl + (static_cast<double>(fl) < c ? 1 : 0)}};
    }
  }
  const int* F = g.a.F.data();
  const double L2 = L * L;
  const double eps = 1e-9 * L2; // touching intervals (shared edge points, rounded differently) merge

  // The section of face f with the plane of row r as squared alphas [l, u]; 0 when empty, else
  // the bit mask of the edges (corner k to k+1) through which the section leaves the face.
  auto section = [&](std::size_t f, long r, double& l, double& u) -> int {
    const std::size_t id[3] = {static_cast<std::size_t>(F[3 * f]), static_cast<std::size_t>(F[3 * f + 1]), static_cast<std::size_t>(F[3 * f + 2])};
    const Eigen::Vector2d w[3] = {{ws.vx[id[0]].x, ws.vx[id[0]].y}, {ws.vx[id[1]].x, ws.vx[id[1]].y}, {ws.vx[id[2]].x, ws.vx[id[2]].y}};
    const double t = static_cast<double>(r);
    const double s[3] = {ws.vx[id[0]].t - t, ws.vx[id[1]].t - t, ws.vx[id[2]].t - t};
    if(s[0] != 0 && s[1] != 0 && s[2] != 0) {
      // The common case: one vertex alone on its side; the section joins its two edges.
      const bool p0 = s[0] > 0, p1 = s[1] > 0, p2 = s[2] > 0;
      if(p0 == p1 && p1 == p2) return 0;
      const int k = (p0 == p1) ? 2 : (p0 == p2 ? 1 : 0);
      const int a = (k + 1) % 3, b = (k + 2) % 3;
      const double ta = s[k] / (s[k] - s[a]), tb = s[k] / (s[k] - s[b]);
      const double ax = w[k].x() + ta * (w[a].x() - w[k].x()), ay = w[k].y() + ta * (w[a].y() - w[k].y());
      const double bx = w[k].x() + tb * (w[b].x() - w[k].x()), by = w[k].y() + tb * (w[b].y() - w[k].y());
      const double a2 = ax * ax + ay * ay, b2 = bx * bx + by * by;
      const double dx = bx - ax, dy = by - ay;
      // squared distance from the axis (the origin) to the segment [A, B]
      const double ad = ax * dx + ay * dy, bd = bx * dx + by * dy;
      if(ad >= 0) l = a2;
      else if(bd <= 0) l = b2;
      else {
        const double c = ax * dy - ay * dx;
        l = c * c / (dx * dx + dy * dy);
      }
      u = std::max(a2, b2);
      return (1 << k) | (1 << b); // edges (k, k+1) and (k+2, k)
    }
    Eigen::Vector2d pts[6];
    int np = 0;
    for(int k = 0; k < 3; ++k) {
      const int k2 = (k + 1) % 3;
      if(s[k] == 0) pts[np++] = w[k];
      if((s[k] < 0 && s[k2] > 0) || (s[k] > 0 && s[k2] < 0)) pts[np++] = w[k] + (s[k] / (s[k] - s[k2])) * (w[k2] - w[k]);
    }
    if(np == 0) return 0;
    u = 0;
    for(int i = 0; i < np; ++i) u = std::max(u, pts[i].squaredNorm());
    if(np == 3 && s[0] == 0 && s[1] == 0 && s[2] == 0) { // the triangle lies in the plane
      const auto cross = [](const Eigen::Vector2d& x, const Eigen::Vector2d& z) { return x.x() * z.y() - x.y() * z.x(); };
      const double c0 = cross(pts[1], pts[2]), c1 = cross(pts[2], pts[0]), c2 = cross(pts[0], pts[1]);
      const bool inside = (c0 >= 0 && c1 >= 0 && c2 >= 0) || (c0 <= 0 && c1 <= 0 && c2 <= 0);
      l = inside ? 0.0 : std::min({origin_to_segment2(pts[0], pts[1]), origin_to_segment2(pts[1], pts[2]), origin_to_segment2(pts[2], pts[0])});
    } else {
      int ia = 0, ib = 0;
      double far = -1;
      for(int i = 0; i < np; ++i)
        for(int j = i + 1; j < np; ++j) {
          const double d = (pts[i] - pts[j]).squaredNorm();
          if(d > far) { far = d; ia = i; ib = j; }
        }
      l = origin_to_segment2(pts[ia], pts[ib]);
    }
    int edges = 0; // corners on the plane: leave through every edge the plane meets
    for(int k = 0; k < 3; ++k)
      if(s[k] * s[(k + 1) % 3] <= 0) edges |= 1 << k;
    return edges;
  };
  // 1. The faces each row plane crosses (most faces cross none), grouped by row.
  // Branch-free in the common case (a face crosses at most two rows): both candidate entries are
  // written and the end advances by the count.
  std::size_t n_rows = 0;
  const int last_row = static_cast<int>(R) - 1;
  auto classify = [&](std::size_t f) {
    const auto& a0 = ws.rows[static_cast<std::size_t>(F[3 * f])];
    const auto& a1 = ws.rows[static_cast<std::size_t>(F[3 * f + 1])];
    const auto& a2 = ws.rows[static_cast<std::size_t>(F[3 * f + 2])];
    // rows r with min y <= r <= max y: from the smallest ceil to the largest floor
    const int lo = std::max(0, std::min({a0[1], a1[1], a2[1]}));
    const int hi = std::min(last_row, std::max({a0[0], a1[0], a2[0]}));
    const int count = std::max(0, hi - lo + 1);
    if(ws.face_rows.size() < n_rows + static_cast<std::size_t>(count) + 2) ws.face_rows.resize(2 * (n_rows + static_cast<std::size_t>(count)) + 64);
    auto* out = ws.face_rows.data() + n_rows;
    out[0] = {static_cast<std::uint32_t>(lo), static_cast<std::uint32_t>(f)};
    out[1] = {static_cast<std::uint32_t>(lo + 1), static_cast<std::uint32_t>(f)};
    for(int r = lo + 2; r <= hi; ++r) out[r - lo] = {static_cast<std::uint32_t>(r), static_cast<std::uint32_t>(f)};
    n_rows += static_cast<std::size_t>(count);
  };
  if(std::sqrt(2.0) * L + g.max_face_radius >= g.bbox_diagonal)
    for(std::size_t f = 0; f < m; ++f) classify(f);
  else
    g.face_tree.for_each_within({op.point.x(), op.point.y(), op.point.z()}, std::sqrt(2.0) * L + g.max_face_radius,
                                [&](std::size_t f, double) { classify(f); });
  group_by_row(ws.face_rows.data(), n_rows, R, ws.count, ws.next, ws.bucket);
  if(ws.stamp.size() != m || ws.epoch > 0xFFFFFFFFu - R) {
    ws.stamp.assign(m, 0);
    ws.epoch = 0;
  }
  // 2. Per row, walk each connected piece of the section across shared edges: along a connected
  //    curve alpha takes every value between its extremes, so a piece contributes one interval
  //    [min l, max u] and the union needs no sorting of per-face intervals.
  //    In the common case (no corner on the plane) a face has exactly two crossing edges, so the
  //    walk follows the section as a chain, carrying the point on the shared edge: one
  //    interpolation per face. Faces with a corner on the plane go through the general code.
  auto edge_point = [&](std::size_t f, int k, double t, double& x, double& y) {
    const std::size_t i = static_cast<std::size_t>(F[3 * f + static_cast<std::size_t>(k)]), j = static_cast<std::size_t>(F[3 * f + static_cast<std::size_t>((k + 1) % 3)]);
    const double si = ws.vx[i].t - t, sj = ws.vx[j].t - t;
    const double c = si == sj ? 0.0 : si / (si - sj);
    x = ws.vx[i].x + c * (ws.vx[j].x - ws.vx[i].x);
    y = ws.vx[i].y + c * (ws.vx[j].y - ws.vx[i].y);
  };
  for(std::size_t r = 0; r < R; ++r) {
    const std::uint32_t key = ++ws.epoch;
    const double t = static_cast<double>(r);
    double lmin = 0, umax = 0;
    // Follows the section from face p out through its edge k_out, whose plane point is (px, py).
    auto follow = [&](std::uint32_t p, int k_out, double px, double py) {
      for(;;) {
        const auto& from = g.face_links[p];
        const int nb = from.nb[k_out];
        if(nb < 0 || ws.stamp[static_cast<std::size_t>(nb)] == key) return;
        const std::size_t f = static_cast<std::size_t>(nb);
        ws.stamp[f] = key;
        const int k_in = from.edge[k_out];
        const auto& fl = g.face_links[f];
        // the next face is one of the two other neighbours: start loading both
        prefetch(&g.face_links[static_cast<std::size_t>(std::max(0, fl.nb[k_in == 2 ? 0 : k_in + 1]))]);
        prefetch(&g.face_links[static_cast<std::size_t>(std::max(0, fl.nb[k_in == 0 ? 2 : k_in - 1]))]);
        const Contour_workspace::Vertex* vr[3] = {&ws.vx[static_cast<std::size_t>(fl.v[0])], &ws.vx[static_cast<std::size_t>(fl.v[1])],
                                                  &ws.vx[static_cast<std::size_t>(fl.v[2])]};
        const double sv[3] = {vr[0]->t - t, vr[1]->t - t, vr[2]->t - t};
        if(sv[0] == 0 || sv[1] == 0 || sv[2] == 0 || k_in < 0) { // a corner on the plane: general code
          ws.stack.push_back(static_cast<std::uint32_t>(f));
          return;
        }
        // The corners' sides are per vertex, so the entry edge crosses here too and exactly one
        // other edge does: the exit (chosen without a branch).
        const bool p0 = sv[0] > 0, p1 = sv[1] > 0, p2 = sv[2] > 0;
        const bool crosses[3] = {p0 != p1, p1 != p2, p2 != p0};
        const int k1 = k_in == 2 ? 0 : k_in + 1, k2 = k1 == 2 ? 0 : k1 + 1;
        const int k_exit = crosses[k1] ? k1 : k2;
        const int k_next = k_exit == 2 ? 0 : k_exit + 1;
        const Contour_workspace::Vertex& vi = *vr[k_exit];
        const Contour_workspace::Vertex& vj = *vr[k_next];
        const double si = sv[k_exit], sj = sv[k_next];
        const double c = si / (si - sj);
        const double qx = vi.x + c * (vj.x - vi.x), qy = vi.y + c * (vj.y - vi.y);
        const double a2 = px * px + py * py, b2 = qx * qx + qy * qy;
        const double dx = qx - px, dy = qy - py;
        double l;
        if(px * dx + py * dy >= 0) l = a2;
        else if(qx * dx + qy * dy <= 0) l = b2;
        else {
          const double cr = px * dy - py * dx;
          l = cr * cr / (dx * dx + dy * dy);
        }
        lmin = std::min(lmin, l);
        umax = std::max(umax, b2);
        p = static_cast<std::uint32_t>(f);
        k_out = k_exit;
        px = qx;
        py = qy;
      }
    };
    for(std::uint32_t b = ws.count[r]; b < ws.count[r + 1]; ++b) {
      const std::uint32_t f0 = ws.bucket[b];
      if(ws.stamp[f0] == key) continue;
      ws.stamp[f0] = key;
      ws.stack.assign(1, f0);
      lmin = std::numeric_limits<double>::infinity();
      umax = -1;
      while(!ws.stack.empty()) {
        const std::uint32_t f = ws.stack.back();
        ws.stack.pop_back();
        double l, u;
        const int edges = section(f, static_cast<long>(r), l, u);
        if(!edges) continue;
        lmin = std::min(lmin, l);
        umax = std::max(umax, u);
        for(int k = 0; k < 3; ++k) {
          if(!(edges >> k & 1)) continue;
          double px, py;
          edge_point(f, k, t, px, py);
          follow(f, k, px, py);
        }
      }
      if(lmin <= L2) ws.entries.push_back({static_cast<std::uint32_t>(r), {lmin, std::min(umax, L2)}});
    }
  }
  // Group the intervals by row, sort each row by its lower ends.
  group_by_row(ws.entries.data(), ws.entries.size(), R, ws.count, ws.next, ws.sorted);
  // Union per row.
  for(std::size_t r = 0; r < R; ++r) {
    auto first = ws.sorted.begin() + ws.count[r], last = ws.sorted.begin() + ws.count[r + 1];
    auto& out = ws.merged[r];
    out.clear();
    std::sort(first, last, [](const std::pair<double, double>& a, const std::pair<double, double>& b) { return a.first < b.first; });
    for(auto it = first; it != last; ++it) {
      const auto& iv = *it;
      if(!out.empty() && iv.first <= out.back().second + eps) out.back().second = std::max(out.back().second, iv.second);
      else out.push_back(iv);
    }
    for(auto& iv : out) iv = {std::sqrt(iv.first), std::sqrt(iv.second)};
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
