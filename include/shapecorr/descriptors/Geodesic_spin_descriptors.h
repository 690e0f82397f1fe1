// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Geodesic_spin_descriptors.h
/// The Geodesic Spin Contour and the geodesic spin image (thesis chapter 4): spin coordinates
/// replaced by the isometry invariants (average geodesic distance, geodesic distance).
#ifndef SHAPECORR_DESCRIPTORS_GEODESIC_SPIN_DESCRIPTORS_H
#define SHAPECORR_DESCRIPTORS_GEODESIC_SPIN_DESCRIPTORS_H

#include <shapecorr/descriptors/Spin_contour.h>
#include <shapecorr/descriptors/Spin_image.h>
#include <shapecorr/descriptors/internal/contour_construction.h>
#include <shapecorr/descriptors/internal/spin_construction.h>
#include <shapecorr/geodesics/Fast_marching_geodesics.h>
#include <shapecorr/geodesics/average_geodesic_distance.h>
#include <shapecorr/geodesics/geodesic_diameter.h>
#include <shapecorr/parallel.h>
#include <shapecorr/internal/progress.h>
#include <shapecorr/parameters.h>

#include <Eigen/Core>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <memory>
#include <mutex>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace shapecorr {
namespace internal {

// The section policy of the Geodesic Spin Contour (see build_level_set_contour): gd (the row
// coordinate) and agd are linear inside a triangle, so the alpha range of a piece of an isoline
// gd = beta is [min, max] of agd at its points.
struct Geodesic_section {
  struct alignas(16) Vertex {
    double a, t; // agd, gd / h - 1/2 (row r lies at t = r)
  };
  typedef double Point;
  static constexpr bool linear = true; // alpha is linear along a segment: its range is that of its end points
  // The agd where gd crosses the level on the edge a b (offsets sa, sb of opposite signs), by a
  // formula symmetric in the two ends: the same bits from either face of the edge and either
  // walking direction, so that a piece's range does not depend on where its walk started. (Its
  // products have opposite signs and the denominator's terms too: no cancellation.)
  static Point cross(const Vertex& a, const Vertex& b, double sa, double sb) { return (a.a * sb - b.a * sa) / (sb - sa); }
  static Point at(const Vertex& a) { return a.a; }
  double merge_eps = 0;
  void segment(Point p, Point q, double& l, double& u) const {
    l = std::min(p, q);
    u = std::max(p, q);
  }
  void polygon(const Point* p, int np, bool, double& l, double& u) const {
    l = *std::min_element(p, p + np);
    u = *std::max_element(p, p + np);
  }
  bool keep(double&, double&) const { return true; }
  double finish(double x) const { return x; }
};

} // namespace internal

template <typename TriangleMesh>
class Geodesic_spin_descriptors;

namespace internal {
// Test access to the walk's seeding (descent seeds on a sphere, or every crossed face).
struct Geodesic_spin_descriptors_access {
  template <typename TriangleMesh>
  static void use_descent_seeds(Geodesic_spin_descriptors<TriangleMesh>& g, bool on) { g.m_descent_seeds = on; }
};

} // namespace internal

/// \ingroup PkgShapeCorrDescriptors
/// The lengths that normalize geodesic spin descriptors: beta = gd / (support_fraction x
/// `geodesic_diameter`), alpha = (agd - `agd_offset`) / `agd_scale` (mesh units). Descriptors of two
/// shapes are comparable when both use the same normalization. To match a part of a shape (or
/// any source) against a whole target, build the target's descriptors first and give the
/// source's `parameters::geodesic_spin_normalization(target.normalization())`: the part is then
/// described with the whole shape's lengths, which its own (smaller) diameter and agd range would
/// distort.
struct Geodesic_spin_normalization {
  double geodesic_diameter = 0; ///< D; 0 (the default) means "not given: compute it"
  double agd_offset = 0;        ///< subtracted from the agd
  double agd_scale = 0;         ///< divides agd - agd_offset
};

