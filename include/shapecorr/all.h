// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file all.h
/// Everything ShapeCorr offers (convenient, slow to compile: prefer the module headers).
#ifndef SHAPECORR_ALL_H
#define SHAPECORR_ALL_H
#include <shapecorr/exceptions.h>
#include <shapecorr/geodesics.h>
#include <shapecorr/io.h>
#include <shapecorr/mesh.h>
#include <shapecorr/mesh/primitives.h>
#include <shapecorr/operators.h>
#include <shapecorr/parameters.h>
#include <shapecorr/sampling.h>
#include <shapecorr/spectral.h>
#include <shapecorr/descriptors.h>
#include <shapecorr/registration.h>
#include <shapecorr/evaluation.h>
#include <shapecorr/shape_model.h>
#endif
