// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file fit_template.h
/// The fit of a template to a specimen (thesis chapter 6): rigid pre-alignment, then NICPS, so that
/// the fitted template has the specimen's shape and the template's connectivity — the training
/// data of a statistical shape model.
#ifndef SHAPECORR_SHAPE_MODEL_FIT_TEMPLATE_H
#define SHAPECORR_SHAPE_MODEL_FIT_TEMPLATE_H

#include <shapecorr/exceptions.h>
#include <shapecorr/parameters.h>
#include <shapecorr/evaluation/surface_distance.h>
#include <shapecorr/internal/indexed_mesh.h>
#include <shapecorr/registration/nicps.h>
#include <shapecorr/registration/rigid_alignment.h>

#include <boost/property_map/function_property_map.hpp>

#include <Eigen/Core>

#include <chrono>
#include <limits>
#include <type_traits>
#include <utility>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrShapeModel
/// The result of `fit_template()`: both stages' reports, the surface distances of the template to
/// the specimen (`surface_distance()`: l1, l2, lmax) before, after the rigid alignment and after
/// NICPS, and with landmarks their distances.
struct Template_fit_report {
  Rigid_alignment_report rigid;          ///< the rigid pre-alignment (template ↦ specimen)
  Nicps_report nicps;                    ///< the non-rigid fit
  Surface_distance before;               ///< the template as given to the specimen
  Surface_distance after_rigid;          ///< after the rigid alignment
  Surface_distance after;                ///< the fitted template to the specimen
  std::vector<std::size_t> landmark_vertices;       ///< per landmark, the template vertex that carries it (nearest after the rigid alignment)
  std::vector<double> landmark_distances_before;    ///< template landmark to specimen landmark, as given
  std::vector<double> landmark_distances_after_rigid; ///< the template landmarks moved rigidly
  std::vector<double> landmark_distances_after;     ///< the carrying vertices after the fit
  double seconds = 0;                    ///< wall time
};

