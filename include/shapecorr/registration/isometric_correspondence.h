// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file isometric_correspondence.h
/// Fully automatic near-isometric registration (thesis chapter 5; ALGORITHMS.md): from two meshes
/// and nothing else, sparse correspondences by furthest point sampling, descriptor trimming, the
/// coarse matching program, local optimization and coarse-to-fine refinement; then a dense map.
#ifndef SHAPECORR_REGISTRATION_ISOMETRIC_CORRESPONDENCE_H
#define SHAPECORR_REGISTRATION_ISOMETRIC_CORRESPONDENCE_H

#include <shapecorr/descriptors/Geodesic_spin_descriptors.h>
#include <shapecorr/descriptors/match_descriptors.h>
#include <shapecorr/exceptions.h>
#include <shapecorr/geodesics/Fast_marching_geodesics.h>
#include <shapecorr/internal/components.h>
#include <shapecorr/internal/furthest_point_order.h>
#include <shapecorr/internal/progress.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/parameters.h>
#include <shapecorr/registration/feature_matching.h>
#include <shapecorr/registration/internal/orientation.h>
#include <shapecorr/spectral/Intrinsic_shape_context.h>
#include <shapecorr/spectral/Laplace_beltrami_eigenbasis.h>
#include <shapecorr/spectral/compute_wave_kernel_signature.h>
#include <shapecorr/spectral/spectral_descriptor_distance.h>

#include <CGAL/GLPK_mixed_integer_program_traits.h>
#include <CGAL/Polygon_mesh_processing/locate.h>

#include <Eigen/Core>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <limits>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrRegistration
/// The descriptor that trims the candidate pairs of the coarse program (named parameter
/// `trim_descriptor`).
enum class Trim_descriptor {
  GEODESIC_SPIN_CONTOUR,  ///< Geodesic Spin Contours compared by L1 (the thesis's choice)
  WAVE_KERNEL_SIGNATURE,  ///< wave kernel signatures (100 energies on 100 eigenpairs) compared by L2
  INTRINSIC_SHAPE_CONTEXT ///< intrinsic shape contexts (`Intrinsic_shape_context`, its defaults, SI-HKS on 100 eigenpairs) compared by L2
};

/// \ingroup PkgShapeCorrRegistration
/// The solver of the coarse matching program (named parameter `coarse_solver`).
enum class Coarse_solver {
  BRANCH_AND_BOUND,     ///< `solve_coarse_matching_branch_and_bound` (no external solver; bounded by `maximum_nodes`)
  MIXED_INTEGER_PROGRAM ///< `solve_coarse_matching_mip` with the class's `MipTraits` (default GLPK)
};

/// \ingroup PkgShapeCorrRegistration
/// The orientation of a map between two oriented surfaces (named parameter `orientation`).
/// An orientation-preserving map (a *direct* map) takes a counter-clockwise turn around a point,
/// seen from outside (the side the faces' orientation defines), to a counter-clockwise turn; an
/// orientation-reversing one is a mirror (left hand onto right hand). Bilateral shapes have both,
/// at nearly the same geodesic distortion: intrinsic distances cannot tell them apart.
enum class Map_orientation {
  PRESERVING, ///< a direct map (the default: what transferring a texture, a label, a landmark needs)
  REVERSING,  ///< the mirror map
  ANY         ///< whichever has the lowest distortion (the thesis's method)
};

/// \ingroup PkgShapeCorrRegistration
/// A sparse correspondence between a source vertex and a target vertex (0-based indices of the
/// vertex index maps), found at `level` (0: the coarse program, 1, 2, ...: refinement levels).
struct Vertex_match {
  std::size_t source = 0; ///< source vertex index
  std::size_t target = 0; ///< target vertex index
  std::size_t level = 0;  ///< level that found it (0: the coarse program)
};

/// \ingroup PkgShapeCorrRegistration
/// What one level of the method did.
struct Isometric_level_record {
  std::size_t level = 0;             ///< 0: coarse
  std::size_t source_features = 0;   ///< features added on the source at this level
  std::size_t target_features = 0;   ///< on the target
  std::size_t candidates = 0;        ///< candidate pairs (coarse level: after trimming; refinement: all pairs)
  std::size_t candidates_per_feature = 0; ///< coarse level: the k of the k-best trimming, after widening
  std::size_t new_matches = 0;       ///< pairs chosen at this level
  double objective = 0;              ///< coarse: the distortion of Eq. 5.2; refinement: the assignment cost of Eq. 5.4
  bool optimal = false;              ///< the matching is proven optimal
  std::size_t nodes = 0;             ///< branch-and-bound nodes (coarse level)
  std::vector<double> energies;      ///< E of Eq. 5.3 over all matches: before local optimization, then after each sweep
  std::vector<std::vector<Vertex_match>> snapshots; ///< all matches before local optimization, then after each sweep
  double orientation_score = 0;      ///< coarse level: the triple orientation score of the program's matching (see the class description)
  bool orientation_met = true;       ///< coarse level: the program's matching has the orientation asked for (always true for `ANY`)
  std::size_t orientation_tests = 0; ///< coarse level: matchings whose orientation was tested
  double matching_seconds = 0;       ///< sampling, trimming and solving
  double local_seconds = 0;          ///< local optimization
};

/// \ingroup PkgShapeCorrRegistration
/// The result of `compute_isometric_correspondences()`.
struct Isometric_correspondence_report {
  std::vector<Vertex_match> matches;          ///< the sparse correspondences
  std::vector<Isometric_level_record> levels; ///< one per level
  double descriptor_seconds = 0;              ///< trimming descriptors
  double dense_seconds = 0;                   ///< the dense map
  std::size_t starts = 1;                     ///< first vertices tried by `run()`
  unsigned chosen_seed = 0;                   ///< the seed of the start `run()` kept
  Map_orientation requested_orientation = Map_orientation::PRESERVING; ///< the `orientation` asked for
  /// The orientation of the map returned: `PRESERVING` when `orientation_score` > 0, else `REVERSING`.
  Map_orientation orientation = Map_orientation::PRESERVING;
  /// How sure, in [−1, 1]: the **orientation agreement** of the map. Over the source triangles
  /// whose corners go to three distinct target vertices, the area-weighted mean of the sign of
  /// (image triangle's normal) · (the target's normals at its corners): +1 every triangle keeps
  /// its turning sense, −1 every one is flipped (a mirror), near 0 undecided (a map that folds).
  /// After `compute_dense_map()` this is the dense map's, over every source triangle; before,
  /// the coarse matches' triple orientation score (see the class description).
  /// Measured on TOSCA pairs: 0.5 to 0.8 for right maps, −0.4 to −0.8 for mirrored ones.
  double orientation_score = 0;
  /// With `keep_largest_component`: the source vertices off its largest component (each mapped
  /// as the nearest vertex on it).
  std::size_t source_vertices_dropped = 0;
  /// With `keep_largest_component`: the target vertices off its largest component (never an image).
  std::size_t target_vertices_dropped = 0;
};

