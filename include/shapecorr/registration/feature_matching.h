// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file feature_matching.h
/// The matching problems of fully automatic near-isometric registration (thesis chapter 5;
/// ALGORITHMS.md): the coarse quadratic matching of feature points (Eq. 5.2) with two exact
/// solvers — a mixed-integer program through any model of CGAL's `MixedIntegerProgramTraits`
/// and a dedicated branch and bound — and the cardinality-constrained assignment of the
/// refinement (Eq. 5.4) as a min-cost flow.
#ifndef SHAPECORR_REGISTRATION_FEATURE_MATCHING_H
#define SHAPECORR_REGISTRATION_FEATURE_MATCHING_H

#include <shapecorr/exceptions.h>

#include <Eigen/Core>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrRegistration
/// A correspondence between source feature `source` and target feature `target` (positions in
/// the feature lists of the two shapes).
struct Feature_pair {
  std::size_t source = 0; ///< position in the source feature list
  std::size_t target = 0; ///< position in the target feature list
  /// Same source and target.
  friend bool operator==(const Feature_pair& a, const Feature_pair& b) { return a.source == b.source && a.target == b.target; }
  /// Lexicographic order on (source, target).
  friend bool operator<(const Feature_pair& a, const Feature_pair& b) { return a.source < b.source || (a.source == b.source && a.target < b.target); }
};

/// \ingroup PkgShapeCorrRegistration
/// The coarse matching problem (thesis Eq. 5.2): among the `candidates`, choose exactly
/// `number_of_matches` pairs, one-to-one, minimizing the geodesic distortion
/// `Σ_{pairs {(i,k),(j,l)} chosen} |source_distances(i,j) − target_distances(k,l)|`, each unordered
/// pair of chosen pairs counted once (half of the thesis's sum over ordered pairs; same minimizer).
struct Coarse_matching_problem {
  Eigen::MatrixXd source_distances;   ///< n × n geodesic distances between the source features (symmetric)
  Eigen::MatrixXd target_distances;   ///< m × m between the target features
  std::vector<Feature_pair> candidates; ///< the pairs allowed (after trimming)
  std::size_t number_of_matches = 0;  ///< n̂

  /// |g(s_i, s_j) − g(t_k, t_l)| for pairs a = (i, k) and b = (j, l).
  double distortion(const Feature_pair& a, const Feature_pair& b) const {
    return std::abs(source_distances(static_cast<Eigen::Index>(a.source), static_cast<Eigen::Index>(b.source)) -
                    target_distances(static_cast<Eigen::Index>(a.target), static_cast<Eigen::Index>(b.target)));
  }
  /// The objective of a set of pairs (each unordered pair once).
  double objective(const std::vector<Feature_pair>& pairs) const {
    double sum = 0;
    for(std::size_t a = 0; a < pairs.size(); ++a)
      for(std::size_t b = a + 1; b < pairs.size(); ++b) sum += distortion(pairs[a], pairs[b]);
    return sum;
  }
};

/// \ingroup PkgShapeCorrRegistration
/// A solution of a matching problem.
struct Feature_matching {
  std::vector<Feature_pair> pairs; ///< the chosen pairs, sorted by source
  double objective = 0;            ///< its objective
  bool optimal = false;            ///< proven optimal (false: the solver stopped at its work bound with the best found)
  std::size_t nodes = 0;           ///< search nodes visited (branch and bound; 0 for other solvers)
  bool accepted = true;            ///< the matching satisfies the caller's acceptance test (false: none found that does; this is the best rejected one)
};

/// \ingroup PkgShapeCorrRegistration
/// A test a complete matching must pass to be a solution (e.g. an orientation test); empty: every
/// matching passes.
typedef std::function<bool(const std::vector<Feature_pair>&)> Matching_acceptance;

