!> The interface alone under traction control, solved by Newton's method with different
!> tangents: which symmetric tangent serves a host that symmetrizes (CalculiX) best?
!>
!> Each scene loads one point from the virgin (or pre-fractured) state in steps of prescribed
!> traction, or of prescribed far-end displacement through elastic springs in series (the
!> surrounding material of a host), and solves every step for the separation s by Newton's
!> method with the matrix K of one option:
!>   exact      the law's algorithmic tangent D (unsymmetric)
!>   sym        (D + D^T) / 2, what ccx keeps of any DDSDDE (umat_abaqus.f)
!>   nocouple   diag(D) where the normal traction is compressive, else sym (an adapter
!>              that drops the coupling in compression)
!>   clipped    sym with the off-diagonal clipped to |c| <= sqrt(D11 D22) (diagonal >= 0)
!>   library    the library's symmetric tangent (PROPS 20 tangent = 2,
!>              interlock_symmetric_tangent)
!> and prints iterations per step, the failures and the residual sequence of the hardest step.
!> Converged: |r| <= 1e-10 (sigma0 + |t*|); at most 100 iterations; a step that does not
!> converge is counted as failed and the scene goes on from the last converged state (so every
!> option sees every step).
program tangent_newton
  use interlock
  use interlock_host_tangent, only: interlock_symmetric_tangent
  implicit none

  integer, parameter :: n_options = 6
  character(len=8), parameter :: option_names(n_options) = [character(len=8) :: 'exact', &
      'sym', 'nocouple', 'clipped', 'similar', 'library']
  integer, parameter :: max_iterations = 100

  ! Table 1 (theta_0 = 25 deg, H_N = 0.5 mm), intact; Table 5 clay-bar, pre-fractured.
  real(dp), parameter :: props_table1(11) = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp, 0.5_dp, 0.5_dp, &
      25.0_dp, 25.0_dp, 1.0e30_dp, 0.0_dp, 2.0_dp]
  real(dp), parameter :: props_table1_broken(11) = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp, 0.5_dp, &
      0.5_dp, 25.0_dp, 25.0_dp, 1.0e30_dp, 1.0_dp, 2.0_dp]
  real(dp), parameter :: props_clay(11) = [0.5_dp, 0.5_dp, 0.05_dp, 0.995_dp, 0.6_dp, 0.5_dp, &
      1.75_dp, 0.0_dp, 33.3_dp, 1.0_dp, 2.0_dp]

  write (*, '(a)') 'scene                                     tangent   steps  failed  iterations' // &
    ' (median, max, total)  residuals of the hardest step'
  ! (1) Table 1: sigma_N = -0.2 MPa, tau 0 -> 2.9 MPa (the peak is about 3.1) in 58 steps.
  call traction_scene('Table 1, traction control', props_table1, -0.2_dp, 2.9_dp, 58)
  call traction_scene('Table 1 D = 1, traction control', props_table1_broken, -0.2_dp, 0.3_dp, 60)
  ! (2) Clay-bar, fully damaged: sigma_N = -1 MPa, tau 0 -> 0.7 MPa: past the friction limit
  !     (mu p = 0.6) into sliding on the +1.75 deg plane, which hardens slowly (finite depth).
  call traction_scene('clay-bar D = 1, traction control', props_clay, -1.0_dp, 0.7_dp, 70)
  ! (3) The same point behind springs (the surrounding material, k = 20 MPa/mm in both
  !     directions): the far end pushed by -0.1 mm, then slid by 2 mm in 100 steps.
  call spring_scene('clay-bar D = 1, springs k = 20 MPa/mm', props_clay, 20.0_dp, -0.1_dp, &
                    2.0_dp, 100)
  call spring_scene('Table 1, springs k = 200 MPa/mm', props_table1, 200.0_dp, -0.01_dp, &
                    1.0_dp, 100)

