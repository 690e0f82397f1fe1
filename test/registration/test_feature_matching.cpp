// The matching problems of chapter 5: the coarse program (branch and bound, GLPK through CGAL's
// MixedIntegerProgramTraits) against exhaustive enumeration and against each other on random
// instances; the refinement's assignment against enumeration; feasibility and bad input.
#include <shapecorr/registration/feature_matching.h>

#include <CGAL/GLPK_mixed_integer_program_traits.h>

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <functional>
#include <random>

using shapecorr::Coarse_matching_problem;
using shapecorr::Feature_matching;
using shapecorr::Feature_pair;

namespace {

Eigen::MatrixXd distances_of(const Eigen::MatrixXd& points) {
  Eigen::MatrixXd d(points.rows(), points.rows());
  for(Eigen::Index i = 0; i < points.rows(); ++i)
    for(Eigen::Index j = 0; j < points.rows(); ++j) d(i, j) = (points.row(i) - points.row(j)).norm();
  return d;
}

// n source points in the unit square, the target: a shuffled, jittered copy of m of them plus
// m - overlap new points; candidates: each source point's `k` nearest target points in a noisy
// "descriptor" (its true position plus noise), so the true pairs are usually but not always there.
Coarse_matching_problem random_problem(std::mt19937& rng, std::size_t n, std::size_t m, std::size_t k, double jitter) {
  std::uniform_real_distribution<double> u(0, 1);
  std::normal_distribution<double> noise(0, jitter);
  Eigen::MatrixXd s(n, 2), t(m, 2);
  for(Eigen::Index i = 0; i < s.size(); ++i) s(i) = u(rng);
  std::vector<std::size_t> perm(m);
  for(std::size_t i = 0; i < m; ++i) perm[i] = i;
  std::shuffle(perm.begin(), perm.end(), rng);
  for(std::size_t k2 = 0; k2 < m; ++k2) {
    const std::size_t i = perm[k2];
    for(int c = 0; c < 2; ++c) t(static_cast<Eigen::Index>(k2), c) = i < n ? s(static_cast<Eigen::Index>(i), c) + noise(rng) : u(rng);
  }
  Coarse_matching_problem p;
  p.source_distances = distances_of(s);
  p.target_distances = distances_of(t);
  for(std::size_t i = 0; i < n; ++i) {
    const Eigen::RowVector2d d = s.row(static_cast<Eigen::Index>(i)) + Eigen::RowVector2d(noise(rng), noise(rng));
    std::vector<std::pair<double, std::size_t>> by;
    for(std::size_t j = 0; j < m; ++j) by.push_back({(t.row(static_cast<Eigen::Index>(j)) - d).norm(), j});
    std::sort(by.begin(), by.end());
    for(std::size_t j = 0; j < std::min(k, m); ++j) p.candidates.push_back({i, by[j].second});
  }
  p.number_of_matches = (4 * std::min(n, m)) / 5;
  return p;
}

// Every one-to-one choice of number_of_matches candidates (small problems only); with `accept`,
// only the choices it accepts.
double exhaustive_minimum(const Coarse_matching_problem& p, const shapecorr::Matching_acceptance& accept = {}) {
  double best = std::numeric_limits<double>::infinity();
  std::vector<Feature_pair> chosen;
  std::function<void(std::size_t)> go = [&](std::size_t c) {
    if(chosen.size() == p.number_of_matches) {
      std::vector<Feature_pair> sorted = chosen;
      std::sort(sorted.begin(), sorted.end());
      if(!accept || accept(sorted)) best = std::min(best, p.objective(chosen));
      return;
    }
    if(c == p.candidates.size()) return;
    const Feature_pair& f = p.candidates[c];
    bool free = true;
    for(const Feature_pair& g : chosen) free = free && g.source != f.source && g.target != f.target;
    if(free) {
      chosen.push_back(f);
      go(c + 1);
      chosen.pop_back();
    }
    go(c + 1);
  };
  go(0);
  return best;
}

void check_one_to_one(const Coarse_matching_problem& p, const Feature_matching& r) {
  REQUIRE(r.pairs.size() == p.number_of_matches);
  for(std::size_t a = 0; a < r.pairs.size(); ++a) {
    CHECK(std::find(p.candidates.begin(), p.candidates.end(), r.pairs[a]) != p.candidates.end());
    for(std::size_t b = a + 1; b < r.pairs.size(); ++b) {
      CHECK(r.pairs[a].source != r.pairs[b].source);
      CHECK(r.pairs[a].target != r.pairs[b].target);
    }
  }
  CHECK(r.objective == Approx(p.objective(r.pairs)).epsilon(1e-12));
}

} // namespace

