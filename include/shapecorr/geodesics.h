// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file geodesics.h
/// Module header: geodesic distances (exact, heat method, fast marching; single, multi-source,
/// all-pairs, radius-limited), geodesic diameter, average geodesic distance.
#ifndef SHAPECORR_GEODESICS_H
#define SHAPECORR_GEODESICS_H
#include <shapecorr/geodesics/Exact_geodesics.h>
#include <shapecorr/geodesics/Fast_marching_geodesics.h>
#include <shapecorr/geodesics/Heat_method_geodesics.h>
#include <shapecorr/geodesics/all_pairs_geodesic_distances.h>
#include <shapecorr/geodesics/average_geodesic_distance.h>
#include <shapecorr/geodesics/compute_geodesic_distances.h>
#include <shapecorr/geodesics/geodesic_diameter.h>
#include <shapecorr/geodesics/geodesic_method.h>
#include <shapecorr/geodesics/with_geodesic_engine.h>
#endif