namespace internal {

inline void check_problem(const Coarse_matching_problem& p, const char* who) {
  const auto n = static_cast<std::size_t>(p.source_distances.rows()), m = static_cast<std::size_t>(p.target_distances.rows());
  if(p.source_distances.cols() != p.source_distances.rows() || p.target_distances.cols() != p.target_distances.rows())
    throw Invalid_argument(std::string(who) + ": the distance matrices must be square");
  if(!p.source_distances.allFinite() || !p.target_distances.allFinite())
    throw Invalid_argument(std::string(who) + ": a feature distance is not finite (features on different components?)");
  for(const Feature_pair& c : p.candidates)
    if(c.source >= n || c.target >= m) throw Invalid_argument(std::string(who) + ": a candidate pair is out of range");
  if(p.number_of_matches == 0) throw Invalid_argument(std::string(who) + ": the number of matches must be at least 1");
}

/// The size of a maximum one-to-one matching among `pairs` (augmenting paths; small problems).
inline std::size_t maximum_matching_size(const std::vector<Feature_pair>& pairs, std::size_t n, std::size_t m) {
  std::vector<std::vector<std::size_t>> adjacent(n);
  for(const Feature_pair& p : pairs) adjacent[p.source].push_back(p.target);
  std::vector<std::size_t> owner(m, n); // target -> source, n = free
  std::vector<char> seen(m);
  std::function<bool(std::size_t)> augment = [&](std::size_t i) {
    for(std::size_t k : adjacent[i]) {
      if(seen[k]) continue;
      seen[k] = 1;
      if(owner[k] == n || augment(owner[k])) { owner[k] = i; return true; }
    }
    return false;
  };
  std::size_t size = 0;
  for(std::size_t i = 0; i < n; ++i) {
    std::fill(seen.begin(), seen.end(), 0);
    size += augment(i) ? 1 : 0;
  }
  return size;
}

[[noreturn]] inline void throw_infeasible(const Coarse_matching_problem& p, const char* who) {
  throw Invalid_argument(std::string(who) + ": infeasible: the candidate pairs allow no one-to-one matching of " +
                         std::to_string(p.number_of_matches) + " pairs (widen the candidates)");
}

} // namespace internal

/// \ingroup PkgShapeCorrRegistration
/// Whether `p` has a solution: a one-to-one matching of `number_of_matches` pairs among its
/// candidates (maximum bipartite matching).
inline bool is_feasible(const Coarse_matching_problem& p) {
  return internal::maximum_matching_size(p.candidates, static_cast<std::size_t>(p.source_distances.rows()),
                                         static_cast<std::size_t>(p.target_distances.rows())) >= p.number_of_matches;
}

