// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: the heat method (Crane, Weischedel & Wardetzky 2013) on flat arrays, factored once,
// queried for batches of sources at once (several right-hand sides per triangular solve) and in
// parallel over batches.
#ifndef SHAPECORR_GEODESICS_INTERNAL_HEAT_METHOD_ENGINE_H
#define SHAPECORR_GEODESICS_INTERNAL_HEAT_METHOD_ENGINE_H

#include <shapecorr/exceptions.h>
#include <shapecorr/parallel.h>
#include <shapecorr/internal/sparse_solver.h>
#include <shapecorr/internal/components.h>
#include <shapecorr/internal/intrinsic_triangulation.h>
#include <shapecorr/internal/cotangent_operators.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>

#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <vector>

namespace shapecorr {
namespace internal {

struct Heat_method_options {
  double time_step_factor = 1.0;     // t = factor * h^2, h = mean edge length
  bool intrinsic_delaunay = false;   // run on the intrinsic Delaunay triangulation
  unsigned threads = 0;              // 0 = hardware concurrency
  std::size_t batch_size = 8;        // right-hand sides per solve (small blocks stay in cache)
};

template <typename SparseSolver = Default_sparse_spd_solver>
class Heat_method_engine {
public:
  typedef Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic> Matrix;

  Heat_method_engine(const Triangle_arrays& arrays, const Heat_method_options& opt = Heat_method_options())
    : m_opt(opt) {
    m_n = arrays.number_of_vertices();
    if(m_n == 0 || arrays.number_of_faces() == 0)
      throw Invalid_input(Mesh_defect::empty_mesh, "heat method: the mesh has no vertex or no face");
    if(!arrays.V.allFinite())
      throw Invalid_input(Mesh_defect::non_finite_coordinate, "heat method: the mesh has NaN or infinite coordinates");
    Intrinsic_triangulation tri = Intrinsic_triangulation::from_arrays(arrays);
    double h = 0; // mean edge length (interior edges counted from both sides)
    for(double l : tri.length) h += l;
    h /= static_cast<double>(tri.length.size());
    if(opt.intrinsic_delaunay) m_flips = tri.make_delaunay();

    m_components = vertex_components(m_n, arrays.F, m_component);
    // per-face data in the face's own 2-D frame: area and the gradients of the three hat functions
    const std::size_t m = tri.number_of_faces();
    m_faces.resize(m);
    m_face_area.resize(m);
    m_grad.resize(m);
    for(std::size_t f = 0; f < m; ++f) {
      m_faces[f] = tri.faces[f];
      const double l01 = tri.length[3 * f], l12 = tri.length[3 * f + 1], l20 = tri.length[3 * f + 2];
      const double A = tri.area(f);
      m_face_area[f] = A;
      const auto apex = unfold_apex(l01, l20, l12);
      const std::array<Eigen::Vector2d, 3> q = {Eigen::Vector2d(0, 0), Eigen::Vector2d(l01, 0),
                                                Eigen::Vector2d(apex.first, apex.second)};
      for(int k = 0; k < 3; ++k) {
        const Eigen::Vector2d e = q[static_cast<std::size_t>((k + 2) % 3)] - q[static_cast<std::size_t>((k + 1) % 3)];
        m_grad[f][static_cast<std::size_t>(k)] = A > 0 ? Eigen::Vector2d(-e.y(), e.x()) / (2 * A) : Eigen::Vector2d(0, 0);
      }
    }
    const Eigen::SparseMatrix<double> L = cotangent_laplacian(tri);
    const Eigen::VectorXd M = lumped_mass(tri);
    const double t = opt.time_step_factor * h * h;
    m_time = t;
    // isolated vertices get the mass h^2 so both systems stay positive definite
    const Eigen::VectorXd mass = (M.array() > 0).select(M, h * h);
    const Eigen::SparseMatrix<double> Mdiag(mass.asDiagonal());
    m_heat_matrix = Mdiag + t * L;
    // Poisson: L is singular (constants per component); a tiny mass shift makes it definite and only
    // moves the solution by a constant per component, removed when distances are anchored.
    const double shift = 1e-10 * (L.diagonal().mean()) / (Mdiag.diagonal().mean());
    m_poisson_matrix = L + shift * Mdiag;
    m_threads = resolve_thread_count(opt.threads);
    m_solvers.resize(m_threads);
  }

  std::size_t number_of_vertices() const { return m_n; }
  double time_step() const { return m_time; }
  std::size_t number_of_flips() const { return m_flips; }
  unsigned number_of_threads() const { return m_threads; }

  /// Distances from each source separately: fn(first, count, block) is called once per batch with
  /// block (n x count), column j = distances from sources[first + j]. Batches run in parallel:
  /// fn must be safe to call concurrently for different batches.
  template <typename BlockFn>
  void for_each_batch(const std::vector<std::size_t>& sources, BlockFn&& fn,
                      const std::function<void(std::size_t, std::size_t)>& progress = {}) const {
    for(std::size_t s : sources) check_source(s);
    const std::size_t B = std::max<std::size_t>(1, m_opt.batch_size);
    const std::size_t nb = (sources.size() + B - 1) / B;
    std::mutex progress_mutex;
    std::size_t done = 0;
    parallel_for(nb, m_threads, [&](std::size_t b, unsigned tid) {
      const std::size_t first = b * B, count = std::min(B, sources.size() - first);
      Matrix rhs = Matrix::Zero(static_cast<Eigen::Index>(m_n), static_cast<Eigen::Index>(count));
      for(std::size_t j = 0; j < count; ++j) rhs(static_cast<Eigen::Index>(sources[first + j]), static_cast<Eigen::Index>(j)) = 1.0;
      Matrix block = solve_columns(rhs, tid);
      for(std::size_t j = 0; j < count; ++j) anchor(block.col(static_cast<Eigen::Index>(j)), &sources[first + j], 1);
      fn(first, count, block);
      if(progress) {
        std::lock_guard<std::mutex> lock(progress_mutex);
        done += count;
        progress(done, sources.size());
      }
    });
  }

