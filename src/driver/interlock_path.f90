!> The loading path of a point history: points (times(i), values(:, i)) joined by segments of
!> uniform steps, a segment straight or, in 3D, a circular arc in the (T1, T2) plane (arc_t);
!> the path's point at the end of each step (path_point); and the named paths of a deck
!> (path_points: 'straight', 'square', 'circle' after a preload of the normal component,
!> docs/deck-format.md). The driver walks the path; the deck builds it.
module interlock_path
  use interlock, only: dp, pi, deg_to_rad, same_value
  implicit none
  private
  public :: arc_t, path_point, path_points

  !> A segment of the loading path that is a circular arc in the (T1, T2) plane (3D only): at
  !> the fraction f of the segment the in-plane components are center + radius (cos a, sin a),
  !> a = angle0 + sweep f; the normal component goes linearly. sweep = 0: a straight segment.
  type :: arc_t
    real(dp) :: sweep = 0.0_dp          !< angle swept [rad], > 0 counter-clockwise
    real(dp) :: angle0 = 0.0_dp         !< angle of the start point about the center [rad]
    real(dp) :: radius = 0.0_dp         !< [mm]
    real(dp) :: center(2) = 0.0_dp      !< (s_T1, s_T2) [mm]
  end type arc_t

contains

  !> The path's values and time at the end of step j of segment iseg, in n uniform steps (the
  !> segment's end point exactly at j = n). The same expression for every run, so that the
  !> step 2j of 2n steps lands on the same numbers as the step j of n. An arc segment (arcs,
  !> 3D) takes its in-plane components on the arc at every step, its end included.
  pure subroutine path_point(times, values, iseg, j, n, target, time, arcs)
    real(dp), intent(in) :: times(:), values(:, :)
    integer, intent(in) :: iseg, j, n
    real(dp), intent(out) :: target(:), time
    type(arc_t), intent(in), optional :: arcs(:)
    real(dp) :: f
    if (j == n) then
      target = values(:, iseg + 1)
      time = times(iseg + 1)
    else
      f = real(j, dp) / real(n, dp)
      target = values(:, iseg) + (values(:, iseg + 1) - values(:, iseg)) * f
      time = times(iseg) + (times(iseg + 1) - times(iseg)) * f
    end if
    if (present(arcs) .and. size(target) == 3) then
      if (abs(arcs(iseg)%sweep) > 0.0_dp) target(2:3) = arc_point(arcs(iseg), j, n)
    end if
  end subroutine path_point

  !> The point (s_T1, s_T2) of an arc after j of its n steps: angle0 + sweep j / n.
  pure function arc_point(arc, j, n) result(p)
    type(arc_t), intent(in) :: arc
    integer, intent(in) :: j, n
    real(dp) :: p(2), a
    a = arc%angle0 + arc%sweep * real(j, dp) / real(n, dp)
    p = arc%center + arc%radius * [cos(a), sin(a)]
  end function arc_point

  !> The points of a named path in the (T1, T2) plane (docs/deck-format.md): the origin at time
  !> 0; the normal component from 0 to `normal` at zero slip by time 1 (the preload, SPEC D8);
  !> then the path at that normal value, turned by angle_deg from t1, with time = 1 + the slip
  !> length. straight: one leg of length `size_mm`; square: 0 -> (a, 0) -> (a, a) -> (0, a) -> 0
  !> with a = `size_mm`; circle: out to (r, 0), r = `size_mm`, then `turns` counter-clockwise
  !> turns about the origin (one arc, whose end point is the arc's own, arc_point). arcs: one per
  !> segment (sweep = 0 for the straight ones).
  pure subroutine path_points(path, angle_deg, size_mm, turns, normal, times, values, arcs)
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: angle_deg, size_mm, turns, normal
    real(dp), allocatable, intent(out) :: times(:), values(:, :)
    type(arc_t), allocatable, intent(out) :: arcs(:)
    real(dp), allocatable :: local(:, :)
    real(dp) :: c, s, angle
    integer :: m, k
    angle = angle_deg * deg_to_rad
    c = 1.0_dp
    s = 0.0_dp
    ! A direction along t1 to the bit (cos and sin of 0 are exact; of pi/2 they are not).
    if (.not. same_value(angle_deg, 0.0_dp)) then
      c = cos(angle)
      s = sin(angle)
    end if
    select case (trim(path))
    case ('straight')
      local = reshape([0.0_dp, 0.0_dp, size_mm, 0.0_dp], [2, 2])
    case ('square')
      local = reshape([0.0_dp, 0.0_dp, size_mm, 0.0_dp, size_mm, size_mm, 0.0_dp, size_mm, &
                       0.0_dp, 0.0_dp], [2, 5])
    case default
      local = reshape([0.0_dp, 0.0_dp, size_mm, 0.0_dp, size_mm, 0.0_dp], [2, 3])
    end select
    m = size(local, 2) + 1
    allocate (times(m), values(3, m), arcs(m - 1))
    values(:, 1) = 0.0_dp
    times(1) = 0.0_dp
    do k = 2, m
      values(1, k) = normal
      values(2, k) = c * local(1, k - 1) - s * local(2, k - 1)
      values(3, k) = s * local(1, k - 1) + c * local(2, k - 1)
    end do
    times(2) = 1.0_dp
    do k = 3, m
      times(k) = times(k - 1) + hypot(values(2, k) - values(2, k - 1), values(3, k) - values(3, k - 1))
    end do
    if (trim(path) == 'circle') then
      arcs(3)%sweep = 2.0_dp * pi * turns
      arcs(3)%angle0 = angle
      arcs(3)%radius = size_mm
      arcs(3)%center = 0.0_dp
      values(2:3, 4) = arc_point(arcs(3), 1, 1)
      times(4) = times(3) + abs(arcs(3)%sweep) * size_mm
    end if
  end subroutine path_points

end module interlock_path
