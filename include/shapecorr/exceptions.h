// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file exceptions.h
/// The one small hierarchy of errors that ShapeCorr raises: bad input data, parameters outside their
/// domain, files that cannot be written, solvers that fail. All derive from `shapecorr::Error`.
#ifndef SHAPECORR_EXCEPTIONS_H
#define SHAPECORR_EXCEPTIONS_H

#include <stdexcept>
#include <string>

namespace shapecorr {

/// \ingroup PkgShapeCorrCore
/// Base class of every exception ShapeCorr throws on purpose.
class Error : public std::runtime_error {
public:
  using std::runtime_error::runtime_error;
};

/// \ingroup PkgShapeCorrCore
/// What is wrong with an input mesh (or file); carried by `Invalid_input`.
enum class Mesh_defect {
  unreadable_file,        ///< the file could not be opened or parsed
  empty_mesh,             ///< no vertex or no face
  non_triangle_face,      ///< a face with other than three vertices
  non_finite_coordinate,  ///< a NaN or infinite coordinate
  coordinate_out_of_range, ///< a finite coordinate beyond `max_coordinate_magnitude` (1e38): lengths and areas would overflow
  degenerate_face,        ///< a face of (numerically) zero area, or with a repeated vertex
  non_manifold_edge,      ///< an edge shared by more than two faces, or orientations that disagree
  non_manifold_vertex,    ///< a vertex whose incident faces do not form a single fan
  isolated_vertex,        ///< a vertex used by no face
  boundary,               ///< the surface has boundary edges (where a closed one is required)
  several_components      ///< more than one connected component (where one is required)
};

/// Name of a defect, as used in reports and messages (`"non_manifold_edge"`).
inline const char* to_string(Mesh_defect d) {
  switch(d) {
    case Mesh_defect::unreadable_file: return "unreadable_file";
    case Mesh_defect::empty_mesh: return "empty_mesh";
    case Mesh_defect::non_triangle_face: return "non_triangle_face";
    case Mesh_defect::non_finite_coordinate: return "non_finite_coordinate";
    case Mesh_defect::coordinate_out_of_range: return "coordinate_out_of_range";
    case Mesh_defect::degenerate_face: return "degenerate_face";
    case Mesh_defect::non_manifold_edge: return "non_manifold_edge";
    case Mesh_defect::non_manifold_vertex: return "non_manifold_vertex";
    case Mesh_defect::isolated_vertex: return "isolated_vertex";
    case Mesh_defect::boundary: return "boundary";
    case Mesh_defect::several_components: return "several_components";
  }
  return "unknown";
}

/// \ingroup PkgShapeCorrCore
/// Bad input data: the message says what is wrong and where (file, vertex or face index).
class Invalid_input : public Error {
public:
  /// The kind of defect and a message saying what and where.
  Invalid_input(Mesh_defect defect, const std::string& what)
    : Error(what), m_defect(defect) {}
  /// The kind of problem.
  Mesh_defect defect() const { return m_defect; }
private:
  Mesh_defect m_defect;
};

/// \ingroup PkgShapeCorrCore
/// A parameter outside its domain: a vertex id past the end, a negative radius, a support of zero,
/// descriptors of different shapes compared. The message names the parameter and its valid range.
class Invalid_argument : public Error {
public:
  using Error::Error;
};

/// \ingroup PkgShapeCorrCore
/// A file that cannot be written (missing directory, no permission, disk full); the message names
/// the file.
class Output_error : public Error {
public:
  using Error::Error;
};

/// \ingroup PkgShapeCorrCore
/// A numerical solver (factorization, eigensolver, optimizer) failed; the message says which and why.
class Solver_failure : public Error {
public:
  using Error::Error;
};

} // namespace shapecorr

#endif // SHAPECORR_EXCEPTIONS_H
