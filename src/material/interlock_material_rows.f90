!> The one mapping from the material table's property rows to the material: the rows' values in
!> the table's order and units (a PROPS; angles in degrees) become the material's given
!> fields, the RIA their rows select, the solver and the UMAT's controls, and the material is
!> derived. PROPS (interlock_props), decks, their sweeps and fits (src/io, src/programs/fit)
!> all build a material here: a row reaches its field in one place, and an angle becomes
!> radians in one place. The values are checked where they enter (the PROPS check, the deck's
!> readers), not here.
module interlock_material_rows
  use interlock_kinds, only: dp, deg_to_rad
  use interlock_material_table, only: n_properties, property_defaults, ria_azimuthal, &
      prop_sigma0_n, prop_sigma0_t, prop_gc, prop_eta, prop_mu, prop_h_n, prop_theta0, &
      prop_thetaf, prop_zeta0, prop_prefractured, prop_scheme, prop_substep_tol, prop_max_dd, &
      prop_max_dtheta, prop_effect_damage, prop_ria, prop_n_azimuths, prop_tangent, &
      tangent_symmetric
  use interlock_material, only: interlock_material_t, interlock_solver_t, n_effects, &
      interlock_paper_material_derive, interlock_azimuthal_ria, interlock_general_ria, &
      interlock_material_derive, interlock_material_prepare
  implicit none
  private
  public :: umat_controls_t, material_from_rows, rows_n_azimuths

  !> What the UMAT needs besides the material: the accuracy bounds behind PNEWDT.
  type :: umat_controls_t
    real(dp) :: max_damage_increment = property_defaults(prop_max_dd)
    real(dp) :: max_angle_increment = property_defaults(prop_max_dtheta) * deg_to_rad  !< [rad]
    !> DDSDDE symmetric (row `tangent` = tangent_symmetric: hosts that keep only its symmetric
    !> part), else the exact tangent
    logical :: symmetric_tangent = nint(property_defaults(prop_tangent)) == tangent_symmetric
  end type umat_controls_t