  /// Distance to the nearest of `sources` (multi-source), one vector of n values.
  Eigen::VectorXd distances_to_set(const std::vector<std::size_t>& sources) const {
    if(sources.empty()) throw Invalid_argument("heat method: no source vertex given");
    for(std::size_t s : sources) check_source(s);
    Matrix rhs = Matrix::Zero(static_cast<Eigen::Index>(m_n), 1);
    for(std::size_t s : sources) rhs(static_cast<Eigen::Index>(s), 0) = 1.0;
    Matrix d = solve_columns(rhs, 0);
    Eigen::VectorXd out = d.col(0);
    anchor(out, sources.data(), sources.size());
    return out;
  }

  Eigen::VectorXd distances_from(std::size_t source) const { return distances_to_set({source}); }

private:
  void check_source(std::size_t s) const {
    if(s >= m_n)
      throw Invalid_argument("source vertex " + std::to_string(s) + " out of range (mesh has " + std::to_string(m_n) + " vertices)");
  }

  SparseSolver& solver(std::unique_ptr<SparseSolver>& slot, const Eigen::SparseMatrix<double>& A, const char* what) const {
    if(!slot) {
      auto s = std::make_unique<SparseSolver>();
      factor_or_throw(*s, A, what);
      slot = std::move(s);
    }
    return *slot;
  }

  struct Solver_pair {
    std::unique_ptr<SparseSolver> heat, poisson;
  };

  // heat diffusion, normalized gradient, divergence, Poisson; one column per source set
  Matrix solve_columns(const Matrix& rhs, unsigned tid) const {
    Solver_pair& sp = m_solvers[tid];
    {
      // factor lazily, once per thread (CHOLMOD's workspace is not shareable between threads)
      std::lock_guard<std::mutex> lock(m_factor_mutex);
      solver(sp.heat, m_heat_matrix, "heat operator M + tL");
      solver(sp.poisson, m_poisson_matrix, "cotangent Laplacian");
    }
    Matrix u = sp.heat->solve(rhs);
    if(sp.heat->info() != Eigen::Success) throw Solver_failure("heat method: heat-flow solve failed");
    Matrix div = Matrix::Zero(u.rows(), u.cols());
    const std::size_t m = m_faces.size();
    for(Eigen::Index c = 0; c < u.cols(); ++c) {
      const double* uc = u.col(c).data();
      double* dc = div.col(c).data();
      for(std::size_t f = 0; f < m; ++f) {
        const auto& F = m_faces[f];
        const auto& g = m_grad[f];
        // far from the source the heat is tiny (1e-300 is common): rescale per face before the
        // gradient so its squared norm does not underflow; only the direction is used
        const double scale = std::max(std::abs(uc[F[0]]), std::max(std::abs(uc[F[1]]), std::abs(uc[F[2]])));
        if(!(scale > 0)) continue;
        const double s = 1.0 / scale;
        const Eigen::Vector2d grad = (s * std::abs(uc[F[0]])) * g[0] + (s * std::abs(uc[F[1]])) * g[1] + (s * std::abs(uc[F[2]])) * g[2];
        const double nrm = grad.norm();
        if(!(nrm > 0)) continue;
        const Eigen::Vector2d X = -grad / nrm;
        const double A = m_face_area[f];
        dc[F[0]] += A * g[0].dot(X);
        dc[F[1]] += A * g[1].dot(X);
        dc[F[2]] += A * g[2].dot(X);
      }
    }
    Matrix phi = sp.poisson->solve(div);
    if(sp.poisson->info() != Eigen::Success) throw Solver_failure("heat method: Poisson solve failed");
    return phi;
  }

  // shift so that the sources are at distance 0 in their components; +inf in components without source
  template <typename Column>
  void anchor(Column&& phi, const std::size_t* sources, std::size_t ns) const {
    std::vector<double> shift(m_components, 0.0);
    std::vector<int> count(m_components, 0);
    for(std::size_t k = 0; k < ns; ++k) {
      const int c = m_component[sources[k]];
      shift[static_cast<std::size_t>(c)] += phi[static_cast<Eigen::Index>(sources[k])];
      ++count[static_cast<std::size_t>(c)];
    }
    const double inf = std::numeric_limits<double>::infinity();
    for(std::size_t i = 0; i < m_n; ++i) {
      const std::size_t c = static_cast<std::size_t>(m_component[i]);
      if(count[c] == 0) { phi[static_cast<Eigen::Index>(i)] = inf; continue; }
      const double d = phi[static_cast<Eigen::Index>(i)] - shift[c] / count[c];
      phi[static_cast<Eigen::Index>(i)] = d > 0 ? d : 0.0;
    }
    for(std::size_t k = 0; k < ns; ++k) phi[static_cast<Eigen::Index>(sources[k])] = 0.0;
  }

  Heat_method_options m_opt;
  std::size_t m_n = 0;
  double m_time = 0;
  std::size_t m_flips = 0, m_components = 0;
  std::vector<int> m_component;
  std::vector<std::array<int, 3>> m_faces;
  std::vector<double> m_face_area;
  std::vector<std::array<Eigen::Vector2d, 3>> m_grad;
  Eigen::SparseMatrix<double> m_heat_matrix, m_poisson_matrix;
  unsigned m_threads = 1;
  mutable std::vector<Solver_pair> m_solvers;
  mutable std::mutex m_factor_mutex;
};

} // namespace internal
} // namespace shapecorr

#endif