/// \ingroup PkgShapeCorrRegistration
/// Fully automatic near-isometric registration of a source and a target mesh, stage by stage
/// (thesis chapter 5). `run()` does every stage; tests and users who want to stop early or look
/// in between call the stages themselves, in this order:
/// 1. `sample_features()`: furthest point sampling (fast-marching geodesics) of `number_of_features`
///    (10) features per shape, from a vertex drawn with `random_seed`;
/// 2. `trim()`: candidate pairs by descriptor distance. A fixed threshold can leave the program
///    without a solution (the thesis warns), so the candidates are each feature's k nearest on the
///    other shape, both ways (k = `number_of_candidates`, 3), **k widened one by one until a
///    one-to-one matching of n̂ pairs exists**: the program is always feasible;
/// 3. `solve_coarse()`: the program of Eq. 5.2 (`feature_matching.h`), n̂ = ⌊`match_fraction` (0.8)
///    · min(|s|, |t|)⌋, by the dedicated branch and bound (default) or the MIP solver;
/// 4. `optimize_locally()`: Eq. 5.3, E = Σ (g(s_i, s_j) − g(t_k, t_l))² over pairs of matches.
///    Features of one side move, one at a time, to the vertex of lowest E within the step (the
///    gradient step of the thesis, taken as the best vertex of the step's disc; see Scale), until
///    a sweep improves nothing or after `local_optimization_iterations` (30) sweeps; then the
///    other side. Each move costs one single-source fast marching;
/// 5. `refine()`: one level: `features_per_level` (20) new furthest-point features per shape, the
///    assignment of Eq. 5.4 (cost of (i, k): Σ over matches (j, l) of |g(s_i, s_j) − g(t_k, t_l)|,
///    solved exactly by `solve_assignment`), then local optimization; `number_of_levels` (3) times;
/// 6. `compute_dense_map()` (beyond the thesis): each source vertex goes to the target vertex
///    nearest in **geodesic coordinates** (the vector of its distances to the matched features:
///    isometry-invariant, defined on partial shapes), then **spectral upsampling** on
///    Laplace–Beltrami bases (as ZoomOut, Melzi et al. 2019: the functional map of the current
///    map in k eigenfunctions, and back to a map by nearest neighbours in the spectral embedding,
///    k from 20 to `number_of_eigenpairs` (60) by 5; 0 disables it, e.g. for a part of a shape;
///    each source vertex's spectral row is matched to the target rows carried by the functional map).
///
/// **Orientation** (beyond the thesis; Ren et al. 2018 make the same point for functional maps):
/// on bilateral shapes the mirror configuration has nearly the distortion of the right one, and
/// geodesic distances cannot tell them apart; the faces' orientation can. For each triple of
/// coarse features, the vertex x minimizing the largest of their three distances (the triple's
/// centre, defined by distances alone) sees them turn one way: `n_x · (g_a × g_b + g_b × g_c +
/// g_c × g_a)`, g the unit gradients of the features' distance fields at x, keeps its sign under
/// an orientation-preserving isometry and flips under a reflection. With `orientation`
/// `PRESERVING` (default) or `REVERSING`, the coarse program accepts only a matching whose
/// orientation score (the correlation of these signed areas between the shapes over its triples,
/// in [−1, 1]) is above 0.25 (below −0.25): the branch and bound returns the best accepted
/// matching; the MIP solver is called again with the rejected answer cut off, at most 32 times.
/// `run()` keeps the best start whose matches still have the orientation after local
/// optimization; refinement and the dense map follow the coarse level. When no matching of the
/// orientation asked for is found (within the work bound), the best one is kept and
/// `orientation_met` is false. Both meshes must be consistently oriented (the orientation is
/// relative to their faces').
///
/// **Scale**: every geodesic distance is divided by the square root of its shape's area, so
/// shapes of different sizes (a near-isometry up to scale, or a stretched pair) compare, and the
/// local optimization's step is 0.03 √area (at least two mean edge lengths): the same region of
/// the shape at any resolution.
///
/// **Several starts** (beyond the thesis): `run()` does stages 1 to 4 from `number_of_starts` (3)
/// first vertices (seeds `random_seed`, `random_seed` + 1, ...) and goes on with the coarse
/// level of lowest energy E after local optimization. The furthest-point features depend on the
/// first vertex where a shape has no clear extremities (a round body), and the program's optimum
/// on features that do not correspond can be a wrong configuration; local optimization moves the
/// features of a right configuration to where they correspond (E near 0 for an isometry) but
/// cannot repair a wrong one. A heuristic: a low E is not a proof.
///
/// **Limitations** (measured on the generated creature, `make_creature`: a round body with five
/// limbs). An exact isometric copy, renumbered, is matched from every start. With the longest limb
/// bent by 40 degrees and the vertices renumbered, the coarse level kept a wrong configuration for
/// each of seeds 0 to 3 (matches 30 edge lengths away): half the features lie on the round body,
/// where a rotation is nearly an isometry, and after local optimization the wrong configurations'
/// energy (0.04 to 0.17) is no higher than the right one's (0.10, found with another choice of the
/// first vertex); with the same numbering (the same first
/// vertex on both shapes) 7 of 8 seeds were right with one start and 8 of 8 with three. Between a
/// coarse and a finer triangulation of the same creature (642 and 2562 vertices) most starts
/// failed: fast-marching distances on the coarse mesh are longer, and the distortion of the right
/// configuration exceeds that of wrong ones. Shapes with boundaries are accepted, but the creature
/// with one limb tip cut off, onto the whole renumbered creature, failed for seeds 0 to 3. The method wants shapes with distinct extremities
/// (which furthest point sampling finds in the same order on both) at similar resolutions.
///
/// \tparam TriangleMesh a model of `FaceListGraph` with triangle faces, one connected component
/// \tparam MipTraits a model of CGAL's `MixedIntegerProgramTraits` for `Coarse_solver::MIXED_INTEGER_PROGRAM`
///
/// Named parameters (the algorithm's are read from the first set; each set also carries its
/// mesh's `vertex_point_map` and `vertex_index_map`):
/// | name | meaning | type | default |
/// |---|---|---|---|
/// | `number_of_features` | coarse features per shape | `std::size_t` | 10 |
/// | `number_of_levels` | refinement levels | `std::size_t` | 3 |
/// | `features_per_level` | new features per shape and level | `std::size_t` | 20 |
/// | `match_fraction` | n̂ / min(|s|, |t|) per level | `double` | 0.8 |
/// | `trim_descriptor` | descriptor of the trimming | `Trim_descriptor` | `GEODESIC_SPIN_CONTOUR` |
/// | `number_of_candidates` | k of the k-best trimming (widened until feasible) | `std::size_t` | 3 |
/// | `coarse_solver` | solver of the coarse program | `Coarse_solver` | `BRANCH_AND_BOUND` |
/// | `maximum_nodes` | work bound of the branch and bound | `std::size_t` | 5e7 |
/// | `local_optimization_iterations` | sweeps per side and level | `std::size_t` | 30 |
/// | `number_of_eigenpairs` | largest spectral basis of the dense map; 0: geodesic coordinates only | `std::size_t` | 60 |
/// | `random_seed` | seed of the first sampled vertex | `unsigned` | 0 |
/// | `number_of_starts` | first vertices tried by `run()` (stages 1 to 4 each) | `std::size_t` | 3 |
/// | `orientation` | the orientation of the map | `Map_orientation` | `PRESERVING` |
/// | `keep_largest_component` | a mesh of several connected components is worked on its largest one (else it is an error); not with custom vertex point or index maps | `bool` | false |
/// | `support_fraction`, `agd_radius_fraction`, ... | the trim descriptor's parameters (`support_fraction`: GSC's L / D, or ISC's R / D) | | those of `Geodesic_spin_descriptors`, `Intrinsic_shape_context` |
/// | `progress_callback` | `f(done, total)` after each stage of `run()` | `std::function<void(size_t, size_t)>` | none |
///
/// \throws Invalid_input for an empty mesh, non-triangle faces, non-finite coordinates, a mesh
///   with several connected components without `keep_largest_component` (geodesic distances
///   between them are undefined), or fewer vertices than features
template <typename TriangleMesh, typename MipTraits = CGAL::GLPK_mixed_integer_program_traits<double>>
class Isometric_correspondence {
public:
  /// The mesh's vertex type.
  typedef typename boost::graph_traits<TriangleMesh>::vertex_descriptor vertex_descriptor;
  /// The mesh's face type.
  typedef typename boost::graph_traits<TriangleMesh>::face_descriptor face_descriptor;
  /// A point on the target: a face and barycentric coordinates.
  typedef CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double> Face_location;

