// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file registration.h
/// The registration module (thesis chapter 6): rigid alignment, NICPS, and the report shape of the
/// iterative methods. The baselines are to come.
#ifndef SHAPECORR_REGISTRATION_H
#define SHAPECORR_REGISTRATION_H
#include <shapecorr/registration/registration_report.h>
#include <shapecorr/registration/nicps.h>
#include <shapecorr/registration/rigid_alignment.h>
#endif
