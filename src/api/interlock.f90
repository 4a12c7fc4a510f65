!> interlock: a cohesive-zone law for rough interfaces (Serpieri, Alfano, Sacco) with damage,
!> friction, interlocking, finite asperity depth and asperity wear. `use interlock` is all a
!> user needs: the material and solver types, the state, the update, the material table and
!> the PROPS/STATEV packing of the UMAT.
module interlock
  use interlock_kinds, only: dp, pi, deg_to_rad, rad_to_deg, infinite_threshold, &
      separation_bound, is_finite_bits, is_finite_value, is_infinite_value, is_nan_value, &
      same_value, exponent_bits, within_separation_bound
  use interlock_status, only: interlock_info_t, status_ok, status_bad_input, status_local_failure, &
      message_len
  use interlock_numbers, only: key_in_range, keys_in_range, format_real, format_reals, format_integer
  use interlock_material_table
  use interlock_material, only: interlock_material_t, interlock_solver_t, max_planes, &
      max_azimuths, interlock_material_prepare, interlock_paper_ria, &
      interlock_azimuthal_ria, interlock_general_ria, scheme_explicit, scheme_implicit, &
      scheme_trapezoidal, scheme_name, effect_damage, effect_friction, effect_interlocking, &
      effect_finite_depth, effect_wear, effect_names, n_effects, kernel_general, kernel_flat, &
      kernel_inclined, kernel_cohesive
  use interlock_material_rows, only: material_from_rows, rows_n_azimuths
  use interlock_state, only: interlock_state_t, interlock_state_init, interlock_state_3d_t, &
      interlock_state_3d_init
  use interlock_integrate, only: interlock_update
  use interlock_integrate_3d, only: interlock_update_3d
  use interlock_props, only: props_to_material, props_n_to_material, statev_to_state, &
      state_to_statev, umat_controls_t, &
      statev_bounds, statev_bad_index, statev_message, state_bound, props_n_to_material_3d, props_n_planes_3d, &
      statev_bad_index_3d, statev_message_3d, statev_to_state_3d, state_to_statev_3d, statev_range, &
      statev_variable
  use interlock_host_tangent, only: interlock_symmetric_tangent, interlock_symmetric_tangent_3d
  use interlock_version, only: interlock_version_string
  use interlock_replay, only: interlock_write_replay_deck
  implicit none
  public
end module interlock
