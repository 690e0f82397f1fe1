#include <shapecorr/geodesics.h>
#include <shapecorr/mesh/primitives.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <iostream>

int main() {
  typedef CGAL::Surface_mesh<CGAL::Exact_predicates_inexact_constructions_kernel::Point_3> Mesh;
  Mesh m;
  shapecorr::make_icosphere(m, 2);
  shapecorr::Heat_method_geodesics<Mesh> heat(m);
  const double d = heat.distances_from(0)[3];
  std::cout << "antipode distance " << d << "\n";
  return (d > 3.0 && d < 3.3) ? 0 : 1;
}
