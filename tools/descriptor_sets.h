// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// The descriptors the command line knows (spectral, rigid, geodesic) as one type-erased set per
// shape, with their options read from the command line; shared by `descriptors` and `match`.
#ifndef SHAPECORR_TOOLS_DESCRIPTOR_SETS_H
#define SHAPECORR_TOOLS_DESCRIPTOR_SETS_H

#include "cli_common.h"

#include <shapecorr/descriptors/Geodesic_spin_descriptors.h>
#include <shapecorr/descriptors/Spin_contour.h>
#include <shapecorr/descriptors/Spin_image.h>
#include <shapecorr/descriptors/match_contours.h>

#include <Eigen/Core>

namespace cli {

bool is_rigid(const std::string& type);
bool is_spectral(const std::string& type);
bool is_geodesic(const std::string& type);
bool is_contour(const std::string& type);
/// Throws a usage error unless `type` is a descriptor name.
void check_descriptor_type(const std::string& type, const std::string& option);

/// The options of the descriptors, for the option tables of `descriptors` and `match`.
std::vector<Option> descriptor_options();

/// Descriptors of one kind for some vertices of a mesh: exactly one member is filled.
struct Descriptor_set {
  std::vector<shapecorr::Spin_image> images;
  std::vector<shapecorr::Spin_contour> contours;
  Eigen::MatrixXd rows; // spectral: one row per vertex
  std::size_t size() const;
};

/// The descriptors `type` of the vertices `ids` of `m`. Rigid support and central radius are
/// fractions of `reference`'s extent (the target when matching); geodesic ones take the
/// normalization `*norm` when it is set (geodesic_diameter != 0), else set it to `m`'s.
Descriptor_set compute_descriptor_set(const Mesh& m, const std::vector<std::size_t>& ids, const std::string& type, const Args& a,
                                      const Mesh& reference, const std::string& label,
                                      shapecorr::Geodesic_spin_normalization* norm = nullptr);

/// The k nearest target descriptors of every source (contours compared as `comparison` says).
std::vector<std::vector<shapecorr::Descriptor_neighbor>> nearest_descriptors(const Descriptor_set& sources, const Descriptor_set& targets,
                                                                            std::size_t k, shapecorr::Contour_comparison comparison);

/// The descriptor distance from element `k` of `from` to every element of `to`.
std::vector<double> distances_from(const Descriptor_set& from, const Descriptor_set& to, std::size_t k);

/// --plot V: a spin image (or geodesic spin image) and its contour side by side, as a PNG.
void write_descriptor_plot(const Mesh& m, const Args& a, const std::string& type, std::size_t v, const std::string& output);

std::vector<std::size_t> all_ids(std::size_t n);

} // namespace cli

#endif