/// \ingroup PkgShapeCorrDescriptors
/// The Geodesic Spin Contour (GSC) and the geodesic spin image of the vertices of a mesh (thesis
/// chapter 4, ALGORITHMS.md): for a point P, every surface point Q gets the coordinates
/// `(alpha, beta) = (agd(Q), gd(P, Q))`, agd the average geodesic distance (global, or local
/// within radius r), gd the geodesic distance; only the geodesic disc gd <= L enters.
///
/// The contour is built as the Spin Contour (fast construction): gd and agd are taken linear in
/// each triangle; for each of `rows` isolines gd = beta_r = (r + 1/2) L / rows the alpha range of
/// each connected piece of the isoline, their union, the end points, and closing samples on
/// `columns` alpha samples. Coordinates are normalized to [0, 1] before comparing ("we normalize
/// the range of spin coordinates to [0, 1]", thesis section 4.2): **beta = gd / L, alpha =
/// (agd - offset) / scale with the range [min agd, max agd] of the mesh** by default. ALGORITHMS.md
/// chose alpha = agd / D; with the local agd (values below r = 0.15 D) that squeezes every contour
/// into a band of about 1/60 of the alpha axis (see doc/geodesic_spin_contour.md), so the range is
/// the default and `agd_offset(0).agd_scale(D)` gives the other choice. To compare a part with a
/// whole shape, give both the whole shape's normalization (`geodesic_spin_normalization`). Compare contours with
/// `contour_l1_distance` (the same function as the rigid Spin Contour), images with
/// `spin_image_correlation`.
///
/// Geodesic distances from P come from radius-limited fast marching (radius L plus the longest
/// edge, so that every triangle an isoline crosses has all its distances); the agd of all
/// vertices and the diameter are computed once at construction.
///
/// \tparam TriangleMesh a model of `FaceListGraph` with triangle faces
///
/// Named parameters of the constructor:
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `vertex_point_map`, `vertex_index_map` | positions, 0-based indices | property maps | the mesh's |
/// | `support_fraction` | L / D (0.4: see the parameter study in doc/geodesic_spin_contour.md) | `double` | 0.4 |
/// | `agd_radius_fraction` | r / D for the local agd; 0 selects the global agd | `double` | 0.15 |
/// | `number_of_sources` | global agd: furthest-point sources averaged | `std::size_t` | 100 |
/// | `geodesic_engine` | global agd: the engine of its distance fields | pointer to a `GeodesicDistanceEngine` | this object's fast marching |
/// | `geodesic_diameter` | D in mesh units (e.g. the whole shape's D for a part of it) | `double` | computed (farthest-point sweeps) |
/// | `agd_offset`, `agd_scale` | alpha = (agd - offset) / scale, mesh units | `double` | min agd, max agd - min agd (D when the agd is constant) |
/// | `geodesic_spin_normalization` | D, offset and scale at once, e.g. another object's `normalization()` (the three parameters above, when given, take precedence) | `Geodesic_spin_normalization` | computed |
/// | `image_rows`, `image_columns` | beta samples (rows), alpha samples (columns) | `std::size_t` | 64, 64 |
/// | `number_of_threads` | threads of the batch function and of the agd | `unsigned` | all |
/// | `progress_callback` | `f(done, total)` during the agd | `std::function<void(size_t, size_t)>` | none |
///
/// \throws Invalid_input for an empty mesh, non-triangle faces, non-finite coordinates or
/// parameters out of range
template <typename TriangleMesh>
class Geodesic_spin_descriptors {
public:
  /// The mesh's vertex type.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// (vertex index, geodesic distance) pairs: a geodesic ball around a point.
  typedef std::vector<std::pair<std::size_t, double>> Ball;

