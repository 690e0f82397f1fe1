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
#include <string>

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
/// Spectra is asked for `k + margin` pairs, `margin = max(min_margin, margin_fraction * k)`, and the
/// `k` smallest are returned: Lanczos converges poorly on the last pairs it is asked for, and a
/// cluster of equal eigenvalues (the 2l+1 of a sphere) cut by the request would come back
/// incomplete. Small problems (`n <= dense_size` or `k + margin >= n / 2`) use Eigen's dense
/// self-adjoint solver instead.
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
  double subspace_factor = 2.0;      ///< Lanczos subspace size ncv = subspace_factor * (k + margin) + 1

  void solve(const Eigen::SparseMatrix<double>& L, const Eigen::VectorXd& mass, std::size_t k,
             Eigen::VectorXd& values, Eigen::MatrixXd& vectors) const {
    const Eigen::Index n = L.rows();
    if(k == 0 || static_cast<Eigen::Index>(k) > n)
      throw Invalid_input(Mesh_defect::invalid_argument, "eigensolver: " + std::to_string(k) + " eigenpairs asked of a " +
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
    const double sigma = -shift_factor * (L.diagonal().array() / mass.array()).mean();
    const Eigen::SparseMatrix<double> A = L - sigma * Eigen::SparseMatrix<double>(mass.asDiagonal());
    Shift_invert op(A, mass.cwiseSqrt());
    const Eigen::Index ncv = std::min<Eigen::Index>(n, std::max<Eigen::Index>(static_cast<Eigen::Index>(subspace_factor * static_cast<double>(nev)) + 1, std::max<Eigen::Index>(nev + 2, 20)));
    Spectra::SymEigsShiftSolver<Shift_invert> eigs(op, nev, ncv, sigma);
    eigs.init();
    eigs.compute(Spectra::SortRule::LargestMagn, max_iterations, tolerance, Spectra::SortRule::SmallestAlge);
    if(eigs.info() != Spectra::CompInfo::Successful)
      throw Solver_failure("eigensolver: Spectra's shift-invert Lanczos did not converge for " + std::to_string(nev) +
                           " eigenpairs in " + std::to_string(max_iterations) + " restarts (" +
                           (eigs.info() == Spectra::CompInfo::NumericalIssue ? "numerical issue" : "not converging") + ")");
    values = eigs.eigenvalues().head(static_cast<Eigen::Index>(k));
    vectors = isqrt.asDiagonal() * eigs.eigenvectors().leftCols(static_cast<Eigen::Index>(k));
  }

private:
  // y = M^1/2 (L - sigma M)^-1 M^1/2 x, the factorization done once
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
    SparseSolver m_solver;
    Eigen::VectorXd m_sqrt;
    Eigen::Index m_n;
  };
};

} // namespace shapecorr

#endif