  /// Validates both meshes and reads the parameters (`np1` carries the method's parameters and the
  /// source's maps, `np2` the target's maps); no work is done until the stages are called.
  /// \throws Invalid_input as described above
  template <typename NamedParameters1 = parameters::Default_named_parameters, typename NamedParameters2 = parameters::Default_named_parameters>
  Isometric_correspondence(const TriangleMesh& source, const TriangleMesh& target,
                           const NamedParameters1& np1 = CGAL::parameters::default_values(),
                           const NamedParameters2& np2 = CGAL::parameters::default_values())
    : m_source(source, np1, "the source", parameters::choose_parameter(parameters::get_parameter(np1, internal_np::keep_largest_component), false)),
      m_target(target, np2, "the target", parameters::choose_parameter(parameters::get_parameter(np1, internal_np::keep_largest_component), false)) {
    using parameters::choose_parameter;
    using parameters::get_parameter;
    m_features = choose_parameter(get_parameter(np1, internal_np::number_of_features), std::size_t(10));
    m_levels = choose_parameter(get_parameter(np1, internal_np::number_of_levels), std::size_t(3));
    m_per_level = choose_parameter(get_parameter(np1, internal_np::features_per_level), std::size_t(20));
    m_fraction = choose_parameter(get_parameter(np1, internal_np::match_fraction), 0.8);
    m_trim = choose_parameter(get_parameter(np1, internal_np::trim_descriptor), Trim_descriptor::GEODESIC_SPIN_CONTOUR);
    m_k = choose_parameter(get_parameter(np1, internal_np::number_of_candidates), std::size_t(3));
    m_solver = choose_parameter(get_parameter(np1, internal_np::coarse_solver), Coarse_solver::BRANCH_AND_BOUND);
    m_max_nodes = choose_parameter(get_parameter(np1, internal_np::maximum_nodes), std::size_t(50'000'000));
    m_sweeps = choose_parameter(get_parameter(np1, internal_np::local_optimization_iterations), std::size_t(30));
    m_eigenpairs = choose_parameter(get_parameter(np1, internal_np::number_of_eigenpairs), std::size_t(60));
    m_seed = choose_parameter(get_parameter(np1, CGAL::internal_np::random_seed), 0u);
    m_starts = choose_parameter(get_parameter(np1, internal_np::number_of_starts), std::size_t(3));
    m_orientation = choose_parameter(get_parameter(np1, internal_np::orientation), Map_orientation::PRESERVING);
    m_progress = internal::progress_of(np1);
    if(m_features < 2) throw Invalid_argument("isometric correspondence: number_of_features must be at least 2");
    if(!(m_fraction > 0 && m_fraction <= 1)) throw Invalid_argument("isometric correspondence: match_fraction must be in (0, 1]");
    if(m_k == 0) throw Invalid_argument("isometric correspondence: number_of_candidates must be at least 1");
    if(m_starts == 0) throw Invalid_argument("isometric correspondence: number_of_starts must be at least 1");
    if(m_sweeps > 100000 || m_levels > 1000 || m_per_level > 100000 || m_starts > 10000)
      throw Invalid_argument("isometric correspondence: an iteration count is out of range");
    if(static_cast<std::size_t>(std::floor(m_fraction * double(m_features))) == 0)
      throw Invalid_argument("isometric correspondence: match_fraction x number_of_features leaves no pair to match");
    for(const Side* s : {&m_source, &m_target})
      if(s->size() < m_features + 1)
        throw Invalid_input(Mesh_defect::empty_mesh, "isometric correspondence: " + s->name + " has " + std::to_string(s->size()) +
                                                         " vertices, fewer than the features asked for plus one (" + std::to_string(m_features + 1) + ")");
    // the descriptors are built on demand in trim() with these parameters, without the progress
    // callback (it reports this class's stages, not the descriptors' own progress)
    m_make_descriptors = [this, np1 = without_progress(np1), np2 = without_progress(np2)](Side& side, bool is_source) {
      if(m_trim == Trim_descriptor::GEODESIC_SPIN_CONTOUR) {
        if(is_source) side.contours = contours_of(side, np1);
        else side.contours = contours_of(side, np2);
      } else if(m_trim == Trim_descriptor::INTRINSIC_SHAPE_CONTEXT) {
        if(!side.isc_context) { // the SI-HKS of all vertices: once; the contexts of the current features each time
          const Laplace_beltrami_eigenbasis basis = is_source ? compute_laplace_beltrami_eigenbasis(side.mesh(), std::min<std::size_t>(100, side.size() - 1), np1)
                                                              : compute_laplace_beltrami_eigenbasis(side.mesh(), std::min<std::size_t>(100, side.size() - 1), np2);
          side.isc_context = is_source ? make_isc(side, basis, np1) : make_isc(side, basis, np2);
        }
        side.isc = side.isc_context->descriptors(side.features);
      } else if(side.wks.rows() == 0) { // the signatures of all vertices: once (they do not depend on the features)
        const Laplace_beltrami_eigenbasis basis = is_source ? compute_laplace_beltrami_eigenbasis(side.mesh(), std::min<std::size_t>(100, side.size() - 1), np1)
                                                            : compute_laplace_beltrami_eigenbasis(side.mesh(), std::min<std::size_t>(100, side.size() - 1), np2);
        side.wks = wave_kernel_signature_matrix(basis);
      }
    };
    m_make_basis = [np1 = without_progress(np1), np2 = without_progress(np2)](const Side& side, bool is_source, std::size_t k) {
      return is_source ? compute_laplace_beltrami_eigenbasis(side.mesh(), k, np1) : compute_laplace_beltrami_eigenbasis(side.mesh(), k, np2);
    };
  }