  template <typename NamedParameters = parameters::Default_named_parameters>
  /// Computes the diameter, the agd of every vertex and the topology tables (named parameters above).
  explicit Geodesic_spin_descriptors(const TriangleMesh& tm, const NamedParameters& np = CGAL::parameters::default_values())
    : m_engine(tm, np) {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    const internal::Triangle_arrays& a = m_engine.arrays();
    const std::size_t n = a.number_of_vertices(), m = a.number_of_faces();
    if(n == 0 || m == 0) throw Invalid_input(Mesh_defect::empty_mesh, "geodesic spin descriptors: the mesh has no vertex or no face");
    if(!a.V.allFinite()) throw Invalid_input(Mesh_defect::non_finite_coordinate, "geodesic spin descriptors: a vertex has a non-finite coordinate");
    const double support_fraction = choose_parameter(get_parameter(np, internal_np::support_fraction), 0.4);
    const double radius_fraction = choose_parameter(get_parameter(np, internal_np::agd_radius_fraction), 0.15);
    m_rows = choose_parameter(get_parameter(np, internal_np::image_rows), std::size_t(64));
    m_cols = choose_parameter(get_parameter(np, internal_np::image_columns), std::size_t(64));
    if(!(support_fraction > 0) || !std::isfinite(support_fraction))
      throw Invalid_argument("geodesic spin descriptors: support_fraction must be positive");
    if(!(radius_fraction >= 0) || !std::isfinite(radius_fraction))
      throw Invalid_argument("geodesic spin descriptors: agd_radius_fraction must be >= 0 (0: global agd)");
    if(m_rows < 2 || m_cols < 1)
      throw Invalid_argument("geodesic spin descriptors: need at least 2 rows and 1 column");
    const Geodesic_spin_normalization imposed =
        choose_parameter(get_parameter(np, internal_np::geodesic_spin_normalization), Geodesic_spin_normalization());
    const bool normalized = imposed.geodesic_diameter != 0;
    m_diameter = choose_parameter(get_parameter(np, internal_np::geodesic_diameter), normalized ? imposed.geodesic_diameter : -1.0);
    if(m_diameter < 0) m_diameter = internal::diameter_by_sweeps(m_engine, internal::canonical_start_vertex(a), 6);
    if(!(m_diameter > 0) || !std::isfinite(m_diameter))
      throw Invalid_argument("geodesic spin descriptors: the geodesic diameter is zero or not finite");
    m_support = support_fraction * m_diameter;
    m_radius = radius_fraction * m_diameter;
    // the average geodesic distance of every vertex
    if(m_radius > 0) {
      m_agd = internal::local_average_geodesic_distances(m_engine, m_radius, internal::progress_of(np));
    } else {
      m_agd.assign(n, 0.0);
      // with this object's fast-marching engine unless the caller gave an engine of their own
      if constexpr(std::is_same<decltype(get_parameter(np, internal_np::geodesic_engine)), CGAL::internal_np::Param_not_found>::value)
        compute_average_geodesic_distance(tm, Agd_writer{&m_agd, &m_engine},
                                          shapecorr::Named_function_parameters<const Fast_marching_geodesics<TriangleMesh>*, internal_np::geodesic_engine_t, NamedParameters>(&m_engine, np));
      else
        compute_average_geodesic_distance(tm, Agd_writer{&m_agd, &m_engine}, np);
    }
    // alpha = (agd - offset) / scale: by default the range of the agd over the mesh maps to [0, 1]
    const auto range = std::minmax_element(m_agd.begin(), m_agd.end());
    m_alpha_offset = choose_parameter(get_parameter(np, internal_np::agd_offset), normalized ? imposed.agd_offset : *range.first);
    const double spread = *range.second - *range.first;
    // a (numerically) constant agd, e.g. a local radius smaller than every edge: scale by D
    m_alpha_scale = choose_parameter(get_parameter(np, internal_np::agd_scale),
                                     normalized ? imposed.agd_scale : spread > 1e-9 * m_diameter ? spread : m_diameter);
    if(!(m_alpha_scale > 0) || !std::isfinite(m_alpha_scale) || !std::isfinite(m_alpha_offset))
      throw Invalid_argument("geodesic spin descriptors: agd_scale must be positive and agd_offset finite");
    // topology: faces with their neighbours; each face listed once, under its corner of smallest
    // index (its owner); the longest edge
    m_links = internal::build_face_links(a);
    m_half_edges = internal::build_half_edge_links(m_links);
    m_owned_begin.assign(n + 1, 0);
    auto owner = [&](std::size_t f) { return static_cast<std::size_t>(std::min({m_links[f].v[0], m_links[f].v[1], m_links[f].v[2]})); };
    for(std::size_t f = 0; f < m; ++f) ++m_owned_begin[owner(f) + 1];
    for(std::size_t v = 0; v < n; ++v) m_owned_begin[v + 1] += m_owned_begin[v];
    m_owned.assign(m + kOwnedCopy, 0u); // padded: the disc's face list copies kOwnedCopy entries per vertex
    std::vector<std::uint32_t> next(m_owned_begin.begin(), m_owned_begin.end() - 1);
    double longest = 0;
    for(std::size_t f = 0; f < m; ++f) {
      m_owned[next[owner(f)]++] = static_cast<std::uint32_t>(f);
      for(int k = 0; k < 3; ++k)
        longest = std::max(longest, (a.point(static_cast<std::size_t>(m_links[f].v[k])) - a.point(static_cast<std::size_t>(m_links[f].v[(k + 1) % 3]))).norm());
    }
    m_ball_radius = m_support + 1.01 * longest;
    // the row coordinate of the vertices outside a ball: above every row and every vertex of the ball
    m_outside_t = static_cast<double>(m_rows) * (m_ball_radius / m_support) + 2.0;
    m_sphere = internal::is_topological_sphere(m_links, n);
    if(m_sphere) m_stars = internal::build_vertex_stars(m_links, n);
    // A(Q)/3: the share of a vertex in the area (the geodesic spin image's weights)
    const Eigen::VectorXd A = internal::incident_triangle_areas(a);
    m_vertex_area.resize(n);
    for(std::size_t v = 0; v < n; ++v) m_vertex_area[v] = A[static_cast<Eigen::Index>(v)] / 3.0;
    m_threads = m_engine.number_of_threads();
  }

