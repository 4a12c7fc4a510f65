!> The material: interface parameters, the RIA (microplanes), the effect switches, and what is
!> derived from them once, when the material is prepared (stiffnesses, the resolved effect set,
!> constant sines and cosines), so that an update pays only for the effects a scene uses.
module interlock_material
  use interlock_kinds, only: dp, deg_to_rad, pi, is_finite_bits, is_finite_value, infinite_threshold
  use interlock_numbers, only: format_real, format_integer
  use interlock_material_table, only: check_property, &
      prop_sigma0_n, prop_sigma0_t, prop_gc, prop_eta, prop_mu, prop_h_n, prop_zeta0
  use interlock_status, only: status_ok, status_bad_input, message_len
  implicit none
  private
  public :: interlock_material_t, interlock_solver_t, max_planes, max_azimuths
  public :: interlock_material_prepare, interlock_paper_ria, interlock_azimuthal_ria, &
            interlock_general_ria, interlock_material_derive, interlock_paper_material_derive, &
            derived_range_message
  public :: scheme_explicit, scheme_implicit, scheme_trapezoidal, scheme_name, n_schemes, &
            scheme_names, scheme_list
  public :: effect_damage, effect_friction, effect_interlocking, effect_finite_depth, effect_wear
  public :: effect_names, n_effects
  public :: kernel_general, kernel_flat, kernel_inclined, kernel_cohesive

  !> Planes of a RIA (the `azimuthal` RIA of SPEC section 9 has 1 + 2 N_a planes). Every
  !> point's material and state hold this many (the UMAT builds them on every call).
  integer, parameter :: max_planes = 13
  !> The largest number of azimuths of interlock_azimuthal_ria (1 + 2 N_a <= max_planes).
  integer, parameter :: max_azimuths = 6
  !> Integration schemes (SPEC section 5, D11): the paper's explicit one, backward Euler, and
  !> the trapezoidal rule on the wear equation (second order, consistent at a zero increment).
  integer, parameter :: scheme_explicit = 1, scheme_implicit = 2, scheme_trapezoidal = 3
  !> The schemes are the codes 1..n_schemes; their names in that order (messages, decks, and
  !> the tests that run every scheme loop over them).
  integer, parameter :: n_schemes = 3
  character(len=11), parameter :: scheme_names(n_schemes) = &
    [character(len=11) :: 'explicit', 'implicit', 'trapezoidal']
  integer, parameter :: n_effects = 5
  integer, parameter :: effect_damage = 1, effect_friction = 2, effect_interlocking = 3, &
                        effect_finite_depth = 4, effect_wear = 5
  !> Update kernels, chosen once by interlock_material_prepare from the effect set.
  integer, parameter :: kernel_general = 0      !< any effect set and scheme
  integer, parameter :: kernel_flat = 1         !< every plane flat: one plane, no rotation
  !> inclined planes, constant or wearing (the explicit scheme freezes the angle in the step,
  !> the implicit and trapezoidal schemes solve each wearing plane's wear equation)
  integer, parameter :: kernel_inclined = 2
  !> one flat plane without finite depth (the Alfano-Sacco interface), inlined in the update
  integer, parameter :: kernel_cohesive = 3
  character(len=12), parameter :: effect_names(n_effects) = &
    [character(len=12) :: 'damage', 'friction', 'interlocking', 'finite_depth', 'wear']

  !> Parameters as the user gives them (angles in radians), then what `prepare` derives.
  type :: interlock_material_t
    ! --- given
    real(dp) :: sigma0_n = 0.0_dp   !< peak normal traction [MPa]
    real(dp) :: sigma0_t = 0.0_dp   !< peak tangential traction [MPa]
    real(dp) :: gc = 0.0_dp         !< macroscopic fracture energy Gc_bar [N/mm]
    real(dp) :: eta = 0.0_dp        !< ductility parameter [-]
    real(dp) :: mu = 0.0_dp         !< friction coefficient [-]
    real(dp) :: h_n = huge(1.0_dp)  !< asperity depth [mm]; infinite by default
    logical  :: prefractured = .false.
    !> The RIA: planes 1..n_planes, each with all five values below. They have no default
    !> value (a default would cost every UMAT call, which declares its material anew, a
    !> component-wise copy of the whole material); interlock_paper_ria,
    !> interlock_azimuthal_ria and interlock_general_ria set them all. Values beyond n_planes
    !> are never read.
    integer  :: n_planes = 0
    real(dp) :: gamma_hat(max_planes)  !< area fractions, sum 1
    real(dp) :: theta0(max_planes)     !< initial inclinations [rad]
    real(dp) :: thetaf(max_planes)     !< final inclinations [rad]
    real(dp) :: zeta0(max_planes)      !< wear energy scales [N/mm]; huge(1.0_dp): no wear
    !> azimuths [rad] (SPEC section 9): plane k dips along cos(phi) t1 + sin(phi) t2; they
    !> matter only to the three-dimensional update
    real(dp) :: phi(max_planes)
    logical  :: effect(n_effects) = .true.       !< user switches, see effect_*
    ! --- derived by interlock_material_prepare (interlock_material_derive sets every one;
    ! no default value, so that a material declared on every call, the UMAT's, is not filled
    ! twice: read them only from a prepared material)
    logical  :: prepared = .false.
    real(dp) :: s0n, s0t, scn, sct
    real(dp) :: kn, kt
    real(dp) :: beta_break   !< 1/(1 - eta): equivalent displacement at D = 1
    real(dp) :: mu_eff       !< mu, or 0 with friction off
    real(dp) :: inv_h_n      !< 1/H_N, or 0 with infinite depth
    real(dp) :: d_frozen     !< the constant damage when damage does not evolve
    !> the damage law runs (damage on): beta is the running maximum (SPEC 4.3), also on a
    !> pre-fractured interface, whose D stays 1 since beta starts at 1/(1 - eta)
    logical  :: use_damage
    logical  :: use_friction  !< mu_eff > 0
    logical  :: use_depth     !< finite H_N
    logical  :: use_wear      !< some plane's angle can change
    logical  :: flat          !< every plane flat: one plane is computed for all
    !> per plane (planes beyond n_planes: flat, not wearing)
    logical  :: plane_wears(max_planes)
    real(dp) :: theta_init(max_planes)  !< effective initial angle (0 when interlocking off)
    real(dp) :: thetaf_eff(max_planes)
    real(dp) :: inv_zeta0(max_planes)
    real(dp) :: cos0(max_planes), sin0(max_planes)
    !> cos and sin of each azimuth phi (1 and 0 to the bit where phi = 0: the 3D update's
    !> frames cost no libm call per update), and every plane's azimuth 0
    real(dp) :: cos_phi(max_planes), sin_phi(max_planes)
    logical  :: azimuths_zero
    !> plane k + 1 has plane k's azimuth (false for the last plane): the 3D kernels sum a run of
    !> planes that share an azimuth in its frame and turn the sum once
    logical  :: same_azimuth_as_next(max_planes)
    !> Inverses for the kernels (a multiplication instead of a division on the hot path), and
    !> c/(2 eta) with c = K_n s_0n^2: decohesion energy per unit growth of beta.
    real(dp) :: inv_s0n, inv_s0t, inv_eta, inv_kt
    real(dp) :: decohesion_energy_factor
    !> The kernel for updates without substepping (kernel_general forces the general path).
    integer  :: kernel = kernel_general
  end type interlock_material_t

  !> How an update integrates.
  type :: interlock_solver_t
    !> the default: consistent at a zero increment (SPEC D10) and the cheapest per accuracy on
    !> the paper's wear scenes (docs/bench.md); scheme_explicit is the paper's
    integer  :: scheme = scheme_trapezoidal
    real(dp) :: substep_tol = 0.0_dp      !< local error tolerance; 0: no substepping
    real(dp) :: newton_tol = 1.0e-13_dp   !< relative residual of the per-plane wear equation
    integer  :: newton_max_iterations = 60
    integer  :: max_substeps = 100000     !< bound on sub-increments tried in one update
  end type interlock_solver_t

contains

  !> scheme_name's text, blank-padded (see interlock_numbers:format_real).
  pure function scheme_name_padded(scheme) result(name)
    integer, intent(in) :: scheme
    character(len=len(scheme_names)) :: name
    if (scheme >= 1 .and. scheme <= n_schemes) then
      name = scheme_names(scheme)
    else
      name = 'unknown'
    end if
  end function scheme_name_padded

  !> The name of scheme code `scheme` ('unknown' outside 1..n_schemes).
  pure function scheme_name(scheme) result(name)
    integer, intent(in) :: scheme
    character(len=len_trim(scheme_name_padded(scheme))) :: name
    name = scheme_name_padded(scheme)
  end function scheme_name

  !> scheme_list's text, blank-padded (see interlock_numbers:format_real).
  pure function scheme_list_padded() result(padded)
    character(len=120) :: padded
    character(len=:), allocatable :: text
    integer :: i
    text = ''
    do i = 1, n_schemes
      if (i == n_schemes .and. i > 1) then
        text = text // ' or '
      else if (i > 1) then
        text = text // ', '
      end if
      text = text // format_integer(i) // ' (' // trim(scheme_names(i)) // ')'
    end do
    padded = text
  end function scheme_list_padded

  !> The schemes and their codes, for messages and docs: "1 (explicit), 2 (implicit) or 3
  !> (trapezoidal)".
  pure function scheme_list() result(text)
    character(len=len_trim(scheme_list_padded())) :: text
    text = scheme_list_padded()
  end function scheme_list

  !> The paper's symmetric three-plane RIA (gamma_hat = 1/3; -theta_0, 0, +theta_0; the middle
  !> plane never wears). Angles in radians.
  pure subroutine interlock_paper_ria(mat, theta0, thetaf, zeta0)
    type(interlock_material_t), intent(inout) :: mat
    real(dp), intent(in) :: theta0, thetaf, zeta0
    call interlock_general_ria(mat, 3, spread(1.0_dp / 3.0_dp, 1, 3), [-theta0, 0.0_dp, theta0], &
                               [-thetaf, 0.0_dp, thetaf], [zeta0, huge(1.0_dp), zeta0])
  end subroutine interlock_paper_ria

  !> A general RIA of n_planes = n planes (n <= max_planes; interlock_material_prepare checks
  !> n and every value): area fractions, initial and final inclinations [rad], and optionally
  !> the wear energy scales [N/mm] (default huge(1.0_dp): no plane wears) and the azimuths
  !> [rad] (default 0: every plane dips along t1).
  pure subroutine interlock_general_ria(mat, n, gamma_hat, theta0, thetaf, zeta0, phi)
    type(interlock_material_t), intent(inout) :: mat
    integer, intent(in) :: n
    real(dp), intent(in) :: gamma_hat(n), theta0(n), thetaf(n)
    real(dp), intent(in), optional :: zeta0(n), phi(n)
    integer :: m
    mat%n_planes = n
    m = max(0, min(n, max_planes))
    mat%gamma_hat(1:m) = gamma_hat(1:m)
    mat%theta0(1:m) = theta0(1:m)
    mat%thetaf(1:m) = thetaf(1:m)
    mat%zeta0(1:m) = huge(1.0_dp)
    if (present(zeta0)) mat%zeta0(1:m) = zeta0(1:m)
    mat%phi(1:m) = 0.0_dp
    if (present(phi)) mat%phi(1:m) = phi(1:m)
  end subroutine interlock_general_ria

  !> The `azimuthal` RIA of SPEC section 9 with n_azimuths = N_a directions (1 <= N_a <=
  !> max_azimuths; the caller checks): the planes (phi_0, -theta_0), flat, (phi_0, +theta_0),
  !> then (phi_j, -theta_0), (phi_j, +theta_0) for j = 1..N_a-1, phi_j = pi j / N_a; the flat
  !> plane 1/3, each inclined plane 1/(3 N_a). N_a = 1 is the paper's RIA, layout included.
  !> Angles in radians.
  pure subroutine interlock_azimuthal_ria(mat, n_azimuths, theta0, thetaf, zeta0)
    type(interlock_material_t), intent(inout) :: mat
    integer, intent(in) :: n_azimuths
    real(dp), intent(in) :: theta0, thetaf, zeta0
    integer :: j, k
    real(dp) :: g
    g = 1.0_dp / (3.0_dp * max(n_azimuths, 1))
    mat%gamma_hat(1:3) = [g, 1.0_dp / 3.0_dp, g]
    mat%theta0(1:3) = [-theta0, 0.0_dp, theta0]
    mat%thetaf(1:3) = [-thetaf, 0.0_dp, thetaf]
    mat%zeta0(1:3) = [zeta0, huge(1.0_dp), zeta0]
    mat%phi(1:3) = 0.0_dp
    k = 3
    do j = 1, n_azimuths - 1
      mat%gamma_hat(k + 1:k + 2) = g
      mat%theta0(k + 1:k + 2) = [-theta0, theta0]
      mat%thetaf(k + 1:k + 2) = [-thetaf, thetaf]
      mat%zeta0(k + 1:k + 2) = zeta0
      mat%phi(k + 1:k + 2) = pi * j / n_azimuths
      k = k + 2
    end do
    mat%n_planes = k
  end subroutine interlock_azimuthal_ria

  !> Validate the given parameters and derive everything the update needs. On bad input
  !> `stat` = status_bad_input and `message` names the value and the admissible range.
  pure subroutine interlock_material_prepare(mat, stat, message)
    type(interlock_material_t), intent(inout) :: mat
    integer, intent(out) :: stat
    character(len=*), intent(out) :: message
    logical :: ok
    integer :: k
    real(dp) :: gsum

    stat = status_bad_input
    mat%prepared = .false.
    mat%kernel = kernel_general   ! a kernel other than the general one implies a prepared material
    call check_property(prop_sigma0_n, mat%sigma0_n, ok, message); if (.not. ok) return
    call check_property(prop_sigma0_t, mat%sigma0_t, ok, message); if (.not. ok) return
    call check_property(prop_gc, mat%gc, ok, message); if (.not. ok) return
    call check_property(prop_eta, mat%eta, ok, message); if (.not. ok) return
    call check_property(prop_mu, mat%mu, ok, message); if (.not. ok) return
    call check_property(prop_h_n, mat%h_n, ok, message); if (.not. ok) return
    if (mat%n_planes < 1 .or. mat%n_planes > max_planes) then
      message = "n_planes = " // format_integer(mat%n_planes) // &
                " is inadmissible: admissible 1 <= n_planes <= " // format_integer(max_planes)
      return
    end if
    gsum = 0.0_dp
    do k = 1, mat%n_planes
      ! (each value tested on its bits first: no comparison of a NaN)
      ok = is_finite_bits(mat%gamma_hat(k))
      if (ok) ok = mat%gamma_hat(k) > 0.0_dp .and. mat%gamma_hat(k) <= 1.0_dp
      if (.not. ok) then
        message = 'gamma_hat(' // format_integer(k) // ') = ' // format_real(mat%gamma_hat(k)) &
                  // ' is inadmissible: admissible 0 < gamma_hat <= 1'
        return
      end if
      gsum = gsum + mat%gamma_hat(k)
      ok = is_finite_bits(mat%theta0(k))
      if (ok) ok = abs(mat%theta0(k)) < 0.5_dp * pi
      if (.not. ok) then
        message = 'theta0(' // format_integer(k) // ') = ' // &
                  degrees_text(mat%theta0(k)) // &
                  ' is inadmissible: admissible -90 < theta0 < 90 deg'
        return
      end if
      ok = is_finite_bits(mat%thetaf(k))
      if (ok) ok = abs(mat%thetaf(k)) <= abs(mat%theta0(k)) .and. &
                   mat%thetaf(k) * mat%theta0(k) >= 0.0_dp
      if (.not. ok) then
        message = 'thetaf(' // format_integer(k) // ') = ' // &
                  degrees_text(mat%thetaf(k)) // &
                  ' is inadmissible: admissible 0 <= |thetaf| <= |theta0| = ' // &
                  format_real(abs(mat%theta0(k)) / deg_to_rad) // ' deg, same sign as theta0'
        return
      end if
      call check_property(prop_zeta0, mat%zeta0(k), ok, message)
      if (.not. ok) then
        message = 'plane ' // format_integer(k) // ': ' // message
        return
      end if
      ok = is_finite_bits(mat%phi(k))
      if (ok) ok = abs(mat%phi(k)) <= 2.0_dp * pi
      if (.not. ok) then
        message = 'phi(' // format_integer(k) // ') = ' // degrees_text(mat%phi(k)) // &
                  ' is inadmissible: admissible -360 <= phi <= 360 deg'
        return
      end if
    end do
    if (abs(gsum - 1.0_dp) > 1.0e-9_dp) then
      message = 'gamma_hat sums to ' // format_real(gsum) // &
                ': the area fractions must sum to 1 (within 1e-9)'
      return
    end if
    call interlock_material_derive(mat, stat, message)
    if (stat == status_ok) message = ''
  end subroutine interlock_material_prepare

  !> Derive what the update needs from given parameters that are each in their range (the
  !> checks of interlock_material_prepare; the UMAT makes its own, cheaper ones on PROPS): the
  !> lengths and stiffnesses (SPEC section 2), the effect set and the kernel. `ok` is false
  !> (and the material not prepared) when the lengths or stiffnesses fall outside double
  !> precision's safe range, or eta, H_N or zeta_0 is too small to invert: then `stat` =
  !> status_bad_input and `message` says why (it is set only then). Arithmetic only on
  !> success: no message, no formatted write, one sine and cosine per distinct |theta_0|.
  pure subroutine interlock_material_derive(mat, stat, message)
    type(interlock_material_t), intent(inout) :: mat
    integer, intent(out) :: stat
    character(len=*), intent(inout) :: message
    logical :: ok
    stat = status_ok
    call derive(mat, ok)
    if (.not. ok) then
      stat = status_bad_input
      message = derived_range_message(mat)
    end if
  end subroutine interlock_material_derive

  !> interlock_material_derive's arithmetic; `ok` false when the parameters cannot be derived.
  pure subroutine derive(mat, ok)
    type(interlock_material_t), intent(inout) :: mat
    logical, intent(out) :: ok
    integer :: k, j

    mat%prepared = .false.
    mat%kernel = kernel_general
    call derive_constants(mat, minval(mat%zeta0(1:mat%n_planes)), ok)
    if (.not. ok) return
    do k = 1, mat%n_planes
      call derive_plane(mat%effect(effect_interlocking), mat%effect(effect_wear), mat%theta0(k), &
                        mat%thetaf(k), mat%zeta0(k), mat%theta_init(k), mat%thetaf_eff(k), &
                        mat%plane_wears(k), mat%inv_zeta0(k))
      ! cos and sin are even and odd to the bit: one evaluation per distinct |theta|.
      mat%cos0(k) = 1.0_dp
      mat%sin0(k) = 0.0_dp
      if (.not. equal(mat%theta_init(k), 0.0_dp)) then
        do j = 1, k
          if (j == k) then
            mat%cos0(k) = cos(mat%theta_init(k))
            mat%sin0(k) = sin(mat%theta_init(k))
          else if (equal(abs(mat%theta_init(j)), abs(mat%theta_init(k)))) then
            mat%cos0(k) = mat%cos0(j)
            mat%sin0(k) = sign(mat%sin0(j), mat%theta_init(k))
            exit
          end if
        end do
      end if
    end do
    call derive_flat_beyond(mat)
    call derive_azimuths(mat)
    mat%use_wear = any(mat%plane_wears(1:mat%n_planes))
    call derive_kernel(mat, all(equal(mat%theta_init(1:mat%n_planes), 0.0_dp)))
  end subroutine derive

  !> interlock_paper_ria and interlock_material_derive in one (the same values to the bit), for
  !> the UMAT, which builds its material on every call: the three planes written out, one sine
  !> and cosine, no loop over the planes (the given per-plane values beyond the third are
  !> left as they are: never read). Its scalar given parameters and switches must be set.
  !> Angles in radians.
  pure subroutine interlock_paper_material_derive(mat, theta0, thetaf, zeta0, stat, message)
    type(interlock_material_t), intent(inout) :: mat
    real(dp), intent(in) :: theta0, thetaf, zeta0
    integer, intent(out) :: stat
    character(len=*), intent(inout) :: message
    logical :: ok, interlocking, wear

    mat%n_planes = 3
    mat%gamma_hat(1:3) = 1.0_dp / 3.0_dp
    mat%theta0(1:3) = [-theta0, 0.0_dp, theta0]
    mat%thetaf(1:3) = [-thetaf, 0.0_dp, thetaf]
    mat%zeta0(1:3) = [zeta0, huge(1.0_dp), zeta0]
    mat%phi(1:3) = 0.0_dp
    mat%prepared = .false.
    mat%kernel = kernel_general
    stat = status_bad_input
    call derive_constants(mat, zeta0, ok)
    if (.not. ok) then
      message = derived_range_message(mat)
      return
    end if
    stat = status_ok
    interlocking = mat%effect(effect_interlocking)
    wear = mat%effect(effect_wear)
    ! (the three planes written out: the middle one's values fold to constants)
    call derive_plane(interlocking, wear, -theta0, -thetaf, zeta0, mat%theta_init(1), &
                      mat%thetaf_eff(1), mat%plane_wears(1), mat%inv_zeta0(1))
    call derive_plane(interlocking, wear, 0.0_dp, 0.0_dp, huge(1.0_dp), mat%theta_init(2), &
                      mat%thetaf_eff(2), mat%plane_wears(2), mat%inv_zeta0(2))
    call derive_plane(interlocking, wear, theta0, thetaf, zeta0, mat%theta_init(3), &
                      mat%thetaf_eff(3), mat%plane_wears(3), mat%inv_zeta0(3))
    ! the planes -theta, 0, +theta: derive's evaluation for the first, its copy for the third
    mat%cos0(1:3) = 1.0_dp
    mat%sin0(1:3) = 0.0_dp
    if (.not. equal(mat%theta_init(1), 0.0_dp)) then
      mat%cos0(1) = cos(mat%theta_init(1))
      mat%sin0(1) = sin(mat%theta_init(1))
      mat%cos0(3) = mat%cos0(1)
      mat%sin0(3) = sign(mat%sin0(1), mat%theta_init(3))
    end if
    call derive_flat_beyond(mat)
    mat%cos_phi(1:3) = 1.0_dp
    mat%sin_phi(1:3) = 0.0_dp
    mat%azimuths_zero = .true.
    mat%same_azimuth_as_next = .false.
    mat%same_azimuth_as_next(1:2) = .true.
    mat%use_wear = mat%plane_wears(1) .or. mat%plane_wears(3)
    call derive_kernel(mat, equal(mat%theta_init(1), 0.0_dp))
  end subroutine interlock_paper_material_derive

  !> The lengths, stiffnesses and inverses (SPEC section 2) and the effect set's scalars (SPEC
  !> section 7); `ok` false when they fall outside double precision's safe range (`zeta0_min`:
  !> the smallest wear energy scale of the planes).
  pure subroutine derive_constants(mat, zeta0_min, ok)
    type(interlock_material_t), intent(inout) :: mat
    real(dp), intent(in) :: zeta0_min
    logical, intent(out) :: ok
    ! First the ranges of what the divisions below give, by products (no division can then
    ! overflow or underflow; FE codes may run with floating-point traps on, and the properties
    ! are below 1e30, so the products cannot overflow): the lengths s_c = 2 gc / sigma0,
    ! s_0 = (1 - eta) s_c and the stiffnesses K = sigma0 / s_0 must lie within 2^(+-300)
    ! (about 1e(+-90)).
    ok = lengths_in_range(mat%sigma0_n, mat%gc, mat%eta) .and. &
         lengths_in_range(mat%sigma0_t, mat%gc, mat%eta) .and. &
         inverses_in_range(mat%eta, mat%h_n, zeta0_min)
    if (.not. ok) return
    mat%scn = 2.0_dp * mat%gc / mat%sigma0_n
    mat%sct = 2.0_dp * mat%gc / mat%sigma0_t
    mat%s0n = (1.0_dp - mat%eta) * mat%scn
    mat%s0t = (1.0_dp - mat%eta) * mat%sct
    mat%kn = mat%sigma0_n / mat%s0n
    mat%kt = mat%sigma0_t / mat%s0t
    mat%beta_break = 1.0_dp / (1.0_dp - mat%eta)
    mat%inv_s0n = 1.0_dp / mat%s0n
    mat%inv_s0t = 1.0_dp / mat%s0t
    mat%inv_eta = 1.0_dp / mat%eta
    mat%inv_kt = 1.0_dp / mat%kt
    mat%decohesion_energy_factor = 0.5_dp * mat%kn * mat%s0n**2 / mat%eta
    ok = is_finite_value(mat%kn) .and. is_finite_value(mat%kt) .and. mat%s0n > 0.0_dp .and. &
         mat%s0t > 0.0_dp
    if (.not. ok) return

    ! The effect set, resolved once (SPEC section 7). The damage law runs on a pre-fractured
    ! interface too: beta stays the running maximum, D = 1 (beta >= 1/(1 - eta) from the start).
    mat%use_damage = mat%effect(effect_damage)
    mat%d_frozen = merge(1.0_dp, 0.0_dp, mat%prefractured)
    mat%mu_eff = merge(mat%mu, 0.0_dp, mat%effect(effect_friction))
    mat%use_friction = mat%mu_eff > 0.0_dp
    ! (x >= infinite_threshold: is_infinite_value for the checked, non-NaN parameters, without
    ! the IEEE module's save and restore of the floating-point state)
    mat%use_depth = mat%effect(effect_finite_depth) .and. .not. mat%h_n >= infinite_threshold
    mat%inv_h_n = 0.0_dp
    if (mat%use_depth) mat%inv_h_n = 1.0_dp / mat%h_n
  end subroutine derive_constants

  !> One plane's effective angles (0 with interlocking off), whether it wears (wear on, a finite
  !> zeta_0 and an angle that can change) and 1/zeta_0 when it does (0 otherwise).
  elemental subroutine derive_plane(interlocking, wear, theta0, thetaf, zeta0, theta_init, &
                                    thetaf_eff, wears, inv_zeta0)
    logical, intent(in) :: interlocking, wear
    real(dp), intent(in) :: theta0, thetaf, zeta0
    real(dp), intent(out) :: theta_init, thetaf_eff, inv_zeta0
    logical, intent(out) :: wears
    if (interlocking) then
      theta_init = theta0
      thetaf_eff = thetaf
    else
      theta_init = 0.0_dp
      thetaf_eff = 0.0_dp
    end if
    wears = wear .and. .not. zeta0 >= infinite_threshold .and. .not. equal(theta_init, thetaf_eff)
    inv_zeta0 = 0.0_dp
    if (wears) inv_zeta0 = 1.0_dp / zeta0
  end subroutine derive_plane

  !> cos and sin of each plane's azimuth (SPEC section 9), evaluated only where phi /= 0.
  pure subroutine derive_azimuths(mat)
    type(interlock_material_t), intent(inout) :: mat
    integer :: k
    mat%azimuths_zero = .true.
    mat%cos_phi = 1.0_dp
    mat%sin_phi = 0.0_dp
    mat%same_azimuth_as_next = .false.
    do k = 1, mat%n_planes
      if (mat%phi(k) < 0.0_dp .or. mat%phi(k) > 0.0_dp) then
        mat%cos_phi(k) = cos(mat%phi(k))
        mat%sin_phi(k) = sin(mat%phi(k))
        mat%azimuths_zero = .false.
      end if
    end do
    do k = 1, mat%n_planes - 1
      mat%same_azimuth_as_next(k) = equal(mat%phi(k + 1), mat%phi(k))
    end do
  end subroutine derive_azimuths

  !> The planes beyond n_planes: flat, not wearing.
  pure subroutine derive_flat_beyond(mat)
    type(interlock_material_t), intent(inout) :: mat
    mat%plane_wears(mat%n_planes + 1:) = .false.
    mat%theta_init(mat%n_planes + 1:) = 0.0_dp
    mat%thetaf_eff(mat%n_planes + 1:) = 0.0_dp
    mat%inv_zeta0(mat%n_planes + 1:) = 0.0_dp
    mat%cos0(mat%n_planes + 1:) = 1.0_dp
    mat%sin0(mat%n_planes + 1:) = 0.0_dp
  end subroutine derive_flat_beyond

  !> The kernel for the effect set (use_wear and use_depth set; `flat_angles`: every plane's
  !> effective angle 0); the material is then prepared.
  pure subroutine derive_kernel(mat, flat_angles)
    type(interlock_material_t), intent(inout) :: mat
    logical, intent(in) :: flat_angles
    mat%flat = flat_angles .and. .not. mat%use_wear
    if (mat%flat .and. .not. mat%use_depth) then
      mat%kernel = kernel_cohesive
    else if (mat%flat) then
      mat%kernel = kernel_flat
    else
      mat%kernel = kernel_inclined
    end if
    mat%prepared = .true.
  end subroutine derive_kernel

  !> Why interlock_material_derive refused the parameters.
  !> (a fixed length, blank-padded: see interlock_numbers:format_real)
  pure function derived_range_message(mat) result(message)
    type(interlock_material_t), intent(in) :: mat
    character(len=message_len) :: message
    if (.not. inverses_in_range(mat%eta, mat%h_n, minval(mat%zeta0(1:mat%n_planes)))) then
      message = 'eta = ' // format_real(mat%eta) // ', h_n = ' // format_real(mat%h_n) // &
                ', zeta0 = ' // format_real(minval(mat%zeta0(1:mat%n_planes))) // &
                ' is inadmissible: eta, h_n and zeta0 must be >= 1e-100 (the law takes ' // &
                'their inverses; a denormal number would overflow them)'
      return
    end if
    message = 'sigma0_n = ' // format_real(mat%sigma0_n) // ', sigma0_t = ' // &
              format_real(mat%sigma0_t) // ', gc = ' // format_real(mat%gc) // ' and eta = ' // &
              format_real(mat%eta) // ' give lengths s_c = 2 gc/sigma0, s_0 = (1-eta) s_c ' // &
              'or stiffnesses K = sigma0/s_0 outside 1e-90 .. 1e90 (mm, MPa/mm): not a ' // &
              'physical interface'
  end function derived_range_message

  !> degrees_text's text, blank-padded (see interlock_numbers:format_real).
  pure function degrees_text_padded(x) result(text)
    real(dp), intent(in) :: x
    character(len=40) :: text
    logical :: small
    small = is_finite_bits(x)
    if (small) small = abs(x) < 1.0e300_dp
    if (small) then
      text = format_real(x / deg_to_rad) // ' deg'
    else
      text = format_real(x) // ' rad'
    end if
  end function degrees_text_padded

  !> An angle given in radians, for a message: in degrees, or as given (in rad) where it is not
  !> finite or so large that the conversion would overflow (tested on the bits first: a
  !> signalling NaN traps in any comparison).
  pure function degrees_text(x) result(text)
    real(dp), intent(in) :: x
    character(len=len_trim(degrees_text_padded(x))) :: text
    text = degrees_text_padded(x)
  end function degrees_text

  !> same_value of interlock_kinds for derive, where a call into another module would cost more
  !> than the comparison (derive runs on every UMAT call; the angles are checked, not NaN).
  elemental logical function equal(a, b)
    real(dp), intent(in) :: a, b
    equal = .not. (a < b .or. a > b)
  end function equal

  !> eta, H_N and zeta_0 >= smallest_inverted: the law takes their inverses (1/eta, 1/H_N,
  !> 1/zeta_0), which then stay below 1e100, so that no product with a separation, a stiffness
  !> or a work overflows (a denormal zeta_0 would make 1/zeta_0 infinite). `zeta0_min`: the
  !> smallest zeta_0 of the planes.
  pure logical function inverses_in_range(eta, h_n, zeta0_min) result(ok)
    real(dp), intent(in) :: eta, h_n, zeta0_min
    real(dp), parameter :: smallest_inverted = 1.0e-100_dp
    ok = eta >= smallest_inverted .and. h_n >= smallest_inverted .and. &
         zeta0_min >= smallest_inverted
  end function inverses_in_range

  !> 2^-300 <= s_0 <= s_c <= 2^300 and 2^-300 <= K <= 2^300 for peak traction sigma0 (s_c =
  !> 2 gc / sigma0, s_0 = (1 - eta) s_c, K = sigma0 / s_0), by products only.
  pure logical function lengths_in_range(sigma0, gc, eta) result(ok)
    real(dp), intent(in) :: sigma0, gc, eta
    real(dp), parameter :: lo = 2.0_dp**(-300), hi = 2.0_dp**300
    real(dp) :: two_gc, two_gc_s0
    two_gc = 2.0_dp * gc
    two_gc_s0 = two_gc * (1.0_dp - eta)      ! sigma0 s_0
    ok = two_gc <= hi * sigma0 .and. two_gc_s0 >= lo * sigma0 .and. &
         sigma0 * sigma0 <= hi * two_gc_s0 .and. sigma0 * sigma0 >= lo * two_gc_s0
  end function lengths_in_range

end module interlock_material