TEST_CASE("coarse matching: branch and bound equals exhaustive enumeration", "[feature_matching]") {
  std::mt19937 rng(7);
  for(int trial = 0; trial < 30; ++trial) {
    const Coarse_matching_problem p = random_problem(rng, 6, 7, 4, 0.05);
    if(!shapecorr::is_feasible(p)) continue;
    const Feature_matching r = shapecorr::solve_coarse_matching_branch_and_bound(p);
    check_one_to_one(p, r);
    CHECK(r.optimal);
    CHECK(r.objective == Approx(exhaustive_minimum(p)).margin(1e-12));
  }
}

TEST_CASE("coarse matching: an acceptance test (branch and bound) and cuts (GLPK) give the best accepted matching", "[feature_matching]") {
  // the test rejects the two best matchings (found first without it): the answer is the third,
  // as exhaustive enumeration of the accepted ones says
  std::mt19937 rng(5);
  int compared = 0;
  for(int trial = 0; trial < 20; ++trial) {
    const Coarse_matching_problem p = random_problem(rng, 6, 7, 4, 0.05);
    if(!shapecorr::is_feasible(p)) continue;
    const Feature_matching first = shapecorr::solve_coarse_matching_branch_and_bound(p);
    const Feature_matching second =
        shapecorr::solve_coarse_matching_branch_and_bound(p, 50'000'000, [&](const std::vector<Feature_pair>& m) { return m != first.pairs; });
    if(!second.accepted) continue; // a single matching exists
    const shapecorr::Matching_acceptance accept = [&](const std::vector<Feature_pair>& m) { return m != first.pairs && m != second.pairs; };
    const double expected = exhaustive_minimum(p, accept);
    if(!std::isfinite(expected)) continue;
    const Feature_matching third = shapecorr::solve_coarse_matching_branch_and_bound(p, 50'000'000, accept);
    check_one_to_one(p, third);
    CHECK(third.accepted);
    CHECK(third.optimal);
    CHECK(third.objective == Approx(expected).margin(1e-12));
    CHECK(third.objective >= second.objective - 1e-12);
    CGAL::GLPK_mixed_integer_program_traits<double> glpk;
    const Feature_matching mip = shapecorr::solve_coarse_matching_mip(p, glpk, {first.pairs, second.pairs});
    check_one_to_one(p, mip);
    CHECK(mip.objective == Approx(expected).margin(1e-7));
    ++compared;
  }
  CHECK(compared >= 10);
  // nothing accepted: the best rejected matching, flagged
  std::mt19937 rng2(9);
  const Coarse_matching_problem p = random_problem(rng2, 6, 7, 4, 0.05);
  REQUIRE(shapecorr::is_feasible(p));
  const Feature_matching none = shapecorr::solve_coarse_matching_branch_and_bound(p, 50'000'000, [](const std::vector<Feature_pair>&) { return false; });
  CHECK(!none.accepted);
  CHECK(none.objective == Approx(exhaustive_minimum(p)).margin(1e-12));
}

TEST_CASE("coarse matching: branch and bound and GLPK agree on random 10-feature instances", "[feature_matching]") {
  std::mt19937 rng(11);
  int compared = 0;
  for(int trial = 0; trial < 8; ++trial) {
    const Coarse_matching_problem p = random_problem(rng, 10, 10, 3, 0.03);
    if(!shapecorr::is_feasible(p)) continue;
    const Feature_matching bb = shapecorr::solve_coarse_matching_branch_and_bound(p);
    CGAL::GLPK_mixed_integer_program_traits<double> glpk;
    const Feature_matching mip = shapecorr::solve_coarse_matching_mip(p, glpk);
    check_one_to_one(p, bb);
    check_one_to_one(p, mip);
    CHECK(bb.optimal);
    CHECK(bb.objective == Approx(mip.objective).epsilon(1e-7));
    ++compared;
  }
  CHECK(compared >= 5);
}