  /// Geodesic diameter D (mesh units).
  double geodesic_diameter() const { return m_diameter; }
  /// Support length L (mesh units).
  double support_length() const { return m_support; }
  /// Radius r of the local agd (mesh units); 0 for the global agd.
  double agd_radius() const { return m_radius; }
  /// The alpha normalization alpha = (agd - alpha_offset()) / alpha_scale() (mesh units).
  double alpha_scale() const { return m_alpha_scale; }
  /// (see `alpha_scale`)
  double alpha_offset() const { return m_alpha_offset; }
  /// D, the alpha offset and the alpha scale together: give them to the descriptors of another
  /// shape (`parameters::geodesic_spin_normalization`) to make the two comparable.
  Geodesic_spin_normalization normalization() const { return {m_diameter, m_alpha_offset, m_alpha_scale}; }
  /// Number of rows (beta = gd samples).
  std::size_t rows() const { return m_rows; }
  /// Number of columns (alpha samples).
  std::size_t columns() const { return m_cols; }
  /// Number of vertices of the mesh.
  std::size_t number_of_vertices() const { return m_engine.number_of_vertices(); }
  /// The 0-based index of `v`.
  std::size_t index(vertex_descriptor v) const { return m_engine.index(v); }
  /// The vertex of index `i`.
  vertex_descriptor vertex(std::size_t i) const { return m_engine.vertex(i); }
  /// The average geodesic distance of every vertex (engine's index order), mesh units.
  const std::vector<double>& average_geodesic_distances() const { return m_agd; }
  /// The fast-marching engine (also usable for other distance queries).
  const Fast_marching_geodesics<TriangleMesh>& geodesic_engine() const { return m_engine; }
  /// Whether the mesh is a topological sphere (closed, connected, manifold, genus 0). On one, a
  /// contour's walk along the isolines starts from a few seeds per row found by steepest descent
  /// (see doc/geodesic_spin_contour.md) instead of every face an isoline crosses, when the ball
  /// allows it (one minimum, no vertex exactly on a row, complete); the contours are the same.
  bool is_topological_sphere() const { return m_sphere; }

  /// Scratch memory of one thread's descriptor computations on this object: records of every
  /// vertex of the mesh (about 64 bytes each) and a fast-marching state. The member functions that
  /// take a `Workspace` may run concurrently, each thread with its own; those without one share
  /// a workspace of the object's, one call at a time. Hold one per thread to compute many
  /// descriptors in parallel (as the batch functions do).
  /// \code
  ///   Geodesic_spin_descriptors<Mesh>::Workspace ws(gsd);   // in each thread
  ///   for(auto v : my_vertices) contours.push_back(gsd.geodesic_spin_contour(v, ws));
  /// \endcode
  class alignas(64) Workspace { // (a cache line of its own: workspaces of two threads side by side in a vector must not share one)
  public:
    /// A workspace for `gsd`'s descriptors (only: using it with another object throws).
    explicit Workspace(const Geodesic_spin_descriptors& gsd) : m_owner(&gsd) { gsd.reset(*this); }

  private:
    friend class Geodesic_spin_descriptors;
    const Geodesic_spin_descriptors* m_owner;
    typename Fast_marching_geodesics<TriangleMesh>::Workspace fmm;
    Ball ball;
    internal::Contour_workspace<internal::Geodesic_section::Vertex> cws;
    std::vector<std::uint32_t> faces; // the disc's faces
    std::vector<float> tf;            // per vertex: the row coordinate t in float (the descent seeds read it)
  };

