// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The benchmarks' mesh: $SHAPECORR_BENCH_MESH, else a file of ../shared/data, else a generated
// stand-in (so that the programs run without the data, with a note on stderr).
#ifndef SHAPECORR_BENCHMARK_BENCH_MESH_H
#define SHAPECORR_BENCHMARK_BENCH_MESH_H

#include <shapecorr/io.h>

#include <cstdlib>
#include <exception>
#include <functional>
#include <iostream>
#include <string>

namespace bench {

/// Reads the benchmark mesh into `mesh` (`data_file` relative to ../shared/data); on failure calls
/// `stand_in(mesh)` and returns `stand_in_name`. Returns the name of what was loaded.
template <typename Mesh>
std::string load_mesh(Mesh& mesh, const std::string& data_file, const std::function<void(Mesh&)>& stand_in, const std::string& stand_in_name) {
  const char* env = std::getenv("SHAPECORR_BENCH_MESH");
  const std::string name = env ? env : std::string(SHAPECORR_BENCH_DATA_DIR) + "/" + data_file;
  try {
    shapecorr::read_triangle_mesh(name, mesh);
    return name;
  } catch(const std::exception& e) {
    std::cerr << "benchmark mesh unavailable (" << e.what() << "): using " << stand_in_name << "\n";
    mesh.clear();
    stand_in(mesh);
    return stand_in_name;
  }
}

} // namespace bench

#endif
