!> The reports of the UMAT entries, built only when a call fails: one line that names the
!> point (element, integration point, material, increment) and the value with its admissible
!> range, once per material and kind of message (umat/interlock_umat_messages.f90), PNEWDT
!> lowered to the answer of umat/interlock_umat_body.f90's header, and a failed update's replay
!> deck. The check sequence (umat/interlock_umat_support.f90), the bodies and the thin layer
!> call them. (A file of their own, compiled without link-time optimisation: the string
!> building never inlines into the check sequence, which runs on every call.)
!>
!> **Threads.** No SAVE'd, module or COMMON state is written but the messages' table
!> (umat/interlock_umat_messages.f90, under its lock).
module interlock_umat_reports
  use interlock_umat_messages, only: umat_say, said_argument, said_property, said_statev, &
      said_stress, said_start_strain, said_diverged, said_local_failure, said_replay
  use interlock, only: dp, separation_bound, state_bound, interlock_material_t, &
      interlock_solver_t, interlock_state_t, interlock_info_t, status_local_failure, &
      message_len, format_integer, format_real, format_reals, is_finite_bits
  use interlock_step_control, only: pnewdt_bad_input, pnewdt_local_failure, pnewdt_diverged
  implicit none
  private
  public :: umat_update_failed, lower_pnewdt, say_at_point, diverged_iteration_message
  public :: bad_precision, bad_ntens, reject_argument, reject_nstatv, reject_layer_nstatv, &
            reject_properties, reject_start_separation, reject_statev, reject_diverged, &
            bad_stress

  !> What reject_argument reports (the host argument's `said_argument` offset).
  integer, parameter :: bad_precision = 1, bad_ntens = 2, bad_nstatv = 3, bad_stress = 4

contains

  !> A failed update: one line with its message, PNEWDT 0.5 for a local failure (a shorter
  !> increment may pass; and its replay deck when INTERLOCK_REPLAY_DIR asks for it), -1 for
  !> bad input.
  subroutine umat_update_failed(info, mat, solver, old, s, noel, npt, kinc, cmname, pnewdt)
    type(interlock_info_t), intent(in) :: info
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    class(interlock_state_t), intent(in) :: old
    real(dp), intent(in) :: s(:)
    integer, intent(in) :: noel, npt, kinc
    character(len=*), intent(in) :: cmname
    real(dp), intent(inout) :: pnewdt
    if (info%status == status_local_failure) then
      call report(info%message, pnewdt_local_failure, said_local_failure, noel, npt, kinc, &
                  cmname, pnewdt)
      call write_replay(info%message, mat, solver, old, s, noel, npt, kinc, cmname)
    else
      call report(info%message, pnewdt_bad_input, said_argument, noel, npt, kinc, cmname, pnewdt)
    end if
  end subroutine umat_update_failed

  !> PNEWDT = min(PNEWDT, proposal); a NaN on entry is replaced (tested on its bits: an
  !> ordered comparison of a NaN raises the invalid flag, a trap in hosts that run with traps).
  pure subroutine lower_pnewdt(pnewdt, proposal)
    real(dp), intent(inout) :: pnewdt
    real(dp), intent(in) :: proposal
    if (.not. is_finite_bits(pnewdt)) then
      pnewdt = proposal
    else if (proposal < pnewdt) then
      pnewdt = proposal
    end if
  end subroutine lower_pnewdt

  !> One line `<who>element E, point P (material 'M', increment K): <why>`, once per material
  !> and `kind` (umat_say).
  subroutine say_at_point(who, why, kind, noel, npt, kinc, cmname)
    character(len=*), intent(in) :: who, why, cmname
    integer, intent(in) :: kind, noel, npt, kinc
    call umat_say(cmname, kind, who // 'element ' // format_integer(noel) // ', point ' // &
      format_integer(npt) // " (material '" // trim(cmname) // "', increment " // &
      format_integer(kinc) // '): ' // trim(why))
  end subroutine say_at_point

  !> One line naming the point; PNEWDT lowered to `proposal`. STRESS and STATEV stay as they
  !> came.
  subroutine report(why, proposal, kind, noel, npt, kinc, cmname, pnewdt)
    character(len=*), intent(in) :: why, cmname
    real(dp), intent(in) :: proposal
    integer, intent(in) :: kind, noel, npt, kinc
    real(dp), intent(inout) :: pnewdt
    call say_at_point('interlock UMAT: ', why, kind, noel, npt, kinc, cmname)
    call lower_pnewdt(pnewdt, proposal)
  end subroutine report

  !> Reject the PROPS (props_n_to_material's `message`, "PROPS(i): ..."); the thin layer's
  !> are named by both indices.
  subroutine reject_properties(message, nprops, noel, npt, kinc, cmname, pnewdt, &
                               layer_props_offset)
    character(len=*), intent(inout) :: message
    integer, intent(in) :: nprops, noel, npt, kinc
    character(len=*), intent(in) :: cmname
    real(dp), intent(inout) :: pnewdt
    integer, intent(in), optional :: layer_props_offset
    integer :: bad
    bad = property_index(message)
    if (present(layer_props_offset)) call name_layer_property(message, layer_props_offset, nprops)
    call report(message, pnewdt_bad_input, said_property + bad, noel, npt, kinc, cmname, pnewdt)
  end subroutine reject_properties

  !> A diverged global iteration: DSTRAN not finite or beyond its bound, or the end of the
  !> increment beyond the separations' bound.
  subroutine reject_diverged(dstran, noel, npt, kinc, cmname, pnewdt)
    real(dp), intent(in) :: dstran(:)
    integer, intent(in) :: noel, npt, kinc
    character(len=*), intent(in) :: cmname
    real(dp), intent(inout) :: pnewdt
    call report(diverged_iteration_message('DSTRAN = ' // separation_text(dstran) // ' mm', &
                trim(separation_names(size(dstran))) // ' <= ' // &
                format_real(separation_bound) // ' mm'), pnewdt_diverged, said_diverged, noel, &
                npt, kinc, cmname, pnewdt)
  end subroutine reject_diverged

  !> A bad interlock property of the thin layer, named by its index in the layer's PROPS too
  !> ("layer PROPS(8) = interlock PROPS(4): ..."): its PROPS start `offset` values later.
  subroutine name_layer_property(message, offset, nprops)
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

  !> Reject NSTATV below the law's count `nsv` (a law of dimension n; in 3D the count
  !> follows the RIA's n_planes).
  subroutine reject_nstatv(nstatv, nsv, n, n_planes, noel, npt, kinc, cmname, pnewdt)
    integer, intent(in) :: nstatv, nsv, n, n_planes, noel, npt, kinc
    character(len=*), intent(in) :: cmname
    real(dp), intent(inout) :: pnewdt
    if (n == 2) then
      call report('NSTATV = ' // format_integer(nstatv) // ' is inadmissible: admissible ' // &
                  'NSTATV >= ' // format_integer(nsv) // ' (*DEPVAR; see interlock-query ' // &
                  '--statev)', pnewdt_bad_input, said_argument + bad_nstatv, noel, npt, kinc, &
                  cmname, pnewdt)
    else
      call report('NSTATV = ' // format_integer(nstatv) // ' is inadmissible: admissible ' // &
                  'NSTATV >= ' // format_integer(nsv) // ' for a 3D interface (the 3D law) ' // &
                  'with a RIA of ' // format_integer(n_planes) // ' planes (*DEPVAR; see ' // &
                  'interlock-query --statev)', pnewdt_bad_input, said_argument + bad_nstatv, &
                  noel, npt, kinc, cmname, pnewdt)
    end if
  end subroutine reject_nstatv

  !> Reject a thin layer's NSTATV between the law's count and the law's and the layer's: the
  !> layer's output after the law's state would be partly, silently, unwritten.
  subroutine reject_layer_nstatv(nstatv, law_nstatv, extra, noel, npt, kinc, cmname, pnewdt)
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
    real(dp), intent(in) :: stran(:)   !< (s_N, s_T) or (s_N, s_T1, s_T2)
    integer, intent(in) :: noel, npt, kinc
    character(len=*), intent(in) :: cmname
    real(dp), intent(inout) :: pnewdt
    call report('the separation at the start of the increment STRAN = ' // &
                separation_text(stran) // ' mm is inadmissible: admissible ' // &
                trim(separation_names(size(stran))) // ' <= ' // format_real(separation_bound) &
                // ' mm (separations in mm: constitutive thickness 1)', pnewdt_bad_input, &
                said_start_strain, noel, npt, kinc, cmname, pnewdt)
  end subroutine reject_start_separation

  !> The separations' magnitudes of a law of dimension n, for messages.
  pure function separation_names(n) result(names)
    integer, intent(in) :: n
    character(len=*), parameter :: names_2d = '|s_N|, |s_T|', names_3d = '|s_N|, |s_T1|, |s_T2|'
    character(len=len(names_3d)) :: names
    names = names_3d
    if (n == 2) names = names_2d
  end function separation_names

  !> "(x, y)" or "(x, y, z)".
  pure function separation_text(s) result(text)
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
    character(len=*), intent(in) :: what, bound
    character(len=message_len) :: message
    message = 'diverged global iteration: ' // what // ' is not finite or takes the end of ' // &
              'the increment beyond ' // bound // ' (the start is sound: the host''s Newton ' // &
              'iterate went astray): PNEWDT ' // format_real(pnewdt_diverged) // ' asks to ' // &
              'retry the increment cut back to a quarter (automatic incrementation); with ' // &
              'fixed increments the host cannot cut back and stops'
  end function diverged_iteration_message

  !> Reject STATEV(bad) of a law of dimension n, naming index, variable, value and range.
  subroutine reject_statev(statev, n, bad, mat, noel, npt, kinc, cmname, pnewdt)
    use interlock, only: statev_message, statev_message_3d
    real(dp), intent(in) :: statev(:)
    integer, intent(in) :: n, bad, noel, npt, kinc
    type(interlock_material_t), intent(in) :: mat
    character(len=*), intent(in) :: cmname
    real(dp), intent(inout) :: pnewdt
    character(len=message_len) :: message
    if (n == 2) then
      call statev_message(statev, bad, mat, message)
    else
      call statev_message_3d(statev, bad, mat, message)
    end if
    call report(message, pnewdt_bad_input, said_statev + bad, noel, npt, kinc, cmname, pnewdt)
  end subroutine reject_statev

  !> The replay deck of a failed increment, when INTERLOCK_REPLAY_DIR asks for it (a 3D state
  !> and s = (s_N, s_T1, s_T2): a 3D deck).
  subroutine write_replay(why, mat, solver, old, s, noel, npt, kinc, cmname)
    use interlock, only: interlock_write_replay_deck
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


end module interlock_umat_reports
