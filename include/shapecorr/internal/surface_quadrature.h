// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: area integrals of a 1-Lipschitz function (a distance to a surface) over a triangle
// mesh, by the composite midpoint rule on a uniform subdivision of every triangle, with a rigorous
// error bound. Shared by the surface-distance metrics (evaluation/) and the registration methods
// (their stopping test).
#ifndef SHAPECORR_INTERNAL_SURFACE_QUADRATURE_H
#define SHAPECORR_INTERNAL_SURFACE_QUADRATURE_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/parallel.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <vector>

namespace shapecorr {
namespace internal {

/// Mean, root mean square and maximum of f over a surface, and how far they can be from the
/// integrals (see `integrate_over_surface`).
struct Surface_integrals {
  double mean = 0;          // (1/|R|) ∫ f
  double root_mean_square = 0; // sqrt((1/|R|) ∫ f²)
  double maximum = 0;       // max over the samples (vertices and sub-triangle centroids)
  double area = 0;          // |R|
  double error_bound = 0;   // each of the three is within this of its exact value
  std::size_t samples = 0;  // evaluations of f
};

/// Number of subdivisions of a triangle (each edge cut into s pieces, s² congruent sub-triangles)
/// for sub-triangles with edges at most `step`.
inline std::size_t quadrature_subdivisions(const Eigen::Vector3d& a, const Eigen::Vector3d& b, const Eigen::Vector3d& c, double step) {
  const double longest = std::max({(b - a).norm(), (c - b).norm(), (a - c).norm()});
  const double s = std::ceil(longest / step);
  return s < 1 ? 1 : static_cast<std::size_t>(std::min(s, 1000.0));
}

/// The integrals of f over the triangles of `R`. Each triangle is cut into s² congruent
/// sub-triangles (s from `step`); f is evaluated at every sub-triangle centroid (weight: its area)
/// and at the vertices (for the maximum). For f 1-Lipschitz (|f(p) − f(q)| ≤ |p − q|, as a distance
/// to a set is) the piecewise-constant interpolant differs from f by at most h, the largest
/// distance from a sub-triangle's centroid to its corners; hence the mean, the root mean square
/// (Minkowski) and the maximum are each within h of the exact values: `error_bound` = h. Where f is
/// smooth the midpoint rule's error is O(h²), far below the bound.
/// `f(p)` must be thread-safe; evaluated on `threads` threads.
template <typename Function>
Surface_integrals integrate_over_surface(const Triangle_arrays& R, double step, const Function& f, unsigned threads = 0) {
  const std::size_t m = R.number_of_faces();
  if(m == 0) throw Invalid_input(Mesh_defect::empty_mesh, "surface distance: the mesh has no triangle");
  if(!(step > 0) || !std::isfinite(step)) throw Invalid_argument("surface distance: the quadrature step must be positive and finite");
  struct Partial {
    double sum = 0, sum2 = 0, max = 0, area = 0, h = 0;
    std::size_t samples = 0;
  };
  std::vector<Partial> per_face(m);
  parallel_for(m, threads, [&](std::size_t t, unsigned) {
    const Eigen::Index ti = static_cast<Eigen::Index>(t);
    const Eigen::Vector3d a = R.point(static_cast<std::size_t>(R.F(ti, 0))), b = R.point(static_cast<std::size_t>(R.F(ti, 1))),
                          c = R.point(static_cast<std::size_t>(R.F(ti, 2)));
    const std::size_t s = quadrature_subdivisions(a, b, c, step);
    const double area = 0.5 * (b - a).cross(c - a).norm();
    const double w = area / static_cast<double>(s * s);
    const Eigen::Vector3d u = (b - a) / static_cast<double>(s), v = (c - a) / static_cast<double>(s);
    Partial& P = per_face[t];
    P.area = area;
    // the centroid of a sub-triangle is at most this far from its corners (the same for the
    // upward and the downward ones: congruent, rotated by 180 degrees)
    const Eigen::Vector3d g = (a + b + c) / 3.0;
    P.h = std::max({(a - g).norm(), (b - g).norm(), (c - g).norm()}) / static_cast<double>(s);
    auto sample = [&](const Eigen::Vector3d& p, double weight) {
      const double d = f(p);
      P.sum += weight * d;
      P.sum2 += weight * d * d;
      P.max = std::max(P.max, d);
      ++P.samples;
    };
    for(std::size_t i = 0; i < s; ++i)
      for(std::size_t j = 0; i + j < s; ++j) {
        const Eigen::Vector3d o = a + static_cast<double>(i) * u + static_cast<double>(j) * v;
        sample(o + (u + v) / 3.0, w);                              // upward sub-triangle (o, o+u, o+v)
        if(i + j + 1 < s) sample(o + 2.0 * (u + v) / 3.0, w);     // downward (o+u, o+u+v, o+v)
      }
    for(const Eigen::Vector3d* p : {&a, &b, &c}) sample(*p, 0.0); // vertices: the maximum only
  });
  Partial total;
  for(const Partial& P : per_face) {
    total.sum += P.sum;
    total.sum2 += P.sum2;
    total.max = std::max(total.max, P.max);
    total.area += P.area;
    total.h = std::max(total.h, P.h);
    total.samples += P.samples;
  }
  if(!(total.area > 0)) throw Invalid_input(Mesh_defect::degenerate_face, "surface distance: the mesh has zero area");
  Surface_integrals r;
  r.area = total.area;
  r.mean = total.sum / total.area;
  r.root_mean_square = std::sqrt(std::max(0.0, total.sum2 / total.area));
  r.maximum = total.max;
  r.error_bound = total.h;
  r.samples = total.samples;
  return r;
}

/// Mean edge length of a flat mesh copy (each edge counted once per incident triangle).
inline double mean_edge_length(const Triangle_arrays& a) {
  double sum = 0;
  for(Eigen::Index f = 0; f < a.F.rows(); ++f)
    for(int k = 0; k < 3; ++k) sum += (a.point(static_cast<std::size_t>(a.F(f, k))) - a.point(static_cast<std::size_t>(a.F(f, (k + 1) % 3)))).norm();
  return a.F.rows() ? sum / (3.0 * static_cast<double>(a.F.rows())) : 0.0;
}

} // namespace internal
} // namespace shapecorr

#endif