  /// Every stage: features, trimming, the coarse program, local optimization, `number_of_levels`
  /// refinement levels and the dense map; `progress_callback(done, total)` after each.
  /// Stages 1 to 4 run `number_of_starts` times (see above); the report's times include every start.
  const Isometric_correspondence_report& run() {
    const std::size_t total = 4 * m_starts + 1 + m_levels;
    std::size_t done = 0;
    auto step = [&] { if(m_progress) m_progress(++done, total); };
    Coarse_state best;
    double best_energy = std::numeric_limits<double>::infinity(), matching = 0, local = 0, descriptors = 0;
    bool best_met = false;
    for(std::size_t s = 0; s < m_starts; ++s) {
      sample_features(m_seed + unsigned(s)); step();
      trim(); step();
      solve_coarse(); step();
      optimize_locally(); step();
      matching += m_report.levels[0].matching_seconds;
      local += m_report.levels[0].local_seconds;
      descriptors += m_report.descriptor_seconds;
      // the lowest energy among the starts with the orientation asked for after local optimization
      // (any start if none has it)
      const bool met = m_report.levels[0].orientation_met && has_orientation(m_report.orientation_score, 0);
      m_report.levels[0].orientation_met = met;
      if((met && !best_met) || (met == best_met && m_report.levels[0].energies.back() < best_energy)) {
        best_energy = m_report.levels[0].energies.back();
        best_met = met;
        best = save_coarse();
      }
    }
    restore_coarse(std::move(best));
    m_report.levels[0].matching_seconds = matching;
    m_report.levels[0].local_seconds = local;
    m_report.descriptor_seconds = descriptors;
    m_report.starts = m_starts;
    for(std::size_t l = 0; l < m_levels; ++l) { refine(); step(); }
    compute_dense_map(); step();
    return m_report;
  }

  /// Stage 1: `number_of_features` furthest-point features per shape, from a first vertex drawn
  /// with `seed` (default: `random_seed`).
  void sample_features() { sample_features(m_seed); }
  /// Stage 1 from the first vertex drawn with `seed`.
  void sample_features(unsigned seed) {
    Timer t;
    m_source.clear();
    m_target.clear();
    m_matches.clear();
    m_report = Isometric_correspondence_report();
    m_report.chosen_seed = seed;
    m_source.add_features(m_features, internal::seeded_start_vertex(seed, m_source.size()));
    m_target.add_features(m_features, internal::seeded_start_vertex(seed, m_target.size()));
    m_report.levels.push_back(Isometric_level_record());
    m_report.levels.back().source_features = m_features;
    m_report.levels.back().target_features = m_features;
    m_report.levels.back().matching_seconds += t.seconds();
  }

  /// Stage 2: candidate pairs among the features (see the class description).
  void trim() {
    require(!m_source.features.empty(), "trim() needs sample_features() first");
    Timer t;
    m_make_descriptors(m_source, true);
    m_make_descriptors(m_target, false);
    const std::size_t n = m_source.features.size(), m = m_target.features.size();
    Eigen::MatrixXd d(n, m);
    for(std::size_t i = 0; i < n; ++i)
      for(std::size_t k = 0; k < m; ++k) d(long(i), long(k)) = descriptor_distance(i, k);
    m_problem = Coarse_matching_problem();
    m_problem.source_distances = m_source.feature_distances();
    m_problem.target_distances = m_target.feature_distances();
    m_problem.number_of_matches = matches_for(n, m);
    m_source.make_triples();
    m_target.make_triples();
    for(std::size_t k = m_k;; ++k) {
      m_problem.candidates = k_best_both_ways(d, k);
      if(is_feasible(m_problem) || k >= std::max(n, m)) {
        m_report.levels[0].candidates_per_feature = k;
        break;
      }
    }
    m_report.levels[0].candidates = m_problem.candidates.size();
    const double s = t.seconds();
    m_report.descriptor_seconds += s;
    m_report.levels[0].matching_seconds += s;
  }

  /// Stage 3: the coarse program (Eq. 5.2).
  void solve_coarse() {
    require(!m_problem.candidates.empty(), "solve_coarse() needs trim() first");
    Timer t;
    Feature_matching r;
    std::size_t tests = 0;
    auto wanted = [&](const std::vector<Feature_pair>& pairs) {
      ++tests;
      return has_orientation(triple_score(pairs), orientation_margin);
    };
    Matching_acceptance accept;
    if(m_orientation != Map_orientation::ANY) accept = wanted;
    if(m_solver == Coarse_solver::BRANCH_AND_BOUND) {
      r = solve_coarse_matching_branch_and_bound(m_problem, m_max_nodes, accept);
    } else { // the rejected answers cut off, a bounded number of times
      std::vector<std::vector<Feature_pair>> excluded;
      for(std::size_t attempt = 0; attempt < 32; ++attempt) {
        MipTraits solver;
        Feature_matching a;
        try {
          a = solve_coarse_matching_mip(m_problem, solver, excluded);
        } catch(const Solver_failure&) {
          if(excluded.empty()) throw;
          break; // no other matching: keep the first one
        }
        a.accepted = wanted(a.pairs);
        if(excluded.empty() || a.accepted) r = a; // the unconstrained optimum stays when nothing is accepted
        if(a.accepted) break;
        excluded.push_back(a.pairs);
      }
    }
    m_matches.clear();
    for(const Feature_pair& p : r.pairs) m_matches.push_back({p.source, p.target, 0});
    Isometric_level_record& rec = m_report.levels[0];
    rec.new_matches = r.pairs.size();
    rec.objective = r.objective;
    rec.optimal = r.optimal;
    rec.nodes = r.nodes;
    rec.orientation_score = triple_score(r.pairs);
    rec.orientation_met = r.accepted;
    rec.orientation_tests = tests;
    rec.matching_seconds += t.seconds();
    publish();
  }

  /// Stage 4: local optimization (Eq. 5.3) of all matches, source side first.
  void optimize_locally() {
    require(!m_matches.empty(), "optimize_locally() needs matches (solve_coarse() first)");
    Timer t;
    Isometric_level_record& rec = m_report.levels.back();
    rec.energies.assign(1, energy());
    rec.snapshots.assign(1, vertex_matches());
    for(int side = 0; side < 2; ++side)
      for(std::size_t sweep = 0; sweep < m_sweeps; ++sweep) {
        const bool moved = local_sweep(side == 0);
        if(!moved) break;
        rec.energies.push_back(energy());
        rec.snapshots.push_back(vertex_matches());
      }
    if(m_report.levels.size() == 1) { // the coarse features moved: their orientation tables again
      m_source.make_triples();
      m_target.make_triples();
    }
    rec.local_seconds += t.seconds();
    publish();
  }

