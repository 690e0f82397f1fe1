// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
/// \file io.h
/// Module header: reading meshes with validation and repairs; writing coloured PLY, PNG pictures,
/// spin descriptor plots, line plots and correspondence lines. The top layer: no other module includes it.
#ifndef SHAPECORR_IO_H
#define SHAPECORR_IO_H
#include <shapecorr/io/read_polygon_soup.h>
#include <shapecorr/io/read_triangle_mesh.h>
#include <shapecorr/io/draw_on_picture.h>
#include <shapecorr/io/line_plot.h>
#include <shapecorr/io/render_mesh.h>
#include <shapecorr/io/write_colored_ply.h>
#include <shapecorr/io/write_correspondences.h>
#include <shapecorr/io/write_png.h>
#include <shapecorr/io/write_spin_descriptor_plot.h>
#endif
