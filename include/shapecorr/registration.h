// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file registration.h
/// The registration module: fully automatic near-isometric correspondence (thesis chapter 5) with
/// its matching problems; rigid alignment, NICPS, the baselines the thesis compares it with
/// (Andresen 2001, Pauly 2005, CPD, GMM-L2) and the report shape of the iterative methods
/// (chapter 6).
#ifndef SHAPECORR_REGISTRATION_H
#define SHAPECORR_REGISTRATION_H
#include <shapecorr/registration/registration_report.h>
#include <shapecorr/registration/nicps.h>
#include <shapecorr/registration/rigid_alignment.h>
#include <shapecorr/registration/andresen_registration.h>
#include <shapecorr/registration/pauly_registration.h>
#include <shapecorr/registration/cpd_registration.h>
#include <shapecorr/registration/gmm_l2_registration.h>
#include <shapecorr/registration/feature_matching.h>
#include <shapecorr/registration/isometric_correspondence.h>
#endif
