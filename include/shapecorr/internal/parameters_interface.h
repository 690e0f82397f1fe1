// Copyright (c) 2026 ShapeCorr contributors.
// SPDX-License-Identifier: GPL-3.0-or-later
// No include guard: this file is included several times with different macro definitions.
// SHAPECORR_add_named_parameter(tag type, tag value, builder name)

// geodesics
SHAPECORR_add_named_parameter(geodesic_method_t, geodesic_method, geodesic_method)
SHAPECORR_add_named_parameter(time_step_factor_t, time_step_factor, time_step_factor)
SHAPECORR_add_named_parameter(use_intrinsic_delaunay_t, use_intrinsic_delaunay, use_intrinsic_delaunay)
SHAPECORR_add_named_parameter(geodesic_engine_t, geodesic_engine, geodesic_engine)
SHAPECORR_add_named_parameter(number_of_threads_t, number_of_threads, number_of_threads)
SHAPECORR_add_named_parameter(batch_size_t, batch_size, batch_size)
SHAPECORR_add_named_parameter(number_of_sources_t, number_of_sources, number_of_sources)
SHAPECORR_add_named_parameter(progress_callback_t, progress_callback, progress_callback)
// sampling
SHAPECORR_add_named_parameter(distance_metric_t, distance_metric, distance_metric)
SHAPECORR_add_named_parameter(first_vertex_t, first_vertex, first_vertex)
SHAPECORR_add_named_parameter(keep_first_vertex_t, keep_first_vertex, keep_first_vertex)