contains

  !> The matrix of option `opt` for the law's tangent d at traction sigma.
  pure function option_matrix(opt, d, sigma) result(k)
    integer, intent(in) :: opt
    real(dp), intent(in) :: d(2, 2), sigma(2)
    real(dp) :: k(2, 2), c
    select case (opt)
    case (1)
      k = d
    case (2)
      k = 0.5_dp * (d + transpose(d))
    case (3)
      k = 0.5_dp * (d + transpose(d))
      if (sigma(1) < 0.0_dp) then
        k(1, 2) = 0.0_dp
        k(2, 1) = 0.0_dp
      end if
    case (4)
      k = 0.5_dp * (d + transpose(d))
      c = sqrt(max(d(1, 1), 0.0_dp) * max(d(2, 2), 0.0_dp))
      k(1, 2) = max(-c, min(c, k(1, 2)))
      k(2, 1) = k(1, 2)
    case (5)
      k = d
      c = 0.0_dp
      if (d(1, 2) * d(2, 1) > 0.0_dp) c = sign(sqrt(d(1, 2) * d(2, 1)), d(1, 2))
      k(1, 2) = c
      k(2, 1) = c
    case default
      k = d
      call interlock_symmetric_tangent(k)
    end select
  end function option_matrix

  subroutine traction_scene(title, props, sigma_n, tau_end, n_steps)
    character(len=*), intent(in) :: title
    real(dp), intent(in) :: props(:), sigma_n, tau_end
    integer, intent(in) :: n_steps
    integer :: opt, j
    real(dp) :: target(2, 0:n_steps)
    target(1, 0) = sigma_n
    target(2, 0) = 0.0_dp
    do j = 1, n_steps
      target(:, j) = [sigma_n, tau_end * real(j, dp) / real(n_steps, dp)]
    end do
    do opt = 1, n_options
      call run_scene(title, props, opt, target, 0.0_dp, spread(0.0_dp, 1, 1))
    end do
  end subroutine traction_scene

  subroutine spring_scene(title, props, k_spring, u_n, u_t, n_steps)
    character(len=*), intent(in) :: title
    real(dp), intent(in) :: props(:), k_spring, u_n, u_t
    integer, intent(in) :: n_steps
    integer :: opt, j
    real(dp) :: far(2, 0:n_steps)
    far(:, 0) = [u_n, 0.0_dp]
    do j = 1, n_steps
      far(:, j) = [u_n, u_t * real(j, dp) / real(n_steps, dp)]
    end do
    do opt = 1, n_options
      call run_scene(title, props, opt, far, k_spring, spread(0.0_dp, 1, 1))
    end do
  end subroutine spring_scene

  !> Steps 0..n: traction control (k_spring = 0: load(:, j) is the traction) or a far-end
  !> displacement load(:, j) through springs k_spring (residual sigma(s) - k (u - s)).
  subroutine run_scene(title, props, opt, load, k_spring, unused)
    character(len=*), intent(in) :: title
    real(dp), intent(in) :: props(:), load(:, 0:), k_spring, unused(:)
    integer, intent(in) :: opt
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(umat_controls_t) :: controls
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info
    integer :: stat, j, it, n_failed, n_steps, worst_step, count(0:ubound(load, 2))
    real(dp) :: s(2), sigma(2), d(2, 2), k(2, 2), r(2), ds(2), det, scale, res(max_iterations), &
                worst_res(max_iterations)
    integer :: worst_count
    logical :: converged
    character(len=message_len) :: message
    character(len=600) :: line
    associate (unused_1 => unused)
    end associate
    call props_to_material(props, mat, solver, controls, stat, message)
    if (stat /= status_ok) error stop 'tangent_newton: bad props'
    call interlock_state_init(mat, old)
    n_steps = ubound(load, 2)
    n_failed = 0
    worst_count = 0
    worst_step = 0
    count = 0
    s = old%s
    do j = 0, n_steps
      scale = maxval([mat%sigma0_n, mat%sigma0_t]) + norm2(load(:, j)) * merge(k_spring, 1.0_dp, k_spring > 0.0_dp)
      converged = .false.
      s = old%s
      do it = 1, max_iterations
        call interlock_update(mat, solver, s, old, new, sigma, d, info)
        if (info%status /= status_ok) exit
        if (k_spring > 0.0_dp) then
          r = sigma - k_spring * (load(:, j) - s)
        else
          r = sigma - load(:, j)
        end if
        res(it) = norm2(r) / scale
        if (res(it) <= 1.0e-10_dp) then
          converged = .true.
          exit
        end if
        k = option_matrix(opt, d, sigma)
        k(1, 1) = k(1, 1) + k_spring
        k(2, 2) = k(2, 2) + k_spring
        det = k(1, 1) * k(2, 2) - k(1, 2) * k(2, 1)
        if (abs(det) <= 1.0e-14_dp * maxval(abs(k))**2) exit
        ds = [k(2, 2) * r(1) - k(1, 2) * r(2), k(1, 1) * r(2) - k(2, 1) * r(1)] / det
        s = s - ds
        if (.not. all(abs(s) < 1.0e3_dp)) exit
      end do
      if (converged) then
        count(j) = it - 1
        old = new
        if (it > worst_count) then
          worst_count = it
          worst_step = j
          worst_res(1:it) = res(1:it)
        end if
      else
        n_failed = n_failed + 1
        count(j) = -1
      end if
    end do
    write (line, '(a42,a9,i6,i8,i8,i6,i8)') title, option_names(opt), n_steps + 1, n_failed, &
      median_of(pack(count, count >= 0)), maxval(count), sum(pack(count, count >= 0))
    if (worst_count > 0) then
      write (line(len_trim(line) + 1:), '(a,i0,a)') '          step ', worst_step, ':'
      do it = 1, min(worst_count, 12)
        write (line(len_trim(line) + 1:), '(es9.1)') worst_res(it)
      end do
    end if
    write (*, '(a)') trim(line)
  end subroutine run_scene

  pure integer function median_of(v)
    integer, intent(in) :: v(:)
    integer :: w(size(v)), i, j, t
    if (size(v) == 0) then
      median_of = -1
      return
    end if
    w = v
    do i = 2, size(w)
      t = w(i)
      j = i - 1
      do while (j >= 1)
        if (w(j) <= t) exit
        w(j + 1) = w(j)
        j = j - 1
      end do
      w(j + 1) = t
    end do
    median_of = w((size(w) + 1) / 2)
  end function median_of

end program tangent_newton
