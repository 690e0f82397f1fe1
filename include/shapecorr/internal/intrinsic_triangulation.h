// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: a triangulation described by edge lengths only (the intrinsic metric), with the
// edge flips that turn it into an intrinsic Delaunay triangulation (Bobenko & Springborn 2007;
// Sharp, Soliman & Crane 2019). Vertices are those of the input; faces may change.
#ifndef SHAPECORR_INTERNAL_INTRINSIC_TRIANGULATION_H
#define SHAPECORR_INTERNAL_INTRINSIC_TRIANGULATION_H

#include <shapecorr/internal/indexed_mesh.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <map>
#include <utility>
#include <vector>

namespace shapecorr {
namespace internal {

/// Planar layout of a triangle from its edge lengths: with A = (0,0) and B = (base,0), the apex C
/// with |AC| = left and |BC| = right, on the side y >= 0 (y = 0 when the lengths violate the
/// triangle inequality or base is 0).
inline std::pair<double, double> unfold_apex(double base, double left, double right) {
  if(!(base > 0)) return {0.0, 0.0};
  const double x = (left * left + base * base - right * right) / (2 * base);
  return {x, std::sqrt(std::max(0.0, left * left - x * x))};
}

/// Halfedge h = 3 f + k of face f runs from corner k to corner (k+1) mod 3.
/// `length[h]` is the length of that edge, `twin[h]` the opposite halfedge or -1 on a boundary.
struct Intrinsic_triangulation {
  std::vector<std::array<int, 3>> faces;
  std::vector<double> length;
  std::vector<int> twin;
  std::size_t n_vertices = 0;

  std::size_t number_of_faces() const { return faces.size(); }
  static int next(int h) { return (h % 3 == 2) ? h - 2 : h + 1; }
  static int prev(int h) { return (h % 3 == 0) ? h + 2 : h - 1; }
  int tail(int h) const { return faces[static_cast<std::size_t>(h / 3)][static_cast<std::size_t>(h % 3)]; }
  int head(int h) const { return tail(next(h)); }

  /// Area of face f from its edge lengths (Heron, in the numerically stable form).
  double area(std::size_t f) const {
    double a = length[3 * f], b = length[3 * f + 1], c = length[3 * f + 2];
    if(a < b) std::swap(a, b);
    if(a < c) std::swap(a, c);
    if(b < c) std::swap(b, c);
    const double s = (a + (b + c)) * (c - (a - b)) * (c + (a - b)) * (a + (b - c));
    return s > 0 ? 0.25 * std::sqrt(s) : 0.0;
  }
  /// Cotangent of the angle opposite halfedge h (in h's face).
  double cotan_opposite(int h) const {
    const double a = length[static_cast<std::size_t>(next(h))];
    const double b = length[static_cast<std::size_t>(prev(h))];
    const double c = length[static_cast<std::size_t>(h)];
    const double A = area(static_cast<std::size_t>(h / 3));
    if(A <= 0) return 0.0; // degenerate face: contributes nothing (validation reports it)
    return (a * a + b * b - c * c) / (4.0 * A);
  }

  /// Build from the extrinsic triangles. Non-manifold edges (three or more faces) are left
  /// unglued (treated as boundaries) rather than rejected: validation reports them.
  static Intrinsic_triangulation from_arrays(const Triangle_arrays& a) {
    Intrinsic_triangulation t;
    t.n_vertices = a.number_of_vertices();
    const std::size_t m = a.number_of_faces();
    t.faces.resize(m);
    t.length.resize(3 * m);
    t.twin.assign(3 * m, -1);
    std::map<std::pair<int, int>, int> open; // directed edge -> halfedge
    for(std::size_t f = 0; f < m; ++f) {
      for(int k = 0; k < 3; ++k) {
        t.faces[f][static_cast<std::size_t>(k)] = a.F(static_cast<Eigen::Index>(f), k);
      }
      for(int k = 0; k < 3; ++k) {
        const int i = t.faces[f][static_cast<std::size_t>(k)], j = t.faces[f][static_cast<std::size_t>((k + 1) % 3)];
        const int h = static_cast<int>(3 * f) + k;
        t.length[static_cast<std::size_t>(h)] = (a.point(static_cast<std::size_t>(i)) - a.point(static_cast<std::size_t>(j))).norm();
        auto it = open.find(std::make_pair(j, i));
        if(it != open.end() && it->second >= 0) {
          t.twin[static_cast<std::size_t>(h)] = it->second;
          t.twin[static_cast<std::size_t>(it->second)] = h;
          it->second = -1; // glued; a third face on this edge stays a boundary
        } else if(it == open.end()) {
          open.emplace(std::make_pair(i, j), h);
        }
      }
    }
    return t;
  }