  /// Stage 5: one refinement level (new features, the assignment of Eq. 5.4, local optimization).
  /// Does nothing when a shape has no vertex left to sample.
  void refine() {
    require(!m_matches.empty(), "refine() needs matches (solve_coarse() first)");
    Timer t;
    const std::size_t first_s = m_source.features.size(), first_t = m_target.features.size();
    m_source.add_features(m_per_level);
    m_target.add_features(m_per_level);
    const std::size_t ns = m_source.features.size() - first_s, nt = m_target.features.size() - first_t;
    Isometric_level_record rec;
    rec.level = m_report.levels.size();
    rec.source_features = ns;
    rec.target_features = nt;
    rec.candidates = ns * nt;
    if(ns > 0 && nt > 0) {
      Eigen::MatrixXd cost = Eigen::MatrixXd::Zero(long(ns), long(nt));
      for(const Match& mt : m_matches) {
        const Eigen::VectorXd& fs = m_source.fields[mt.source];
        const Eigen::VectorXd& ft = m_target.fields[mt.target];
        for(std::size_t i = 0; i < ns; ++i)
          for(std::size_t k = 0; k < nt; ++k)
            cost(long(i), long(k)) += std::abs(fs[long(m_source.features[first_s + i])] - ft[long(m_target.features[first_t + k])]);
      }
      const Feature_matching r = solve_assignment(cost, matches_for(ns, nt));
      for(const Feature_pair& p : r.pairs) m_matches.push_back({first_s + p.source, first_t + p.target, rec.level});
      rec.new_matches = r.pairs.size();
      rec.objective = r.objective;
      rec.optimal = true;
    }
    rec.matching_seconds = t.seconds();
    m_report.levels.push_back(rec);
    publish();
    if(rec.new_matches > 0) optimize_locally();
  }

  /// Stage 6: the dense map (see the class description). Afterwards `dense_map()` has one target
  /// vertex per source vertex.
  void compute_dense_map() {
    require(!m_matches.empty(), "compute_dense_map() needs matches");
    Timer t;
    const std::size_t K = m_matches.size();
    Eigen::MatrixXd X(long(m_source.size()), long(K)), Y(long(m_target.size()), long(K));
    for(std::size_t j = 0; j < K; ++j) {
      X.col(long(j)) = m_source.fields[m_matches[j].source];
      Y.col(long(j)) = m_target.fields[m_matches[j].target];
    }
    m_dense = nearest_rows(X, Y);
    if(m_eigenpairs > 0) {
      const std::size_t kmax = std::min({m_eigenpairs, m_source.size() - 1, m_target.size() - 1});
      const Laplace_beltrami_eigenbasis bs = m_make_basis(m_source, true, kmax), bt = m_make_basis(m_target, false, kmax);
      const Eigen::MatrixXd& Ps = bs.eigenvectors();
      const Eigen::MatrixXd& Pt = bt.eigenvectors();
      const Eigen::VectorXd& mass = bs.mass();
      for(std::size_t k = std::min<std::size_t>(20, kmax);; k = std::min(k + 5, kmax)) {
        // C (k x k): target coefficients -> source coefficients of the pull-back by the map
        Eigen::MatrixXd pulled(long(m_source.size()), long(k));
        for(std::size_t v = 0; v < m_source.size(); ++v) pulled.row(long(v)) = Pt.row(long(m_dense[v])).head(long(k));
        const Eigen::MatrixXd C = Ps.leftCols(long(k)).transpose() * mass.asDiagonal() * pulled;
        // each source vertex's spectral row against the target rows carried into the source's
        // basis by C (ZoomOut's conversion; carrying the source rows by C instead is the same only
        // for an orthogonal C, and measured less precise: 56 % against 74 % of TOSCA points within 0.05)
        m_dense = nearest_rows(Ps.leftCols(long(k)), Pt.leftCols(long(k)) * C.transpose());
        if(k == kmax) break;
      }
    }
    set_orientation(internal::orientation_agreement(m_source.engine.arrays(), m_target.engine.arrays(), m_target.normals, m_dense));
    m_dense_user.resize(m_source.user_size());
    for(std::size_t v = 0; v < m_dense_user.size(); ++v) m_dense_user[v] = m_target.to_user(m_dense[m_source.from_user(v)]);
    m_report.source_vertices_dropped = m_source.dropped;
    m_report.target_vertices_dropped = m_target.dropped;
    m_report.dense_seconds = t.seconds();
  }

  /// The source's features (vertex indices), in sampling order (moved by local optimization).
  std::vector<std::size_t> source_features() const { return user_indices(m_source, m_source.features); }
  /// The target's features.
  std::vector<std::size_t> target_features() const { return user_indices(m_target, m_target.features); }
  /// The coarse problem built by `trim()`.
  const Coarse_matching_problem& coarse_problem() const { return m_problem; }
  /// The sparse matches (vertex indices) found so far, with their level.
  std::vector<Vertex_match> matches() const { return vertex_matches(); }
  /// The report so far.
  const Isometric_correspondence_report& report() const { return m_report; }
  /// After `compute_dense_map()`: the target vertex index of each source vertex (with
  /// `keep_largest_component`, a source vertex off the largest component gets the image of the
  /// nearest vertex on it, and the map reaches the target's largest component only).
  const std::vector<std::size_t>& dense_map() const { return m_dense_user; }
  /// The same as points of the target: a face incident to the vertex, with barycentric
  /// coordinate 1 at that vertex.
  Face_location dense_location(std::size_t source_vertex) const {
    require(source_vertex < m_dense_user.size(), "dense_location() needs compute_dense_map() and a valid index");
    return m_target.location_of(m_dense_user[source_vertex]);
  }
  /// The source vertex of an index.
  vertex_descriptor source_vertex(std::size_t i) const { return m_source.user.vertex(i); }
  /// The target vertex of an index.
  vertex_descriptor target_vertex(std::size_t i) const { return m_target.user.vertex(i); }
  /// E of Eq. 5.3 over all current matches (each unordered pair once).
  double energy() const {
    double e = 0;
    for(std::size_t a = 0; a < m_matches.size(); ++a)
      for(std::size_t b = a + 1; b < m_matches.size(); ++b) {
        const double r = source_distance(m_matches[a].source, m_matches[b].source) - target_distance(m_matches[a].target, m_matches[b].target);
        e += r * r;
      }
    return e;
  }

private:
  struct Match {
    std::size_t source, target, level; // positions in the feature lists
  };
  // What stages 1 to 4 leave behind: run() keeps the best start's (the engines stay).
  struct Coarse_state {
    std::vector<std::size_t> source_features, target_features;
    std::vector<Eigen::VectorXd> source_fields, target_fields;
    std::vector<Spin_contour> source_contours, target_contours;
    Eigen::MatrixXd source_isc, target_isc;
    std::vector<Match> matches;
    Coarse_matching_problem problem;
    Isometric_correspondence_report report;
  };
  struct Timer {
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double seconds() const { return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
  };

