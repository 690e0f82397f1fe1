// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file evaluation.h
/// The evaluation module: the descriptor ranking of chapter 4 (hit rate, geodesic error) and the
/// surface distances of chapter 6 (l1, l2, lmax, landmark distances).
#ifndef SHAPECORR_EVALUATION_H
#define SHAPECORR_EVALUATION_H
#include <shapecorr/evaluation/descriptor_ranking.h>
#include <shapecorr/evaluation/map_geodesic_error.h>
#include <shapecorr/evaluation/surface_distance.h>
#endif
