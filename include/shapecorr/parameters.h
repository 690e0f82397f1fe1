// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file parameters.h
/// ShapeCorr's named parameters, next to CGAL's.
///
/// Every optional input of a ShapeCorr function is a named parameter. CGAL's own tags
/// (`vertex_point_map`, `vertex_index_map`, `random_seed`, `verbose`, `number_of_iterations`...) are
/// read as CGAL reads them, so `CGAL::parameters::vertex_point_map(vpm)` works as it is. ShapeCorr
/// adds its tags in `shapecorr::internal_np`; their builders live in `shapecorr::parameters`, which
/// also offers every CGAL builder, so one chain can mix both in any order:
/// \code
///   namespace SP = shapecorr::parameters;
///   shapecorr::compute_geodesic_distances(tm, sources, dmap,
///       SP::geodesic_method(shapecorr::Geodesic_method::EXACT).vertex_point_map(vpm));
/// \endcode
#ifndef SHAPECORR_PARAMETERS_H
#define SHAPECORR_PARAMETERS_H

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace shapecorr {

#ifndef SHAPECORR_DOXYGEN_RUNNING // (the tags and builders are generated from one list)
namespace internal_np {
#define SHAPECORR_add_named_parameter(X, Y, Z) enum X { Y };
#include <shapecorr/internal/parameters_interface.h>
#undef SHAPECORR_add_named_parameter
} // namespace internal_np
#endif

/// A chain of named parameters: CGAL's `Named_function_parameters` (so CGAL's `get_parameter`
/// reads it) that can be extended with CGAL's and ShapeCorr's tags alike.
template <typename T, typename Tag, typename Base = CGAL::internal_np::No_property>
struct Named_function_parameters : CGAL::Named_function_parameters<T, Tag, Base> {
  typedef CGAL::Named_function_parameters<T, Tag, Base> cgal_base; ///< what CGAL's functions read
  typedef Named_function_parameters<T, Tag, Base> self;             ///< this chain
  Named_function_parameters() : cgal_base() {}                      ///< the empty chain
  Named_function_parameters(const T& v) : cgal_base(v) {}           ///< a chain of one parameter
  Named_function_parameters(const T& v, const Base& b) : cgal_base(v, b) {} ///< parameter `v` in front of chain `b`
#ifndef SHAPECORR_DOXYGEN_RUNNING

#define CGAL_add_named_parameter(X, Y, Z)                                                          \
  template <typename K>                                                                            \
  Named_function_parameters<K, CGAL::internal_np::X, self> Z(const K& k) const {                  \
    return Named_function_parameters<K, CGAL::internal_np::X, self>(k, *this);                    \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#define SHAPECORR_add_named_parameter(X, Y, Z)                                                     \
  template <typename K>                                                                            \
  Named_function_parameters<K, internal_np::X, self> Z(const K& k) const {                        \
    return Named_function_parameters<K, internal_np::X, self>(k, *this);                          \
  }
#include <shapecorr/internal/parameters_interface.h>
#undef SHAPECORR_add_named_parameter
#endif
};

namespace parameters {

/// The empty chain (every parameter at its default).
inline Named_function_parameters<bool, CGAL::internal_np::all_default_t> default_values() {
  return Named_function_parameters<bool, CGAL::internal_np::all_default_t>();
}

#ifndef SHAPECORR_DOXYGEN_RUNNING
#define CGAL_add_named_parameter(X, Y, Z)                                                          \
  template <typename K>                                                                            \
  Named_function_parameters<K, CGAL::internal_np::X> Z(const K& p) {                              \
    return Named_function_parameters<K, CGAL::internal_np::X>(p);                                 \
  }
#include <CGAL/STL_Extension/internal/parameters_interface.h>
#undef CGAL_add_named_parameter
#define SHAPECORR_add_named_parameter(X, Y, Z)                                                     \
  template <typename K>                                                                            \
  Named_function_parameters<K, internal_np::X> Z(const K& p) {                                    \
    return Named_function_parameters<K, internal_np::X>(p);                                       \
  }
#include <shapecorr/internal/parameters_interface.h>
#undef SHAPECORR_add_named_parameter
#endif

/// The type of `CGAL::parameters::default_values()`: the default of every `np` argument.
typedef CGAL::parameters::Default_named_parameters Default_named_parameters;
using CGAL::parameters::choose_parameter;
using CGAL::parameters::get_parameter;
using CGAL::parameters::is_default_parameter;

} // namespace parameters
} // namespace shapecorr

#endif // SHAPECORR_PARAMETERS_H
