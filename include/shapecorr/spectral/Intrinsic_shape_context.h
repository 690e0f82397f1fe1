// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Intrinsic_shape_context.h
/// The intrinsic shape context (ISC, Kokkinos et al. 2012): a geodesic polar histogram of a
/// pointwise descriptor (SI-HKS) around a point, made invariant to the choice of angular origin by
/// the modulus of its Fourier transform over the directions.
#ifndef SHAPECORR_SPECTRAL_INTRINSIC_SHAPE_CONTEXT_H
#define SHAPECORR_SPECTRAL_INTRINSIC_SHAPE_CONTEXT_H

#include <shapecorr/exceptions.h>
#include <shapecorr/geodesics/Fast_marching_geodesics.h>
#include <shapecorr/geodesics/average_geodesic_distance.h>
#include <shapecorr/geodesics/geodesic_diameter.h>
#include <shapecorr/internal/progress.h>
#include <shapecorr/parallel.h>
#include <shapecorr/parameters.h>
#include <shapecorr/spectral/compute_scale_invariant_heat_kernel_signature.h>

#include <Eigen/Core>
#include <Eigen/Geometry>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrSpectral
/// The intrinsic shape context (ISC) of the vertices of a mesh (Kokkinos, Bronstein, Litman and
/// Bronstein 2012; the thesis's chapter-4 baseline): around a point x, the geodesic disc of radius
/// R is cut into `number_of_rings` rings by the geodesic distance rho and `number_of_directions`
/// sectors by a geodesic polar angle theta; each bin holds the area-weighted mean of a pointwise
/// descriptor f (the SI-HKS of every vertex by default) over the bin; the histogram's arbitrary
/// angular origin is removed by keeping, per ring and per component of f, the modulus of the
/// discrete Fourier transform over the directions (frequencies 0 to directions / 2, divided by the
/// number of directions). The descriptor has `rings x (directions / 2 + 1) x dim f` values, ordered
/// ring, frequency, component; compare two with `spectral_descriptor_distance` (L2).
///
/// Construction of the coordinates, our choices where the paper leaves room:
/// - rho is the fast-marching geodesic distance from x (radius-limited march);
/// - theta comes from the discrete exponential map (Schmidt, Grimm and Wyvill 2006): x's tangent
///   frame is carried to each vertex p of the disc by the rotation taking x's normal to p's, and a
///   vertex y gets the 2-D coordinates u(y) = mean over its already placed neighbours p (nearer
///   to x) of u(p) + (y - p) in p's frame (projected to p's tangent plane, length kept), weighted
///   by 1 / |y - p|; theta = atan2(u). The Fourier modulus makes the result independent of the
///   frame's first axis and of the orientation (a mirror image has the same modulus);
/// - binning is linear ("soft"): a vertex's area share (A/3) is split between the two nearest
///   ring centres and the two nearest direction centres; x itself spreads over all directions of
///   the first ring;
/// - an empty bin (a disc of few vertices) takes the mean of its ring, an empty ring the values of
///   the ring inside it.
///
/// \tparam TriangleMesh a model of `FaceListGraph` with triangle faces
///
/// Named parameters of the constructor:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `vertex_point_map`, `vertex_index_map` | positions, 0-based indices | property maps | the mesh's |
/// | `support_length` | R, mesh units (the thesis: 20 on TOSCA) | `double` | `support_fraction` x D |
/// | `support_fraction` | R / D, D the geodesic diameter | `double` | 0.055 (20 / 360, the thesis's radius on the TOSCA centaur) |
/// | `geodesic_diameter` | D in mesh units (e.g. the whole shape's D for a part of it) | `double` | computed (farthest-point sweeps) |
/// | `number_of_rings`, `number_of_directions` | bins of rho and theta (directions even) | `std::size_t` | 5, 16 |
/// | `eigenbasis` | the basis of the SI-HKS | `const Laplace_beltrami_eigenbasis*` | computed (`number_of_eigenpairs`, default min(300, n)) |
/// | SI-HKS parameters | `log_time_base`, `log_time_range`, `log_time_step`, `time_unit`, `frequency_range` | see `compute_scale_invariant_heat_kernel_signature` | its defaults (thesis: [1, 20], [2, 20]) |
/// | `number_of_threads` | threads of the batch function | `unsigned` | all |
///
/// \throws Invalid_input for an empty mesh or non-finite coordinates; Invalid_argument for
/// parameters out of range
///
/// \code
///   const shapecorr::Intrinsic_shape_context<Mesh> isc(mesh);
///   const Eigen::MatrixXd D = isc.descriptors({0, 10, 20}); // one row per vertex
/// \endcode
template <typename TriangleMesh>
class Intrinsic_shape_context {
public:
  /// The mesh's vertex type.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// (vertex index, geodesic distance) pairs: a geodesic disc around a point.
  typedef std::vector<std::pair<std::size_t, double>> Ball;

