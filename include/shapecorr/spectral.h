// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file spectral.h
/// Module header: Laplace operators, the Laplace-Beltrami eigenbasis (Spectra), and the spectral
/// descriptors HKS, WKS, SI-HKS.
#ifndef SHAPECORR_SPECTRAL_H
#define SHAPECORR_SPECTRAL_H
#include <shapecorr/spectral/Laplace_beltrami_eigenbasis.h>
#include <shapecorr/spectral/Spectra_eigensolver.h>
#include <shapecorr/spectral/compute_heat_kernel_signature.h>
#include <shapecorr/spectral/compute_scale_invariant_heat_kernel_signature.h>
#include <shapecorr/spectral/compute_wave_kernel_signature.h>
#include <shapecorr/spectral/laplacian.h>
#include <shapecorr/spectral/spectral_descriptor_distance.h>
#endif