  /// The geodesic ball of vertex i that the descriptors need (radius L plus the longest edge).
  void support_ball(std::size_t i, Ball& ball) const { m_engine.distances_within(i, m_ball_radius, ball); }
  /// As above, with a workspace of the caller's (concurrent calls with distinct workspaces are safe).
  void support_ball(std::size_t i, Ball& ball, Workspace& ws) const { m_engine.distances_within(i, m_ball_radius, ball, own(ws).fmm); }
  /// The radius `support_ball` marches to: distances given to the `Ball` overloads must cover it.
  double support_ball_radius() const { return m_ball_radius; }

  /// The Geodesic Spin Contour of vertex v.
  Spin_contour geodesic_spin_contour(vertex_descriptor v, Workspace& ws) const { return contour_of(m_engine.index(v), own(ws)); }
  /// As above, with the object's shared workspace (one call at a time).
  Spin_contour geodesic_spin_contour(vertex_descriptor v) const {
    return with_shared_workspace([&](Workspace& ws) { return geodesic_spin_contour(v, ws); });
  }
  /// The Geodesic Spin Contour from the geodesic distances of a point to the vertices of
  /// `ball` (for instance a row of an all-pairs matrix; every vertex within
  /// `support_ball_radius()` must be in it, others may be).
  Spin_contour geodesic_spin_contour(const Ball& ball, Workspace& ws) const { return contour_from(ball, own(ws)); }
  /// As above, with the object's shared workspace (one call at a time).
  Spin_contour geodesic_spin_contour(const Ball& ball) const {
    return with_shared_workspace([&](Workspace& ws) { return geodesic_spin_contour(ball, ws); });
  }
  /// The geodesic spin image of vertex v: rows over beta = gd in [0, L] (row 0 at gd = 0),
  /// columns over alpha = agd in [0, alpha_scale()], each vertex of the disc splatted bilinearly
  /// with weight A(Q)/3.
  Spin_image geodesic_spin_image(vertex_descriptor v, Workspace& ws) const {
    support_ball(m_engine.index(v), ws.ball, ws);
    return image_from(ws.ball);
  }
  /// As above, with the object's shared workspace (one call at a time).
  Spin_image geodesic_spin_image(vertex_descriptor v) const {
    return with_shared_workspace([&](Workspace& ws) { return geodesic_spin_image(v, ws); });
  }
  /// The geodesic spin image from the distances of a ball (no workspace needed).
  Spin_image geodesic_spin_image(const Ball& ball) const { return image_from(ball); }

