// Part of a shape (CGAL::Face_filtered_graph): Geodesic Spin Contours, Spin Contours and spin
// images on the patch equal those on a copy of it (CGAL::copy_face_graph).
#include "test_patches.h"

#include <shapecorr/descriptors.h>

#include <catch2/catch.hpp>

#include <cmath>

namespace SP = shapecorr::parameters;
typedef test::Patch::vertex_descriptor vertex_descriptor;

namespace {
// Largest L1 distance between the contours of the patch's vertices and their copies', and the
// number of points compared.
template <typename PatchMap, typename CopyMap>
std::pair<double, std::size_t> contour_difference(const test::Patch& p, const std::vector<vertex_descriptor>& vs, PatchMap on_patch, CopyMap on_copy) {
  double diff = 0;
  std::size_t points = 0;
  for(vertex_descriptor v : vs) {
    const shapecorr::Spin_contour& a = on_patch[v];
    const shapecorr::Spin_contour& b = on_copy[p.to_copy.at(v)];
    diff = std::max(diff, shapecorr::contour_l1_distance(a, b));
    points += a.size();
  }
  return {diff, points};
}
} // namespace

TEST_CASE("patch: Geodesic Spin Contours equal the copy's", "[partial][descriptors][gsc]") {
  const auto p = test::sphere_patch();
  std::vector<vertex_descriptor> vs;
  for(vertex_descriptor v : vertices(*p->filtered))
    if(vs.size() < 40) vs.push_back(v);
  std::vector<vertex_descriptor> copies;
  for(vertex_descriptor v : vs) copies.push_back(p->to_copy.at(v));
  auto on_patch = p->whole.add_property_map<vertex_descriptor, shapecorr::Spin_contour>("v:gsc").first;
  auto on_copy = p->copy.add_property_map<vertex_descriptor, shapecorr::Spin_contour>("v:gsc").first;
  shapecorr::compute_geodesic_spin_contours(*p->filtered, vs, on_patch, SP::support_fraction(0.4).image_rows(std::size_t(32)));
  shapecorr::compute_geodesic_spin_contours(p->copy, copies, on_copy, SP::support_fraction(0.4).image_rows(std::size_t(32)));
  const auto d = contour_difference(*p, vs, on_patch, on_copy);
  INFO("max L1 difference " << d.first << " over " << d.second << " points");
  CHECK(d.second > 40 * 10);
  CHECK(d.first < 1e-9);
}

TEST_CASE("patch: Spin Contours and spin images equal the copy's", "[partial][descriptors][spin-contour]") {
  const auto p = test::sphere_patch();
  const std::vector<vertex_descriptor> vs = p->patch_vertices();
  std::vector<vertex_descriptor> copies;
  for(vertex_descriptor v : vs) copies.push_back(p->to_copy.at(v));
  const auto np = SP::support_length(0.8).spin_axis(shapecorr::Spin_axis::NORMAL);

  auto sc_patch = p->whole.add_property_map<vertex_descriptor, shapecorr::Spin_contour>("v:sc").first;
  auto sc_copy = p->copy.add_property_map<vertex_descriptor, shapecorr::Spin_contour>("v:sc").first;
  shapecorr::compute_spin_contours(*p->filtered, vs, sc_patch, np);
  shapecorr::compute_spin_contours(p->copy, copies, sc_copy, np);
  const auto d = contour_difference(*p, vs, sc_patch, sc_copy);
  INFO("Spin Contours: max L1 difference " << d.first << " over " << d.second << " points");
  CHECK(d.second > vs.size() * 10);
  CHECK(d.first < 1e-9);

  auto si_patch = p->whole.add_property_map<vertex_descriptor, shapecorr::Spin_image>("v:si").first;
  auto si_copy = p->copy.add_property_map<vertex_descriptor, shapecorr::Spin_image>("v:si").first;
  shapecorr::compute_spin_images(*p->filtered, vs, si_patch, np);
  shapecorr::compute_spin_images(p->copy, copies, si_copy, np);
  double diff = 0, total = 0, largest = 0;
  for(vertex_descriptor v : vs) {
    const auto& a = si_patch[v];
    const auto& b = si_copy[p->to_copy.at(v)];
    REQUIRE(a.rows() == b.rows());
    REQUIRE(a.columns() == b.columns());
    for(std::size_t r = 0; r < a.rows(); ++r)
      for(std::size_t c = 0; c < a.columns(); ++c) {
        diff = std::max(diff, std::abs(static_cast<double>(a.at(r, c)) - static_cast<double>(b.at(r, c))));
        total += a.at(r, c);
        largest = std::max(largest, static_cast<double>(a.at(r, c)));
      }
  }
  INFO("spin images: max bin difference " << diff << ", largest bin " << largest << ", total " << total);
  CHECK(total > 0);
  CHECK(diff < 1e-6 * largest); // bins are floats: a few units in the last place
}