  // The largest connected component (by faces) of a mesh as a mesh of its own, or null when the
  // mesh is one component. `kept[i]`: the user's index of the part's vertex i.
  static std::unique_ptr<TriangleMesh> largest_part(const internal::Triangle_arrays& a, bool keep, bool custom_maps, const std::string& name,
                                                    std::vector<std::size_t>& kept) {
    internal::require_finite_triangles(a, "isometric correspondence", name);
    std::vector<int> component;
    const std::size_t count = internal::vertex_components(a.number_of_vertices(), a.F, component);
    if(count <= 1) return nullptr;
    if(!keep)
      throw Invalid_input(Mesh_defect::several_components, "isometric correspondence: " + name +
                                                               " has several connected components (or isolated vertices); keep the largest one"
                                                               " (named parameter keep_largest_component)");
    if(custom_maps)
      throw Invalid_argument("isometric correspondence: keep_largest_component works on the mesh's own vertex points and indices"
                             " (no vertex_point_map or vertex_index_map)");
    std::vector<std::size_t> faces(count, 0);
    for(Eigen::Index f = 0; f < a.F.rows(); ++f) ++faces[std::size_t(component[std::size_t(a.F(f, 0))])];
    const int largest = int(std::max_element(faces.begin(), faces.end()) - faces.begin());
    std::vector<std::size_t> part_of(a.number_of_vertices(), a.number_of_vertices());
    std::vector<std::array<double, 3>> points;
    std::vector<std::array<std::size_t, 3>> triangles;
    for(std::size_t v = 0; v < a.number_of_vertices(); ++v)
      if(component[v] == largest) {
        part_of[v] = points.size();
        points.push_back({a.V(long(v), 0), a.V(long(v), 1), a.V(long(v), 2)});
        kept.push_back(v);
      }
    for(Eigen::Index f = 0; f < a.F.rows(); ++f)
      if(component[std::size_t(a.F(f, 0))] == largest)
        triangles.push_back({part_of[std::size_t(a.F(f, 0))], part_of[std::size_t(a.F(f, 1))], part_of[std::size_t(a.F(f, 2))]});
    auto part = std::make_unique<TriangleMesh>();
    internal::soup_to_mesh(points, triangles, *part);
    if(num_vertices(*part) != points.size())
      throw Invalid_input(Mesh_defect::non_manifold_vertex, "isometric correspondence: the largest component of " + name + " is not a manifold surface");
    return part;
  }

  // One shape: its fast-marching engine, features and their distance fields. With
  // keep_largest_component on a mesh of several components, the work is done on `part` (the
  // largest one); the user's indices are translated in and out here.
  struct Side {
    template <typename NamedParameters>
    Side(const TriangleMesh& tm, const NamedParameters& np, const char* which, bool keep_largest)
      : user(tm, np),
        part(largest_part(user.arrays(), keep_largest,
                          !std::is_same<std::decay_t<decltype(parameters::get_parameter(np, CGAL::internal_np::vertex_point))>, CGAL::internal_np::Param_not_found>::value ||
                              !std::is_same<std::decay_t<decltype(parameters::get_parameter(np, CGAL::internal_np::vertex_index))>, CGAL::internal_np::Param_not_found>::value,
                          which, kept)),
        tm_(part ? part.get() : &tm), engine(part ? Fast_marching_geodesics<TriangleMesh>(*part) : Fast_marching_geodesics<TriangleMesh>(tm, np)),
        normals(internal::vertex_normals(engine.arrays())), faces_of(internal::vertex_faces(engine.arrays())), name(which) {
      const internal::Triangle_arrays& a = engine.arrays();
      if(part) { // every user vertex goes to its own place on the part, or to the nearest one there
        const internal::Triangle_arrays& all = user.arrays();
        part_of.assign(all.number_of_vertices(), all.number_of_vertices());
        for(std::size_t i = 0; i < kept.size(); ++i) part_of[kept[i]] = i;
        std::vector<std::size_t> off;
        for(std::size_t v = 0; v < part_of.size(); ++v)
          if(part_of[v] == all.number_of_vertices()) off.push_back(v);
        Eigen::MatrixXd A(long(off.size()), 3);
        for(std::size_t k = 0; k < off.size(); ++k) A.row(long(k)) = all.V.row(long(off[k]));
        const std::vector<std::size_t> near = nearest_rows(A, a.V);
        for(std::size_t k = 0; k < off.size(); ++k) part_of[off[k]] = near[k];
        dropped = off.size();
      }
      double sum = 0, area = 0;
      for(Eigen::Index f = 0; f < a.F.rows(); ++f) {
        for(int c = 0; c < 3; ++c) sum += (a.V.row(a.F(f, c)) - a.V.row(a.F(f, (c + 1) % 3))).norm();
        area += 0.5 * internal::twice_area_normal(a, f).norm();
      }
      if(!(area > 0))
        throw Invalid_input(Mesh_defect::degenerate_face, "isometric correspondence: " + name + " has no area (every face is degenerate)");
      scale = 1 / std::sqrt(area);
      mean_edge = scale * sum / double(3 * a.F.rows());
    }
    // the geodesic distances from vertex v, divided by sqrt(area)
    Eigen::VectorXd field_from(std::size_t v) const { return scale * engine.distances_from(v); }
    const TriangleMesh& mesh() const { return *tm_; } // what the work is done on (the part, or the user's mesh)
    std::size_t to_user(std::size_t i) const { return part ? kept[i] : i; }           // a vertex of mesh() -> the user's index
    std::size_t from_user(std::size_t v) const { return part ? part_of[v] : v; }      // the user's index -> a vertex of mesh()
    std::size_t user_size() const { return user.number_of_vertices(); }
    std::size_t size() const { return engine.number_of_vertices(); }
    void clear() { features.clear(); fields.clear(); nearest.resize(0); }
    // furthest point sampling, continued from the current features (or from `start`, dropped)
    void add_features(std::size_t count, std::size_t start = 0) {
      if(features.empty()) nearest = field_from(start);
      else {
        nearest = fields[0];
        for(const Eigen::VectorXd& f : fields) nearest = nearest.cwiseMin(f);
      }
      for(std::size_t c = 0; c < count; ++c) {
        Eigen::Index best;
        if(!(nearest.maxCoeff(&best) > 0)) break; // every vertex is a feature
        features.push_back(std::size_t(best));
        fields.push_back(field_from(std::size_t(best)));
        nearest = nearest.cwiseMin(fields.back());
      }
    }
    // symmetric geodesic distance between features a and b (fast marching is not exactly symmetric)
    double distance(std::size_t a, std::size_t b) const {
      return 0.5 * (fields[a][long(features[b])] + fields[b][long(features[a])]);
    }
    Eigen::MatrixXd feature_distances() const {
      Eigen::MatrixXd d(long(features.size()), long(features.size()));
      for(std::size_t a = 0; a < features.size(); ++a)
        for(std::size_t b = 0; b < features.size(); ++b) d(long(a), long(b)) = a == b ? 0.0 : distance(a, b);
      return d;
    }
    void make_triples() {
      std::vector<const Eigen::VectorXd*> f;
      for(const Eigen::VectorXd& x : fields) f.push_back(&x);
      triples = internal::triple_orientations(engine.arrays(), faces_of, normals, f);
    }
    Face_location location_of(std::size_t user_index) const { // of the user's vertex
      return CGAL::Polygon_mesh_processing::locate_vertex(user.vertex(user_index), user.mesh());
    }

