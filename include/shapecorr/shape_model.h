// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file shape_model.h
/// The shape-model module (thesis chapter 6: statistical shape models of template-fitted bones):
/// `Statistical_shape_model` (Procrustes alignment, PCA, instances, projection, its file), the
/// quality measures (compactness, generalization, specificity) and the template fit of a specimen.
/// The Statismo HDF5 layout is in `shapecorr/shape_model/statismo_io.h` (needs HDF5; not included here).
#ifndef SHAPECORR_SHAPE_MODEL_H
#define SHAPECORR_SHAPE_MODEL_H
#include <shapecorr/shape_model/Statistical_shape_model.h>
#include <shapecorr/shape_model/fit_template.h>
#include <shapecorr/shape_model/shape_model_quality.h>
#endif
