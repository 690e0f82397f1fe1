// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file operators.h
/// Module header: discrete differential operators of a triangle mesh (cotangent and combinatorial
/// Laplacians, lumped mass matrices), used by geodesics, spectral analysis and registration.
#ifndef SHAPECORR_OPERATORS_H
#define SHAPECORR_OPERATORS_H
#include <shapecorr/operators/laplacian.h>
#endif
