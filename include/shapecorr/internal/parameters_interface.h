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
// spectral
SHAPECORR_add_named_parameter(mass_matrix_type_t, mass_matrix_type, mass_matrix_type)
SHAPECORR_add_named_parameter(eigensolver_t, eigensolver, eigensolver)
SHAPECORR_add_named_parameter(eigenbasis_t, eigenbasis, eigenbasis)
SHAPECORR_add_named_parameter(number_of_eigenpairs_t, number_of_eigenpairs, number_of_eigenpairs)
SHAPECORR_add_named_parameter(number_of_scales_t, number_of_scales, number_of_scales)
SHAPECORR_add_named_parameter(time_range_t, time_range, time_range)
SHAPECORR_add_named_parameter(energy_range_t, energy_range, energy_range)
SHAPECORR_add_named_parameter(wks_sigma_factor_t, wks_sigma_factor, wks_sigma_factor)
SHAPECORR_add_named_parameter(log_time_base_t, log_time_base, log_time_base)
SHAPECORR_add_named_parameter(log_time_range_t, log_time_range, log_time_range)
SHAPECORR_add_named_parameter(log_time_step_t, log_time_step, log_time_step)
SHAPECORR_add_named_parameter(time_unit_t, time_unit, time_unit)
SHAPECORR_add_named_parameter(frequency_range_t, frequency_range, frequency_range)
SHAPECORR_add_named_parameter(normalize_per_scale_t, normalize_per_scale, normalize_per_scale)
// rigid descriptors
SHAPECORR_add_named_parameter(support_length_t, support_length, support_length)
SHAPECORR_add_named_parameter(image_rows_t, image_rows, image_rows)
SHAPECORR_add_named_parameter(image_columns_t, image_columns, image_columns)
SHAPECORR_add_named_parameter(spin_axis_t, spin_axis, spin_axis)
SHAPECORR_add_named_parameter(central_radius_t, central_radius, central_radius)
SHAPECORR_add_named_parameter(lrf_radius_t, lrf_radius, lrf_radius)
SHAPECORR_add_named_parameter(support_angle_t, support_angle, support_angle)
SHAPECORR_add_named_parameter(face_samples_per_bin_t, face_samples_per_bin, face_samples_per_bin)
// geodesic spin descriptors
SHAPECORR_add_named_parameter(support_fraction_t, support_fraction, support_fraction)
SHAPECORR_add_named_parameter(agd_radius_fraction_t, agd_radius_fraction, agd_radius_fraction)
SHAPECORR_add_named_parameter(geodesic_diameter_t, geodesic_diameter, geodesic_diameter)
SHAPECORR_add_named_parameter(agd_scale_t, agd_scale, agd_scale)
SHAPECORR_add_named_parameter(agd_offset_t, agd_offset, agd_offset)
