// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file Spectra_eigensolver.h
/// The default model of the `LaplaceBeltramiEigensolver` concept (doc/concepts.md).
#ifndef SHAPECORR_SPECTRAL_SPECTRA_EIGENSOLVER_H
#define SHAPECORR_SPECTRAL_SPECTRA_EIGENSOLVER_H

#include <shapecorr/exceptions.h>
#include <shapecorr/internal/sparse_solver.h>

#include <Eigen/Dense>
#include <Eigen/Sparse>
#include <Spectra/SymEigsShiftSolver.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrSpectral
/// Smallest eigenpairs of the generalized problem `L phi = lambda M phi` with a diagonal (lumped)
/// mass `M`, by Spectra's Lanczos solver in **shift-invert** mode. The problem is turned into the
/// standard symmetric one `C psi = lambda psi`, `C = M^-1/2 L M^-1/2`, `phi = M^-1/2 psi`, whose
/// shifted inverse `(C - sigma I)^-1 = M^1/2 (L - sigma M)^-1 M^1/2` costs one sparse Cholesky
/// factorization (`SparseSolver`) and two triangular solves per Lanczos step. The shift `sigma`
/// is slightly negative (`-shift_factor` times the mean of `L_ii / M_ii`), so `L - sigma M` is
/// positive definite even though `L` is singular (one zero eigenvalue per connected component).
///
/// **Spectrum slicing.** The k pairs are computed in slices of about `slice_size`: Spectra is asked
/// for `slice + margin` pairs nearest a shift (`margin = max(min_margin, margin_fraction * k)`); the
/// values up to the widest gap among the top `margin` ones are kept (a cluster of equal
/// eigenvalues, such as the 2l+1 of a sphere, is never split at the edge of a window); the next
/// shift is placed so that its window starts just below that cut (indefinite `L - sigma M` is
/// factored by `SimplicialLDLT`). After every slice, Sylvester's law of inertia (the negative pivots
/// of the LDL^T factorization of `L - cut M`) checks that no eigenvalue below the cut was missed;
/// if one was (Lanczos can miss a member of a tight cluster), or if the assembled eigenvectors are
/// not M-orthonormal to 1e-8 (a cluster wider than the window was cut), one run over all
/// `k + margin` pairs replaces the slices. The Lanczos cost grows with the square of the subspace
/// (O(n ncv^2)), so several slices of 100 cost less than one run for all k pairs, at the price of
/// one factorization per slice.
/// Small problems (`n <= dense_size` or `k + margin >= n / 2`) use Eigen's dense self-adjoint
/// solver instead.
///
/// Model of `LaplaceBeltramiEigensolver`:
/// `void solve(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& mass, std::size_t k,
///             Eigen::VectorXd& values, Eigen::MatrixXd& vectors) const`,
/// values ascending, vectors n x k and M-orthonormal (`Phi^T M Phi = I`); throws `Solver_failure`.
template <typename SparseSolver = Default_sparse_spd_solver>
struct Spectra_eigensolver {
  std::size_t min_margin = 10;       ///< at least this many extra pairs are computed
  double margin_fraction = 0.1;      ///< and at least this fraction of k
  double tolerance = 1e-10;          ///< Spectra's relative tolerance on the Ritz values
  int max_iterations = 1000;         ///< Spectra's restarts
  double shift_factor = 1e-8;        ///< sigma = -shift_factor * mean(L_ii / M_ii)
  std::size_t dense_size = 400;      ///< up to this many vertices, a dense solve
  double subspace_factor = 2.0;      ///< Lanczos subspace size ncv = subspace_factor * nev + 1 per run
  std::size_t slice_size = 100;      ///< eigenpairs per shift-invert run (spectrum slicing)

