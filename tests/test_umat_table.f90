!> The material table tells the truth: the defaults it documents are what props_to_material
!> gives when the optional PROPS are left out, each PROPS slot drives the field its name says,
!> and the STATEV layout is a one-to-one map that packs and unpacks the state unchanged.
module test_umat_table_cases
  use interlock
  use interlock_assert
  implicit none
  private
  public :: collect_umat_table

  real(dp), parameter :: required(9) = [2.0_dp, 4.0_dp, 0.3_dp, 0.9_dp, 0.6_dp, 1.5_dp, &
                                        25.0_dp, 5.0_dp, 3.0_dp]

contains

  subroutine collect_umat_table()
    call run_case('table_is_consistent', table_is_consistent)
    call run_case('defaults_give_documented_material', defaults_give_documented_material)
    call run_case('each_optional_prop_drives_its_field', each_optional_prop_drives_its_field)
    call run_case('statev_layout_roundtrip', statev_layout_roundtrip)
  end subroutine collect_umat_table

  subroutine table_is_consistent()
    integer :: i
    logical :: ok
    character(len=message_len) :: message
    do i = 1, n_properties
      call assert_equal(i, property_index(properties(i)%name), 'property_index(' // &
                        trim(properties(i)%name) // ')')
      call assert_true(properties(i)%required .eqv. (i <= n_required_properties), &
                       trim(properties(i)%name) // ': required exactly when in PROPS(1:9)')
      if (.not. properties(i)%required) then
        call check_property(i, properties(i)%default, ok, message)
        call assert_true(ok, trim(properties(i)%name) // ': the default is admissible')
      end if
    end do
    call assert_equal(prop_eta, property_index('eta'), 'prop_eta')
    call assert_equal(prop_h_n, property_index('h_n'), 'prop_h_n')
    call assert_equal(prop_theta0, property_index('theta0_deg'), 'prop_theta0')
    call assert_equal(prop_zeta0, property_index('zeta0'), 'prop_zeta0')
    call assert_equal(prop_scheme, property_index('scheme'), 'prop_scheme')
    call assert_equal(prop_max_dd, property_index('max_damage_increment'), 'prop_max_dd')
    call assert_equal(prop_max_dtheta, property_index('max_angle_increment_deg'), 'prop_max_dtheta')
    call assert_equal(prop_effect_damage, property_index('damage'), 'prop_effect_damage')
    call assert_equal(prop_effect_wear, property_index('wear'), 'prop_effect_wear')
    call assert_equal(22, umat_nstatv, 'umat_nstatv = 6 x 3 planes + 4')
  end subroutine table_is_consistent

  !> NPROPS = 9 (optional ones left out), NPROPS = 19 with the table's defaults, and the
  !> material set up through the library API with what the descriptions say the defaults mean.
  subroutine defaults_give_documented_material()
    type(interlock_material_t) :: m9, m19, ref
    type(interlock_solver_t) :: s9, s19, sref
    type(umat_controls_t) :: c9, c19
    real(dp) :: props(n_properties)
    integer :: stat
    character(len=message_len) :: message
    call props_to_material(required, m9, s9, c9, stat, message)
    call assert_equal(status_ok, stat, 'NPROPS = 9 accepted: ' // trim(message))
    props = properties%default
    props(1:9) = required
    call props_to_material(props, m19, s19, c19, stat, message)
    call assert_equal(status_ok, stat, 'NPROPS = 19 with the defaults accepted: ' // trim(message))
    ! What the documented defaults mean, set by hand.
    ref%sigma0_n = 2.0_dp
    ref%sigma0_t = 4.0_dp
    ref%gc = 0.3_dp
    ref%eta = 0.9_dp
    ref%mu = 0.6_dp
    ref%h_n = 1.5_dp
    ref%prefractured = .false.                       ! prefractured = 0: intact
    call interlock_paper_ria(ref, 25.0_dp * deg_to_rad, 5.0_dp * deg_to_rad, 3.0_dp)
    ref%effect = .true.                              ! every effect switch = 1
    call interlock_material_prepare(ref, stat, message)
    call assert_equal(status_ok, stat, 'reference material prepared')
    call same_material(ref, m9, 'NPROPS = 9')
    call same_material(ref, m19, 'NPROPS = 19')
    call assert_equal(scheme_trapezoidal, s9%scheme, 'default scheme 3 = trapezoidal')
    call assert_equal(scheme_trapezoidal, s19%scheme, 'default scheme (NPROPS = 19)')
    call assert_equal(sref%substep_tol, s9%substep_tol, 0.0_dp, 'default substep_tol')
    call assert_equal(0.0_dp, s9%substep_tol, 0.0_dp, 'default substep_tol = 0: no substepping')
    call assert_equal(0.25_dp, c9%max_damage_increment, 0.0_dp, 'default max_damage_increment')
    call assert_equal(1.0_dp * deg_to_rad, c9%max_angle_increment, 1.0e-16_dp, &
                      'default max_angle_increment = 1 deg, in rad')
    call assert_equal(c9%max_damage_increment, c19%max_damage_increment, 0.0_dp, 'NPROPS 9 = 19: dD')
    call assert_equal(c9%max_angle_increment, c19%max_angle_increment, 0.0_dp, 'NPROPS 9 = 19: dtheta')
  end subroutine defaults_give_documented_material

  subroutine same_material(a, b, what)
    type(interlock_material_t), intent(in) :: a, b
    character(len=*), intent(in) :: what
    call assert_equal([a%sigma0_n, a%sigma0_t, a%gc, a%eta, a%mu, a%h_n, a%kn, a%kt, a%s0n, a%s0t], &
                      [b%sigma0_n, b%sigma0_t, b%gc, b%eta, b%mu, b%h_n, b%kn, b%kt, b%s0n, b%s0t], &
                      0.0_dp, what // ': parameters and stiffnesses')
    call assert_equal(a%n_planes, b%n_planes, what // ': n_planes')
    call assert_equal(a%gamma_hat, b%gamma_hat, 0.0_dp, what // ': gamma_hat')
    call assert_equal(a%theta0, b%theta0, 0.0_dp, what // ': theta0')
    call assert_equal(a%thetaf, b%thetaf, 0.0_dp, what // ': thetaf')
    call assert_equal(a%zeta0, b%zeta0, 0.0_dp, what // ': zeta0')
    call assert_true(a%prefractured .eqv. b%prefractured, what // ': prefractured')
    call assert_true(all(a%effect .eqv. b%effect), what // ': effects')
    call assert_true(all(a%plane_wears .eqv. b%plane_wears), what // ': planes that wear')
    call assert_true(b%prepared, what // ': prepared')
  end subroutine same_material

  !> Setting one optional PROPS slot to a non-default value changes the field its name says.
  subroutine each_optional_prop_drives_its_field()
    type(interlock_material_t) :: m
    type(interlock_solver_t) :: s
    type(umat_controls_t) :: c
    real(dp) :: props(n_properties)
    integer :: stat, e
    character(len=message_len) :: message
    props = properties%default
    props(1:9) = required
    props(prop_prefractured) = 1.0_dp
    props(prop_scheme) = 2.0_dp
    props(prop_substep_tol) = 1.0e-3_dp
    props(prop_max_dd) = 0.1_dp
    props(prop_max_dtheta) = 2.0_dp
    call props_to_material(props, m, s, c, stat, message)
    call assert_equal(status_ok, stat, 'accepted')
    call assert_true(m%prefractured, 'prefractured = 1')
    call assert_equal(scheme_implicit, s%scheme, 'scheme = 2: implicit')
    call assert_equal(1.0e-3_dp, s%substep_tol, 0.0_dp, 'substep_tol')
    call assert_equal(0.1_dp, c%max_damage_increment, 0.0_dp, 'max_damage_increment')
    call assert_equal(2.0_dp * deg_to_rad, c%max_angle_increment, 1.0e-16_dp, 'max_angle_increment')
    do e = 1, n_effects
      props = properties%default
      props(1:9) = required
      props(prop_effect_damage + e - 1) = 0.0_dp
      call props_to_material(props, m, s, c, stat, message)
      call assert_equal(status_ok, stat, 'effect off accepted')
      call assert_true(trim(properties(prop_effect_damage + e - 1)%name) == trim(effect_names(e)), &
                       'PROPS(' // trim(properties(prop_effect_damage + e - 1)%name) // &
                       ') is effect ' // trim(effect_names(e)))
      call assert_true(.not. m%effect(e) .and. count(m%effect) == n_effects - 1, &
                       'PROPS ' // trim(effect_names(e)) // ' = 0 switches that effect off only')
    end do
  end subroutine each_optional_prop_drives_its_field

  subroutine statev_layout_roundtrip()
    type(interlock_material_t) :: m
    type(interlock_solver_t) :: s
    type(umat_controls_t) :: c
    type(interlock_state_t) :: a, b, virgin
    real(dp) :: statev(umat_nstatv)
    integer :: hits(umat_nstatv), ivar, k, stat
    character(len=message_len) :: message
    hits = 0
    do ivar = 1, size(statevars)
      if (statevars(ivar)%per_plane) then
        do k = 1, umat_planes
          hits(statevar_index(ivar, k)) = hits(statevar_index(ivar, k)) + 1
        end do
      else
        hits(statevar_index(ivar, 0)) = hits(statevar_index(ivar, 0)) + 1
      end if
    end do
    call assert_true(all(hits == 1), 'every STATEV slot holds exactly one variable')
    call props_to_material(required, m, s, c, stat, message)
    call interlock_state_init(m, a)
    do k = 1, 3
      a%damage(k) = 0.1_dp * k
      a%beta(k) = 1.0_dp + k
      a%sf(k) = -0.01_dp * k
      a%zeta(k) = 0.5_dp * k
      a%theta(k) = 0.2_dp - 0.1_dp * k
      a%tauf(k) = 3.0_dp * k
    end do
    a%work = 1.25_dp
    a%diss_damage = 0.5_dp
    a%diss_friction = 0.25_dp
    statev = 0.0_dp
    call statev_to_state(statev, m, virgin)
    call assert_equal(m%theta_init(1:3), virgin%theta(1:3), 0.0_dp, 'zero STATEV: virgin angles')
    call state_to_statev(a, statev)
    call statev_to_state(statev, m, b)
    call assert_equal([a%damage(1:3), a%beta(1:3), a%sf(1:3), a%zeta(1:3), a%theta(1:3), &
                       a%tauf(1:3), a%work, a%diss_damage, a%diss_friction], &
                      [b%damage(1:3), b%beta(1:3), b%sf(1:3), b%zeta(1:3), b%theta(1:3), &
                       b%tauf(1:3), b%work, b%diss_damage, b%diss_friction], 0.0_dp, 'roundtrip')
    call assert_equal(a%damage(2), statev(statevar_index(sv_damage, 2)), 0.0_dp, 'STATEV(2) = D_2')
    call assert_equal(a%theta(3), statev(statevar_index(sv_theta, 3)), 0.0_dp, 'STATEV(15) = theta_3')
    call assert_equal(15, statevar_index(sv_theta, 3), 'theta_3 slot')
    call assert_equal(19, statevar_index(sv_work, 0), 'work slot')
    call assert_equal(1.0_dp, statev(umat_nstatv), 0.0_dp, 'initialized flag')
  end subroutine statev_layout_roundtrip

end module test_umat_table_cases

program test_umat_table
  use test_umat_table_cases, only: collect_umat_table
  use interlock_assert, only: suite_summary
  implicit none
  call collect_umat_table()
  if (suite_summary('umat_table') /= 0) error stop 1
end program test_umat_table
