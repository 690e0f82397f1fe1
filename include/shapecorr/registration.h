// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file registration.h
/// The registration module (thesis chapter 6): rigid alignment, NICPS, the baselines the thesis
/// compares it with (Andresen 2001, Pauly 2005, CPD, GMM-L2) and the report shape of the
/// iterative methods.
#ifndef SHAPECORR_REGISTRATION_H
#define SHAPECORR_REGISTRATION_H
#include <shapecorr/registration/registration_report.h>
#include <shapecorr/registration/nicps.h>
#include <shapecorr/registration/rigid_alignment.h>
#include <shapecorr/registration/andresen_registration.h>
#include <shapecorr/registration/pauly_registration.h>
#include <shapecorr/registration/cpd_registration.h>
#include <shapecorr/registration/gmm_l2_registration.h>
#endif