  /// Computes the diameter (unless R or D is given), the pointwise SI-HKS of every vertex, vertex
  /// normals, areas and adjacency (named parameters above).
  template <typename NamedParameters = parameters::Default_named_parameters,
            typename = std::enable_if_t<!std::is_base_of<Eigen::EigenBase<NamedParameters>, NamedParameters>::value>>
  explicit Intrinsic_shape_context(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
    : m_engine(tm, np) {
    check_mesh();
    std::unique_ptr<Laplace_beltrami_eigenbasis> owned;
    init(np, &internal::eigenbasis_of(tm, np, owned));
  }

  /// As above with the pointwise descriptor given: row i of `signatures` is f at vertex i (index
  /// order), e.g. a WKS or HKS matrix instead of the SI-HKS.
  template <typename NamedParameters = parameters::Default_named_parameters>
  Intrinsic_shape_context(const TriangleMesh& tm, Eigen::MatrixXd signatures,
                          const NamedParameters& np = CGAL::parameters::default_values())
    : m_engine(tm, np), m_f(std::move(signatures)) {
    check_mesh();
    init(np, nullptr);
  }

  /// R, mesh units.
  double radius() const { return m_radius; }
  /// Number of rings.
  std::size_t rings() const { return m_rings; }
  /// Number of directions.
  std::size_t directions() const { return m_dirs; }
  /// Length of a descriptor: rings x (directions / 2 + 1) x dim f.
  std::size_t size() const { return m_rings * (m_dirs / 2 + 1) * std::size_t(m_f.cols()); }
  /// The pointwise descriptor f of every vertex (rows in index order).
  const Eigen::MatrixXd& signatures() const { return m_f; }
  /// Number of vertices.
  std::size_t number_of_vertices() const { return m_engine.number_of_vertices(); }
  /// The 0-based index of `v`.
  std::size_t index(vertex_descriptor v) const { return m_engine.index(v); }
  /// The fast-marching engine of the discs.
  const Fast_marching_geodesics<TriangleMesh>& geodesic_engine() const { return m_engine; }

  /// Scratch memory of one thread (a fast-marching state and per-vertex records); distinct
  /// workspaces make concurrent calls safe.
  class Workspace {
  public:
    /// A workspace for `isc`'s descriptors.
    explicit Workspace(const Intrinsic_shape_context& isc)
      : m_owner(&isc), u(isc.number_of_vertices(), Eigen::Vector2d::Zero()), frame(isc.number_of_vertices()), placed(isc.number_of_vertices(), 0),
        framed(isc.number_of_vertices(), 0) {}

  private:
    friend class Intrinsic_shape_context;
    const Intrinsic_shape_context* m_owner;
    typename Fast_marching_geodesics<TriangleMesh>::Workspace fmm;
    Ball ball;
    std::vector<Eigen::Vector2d> u;    // exponential-map coordinates
    std::vector<Eigen::Matrix<double, 3, 2>> frame; // x's frame carried to the vertex (columns: the two axes)
    std::vector<unsigned> placed;      // == stamp: u is set for this call
    std::vector<unsigned> framed;      // == stamp: frame is set for this call (not for a normal opposite to x's)
    unsigned stamp = 0;
  };

  /// The ISC of vertex v.
  Eigen::VectorXd descriptor(vertex_descriptor v, Workspace& ws) const { return descriptor_of(m_engine.index(v), own(ws)); }
  /// As above, with a workspace of its own.
  Eigen::VectorXd descriptor(vertex_descriptor v) const {
    Workspace ws(*this);
    return descriptor(v, ws);
  }
  /// The ISC of vertex i from the geodesic distances `ball` of i to the vertices around it (e.g. a
  /// row of an all-pairs matrix): every vertex within `radius()` must be in it, others may be.
  Eigen::VectorXd descriptor(std::size_t i, const Ball& ball, Workspace& ws) const { return from_ball(i, ball, own(ws)); }

  /// The ISC of many vertices (indices) in parallel, one row each; `progress(done, total)`.
  Eigen::MatrixXd descriptors(const std::vector<std::size_t>& indices,
                              const std::function<void(std::size_t, std::size_t)>& progress = {}) const {
    for(std::size_t i : indices)
      if(i >= number_of_vertices()) throw Invalid_argument("intrinsic shape context: vertex index " + std::to_string(i) + " out of range");
    Eigen::MatrixXd out(Eigen::Index(indices.size()), Eigen::Index(size()));
    const unsigned threads = m_engine.number_of_threads();
    std::vector<std::unique_ptr<Workspace>> states;
    for(unsigned t = 0; t < threads; ++t) states.emplace_back(new Workspace(*this));
    std::atomic<std::size_t> done(0);
    std::mutex report;
    parallel_for(indices.size(), threads, [&](std::size_t k, unsigned tid) {
      out.row(Eigen::Index(k)) = descriptor_of(indices[k], *states[tid]).transpose();
      const std::size_t d = ++done;
      if(progress && (d % 64 == 0 || d == indices.size())) {
        std::lock_guard<std::mutex> lock(report);
        progress(d, indices.size());
      }
    });
    return out;
  }

private:
  void check_mesh() const {
    const internal::Triangle_arrays& a = m_engine.arrays();
    if(a.number_of_vertices() == 0 || a.number_of_faces() == 0)
      throw Invalid_input(Mesh_defect::empty_mesh, "intrinsic shape context: the mesh has no vertex or no face");
    if(!a.V.allFinite()) throw Invalid_input(Mesh_defect::non_finite_coordinate, "intrinsic shape context: a vertex has a non-finite coordinate");
  }
  template <typename NamedParameters>
  void init(const NamedParameters& np, const Laplace_beltrami_eigenbasis* basis) {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    const internal::Triangle_arrays& a = m_engine.arrays();
    const std::size_t n = a.number_of_vertices();
    m_rings = choose_parameter(get_parameter(np, internal_np::number_of_rings), std::size_t(5));
    m_dirs = choose_parameter(get_parameter(np, internal_np::number_of_directions), std::size_t(16));
    if(m_rings < 1 || m_rings > 1000 || m_dirs < 2 || m_dirs > 1000 || m_dirs % 2 != 0)
      throw Invalid_argument("intrinsic shape context: need 1 to 1000 rings and an even number of directions from 2 to 1000");
    m_radius = choose_parameter(get_parameter(np, internal_np::support_length), -1.0);
    if(m_radius < 0) {
      const double fraction = choose_parameter(get_parameter(np, internal_np::support_fraction), 0.055);
      if(!(fraction > 0) || !std::isfinite(fraction)) throw Invalid_argument("intrinsic shape context: support_fraction must be positive");
      double D = choose_parameter(get_parameter(np, internal_np::geodesic_diameter), -1.0);
      if(D < 0) D = internal::diameter_by_sweeps(m_engine, internal::canonical_start_vertex(a), 6);
      m_radius = fraction * D;
    }
    if(!(m_radius > 0) || !std::isfinite(m_radius)) throw Invalid_argument("intrinsic shape context: the radius must be positive and finite");
    if(basis) m_f = scale_invariant_heat_kernel_signature_matrix(*basis, np);
    if(std::size_t(m_f.rows()) != n || m_f.cols() == 0 || !m_f.allFinite())
      throw Invalid_argument("intrinsic shape context: the pointwise descriptor needs one finite, non-empty row per vertex (" +
                             std::to_string(m_f.rows()) + " rows, " + std::to_string(n) + " vertices)");
    // vertex normals (area-weighted), area shares, neighbours
    m_normal.assign(n, Eigen::Vector3d::Zero());
    for(Eigen::Index f = 0; f < a.F.rows(); ++f) {
      const Eigen::Vector3d p = a.V.row(a.F(f, 0)), q = a.V.row(a.F(f, 1)), r = a.V.row(a.F(f, 2));
      const Eigen::Vector3d c = (q - p).cross(r - p); // twice the area along the normal
      for(int k = 0; k < 3; ++k) m_normal[std::size_t(a.F(f, k))] += c;
    }
    for(auto& v : m_normal) {
      const double l = v.norm();
      v = l > 0 ? Eigen::Vector3d(v / l) : Eigen::Vector3d::UnitZ();
    }
    m_area = internal::incident_triangle_areas(a) / 3.0;
    std::vector<std::vector<std::size_t>> adj(n);
    for(Eigen::Index f = 0; f < a.F.rows(); ++f)
      for(int k = 0; k < 3; ++k) {
        adj[std::size_t(a.F(f, k))].push_back(std::size_t(a.F(f, (k + 1) % 3)));
        adj[std::size_t(a.F(f, (k + 1) % 3))].push_back(std::size_t(a.F(f, k)));
      }
    m_adj_begin.assign(n + 1, 0);
    for(std::size_t v = 0; v < n; ++v) {
      std::sort(adj[v].begin(), adj[v].end());
      adj[v].erase(std::unique(adj[v].begin(), adj[v].end()), adj[v].end());
      m_adj_begin[v + 1] = m_adj_begin[v] + adj[v].size();
      m_adj.insert(m_adj.end(), adj[v].begin(), adj[v].end());
    }
  }

  Workspace& own(Workspace& ws) const {
    if(ws.m_owner != this) throw Invalid_argument("intrinsic shape context: a workspace of another object");
    return ws;
  }

  Eigen::VectorXd descriptor_of(std::size_t i, Workspace& ws) const {
    // (an edge beyond R: the march's vertices near R are then complete, see distances_within)
    m_engine.distances_within(i, m_radius * 1.05, ws.ball, ws.fmm);
    return from_ball(i, ws.ball, ws);
  }

  Eigen::VectorXd from_ball(std::size_t x, const Ball& given, Workspace& ws) const {
    const std::size_t n = number_of_vertices();
    if(x >= n) throw Invalid_argument("intrinsic shape context: vertex index out of range");
    Ball ball;
    ball.reserve(given.size());
    for(const auto& p : given) {
      if(p.first >= n) throw Invalid_argument("intrinsic shape context: a vertex index of the ball is out of range");
      if(p.second <= m_radius && p.first != x) ball.push_back(p);
    }
    std::sort(ball.begin(), ball.end(), [](const auto& p, const auto& q) { return p.second < q.second || (p.second == q.second && p.first < q.first); });
    if(++ws.stamp == 0) { // wrapped: clear the records
      std::fill(ws.placed.begin(), ws.placed.end(), 0u);
      std::fill(ws.framed.begin(), ws.framed.end(), 0u);
      ws.stamp = 1;
    }
    const unsigned s = ws.stamp;
    const internal::Triangle_arrays& a = m_engine.arrays();
    // x's tangent frame
    const Eigen::Vector3d nx = m_normal[x];
    const int axis = nx.cwiseAbs().minCoeff() == std::abs(nx.x()) ? 0 : nx.cwiseAbs().minCoeff() == std::abs(nx.y()) ? 1 : 2;
    const Eigen::Vector3d e1 = (Eigen::Vector3d::Unit(axis) - nx[axis] * nx).normalized(), e2 = nx.cross(e1);
    // x's frame carried to a placed vertex by the rotation taking nx to its normal, once per vertex
    // (none for a normal opposite to nx: no meaningful rotation)
    auto place = [&](std::size_t v) {
      ws.placed[v] = s;
      if(nx.dot(m_normal[v]) < -0.999) return;
      const Eigen::Quaterniond rot = Eigen::Quaterniond::FromTwoVectors(nx, m_normal[v]);
      ws.frame[v].col(0) = rot * e1;
      ws.frame[v].col(1) = rot * e2;
      ws.framed[v] = s;
    };
    ws.u[x].setZero();
    place(x);
    // the bins: weighted sums of f and their weights
    const Eigen::Index F = m_f.cols(), R = Eigen::Index(m_rings), T = Eigen::Index(m_dirs);
    Eigen::MatrixXd sum = Eigen::MatrixXd::Zero(R * T, F);
    Eigen::VectorXd mass = Eigen::VectorXd::Zero(R * T);
    auto add = [&](Eigen::Index r, Eigen::Index t, double w, std::size_t y) {
      if(w <= 0) return;
      sum.row(r * T + t) += w * m_f.row(Eigen::Index(y));
      mass[r * T + t] += w;
    };
    auto ring_split = [&](double rho, std::size_t y, double w, auto&& dir) {
      const double c = rho / m_radius * double(R) - 0.5;
      if(c <= 0) return dir(0, w, y);
      if(c >= double(R - 1)) return dir(R - 1, w, y);
      const Eigen::Index r0 = Eigen::Index(std::floor(c));
      const double f = c - double(r0);
      dir(r0, w * (1 - f), y);
      dir(r0 + 1, w * f, y);
    };
    // x: every direction of the first ring (rho = 0)
    ring_split(0.0, x, m_area[Eigen::Index(x)], [&](Eigen::Index r, double w, std::size_t y) {
      for(Eigen::Index t = 0; t < T; ++t) add(r, t, w / double(T), y);
    });
    const double pi = 3.14159265358979323846;
    for(const auto& q : ball) {
      const std::size_t y = q.first;
      const Eigen::Vector3d py = a.point(y);
      Eigen::Vector2d acc = Eigen::Vector2d::Zero();
      double wsum = 0;
      for(std::size_t k = m_adj_begin[y]; k < m_adj_begin[y + 1]; ++k) {
        const std::size_t p = m_adj[k];
        if(ws.placed[p] != s || ws.framed[p] != s) continue;
        const Eigen::Vector3d np_ = m_normal[p];
        const auto& f = ws.frame[p];
        const Eigen::Vector3d d = py - a.point(p);
        const double len = d.norm();
        if(!(len > 0)) continue;
        Eigen::Vector3d dt = d - d.dot(np_) * np_;
        const double lt = dt.norm();
        if(lt > 1e-12 * len) dt *= len / lt;
        const double w = 1.0 / len;
        acc += w * (ws.u[p] + Eigen::Vector2d(dt.dot(f.col(0)), dt.dot(f.col(1))));
        wsum += w;
      }
      if(!(wsum > 0)) continue; // no placed neighbour (a disc cut by the mesh's border): no angle
      ws.u[y] = acc / wsum;
      place(y);
      const double theta = std::atan2(ws.u[y].y(), ws.u[y].x()); // (-pi, pi]
      ring_split(q.second, y, m_area[Eigen::Index(y)], [&](Eigen::Index r, double w, std::size_t yy) {
        double c = (theta + pi) / (2 * pi) * double(T) - 0.5;
        c -= double(T) * std::floor(c / double(T));
        const Eigen::Index t0 = std::min<Eigen::Index>(Eigen::Index(std::floor(c)), T - 1);
        const double f = c - double(t0);
        add(r, t0, w * (1 - f), yy);
        add(r, (t0 + 1) % T, w * f, yy);
      });
    }
    // bin means; empty bins from their ring, empty rings from the ring inside
    Eigen::MatrixXd h(R * T, F);
    for(Eigen::Index r = 0; r < R; ++r) {
      const double ring_mass = mass.segment(r * T, T).sum();
      Eigen::RowVectorXd ring_mean = Eigen::RowVectorXd::Zero(F);
      if(ring_mass > 0) ring_mean = sum.middleRows(r * T, T).colwise().sum() / ring_mass;
      for(Eigen::Index t = 0; t < T; ++t) {
        if(mass[r * T + t] > 0) h.row(r * T + t) = sum.row(r * T + t) / mass[r * T + t];
        else if(ring_mass > 0) h.row(r * T + t) = ring_mean;
        else h.row(r * T + t) = h.row((r - 1) * T + t); // r > 0: ring 0 holds x
      }
    }
    // |DFT| over the directions, per ring and component
    const Eigen::Index K = T / 2 + 1;
    Eigen::VectorXd out(R * K * F);
    for(Eigen::Index r = 0; r < R; ++r)
      for(Eigen::Index k = 0; k < K; ++k) {
        Eigen::RowVectorXd re = Eigen::RowVectorXd::Zero(F), im = Eigen::RowVectorXd::Zero(F);
        for(Eigen::Index t = 0; t < T; ++t) {
          const double ang = -2 * pi * double(k * t) / double(T);
          re += std::cos(ang) * h.row(r * T + t);
          im += std::sin(ang) * h.row(r * T + t);
        }
        out.segment((r * K + k) * F, F) = ((re.array().square() + im.array().square()).sqrt() / double(T)).matrix().transpose();
      }
    return out;
  }

  Fast_marching_geodesics<TriangleMesh> m_engine;
  Eigen::MatrixXd m_f;
  std::size_t m_rings = 5, m_dirs = 16;
  double m_radius = 0;
  std::vector<Eigen::Vector3d> m_normal;
  Eigen::VectorXd m_area;
  std::vector<std::size_t> m_adj_begin, m_adj;
};

/// \ingroup PkgShapeCorrSpectral
/// Intrinsic shape contexts of the vertices of `vertices`, in parallel, written into `isc` (a
/// `WritablePropertyMap` from `vertex_descriptor` to `std::vector<double>`); compare them with
/// `spectral_descriptor_distance`. For several calls on one mesh build one
/// `Intrinsic_shape_context`.
/// \param np the named parameters of `Intrinsic_shape_context`, and `progress_callback`
template <typename TriangleMesh, typename VertexRange, typename DescriptorMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_intrinsic_shape_contexts(const TriangleMesh& tm, const VertexRange& vertices, DescriptorMap isc,
                                      const NamedParameters& np = CGAL::parameters::default_values()) {
  const Intrinsic_shape_context<TriangleMesh> context(tm, np);
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vs(vertices.begin(), vertices.end());
  std::vector<std::size_t> ids;
  for(auto v : vs) ids.push_back(context.index(v));
  const Eigen::MatrixXd d = context.descriptors(ids, internal::progress_of(np));
  for(std::size_t i = 0; i < vs.size(); ++i) {
    std::vector<double> row(std::size_t(d.cols()));
    for(Eigen::Index c = 0; c < d.cols(); ++c) row[std::size_t(c)] = d(Eigen::Index(i), c);
    put(isc, vs[i], row);
  }
}

} // namespace shapecorr

#endif
