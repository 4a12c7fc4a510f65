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
!> heap allocation. The checks are the sequence both bodies run (umat/interlock_umat_support.f90:
!> umat_check_call); every check of a value that may be garbage is one integer test on its bits
!> (interlock_numbers:key_in_range: no comparison of a NaN): PROPS and STATEV against
!> the material table's bounds in loops unrolled over the constant table, STRAN, DSTRAN and
!> STRESS by their magnitude. PROPS are read as the host passes them (props_n_to_material,
!> explicit shape), and the paper's three-plane RIA is derived in one
!> (interlock_material:interlock_paper_material_derive: no loops over the planes, one sine and
!> cosine, derive's formulas shared). The local material and states are not filled with
!> default values first (their derived and per-plane parts have none; props_n_to_material and
!> statev_to_state set what the update reads). The step fraction (interlock_step_control)
!> interpolates only when a bound is exceeded (bounds_met, one test per plane, first). This
!> file and the checks' are compiled for link-time optimisation with the UMAT's path
!> (umat/CMakeLists.txt), so that the check sequence, the STATEV checks and copies inline here.
!> Messages are built only on failure, in umat/interlock_umat_reports.f90.
!> interlock-bench measures the UMAT call against its update (docs/bench.md).
!>
!> **Threads.** No SAVE'd, module or COMMON state is written but the table of the messages
!> already written (umat/interlock_umat_messages.f90: only when a message is due, under a
!> lock); the procedure is `recursive` so that every local lives on the stack: safe to call
!> from many threads at once.
module interlock_umat_body
  use interlock_umat_support, only: umat_check_call, umat_symmetric_tangent_wanted, &
      umat_energies
  use interlock_umat_reports, only: umat_update_failed, lower_pnewdt
  use interlock, only: dp, interlock_material_t, interlock_solver_t, interlock_state_t, &
      interlock_info_t, interlock_update, umat_controls_t, status_ok
  use interlock_step_control, only: step_fraction
  implicit none
  private
  public :: interlock_umat_cohesive

contains

  recursive subroutine interlock_umat_cohesive(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, DDSDDT, DRPLDE, DRPLDT, &
                            STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, NDI, &
                            NSHR, NTENS, NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT, &
                            DFGRD0, DFGRD1, NOEL, NPT, LAYER, KSPT, JSTEP, KINC, &
                            layer_props_offset, layer_nstatv_extra)
    use interlock, only: statev_to_state, state_to_statev, interlock_symmetric_tangent
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
    integer :: nsv
    logical :: ok

    associate (unused_1 => NDI, unused_2 => NSHR, unused_3 => LAYER, unused_4 => KSPT, &
               unused_5 => JSTEP, unused_6 => TIME, unused_7 => DTIME, unused_8 => TEMP, &
               unused_9 => DTEMP, unused_10 => PREDEF(1), unused_11 => DPRED(1), &
               unused_12 => COORDS, unused_13 => DROT, unused_14 => CELENT, &
               unused_15 => DFGRD0, unused_16 => DFGRD1)
    end associate

    ! --- Bad input and a diverged global iteration: the sequence both bodies run.
    call umat_check_call(2, NTENS, NSTATV, NPROPS, STRESS, STATEV, STRAN, DSTRAN, PROPS, PNEWDT, &
                         NOEL, NPT, KINC, CMNAME, mat, solver, controls, nsv, s, ok, &
                         layer_props_offset, layer_nstatv_extra)
    if (.not. ok) return

    ! --- The update: state at the start from STATEV, STRAN and STRESS.
    call statev_to_state(STATEV(1:nsv), mat, old)
    old%s = STRAN(1:2)
    old%sigma = STRESS(1:2)
    call interlock_update(mat, solver, s, old, new, sigma, tangent, info)
    if (info%status /= status_ok) then
      call umat_update_failed(info, mat, solver, old, s, NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if

    if (umat_symmetric_tangent_wanted(NPROPS, PROPS)) call interlock_symmetric_tangent(tangent)
    STRESS(1:2) = sigma
    DDSDDE(1:2, 1:2) = tangent
    call state_to_statev(new, STATEV(1:nsv))
    call umat_energies(new, SSE, SPD, SCD, RPL, DDSDDT(1:2), DRPLDE(1:2), DRPLDT)

    ! --- Accuracy control: propose the fraction of the increment that meets the bounds
    ! (interlock_step_control:step_fraction).
    factor = step_fraction(mat, solver, controls, old, new)
    if (factor < 1.0_dp) call lower_pnewdt(PNEWDT, factor)
  end subroutine interlock_umat_cohesive

end module interlock_umat_body
