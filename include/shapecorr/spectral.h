// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file spectral.h
/// Module header: the Laplace-Beltrami eigenbasis (Spectra) and the spectral descriptors HKS, WKS,
/// SI-HKS (and, for convenience, the Laplace operators of `shapecorr/operators.h`).
#ifndef SHAPECORR_SPECTRAL_H
#define SHAPECORR_SPECTRAL_H
#include <shapecorr/operators.h>
#include <shapecorr/spectral/Intrinsic_shape_context.h>
#include <shapecorr/spectral/Laplace_beltrami_eigenbasis.h>
#include <shapecorr/spectral/Spectra_eigensolver.h>
#include <shapecorr/spectral/compute_heat_kernel_signature.h>
#include <shapecorr/spectral/compute_scale_invariant_heat_kernel_signature.h>
#include <shapecorr/spectral/compute_wave_kernel_signature.h>
#include <shapecorr/spectral/spectral_descriptor_distance.h>
#include <shapecorr/spectral/spectral_signature_matrix.h>
#endif