/// \ingroup PkgShapeCorrRegistration
/// Solves the coarse matching problem exactly with a dedicated depth-first branch and bound over
/// partial one-to-one matchings. Source features are decided one at a time (matched to a free
/// candidate target, or left out while the cardinality still allows it); each candidate keeps
/// its distortion against the pairs already chosen, and a node is cut when its cost plus the
/// sum of the r smallest per-feature minima of those distortions (r = matches still needed; the
/// distortions among future pairs are left out, so the bound is admissible) reaches the best
/// solution found. Needs no external solver.
/// \param max_nodes bound on the work: when reached the best matching found so far is returned
///   with `optimal = false`
/// \param accept when not empty, only complete matchings it accepts are solutions: the result is
///   the best accepted matching (optimal among them when `optimal`); when none is accepted within
///   the work bound, the best rejected one with `accepted = false`
/// \throws Invalid_argument for a malformed or infeasible problem (see `is_feasible`)
/// \code
///   shapecorr::Feature_matching best = shapecorr::solve_coarse_matching_branch_and_bound(problem);
/// \endcode
inline Feature_matching solve_coarse_matching_branch_and_bound(const Coarse_matching_problem& p,
                                                               std::size_t max_nodes = 50'000'000,
                                                               const Matching_acceptance& accept = {}) {
  const char* who = "coarse matching (branch and bound)";
  internal::check_problem(p, who);
  if(!is_feasible(p)) internal::throw_infeasible(p, who);
  const std::size_t n = static_cast<std::size_t>(p.source_distances.rows()), m = static_cast<std::size_t>(p.target_distances.rows());
  const std::size_t C = p.candidates.size();
  // the candidates of each source feature; decide features with fewer candidates first
  std::vector<std::vector<std::size_t>> of_source(n);
  for(std::size_t c = 0; c < C; ++c) of_source[p.candidates[c].source].push_back(c);
  std::vector<std::size_t> order;
  for(std::size_t i = 0; i < n; ++i)
    if(!of_source[i].empty()) order.push_back(i);
  std::stable_sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return of_source[a].size() < of_source[b].size(); });
  const std::size_t F = order.size(), need = p.number_of_matches;
  // pairwise distortions of candidates (0 for pairs that share a feature: never both chosen)
  Eigen::MatrixXd W(C, C);
  for(std::size_t a = 0; a < C; ++a)
    for(std::size_t b = 0; b < C; ++b) {
      const Feature_pair &x = p.candidates[a], &y = p.candidates[b];
      W(a, b) = (x.source == y.source || x.target == y.target) ? 0.0 : p.distortion(x, y);
    }
  Eigen::VectorXd added = Eigen::VectorXd::Zero(C); // distortion of each candidate against the chosen pairs
  std::vector<char> target_used(m, 0);
  std::vector<std::size_t> chosen, best_chosen, rejected_chosen;
  double best = std::numeric_limits<double>::infinity(), best_rejected = best;
  std::vector<Feature_pair> leaf;
  auto accepted = [&] {
    if(!accept) return true;
    leaf.clear();
    for(std::size_t c : chosen) leaf.push_back(p.candidates[c]);
    std::sort(leaf.begin(), leaf.end());
    return accept(leaf);
  };
  std::size_t nodes = 0;
  bool stopped = false;
  std::vector<double> minima;
  minima.reserve(F);
  // lower bound on the cost still to come when features order[pos..] remain and r pairs are needed
  auto bound = [&](std::size_t pos, std::size_t r) {
    if(r == 0) return 0.0;
    minima.clear();
    for(std::size_t q = pos; q < F; ++q) {
      double low = std::numeric_limits<double>::infinity();
      for(std::size_t c : of_source[order[q]])
        if(!target_used[p.candidates[c].target]) low = std::min(low, added[static_cast<Eigen::Index>(c)]);
      if(std::isfinite(low)) minima.push_back(low);
    }
    if(minima.size() < r) return std::numeric_limits<double>::infinity();
    std::nth_element(minima.begin(), minima.begin() + static_cast<std::ptrdiff_t>(r - 1), minima.end());
    return std::accumulate(minima.begin(), minima.begin() + static_cast<std::ptrdiff_t>(r), 0.0);
  };
  std::function<void(std::size_t, double)> search = [&](std::size_t pos, double cost) {
    if(stopped) return;
    if(++nodes > max_nodes) { stopped = true; return; }
    const std::size_t r = need - chosen.size();
    if(r == 0) {
      if(cost < best) {
        if(accepted()) { best = cost; best_chosen = chosen; }
        else if(cost < best_rejected) { best_rejected = cost; rejected_chosen = chosen; }
      }
      return;
    }
    if(F - pos < r || cost + bound(pos, r) >= best) return;
    // children: the free candidates of this feature by increasing added distortion, then "left out"
    std::vector<std::size_t> options;
    for(std::size_t c : of_source[order[pos]])
      if(!target_used[p.candidates[c].target]) options.push_back(c);
    std::sort(options.begin(), options.end(), [&](std::size_t a, std::size_t b) {
      return added[static_cast<Eigen::Index>(a)] < added[static_cast<Eigen::Index>(b)] || (added[static_cast<Eigen::Index>(a)] == added[static_cast<Eigen::Index>(b)] && a < b);
    });
    for(std::size_t c : options) {
      const double next = cost + added[static_cast<Eigen::Index>(c)];
      if(next >= best) continue;
      chosen.push_back(c);
      target_used[p.candidates[c].target] = 1;
      added += W.col(static_cast<Eigen::Index>(c));
      search(pos + 1, next);
      added -= W.col(static_cast<Eigen::Index>(c));
      target_used[p.candidates[c].target] = 0;
      chosen.pop_back();
      if(stopped) return;
    }
    if(F - pos - 1 >= r) search(pos + 1, cost);
  };
  search(0, 0.0);
  Feature_matching result;
  if(best_chosen.empty() && !rejected_chosen.empty()) {
    best_chosen = rejected_chosen;
    result.accepted = false;
  }
  for(std::size_t c : best_chosen) result.pairs.push_back(p.candidates[c]);
  std::sort(result.pairs.begin(), result.pairs.end());
  result.objective = p.objective(result.pairs); // recomputed: no drift from the incremental sums
  result.optimal = !stopped;
  result.nodes = std::min(nodes, max_nodes);
  if(result.pairs.size() != need)
    throw Solver_failure(std::string(who) + ": no matching found within " + std::to_string(max_nodes) + " nodes");
  return result;
}