  /// The k smallest eigenpairs of `L phi = lambda diag(mass) phi` (the `LaplaceBeltramiEigensolver`
  /// concept, doc/concepts.md): eigenvalues ascending into `values`, M-orthonormal eigenvectors
  /// as the columns of `vectors`. \throws Solver_failure when it cannot deliver k accurate pairs
  void solve(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& mass, std::size_t k,
             Eigen::VectorXd& values, Eigen::MatrixXd& vectors) const {
    const Eigen::Index n = L.rows();
    if(k == 0 || static_cast<Eigen::Index>(k) > n)
      throw Invalid_argument("eigensolver: " + std::to_string(k) + " eigenpairs asked of a " +
                                                            std::to_string(n) + "-vertex mesh (1 <= k <= n)");
    if(!(mass.array() > 0).all() || !mass.allFinite())
      throw Invalid_input(Mesh_defect::isolated_vertex,
                          "eigensolver: a vertex has zero or non-finite area (isolated vertex or only degenerate faces around it)");
    const Eigen::VectorXd isqrt = mass.cwiseSqrt().cwiseInverse();
    const std::size_t margin = std::max(min_margin, static_cast<std::size_t>(std::ceil(margin_fraction * static_cast<double>(k))));
    const Eigen::Index nev = static_cast<Eigen::Index>(k + margin);
    if(n <= static_cast<Eigen::Index>(dense_size) || 2 * nev >= n) {
      const Eigen::MatrixXd C = isqrt.asDiagonal() * Eigen::MatrixXd(L) * isqrt.asDiagonal();
      Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> es(C);
      if(es.info() != Eigen::Success) throw Solver_failure("eigensolver: the dense symmetric eigensolver did not converge");
      values = es.eigenvalues().head(static_cast<Eigen::Index>(k));
      vectors = isqrt.asDiagonal() * es.eigenvectors().leftCols(static_cast<Eigen::Index>(k));
      return;
    }
    const double scale = (L.diagonal().array() / mass.array()).mean();
    const Eigen::VectorXd sqrt_mass = mass.cwiseSqrt();
    // spectrum slicing: successive shift-invert runs, each trusted between two gaps (see above)
    std::vector<double> vals;
    std::vector<Eigen::VectorXd> vecs;
    double cut = -std::numeric_limits<double>::infinity(); // eigenvalues <= cut are done
    double sigma = -shift_factor * scale;
    const std::size_t slice = std::max<std::size_t>(slice_size, 1);
    for(int run = 0; vals.size() < k; ++run) {
      if(run > static_cast<int>(4 * (k / slice + 2)))
        throw Solver_failure("eigensolver: spectrum slicing made no progress after " + std::to_string(run) + " shift-invert runs");
      const std::size_t want = std::min(k - vals.size(), slice);
      const Eigen::Index nev_run = std::min<Eigen::Index>(static_cast<Eigen::Index>(want + margin), n - 2);
      Eigen::VectorXd v;
      Eigen::MatrixXd V;
      run_shift_invert(L, mass, sqrt_mass, sigma, nev_run, v, V); // ascending
      const Eigen::Index m = v.size();
      if(run > 0 && !(v[0] < cut)) { // the window does not reach down to the cut: move it down
        sigma = cut + 0.5 * (sigma - cut);
        continue;
      }
      // the next cut: in the middle of the widest gap in the upper half of the window, so that a
      // cluster of equal eigenvalues at the edge of the window is never split
      Eigen::Index top = -1;
      double gap = -1;
      for(Eigen::Index i2 = std::max<Eigen::Index>(0, std::min<Eigen::Index>(m / 2, m - 1 - static_cast<Eigen::Index>(margin))); i2 < m - 1; ++i2)
        if(v[i2] > cut && v[i2 + 1] - v[i2] > gap) { gap = v[i2 + 1] - v[i2]; top = i2; }
      if(top < 0) { // nothing new below the top of the window: move it up
        sigma = v[m - 1] + 0.5 * (v[m - 1] - v[0]);
        continue;
      }
      const double new_cut = 0.5 * (v[top] + v[top + 1]);
      for(Eigen::Index i2 = 0; i2 <= top; ++i2)
        if(v[i2] > cut) {
          vals.push_back(v[i2]);
          vecs.emplace_back(V.col(i2));
        }
      // Sylvester's law of inertia: the number of eigenvalues below new_cut is the number of
      // negative pivots of L - new_cut M = P^T U D U^T P. Lanczos can miss a member of a tight
      // cluster; then the slices are abandoned for one run over all k pairs.
      if(count_below(L, mass, new_cut) != vals.size()) return one_run(L, mass, sqrt_mass, scale, nev, k, values, vectors);
      cut = new_cut;
      // next window: centred so that its lower edge falls about margin/2 values below the cut
      const double density = static_cast<double>(m - 1) / std::max(v[m - 1] - v[0], 1e-300);
      sigma = cut + 0.5 * static_cast<double>(std::min(k - std::min(k, vals.size()), slice)) / density;
    }
    const Eigen::Index kk = static_cast<Eigen::Index>(k);
    values.resize(kk);
    vectors.resize(n, kk);
    for(Eigen::Index c = 0; c < kk; ++c) {
      values[c] = vals[static_cast<std::size_t>(c)];
      vectors.col(c) = vecs[static_cast<std::size_t>(c)];
    }
    // a cluster cut by a slice boundary comes back as two non-orthogonal halves: check M-orthonormality
    const Eigen::MatrixXd G = vectors.transpose() * mass.asDiagonal() * vectors;
    if((G - Eigen::MatrixXd::Identity(kk, kk)).cwiseAbs().maxCoeff() > 1e-8) one_run(L, mass, sqrt_mass, scale, nev, k, values, vectors);
  }

private:
  // the fallback: one shift-invert run over all k + margin pairs, checked by inertia at a gap above
  // the k-th value; a run that missed an eigenvalue is repeated with a larger request (3 tries)
  void one_run(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& mass, const Eigen::VectorXd& sqrt_mass, double scale,
               Eigen::Index nev, std::size_t k, Eigen::VectorXd& values, Eigen::MatrixXd& vectors) const {
    const Eigen::Index n = L.rows(), kk = static_cast<Eigen::Index>(k);
    for(int attempt = 0; attempt < 3; ++attempt, nev = std::min<Eigen::Index>(n / 2, 2 * nev)) {
      run_shift_invert(L, mass, sqrt_mass, -shift_factor * scale, nev, values, vectors);
      Eigen::Index top = -1;
      double gap = -1;
      for(Eigen::Index i = kk - 1; i < values.size() - 1; ++i)
        if(values[i + 1] - values[i] > gap) { gap = values[i + 1] - values[i]; top = i; }
      if(top >= 0 && count_below(L, mass, 0.5 * (values[top] + values[top + 1])) == static_cast<std::size_t>(top + 1)) {
        values.conservativeResize(kk);
        vectors.conservativeResize(Eigen::NoChange, kk);
        return;
      }
    }
    throw Solver_failure("eigensolver: shift-invert Lanczos kept missing eigenvalues of a cluster (inertia check failed three times)");
  }