contains

  !> The azimuths N_a of the RIA that the rows `ria` and `n_azimuths` select (SPEC section 9):
  !> 1 for the paper's RIA (its three planes), n_azimuths for the azimuthal one (1 + 2 N_a
  !> planes; N_a = 1 is the paper's).
  elemental integer function rows_n_azimuths(ria, n_azimuths) result(n_a)
    real(dp), intent(in) :: ria, n_azimuths
    n_a = 1
    if (ria > ria_azimuthal - 0.5_dp) n_a = nint(n_azimuths)
  end function rows_n_azimuths

  !> The material, solver and controls of the rows' values(1:n) (n_properties at most; the rows
  !> after n take their defaults), each admissible (checked by the caller, where they entered).
  !> The RIA: the paper's or the azimuthal one, as rows `ria` and `n_azimuths` select, with
  !> the rows theta0_deg, thetaf_deg and zeta0; or, where the caller gives the planes of a
  !> general RIA (a deck's n_planes: gamma_hat, signed theta0_deg, thetaf_deg, zeta0, phi_deg),
  !> those (checked by the caller too). A row the caller `varied` (a sweep, a fit) sets every
  !> plane of such planes (an angle: its magnitude, with the sign of the plane's theta0_deg),
  !> and the material is then checked whole (interlock_material_prepare: the varied row
  !> against the others). stat /= status_ok: `message` says why the material cannot be derived
  !> (it is set only then: the UMAT's every call builds no text). `mat`, `solver` and
  !> `controls` are intent(inout) only so that the caller's fresh ones are not initialised a
  !> second time on every UMAT call: every field a row gives is set here (the solver's Newton
  !> controls, which no row gives, stay as the caller has them).
  pure subroutine material_from_rows(n, values, mat, solver, controls, stat, message, varied, &
                                     gamma_hat, theta0_deg, thetaf_deg, zeta0, phi_deg)
    integer, intent(in) :: n
    real(dp), intent(in) :: values(n)
    type(interlock_material_t), intent(inout) :: mat
    type(interlock_solver_t), intent(inout) :: solver
    type(umat_controls_t), intent(inout) :: controls
    integer, intent(out) :: stat
    character(len=*), intent(inout) :: message
    logical, intent(in), optional :: varied(n_properties)
    real(dp), intent(in), optional :: gamma_hat(:), theta0_deg(:), thetaf_deg(:), zeta0(:), &
                                      phi_deg(:)
    integer :: i, n_azimuths
    logical :: varies
    real(dp) :: theta0, thetaf

    mat%sigma0_n = values(prop_sigma0_n)
    mat%sigma0_t = values(prop_sigma0_t)
    mat%gc = values(prop_gc)
    mat%eta = values(prop_eta)
    mat%mu = values(prop_mu)
    mat%h_n = values(prop_h_n)
    mat%prefractured = row(prop_prefractured) > 0.5_dp
    !GCC$ unroll 5
    do i = 1, n_effects
      mat%effect(i) = row(prop_effect_damage + i - 1) > 0.5_dp
    end do
    solver%scheme = int(row(prop_scheme))   ! a whole number (checked): no rounding call
    solver%substep_tol = row(prop_substep_tol)
    controls%max_damage_increment = row(prop_max_dd)
    controls%max_angle_increment = row(prop_max_dtheta) * deg_to_rad
    controls%symmetric_tangent = row(prop_tangent) > tangent_symmetric - 0.5_dp
    varies = .false.
    if (present(varied)) varies = any(varied)
    ! (the angles of the table are in degrees, the material's in radians)
    theta0 = values(prop_theta0) * deg_to_rad
    thetaf = values(prop_thetaf) * deg_to_rad
    n_azimuths = rows_n_azimuths(row(prop_ria), row(prop_n_azimuths))
    if (present(gamma_hat)) then
      call general_planes(values, gamma_hat, theta0_deg, thetaf_deg, zeta0, phi_deg, mat, varied)
    else if (n_azimuths <= 1 .and. .not. varies) then
      ! (the paper's three planes built and derived in one, no loop over the planes)
      call interlock_paper_material_derive(mat, theta0, thetaf, values(prop_zeta0), stat, message)
      return
    else
      call interlock_azimuthal_ria(mat, n_azimuths, theta0, thetaf, values(prop_zeta0))
    end if
    if (varies) then
      ! (a varied row is checked against the others here, where it meets them)
      call interlock_material_prepare(mat, stat, message)
    else
      call interlock_material_derive(mat, stat, message)
    end if

  contains

    !> Row i: given, or its default.
    pure real(dp) function row(i)
      integer, intent(in) :: i
      if (i <= n) then
        row = values(i)
      else
        row = property_defaults(i)
      end if
    end function row

  end subroutine material_from_rows

  !> The general RIA of the planes a caller gives (angles in degrees), a `varied` row of
  !> theta0_deg, thetaf_deg or zeta0 (values) over every plane.
  pure subroutine general_planes(values, gamma_hat, theta0_deg, thetaf_deg, zeta0, phi_deg, &
                                 mat, varied)
    real(dp), intent(in) :: values(:)
    real(dp), intent(in) :: gamma_hat(:), theta0_deg(:), thetaf_deg(:), zeta0(:), phi_deg(:)
    type(interlock_material_t), intent(inout) :: mat
    logical, intent(in), optional :: varied(n_properties)
    real(dp) :: t0(size(gamma_hat)), tf(size(gamma_hat)), z(size(gamma_hat))
    logical :: vary(n_properties)
    vary = .false.
    if (present(varied)) vary = varied
    t0 = theta0_deg
    tf = thetaf_deg
    z = zeta0
    if (vary(prop_theta0)) t0 = sign(values(prop_theta0), theta0_deg)
    if (vary(prop_thetaf)) tf = sign(values(prop_thetaf), theta0_deg)
    if (vary(prop_zeta0)) z = values(prop_zeta0)
    call interlock_general_ria(mat, size(gamma_hat), gamma_hat, t0 * deg_to_rad, &
                               tf * deg_to_rad, z, phi_deg * deg_to_rad)
  end subroutine general_planes

end module interlock_material_rows