/// \ingroup PkgShapeCorrRegistration
/// Solves the coarse matching problem as the mixed-integer program of the thesis (Eq. 5.2) with
/// any model of CGAL's `MixedIntegerProgramTraits`: binary m(c) per candidate c, continuous
/// M(a, b) ≥ m(a) + m(b) − 1, M ≥ 0, for each unordered pair of candidates that share no feature;
/// `Σ_k m(i,k) ≤ 1`, `Σ_i m(i,k) ≤ 1`, `Σ m = n̂`; minimize `Σ distortion(a, b) M(a, b)`.
/// \tparam MipTraits e.g. `CGAL::GLPK_mixed_integer_program_traits<double>` (Debian's
///   libglpk-dev) or `CGAL::SCIP_mixed_integer_program_traits<double>`
/// \param solver a fresh traits object (the program is built in it)
/// \param excluded matchings that are not solutions (each gets the cut `Σ_{c in it} m(c) ≤ |it| − 1`),
///   e.g. the previous answers of a caller that rejected them
/// The program has |C| binaries and up to |C|²/2 continuous variables and constraints; the work
/// of the solver is bounded by what the traits offer (CGAL's GLPK traits have no time limit, so
/// keep the candidates few: the branch and bound is the scalable choice).
/// \throws Invalid_argument for a malformed or infeasible problem; Solver_failure with the
///   solver's message when it fails
template <typename MipTraits>
Feature_matching solve_coarse_matching_mip(const Coarse_matching_problem& p, MipTraits& solver,
                                           const std::vector<std::vector<Feature_pair>>& excluded = {}) {
  const char* who = "coarse matching (mixed-integer program)";
  internal::check_problem(p, who);
  if(!is_feasible(p)) internal::throw_infeasible(p, who);
  typedef typename MipTraits::Variable Variable;
  typedef typename MipTraits::Linear_constraint Linear_constraint;
  typedef typename MipTraits::Linear_objective Linear_objective;
  const std::size_t n = static_cast<std::size_t>(p.source_distances.rows()), m = static_cast<std::size_t>(p.target_distances.rows());
  const std::size_t C = p.candidates.size();
  std::vector<Variable*> x(C);
  for(std::size_t c = 0; c < C; ++c) x[c] = solver.create_variable(Variable::BINARY, 0, 1);
  std::vector<Linear_constraint*> per_source(n, nullptr), per_target(m, nullptr);
  Linear_constraint* cardinality = solver.create_constraint(double(p.number_of_matches), double(p.number_of_matches));
  for(std::size_t c = 0; c < C; ++c) {
    const Feature_pair& f = p.candidates[c];
    if(!per_source[f.source]) per_source[f.source] = solver.create_constraint(0, 1);
    if(!per_target[f.target]) per_target[f.target] = solver.create_constraint(0, 1);
    per_source[f.source]->add_coefficient(x[c], 1);
    per_target[f.target]->add_coefficient(x[c], 1);
    cardinality->add_coefficient(x[c], 1);
  }
  for(const std::vector<Feature_pair>& cut : excluded) {
    Linear_constraint* no_good = solver.create_constraint(-MipTraits::Variable::infinity(), double(cut.size()) - 1);
    for(std::size_t c = 0; c < C; ++c)
      if(std::find(cut.begin(), cut.end(), p.candidates[c]) != cut.end()) no_good->add_coefficient(x[c], 1);
  }
  Linear_objective* objective = solver.create_objective(Linear_objective::MINIMIZE);
  for(std::size_t a = 0; a < C; ++a)
    for(std::size_t b = a + 1; b < C; ++b) {
      const Feature_pair &u = p.candidates[a], &v = p.candidates[b];
      if(u.source == v.source || u.target == v.target) continue;
      const double w = p.distortion(u, v);
      if(w == 0) continue; // M would not change the objective
      Variable* y = solver.create_variable(Variable::CONTINUOUS, 0, 1);
      Linear_constraint* link = solver.create_constraint(-1, MipTraits::Variable::infinity()); // y − x_a − x_b ≥ −1
      link->add_coefficient(y, 1);
      link->add_coefficient(x[a], -1);
      link->add_coefficient(x[b], -1);
      objective->add_coefficient(y, w);
    }
  if(!solver.solve()) throw Solver_failure(std::string(who) + ": " + solver.error_message());
  const std::vector<double>& values = solver.solution();
  Feature_matching result;
  for(std::size_t c = 0; c < C; ++c)
    if(values[static_cast<std::size_t>(x[c]->index())] > 0.5) result.pairs.push_back(p.candidates[c]);
  std::sort(result.pairs.begin(), result.pairs.end());
  if(result.pairs.size() != p.number_of_matches)
    throw Solver_failure(std::string(who) + ": the solver returned " + std::to_string(result.pairs.size()) + " pairs instead of " +
                         std::to_string(p.number_of_matches));
  result.objective = p.objective(result.pairs);
  result.optimal = true;
  return result;
}

