// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file mesh.h
/// Module header: mesh validation.
#ifndef SHAPECORR_MESH_H
#define SHAPECORR_MESH_H
#include <shapecorr/mesh/validate_mesh.h>
#endif