  /// The contours of many vertices (engine indices) in parallel; `progress(done, total)`.
  std::vector<Spin_contour> geodesic_spin_contours(const std::vector<std::size_t>& indices,
                                                   const std::function<void(std::size_t, std::size_t)>& progress = {}) const {
    return for_each_index<Spin_contour>(indices, [&](std::size_t i, Workspace& ws) { return contour_of(i, ws); }, progress);
  }
  /// The images of many vertices (engine indices) in parallel.
  std::vector<Spin_image> geodesic_spin_images(const std::vector<std::size_t>& indices,
                                               const std::function<void(std::size_t, std::size_t)>& progress = {}) const {
    return for_each_index<Spin_image>(indices, [&](std::size_t i, Workspace& ws) {
      support_ball(i, ws.ball, ws);
      return image_from(ws.ball);
    }, progress);
  }

private:
  // writes the global agd into m_agd by the engine's vertex indices
  struct Agd_writer {
    std::vector<double>* agd;
    const Fast_marching_geodesics<TriangleMesh>* engine;
    friend void put(const Agd_writer& w, vertex_descriptor v, double x) { (*w.agd)[w.engine->index(v)] = x; }
  };
  friend struct internal::Geodesic_spin_descriptors_access;
  static constexpr std::size_t kOwnedCopy = 8;
  // Sizes a new workspace for this object and puts every vertex outside any ball.
  void reset(Workspace& ws) const {
    const std::size_t n = number_of_vertices();
    ws.cws.resize(n);
    ws.tf.resize(n);
    ws.faces.assign(m_links.size() + kOwnedCopy, 0u);
    for(std::size_t v = 0; v < n; ++v) unset(ws, v);
  }
  Workspace& own(Workspace& ws) const {
    if(ws.m_owner != this) throw Invalid_argument("geodesic spin descriptors: a workspace of another object");
    return ws;
  }
  // fn(ws) with the object's own workspace, one call at a time.
  template <typename Fn>
  decltype(auto) with_shared_workspace(Fn&& fn) const {
    std::lock_guard<std::mutex> lock(m_shared_mutex);
    if(!m_shared) m_shared.reset(new Workspace(*this));
    return fn(*m_shared);
  }
  // A vertex outside the ball: beyond the last row and every vertex of a ball.
  // (rows: unless the contour left them untouched, as the descent seeds do)
  void unset(Workspace& st, std::size_t v, bool rows = true) const {
    st.cws.vx[v] = {0.0, m_outside_t};
    st.tf[v] = static_cast<float>(m_outside_t);
    if(rows) st.cws.rows[v] = {{static_cast<int>(m_rows), static_cast<int>(m_rows)}}; // set_rows of that t
  }
  Spin_contour contour_of(std::size_t i, Workspace& st) const {
    support_ball(i, st.ball, st);
    return contour_from(st.ball, st);
  }
  Spin_contour contour_from(const Ball& ball, Workspace& st) const {
    const std::size_t R = m_rows;
    const double inv_h = static_cast<double>(R) / m_support;
    const std::size_t n = number_of_vertices();
    internal::Geodesic_section sec;
    sec.merge_eps = 1e-12 * m_alpha_scale;
    Spin_contour c(R, m_support, 0.0, 1.0);
    // (checked first: the records must not be left set by a ball rejected half-way)
    for(const auto& p : ball)
      if(p.first >= n) throw Invalid_argument("geodesic spin contour: a vertex index of the ball is out of range");
    for(const auto& p : ball) {
      const double t = p.second * inv_h - 0.5;
      st.cws.vx[p.first] = {m_agd[p.first] - m_alpha_offset, t};
      st.tf[p.first] = static_cast<float>(t);
    }
    // The walk's seeds: by descent on a topological sphere (a few per row), else every face an
    // isoline crosses.
    const bool by_descent = m_sphere && m_descent_seeds &&
                            internal::seed_rows_by_descent(m_stars, st.tf.data(), ball, R, m_outside_t, st.cws);
    if(!by_descent) {
      // Every face an isoline crosses has a corner inside the disc, hence all its corners in the
      // ball (radius L + the longest edge), its owner among them: the faces owned by the ball's
      // vertices, each once. Listed without a data-dependent loop per vertex (most own 0 to 4
      // faces): a fixed block is copied and the end advances by the count.
      std::size_t nf = 0;
      std::uint32_t* faces = st.faces.data();
      for(const auto& p : ball) {
        st.cws.set_rows(p.first, st.cws.vx[p.first].t, R);
        const std::uint32_t b = m_owned_begin[p.first], e = m_owned_begin[p.first + 1];
        if(nf + kOwnedCopy + (e - b) > st.faces.size()) { // only when the ball lists a vertex twice
          st.faces.resize(2 * st.faces.size());
          faces = st.faces.data();
        }
        std::copy(m_owned.data() + b, m_owned.data() + b + kOwnedCopy, faces + nf);
        if(e - b > kOwnedCopy) std::copy(m_owned.data() + b + kOwnedCopy, m_owned.data() + e, faces + nf + kOwnedCopy);
        nf += e - b;
      }
      internal::seed_rows_by_faces(m_engine.arrays().F.data(), R, [&](auto&& visit) {
        for(std::size_t k = 0; k < nf; ++k) visit(faces[k]);
      }, st.cws);
    }
    internal::walk_level_sets(m_links, m_half_edges, sec, R, m_cols, m_alpha_scale, st.cws, c);
    for(const auto& p : ball) unset(st, p.first, !by_descent);
    return c;
  }
  Spin_image image_from(const Ball& ball) const {
    Spin_image img(m_rows, m_cols, m_support);
    for(const auto& p : ball) {
      if(p.first >= number_of_vertices()) throw Invalid_argument("geodesic spin image: a vertex index of the ball is out of range");
      if(!(p.second <= m_support)) continue;
      internal::splat_bilinear(img, (m_agd[p.first] - m_alpha_offset) / m_alpha_scale * static_cast<double>(m_cols) - 0.5,
                               p.second / m_support * static_cast<double>(m_rows) - 0.5, m_vertex_area[p.first]);
    }
    return img;
  }
  template <typename Descriptor, typename Fn>
  std::vector<Descriptor> for_each_index(const std::vector<std::size_t>& indices, Fn&& fn,
                                         const std::function<void(std::size_t, std::size_t)>& progress) const {
    for(std::size_t i : indices)
      if(i >= number_of_vertices()) throw Invalid_argument("geodesic spin descriptors: vertex index " + std::to_string(i) + " out of range");
    std::vector<Descriptor> out(indices.size());
    std::vector<Workspace> states;
    states.reserve(m_threads);
    for(unsigned t = 0; t < m_threads; ++t) states.emplace_back(*this);
    std::atomic<std::size_t> done(0);
    std::mutex report;
    parallel_for(indices.size(), m_threads, [&](std::size_t k, unsigned tid) {
      out[k] = fn(indices[k], states[tid]);
      const std::size_t d = ++done;
      if(progress && (d % 64 == 0 || d == indices.size())) {
        std::lock_guard<std::mutex> lock(report);
        progress(d, indices.size());
      }
    });
    return out;
  }

