!> The interlock law in a thin layer of continuum elements, for hosts without cohesive elements
!> (CalculiX): `interlock_umat_layer_point` has the Abaqus UMAT argument list plus `host`, the
!> host's PNEWDT convention. The interface is a layer of thickness h; one local axis is its
!> normal, another its slip direction, and the 2D law (`interlock_umat_cohesive`,
!> umat/interlock_umat_body.f90) acts on that pair:
!>
!>     separation s = h * (strain of the normal, engineering shear strain normal-slip)
!>     traction   t = (stress of the normal, shear stress normal-slip)
!>     DDSDDE on that block = h * (the law's tangent d t / d s)   [MPa = mm * MPa/mm]
!>
!> Every other component (the in-plane direct strains, the in-plane shear, the shear of the
!> normal with the third axis) is linear elastic and uncoupled: stress = e_other * strain,
!> DDSDDE = e_other on the diagonal. All NTENS x NTENS entries of DDSDDE are written.
!>
!> **Components.** NTENS = 6 (NDI = NSHR = 3; 11, 22, 33, 12, 13, 23; engineering shear; what
!> CalculiX passes for every element) or NTENS = 4 (11, 22, 33, 12; Abaqus' plane strain and
!> axisymmetric elements: only the 1-2 pair is an interface there). In the host's local axes
!> (the user's orientation; CalculiX rotates strains into them before the call and the stress
!> and the tangent back after it).
!>
!> **PROPS** (`layer_nprops_head` = 4 values, then the 2D law's PROPS 1 .. 9 to 1 .. 20):
!>   1 h [mm] > 0, 2 e_other [MPa] > 0, 3 normal_axis 1..3, 4 slip_axis 1..3 (/= normal_axis),
!>   5 .. the interlock PROPS (interlock-query --props). NPROPS from 13 to 24.
!> **STATEV**: the 2D law's 22 (NSTATV >= 22); with NSTATV >= 26 (`*DEPVAR` 26) also 23, 24 the
!> separation (normal, slip) [mm] and 25, 26 the traction (normal, slip) [MPa] at the end of the
!> increment, in the interface's axes (for output: hosts print S in their global axes).
!> **Energies** per unit volume: the law's SSE and SCD
!> (per unit area) / h, plus the elastic energy of the other components in SSE; SPD = 0.
!>
!> **PNEWDT** (`host`):
!>  - `host_abaqus`: as the 2D law (only lowered: -1 for bad input, 0.5 for a local failure,
!>    the accuracy bounds' fraction in [0.1, 1)).
!>  - `host_calculix`: ccx passes PNEWDT = -1 meaning "no request", and carries it from point to
!>    point within one thread (resultsmech.f); ANY positive value returned makes ccx discard the
!>    iteration and cut the increment by that factor (checkconvergence.c), at every iteration.
!>    So: a positive request is only ever lowered (a positive value that arrives is another
!>    point's request); bad input returns `pnewdt_calculix_stop` (1e-6: the increment falls
!>    below the minimum and ccx stops, or stops at once with fixed increments); a local
!>    failure 0.5 and the accuracy bounds their fraction. -1 is left alone when all is well.
!>  On bad input or a failure, STRESS, STATEV, DDSDDE and the energies are left as they came.
!>
!> **Threads.** No SAVE'd, module or COMMON state is written; `recursive`: every local on the
!> stack.
module interlock_umat_layer
  use interlock, only: dp, message_len, format_integer, format_real, is_nan_value, &
      same_value, umat_nstatv, n_required_properties, n_properties
  use interlock_umat_body, only: interlock_umat_cohesive
  implicit none
  private
  public :: interlock_umat_layer_point, host_abaqus, host_calculix, layer_nprops_head, &
            layer_nstatv_extra, &
            pnewdt_calculix_stop, layer_components

  integer, parameter :: host_abaqus = 1    !< PNEWDT starts at >= 1 and is only lowered
  integer, parameter :: host_calculix = 2  !< PNEWDT starts at -1 ("no request")
  integer, parameter :: layer_nprops_head = 4  !< h, e_other, normal_axis, slip_axis
  !> Optional STATEV after the law's 22: separation (normal, slip) and traction (normal, slip)
  !> in the interface's own axes, for output (a host prints stresses in its global axes).
  integer, parameter :: layer_nstatv_extra = 4
  !> The cutback factor that makes CalculiX stop on bad input (below any sensible minimum).
  real(dp), parameter :: pnewdt_calculix_stop = 1.0e-6_dp

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

  recursive subroutine interlock_umat_layer_point(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, &
      DDSDDT, DRPLDE, DRPLDT, STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, &
      NDI, NSHR, NTENS, NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT, DFGRD0, DFGRD1, &
      NOEL, NPT, LAYER, KSPT, JSTEP, KINC, host)
    use, intrinsic :: iso_fortran_env, only: output_unit
    integer, intent(in) :: NDI, NSHR, NTENS, NSTATV, NPROPS, NOEL, NPT, LAYER, KSPT, JSTEP(4), KINC
    character(len=*), intent(in) :: CMNAME
    real(dp), intent(inout) :: STRESS(NTENS), STATEV(NSTATV), DDSDDE(NTENS, NTENS)
    real(dp), intent(inout) :: SSE, SPD, SCD, RPL, DRPLDT, DDSDDT(NTENS), DRPLDE(NTENS)
    real(dp), intent(in) :: STRAN(NTENS), DSTRAN(NTENS), TIME(2), DTIME, TEMP, DTEMP
    real(dp), intent(in) :: PREDEF(*), DPRED(*), PROPS(NPROPS), COORDS(3), DROT(3, 3), CELENT
    real(dp), intent(in) :: DFGRD0(3, 3), DFGRD1(3, 3)
    real(dp), intent(inout) :: PNEWDT
    integer, intent(in) :: host   !< host_abaqus or host_calculix: the PNEWDT convention

    real(dp), parameter :: pnewdt_none = 1.0_dp
    real(dp), parameter :: untouched = -huge(1.0_dp)
    integer :: comp(2), normal, slip, i
    real(dp) :: h, e_other, t(2), s0(2), ds(2), d2(2, 2), sse2, spd2, scd2, rpl2, drpldt2, &
                ddsddt2(2), drplde2(2), p2, strain, elastic
    logical :: interface_component(NTENS)
    character(len=message_len) :: message

    ! --- The host's arguments and the layer's own PROPS, each by name and range.
    if (NTENS /= 4 .and. NTENS /= 6) then
      call fail('NTENS = ' // format_integer(NTENS) // ' is inadmissible: admissible NTENS = ' &
                // '6 (11, 22, 33, 12, 13, 23) or 4 (11, 22, 33, 12)', .true.)
      return
    end if
    if (NPROPS < layer_nprops_head + n_required_properties .or. &
        NPROPS > layer_nprops_head + n_properties) then
      call fail('NPROPS = ' // format_integer(NPROPS) // ' is inadmissible: admissible ' // &
                format_integer(layer_nprops_head + n_required_properties) // ' <= NPROPS <= ' // &
                format_integer(layer_nprops_head + n_properties) // ' (h, e_other, normal_axis, ' // &
                'slip_axis, then the interlock PROPS)', .true.)
      return
    end if
    h = PROPS(1)
    e_other = PROPS(2)
    if (.not. inside(h, 0.0_dp, 1.0e30_dp)) then
      call fail("layer PROPS(1): 'h' = " // format_real(h) // ' is inadmissible: admissible ' &
                // '0 < h < 1e30 [mm] (the layer thickness)', .true.)
      return
    end if
    if (.not. inside(e_other, 0.0_dp, 1.0e30_dp)) then
      call fail("layer PROPS(2): 'e_other' = " // format_real(e_other) // ' is inadmissible: ' &
                // 'admissible 0 < e_other < 1e30 [MPa] (the modulus of the other components)', &
                .true.)
      return
    end if
    do i = 3, 4
      if (.not. axis_value(PROPS(i))) then
        call fail('layer PROPS(' // format_integer(i) // "): '" // &
                  trim(merge('normal_axis', 'slip_axis  ', i == 3)) // "' = " // &
                  format_real(PROPS(i)) // ' is inadmissible: admissible 1, 2 or 3 (a local ' // &
                  'axis)', .true.)
        return
      end if
    end do
    normal = nint(PROPS(3))
    slip = nint(PROPS(4))
    comp = layer_components(NTENS, normal, slip)
    if (comp(1) == 0) then
      if (normal == slip) then
        message = "layer PROPS(4): 'slip_axis' = " // format_integer(slip) // ' is ' // &
                  "inadmissible: admissible a local axis other than 'normal_axis' = " // &
                  format_integer(normal)
      else
        message = "layer PROPS(3:4): 'normal_axis', 'slip_axis' = " // format_integer(normal) &
                  // ', ' // format_integer(slip) // ' is inadmissible with NTENS = 4: ' // &
                  'admissible the axes 1 and 2 (the only shear component is 12)'
      end if
      call fail(message, .true.)
      return
    end if
    ! --- The 2D law on the interface pair (separation = h * strain).
    t = STRESS(comp)
    s0 = h * STRAN(comp)
    ds = h * DSTRAN(comp)
    sse2 = SSE * h
    spd2 = 0.0_dp
    scd2 = SCD * h
    rpl2 = 0.0_dp
    drpldt2 = 0.0_dp
    ddsddt2 = 0.0_dp
    drplde2 = 0.0_dp
    d2 = untouched   ! the law writes all of DDSDDE when it succeeds, nothing when it fails
    p2 = pnewdt_none
    call interlock_umat_cohesive(t, STATEV, d2, sse2, spd2, scd2, rpl2, ddsddt2, drplde2, &
      drpldt2, s0, ds, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, 1, 1, 2, NSTATV, &
      PROPS(layer_nprops_head + 1:NPROPS), NPROPS - layer_nprops_head, COORDS, DROT, p2, &
      CELENT, DFGRD0, DFGRD1, NOEL, NPT, LAYER, KSPT, JSTEP, KINC, &
      layer_props_offset=layer_nprops_head)   ! (the law checks its PROPS, named by both indices)
    if (same_value(d2(1, 1), untouched)) then
      ! The law failed (it wrote its line and left its arguments alone): so does the layer.
      call request(max(p2, 0.0_dp), p2 <= 0.0_dp)
      return
    end if

    ! --- Assemble: the law's block, the other components elastic.
    interface_component = .false.
    interface_component(comp) = .true.
    DDSDDE = 0.0_dp
    elastic = 0.0_dp
    do i = 1, NTENS
      if (interface_component(i)) cycle
      strain = STRAN(i) + DSTRAN(i)
      STRESS(i) = e_other * strain
      DDSDDE(i, i) = e_other
      elastic = elastic + 0.5_dp * e_other * strain**2
    end do
    STRESS(comp) = t
    DDSDDE(comp, comp) = h * d2
    SSE = sse2 / h + elastic
    SPD = 0.0_dp
    SCD = scd2 / h
    RPL = 0.0_dp
    DDSDDT = 0.0_dp
    DRPLDE = 0.0_dp
    DRPLDT = 0.0_dp
    if (NSTATV >= umat_nstatv + layer_nstatv_extra) then
      STATEV(umat_nstatv + 1:umat_nstatv + 2) = s0 + ds
      STATEV(umat_nstatv + 3:umat_nstatv + 4) = t
    end if
    if (p2 < pnewdt_none) call request(p2, .false.)
    associate (unused_1 => NDI, unused_2 => NSHR)
    end associate

  contains

    !> lower < x < upper, false for NaN (tested first: no comparison with a NaN).
    pure logical function inside(x, lower, upper)
      real(dp), intent(in) :: x, lower, upper
      inside = .false.
      if (.not. is_nan_value(x)) inside = x > lower .and. x < upper
    end function inside

    !> 1, 2 or 3.
    pure logical function axis_value(x)
      real(dp), intent(in) :: x
      axis_value = inside(x, 0.5_dp, 3.5_dp)
      if (axis_value) axis_value = same_value(x, anint(x))
    end function axis_value

    !> One line naming the point; PNEWDT per the host's convention.
    subroutine fail(why, bad_input)
      character(len=*), intent(in) :: why
      logical, intent(in) :: bad_input
      character(len=64) :: where
      write (where, '(a,i0,a,i0)') 'element ', NOEL, ', point ', NPT
      write (output_unit, '(a)') 'interlock UMAT (layer): ' // trim(where) // " (material '" &
        // trim(CMNAME) // "', increment " // format_integer(KINC) // '): ' // trim(why)
      call request(-1.0_dp, bad_input)
    end subroutine fail

    !> Ask the host for a shorter increment: `factor` in (0, 1), or a stop (bad input).
    subroutine request(factor, stop_analysis)
      real(dp), intent(in) :: factor
      logical, intent(in) :: stop_analysis
      real(dp) :: wanted
      select case (host)
      case (host_calculix)
        wanted = merge(pnewdt_calculix_stop, factor, stop_analysis)
        if (is_nan_value(PNEWDT) .or. PNEWDT <= 0.0_dp) then
          PNEWDT = wanted          ! -1 (no request yet) or garbage
        else
          PNEWDT = min(PNEWDT, wanted)
        end if
      case default
        wanted = merge(-1.0_dp, factor, stop_analysis)
        if (is_nan_value(PNEWDT) .or. wanted < PNEWDT) PNEWDT = wanted
      end select
    end subroutine request

  end subroutine interlock_umat_layer_point

end module interlock_umat_layer
