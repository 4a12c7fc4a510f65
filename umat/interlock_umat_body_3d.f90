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
!> **Checks, PNEWDT, messages, energies** as the 2D body's header says, component by component
!> (the one check sequence of both bodies, umat/interlock_umat_support.f90: umat_check_call):
!> bad input -1, a diverged global iteration 0.25, a local failure 0.5, the accuracy bounds'
!> fraction (damage and the angles: the dip direction's wear); one line per material and kind;
!> a NaN PNEWDT on entry is replaced (by 1, no request, when none is due).
!> A local failure writes a 3D replay deck when INTERLOCK_REPLAY_DIR names a folder, as in 2D
!> (strike components, s_T2 and the RIA in it; `interlock-history` runs it).
!>
!> **Threads.** No SAVE'd, module or COMMON state is written but the messages' table (under
!> its lock); `recursive`: every local on the stack.
module interlock_umat_body_3d
  use interlock_umat_support, only: umat_check_call, umat_symmetric_tangent_wanted, &
      umat_energies
  use interlock_umat_reports, only: umat_update_failed, lower_pnewdt
  use interlock, only: dp, interlock_material_t, interlock_solver_t, interlock_state_3d_t, &
      interlock_info_t, interlock_update_3d, umat_controls_t, status_ok
  use interlock_step_control, only: step_fraction_3d
  implicit none
  private
  public :: interlock_umat_cohesive_3d

contains

  recursive subroutine interlock_umat_cohesive_3d(STRESS, STATEV, DDSDDE, SSE, SPD, SCD, RPL, &
      DDSDDT, DRPLDE, DRPLDT, STRAN, DSTRAN, TIME, DTIME, TEMP, DTEMP, PREDEF, DPRED, CMNAME, &
      NDI, NSHR, NTENS, NSTATV, PROPS, NPROPS, COORDS, DROT, PNEWDT, CELENT, DFGRD0, DFGRD1, &
      NOEL, NPT, LAYER, KSPT, JSTEP, KINC, layer_props_offset, layer_nstatv_extra)
    use interlock, only: statev_to_state_3d, state_to_statev_3d, interlock_symmetric_tangent_3d
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
    integer :: nsv
    logical :: ok

    associate (unused_1 => NDI, unused_2 => NSHR, unused_3 => LAYER, unused_4 => KSPT, &
               unused_5 => JSTEP, unused_6 => TIME, unused_7 => DTIME, unused_8 => TEMP, &
               unused_9 => DTEMP, unused_10 => PREDEF(1), unused_11 => DPRED(1), &
               unused_12 => COORDS, unused_13 => DROT, unused_14 => CELENT, &
               unused_15 => DFGRD0, unused_16 => DFGRD1)
    end associate

    ! --- Bad input and a diverged global iteration: the sequence both bodies run (the
    ! NSTATV the RIA needs, nsv, is known once the PROPS are).
    call umat_check_call(3, NTENS, NSTATV, NPROPS, STRESS, STATEV, STRAN, DSTRAN, PROPS, PNEWDT, &
                         NOEL, NPT, KINC, CMNAME, mat, solver, controls, nsv, s, ok, &
                         layer_props_offset, layer_nstatv_extra)
    if (.not. ok) return

    ! --- The update.
    call statev_to_state_3d(STATEV(1:nsv), mat, old)
    old%s = STRAN(1:2)
    old%s_t2 = STRAN(3)
    old%sigma = STRESS(1:2)
    old%sigma_t2 = STRESS(3)
    call interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
    if (info%status /= status_ok) then
      call umat_update_failed(info, mat, solver, old, s, NOEL, NPT, KINC, CMNAME, PNEWDT)
      return
    end if
    if (umat_symmetric_tangent_wanted(NPROPS, PROPS)) call interlock_symmetric_tangent_3d(tangent)
    STRESS = sigma
    DDSDDE = tangent
    call state_to_statev_3d(new, mat%n_planes, STATEV(1:nsv))
    call umat_energies(new, SSE, SPD, SCD, RPL, DDSDDT, DRPLDE, DRPLDT)

    ! --- Accuracy control, as in 2D (the damage and the dip angles of every plane).
    factor = step_fraction_3d(mat, solver, controls, old, new)
    if (factor < 1.0_dp) call lower_pnewdt(PNEWDT, factor)
  end subroutine interlock_umat_cohesive_3d

end module interlock_umat_body_3d
