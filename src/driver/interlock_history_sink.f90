!> The rows of a point history and where they go as they are computed: history_row_t (the
!> state at the end of a load step), history_sink_t (the sink the run loop hands each row to:
!> kept in memory by history_t, or written as it comes by interlock_history_output), the
!> history's status and its record of the one-step segments that slid or wore.
module interlock_history_sink
  use interlock, only: dp, interlock_state_3d_t, format_real, format_integer, max_planes
  implicit none
  private
  public :: history_row_t, history_sink_t, history_t, begin_history, note_sliding_jump

  !> The one-step segments that slid or wore named in history_sink_t%sliding_jumps (the others
  !> are counted).
  integer, parameter :: listed_jumps = 3

  !> One row of a history: the state at the end of a load step. separation and traction hold
  !> (N, T) in 2D, (N, T1, T2) in 3D (the sink's n_components).
  type :: history_row_t
    real(dp) :: time = 0.0_dp
    real(dp) :: separation(3) = 0.0_dp, traction(3) = 0.0_dp
    real(dp), dimension(max_planes) :: damage = 0.0_dp, beta = 0.0_dp, frictional_slip = 0.0_dp, &
                                       zeta = 0.0_dp, theta = 0.0_dp, friction_traction = 0.0_dp
    !> the strike components of the frictional slip and the friction traction (3D)
    real(dp), dimension(max_planes) :: sf_strike = 0.0_dp, tauf_strike = 0.0_dp
    real(dp) :: work = 0.0_dp, stored = 0.0_dp, diss_damage = 0.0_dp, diss_friction = 0.0_dp
    integer :: iterations = 0, substeps = 0
  end type history_row_t

  !> Where the rows of a history go as they are computed (run_history, put): kept in memory
  !> (history_t) or written to a file as they come (interlock_history_output), so that a long
  !> history never has to be held whole.
  type, abstract :: history_sink_t
    integer :: n_rows = 0                         !< rows computed so far
    integer :: n_planes = 0
    integer :: n_components = 2                   !< 2 (N, T) or 3 (N, T1, T2)
    character(len=:), allocatable :: status       !< 'completed' or why the case stopped
    !> .true.: separation and traction are Richardson-extrapolated, 2 u(2n) - u(n); the state
    !> variables and energies are those of the run with doubled steps, iterations and substeps
    !> the sums of both runs (run_history_extrapolated)
    logical :: extrapolated = .false.
    !> The one-step segments (load jumps) in which a plane slid or wore, as "t = a to b, ...",
    !> '' if none: their end state is the scheme's, not the law's (one step of a scheme of
    !> order one or two over the whole jump), and more steps elsewhere do not change it. The
    !> first listed_jumps of them, then their count ("... and 997 more: 1000 segments"): a deck
    !> with one point per step has thousands.
    character(len=:), allocatable :: sliding_jumps
    !> how many one-step segments slid or wore; the text of the first listed_jumps of them
    integer :: n_sliding_jumps = 0
    character(len=:), allocatable :: listed_jumps_text
  contains
    procedure(put_row), deferred :: put
  end type history_sink_t

  abstract interface
    !> Take row sink%n_rows (already counted). stat /= 0: the row could not be kept (the history
    !> stops; the sink knows why).
    subroutine put_row(sink, row, stat)
      import :: history_sink_t, history_row_t
      class(history_sink_t), intent(inout) :: sink
      type(history_row_t), intent(in) :: row
      integer, intent(out) :: stat
    end subroutine put_row
  end interface

  !> A whole history in memory: one row per load step (row 1 = after the first step).
  type, extends(history_sink_t) :: history_t
    real(dp), allocatable :: time(:)
    real(dp), allocatable :: separation(:, :), traction(:, :)         ! (n_components, n)
    real(dp), allocatable :: damage(:, :), beta(:, :), frictional_slip(:, :), zeta(:, :), &
                             theta(:, :), friction_traction(:, :), &
                             sf_strike(:, :), tauf_strike(:, :)       ! (n_planes, n)
    real(dp), allocatable :: work(:), stored(:), diss_damage(:), diss_friction(:)
    integer, allocatable :: iterations(:), substeps(:)
  contains
    procedure :: put => history_put
    procedure :: reserve => history_reserve
    procedure :: clear => history_clear
  end type history_t

contains

  !> A history about to be computed: no rows, status 'completed' until a step fails.
  subroutine begin_history(hist, np, n_components, extrapolated)
    class(history_sink_t), intent(inout) :: hist
    integer, intent(in) :: np, n_components
    logical, intent(in) :: extrapolated
    hist%n_planes = np
    hist%n_components = n_components
    hist%n_rows = 0
    hist%extrapolated = extrapolated
    hist%status = 'completed'
    hist%sliding_jumps = ''
    hist%listed_jumps_text = ''
    hist%n_sliding_jumps = 0
  end subroutine begin_history

  !> A one-step segment iseg from `old` to `new`: noted in hist%sliding_jumps where a plane slid
  !> (its frictional slip changed, along the dip or the strike) or wore (its inclination changed).
  subroutine note_sliding_jump(hist, np, old, new, times, iseg)
    class(history_sink_t), intent(inout) :: hist
    integer, intent(in) :: np, iseg
    type(interlock_state_3d_t), intent(in) :: old, new
    real(dp), intent(in) :: times(:)
    if (.not. (any(abs(new%sf(1:np) - old%sf(1:np)) > 0.0_dp) .or. &
               any(abs(new%sf_strike(1:np) - old%sf_strike(1:np)) > 0.0_dp) .or. &
               any(abs(new%theta(1:np) - old%theta(1:np)) > 0.0_dp))) return
    hist%n_sliding_jumps = hist%n_sliding_jumps + 1
    if (hist%n_sliding_jumps <= listed_jumps) then
      if (hist%n_sliding_jumps > 1) hist%listed_jumps_text = hist%listed_jumps_text // ', '
      hist%listed_jumps_text = hist%listed_jumps_text // 't = ' // format_real(times(iseg)) // &
                               ' to ' // format_real(times(iseg + 1))
      hist%sliding_jumps = hist%listed_jumps_text
    else
      hist%sliding_jumps = hist%listed_jumps_text // ' and ' // &
        format_integer(hist%n_sliding_jumps - listed_jumps) // ' more: ' // &
        format_integer(hist%n_sliding_jumps) // ' segments'
    end if
  end subroutine note_sliding_jump

  !> history_t: keep the row (room grows by doubling).
  subroutine history_put(sink, row, stat)
    class(history_t), intent(inout) :: sink
    type(history_row_t), intent(in) :: row
    integer, intent(out) :: stat
    integer :: n, np
    stat = 0
    n = sink%n_rows
    np = sink%n_planes
    if (.not. allocated(sink%time)) call sink%reserve(max(n, 16))
    if (n > size(sink%time)) call sink%reserve(2 * size(sink%time))
    sink%time(n) = row%time
    sink%separation(:, n) = row%separation(1:sink%n_components)
    sink%traction(:, n) = row%traction(1:sink%n_components)
    sink%damage(:, n) = row%damage(1:np)
    sink%beta(:, n) = row%beta(1:np)
    sink%frictional_slip(:, n) = row%frictional_slip(1:np)
    sink%zeta(:, n) = row%zeta(1:np)
    sink%theta(:, n) = row%theta(1:np)
    sink%friction_traction(:, n) = row%friction_traction(1:np)
    sink%sf_strike(:, n) = row%sf_strike(1:np)
    sink%tauf_strike(:, n) = row%tauf_strike(1:np)
    sink%work(n) = row%work
    sink%stored(n) = row%stored
    sink%diss_damage(n) = row%diss_damage
    sink%diss_friction(n) = row%diss_friction
    sink%iterations(n) = row%iterations
    sink%substeps(n) = row%substeps
  end subroutine history_put

  !> Room for `capacity` rows, keeping the rows held.
  subroutine history_reserve(sink, capacity)
    class(history_t), intent(inout) :: sink
    integer, intent(in) :: capacity
    integer :: np
    np = sink%n_planes
    call grow_real(sink%time)
    call grow_real(sink%work)
    call grow_real(sink%stored)
    call grow_real(sink%diss_damage)
    call grow_real(sink%diss_friction)
    call grow_int(sink%iterations)
    call grow_int(sink%substeps)
    call grow_real_2d(sink%separation, sink%n_components)
    call grow_real_2d(sink%traction, sink%n_components)
    call grow_real_2d(sink%damage, np)
    call grow_real_2d(sink%beta, np)
    call grow_real_2d(sink%frictional_slip, np)
    call grow_real_2d(sink%zeta, np)
    call grow_real_2d(sink%theta, np)
    call grow_real_2d(sink%friction_traction, np)
    call grow_real_2d(sink%sf_strike, np)
    call grow_real_2d(sink%tauf_strike, np)

  contains

    subroutine grow_real(x)
      real(dp), allocatable, intent(inout) :: x(:)
      real(dp), allocatable :: y(:)
      integer :: m
      allocate (y(capacity))
      m = 0
      if (allocated(x)) m = min(size(x), capacity)
      if (m > 0) y(1:m) = x(1:m)
      call move_alloc(y, x)
    end subroutine grow_real

    subroutine grow_int(x)
      integer, allocatable, intent(inout) :: x(:)
      integer, allocatable :: y(:)
      integer :: m
      allocate (y(capacity))
      m = 0
      if (allocated(x)) m = min(size(x), capacity)
      if (m > 0) y(1:m) = x(1:m)
      call move_alloc(y, x)
    end subroutine grow_int

    subroutine grow_real_2d(x, width)
      real(dp), allocatable, intent(inout) :: x(:, :)
      integer, intent(in) :: width
      real(dp), allocatable :: y(:, :)
      integer :: m
      allocate (y(width, capacity))
      m = 0
      if (allocated(x)) m = min(size(x, 2), capacity)
      if (m > 0) y(:, 1:m) = x(:, 1:m)
      call move_alloc(y, x)
    end subroutine grow_real_2d

  end subroutine history_reserve

  !> Forget the rows held (the room stays): the next row is row 1 again.
  subroutine history_clear(sink)
    class(history_t), intent(inout) :: sink
    sink%n_rows = 0
  end subroutine history_clear

end module interlock_history_sink
