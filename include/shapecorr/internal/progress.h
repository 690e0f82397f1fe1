// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// Internal: the progress callback of the named parameters (done, total), empty when not given.
#ifndef SHAPECORR_INTERNAL_PROGRESS_H
#define SHAPECORR_INTERNAL_PROGRESS_H

#include <shapecorr/parameters.h>

#include <functional>

namespace shapecorr {
namespace internal {

template <typename NamedParameters>
std::function<void(std::size_t, std::size_t)> progress_of(const NamedParameters& np) {
  using parameters::choose_parameter;
  using parameters::get_parameter;
  return choose_parameter(get_parameter(np, internal_np::progress_callback),
                          std::function<void(std::size_t, std::size_t)>());
}

} // namespace internal
} // namespace shapecorr

#endif
