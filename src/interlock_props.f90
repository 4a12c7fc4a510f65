!> The one pack/unpack between the material table's PROPS and STATEV layouts (used by the
!> UMAT) and the library's material, solver and state types.
module interlock_props
  use interlock_kinds, only: dp, deg_to_rad
  use interlock_material_table, only: properties, n_properties, n_required_properties, &
      check_property, umat_planes, umat_nstatv, statevar_index, &
      prop_sigma0_n, prop_sigma0_t, prop_gc, prop_eta, prop_mu, prop_h_n, prop_theta0, &
      prop_thetaf, prop_zeta0, prop_prefractured, prop_scheme, prop_substep_tol, prop_max_dd, &
      prop_max_dtheta, prop_effect_damage, &
      sv_damage, sv_beta, sv_frictional_slip, sv_zeta, sv_theta, sv_friction_traction, &
      sv_work, sv_damage_dissipation, sv_friction_dissipation, sv_initialized
  use interlock_material, only: interlock_material_t, interlock_solver_t, &
      interlock_material_prepare, interlock_paper_ria, n_effects
  use interlock_state, only: interlock_state_t, interlock_state_init
  use interlock_status, only: status_ok, status_bad_input
  implicit none
  private
  public :: props_to_material, statev_to_state, state_to_statev, umat_controls_t

  !> What the UMAT needs besides the material: the accuracy bounds behind PNEWDT.
  type :: umat_controls_t
    real(dp) :: max_damage_increment = 0.25_dp
    real(dp) :: max_angle_increment = 1.0_dp * deg_to_rad  !< [rad]
  end type umat_controls_t

contains

  !> Read and validate PROPS(1:nprops). Missing optional properties take their defaults.
  pure subroutine props_to_material(props, mat, solver, controls, stat, message)
    real(dp), intent(in) :: props(:)
    type(interlock_material_t), intent(out) :: mat
    type(interlock_solver_t), intent(out) :: solver
    type(umat_controls_t), intent(out) :: controls
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    real(dp) :: v(n_properties)
    integer :: i
    logical :: ok
    character(len=16) :: b1, b2, b3

    stat = status_bad_input
    if (size(props) < n_required_properties .or. size(props) > n_properties) then
      write (b1, '(i0)') size(props)
      write (b2, '(i0)') n_required_properties
      write (b3, '(i0)') n_properties
      message = 'NPROPS = ' // trim(b1) // ' is inadmissible: admissible ' // trim(b2) // &
                ' <= NPROPS <= ' // trim(b3) // ' (see interlock-query --props)'
      return
    end if
    v = properties%default
    v(1:size(props)) = props
    do i = 1, n_properties
      call check_property(i, v(i), ok, message)
      if (.not. ok) then
        write (b1, '(i0)') i
        message = 'PROPS(' // trim(b1) // '): ' // trim(message)
        return
      end if
    end do
    if (v(prop_thetaf) > v(prop_theta0)) then
      message = "property 'thetaf_deg' must not exceed 'theta0_deg': admissible 0 <= thetaf_deg" &
                // ' <= theta0_deg'
      return
    end if
    mat%sigma0_n = v(prop_sigma0_n)
    mat%sigma0_t = v(prop_sigma0_t)
    mat%gc = v(prop_gc)
    mat%eta = v(prop_eta)
    mat%mu = v(prop_mu)
    mat%h_n = v(prop_h_n)
    mat%prefractured = v(prop_prefractured) > 0.5_dp
    call interlock_paper_ria(mat, v(prop_theta0) * deg_to_rad, v(prop_thetaf) * deg_to_rad, &
                             v(prop_zeta0))
    do i = 1, n_effects
      mat%effect(i) = v(prop_effect_damage + i - 1) > 0.5_dp
    end do
    solver%scheme = nint(v(prop_scheme))
    solver%substep_tol = v(prop_substep_tol)
    controls%max_damage_increment = v(prop_max_dd)
    controls%max_angle_increment = v(prop_max_dtheta) * deg_to_rad
    call interlock_material_prepare(mat, stat, message)
  end subroutine props_to_material

  !> STATEV -> state; an uninitialised STATEV (all zero, as FE codes start) gives the virgin
  !> state of the material.
  pure subroutine statev_to_state(statev, mat, state)
    real(dp), intent(in) :: statev(umat_nstatv)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_state_t), intent(out) :: state
    integer :: k
    if (statev(statevar_index(sv_initialized, 0)) < 0.5_dp) then
      call interlock_state_init(mat, state)
      return
    end if
    do k = 1, umat_planes
      state%damage(k) = statev(statevar_index(sv_damage, k))
      state%beta(k) = statev(statevar_index(sv_beta, k))
      state%sf(k) = statev(statevar_index(sv_frictional_slip, k))
      state%zeta(k) = statev(statevar_index(sv_zeta, k))
      state%theta(k) = statev(statevar_index(sv_theta, k))
      state%tauf(k) = statev(statevar_index(sv_friction_traction, k))
    end do
    state%work = statev(statevar_index(sv_work, 0))
    state%diss_damage = statev(statevar_index(sv_damage_dissipation, 0))
    state%diss_friction = statev(statevar_index(sv_friction_dissipation, 0))
  end subroutine statev_to_state

  pure subroutine state_to_statev(state, statev)
    type(interlock_state_t), intent(in) :: state
    real(dp), intent(inout) :: statev(umat_nstatv)
    integer :: k
    do k = 1, umat_planes
      statev(statevar_index(sv_damage, k)) = state%damage(k)
      statev(statevar_index(sv_beta, k)) = state%beta(k)
      statev(statevar_index(sv_frictional_slip, k)) = state%sf(k)
      statev(statevar_index(sv_zeta, k)) = state%zeta(k)
      statev(statevar_index(sv_theta, k)) = state%theta(k)
      statev(statevar_index(sv_friction_traction, k)) = state%tauf(k)
    end do
    statev(statevar_index(sv_work, 0)) = state%work
    statev(statevar_index(sv_damage_dissipation, 0)) = state%diss_damage
    statev(statevar_index(sv_friction_dissipation, 0)) = state%diss_friction
    statev(statevar_index(sv_initialized, 0)) = 1.0_dp
  end subroutine state_to_statev

end module interlock_props
