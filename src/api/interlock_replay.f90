!> Replay decks: one failed (or suspicious) update written as an `interlock-history` input deck
!> (docs/deck-format.md) that reproduces it: every parameter (the RIA as a general one, per
!> plane), the effect switches, the solver, the state at the start of the update as
!> `&initial_state`, and a single separation-driven step from `old%s` to `s_new`. A 3D update
!> (a 3D state, three separations) gives a 3D deck: the planes' azimuths, the strike
!> components and t2 as well.
!> No module state: the routine only writes the file it is given.
module interlock_replay
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_null_char
  use interlock_kinds, only: dp, rad_to_deg, is_infinite_value
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_name, &
      effect_damage, effect_friction, effect_interlocking, effect_finite_depth, effect_wear
  use interlock_state, only: interlock_state_t, interlock_state_3d_t
  implicit none
  private
  public :: interlock_write_replay_deck

  !> Format of one real: 17 significant digits, so that the deck reads back bit for bit.
  character(len=*), parameter :: rfmt = '(es25.17e3)'

  interface
    !> C's rename(3): atomic on POSIX when both names are on the same file system.
    function c_rename(old, new) bind(c, name='rename') result(rc)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: old(*), new(*)
      integer(c_int) :: rc
    end function c_rename
  end interface

contains

  !> Write a deck to `path` that replays the update from `old` to the separation `s_new`
  !> with `mat` and `solver`; `reason` goes into the deck as a comment. The deck is written to
  !> `path // '.tmp'` and renamed, so a reader never sees a half-written deck.
  !> `ios` = 0 on success, else the I/O status (or -1 when the rename failed). `old` a 2D
  !> state and s_new (s_N, s_T), or a 3D state and s_new (s_N, s_T1, s_T2).
  subroutine interlock_write_replay_deck(path, mat, solver, old, s_new, reason, ios)
    character(len=*), intent(in) :: path
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    class(interlock_state_t), intent(in) :: old
    real(dp), intent(in) :: s_new(:)
    character(len=*), intent(in) :: reason
    integer, intent(out) :: ios
    character(len=:), allocatable :: tmp
    integer :: u, n, k, line_start, line_end
    integer(c_int) :: rc

    tmp = path // '.tmp'
    open (newunit=u, file=tmp, status='replace', action='write', form='formatted', iostat=ios)
    if (ios /= 0) return
    n = max(1, min(mat%n_planes, size(mat%gamma_hat)))

    write (u, '(a)', iostat=ios) '! interlock replay deck: one update that reproduces a failure'
    ! The reason, one comment line per line of text.
    line_start = 1
    do while (line_start <= len_trim(reason))
      line_end = index(reason(line_start:), new_line('a'))
      if (line_end == 0) then
        line_end = len_trim(reason)
      else
        line_end = line_start + line_end - 2
      end if
      write (u, '(a)', iostat=ios) '! reason: ' // reason(line_start:line_end)
      line_start = line_end + 2
    end do
    ! The core's own solver controls are not deck variables (the deck's newton_* belong to
    ! the mixed control of interlock-history): recorded here for a library-level replay.
    write (u, '(a,es10.3,a,i0,a,i0)', iostat=ios) '! core solver: newton_tol = ', &
      solver%newton_tol, ', newton_max_iterations = ', solver%newton_max_iterations, &
      ', max_substeps = ', solver%max_substeps

    write (u, '(a)', iostat=ios) '&interface'
    call put_real(u, 'sigma0_n', mat%sigma0_n)
    call put_real(u, 'sigma0_t', mat%sigma0_t)
    call put_real(u, 'gc', mat%gc)
    call put_real(u, 'eta', mat%eta)
    call put_real(u, 'mu', mat%mu)
    call put_real(u, 'h_n', mat%h_n)
    call put_logical(u, 'prefractured', mat%prefractured)
    write (u, '(a)', iostat=ios) '/'

    write (u, '(a)', iostat=ios) '&microplanes'
    write (u, '(a,i0)', iostat=ios) '  n_planes = ', n
    call put_reals(u, 'gamma_hat', mat%gamma_hat(1:n))
    call put_reals(u, 'theta0_deg', mat%theta0(1:n) * rad_to_deg)
    call put_reals(u, 'thetaf_deg', mat%thetaf(1:n) * rad_to_deg)
    call put_reals(u, 'zeta0', mat%zeta0(1:n))
    select type (old)
    type is (interlock_state_3d_t)
      call put_reals(u, 'phi_deg', mat%phi(1:n) * rad_to_deg)
    end select
    write (u, '(a)', iostat=ios) '/'

    write (u, '(a)', iostat=ios) '&effects'
    call put_logical(u, 'damage', mat%effect(effect_damage))
    call put_logical(u, 'friction', mat%effect(effect_friction))
    call put_logical(u, 'interlocking', mat%effect(effect_interlocking))
    call put_logical(u, 'finite_depth', mat%effect(effect_finite_depth))
    call put_logical(u, 'wear', mat%effect(effect_wear))
    write (u, '(a)', iostat=ios) '/'

    write (u, '(a)', iostat=ios) '&solver'
    write (u, '(a)', iostat=ios) "  scheme = '" // scheme_name(solver%scheme) // "'"
    call put_real(u, 'substep_tol', solver%substep_tol)
    write (u, '(a)', iostat=ios) '  max_cuts = 0   ! replay the one update as it is: no step cutting'
    write (u, '(a)', iostat=ios) '/'

    write (u, '(a)', iostat=ios) '&initial_state'
    call put_reals(u, 'damage', old%damage(1:n))
    call put_reals(u, 'beta', old%beta(1:n))
    call put_reals(u, 'frictional_slip', old%sf(1:n))
    call put_reals(u, 'zeta', old%zeta(1:n))
    call put_reals(u, 'theta', old%theta(1:n))
    call put_reals(u, 'friction_traction', old%tauf(1:n))
    select type (old)
    type is (interlock_state_3d_t)
      call put_reals(u, 'sf_strike', old%sf_strike(1:n))
      call put_reals(u, 'tauf_strike', old%tauf_strike(1:n))
      call put_reals(u, 'separation', [old%s, old%s_t2])
      call put_reals(u, 'traction', [old%sigma, old%sigma_t2])
    class default
      call put_reals(u, 'separation', old%s)
      call put_reals(u, 'traction', old%sigma)
    end select
    write (u, '(a)', iostat=ios) '/'

    write (u, '(a)', iostat=ios) '&loading'
    write (u, '(a)', iostat=ios) "  normal_control = 'separation'"
    write (u, '(a)', iostat=ios) "  tangential_control = 'separation'"
    write (u, '(a)', iostat=ios) '  times = 0.0, 1.0'
    call put_reals(u, 'normal', [old%s(1), s_new(1)])
    call put_reals(u, 'tangential', [old%s(2), s_new(2)])
    select type (old)
    type is (interlock_state_3d_t)
      write (u, '(a)', iostat=ios) "  t2_control = 'separation'"
      call put_reals(u, 't2', [old%s_t2, s_new(min(3, size(s_new)))])
    end select
    write (u, '(a)', iostat=ios) '  steps = 1'
    write (u, '(a)', iostat=ios) '  cycles = 1'
    write (u, '(a)', iostat=ios) '/'
    close (u, iostat=k)
    if (ios /= 0) return
    if (k /= 0) then
      ios = k
      return
    end if

    rc = c_rename(to_c(tmp), to_c(path))
    if (rc /= 0_c_int) ios = -1

  contains

    subroutine put_real(unit, name, x)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: x
      character(len=32) :: buf
      if (ios /= 0) return
      call format_value(x, buf)
      write (unit, '(a)', iostat=ios) '  ' // name // ' = ' // trim(buf)
    end subroutine put_real

    subroutine put_reals(unit, name, x)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: name
      real(dp), intent(in) :: x(:)
      character(len=32) :: buf
      character(len=:), allocatable :: line
      integer :: i
      if (ios /= 0) return
      line = '  ' // name // ' ='
      do i = 1, size(x)
        call format_value(x(i), buf)
        line = line // ' ' // trim(buf)
        if (i < size(x)) line = line // ','
      end do
      write (unit, '(a)', iostat=ios) line
    end subroutine put_reals

    subroutine put_logical(unit, name, flag)
      integer, intent(in) :: unit
      character(len=*), intent(in) :: name
      logical, intent(in) :: flag
      if (ios /= 0) return
      write (unit, '(a)', iostat=ios) '  ' // name // ' = ' // merge('.true. ', '.false.', flag)
    end subroutine put_logical

  end subroutine interlock_write_replay_deck

  !> A real as the deck writes it: full precision, "+infinity" parameters as 1e30 (the deck's
  !> convention for "effect off").
  pure subroutine format_value(x, buf)
    real(dp), intent(in) :: x
    character(len=*), intent(out) :: buf
    if (is_infinite_value(x)) then
      buf = '1.0e30'
    else
      write (buf, rfmt) x
      buf = adjustl(buf)
    end if
  end subroutine format_value

  pure function to_c(name) result(cname)
    character(len=*), intent(in) :: name
    character(kind=c_char, len=len_trim(name) + 1) :: cname
    cname = trim(name) // c_null_char
  end function to_c

end module interlock_replay
