// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file sparse_solver.h
/// The default sparse symmetric positive definite solver policy.
///
/// A `SparseSPDSolver` is any type with Eigen's sparse solver interface: default constructible,
/// `compute(const Eigen::SparseMatrix<double>&)`, `info()`, and `solve(B)` for a dense `B` with
/// several columns. The default is CHOLMOD's supernodal Cholesky (through Eigen's CholmodSupport)
/// when ShapeCorr was configured with SuiteSparse (`SHAPECORR_HAS_CHOLMOD`), and Eigen's
/// `SimplicialLDLT` otherwise.
#ifndef SHAPECORR_INTERNAL_SPARSE_SOLVER_H
#define SHAPECORR_INTERNAL_SPARSE_SOLVER_H

#include <shapecorr/exceptions.h>

#include <Eigen/Sparse>
#include <Eigen/SparseCholesky>
#ifdef SHAPECORR_HAS_CHOLMOD
#include <Eigen/CholmodSupport>
#endif

#include <string>

namespace shapecorr {

#ifdef SHAPECORR_HAS_CHOLMOD
typedef Eigen::CholmodSupernodalLLT<Eigen::SparseMatrix<double>, Eigen::Lower> Default_sparse_spd_solver;
#else
typedef Eigen::SimplicialLDLT<Eigen::SparseMatrix<double>> Default_sparse_spd_solver;
#endif

namespace internal {

/// Factor A with `solver`, throwing Solver_failure with `what` in the message on failure.
template <typename Solver>
void factor_or_throw(Solver& solver, const Eigen::SparseMatrix<double>& A, const std::string& what) {
  solver.compute(A);
  if(solver.info() != Eigen::Success)
    throw Solver_failure("sparse Cholesky factorization of the " + what +
                         " failed (matrix not positive definite: degenerate or non-finite geometry?)");
}

} // namespace internal
} // namespace shapecorr

#endif
