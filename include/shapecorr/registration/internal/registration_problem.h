// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: what every template-to-target registration method starts from and ends with: the
// template's flat copy (indexed, so results go back to its vertex descriptors), the target's flat
// copy with its closest-point tree, the RMS distance of positions to the target, and the write-back.
#ifndef SHAPECORR_REGISTRATION_INTERNAL_REGISTRATION_PROBLEM_H
#define SHAPECORR_REGISTRATION_INTERNAL_REGISTRATION_PROBLEM_H

#include <shapecorr/internal/closest_point_tree.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/parallel.h>
#include <shapecorr/registration/registration_report.h>

#include <boost/property_map/property_map.hpp>

#include <Eigen/Core>

#include <chrono>
#include <cmath>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace shapecorr {
namespace internal {

template <typename TemplateMesh>
class Registration_problem {
public:
  /// \throws Invalid_input (message starting with `context`) for a mesh without triangles or with a non-finite coordinate
  template <typename TargetMesh, typename NamedParameters1, typename NamedParameters2>
  Registration_problem(const TemplateMesh& tmpl, const TargetMesh& target, const NamedParameters1& np1, const NamedParameters2& np2,
                       const std::string& context)
      : m_start(std::chrono::steady_clock::now()), m_template(tmpl, np1) {
    require_finite_triangles(m_template.arrays(), context, "the template");
    m_target = finite_triangle_arrays(target, np2, context, "the target");
    m_tree.reset(new Closest_point_tree(m_target));
    m_diagonal = (m_target.V.colwise().maxCoeff() - m_target.V.colwise().minCoeff()).norm();
  }

  const Triangle_arrays& template_arrays() const { return m_template.arrays(); }
  const Triangle_arrays& target_arrays() const { return m_target; }
  const Closest_point_tree& target_tree() const { return *m_tree; }
  std::size_t template_size() const { return m_template.number_of_vertices(); }
  std::size_t target_size() const { return m_target.number_of_vertices(); }
  /// The target's bounding-box diagonal.
  double target_diagonal() const { return m_diagonal; }

  /// Root mean square distance of the rows of `x` to the target surface.
  double rms_to_target(const Eigen::MatrixXd& x, unsigned threads) const {
    const std::size_t n = static_cast<std::size_t>(x.rows());
    std::vector<double> d(n);
    parallel_for(n, threads, [&](std::size_t i, unsigned) { d[i] = m_tree->distance(x.row(static_cast<Eigen::Index>(i)).transpose()); });
    double s = 0;
    for(double v : d) s += v * v;
    return n == 0 ? 0.0 : std::sqrt(s / static_cast<double>(n));
  }

  /// Writes row i of `x` as the position of template vertex i.
  template <typename VertexPointMap>
  void write(const Eigen::MatrixXd& x, VertexPointMap out) const {
    typedef typename boost::property_traits<VertexPointMap>::value_type Point;
    for(std::size_t i = 0; i < m_template.number_of_vertices(); ++i) {
      const Eigen::Index r = static_cast<Eigen::Index>(i);
      put(out, m_template.vertex(i), Point(x(r, 0), x(r, 1), x(r, 2)));
    }
  }

  /// Seconds since construction.
  double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - m_start).count(); }

private:
  std::chrono::steady_clock::time_point m_start;
  Indexed_mesh<TemplateMesh> m_template;
  Triangle_arrays m_target;
  std::unique_ptr<Closest_point_tree> m_tree;
  double m_diagonal = 0;
};

/// Records an iteration in `report` (and its RMS distance as the final one) and tells whether to
/// go on: false when the callback asks to stop (the report's stop becomes CANCELLED).
inline bool record_iteration(Registration_report& report, const Iteration_record& rec, const std::function<bool(const Iteration_record&)>& callback) {
  report.iterations.push_back(rec);
  report.final_rms = rec.rms_distance;
  if(callback && !callback(rec)) {
    report.stop = Stop_reason::CANCELLED;
    return false;
  }
  return true;
}

} // namespace internal
} // namespace shapecorr

#endif
