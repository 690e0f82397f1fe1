// Shapes and transformations shared by the spectral tests.
#ifndef SHAPECORR_TEST_SPECTRAL_HELPERS_H
#define SHAPECORR_TEST_SPECTRAL_HELPERS_H

#include "test_meshes.h"

#include <shapecorr/mesh/primitives.h>

#include <Eigen/Geometry>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>

namespace test {

/// Applies p -> f(p) to every vertex position.
template <typename Mesh, typename F>
void transform_points(Mesh& m, F&& f) {
  auto vpm = get(CGAL::vertex_point, m);
  for(auto v : vertices(m)) {
    const auto& p = get(vpm, v);
    const Eigen::Vector3d q = f(Eigen::Vector3d(p.x(), p.y(), p.z()));
    put(vpm, v, Point(q.x(), q.y(), q.z()));
  }
}

/// An ellipsoid with axes 1, 0.8, 0.6 (no symmetry beyond the three mirror planes: simple spectrum).
template <typename Mesh>
void make_ellipsoid(Mesh& m, int subdivisions) {
  shapecorr::make_icosphere(m, subdivisions);
  transform_points(m, [](const Eigen::Vector3d& p) { return Eigen::Vector3d(p.x(), 0.8 * p.y(), 0.6 * p.z()); });
}

/// A random rotation and translation (fixed seed).
inline Eigen::Isometry3d random_rigid_motion(unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> g;
  Eigen::Quaterniond q(g(rng), g(rng), g(rng), g(rng));
  q.normalize();
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = q.toRotationMatrix();
  T.translation() = Eigen::Vector3d(g(rng), g(rng), g(rng)) * 5.0;
  return T;
}

/// A rigid motion that the coordinates of `Mesh` represent exactly enough for an invariance test:
/// `random_rigid_motion(seed)` for double coordinates; for float coordinates (OpenMesh's default
/// traits) a random proper rotation that permutes the axes and flips signs, without translation,
/// which moves every float coordinate exactly. (A general motion rounds every moved coordinate to
/// float, about 1e-7 relative: the test would then measure that rounding, not the algorithm.)
template <typename Mesh>
Eigen::Isometry3d representable_rigid_motion(unsigned seed) {
  if(coordinate_epsilon<Mesh>() == std::numeric_limits<double>::epsilon()) return random_rigid_motion(seed);
  std::mt19937 rng(seed);
  int axis[3] = {0, 1, 2};
  std::shuffle(axis, axis + 3, rng);
  Eigen::Matrix3d R = Eigen::Matrix3d::Zero();
  for(int i = 0; i < 3; ++i) R(i, axis[i]) = (rng() % 2) ? 1.0 : -1.0;
  if(R.determinant() < 0) R.row(0) *= -1.0; // proper: a rotation, not a reflection
  Eigen::Isometry3d T = Eigen::Isometry3d::Identity();
  T.linear() = R;
  return T;
}

} // namespace test

#endif