    internal::Indexed_mesh<TriangleMesh> user;            // the user's mesh, indices and descriptors
    std::vector<std::size_t> kept, part_of;               // part vertex -> user index; user index -> part vertex (the nearest for a dropped one)
    std::unique_ptr<TriangleMesh> part;                   // the largest component (keep_largest_component), or null
    std::size_t dropped = 0;                              // user vertices off the part
    const TriangleMesh* tm_;
    Fast_marching_geodesics<TriangleMesh> engine;
    Eigen::Matrix<double, Eigen::Dynamic, 3, Eigen::RowMajor> normals; // unit vertex normals
    std::vector<std::vector<int>> faces_of;               // faces around each vertex
    std::vector<double> triples;                          // coarse level: the features' triple orientations
    std::string name;
    double scale = 1;                                     // 1 / sqrt(area): the unit of every distance below
    double mean_edge = 0;                                 // in that unit
    std::vector<std::size_t> features;                    // vertex indices
    std::vector<Eigen::VectorXd> fields;                  // distance field of each feature
    Eigen::VectorXd nearest;                              // distance to the nearest feature
    std::vector<Spin_contour> contours;                   // GSC trim: the contours of the features
    Eigen::MatrixXd wks;                                  // WKS trim: the signatures of all vertices
    std::shared_ptr<const Intrinsic_shape_context<TriangleMesh>> isc_context; // ISC trim
    Eigen::MatrixXd isc;                                  // ISC trim: the contexts of the features (row i: feature i)
  };

  // the contours of the current features (position i: feature i)
  template <typename NamedParameters>
  static std::vector<Spin_contour> contours_of(const Side& side, const NamedParameters& np) {
    const Geodesic_spin_descriptors<TriangleMesh> gs(side.mesh(), np);
    return gs.geodesic_spin_contours(side.features, {});
  }

  // the intrinsic shape contexts of a side on `basis` (the parameters of np but its eigenbasis)
  template <typename NamedParameters>
  static std::shared_ptr<const Intrinsic_shape_context<TriangleMesh>> make_isc(const Side& side, const Laplace_beltrami_eigenbasis& basis,
                                                                                const NamedParameters& np) {
    return std::make_shared<const Intrinsic_shape_context<TriangleMesh>>(
        side.mesh(), scale_invariant_heat_kernel_signature_matrix(basis, np), np);
  }

  // `np` with an empty progress callback in front (found first)
  template <typename NamedParameters>
  static auto without_progress(const NamedParameters& np) {
    typedef std::function<void(std::size_t, std::size_t)> Progress;
    return shapecorr::Named_function_parameters<Progress, internal_np::progress_callback_t, NamedParameters>(Progress(), np);
  }

  Coarse_state save_coarse() const {
    return {m_source.features, m_target.features, m_source.fields, m_target.fields, m_source.contours, m_target.contours, m_source.isc, m_target.isc,
            m_matches,         m_problem,         m_report};
  }
  void restore_coarse(Coarse_state c) {
    m_source.features = std::move(c.source_features);
    m_target.features = std::move(c.target_features);
    m_source.fields = std::move(c.source_fields);
    m_target.fields = std::move(c.target_fields);
    m_source.contours = std::move(c.source_contours);
    m_target.contours = std::move(c.target_contours);
    m_source.isc = std::move(c.source_isc);
    m_target.isc = std::move(c.target_isc);
    m_matches = std::move(c.matches);
    m_problem = std::move(c.problem);
    m_report = std::move(c.report);
  }

  static void require(bool ok, const char* what) {
    if(!ok) throw Invalid_argument(std::string("isometric correspondence: ") + what);
  }

  std::size_t matches_for(std::size_t n, std::size_t m) const {
    return std::max<std::size_t>(1, static_cast<std::size_t>(std::floor(m_fraction * double(std::min(n, m)))));
  }

  double descriptor_distance(std::size_t s, std::size_t t) const {
    if(m_trim == Trim_descriptor::GEODESIC_SPIN_CONTOUR) return contour_l1_distance(m_source.contours[s], m_target.contours[t]);
    if(m_trim == Trim_descriptor::INTRINSIC_SHAPE_CONTEXT) return (m_source.isc.row(long(s)) - m_target.isc.row(long(t))).norm();
    return (m_source.wks.row(long(m_source.features[s])) - m_target.wks.row(long(m_target.features[t]))).norm();
  }

  // the union of each source feature's k nearest targets and each target feature's k nearest sources
  static std::vector<Feature_pair> k_best_both_ways(const Eigen::MatrixXd& d, std::size_t k) {
    std::vector<Feature_pair> out;
    std::vector<char> taken(std::size_t(d.size()), 0);
    auto take = [&](std::size_t i, std::size_t j) {
      if(!taken[i * std::size_t(d.cols()) + j]) { taken[i * std::size_t(d.cols()) + j] = 1; out.push_back({i, j}); }
    };
    auto best = [&](const Eigen::VectorXd& row) {
      std::vector<std::size_t> idx(std::size_t(row.size()));
      for(std::size_t j = 0; j < idx.size(); ++j) idx[j] = j;
      const std::size_t kk = std::min(k, idx.size());
      std::partial_sort(idx.begin(), idx.begin() + long(kk), idx.end(), [&](std::size_t a, std::size_t b) {
        return row[long(a)] < row[long(b)] || (row[long(a)] == row[long(b)] && a < b);
      });
      idx.resize(kk);
      return idx;
    };
    for(Eigen::Index i = 0; i < d.rows(); ++i)
      for(std::size_t j : best(d.row(i).transpose())) take(std::size_t(i), j);
    for(Eigen::Index j = 0; j < d.cols(); ++j)
      for(std::size_t i : best(d.col(j))) take(i, std::size_t(j));
    std::sort(out.begin(), out.end());
    return out;
  }

  double source_distance(std::size_t a, std::size_t b) const { return m_source.distance(a, b); }
  double target_distance(std::size_t a, std::size_t b) const { return m_target.distance(a, b); }

