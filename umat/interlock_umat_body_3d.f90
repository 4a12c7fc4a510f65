!> The body of the Abaqus-style UMAT for 3D cohesive elements (SPEC section 9):
!> `interlock_umat_cohesive_3d` has the Abaqus argument list. The external `UMAT`
!> (umat/interlock_umat.f90) calls it for NTENS = 3, the 2D body (umat/interlock_umat_body.f90)
!> for NTENS = 2; the thin layer (umat/interlock_umat_layer.f90) calls it for NTENS = 6.
!>
!> **Element and kinematics.** Abaqus' COH3D8 convention: NTENS = 3, NDI = 1, NSHR = 2;
!> components (normal, shear 1, shear 2) = (N, T1, T2), t1 the element's first local shear
!> direction (its local orientation, never the mesh: an anisotropic RIA must not depend on the
!> element), t2 = n x t1. Separations [mm] with a constitutive thickness of 1, as in 2D.
!>
!> **Material.** PROPS 1-20 are the 2D UMAT's (a 2D deck's constants give the paper's RIA in
!> 3D unchanged), PROPS(21) `ria` (0 paper, 1 azimuthal) and PROPS(22) `n_azimuths` select the
!> RIA (`interlock-query --props`). STATEV: the 2D layout for the RIA's planes, then the strike
!> components (`interlock-query --statev`): NSTATV >= 8 n_planes + 4 (28 for the paper's RIA,
!> 8 (1 + 2 N_a) + 4 for `azimuthal`). With the paper's RIA STATEV 1-22 mean what they mean in 2D.
!> DDSDDE is the exact 3 x 3 tangent (unsymmetric: `*USER MATERIAL, UNSYMM`); PROPS(20)
!> `tangent` = 2 the pairwise symmetric one (src/api/interlock_host_tangent.f90).
!>
!> **Checks, PNEWDT, messages, energies** as the 2D body's header says, component by component:
!> bad input -1, a diverged global iteration 0.25, a local failure 0.5, the accuracy bounds'
!> fraction (damage and the angles: the dip direction's wear); one line per material and kind;
!> a NaN PNEWDT on entry is replaced (by 1, no request, when none is due).
!> A local failure writes a 3D replay deck when INTERLOCK_REPLAY_DIR names a folder, as in 2D
!> (strike components, s_T2 and the RIA in it; `interlock-history` runs it).
!>
!> **Threads.** No SAVE'd, module or COMMON state is written but the messages' table (under
!> its lock); `recursive`: every local on the stack.
module interlock_umat_body_3d
  use interlock_numbers, only: key_in_range
  use interlock_umat_messages, only: said_argument, said_property, said_statev, said_diverged
  use interlock_step_control, only: step_fraction_3d, pnewdt_bad_input, pnewdt_diverged, &
      separation_bits, increment_bits, state_bits
  use interlock_umat_body, only: bad_precision, bad_ntens, &
      bad_nstatv, bad_stress, report, report_update_failure, lower_pnewdt, &
      property_index, name_layer_property, reject_argument, reject_start_separation, separation_text, &
      diverged_iteration_message, write_replay, pnewdt_none, layer_nstatv_between, &
      reject_layer_nstatv
  use interlock, only: dp, separation_bound, interlock_material_t, interlock_solver_t, &
      interlock_state_3d_t, interlock_info_t, interlock_update_3d, umat_controls_t, status_ok, &
      status_local_failure
  implicit none
  private
  public :: interlock_umat_cohesive_3d

contains

  recursive subroutine interlock_umat_cohesive_3d(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, &
      DDSDDT, DRPLDE, DRPLDT, STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, &
      NDI, NSHR, NTENS, NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT, DFGRD0, DFGRD1, &
      NOEL, NPT, LAYER, KSPT, JSTEP, KINC, layer_props_offset, layer_nstatv_extra)
    use interlock, only: props_n_to_material_3d, statev_to_state_3d, state_to_statev_3d, &
        statev_bad_index_3d, statev_message_3d, umat_nstatv_3d, message_len, format_integer, format_real, &
        prop_tangent, tangent_symmetric, interlock_symmetric_tangent_3d, is_nan_value
    integer, intent(in) :: NDI                 !< direct components (1)
    integer, intent(in) :: NSHR                !< shear components (2)
    integer, intent(in) :: NTENS               !< must be 3
    integer, intent(in) :: NSTATV              !< >= 8 n_planes + 4
    integer, intent(in) :: NPROPS              !< 9 .. 22 (later PROPS: defaults)
    integer, intent(in) :: NOEL, NPT           !< element and integration point (for messages)
    integer, intent(in) :: LAYER, KSPT         !< layer and section point (unused)
    integer, intent(in) :: JSTEP(4)            !< step information (unused; KSTEP in old manuals)
    integer, intent(in) :: KINC                !< increment number (for messages)
    character(len=*), intent(in) :: CMNAME     !< material name (for messages)
    real(dp), intent(inout) :: STRESS(NTENS)   !< traction (N, T1, T2) [MPa]: start in, end out
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
    !> For the thin layer: PROPS are its PROPS from this index + 1 on (messages name both).
    integer, intent(in), optional :: layer_props_offset
    !> For the thin layer: the slots of its output after the law's STATEV (NSTATV between the
    !> two counts is bad input: room for part of that output only).
    integer, intent(in), optional :: layer_nstatv_extra

    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(umat_controls_t) :: controls
    type(interlock_state_3d_t) :: old, new
    type(interlock_info_t) :: info
    real(dp) :: s(3), sigma(3), tangent(3, 3), factor
    integer :: stat, bad, nsv
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
    ! --- Bad input, as in 2D (every value that may be garbage tested on its bits).
    if (precision(STRESS) < 15 .or. precision(PROPS) < 15 .or. precision(PNEWDT) < 15) then
      call reject_argument(bad_precision, min(precision(STRESS), precision(PROPS), &
                           precision(PNEWDT)), [0.0_dp], NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    if (NTENS /= 3) then
      call reject_argument(bad_ntens, NTENS, [0.0_dp], NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    call props_n_to_material_3d(NPROPS, PROPS, mat, solver, controls, stat, message)
    if (stat /= status_ok) then
      bad = property_index(message)
      if (present(layer_props_offset)) call name_layer_property(message, layer_props_offset, NPROPS)
      call report(message, pnewdt_bad_input, said_property + bad, NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    ! (the STATEV the RIA needs: known once the PROPS are)
    nsv = umat_nstatv_3d(mat%n_planes)
    if (NSTATV < nsv) then
      call report('NSTATV = ' // format_integer(NSTATV) // ' is inadmissible: admissible ' // &
                  'NSTATV >= ' // format_integer(nsv) // ' for a 3D interface (the 3D law) ' // &
                  'with a RIA of ' // format_integer(mat%n_planes) // ' planes (*DEPVAR; see ' // &
                  'interlock-query --statev)', pnewdt_bad_input, said_argument + bad_nstatv, NOEL, NPT, KINC, CMNAME, &
                  PNEWDT)
      return
    end if
    if (present(layer_nstatv_extra)) then
      if (layer_nstatv_between(NSTATV, nsv, layer_nstatv_extra)) then
        call reject_layer_nstatv(NSTATV, nsv, layer_nstatv_extra, NOEL, NPT, KINC, CMNAME, &
                                 PNEWDT)
        return
      end if
    end if
    if (.not. all(key_in_range(STRAN, -1 - separation_bits, separation_bits))) then
      call reject_start_separation(STRAN, NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    if (.not. all(key_in_range(STRESS, -1 - state_bits, state_bits))) then
      call reject_argument(bad_stress, 0, STRESS, NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    bad = statev_bad_index_3d(STATEV(1:nsv), mat)
    if (bad /= 0) then
      call statev_message_3d(STATEV(1:nsv), bad, mat, message)
      call report(message, pnewdt_bad_input, said_statev + bad, NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    ! (last: bad input wins over a diverged iteration)
    ok = all(key_in_range(DSTRAN, -1 - increment_bits, increment_bits))
    if (ok) then
      s = STRAN + DSTRAN
      ok = all(abs(s) <= separation_bound)
    end if
    if (.not. ok) then
      call report(diverged_iteration_message('DSTRAN = ' // separation_text(DSTRAN) // ' mm', &
                  '|s_N|, |s_T1|, |s_T2| <= ' // &
                  format_real(separation_bound) // ' mm'), pnewdt_diverged, said_diverged, &
                  NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if

    ! --- The update.
    call statev_to_state_3d(STATEV(1:nsv), mat, old)
    old%s = STRAN(1:2)
    old%s_t2 = STRAN(3)
    old%sigma = STRESS(1:2)
    old%sigma_t2 = STRESS(3)
    call interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
    if (info%status /= status_ok) then
      call report_update_failure(info, NOEL, NPT, KINC, CMNAME, PNEWDT)
      if (info%status == status_local_failure) &
        call write_replay(info%message, mat, solver, old, s, NOEL, NPT, KINC, CMNAME)
      return
    end if
    if (NPROPS >= prop_tangent) then
      if (PROPS(prop_tangent) > tangent_symmetric - 0.5_dp) &
        call interlock_symmetric_tangent_3d(tangent)
    end if
    STRESS = sigma
    DDSDDE = tangent
    call state_to_statev_3d(new, mat%n_planes, STATEV(1:nsv))
    SSE = new%stored
    SPD = 0.0_dp
    SCD = new%diss_damage + new%diss_friction
    RPL = 0.0_dp
    DDSDDT = 0.0_dp
    DRPLDE = 0.0_dp
    DRPLDT = 0.0_dp

    ! --- Accuracy control, as in 2D (the damage and the dip angles of every plane).
    factor = step_fraction_3d(mat, solver, controls, old, new)
    if (factor < 1.0_dp) call lower_pnewdt(PNEWDT, factor)
  end subroutine interlock_umat_cohesive_3d

end module interlock_umat_body_3d
