!> The interlock law in a thin layer of continuum elements, for hosts without cohesive elements
!> (CalculiX): `interlock_umat_layer_point` has the Abaqus UMAT argument list plus `host`, the
!> host's PNEWDT convention. The interface is a layer of thickness h; one local axis is its
!> normal n, another its slip direction t1, and the law acts on the separations of the layer:
!>
!>     NTENS = 6: the 3D law (`interlock_umat_cohesive_3d`, umat/interlock_umat_body_3d.f90)
!>       on (n, t1, t2), t2 = n x t1 (the third axis, with the sign that makes the frame
!>       right-handed): separation s = h * (strain of the normal, engineering shear strains
!>       normal-t1 and normal-t2, the latter times that sign);
!>     NTENS = 4: the 2D law (`interlock_umat_cohesive`, umat/interlock_umat_body.f90) on
!>       (n, t1): s = h * (strain of the normal, engineering shear strain normal-t1);
!>     traction   t = the matching stresses (shear normal-t2 times the sign)
!>     DDSDDE on that block = h * (the law's tangent d t / d s)   [MPa = mm * MPa/mm]
!>
!> Every other component (the in-plane direct strains and the in-plane shear; with NTENS = 4
!> also the direct strain of the third axis) is linear elastic and uncoupled: stress =
!> e_other * strain, DDSDDE = e_other on the diagonal. All NTENS x NTENS entries of DDSDDE are
!> written.
!>
!> **Components.** NTENS = 6 (NDI = NSHR = 3; 11, 22, 33, 12, 13, 23; engineering shear; what
!> CalculiX passes for every element) or NTENS = 4 (11, 22, 33, 12; Abaqus' plane strain and
!> axisymmetric elements: only the 1-2 pair is an interface there, and the law is the 2D one).
!> In the host's local axes (the user's orientation; CalculiX rotates strains into them before
!> the call and the stress and the tangent back after it).
!>
!> **PROPS** (`layer_nprops_head` = 4 values, then the law's PROPS 1 .. 9 to 1 .. 22):
!>   1 h [mm] in [1e-12, 1e12], 2 e_other [MPa] in (0, 1e30), 3 normal_axis 1, 2 or 3,
!>   4 slip_axis 1, 2 or 3 (/= normal_axis),
!>   5 .. the interlock PROPS (interlock-query --props; 21, 22 the RIA with NTENS = 6).
!>   NPROPS from 13 to 26.
!> **STATEV**: the law's (NTENS = 4: the 2D law's 22; NTENS = 6: the 3D law's 8 n_planes + 4,
!> 28 for the paper's RIA); with 4 more (NTENS = 4) or 6 more (NTENS = 6) slots also the
!> separation (normal, t1) [mm] and the traction (normal, t1) [MPa] at the end of the
!> increment, in the interface's axes (for output: hosts print S in their global axes), and
!> with NTENS = 6 then the separation and the traction along t2. NSTATV is the law's count or
!> at least the law's and the layer's: a count in between (room for part of the layer's
!> output) is bad input, refused by the law's body with both admissible counts in its message
!> (the law's count is known only once it has read the RIA from PROPS).
!> **Energies** per unit volume: the law's SSE and SCD (per unit area) / h, plus the elastic
!> energy of the other components in SSE; SPD = 0 (nothing is read from them on entry).
!>
!> **Strains.** Every component's separation h x strain must stay within the admissible
!> 1e6 mm (tested on the bits: no comparison of a NaN, no product that overflows): STRAN, the
!> converged start, beyond |STRAN| <= 1e6 mm / h (or not finite) is bad input; its separation
!> h STRAN, which round-off can put an ulp or two beyond 1e6 mm, is taken as at most 1e6 mm, so
!> the law refuses no start the layer admits. DSTRAN not finite or beyond 2e6 mm / h, or the
!> end of the increment h STRAN + h DSTRAN beyond 1e6 mm (the law's own test, on the
!> separations the law receives), is a diverged global iteration of the host (a cutback; the
!> start is sound). So the other components never carry garbage on into STRESS or the
!> energies.
!>
!> **PNEWDT** (`host`):
!>  - `host_abaqus`: as the 2D law (only lowered: -1 for bad input, 0.25 for a diverged global
!>    iteration, 0.5 for a local failure, the accuracy bounds' fraction).
!>  - `host_calculix`: ccx passes PNEWDT = -1 meaning "no request", and carries it from point to
!>    point within one thread (resultsmech.f); ANY positive value returned makes ccx discard the
!>    iteration and cut the increment by that factor (checkconvergence.c), at every iteration.
!>    So: a positive request is only ever lowered (a positive value that arrives is another
!>    point's request); bad input returns `pnewdt_calculix_stop` (1e-6: the increment falls
!>    below the minimum and ccx stops, or stops at once with fixed increments); a diverged
!>    iteration 0.25, a local failure 0.5 and the accuracy bounds their fraction. -1 is left
!>    alone when all is well.
!>  A NaN PNEWDT on entry (tested on its bits) is replaced, by the host's "no request" (-1
!>  for ccx, 1 for Abaqus) when no request is due.
!>  On bad input or a failure, STRESS, STATEV, DDSDDE and the energies are left as they came.
!>
!> **Messages**: one line per material and kind (umat/interlock_umat_messages.f90), naming the
!> point and the value. **Axes**: a layer whose declared normal is not its thin direction runs
!> (every value admissible) with the wrong components: the large strains of the thin direction
!> then land in the other components. When, at the end of an increment, a component that does
!> not involve the normal axis (an in-plane direct strain or the in-plane shear) exceeds
!> `axes_suspect_strain` and every interface component, one warning line says so (the
!> analysis goes on: PNEWDT untouched).
!>
!> **Threads.** No SAVE'd, module or COMMON state is written but the messages' table (under
!> its lock); `recursive`: every local on the stack.
module interlock_umat_layer
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock, only: dp, message_len, format_integer, format_real, format_reals, umat_nstatv, &
      n_required_properties, n_properties, separation_bound, is_finite_bits, is_nan_value, &
      umat_nstatv_3d, props_n_planes_3d
  use interlock_numbers, only: key_in_range
  use interlock_umat_body, only: interlock_umat_cohesive
  use interlock_umat_reports, only: diverged_iteration_message, say_at_point, lower_pnewdt
  use interlock_step_control, only: pnewdt_diverged, pnewdt_none, &
      separation_increment_bits => increment_bits
  use interlock_umat_body_3d, only: interlock_umat_cohesive_3d
  use interlock_umat_messages, only: said_argument, said_start_strain, said_diverged, &
      said_layer_axes
  implicit none
  private
  public :: interlock_umat_layer_point, host_abaqus, host_calculix, layer_nprops_head, &
            layer_nstatv_extra, pnewdt_calculix_stop, layer_components, layer_h_min, &
            layer_h_max, axes_suspect_strain, calculix_linear_iteration, layer_frame_3d, &
            layer_nstatv_extra_3d

  integer, parameter :: host_abaqus = 1    !< PNEWDT starts at >= 1 and is only lowered
  integer, parameter :: host_calculix = 2  !< PNEWDT starts at -1 ("no request")
  integer, parameter :: layer_nprops_head = 4  !< h, e_other, normal_axis, slip_axis
  !> Optional STATEV after the law's 22: separation (normal, slip) and traction (normal, slip)
  !> in the interface's own axes, for output (a host prints stresses in its global axes).
  integer, parameter :: layer_nstatv_extra = 4
  !> With NTENS = 6: those four, then the separation and the traction along t2.
  integer, parameter :: layer_nstatv_extra_3d = 6
  !> The cutback factor that makes CalculiX stop on bad input (below any sensible minimum).
  real(dp), parameter :: pnewdt_calculix_stop = 1.0e-6_dp
  !> The admissible layer thickness [mm]: within it, strain bounds (1e6 mm / h), energies per
  !> volume (per area / h) and stresses (e_other x strain) stay far from overflow.
  real(dp), parameter :: layer_h_min = 1.0e-12_dp, layer_h_max = 1.0e12_dp
  !> An in-plane strain beyond this (and beyond the interface's) suggests the wrong normal
  !> axis: in-plane strains are the neighbouring bulk's, small in a small-strain analysis.
  real(dp), parameter :: axes_suspect_strain = 0.1_dp
  !> Exact bit patterns of the admissible axis values 1, 2, 3.
  integer(int64), parameter :: axis_bits(3) = transfer([1.0_dp, 2.0_dp, 3.0_dp], 0_int64, 3)
  integer(int64), parameter :: h_low_bits = transfer(layer_h_min, 0_int64), &
    h_high_bits = transfer(layer_h_max, 0_int64), &
    e_other_high_bits = transfer(1.0e30_dp, 0_int64) - 1_int64

contains

  !> The (normal, shear) component indices of an interface with normal axis `normal` and slip
  !> axis `slip` in an NTENS = 4 or 6 vector; (0, 0) when the pair has no shear component.
  pure function layer_components(ntens, normal, slip) result(comp)
    integer, intent(in) :: ntens, normal, slip
    integer :: comp(2)
    integer :: a, b
    comp = 0
    a = min(normal, slip)
    b = max(normal, slip)
    if (a < 1 .or. b > 3 .or. a == b) return
    if (a == 1 .and. b == 2) then
      comp = [normal, 4]
    else if (ntens == 6) then
      comp = [normal, merge(5, 6, a == 1)]
    end if
  end function layer_components

  !> The frame of a layer with NTENS = 6: the components of (n, t1, t2) in the (11, 22, 33, 12,
  !> 13, 23) vector, t1 = the slip axis, t2 = n x t1 = sign * (the third axis): `comp` = (the
  !> normal's direct strain, the shear normal-t1, the shear normal-third axis) and `sign`
  !> (+1 when (normal, slip, third) is a cyclic order of (1, 2, 3), else -1). `normal` and
  !> `slip` are distinct axes 1..3 (checked by the caller).
  pure subroutine layer_frame_3d(normal, slip, comp, sign)
    integer, intent(in) :: normal, slip
    integer, intent(out) :: comp(3)
    real(dp), intent(out) :: sign
    integer :: third
    third = 6 - normal - slip
    comp(1) = normal
    comp(2) = shear_component(normal, slip)
    comp(3) = shear_component(normal, third)
    sign = merge(1.0_dp, -1.0_dp, modulo(slip - normal, 3) == 1)
  end subroutine layer_frame_3d

  !> The (12, 13, 23) component 4, 5 or 6 of the shear of two distinct axes.
  pure integer function shear_component(a, b) result(c)
    integer, intent(in) :: a, b
    c = a + b + 1          ! 1+2 -> 4, 1+3 -> 5, 2+3 -> 6
  end function shear_component

  !> Whether ccx calls for the tangent of its "linear iteration": the first iteration of the
  !> first increment of a step whose prescribed displacements change (nonlingeo.c, ilin = 1),
  !> where ccx wants the tangent at the end of the previous increment and throws the stress
  !> away. There calctotstrain.f passes, whatever NLGEOM says, the Green-Lagrange strain of
  !> the old displacements, E = (H + H^T) / 2 + H^T H / 2 with H = DFGRD0 - I, so that
  !> DSTRAN = E - STRAN = H^T H / 2: not a displacement increment but the quadratic term of
  !> the old field. In an FE model's bulk that is of the order of the squared strains and
  !> harmless; in a thin layer the normal "strain" is s_N / h (-3.2 for the granite joint at
  !> 2 MPa in a 0.01 mm layer), and H^T H / 2 (+5.1 there) turns a closed interface into an
  !> open one: the law answers with an open interface's tangent, ccx's predictor diverges.
  !> Detected by traces, which a rotation into the local axes keeps: in every other call
  !> without NLGEOM (JSTEP(3) = 0) ccx's DSTRAN is the small-strain increment, so
  !> tr DSTRAN = tr(DFGRD1 - DFGRD0) to round-off; here tr DSTRAN = |H|^2 / 2 instead.
  !> Values that are not finite and moderate (|x| <= 1e100) never count as that call.
  pure logical function calculix_linear_iteration(ntens, dstran, dfgrd0, dfgrd1, jstep) &
      result(linear)
    integer, intent(in) :: ntens, jstep(4)
    real(dp), intent(in) :: dstran(ntens), dfgrd0(3, 3), dfgrd1(3, 3)
    integer(int64), parameter :: moderate_bits = transfer(1.0e100_dp, 0_int64)
    real(dp), parameter :: round_off = 1.0e-12_dp
    real(dp) :: trace_strain, trace_gradient, quadratic, scale
    integer :: i
    linear = .false.
    if (ntens < 3 .or. jstep(3) /= 0) return
    if (.not. all(key_in_range(dstran(1:3), -1_int64 - moderate_bits, moderate_bits))) return
    if (.not. all(key_in_range(dfgrd0, -1_int64 - moderate_bits, moderate_bits))) return
    if (.not. all(key_in_range(dfgrd1, -1_int64 - moderate_bits, moderate_bits))) return
    trace_strain = dstran(1) + dstran(2) + dstran(3)
    trace_gradient = 0.0_dp
    do i = 1, 3
      trace_gradient = trace_gradient + (dfgrd1(i, i) - dfgrd0(i, i))
    end do
    quadratic = 0.5_dp * (sum(dfgrd0**2) - 2.0_dp * (dfgrd0(1, 1) + dfgrd0(2, 2) + &
                dfgrd0(3, 3)) + 3.0_dp)      ! |DFGRD0 - I|^2 / 2
    scale = 1.0_dp + maxval(abs(dfgrd0)) + maxval(abs(dfgrd1)) + abs(trace_strain)
    linear = abs(trace_strain - trace_gradient) > round_off * scale .and. &
             abs(trace_strain - quadratic) <= round_off * scale * (1.0_dp + quadratic)
  end function calculix_linear_iteration

  recursive subroutine interlock_umat_layer_point(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, &
      DDSDDT, DRPLDE, DRPLDT, STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, &
      NDI, NSHR, NTENS, NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT, DFGRD0, DFGRD1, &
      NOEL, NPT, LAYER, KSPT, JSTEP, KINC, host)
    integer, intent(in) :: NDI, NSHR, NTENS, NSTATV, NPROPS, NOEL, NPT, LAYER, KSPT, JSTEP(4), KINC
    character(len=*), intent(in) :: CMNAME
    real(dp), intent(inout) :: STRESS(NTENS), STATEV(NSTATV), DDSDDE(NTENS, NTENS)
    real(dp), intent(inout) :: SSE, SPD, SCD, RPL, DRPLDT, DDSDDT(NTENS), DRPLDE(NTENS)
    real(dp), intent(in) :: STRAN(NTENS), DSTRAN(NTENS), TIME(2), DTIME, TEMP, DTEMP
    real(dp), intent(in) :: PREDEF(*), DPRED(*), PROPS(NPROPS), COORDS(3), DROT(3, 3), CELENT
    real(dp), intent(in) :: DFGRD0(3, 3), DFGRD1(3, 3)
    real(dp), intent(inout) :: PNEWDT
    integer, intent(in) :: host   !< host_abaqus or host_calculix: the PNEWDT convention

    real(dp), parameter :: untouched = -huge(1.0_dp)
    integer :: comp2(2), comp(3), m, normal, slip, i, law_nstatv
    integer(int64) :: strain_bits, increment_bits
    real(dp) :: h, e_other, t(3), s0(3), ds(3), d(3, 3), sgn(3), sse2, scd2, p2, elastic, strain_bound
    ! (fixed size: NTENS is checked to be 4 or 6 first; no automatic array, no heap per call)
    real(dp) :: strain(6), sep0(6), dsep(6)
    logical :: interface_component(6)
    character(len=message_len) :: message

    ! A NaN PNEWDT on entry is garbage: the host's "no request", whatever happens next.
    if (is_nan_value(PNEWDT)) PNEWDT = merge(-1.0_dp, pnewdt_none, host == host_calculix)
    ! --- The host's arguments and the layer's own PROPS, each by name and range (on the
    ! bits: no comparison of a NaN, signalling or quiet).
    if (NTENS /= 4 .and. NTENS /= 6) then
      call fail('NTENS = ' // format_integer(NTENS) // ' is inadmissible: admissible NTENS = ' &
                // '6 (11, 22, 33, 12, 13, 23) or 4 (11, 22, 33, 12)', said_argument + 1)
      return
    end if
    if (NPROPS < layer_nprops_head + n_required_properties .or. &
        NPROPS > layer_nprops_head + n_properties) then
      call fail('NPROPS = ' // format_integer(NPROPS) // ' is inadmissible: admissible ' // &
                format_integer(layer_nprops_head + n_required_properties) // ' <= NPROPS <= ' // &
                format_integer(layer_nprops_head + n_properties) // ' (h, e_other, normal_axis, ' // &
                'slip_axis, then the interlock PROPS)', said_argument + 2)
      return
    end if
    if (.not. key_in_range(PROPS(1), h_low_bits, h_high_bits)) then
      call fail("layer PROPS(1): 'h' = " // format_real(PROPS(1)) // ' is inadmissible: ' // &
                'admissible ' // format_real(layer_h_min) // ' <= h <= ' // &
                format_real(layer_h_max) // ' [mm] (the layer thickness)', said_argument + 3)
      return
    end if
    if (.not. key_in_range(PROPS(2), 1_int64, e_other_high_bits)) then
      call fail("layer PROPS(2): 'e_other' = " // format_real(PROPS(2)) // ' is inadmissible: ' &
                // 'admissible 0 < e_other < 1e30 [MPa] (the modulus of the other components)', &
                said_argument + 4)
      return
    end if
    h = PROPS(1)
    e_other = PROPS(2)
    do i = 3, 4
      if (.not. any(transfer(PROPS(i), 0_int64) == axis_bits)) then
        call fail('layer PROPS(' // format_integer(i) // "): '" // &
                  trim(merge('normal_axis', 'slip_axis  ', i == 3)) // "' = " // &
                  format_real(PROPS(i)) // ' is inadmissible: admissible 1, 2 or 3 (a local ' // &
                  'axis)', said_argument + 2 + i)
        return
      end if
    end do
    normal = nint(PROPS(3))
    slip = nint(PROPS(4))
    comp2 = layer_components(NTENS, normal, slip)
    if (comp2(1) == 0) then
      if (normal == slip) then
        message = "layer PROPS(4): 'slip_axis' = " // format_integer(slip) // ' is ' // &
                  "inadmissible: admissible a local axis other than 'normal_axis' = " // &
                  format_integer(normal)
      else
        message = "layer PROPS(3:4): 'normal_axis', 'slip_axis' = " // format_integer(normal) &
                  // ', ' // format_integer(slip) // ' is inadmissible with NTENS = 4: ' // &
                  'admissible the axes 1 and 2 (the only shear component is 12)'
      end if
      call fail(message, said_argument + merge(7, 8, normal == slip))
      return
    end if
    ! The interface components: NTENS = 6 the 3D law on (n, t1, t2), NTENS = 4 the 2D law on
    ! (n, t1); sgn(3) turns the shear of the third axis into the component along t2 = n x t1.
    sgn = 1.0_dp
    if (NTENS == 6) then
      m = 3
      call layer_frame_3d(normal, slip, comp, sgn(3))
    else
      m = 2
      comp(1:2) = comp2
      comp(3) = 0
    end if

    ! --- Every strain component within the admissible separation, on the bits (the bound's
    ! bits order as the magnitudes do; NaN and Inf lie beyond). The start: |STRAN| <= 1e6 mm / h,
    ! and its separation h STRAN, which round-off can put an ulp or two beyond 1e6 mm, taken as
    ! at most 1e6 mm (so the law never refuses a start the layer admits). The end: the law's
    ! own test on the very separations it receives (start + h DSTRAN), so the law never finds
    ! a diverged iteration the layer let through; DSTRAN is bounded first on the bits, so
    ! that h DSTRAN cannot overflow.
    strain_bound = separation_bound / h
    strain_bits = transfer(strain_bound, 0_int64)
    increment_bits = transfer(2.0_dp * strain_bound, 0_int64)
    do i = 1, NTENS
      if (.not. key_in_range(STRAN(i), -1_int64 - strain_bits, strain_bits)) then
        call fail('the strain at the start of the increment STRAN(' // format_integer(i) // &
                  ') = ' // format_real(STRAN(i)) // ' is inadmissible: admissible |h STRAN| ' &
                  // '<= ' // format_real(separation_bound) // ' mm (|STRAN| <= ' // &
                  format_real(strain_bound) // ' with h = ' // format_real(h) // ' mm)', &
                  said_start_strain + i)
        return
      end if
      sep0(i) = min(separation_bound, max(-separation_bound, h * STRAN(i)))
    end do
    s0(1:m) = sgn(1:m) * sep0(comp(1:m))
    do i = 1, NTENS
      if (.not. key_in_range(DSTRAN(i), -1_int64 - increment_bits, increment_bits)) exit
      dsep(i) = h * DSTRAN(i)
      if (.not. key_in_range(dsep(i), -1_int64 - separation_increment_bits, &
                             separation_increment_bits)) exit
      if (abs(sep0(i) + dsep(i)) > separation_bound) exit
      strain(i) = STRAN(i) + DSTRAN(i)
    end do
    if (i <= NTENS) then
      call diverged(i)
      return
    end if

    ! --- The law on the interface components (separation = h * strain; the law sets its
    ! energies per area: none is read from SSE, SCD on entry).
    t = 0.0_dp
    t(1:m) = STRESS(comp(1:m))
    if (sgn(3) < 0.0_dp) t(3) = -t(3)   ! (a sign flip: no arithmetic on what may be garbage)
    ds(1:m) = sgn(1:m) * dsep(comp(1:m))
    p2 = pnewdt_none
    call law(t, STATEV, d, sse2, scd2, s0, ds, p2)
    if (transfer(d(1, 1), 0_int64) == transfer(untouched, 0_int64)) then
      ! The law failed (it wrote its line and left its arguments alone): so does the layer.
      call request(max(p2, 0.0_dp), p2 <= 0.0_dp)
      return
    end if

    ! --- Assemble: the law's block, the other components elastic.
    interface_component = .false.
    interface_component(comp(1:m)) = .true.
    DDSDDE = 0.0_dp
    elastic = 0.0_dp
    do i = 1, NTENS
      if (interface_component(i)) cycle
      STRESS(i) = e_other * strain(i)
      DDSDDE(i, i) = e_other
      elastic = elastic + 0.5_dp * e_other * strain(i)**2
    end do
    do i = 1, m
      STRESS(comp(i)) = sgn(i) * t(i)
      DDSDDE(comp(1:m), comp(i)) = (h * sgn(i)) * sgn(1:m) * d(1:m, i)
    end do
    ! (the law's STATEV, known now that the law has accepted its PROPS)
    law_nstatv = umat_nstatv
    if (m == 3) law_nstatv = umat_nstatv_3d(props_n_planes_3d(NPROPS - layer_nprops_head, &
                                                              PROPS(layer_nprops_head + 1:NPROPS)))
    SSE = sse2 / h + elastic
    SPD = 0.0_dp
    SCD = scd2 / h
    RPL = 0.0_dp
    DDSDDT = 0.0_dp
    DRPLDE = 0.0_dp
    DRPLDT = 0.0_dp
    if (NSTATV >= law_nstatv + layer_nstatv_extra + (m - 2) * 2) then
      STATEV(law_nstatv + 1:law_nstatv + 2) = s0(1:2) + ds(1:2)
      STATEV(law_nstatv + 3:law_nstatv + 4) = t(1:2)
      if (m == 3) then
        STATEV(law_nstatv + 5) = s0(3) + ds(3)
        STATEV(law_nstatv + 6) = t(3)
      end if
    end if
    if (p2 < pnewdt_none) call request(p2, .false.)
    if (in_plane_strain() > axes_suspect_strain) call check_axes()
    associate (unused_1 => NDI, unused_2 => NSHR)
    end associate

  contains

    !> The largest |strain| at the end of the increment among the components that do not
    !> involve the normal axis (in a thin layer: the neighbouring bulk's, small).
    pure real(dp) function in_plane_strain() result(e)
      integer :: j
      e = 0.0_dp
      do j = 1, NTENS
        if (.not. involves_normal(j)) e = max(e, abs(strain(j)))
      end do
    end function in_plane_strain

    !> Component j (11, 22, 33, 12, 13, 23) involves the normal axis.
    pure logical function involves_normal(j)
      integer, intent(in) :: j
      integer, parameter :: first_axis(6) = [1, 2, 3, 1, 1, 2], second_axis(6) = [1, 2, 3, 2, 3, 3]
      involves_normal = first_axis(j) == normal .or. second_axis(j) == normal
    end function involves_normal

    !> An in-plane strain beyond the interface's: warn (once per material) that the declared
    !> normal is probably not the layer's thin direction.
    subroutine check_axes()
      integer :: j, worst
      worst = 0
      do j = 1, NTENS
        if (involves_normal(j)) cycle
        if (worst == 0) then
          worst = j
        else if (abs(strain(j)) > abs(strain(worst))) then
          worst = j
        end if
      end do
      if (abs(strain(worst)) <= maxval(abs(strain(comp(1:m))))) return
      call say_at_point('interlock UMAT (layer): warning: ', 'the strain of ' // &
        'component ' // format_integer(worst) // ' = ' // format_real(strain(worst)) // &
        ', which does not involve normal_axis = ' // format_integer(normal) // ', exceeds ' // &
        format_real(axes_suspect_strain) // ' and the interface strains (' // &
        format_reals(strain(comp(1:m))) // '): in a ' // &
        'thin layer only the components of its normal are large; is normal_axis the ' // &
        "layer's thin direction in the element's local axes (*ORIENTATION)?", said_layer_axes, &
        NOEL, NPT, KINC, CMNAME)
    end subroutine check_axes

    !> A diverged global iteration: component i of DSTRAN, or of the end strain, out of range.
    !> Bad input wins (no cutback repairs it): the law first checks its own arguments (PROPS,
    !> STATEV, the start) at a zero increment, on copies; its rejection is the answer.
    subroutine diverged(i)
      integer, intent(in) :: i
      real(dp) :: statev_copy(NSTATV), t_copy(3), d_copy(3, 3), e(2), p_law, no_increment(3)
      t_copy = 0.0_dp
      t_copy(1:m) = STRESS(comp(1:m))
      if (sgn(3) < 0.0_dp) t_copy(3) = -t_copy(3)
      statev_copy = STATEV
      e = 0.0_dp
      p_law = pnewdt_none
      no_increment = 0.0_dp
      call law(t_copy, statev_copy, d_copy, e(1), e(2), s0, no_increment, p_law)
      if (p_law <= 0.0_dp) then
        call request(0.0_dp, .true.)
        return
      end if
      call say_at_point('interlock UMAT (layer): ', diverged_iteration_message('DSTRAN(' // &
        format_integer(i) // ') = ' // format_real(DSTRAN(i)), '|h strain| <= ' // &
        format_real(separation_bound) // ' mm (h = ' // format_real(h) // ' mm)'), &
        said_diverged, NOEL, NPT, KINC, CMNAME)
      call request(pnewdt_diverged, .false.)
    end subroutine diverged

    !> The law on the interface components 1..m (m = 3: the 3D body, m = 2: the 2D one) from
    !> the separation s_start by ds; `d` untouched when it fails. The thermal and heat
    !> arguments are the law's own zeros, not the host's.
    subroutine law(traction, statev_law, d, sse_law, scd_law, s_start, ds_law, p_law)
      real(dp), intent(inout) :: traction(3), statev_law(NSTATV), d(3, 3), sse_law, scd_law, &
                                 p_law
      real(dp), intent(in) :: s_start(3), ds_law(3)
      real(dp) :: d2(2, 2), spd_law, rpl_law, drpldt_law, ddsddt_law(3), drplde_law(3)
      sse_law = 0.0_dp
      scd_law = 0.0_dp
      spd_law = 0.0_dp
      rpl_law = 0.0_dp
      drpldt_law = 0.0_dp
      ddsddt_law = 0.0_dp
      drplde_law = 0.0_dp
      d = untouched   ! the law writes all of DDSDDE when it succeeds, nothing when it fails
      if (m == 3) then
        call interlock_umat_cohesive_3d(traction, statev_law, d, sse_law, spd_law, scd_law, &
          rpl_law, ddsddt_law, drplde_law, drpldt_law, s_start, ds_law, TIME, DTIME, TEMP, &
          DTEMP, PREDEF, DPRED, CMNAME, 1, 2, 3, NSTATV, PROPS(layer_nprops_head + 1:NPROPS), &
          NPROPS - layer_nprops_head, COORDS, DROT, p_law, CELENT, DFGRD0, DFGRD1, NOEL, NPT, &
          LAYER, KSPT, JSTEP, KINC, layer_props_offset=layer_nprops_head, &
          layer_nstatv_extra=layer_nstatv_extra_3d)
      else
        d2 = untouched
        call interlock_umat_cohesive(traction(1:2), statev_law, d2, sse_law, spd_law, scd_law, &
          rpl_law, ddsddt_law(1:2), drplde_law(1:2), drpldt_law, s_start(1:2), ds_law(1:2), &
          TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, 1, 1, 2, NSTATV, &
          PROPS(layer_nprops_head + 1:NPROPS), NPROPS - layer_nprops_head, COORDS, DROT, &
          p_law, CELENT, DFGRD0, DFGRD1, NOEL, NPT, LAYER, KSPT, JSTEP, KINC, &
          layer_props_offset=layer_nprops_head, layer_nstatv_extra=layer_nstatv_extra)
        ! (the law checks its PROPS, named by both indices, and NSTATV)
        if (transfer(d2(1, 1), 0_int64) /= transfer(untouched, 0_int64)) d(1:2, 1:2) = d2
      end if
    end subroutine law

    !> One line naming the point (once per material and `kind`); bad input for the host.
    subroutine fail(why, kind)
      character(len=*), intent(in) :: why
      integer, intent(in) :: kind
      call say_at_point('interlock UMAT (layer): ', why, kind, NOEL, NPT, KINC, CMNAME)
      call request(-1.0_dp, .true.)
    end subroutine fail

    !> Ask the host for a shorter increment: `factor` in (0, 1), or a stop (bad input).
    subroutine request(factor, stop_analysis)
      real(dp), intent(in) :: factor
      logical, intent(in) :: stop_analysis
      real(dp) :: wanted
      select case (host)
      case (host_calculix)
        wanted = merge(pnewdt_calculix_stop, factor, stop_analysis)
        if (.not. is_finite_bits(PNEWDT)) then
          PNEWDT = wanted          ! garbage
        else if (PNEWDT <= 0.0_dp) then
          PNEWDT = wanted          ! -1: no request yet
        else
          PNEWDT = min(PNEWDT, wanted)
        end if
      case default
        call lower_pnewdt(PNEWDT, merge(-1.0_dp, factor, stop_analysis))
      end select
    end subroutine request

  end subroutine interlock_umat_layer_point

end module interlock_umat_layer