  // number of eigenvalues of L phi = lambda M phi below c (inertia of the LDL^T factorization)
  static std::size_t count_below(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& mass, double c) {
    Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> ldlt(L - c * Eigen::SparseMatrix<double>(mass.asDiagonal()));
    if(ldlt.info() != Eigen::Success) return std::numeric_limits<std::size_t>::max(); // forces the fallback
    return static_cast<std::size_t>((ldlt.vectorD().array() < 0).count());
  }

  // the nev eigenpairs nearest sigma, ascending, phi M-orthonormal
  void run_shift_invert(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& mass, const Eigen::VectorXd& sqrt_mass, double sigma,
                        Eigen::Index nev, Eigen::VectorXd& values, Eigen::MatrixXd& vectors) const {
    const Eigen::Index n = L.rows();
    const Eigen::SparseMatrix<double> A = L - sigma * Eigen::SparseMatrix<double>(mass.asDiagonal());
    const Eigen::Index ncv = std::min<Eigen::Index>(n, std::max<Eigen::Index>(static_cast<Eigen::Index>(subspace_factor * static_cast<double>(nev)) + 1, std::max<Eigen::Index>(nev + 2, 20)));
    auto finish = [&](auto& eigs) {
      eigs.init();
      eigs.compute(Spectra::SortRule::LargestMagn, max_iterations, tolerance, Spectra::SortRule::SmallestAlge);
      if(eigs.info() != Spectra::CompInfo::Successful)
        throw Solver_failure("eigensolver: Spectra's shift-invert Lanczos did not converge for " + std::to_string(nev) +
                             " eigenpairs near " + std::to_string(sigma) + " in " + std::to_string(max_iterations) + " restarts (" +
                             (eigs.info() == Spectra::CompInfo::NumericalIssue ? "numerical issue" : "not converging") + ")");
      values = eigs.eigenvalues();
      vectors = sqrt_mass.cwiseInverse().asDiagonal() * eigs.eigenvectors();
    };
    if(sigma < 0) { // L - sigma M is positive definite: the SPD solver policy
      Shift_invert<SparseSolver> op(A, sqrt_mass);
      Spectra::SymEigsShiftSolver<Shift_invert<SparseSolver>> eigs(op, nev, ncv, sigma);
      finish(eigs);
    } else { // indefinite: LDL^T
      Shift_invert<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>> op(A, sqrt_mass);
      Spectra::SymEigsShiftSolver<Shift_invert<Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>>>> eigs(op, nev, ncv, sigma);
      finish(eigs);
    }
  }

  // y = M^1/2 (L - sigma M)^-1 M^1/2 x, the factorization done once
  template <typename Solver>
  struct Shift_invert {
    using Scalar = double;
    Shift_invert(const Eigen::SparseMatrix<double>& A, Eigen::VectorXd sqrt_mass) : m_sqrt(std::move(sqrt_mass)), m_n(A.rows()) {
      internal::factor_or_throw(m_solver, A, "shifted Laplacian L - sigma M (eigensolver)");
    }
    Eigen::Index rows() const { return m_n; }
    Eigen::Index cols() const { return m_n; }
    void set_shift(double) {} // the shift is built into the factored matrix
    void perform_op(const double* x_in, double* y_out) const {
      Eigen::Map<const Eigen::VectorXd> x(x_in, m_n);
      Eigen::Map<Eigen::VectorXd> y(y_out, m_n);
      y = m_sqrt.cwiseProduct(m_solver.solve(m_sqrt.cwiseProduct(x)));
    }
    Solver m_solver;
    Eigen::VectorXd m_sqrt;
    Eigen::Index m_n;
  };
};

} // namespace shapecorr

#endif
