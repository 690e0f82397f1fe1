// A statistical shape model (thesis chapter 6) of generated "specimens": ellipsoids whose axes
// vary, each meshed on its own. One template (a sphere) is fitted to every specimen
// (fit_template: rigid alignment + NICPS), the fits share the template's connectivity, the model
// is built from them (Procrustes + PCA), then queried: explained variance, an instance, the
// reconstruction of a specimen with one mode, the quality curves. Writes model.ssm and
// instance.off into the current folder (and says so).
// Usage: example_shape_model
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/shape_model.h>
#include <shapecorr/shape_model/fit_template.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/IO/polygon_mesh_io.h>

#include <filesystem>
#include <iostream>

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef CGAL::Surface_mesh<K::Point_3> Mesh;
typedef Mesh::Vertex_index vertex_descriptor;

int main() {
  Mesh tmpl;
  shapecorr::make_icosphere(tmpl, 3); // 642 vertices
  std::vector<Mesh> specimens;
  for(double a : {0.8, 1.0, 1.2})
    for(double b : {0.9, 1.1}) {
      Mesh s;
      shapecorr::make_icosphere(s, 4); // another triangulation: 2562 vertices
      for(vertex_descriptor v : vertices(s)) {
        const K::Point_3 p = s.point(v);
        s.point(v) = K::Point_3(1.5 * a * p.x() + 0.2 * a, b * p.y(), 0.8 * p.z()); // moved a little, too
      }
      specimens.push_back(s);
    }

  //! [fit-and-build]
  // 1. the template fitted to every specimen: the fits share the template's connectivity
  std::vector<Mesh> fits;
  for(const Mesh& specimen : specimens) {
    auto fitted = tmpl.add_property_map<vertex_descriptor, K::Point_3>("v:fitted").first;
    const shapecorr::Template_fit_report r = shapecorr::fit_template(tmpl, specimen, fitted);
    Mesh fit = tmpl;
    for(vertex_descriptor v : vertices(fit)) fit.point(v) = fitted[v];
    tmpl.remove_property_map(fitted);
    fits.push_back(fit);
    std::cout << "fit: l2 distance " << r.after_rigid.l2 << " after the rigid alignment, " << r.after.l2 << " after NICPS\n";
  }
  // 2. the model: Procrustes alignment (rigid; allow_scaling(true) for similarities) and PCA
  const shapecorr::Statistical_shape_model model = shapecorr::build_statistical_shape_model(fits);
  std::cout << model.number_of_modes() << " modes; explained variance of the first two: " << model.explained_variance_ratios().head(2).transpose()
            << "\n";
  model.save("model.ssm"); // Statistical_shape_model::load("model.ssm") reads it back
  //! [fit-and-build]

  //! [query]
  // an instance 2 standard deviations along mode 1, as a mesh of the template's connectivity
  Eigen::VectorXd c(1);
  c << 2.0;
  Mesh instance;
  shapecorr::make_shape_mesh(model, model.instance(c), instance);
  CGAL::IO::write_polygon_mesh("instance.off", instance, CGAL::parameters::stream_precision(17));
  // a shape's coefficients, and the shape as the first mode alone sees it
  Eigen::VectorXd x(3 * num_vertices(fits[0]));
  for(vertex_descriptor v : vertices(fits[0])) x.segment<3>(3 * v.idx()) << fits[0].point(v).x(), fits[0].point(v).y(), fits[0].point(v).z();
  std::cout << "coefficients of specimen 0: " << model.project(x).coefficients.transpose() << "\n";
  const Eigen::VectorXd one_mode = model.reconstruct(x, 1);
  // the quality of the model: compactness, generalization (leave-one-out), specificity
  const shapecorr::Shape_model_curve G = shapecorr::shape_model_generalization(model);
  const shapecorr::Shape_model_curve S = shapecorr::shape_model_specificity(model, shapecorr::parameters::number_of_samples(200));
  std::cout << "generalization G(1) = " << G.value[0] << ", G(2) = " << G.value[1] << "; specificity S(1) = " << S.value[0] << "\n";
  //! [query]
  std::cout << "largest vertex error of specimen 0 with one mode: " << (one_mode - x).cwiseAbs().maxCoeff() << "\n";
  std::cout << "wrote " << std::filesystem::absolute("model.ssm").string() << " and " << std::filesystem::absolute("instance.off").string() << "\n";
}