  Fast_marching_geodesics<TriangleMesh> m_engine;
  std::size_t m_rows = 64, m_cols = 64;
  double m_diameter = 0, m_support = 0, m_radius = 0, m_alpha_scale = 0, m_alpha_offset = 0, m_ball_radius = 0, m_outside_t = 0;
  std::vector<double> m_agd, m_vertex_area;
  std::vector<internal::Face_link> m_links;
  std::vector<internal::Half_edge_link> m_half_edges;
  std::vector<std::uint32_t> m_owned_begin, m_owned; // faces by their corner of smallest index
  bool m_sphere = false;       // a topological sphere: the walk can be seeded by descent
  bool m_descent_seeds = true; // false: seed from every crossed face also on a sphere (tests compare the two)
  internal::Vertex_stars m_stars; // on a sphere
  unsigned m_threads = 1;
  mutable std::mutex m_shared_mutex;
  mutable std::unique_ptr<Workspace> m_shared; // of the calls without a workspace
};

namespace internal {
// `batch(gs, ids)` (one of the batch members) for the vertices of a range, written into a map.
template <typename TriangleMesh, typename VertexRange, typename DescriptorMap, typename NamedParameters, typename Batch>
void geodesic_descriptors_for_vertices(const TriangleMesh& tm, const VertexRange& vertices, DescriptorMap map, const NamedParameters& np,
                                       Batch&& batch) {
  const Geodesic_spin_descriptors<TriangleMesh> gs(tm, np);
  std::vector<typename boost::graph_traits<TriangleMesh>::vertex_descriptor> vs(vertices.begin(), vertices.end());
  std::vector<std::size_t> ids;
  for(auto v : vs) ids.push_back(gs.index(v));
  const auto d = batch(gs, ids, progress_of(np));
  for(std::size_t i = 0; i < vs.size(); ++i) put(map, vs[i], d[i]);
}
} // namespace internal

/// \ingroup PkgShapeCorrDescriptors
/// Geodesic Spin Contours of the vertices of `vertices`, in parallel, written into `contours` (a
/// `WritablePropertyMap` from `vertex_descriptor` to `Spin_contour`); compare them with
/// `contour_l1_distance`. For several calls on one mesh build one `Geodesic_spin_descriptors`.
/// \param np the named parameters of `Geodesic_spin_descriptors`, and `progress_callback`
template <typename TriangleMesh, typename VertexRange, typename DescriptorMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_geodesic_spin_contours(const TriangleMesh& tm, const VertexRange& vertices, DescriptorMap contours,
                                    const NamedParameters& np = CGAL::parameters::default_values()) {
  internal::geodesic_descriptors_for_vertices(tm, vertices, contours, np, [](const auto& gs, const auto& ids, const auto& progress) {
    return gs.geodesic_spin_contours(ids, progress);
  });
}

/// \ingroup PkgShapeCorrDescriptors
/// Geodesic spin images of the vertices of `vertices`, as `compute_geodesic_spin_contours`.
template <typename TriangleMesh, typename VertexRange, typename DescriptorMap, typename NamedParameters = parameters::Default_named_parameters>
void compute_geodesic_spin_images(const TriangleMesh& tm, const VertexRange& vertices, DescriptorMap images,
                                  const NamedParameters& np = CGAL::parameters::default_values()) {
  internal::geodesic_descriptors_for_vertices(tm, vertices, images, np, [](const auto& gs, const auto& ids, const auto& progress) {
    return gs.geodesic_spin_images(ids, progress);
  });
}

} // namespace shapecorr

#endif
