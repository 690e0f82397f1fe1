// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file sampling.h
/// Module header: furthest point sampling.
#ifndef SHAPECORR_SAMPLING_H
#define SHAPECORR_SAMPLING_H
#include <shapecorr/sampling/furthest_point_sampling.h>
#endif