/// \ingroup PkgShapeCorrRegistration
/// The assignment problem of the refinement (thesis Eq. 5.4): choose exactly `count` pairs (i, k),
/// one-to-one, minimizing `Σ cost(i, k)`; `+infinity` forbids a pair. Solved exactly as a
/// min-cost flow of value `count` by successive shortest paths (Bellman-Ford on the residual
/// graph; O(count · (n + m) · |pairs|), small for the tens of features of a refinement level).
/// \param cost n × m matrix of nonnegative costs
/// \returns the chosen pairs sorted by source, with their total cost; `optimal` is always true
/// \throws Invalid_argument for negative or NaN costs, or when fewer than `count` pairs can be
///   chosen one-to-one among the finite costs
/// \code
///   Eigen::MatrixXd cost(3, 3);
///   cost << 1, 2, 3,  2, 4, 6,  3, 6, 9;
///   shapecorr::Feature_matching a = shapecorr::solve_assignment(cost, 2); // (0,1), (1,0): cost 4
/// \endcode
inline Feature_matching solve_assignment(const Eigen::MatrixXd& cost, std::size_t count) {
  const std::size_t n = static_cast<std::size_t>(cost.rows()), m = static_cast<std::size_t>(cost.cols());
  if(cost.array().isNaN().any() || (cost.array() < 0).any()) throw Invalid_argument("assignment: the costs must be nonnegative numbers");
  std::vector<Feature_pair> allowed;
  for(std::size_t i = 0; i < n; ++i)
    for(std::size_t k = 0; k < m; ++k)
      if(std::isfinite(cost(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)))) allowed.push_back({i, k});
  if(count == 0) return Feature_matching{{}, 0.0, true, 0};
  if(internal::maximum_matching_size(allowed, n, m) < count)
    throw Invalid_argument("assignment: fewer than " + std::to_string(count) + " pairs can be chosen one-to-one");
  // successive shortest paths (each augmentation keeps the flow of its value minimal); the
  // residual graph has negative arcs (matched column -> row), so paths come from Bellman-Ford,
  // at most n + m rounds each, which also keeps rounding from ever breaking a reduced cost
  const std::size_t none_row = n, none_col = m;
  std::vector<std::size_t> col_of_row(n, none_col), row_of_col(m, none_row), pred(m);
  std::vector<double> to_row(n), to_col(m);
  const double inf = std::numeric_limits<double>::infinity();
  auto c = [&](std::size_t i, std::size_t k) { return cost(static_cast<Eigen::Index>(i), static_cast<Eigen::Index>(k)); };
  for(std::size_t step = 0; step < count; ++step) {
    for(std::size_t i = 0; i < n; ++i) to_row[i] = col_of_row[i] == none_col ? 0.0 : inf;
    std::fill(to_col.begin(), to_col.end(), inf);
    bool changed = true;
    for(std::size_t round = 0; changed && round <= n + m; ++round) {
      changed = false;
      for(const Feature_pair& f : allowed) // row -> column along unmatched pairs
        if(col_of_row[f.source] != f.target && to_row[f.source] + c(f.source, f.target) < to_col[f.target]) {
          to_col[f.target] = to_row[f.source] + c(f.source, f.target);
          pred[f.target] = f.source;
          changed = true;
        }
      for(std::size_t k = 0; k < m; ++k) // column -> its row, back along a matched pair
        if(row_of_col[k] != none_row && to_col[k] - c(row_of_col[k], k) < to_row[row_of_col[k]]) {
          to_row[row_of_col[k]] = to_col[k] - c(row_of_col[k], k);
          changed = true;
        }
    }
    std::size_t end = none_col;
    for(std::size_t k = 0; k < m; ++k)
      if(row_of_col[k] == none_row && to_col[k] < inf && (end == none_col || to_col[k] < to_col[end])) end = k;
    if(end == none_col) break; // cannot happen after the matching-size check; reported below
    for(std::size_t k = end;;) { // flip the path: each row takes the column it was reached from
      const std::size_t i = pred[k], previous = col_of_row[i];
      col_of_row[i] = k;
      row_of_col[k] = i;
      if(previous == none_col) break;
      k = previous;
    }
  }
  Feature_matching result;
  result.optimal = true;
  for(std::size_t i = 0; i < n; ++i)
    if(col_of_row[i] != none_col) {
      result.pairs.push_back({i, col_of_row[i]});
      result.objective += c(i, col_of_row[i]);
    }
  std::sort(result.pairs.begin(), result.pairs.end());
  if(result.pairs.size() != count)
    throw Solver_failure("assignment: the min-cost flow carried " + std::to_string(result.pairs.size()) + " pairs instead of " + std::to_string(count));
  return result;
}

} // namespace shapecorr

#endif