  bool is_delaunay(int h) const {
    const int t = twin[static_cast<std::size_t>(h)];
    if(t < 0) return true;
    return cotan_opposite(h) + cotan_opposite(t) >= -1e-12;
  }

  /// Flip the interior edge h (a->b in face (a,b,c), twin b->a in face (b,a,d)) to c-d.
  /// Returns false (and does nothing) where the flip is impossible.
  bool flip(int h) {
    const int t = twin[static_cast<std::size_t>(h)];
    if(t < 0) return false;
    const int f = h / 3, g = t / 3;
    if(f == g) return false;
    const int h1 = next(h), h2 = prev(h); // b->c, c->a
    const int t1 = next(t), t2 = prev(t); // a->d, d->b
    const int a = tail(h), b = head(h), c = tail(h2), d = tail(t2);
    const double l_ab = length[static_cast<std::size_t>(h)], l_bc = length[static_cast<std::size_t>(h1)],
                 l_ca = length[static_cast<std::size_t>(h2)], l_ad = length[static_cast<std::size_t>(t1)],
                 l_db = length[static_cast<std::size_t>(t2)];
    // Unfold both triangles into the plane: a = (0,0), b = (l_ab, 0), c above, d below.
    const auto c2 = unfold_apex(l_ab, l_ca, l_bc), d2 = unfold_apex(l_ab, l_ad, l_db);
    const double l_cd = std::hypot(c2.first - d2.first, c2.second + d2.second);
    if(!(l_cd > 0) || !std::isfinite(l_cd)) return false;
    // the twins of the four outer halfedges
    const int o_bc = twin[static_cast<std::size_t>(h1)], o_ca = twin[static_cast<std::size_t>(h2)],
              o_ad = twin[static_cast<std::size_t>(t1)], o_db = twin[static_cast<std::size_t>(t2)];
    // new faces: f = (c, a, d), g = (d, b, c)
    faces[static_cast<std::size_t>(f)] = {c, a, d};
    faces[static_cast<std::size_t>(g)] = {d, b, c};
    const int f0 = 3 * f, g0 = 3 * g;
    auto set = [&](int he, double len, int tw) {
      length[static_cast<std::size_t>(he)] = len;
      twin[static_cast<std::size_t>(he)] = tw;
      if(tw >= 0) twin[static_cast<std::size_t>(tw)] = he;
    };
    set(f0 + 0, l_ca, o_ca); // c->a
    set(f0 + 1, l_ad, o_ad); // a->d
    set(f0 + 2, l_cd, -1);   // d->c
    set(g0 + 0, l_db, o_db); // d->b
    set(g0 + 1, l_bc, o_bc); // b->c
    set(g0 + 2, l_cd, f0 + 2); // c->d, twin of d->c
    return true;
  }

  /// Flip non-Delaunay edges until every interior edge is (intrinsic) Delaunay.
  /// Returns the number of flips.
  std::size_t make_delaunay() {
    std::vector<int> stack;
    std::vector<char> queued(length.size(), 0);
    for(int h = 0; h < static_cast<int>(length.size()); ++h) {
      const int t = twin[static_cast<std::size_t>(h)];
      if(t > h) { stack.push_back(h); queued[static_cast<std::size_t>(h)] = 1; }
    }
    std::size_t flips = 0;
    const std::size_t max_flips = 50 * length.size() + 1000; // guard against cycling on degenerate input
    while(!stack.empty() && flips < max_flips) {
      int h = stack.back();
      stack.pop_back();
      queued[static_cast<std::size_t>(h)] = 0;
      if(twin[static_cast<std::size_t>(h)] < 0 || is_delaunay(h)) continue;
      const int f = h / 3, g = twin[static_cast<std::size_t>(h)] / 3;
      if(!flip(h)) continue;
      ++flips;
      for(int e : {3 * f, 3 * f + 1, 3 * g, 3 * g + 1}) { // the four outer edges after the flip
        int k = e;
        const int tw = twin[static_cast<std::size_t>(k)];
        if(tw >= 0 && tw < k) k = tw;
        if(!queued[static_cast<std::size_t>(k)]) { queued[static_cast<std::size_t>(k)] = 1; stack.push_back(k); }
      }
    }
    return flips;
  }
};

} // namespace internal
} // namespace shapecorr

#endif
