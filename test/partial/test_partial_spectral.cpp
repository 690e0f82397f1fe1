// Part of a shape (CGAL::Face_filtered_graph): the Laplace-Beltrami eigenbasis and the heat kernel
// signature on the patch equal those on a copy of it (CGAL::copy_face_graph).
#include "test_patches.h"

#include <shapecorr/spectral.h>

#include <catch2/catch.hpp>

#include <cmath>

namespace SP = shapecorr::parameters;
typedef test::Patch::vertex_descriptor vertex_descriptor;

TEST_CASE("patch: eigenbasis and HKS equal the copy's", "[partial][spectral]") {
  const auto p = test::sphere_patch();
  const auto& patch = *p->filtered;
  const std::size_t k = 12;
  const auto on_patch = shapecorr::compute_laplace_beltrami_eigenbasis(patch, k);
  const auto on_copy = shapecorr::compute_laplace_beltrami_eigenbasis(p->copy, k);
  REQUIRE(on_patch.number_of_vertices() == num_vertices(patch));
  CHECK(std::abs(on_patch.eigenvalues()[0]) < 1e-8); // Neumann boundary: constants
  for(std::size_t j = 0; j < k; ++j) {
    INFO("eigenvalue " << j);
    CHECK(on_patch.eigenvalues()[static_cast<Eigen::Index>(j)] ==
          Approx(on_copy.eigenvalues()[static_cast<Eigen::Index>(j)]).epsilon(1e-8).margin(1e-9));
  }
  // rows follow the vertex index maps: the patch's own (0..n-1), the copy's
  const auto pim = get(boost::vertex_index, patch);
  const auto cim = get(boost::vertex_index, p->copy);
  double mass_diff = 0;
  for(vertex_descriptor v : vertices(patch))
    mass_diff = std::max(mass_diff, std::abs(on_patch.mass()[static_cast<Eigen::Index>(get(pim, v))] -
                                             on_copy.mass()[static_cast<Eigen::Index>(get(cim, p->to_copy.at(v)))]));
  CHECK(mass_diff < 1e-12);

  auto hks_patch = p->whole.add_property_map<vertex_descriptor, std::vector<double>>("v:hks").first;
  auto hks_copy = p->copy.add_property_map<vertex_descriptor, std::vector<double>>("v:hks").first;
  shapecorr::compute_heat_kernel_signature(patch, hks_patch, SP::eigenbasis(&on_patch).number_of_scales(std::size_t(16)));
  shapecorr::compute_heat_kernel_signature(p->copy, hks_copy, SP::eigenbasis(&on_copy).number_of_scales(std::size_t(16)));
  double diff = 0, largest = 0;
  for(vertex_descriptor v : vertices(patch)) {
    const auto& a = hks_patch[v];
    const auto& b = hks_copy[p->to_copy.at(v)];
    REQUIRE(a.size() == 16);
    REQUIRE(b.size() == 16);
    for(std::size_t s = 0; s < a.size(); ++s) {
      diff = std::max(diff, std::abs(a[s] - b[s]));
      largest = std::max(largest, std::abs(a[s]));
    }
  }
  INFO("largest HKS value " << largest << ", max difference " << diff);
  CHECK(largest > 0);
  CHECK(diff < 1e-6 * largest);
}
