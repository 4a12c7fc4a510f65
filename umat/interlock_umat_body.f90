!> The body of the Abaqus-style UMAT of the interlock cohesive-zone law, for 2D cohesive
!> elements: `interlock_umat_cohesive` has the Abaqus argument list. The external `UMAT`
!> (umat/interlock_umat.f90) is a thin wrapper around it, so that hosts that bring a `umat`
!> of their own (CalculiX) and other entries (the thin layer, umat/interlock_umat_layer.f90)
!> can call the law under its own name.
!>
!> **Element and kinematics.** NTENS = 2: component 1 is the normal separation / traction,
!> component 2 the shear one. STRAN and DSTRAN are read as separations [mm]: use a constitutive
!> thickness of 1 (Abaqus: `*COHESIVE SECTION, RESPONSE=TRACTION SEPARATION, THICKNESS=SPECIFIED`
!> with thickness 1.0), so that strain = separation. The start-of-increment separation is
!> STRAN, the end-of-increment one STRAN + DSTRAN; STRESS on entry is the start traction.
!>
!> **Material.** PROPS and STATEV follow the material table (`interlock-query --props`,
!> `interlock-query --statev`, docs/material.md): NPROPS from 9 (the required properties) to 20,
!> NSTATV >= 22 (`*DEPVAR` 22; extra slots are left alone). The three-plane RIA of the paper.
!> DDSDDE is the library's exact algorithmic tangent, which is not symmetric once friction or
!> wear acts: declare `*USER MATERIAL, UNSYMM`. For a host that keeps only the symmetric part
!> (CalculiX), PROPS(20) `tangent` = 2 returns a symmetric tangent with the exact one's
!> eigenvalues (src/api/interlock_host_tangent.f90); the stress update is the same.
!>
!> **Energies.** SSE = stored (free) energy, SCD = total dissipation (damage + friction; the split
!> is in STATEV 20 and 21), SPD = 0. All per unit area [N/mm].
!>
!> **PNEWDT.** PNEWDT is only ever lowered, never raised (a NaN on entry is replaced: by 1, no
!> request, when none is due):
!>  - bad input (precision of the reals < 15, NTENS /= 2, NSTATV < 22, NPROPS or a property out
!>    of its range, NaN; a STATEV slot out of its range: damage outside [0, 1], negative beta
!>    or zeta, theta outside [theta_f, theta_0] of its plane, the flag STATEV(22) not 0 or 1,
!>    a slip, work or friction traction beyond 1e150 or not finite; STRESS on entry not finite
!>    or beyond 1e150 MPa; STRAN, the separation at the start of the increment, which the host
!>    converged, not finite or beyond the admissible 1e6 mm): PNEWDT = -1 (repeating the
!>    increment cannot help: stop the analysis);
!>  - a diverged global iteration (DSTRAN not finite or beyond 2e6 mm, or STRAN + DSTRAN
!>    beyond 1e6 mm: the host's Newton iterate went astray, the start is fine): PNEWDT =
!>    min(PNEWDT, 0.25), the cut a host makes for a diverged iteration of its own (a host on
!>    fixed increments cannot cut back: it stops, and the message says so);
!>  - local integration failure: PNEWDT = min(PNEWDT, 0.5);
!>  in these cases STRESS, STATEV, DDSDDE, SSE, SPD, SCD are left untouched, and one line
!>  `interlock UMAT: element E, point P (...): <why>` names the value (STATEV by index) and
!>  its admissible range, once per material and kind of message in the process
!>  (umat/interlock_umat_messages.f90: a bad property is one line, not one per point and call).
!>  - accuracy control: when one increment raises a damage variable by more than the property
!>    max_damage_increment, or turns a microplane by more than max_angle_increment_deg, f is
!>    the first-order estimate of the fraction of the increment that meets the bound. The
!>    scaling is linear in the variable that drives the bounded one: the history variable beta
!>    for the damage D = (beta-1)/(eta beta), the frictional work zeta for the angle
!>    theta(zeta). Both drivers are convex along a straight separation path (beta: a norm of an
!>    affine function; zeta: zero while sticking, then growing linearly), so the retried
!>    increment f * DSTRAN meets the bound (scaling D or theta themselves, which are concave in
!>    their drivers, would overshoot). With wear on and the explicit scheme, the interpolation
!>    starts from the state a zero increment gives (the angle stored at the end of the previous
!>    increment already turns the local frame, so a zero increment slips and wears a little);
!>    this costs one more update, only when a bound is exceeded (the implicit and trapezoidal
!>    schemes are consistent at a zero increment, SPEC D10: no extra update).
!>    A request discards the host's attempt (CalculiX acts on it at every global iteration,
!>    converged or not), so it is made only where it pays: PNEWDT = min(PNEWDT, max(0.01, f))
!>    when f < 0.8; a bound exceeded by less (f >= 0.8: the cut would shave less than a fifth
!>    of the increment) is accepted, and so is an increment no cut can bring within the bound
!>    (the state a zero increment gives is already beyond it, or the damage jumps: a retry
!>    would fail the same way).
!>    The results of the increment are returned all the same (the host discards them when it
!>    cuts back).
!>
!> **Arguments.** The argument list is the one of the current Abaqus manual, with
!> `JSTEP(4)` (step number, procedure type, NLGEOM flag, linear perturbation flag) where older
!> manuals have the scalar `KSTEP`; JSTEP is never read, so both conventions work.
!> Arguments this law does not need (temperature, field variables, geometry, time) are marked
!> unused with an empty `associate` block, which the compiler sees as a use and which
!> generates no code.
!>
!> **Replaying a failure.** When the environment variable INTERLOCK_REPLAY_DIR names a folder,
!> every local failure also writes a deck there, `interlock_replay_e<NOEL>_p<NPT>_k<KINC>.nml`,
!> with the parameters, the state at the start of the increment and the increment: run it with
!> `interlock-history` to reproduce the failure at that single point. Off by default, since an
!> FE run calls the UMAT from many threads and points.
!>
!> **Cost.** A host calls this once per integration point and iteration, so the success path
!> costs what the law costs plus what any UMAT must do (read and check PROPS and STATEV, derive
!> the constants, write STATEV back): no message, no formatted write, no long string copy, no
!> heap allocation. Every check of a value that may be garbage is one integer test on its bits
!> (interlock_material_table:key_in_range: no comparison of a NaN): PROPS and STATEV against
!> the material table's bounds in loops unrolled over the constant table, STRAN, DSTRAN and
!> STRESS by their magnitude. PROPS are read as the host passes them (props_n_to_material,
!> explicit shape), and the paper's three-plane RIA is derived in one
!> (interlock_material:interlock_paper_material_derive: no loops over the planes, one sine and
!> cosine, derive's formulas shared). The local material and states are not filled with
!> default values first (their derived and per-plane parts have none; props_n_to_material and
!> statev_to_state set what the update reads). The step fraction (interlock_step_control)
!> interpolates only when a bound is exceeded (bounds_met, one test per plane, first). This
!> file is compiled for link-time optimisation with the UMAT's path (umat/CMakeLists.txt), so
!> that the STATEV checks and copies inline here. Messages are built only on failure, in the procedures after the body.
!> interlock-bench measures the UMAT call against its update (docs/bench.md).
!>
!> **Threads.** No SAVE'd, module or COMMON state is written but the table of the messages
!> already written (umat/interlock_umat_messages.f90: only when a message is due, under a
!> lock); the procedure is `recursive` so that every local lives on the stack: safe to call
!> from many threads at once.
module interlock_umat_body
  use, intrinsic :: iso_fortran_env, only: int64
  use interlock_numbers, only: key_in_range
  use interlock_umat_messages, only: umat_say, said_argument, said_property, said_statev, &
      said_stress, said_start_strain, said_diverged, said_local_failure, said_replay
  use interlock, only: dp, separation_bound, state_bound, interlock_material_t, &
      interlock_solver_t, interlock_state_t, interlock_info_t, interlock_update, umat_controls_t, &
      status_ok, status_local_failure
  use interlock_step_control, only: step_fraction, pnewdt_bad_input, pnewdt_local_failure, &
      pnewdt_diverged, pnewdt_none, separation_bits, increment_bits, state_bits
  implicit none
  private
  public :: interlock_umat_cohesive, diverged_iteration_message, pnewdt_diverged
  ! (for the three-dimensional body, umat/interlock_umat_body_3d.f90: the same checks,
  ! messages and PNEWDT rules; the PNEWDT values and bounds are interlock_step_control's)
  public :: bad_precision, bad_ntens, bad_nstatv, bad_stress, &
            report, report_update_failure, separation_text, lower_pnewdt, property_index, name_layer_property, &
            reject_argument, reject_start_separation, write_replay, pnewdt_none, &
            layer_nstatv_between, reject_layer_nstatv

  !> What reject_argument reports.
  integer, parameter :: bad_precision = 1, bad_ntens = 2, bad_nstatv = 3, bad_stress = 4

contains

  recursive subroutine interlock_umat_cohesive(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT, DRPLDE, DRPLDT, &
                            STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, NDI, &
                            NSHR, NTENS, NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT, &
                            DFGRD0, DFGRD1, NOEL, NPT, LAYER, KSPT, JSTEP, KINC, &
                            layer_props_offset, layer_nstatv_extra)
    use interlock, only: props_n_to_material, statev_to_state, state_to_statev, umat_nstatv, &
        message_len, statev_bad_index, format_real, prop_tangent, tangent_symmetric, &
        interlock_symmetric_tangent, is_nan_value
    implicit none
    integer, intent(in) :: NDI                 !< direct components (1 for a 2D cohesive element)
    integer, intent(in) :: NSHR                !< shear components (1 for a 2D cohesive element)
    integer, intent(in) :: NTENS               !< must be 2
    integer, intent(in) :: NSTATV              !< >= 22
    integer, intent(in) :: NPROPS              !< 9 .. 20 (later PROPS: defaults)
    integer, intent(in) :: NOEL, NPT           !< element and integration point (for messages)
    integer, intent(in) :: LAYER, KSPT         !< layer and section point (unused)
    integer, intent(in) :: JSTEP(4)            !< step information (unused; KSTEP in old manuals)
    integer, intent(in) :: KINC                !< increment number (for messages)
    character(len=*), intent(in) :: CMNAME     !< material name (for messages)
    real(dp), intent(inout) :: STRESS(NTENS)   !< traction (normal, shear) [MPa]: start in, end out
    real(dp), intent(inout) :: STATEV(NSTATV)  !< state variables, see interlock-query --statev
    real(dp), intent(inout) :: DDSDDE(NTENS, NTENS) !< d STRESS / d STRAN [MPa/mm]
    real(dp), intent(inout) :: SSE             !< stored energy per unit area [N/mm]
    real(dp), intent(inout) :: SPD             !< set to 0 (all dissipation is in SCD)
    real(dp), intent(inout) :: SCD             !< damage + friction dissipation per area [N/mm]
    real(dp), intent(inout) :: RPL, DRPLDT     !< no heat generation: set to 0
    real(dp), intent(inout) :: DDSDDT(NTENS), DRPLDE(NTENS) !< no thermal coupling: set to 0
    real(dp), intent(in) :: STRAN(NTENS)       !< separation at the start of the increment [mm]
    real(dp), intent(in) :: DSTRAN(NTENS)      !< separation increment [mm]
    real(dp), intent(in) :: TIME(2), DTIME, TEMP, DTEMP, PREDEF(*), DPRED(*) !< unused
    real(dp), intent(in) :: PROPS(NPROPS)      !< properties, see interlock-query --props
    real(dp), intent(in) :: COORDS(3), DROT(3, 3), CELENT, DFGRD0(3, 3), DFGRD1(3, 3) !< unused
    real(dp), intent(inout) :: PNEWDT          !< suggested time-step ratio (only lowered here)
    !> For the thin layer (umat/interlock_umat_layer.f90): PROPS are its PROPS from this index
    !> + 1 on, and a bad property is named by both indices.
    integer, intent(in), optional :: layer_props_offset
    !> For the thin layer: the slots of its output after the law's STATEV (NSTATV between the
    !> two counts is bad input: room for part of that output only).
    integer, intent(in), optional :: layer_nstatv_extra

    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(umat_controls_t) :: controls
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info
    real(dp) :: s(2), sigma(2), tangent(2, 2), factor
    integer :: stat, bad
    logical :: ok
    character(len=message_len) :: message

    associate (unused_1 => NDI, unused_2 => NSHR, unused_3 => LAYER, unused_4 => KSPT, &
               unused_5 => JSTEP, unused_6 => TIME, unused_7 => DTIME, unused_8 => TEMP, &
               unused_9 => DTEMP, unused_10 => PREDEF(1), unused_11 => DPRED(1), &
               unused_12 => COORDS, unused_13 => DROT, unused_14 => CELENT, &
               unused_15 => DFGRD0, unused_16 => DFGRD1)
    end associate

    ! A NaN PNEWDT on entry is garbage: replaced by "no request" (1), whatever happens next.
    if (is_nan_value(PNEWDT)) PNEWDT = pnewdt_none
    ! --- Bad input: the host's arguments, every property by its range, the separations, the
    ! traction and the state on entry (every value that may be garbage tested on its bits, see
    ! "Cost"); the messages only on failure.
    if (precision(STRESS) < 15 .or. precision(PROPS) < 15 .or. precision(PNEWDT) < 15) then
      call reject_argument(bad_precision, min(precision(STRESS), precision(PROPS), &
                           precision(PNEWDT)), [0.0_dp, 0.0_dp], NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    if (NTENS /= 2) then
      call reject_argument(bad_ntens, NTENS, [0.0_dp, 0.0_dp], NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    if (NSTATV < umat_nstatv) then
      call reject_argument(bad_nstatv, NSTATV, [0.0_dp, 0.0_dp], NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    if (present(layer_nstatv_extra)) then
      if (layer_nstatv_between(NSTATV, umat_nstatv, layer_nstatv_extra)) then
        call reject_layer_nstatv(NSTATV, umat_nstatv, layer_nstatv_extra, NOEL, NPT, KINC, &
                                 CMNAME, PNEWDT)
        return
      end if
    end if
    call props_n_to_material(NPROPS, PROPS, mat, solver, controls, stat, message)
    if (stat /= status_ok) then
      bad = property_index(message)
      if (present(layer_props_offset)) call name_layer_property(message, layer_props_offset, NPROPS)
      call report(message, pnewdt_bad_input, said_property + bad, NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    ! |x| <= bound on the magnitude's bits (key_in_range): false for NaN and the infinities,
    ! no comparison of a NaN (a trap), then the sum of values now known finite. STRAN is the
    ! converged start (out of range: bad input); DSTRAN the host's iterate (out of range, or
    ! its end beyond the bound: a diverged global iteration, cut back).
    ok = key_in_range(STRAN(1), -1 - separation_bits, separation_bits) .and. &
         key_in_range(STRAN(2), -1 - separation_bits, separation_bits)
    if (.not. ok) then
      call reject_start_separation(STRAN(1:2), NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    ok = key_in_range(STRESS(1), -1 - state_bits, state_bits) .and. &
         key_in_range(STRESS(2), -1 - state_bits, state_bits)
    if (.not. ok) then
      call reject_argument(bad_stress, 0, STRESS(1:2), NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    bad = statev_bad_index(STATEV(1:umat_nstatv), mat)
    if (bad /= 0) then
      call reject_statev(STATEV(1:umat_nstatv), bad, mat, NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    ! (last: every bad input above wins over a diverged iteration, so that a host is stopped,
    ! not sent into cutbacks, by input that no cutback repairs)
    ok = key_in_range(DSTRAN(1), -1 - increment_bits, increment_bits) .and. &
         key_in_range(DSTRAN(2), -1 - increment_bits, increment_bits)
    if (ok) then
      s = STRAN(1:2) + DSTRAN(1:2)
      ok = abs(s(1)) <= separation_bound .and. abs(s(2)) <= separation_bound
    end if
    if (.not. ok) then
      call report(diverged_iteration_message('DSTRAN = ' // separation_text(DSTRAN(1:2)) // &
                  ' mm', '|s_N|, |s_T| <= ' // &
                  format_real(separation_bound) // ' mm'), pnewdt_diverged, said_diverged, &
                  NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if

    ! --- The update: state at the start from STATEV, STRAN and STRESS.
    call statev_to_state(STATEV(1:umat_nstatv), mat, old)
    old%s = STRAN(1:2)
    old%sigma = STRESS(1:2)
    call interlock_update(mat, solver, s, old, new, sigma, tangent, info)
    if (info%status /= status_ok) then
      call report_update_failure(info, NOEL, NPT, KINC, CMNAME, PNEWDT)
      if (info%status == status_local_failure) &
        call write_replay(info%message, mat, solver, old, s, NOEL, NPT, KINC, CMNAME)
      return
    end if

    ! Property `tangent` = 2: a symmetric DDSDDE for hosts that symmetrize (the update is not
    ! touched; src/api/interlock_host_tangent.f90 says why this one).
    if (NPROPS >= prop_tangent) then
      ! (a whole number, checked: no rounding call)
      if (PROPS(prop_tangent) > tangent_symmetric - 0.5_dp) call interlock_symmetric_tangent(tangent)
    end if
    STRESS(1:2) = sigma
    DDSDDE(1:2, 1:2) = tangent
    call state_to_statev(new, STATEV(1:umat_nstatv))
    SSE = new%stored
    SPD = 0.0_dp
    SCD = new%diss_damage + new%diss_friction
    RPL = 0.0_dp
    DDSDDT(1:2) = 0.0_dp
    DRPLDE(1:2) = 0.0_dp
    DRPLDT = 0.0_dp

    ! --- Accuracy control: propose the fraction of the increment that meets the bounds
    ! (interlock_step_control:step_fraction).
    factor = step_fraction(mat, solver, controls, old, new)
    if (factor < 1.0_dp) call lower_pnewdt(PNEWDT, factor)
  end subroutine interlock_umat_cohesive

  !> PNEWDT = min(PNEWDT, proposal); a NaN on entry is replaced (tested on its bits: an
  !> ordered comparison of a NaN raises the invalid flag, a trap in hosts that run with traps).
  subroutine lower_pnewdt(pnewdt, proposal)
    use interlock, only: is_finite_bits
    real(dp), intent(inout) :: pnewdt
    real(dp), intent(in) :: proposal
    if (.not. is_finite_bits(pnewdt)) then
      pnewdt = proposal
    else if (proposal < pnewdt) then
      pnewdt = proposal
    end if
  end subroutine lower_pnewdt

  !> A failed update: one line with its message; PNEWDT 0.5 for a local failure (a shorter
  !> increment may pass), -1 for bad input.
  subroutine report_update_failure(info, noel, npt, kinc, cmname, pnewdt)
    type(interlock_info_t), intent(in) :: info
    integer, intent(in) :: noel, npt, kinc
    character(len=*), intent(in) :: cmname
    real(dp), intent(inout) :: pnewdt
    if (info%status == status_local_failure) then
      call report(info%message, pnewdt_local_failure, said_local_failure, noel, npt, kinc, &
                  cmname, pnewdt)
    else
      call report(info%message, pnewdt_bad_input, said_argument, noel, npt, kinc, cmname, pnewdt)
    end if
  end subroutine report_update_failure

  !> Write one line naming the point, lower PNEWDT; STRESS and STATEV stay as they came.
  !> A bad interlock property of the thin layer, named by its index in the layer's PROPS too
  !> ("layer PROPS(8) = interlock PROPS(4): ..."): its PROPS start `offset` values later.
  subroutine name_layer_property(message, offset, nprops)
    use interlock, only: format_integer
    character(len=*), intent(inout) :: message
    integer, intent(in) :: offset, nprops
    integer :: index_2d
    index_2d = property_index(message)
    if (index_2d > 0) then
      message = 'layer PROPS(' // format_integer(index_2d + offset) // ') = interlock ' // &
                trim(message)
    else
      message = 'layer PROPS(' // format_integer(offset + 1) // ':' // &
                format_integer(offset + nprops) // ') (the interlock PROPS): ' // trim(message)
    end if
  end subroutine name_layer_property

  !> One line naming the point (once per material and `kind`, umat_say); PNEWDT lowered to
  !> `proposal`.
  subroutine report(why, proposal, kind, noel, npt, kinc, cmname, pnewdt)
    use interlock, only: format_integer
    character(len=*), intent(in) :: why, cmname
    real(dp), intent(in) :: proposal
    integer, intent(in) :: kind, noel, npt, kinc
    real(dp), intent(inout) :: pnewdt
    call umat_say(cmname, kind, 'interlock UMAT: element ' // format_integer(noel) // &
      ', point ' // format_integer(npt) // " (material '" // trim(cmname) // "', increment " // &
      format_integer(kinc) // '): ' // trim(why))
    call lower_pnewdt(pnewdt, proposal)
  end subroutine report

  !> The index i of a message "PROPS(i): ..." (0 when it names none).
  integer function property_index(message) result(i)
    character(len=*), intent(in) :: message
    integer :: close_bracket, ios
    i = 0
    close_bracket = index(message, ')')
    if (index(message, 'PROPS(') == 1 .and. close_bracket > 7) then
      read (message(7:close_bracket - 1), *, iostat=ios) i
      if (ios /= 0) i = 0
    end if
  end function property_index

  !> Reject a bad argument of the host (`what`: bad_*), naming the value.
  subroutine reject_argument(what, n, x, noel, npt, kinc, cmname, pnewdt)
    use interlock, only: format_integer, format_real, umat_nstatv, is_finite_bits
    integer, intent(in) :: what, n, noel, npt, kinc
    real(dp), intent(in) :: x(:)   !< STRESS on entry (bad_stress)
    character(len=*), intent(in) :: cmname
    real(dp), intent(inout) :: pnewdt
    integer :: i
    select case (what)
    case (bad_precision)
      call report('the real arguments have ' // format_integer(n) // ' significant digits, ' // &
                  'fewer than 15: compile the host and the UMAT in double precision', &
                  pnewdt_bad_input, said_argument + what, noel, npt, kinc, cmname, pnewdt)
    case (bad_ntens)
      call report('NTENS = ' // format_integer(n) // ' is inadmissible: admissible NTENS = 2 ' // &
                  '(2D cohesive element: 1 normal, 2 shear) or 3 (3D cohesive element: 1 ' // &
                  'normal, 2 and 3 shear)', pnewdt_bad_input, &
                  said_argument + what, noel, npt, kinc, cmname, pnewdt)
    case (bad_nstatv)
      call report('NSTATV = ' // format_integer(n) // ' is inadmissible: admissible NSTATV >= ' &
                  // format_integer(umat_nstatv) // ' (*DEPVAR; see interlock-query --statev)', &
                  pnewdt_bad_input, said_argument + what, noel, npt, kinc, cmname, pnewdt)
    case (bad_stress)
      do i = 1, size(x) - 1
        if (.not. is_finite_bits(x(i))) exit
        if (abs(x(i)) > state_bound) exit
      end do
      call report('STRESS(' // format_integer(i) // ') = ' // format_real(x(i)) // ' on entry ' // &
                  'is inadmissible: admissible |STRESS| <= ' // format_real(state_bound) // &
                  ' MPa (the traction this UMAT returned for the last increment)', &
                  pnewdt_bad_input, said_stress + i, noel, npt, kinc, cmname, pnewdt)
    end select
  end subroutine reject_argument

  !> The thin layer's NSTATV holds the law's state and part of the layer's output (`extra`
  !> slots after the law's `law_nstatv`): that part would silently never be written.
  pure logical function layer_nstatv_between(nstatv, law_nstatv, extra)
    integer, intent(in) :: nstatv, law_nstatv, extra
    layer_nstatv_between = nstatv > law_nstatv .and. nstatv < law_nstatv + extra
  end function layer_nstatv_between

  !> Reject a thin layer's NSTATV between the law's count and the law's and the layer's.
  subroutine reject_layer_nstatv(nstatv, law_nstatv, extra, noel, npt, kinc, cmname, pnewdt)
    use interlock, only: format_integer
    integer, intent(in) :: nstatv, law_nstatv, extra, noel, npt, kinc
    character(len=*), intent(in) :: cmname
    real(dp), intent(inout) :: pnewdt
    call report('NSTATV = ' // format_integer(nstatv) // ' is inadmissible for the thin ' // &
                'layer: admissible NSTATV = ' // format_integer(law_nstatv) // ' (the law''s ' // &
                'state) or NSTATV >= ' // format_integer(law_nstatv + extra) // ' (also the ' // &
                'layer''s separation and traction, STATEV ' // format_integer(law_nstatv + 1) // &
                '-' // format_integer(law_nstatv + extra) // '); ' // format_integer(nstatv) // &
                ' would leave that output unwritten (*DEPVAR)', pnewdt_bad_input, &
                said_argument + bad_nstatv, noel, npt, kinc, cmname, pnewdt)
  end subroutine reject_layer_nstatv

  !> Reject the separation at the start of the increment (the host's converged STRAN): not
  !> finite or beyond the admissible bound is bad input.
  subroutine reject_start_separation(stran, noel, npt, kinc, cmname, pnewdt)
    use interlock, only: format_real
    real(dp), intent(in) :: stran(:)   !< (s_N, s_T) or (s_N, s_T1, s_T2)
    integer, intent(in) :: noel, npt, kinc
    character(len=*), intent(in) :: cmname
    real(dp), intent(inout) :: pnewdt
    character(len=*), parameter :: names_2d = '|s_N|, |s_T|', names_3d = '|s_N|, |s_T1|, |s_T2|'
    character(len=len(names_3d)) :: names
    names = names_3d
    if (size(stran) == 2) names = names_2d
    call report('the separation at the start of the increment STRAN = ' // &
                separation_text(stran) // ' mm is inadmissible: admissible ' // trim(names) // &
                ' <= ' // format_real(separation_bound) // &
                ' mm (separations in mm: constitutive thickness 1)', pnewdt_bad_input, &
                said_start_strain, noel, npt, kinc, cmname, pnewdt)
  end subroutine reject_start_separation

  !> "(x, y)" or "(x, y, z)".
  pure function separation_text(s) result(text)
    use interlock, only: format_reals
    real(dp), intent(in) :: s(:)
    character(len=len(format_reals(s)) + 2) :: text
    text = '(' // format_reals(s) // ')'
  end function separation_text

  !> The message of a diverged global iteration: `what` ("DSTRAN = (x, y) mm") is not finite
  !> or takes the end of the increment beyond `bound` ("|s| <= 1e6 mm"): the host's iterate
  !> went astray from a sound start. What follows the request depends on the host's
  !> incrementation, and the message says both: automatic increments retry a quarter of the
  !> increment; fixed ones (ccx's *STATIC, DIRECT) cannot be cut back, and the host stops.
  pure function diverged_iteration_message(what, bound) result(message)
    use interlock, only: format_real, message_len
    character(len=*), intent(in) :: what, bound
    character(len=message_len) :: message
    message = 'diverged global iteration: ' // what // ' is not finite or takes the end of ' // &
              'the increment beyond ' // bound // ' (the start is sound: the host''s Newton ' // &
              'iterate went astray): PNEWDT ' // format_real(pnewdt_diverged) // ' asks to ' // &
              'retry the increment cut back to a quarter (automatic incrementation); with ' // &
              'fixed increments the host cannot cut back and stops'
  end function diverged_iteration_message

  !> Reject STATEV(bad), naming index, variable, value and range.
  subroutine reject_statev(statev, bad, mat, noel, npt, kinc, cmname, pnewdt)
    use interlock, only: umat_nstatv, statev_message, message_len
    real(dp), intent(in) :: statev(umat_nstatv)
    integer, intent(in) :: bad, noel, npt, kinc
    type(interlock_material_t), intent(in) :: mat
    character(len=*), intent(in) :: cmname
    real(dp), intent(inout) :: pnewdt
    character(len=message_len) :: message
    call statev_message(statev, bad, mat, message)
    call report(message, pnewdt_bad_input, said_statev + bad, noel, npt, kinc, cmname, pnewdt)
  end subroutine reject_statev

  !> The replay deck of a failed increment, when INTERLOCK_REPLAY_DIR asks for it (a 3D state
  !> and s = (s_N, s_T1, s_T2): a 3D deck).
  subroutine write_replay(why, mat, solver, old, s, noel, npt, kinc, cmname)
    use interlock, only: interlock_write_replay_deck, format_integer
    character(len=*), intent(in) :: why, cmname
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    class(interlock_state_t), intent(in) :: old
    real(dp), intent(in) :: s(:)
    integer, intent(in) :: noel, npt, kinc
    character(len=4096) :: dir
    character(len=:), allocatable :: name
    integer :: length, env_stat, ios
    call get_environment_variable('INTERLOCK_REPLAY_DIR', dir, length, env_stat)
    if (env_stat /= 0 .or. length == 0) return
    name = 'interlock_replay_e' // format_integer(noel) // '_p' // format_integer(npt) // '_k' // &
           format_integer(kinc) // '.nml'
    call interlock_write_replay_deck(trim(dir) // '/' // name, mat, solver, old, s, &
      'UMAT element ' // format_integer(noel) // ', point ' // format_integer(npt) // &
      ', increment ' // format_integer(kinc) // ': ' // why, ios)
    if (ios /= 0) call umat_say(cmname, said_replay, 'interlock UMAT: could not write the ' // &
      'replay deck ' // trim(dir) // '/' // name)
  end subroutine write_replay

end module interlock_umat_body
