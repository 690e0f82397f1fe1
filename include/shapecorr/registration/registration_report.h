// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file registration_report.h
/// What every iterative registration method reports: one record per iteration and the reason it
/// stopped. "Did not converge" is a report value, not an exception; bad input is an exception.
#ifndef SHAPECORR_REGISTRATION_REGISTRATION_REPORT_H
#define SHAPECORR_REGISTRATION_REGISTRATION_REPORT_H

#include <cstddef>
#include <vector>

namespace shapecorr {

/// \ingroup PkgShapeCorrRegistration
/// Why an iterative registration stopped.
enum class Stop_reason {
  CONVERGED,       ///< the objective stopped decreasing (relative change below the tolerance)
  NO_MOTION,       ///< an iteration moved nothing by more than the tolerance
  ITERATION_LIMIT, ///< `number_of_iterations` reached
  TOO_FEW_PAIRS,   ///< fewer correspondence pairs than the unknowns need (no overlap, or all rejected)
  CANCELLED        ///< the iteration callback returned false
};

/// \ingroup PkgShapeCorrRegistration
/// The name of a stop reason ("converged", "no_motion", "iteration_limit", "too_few_pairs", "cancelled").
inline const char* to_string(Stop_reason r) {
  switch(r) {
    case Stop_reason::CONVERGED: return "converged";
    case Stop_reason::NO_MOTION: return "no_motion";
    case Stop_reason::ITERATION_LIMIT: return "iteration_limit";
    case Stop_reason::TOO_FEW_PAIRS: return "too_few_pairs";
    case Stop_reason::CANCELLED: return "cancelled";
  }
  return "unknown";
}

/// \ingroup PkgShapeCorrRegistration
/// One iteration of a registration method.
struct Iteration_record {
  std::size_t iteration = 0; ///< 0-based
  std::size_t pairs = 0;     ///< correspondence pairs used
  double energy = 0;         ///< the objective the iteration minimized (method-specific, documented there)
  double rms_distance = 0;   ///< root mean square distance of the template's vertices to the target surface after the iteration
  double step = 0;           ///< the largest displacement of a point by the update (mesh units)
};

/// \ingroup PkgShapeCorrRegistration
/// The result of a baseline registration method (`andresen_registration()`,
/// `pauly_registration()`, `cpd_registration()`, `gmm_l2_registration()`); NICPS has its own,
/// with more per iteration (`Nicps_report`).
struct Registration_report {
  std::vector<Iteration_record> iterations;        ///< one per iteration (see each method for what an iteration is)
  Stop_reason stop = Stop_reason::ITERATION_LIMIT; ///< why it stopped
  double initial_rms = 0; ///< root mean square distance of the template's vertices to the target surface before
  double final_rms = 0;   ///< and after
  double seconds = 0;     ///< wall time
};

} // namespace shapecorr

#endif