/// \ingroup PkgShapeCorrShapeModel
/// Fits `tmpl` to `specimen` and writes the fitted positions of the template's vertices into
/// `fitted`: `align_rigidly()` (principal axes and trimmed ICP by default; landmark pairs when
/// both packs have `landmark_points`; a similarity with `allow_scaling`), then `nicps()` from the
/// aligned template, steered by the landmarks when given (each template landmark is carried by the
/// template vertex nearest to it after the rigid alignment). The template itself is not modified.
/// The fitted template keeps the template's connectivity, so fits of one template to many
/// specimens are in correspondence: the input of `build_statistical_shape_model()`.
/// \tparam FittedPointMap a `WritablePropertyMap` from the template's `vertex_descriptor` to its point type
/// \param np1 named parameters of the template and of both stages:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `rigid_initialization` | start of the rigid alignment | `Rigid_initialization` | `LANDMARKS` with landmarks, else `PRINCIPAL_AXES` |
/// | `landmark_points` | the template's landmarks (with the specimen's in np2, paired by order) | range of points | none |
/// | `allow_scaling`, `icp_metric`, `trimming_fraction`, `number_of_samples` | the rigid alignment's (`align_rigidly()`) | | its defaults |
/// | `number_of_iterations` | bound of ICP per start and of NICPS | `std::size_t` | 50 |
/// | `nicps_regularizer`, `alpha_initial`, `alpha_decay`, `distance_threshold`, `reject_boundary_pairs`, `maximum_pair_distance`, `landmark_weight`, `iteration_callback`, `number_of_threads` | NICPS's (`nicps()`) | | its defaults |
/// | `vertex_point_map`, `vertex_index_map` | the template's positions and indices | property maps | the mesh's |
/// \param np2 of the specimen: `landmark_points`, `vertex_point_map`, `vertex_index_map`
/// \throws as `align_rigidly()` and `nicps()`; Invalid_argument when only one pack has landmarks
///         or their counts differ
/// \code
///   auto fitted = tmpl.add_property_map<Mesh::Vertex_index, Point>("v:fitted").first;
///   const shapecorr::Template_fit_report r = shapecorr::fit_template(tmpl, specimen, fitted);
///   std::cout << "l2 " << r.after_rigid.l2 << " -> " << r.after.l2 << "\n";
/// \endcode
template <typename TemplateMesh, typename SpecimenMesh, typename FittedPointMap, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Template_fit_report fit_template(const TemplateMesh& tmpl, const SpecimenMesh& specimen, FittedPointMap fitted,
                                 const NamedParameters1& np1 = CGAL::parameters::default_values(),
                                 const NamedParameters2& np2 = CGAL::parameters::default_values()) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  typedef boost::graph_traits<TemplateMesh> GT;
  typedef typename GT::vertex_descriptor vertex_descriptor;
  const auto t0 = std::chrono::steady_clock::now();
  const auto vpm = choose_parameter(get_parameter(np1, CGAL::internal_np::vertex_point), CGAL::get_const_property_map(CGAL::vertex_point, tmpl));
  typedef typename boost::property_traits<typename std::decay<decltype(vpm)>::type>::value_type Point;
  constexpr bool with_landmarks1 = !std::is_same<decltype(get_parameter(np1, internal_np::landmark_points)), CGAL::internal_np::Param_not_found>::value;
  constexpr bool with_landmarks2 = !std::is_same<decltype(get_parameter(np2, internal_np::landmark_points)), CGAL::internal_np::Param_not_found>::value;
  static_assert(with_landmarks1 == with_landmarks2, "fit_template: give landmark_points in both named parameter packs, or in none");
  std::vector<Eigen::Vector3d> template_landmarks, specimen_landmarks;
  if constexpr(with_landmarks1) {
    template_landmarks = internal::landmarks_of(np1, "template's");
    specimen_landmarks = internal::landmarks_of(np2, "specimen's");
    if(template_landmarks.size() != specimen_landmarks.size())
      throw Invalid_argument("fit_template: " + std::to_string(template_landmarks.size()) + " template landmarks against " +
                             std::to_string(specimen_landmarks.size()) + " specimen landmarks");
  }
  const Rigid_initialization init = choose_parameter(get_parameter(np1, internal_np::rigid_initialization),
                                                     with_landmarks1 ? Rigid_initialization::LANDMARKS : Rigid_initialization::PRINCIPAL_AXES);

  Template_fit_report r;
  r.before = surface_distance(tmpl, specimen, np1, np2);
  r.rigid = align_rigidly(tmpl, specimen, Named_function_parameters<Rigid_initialization, internal_np::rigid_initialization_t, NamedParameters1>(init, np1), np2);

  // the template moved rigidly, as a point map over its own vertices
  const internal::Indexed_mesh<TemplateMesh> indexed(tmpl, np1);
  const internal::Triangle_arrays& A = indexed.arrays();
  std::vector<Point> moved(A.number_of_vertices());
  for(std::size_t i = 0; i < moved.size(); ++i) {
    const Eigen::Vector3d q = r.rigid.transform(A.point(i));
    moved[i] = Point(q.x(), q.y(), q.z());
  }
  auto moved_map = boost::make_function_property_map<vertex_descriptor, Point>([&](vertex_descriptor v) { return moved[indexed.index(v)]; });
  const Named_function_parameters<decltype(moved_map), CGAL::internal_np::vertex_point_t, NamedParameters1> np_moved(moved_map, np1);
  r.after_rigid = surface_distance(tmpl, specimen, np_moved, np2);

  // landmarks: carried by the nearest template vertex after the rigid alignment
  std::vector<std::pair<std::size_t, Eigen::Vector3d>> steer;
  for(std::size_t l = 0; l < template_landmarks.size(); ++l) {
    const Eigen::Vector3d p = r.rigid.transform(template_landmarks[l]);
    std::size_t best = 0;
    double best_d = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < moved.size(); ++i) {
      const double d = (Eigen::Vector3d(CGAL::to_double(moved[i].x()), CGAL::to_double(moved[i].y()), CGAL::to_double(moved[i].z())) - p).squaredNorm();
      if(d < best_d) best_d = d, best = i;
    }
    r.landmark_vertices.push_back(best);
    steer.emplace_back(best, specimen_landmarks[l]);
    r.landmark_distances_before.push_back((template_landmarks[l] - specimen_landmarks[l]).norm());
    r.landmark_distances_after_rigid.push_back((p - specimen_landmarks[l]).norm());
  }
  r.nicps = nicps(tmpl, specimen, fitted, np_moved.landmark_correspondences(steer), np2);

  std::vector<Point> after(moved.size());
  for(std::size_t i = 0; i < after.size(); ++i) after[i] = get(fitted, indexed.vertex(i));
  auto fitted_map = boost::make_function_property_map<vertex_descriptor, Point>([&](vertex_descriptor v) { return after[indexed.index(v)]; });
  r.after = surface_distance(tmpl, specimen, Named_function_parameters<decltype(fitted_map), CGAL::internal_np::vertex_point_t, NamedParameters1>(fitted_map, np1), np2);
  for(std::size_t l = 0; l < steer.size(); ++l) {
    const Point& q = after[steer[l].first];
    r.landmark_distances_after.push_back((Eigen::Vector3d(CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())) - steer[l].second).norm());
  }
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  return r;
}

} // namespace shapecorr

#endif
