// Shared helpers of the test suite: the mesh types every generic algorithm is run over, and
// access to ../shared/data (tests that need it skip when it is absent).
//
// Every TEMPLATE_LIST_TEST_CASE of a public generic function runs over `test::Mesh_types`: CGAL's
// Surface_mesh and Polyhedron_3, and OpenMesh's TriMesh, a type outside namespace CGAL (a call that
// only argument-dependent lookup finds in namespace CGAL does not compile for it). OpenMesh stores
// float coordinates: `test::coordinate_epsilon<Mesh>()` is the relative precision of a mesh type.
#ifndef SHAPECORR_TEST_TEST_MESHES_H
#define SHAPECORR_TEST_TEST_MESHES_H

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <OpenMesh/Core/Mesh/TriMesh_ArrayKernelT.hh>
#include <CGAL/boost/graph/graph_traits_TriMesh_ArrayKernelT.h>
#include <CGAL/boost/graph/properties_TriMesh_ArrayKernelT.h>

#include <Eigen/Core>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <tuple>
#include <type_traits>
#include <vector>

#include <unistd.h>

namespace test {

typedef CGAL::Exact_predicates_inexact_constructions_kernel K;
typedef K::Point_3 Point;
typedef CGAL::Surface_mesh<Point> Surface_mesh;
typedef CGAL::Polyhedron_3<K> Polyhedron;
typedef OpenMesh::TriMesh_ArrayKernelT<> OpenMesh_mesh;

/// The mesh types of the typed tests (TEMPLATE_LIST_TEST_CASE(name, tags, test::Mesh_types)).
typedef std::tuple<Surface_mesh, Polyhedron, OpenMesh_mesh> Mesh_types;

/// Relative precision of the coordinates a mesh type stores: the machine epsilon of double for
/// CGAL's types, of float for OpenMesh's default traits.
template <typename Mesh>
constexpr double coordinate_epsilon() {
  return std::is_same<Mesh, OpenMesh_mesh>::value ? double(std::numeric_limits<float>::epsilon())
                                                  : std::numeric_limits<double>::epsilon();
}

/// ../shared/data (or $SHAPECORR_DATA); empty when absent.
inline std::string data_dir() {
  if(const char* env = std::getenv("SHAPECORR_DATA")) return env;
  const std::string d = SHAPECORR_TEST_DATA_DIR;
  std::ifstream probe(d + "/README.md");
  return probe ? d : std::string();
}

/// A path for a scratch file in this process's own temporary directory (created on first use, removed at exit), so
/// that tests never write into the directory they are started from and parallel runs do not collide.
inline std::string temp_path(const std::string& name) {
  struct Scratch {
    std::filesystem::path dir = std::filesystem::temp_directory_path() /
                                ("shapecorr_tests_" + std::to_string(static_cast<long long>(::getpid())));
    Scratch() { std::filesystem::create_directories(dir); }
    ~Scratch() {
      std::error_code ec;
      std::filesystem::remove_all(dir, ec);
    }
  };
  static const Scratch scratch;
  return (scratch.dir / name).string();
}

/// Positions of a mesh in the order of its (initialized) vertex index map.
template <typename Mesh>
std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> vertices_in_index_order(const Mesh& m) {
  auto vim = CGAL::get_initialized_vertex_index_map(m);
  std::vector<typename boost::graph_traits<Mesh>::vertex_descriptor> vs(num_vertices(m));
  for(auto v : vertices(m)) vs[get(vim, v)] = v;
  return vs;
}

} // namespace test

#endif
