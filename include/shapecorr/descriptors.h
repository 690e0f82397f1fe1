// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file descriptors.h
/// The rigid descriptors of thesis chapter 3: spin image, face-based spin image, improved spin
/// image, Spin Contour, the oriented-point axes, the contour L1 distance (exact, and approximate from
/// prepared distance fields) and descriptor matching;
/// the Geodesic Spin Contour and geodesic spin image of chapter 4.
#ifndef SHAPECORR_DESCRIPTORS_H
#define SHAPECORR_DESCRIPTORS_H

#include <shapecorr/descriptors/Contour_distance_field.h>
#include <shapecorr/descriptors/Contour_nearest_point_index.h>
#include <shapecorr/descriptors/Geodesic_spin_descriptors.h>
#include <shapecorr/descriptors/Spin_contour.h>
#include <shapecorr/descriptors/Spin_descriptors.h>
#include <shapecorr/descriptors/Spin_image.h>
#include <shapecorr/descriptors/match_contours.h>
#include <shapecorr/descriptors/match_descriptors.h>

#endif