TEST_CASE("coarse matching: an exact isometric instance is solved by the true pairs", "[feature_matching]") {
  std::mt19937 rng(3);
  // no jitter: the true pairs have distortion 0, and (random points) nothing else does
  Coarse_matching_problem p = random_problem(rng, 10, 10, 10, 0.0);
  const Feature_matching r = shapecorr::solve_coarse_matching_branch_and_bound(p);
  CHECK(r.objective == Approx(0).margin(1e-12));
  for(const Feature_pair& f : r.pairs)
    for(const Feature_pair& g : r.pairs)
      CHECK(p.source_distances(long(f.source), long(g.source)) == Approx(p.target_distances(long(f.target), long(g.target))).margin(1e-12));
}

TEST_CASE("coarse matching: infeasible and malformed problems, the node bound", "[feature_matching]") {
  std::mt19937 rng(5);
  Coarse_matching_problem p = random_problem(rng, 10, 10, 3, 0.03);
  // every candidate to target 0: at most one pair can be chosen
  for(Feature_pair& f : p.candidates) f.target = 0;
  CHECK_FALSE(shapecorr::is_feasible(p));
  CHECK_THROWS_AS(shapecorr::solve_coarse_matching_branch_and_bound(p), shapecorr::Invalid_argument);
  CGAL::GLPK_mixed_integer_program_traits<double> glpk;
  CHECK_THROWS_AS(shapecorr::solve_coarse_matching_mip(p, glpk), shapecorr::Invalid_argument);
  Coarse_matching_problem q = random_problem(rng, 10, 10, 3, 0.03);
  q.candidates.push_back({10, 0});
  CHECK_THROWS_AS(shapecorr::solve_coarse_matching_branch_and_bound(q), shapecorr::Invalid_argument);
  q.candidates.pop_back();
  q.source_distances(0, 1) = std::numeric_limits<double>::quiet_NaN();
  CHECK_THROWS_AS(shapecorr::solve_coarse_matching_branch_and_bound(q), shapecorr::Invalid_argument);
  q.source_distances(0, 1) = q.source_distances(1, 0);
  q.number_of_matches = 0;
  CHECK_THROWS_AS(shapecorr::solve_coarse_matching_branch_and_bound(q), shapecorr::Invalid_argument);
  // the node bound: a valid matching, not proven optimal
  Coarse_matching_problem big = random_problem(rng, 12, 12, 12, 0.1);
  const Feature_matching r = shapecorr::solve_coarse_matching_branch_and_bound(big, 50);
  check_one_to_one(big, r);
  CHECK_FALSE(r.optimal);
  CHECK(r.nodes == 50);
}

TEST_CASE("assignment with a cardinality: min-cost flow equals enumeration", "[feature_matching]") {
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> u(0, 1);
  for(int trial = 0; trial < 20; ++trial) {
    const std::size_t n = 5, m = 6, count = 1 + static_cast<std::size_t>(trial % 5);
    Eigen::MatrixXd cost(n, m);
    for(Eigen::Index i = 0; i < cost.size(); ++i) cost(i) = u(rng) < 0.15 ? std::numeric_limits<double>::infinity() : u(rng);
    // enumeration over injective partial maps
    double best = std::numeric_limits<double>::infinity();
    std::vector<char> used(m);
    std::function<void(std::size_t, std::size_t, double)> go = [&](std::size_t i, std::size_t taken, double sum) {
      if(taken == count) { best = std::min(best, sum); return; }
      if(i == n) return;
      go(i + 1, taken, sum);
      for(std::size_t k = 0; k < m; ++k)
        if(!used[k] && std::isfinite(cost(long(i), long(k)))) {
          used[k] = 1;
          go(i + 1, taken + 1, sum + cost(long(i), long(k)));
          used[k] = 0;
        }
    };
    go(0, 0, 0.0);
    if(!std::isfinite(best)) {
      CHECK_THROWS_AS(shapecorr::solve_assignment(cost, count), shapecorr::Invalid_argument);
      continue;
    }
    const Feature_matching r = shapecorr::solve_assignment(cost, count);
    REQUIRE(r.pairs.size() == count);
    CHECK(r.objective == Approx(best).margin(1e-12));
  }
  Eigen::MatrixXd cost(3, 3);
  cost << 1, 2, 3, 2, 4, 6, 3, 6, 9;
  const Feature_matching a = shapecorr::solve_assignment(cost, 2);
  CHECK(a.objective == Approx(4));
  CHECK(a.pairs == std::vector<Feature_pair>{{0, 1}, {1, 0}});
  cost(0, 0) = -1;
  CHECK_THROWS_AS(shapecorr::solve_assignment(cost, 2), shapecorr::Invalid_argument);
}