  // One sweep over the matches, moving the features of one side; true when one moved.
  bool local_sweep(bool move_source) {
    Side& side = move_source ? m_source : m_target;
    const Side& other = move_source ? m_target : m_source;
    const double step = std::max(0.03, 2 * side.mean_edge); // in units of sqrt(area): the same region at any resolution
    bool moved = false;
    for(std::size_t a = 0; a < m_matches.size(); ++a) {
      const std::size_t mine = move_source ? m_matches[a].source : m_matches[a].target;
      const std::size_t theirs = move_source ? m_matches[a].target : m_matches[a].source;
      // E as a function of the position v of this feature: Σ_b (d_b(v) − g_other(a, b))²
      std::vector<std::pair<const Eigen::VectorXd*, double>> terms;
      for(std::size_t b = 0; b < m_matches.size(); ++b) {
        if(b == a) continue;
        const std::size_t mb = move_source ? m_matches[b].source : m_matches[b].target;
        const std::size_t tb = move_source ? m_matches[b].target : m_matches[b].source;
        terms.push_back({&side.fields[mb], other.distance(theirs, tb)});
      }
      auto e_at = [&](std::size_t v) {
        double e = 0;
        for(const auto& [field, g] : terms) {
          const double r = (*field)[long(v)] - g;
          e += r * r;
        }
        return e;
      };
      const Eigen::VectorXd& here = side.fields[mine];
      const std::size_t current = side.features[mine];
      double best_e = e_at(current);
      std::size_t best_v = current;
      for(std::size_t v = 0; v < side.size(); ++v)
        if(here[long(v)] <= step && v != current) {
          const double e = e_at(v);
          if(e < best_e) { best_e = e; best_v = v; }
        }
      if(best_v != current && best_e < e_at(current) * (1 - 1e-12)) {
        side.features[mine] = best_v;
        side.fields[mine] = side.field_from(best_v);
        moved = true;
      }
    }
    return moved;
  }

  std::vector<Vertex_match> vertex_matches() const {
    std::vector<Vertex_match> out;
    for(const Match& mt : m_matches) out.push_back({m_source.to_user(m_source.features[mt.source]), m_target.to_user(m_target.features[mt.target]), mt.level});
    return out;
  }
  static std::vector<std::size_t> user_indices(const Side& side, const std::vector<std::size_t>& v) {
    std::vector<std::size_t> out;
    for(std::size_t i : v) out.push_back(side.to_user(i));
    return out;
  }
  void publish() {
    m_report.matches = vertex_matches();
    m_report.requested_orientation = m_orientation;
    if(m_report.levels.size() == 1) { // the coarse level; the dense map sets its own
      std::vector<Feature_pair> pairs;
      for(const Match& m : m_matches) pairs.push_back({m.source, m.target});
      set_orientation(triple_score(pairs));
    }
  }
  // the agreement a coarse matching needs (a weak one was seen to end mirrored after local optimization)
  static constexpr double orientation_margin = 0.25;
  bool has_orientation(double score, double margin) const {
    return m_orientation == Map_orientation::ANY || (m_orientation == Map_orientation::PRESERVING ? score > margin : score < -margin);
  }
  void set_orientation(double score) {
    m_report.orientation_score = score;
    m_report.orientation = score > 0 ? Map_orientation::PRESERVING : Map_orientation::REVERSING;
  }

  // The triple orientation score (internal::triple_orientation_score) of pairs of feature
  // positions, with the tables of the current features (made by trim(), again after local
  // optimization moved them).
  double triple_score(const std::vector<Feature_pair>& pairs) const {
    std::vector<std::size_t> s, t;
    for(const Feature_pair& p : pairs) { s.push_back(p.source); t.push_back(p.target); }
    return internal::triple_orientation_score(m_source.triples, m_source.features.size(), m_target.triples, m_target.features.size(), s, t);
  }

  // for each row of A, the index of the nearest row of B (Euclidean), in blocks of A's rows
  static std::vector<std::size_t> nearest_rows(const Eigen::MatrixXd& A, const Eigen::MatrixXd& B) {
    std::vector<std::size_t> out(std::size_t(A.rows()));
    const Eigen::VectorXd b2 = B.rowwise().squaredNorm();
    const Eigen::Index block = 1024;
    for(Eigen::Index r0 = 0; r0 < A.rows(); r0 += block) {
      const Eigen::Index rows = std::min(block, A.rows() - r0);
      Eigen::MatrixXd d = -2.0 * A.middleRows(r0, rows) * B.transpose();
      d.rowwise() += b2.transpose();
      for(Eigen::Index r = 0; r < rows; ++r) {
        Eigen::Index j;
        d.row(r).minCoeff(&j);
        out[std::size_t(r0 + r)] = std::size_t(j);
      }
    }
    return out;
  }

  Side m_source, m_target;
  std::size_t m_features = 10, m_levels = 3, m_per_level = 20, m_k = 3, m_max_nodes = 50'000'000, m_sweeps = 30, m_eigenpairs = 60;
  double m_fraction = 0.8;
  Trim_descriptor m_trim = Trim_descriptor::GEODESIC_SPIN_CONTOUR;
  Coarse_solver m_solver = Coarse_solver::BRANCH_AND_BOUND;
  unsigned m_seed = 0;
  std::size_t m_starts = 3;
  Map_orientation m_orientation = Map_orientation::PRESERVING;
  std::function<void(std::size_t, std::size_t)> m_progress;
  std::function<void(Side&, bool)> m_make_descriptors;
  std::function<Laplace_beltrami_eigenbasis(const Side&, bool, std::size_t)> m_make_basis;
  Coarse_matching_problem m_problem;
  std::vector<Match> m_matches;
  std::vector<std::size_t> m_dense, m_dense_user; // on the parts worked on; in the user's indices
  Isometric_correspondence_report m_report;
};

/// \ingroup PkgShapeCorrRegistration
/// Fully automatic near-isometric correspondence from `source` to `target` (thesis chapter 5 and
/// a dense map): runs every stage of `Isometric_correspondence` and writes, for each source
/// vertex, its point on the target into `out`.
/// \param out a `WritablePropertyMap` from the source's `vertex_descriptor` to
///   `CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>`
/// \param np1, np2 named parameters of the source and the target (see `Isometric_correspondence`)
/// \returns the sparse matches and what each level did
/// \code
///   auto map = get(CGAL::dynamic_vertex_property_t<PMP::Face_location<Mesh, double>>(), source);
///   shapecorr::Isometric_correspondence_report r = shapecorr::compute_isometric_correspondences(source, target, map);
/// \endcode
template <typename TriangleMesh, typename LocationMap, typename NamedParameters1 = parameters::Default_named_parameters,
          typename NamedParameters2 = parameters::Default_named_parameters>
Isometric_correspondence_report compute_isometric_correspondences(const TriangleMesh& source, const TriangleMesh& target, LocationMap out,
                                                                  const NamedParameters1& np1 = CGAL::parameters::default_values(),
                                                                  const NamedParameters2& np2 = CGAL::parameters::default_values()) {
  Isometric_correspondence<TriangleMesh> method(source, target, np1, np2);
  const Isometric_correspondence_report report = method.run();
  for(std::size_t v = 0; v < method.dense_map().size(); ++v) put(out, method.source_vertex(v), method.dense_location(v));
  return report;
}

} // namespace shapecorr

#endif
