!> The three-dimensional update against the independent implementation of SPEC section 9
!> (tests/update/reference3d): 40 single steps per file from old states of a random 3D walk, every
!> scheme, the `paper` and the `azimuthal` (N_a = 3) RIAs, granite (wear) and Table 1 (finite
!> depth, no wear). The traction and the new state must agree to round-off (both compute the
!> same scheme; the reference solves the wear equation to full precision by bracketing); the
!> tangent, exact here, against the reference's central differences (relative step 1e-7, so
!> about 1e-7 accurate away from kinks; a step whose differences straddle a kink is reported,
!> and the library's tangent must there equal one of its own one-sided differences; the rest
!> must agree to 1e-5 of the largest entry).
program test_reference3d_steps
  use interlock
  use interlock_assert, only: assert_true, run_case, suite_summary
  implicit none
  integer :: code

  call run_case('granite paper explicit', granite_paper_explicit)
  call run_case('granite paper implicit', granite_paper_implicit)
  call run_case('granite paper trapezoidal', granite_paper_trapezoidal)
  call run_case('granite azimuthal 3 explicit', granite_az3_explicit)
  call run_case('granite azimuthal 3 implicit', granite_az3_implicit)
  call run_case('granite azimuthal 3 trapezoidal', granite_az3_trapezoidal)
  call run_case('table 1 paper explicit', table1_explicit)
  call run_case('table 1 paper implicit', table1_implicit)
  call run_case('table 1 paper trapezoidal', table1_trapezoidal)
  code = suite_summary('core_reference3d_steps')
  if (code /= 0) error stop 1

contains

  subroutine granite_paper_explicit()
    call check_file('granite_paper', 1, scheme_explicit)
  end subroutine granite_paper_explicit
  subroutine granite_paper_implicit()
    call check_file('granite_paper', 1, scheme_implicit)
  end subroutine granite_paper_implicit
  subroutine granite_paper_trapezoidal()
    call check_file('granite_paper', 1, scheme_trapezoidal)
  end subroutine granite_paper_trapezoidal
  subroutine granite_az3_explicit()
    call check_file('granite_az3', 3, scheme_explicit)
  end subroutine granite_az3_explicit
  subroutine granite_az3_implicit()
    call check_file('granite_az3', 3, scheme_implicit)
  end subroutine granite_az3_implicit
  subroutine granite_az3_trapezoidal()
    call check_file('granite_az3', 3, scheme_trapezoidal)
  end subroutine granite_az3_trapezoidal
  subroutine table1_explicit()
    call check_file('table1_paper', 1, scheme_explicit)
  end subroutine table1_explicit
  subroutine table1_implicit()
    call check_file('table1_paper', 1, scheme_implicit)
  end subroutine table1_implicit
  subroutine table1_trapezoidal()
    call check_file('table1_paper', 1, scheme_trapezoidal)
  end subroutine table1_trapezoidal

  !> The material of a reference file (tests/update/reference3d/interlock3d_ref.py: granite, table1).
  subroutine material_of(name, n_azimuths, mat)
    character(len=*), intent(in) :: name
    integer, intent(in) :: n_azimuths
    type(interlock_material_t), intent(out) :: mat
    integer :: stat
    character(len=256) :: message
    if (name(1:7) == 'granite') then
      mat%sigma0_n = 0.025_dp
      mat%sigma0_t = 0.025_dp
      mat%gc = 0.0005_dp
      mat%eta = 0.99_dp
      mat%mu = tan(34.6_dp * deg_to_rad)
      mat%h_n = 4.0_dp
      call interlock_azimuthal_ria(mat, n_azimuths, 30.0_dp * deg_to_rad, 9.0_dp * deg_to_rad, &
                                   6.666_dp)
    else
      mat%sigma0_n = 3.0_dp
      mat%sigma0_t = 3.0_dp
      mat%gc = 0.3_dp
      mat%eta = 0.9_dp
      mat%mu = 0.5_dp
      mat%h_n = 0.5_dp
      call interlock_azimuthal_ria(mat, n_azimuths, 25.0_dp * deg_to_rad, 25.0_dp * deg_to_rad, &
                                   huge(1.0_dp))
    end if
    call interlock_material_prepare(mat, stat, message)
    call assert_true(stat == status_ok, 'material: ' // trim(message))
  end subroutine material_of

  subroutine check_file(name, n_azimuths, scheme)
    character(len=*), intent(in) :: name
    integer, intent(in) :: n_azimuths, scheme
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(interlock_state_3d_t) :: old, new
    type(interlock_info_t) :: info
    real(dp), allocatable :: row(:)
    real(dp) :: s_old(3), s(3), sigma(3), tangent(3, 3), sig_ref(3), k_ref(3, 3), new_ref(8), &
                err_sig, err_state, err_k, k_scale, sig_scale, state_scale(8), worst_sig, &
                worst_state, worst_k
    integer :: unit, ios, n, k, ncol, kinks, n_rows
    character(len=64) :: schemes(3) = [character(len=64) :: 'explicit', 'implicit', 'trapezoidal']
    character(len=256) :: path

    call material_of(name, n_azimuths, mat)
    solver%scheme = scheme
    n = mat%n_planes
    ncol = 1 + 3 + 3 + 8 * n + 3 + 8 * n + 9
    allocate (row(ncol))
    path = 'data/reference3d/steps_' // name // '_' // trim(schemes(scheme)) // '.csv'
    open (newunit=unit, file=trim(path), status='old', action='read', iostat=ios)
    call assert_true(ios == 0, 'open ' // trim(path))
    if (ios /= 0) return
    read (unit, *)
    read (unit, *)
    worst_sig = 0.0_dp
    worst_state = 0.0_dp
    worst_k = 0.0_dp
    kinks = 0
    n_rows = 0
    do
      read (unit, *, iostat=ios) row
      if (ios /= 0) exit
      n_rows = n_rows + 1
      s_old = row(2:4)
      s = row(5:7)
      call interlock_state_3d_init(mat, old)
      do k = 1, n
        call unpack_plane(row(8 + 8 * (k - 1):7 + 8 * k), k, old)
      end do
      old%s = s_old(1:2)
      old%s_t2 = s_old(3)
      call interlock_update_3d(mat, solver, s, old, new, sigma, tangent, info)
      call assert_true(info%status == status_ok, 'update: ' // trim(info%message))
      sig_ref = row(8 + 8 * n:10 + 8 * n)
      sig_scale = max(maxval(abs(sig_ref)), 1.0e-3_dp * mat%sigma0_n)
      err_sig = maxval(abs(sigma - sig_ref)) / sig_scale
      worst_sig = max(worst_sig, err_sig)
      err_state = 0.0_dp
      do k = 1, n
        new_ref = row(11 + 8 * n + 8 * (k - 1):10 + 8 * n + 8 * k)
        state_scale = [1.0_dp, max(1.0_dp, abs(new_ref(2))), max(1.0e-3_dp, abs(new_ref(3)), &
                       abs(new_ref(4))), max(1.0e-3_dp, abs(new_ref(3)), abs(new_ref(4))), &
                       max(1.0e-3_dp, abs(new_ref(5))), 1.0_dp, sig_scale, sig_scale]
        err_state = max(err_state, maxval(abs(plane_values(new, k) - new_ref) / state_scale))
      end do
      worst_state = max(worst_state, err_state)
      k_ref = transpose(reshape(row(ncol - 8:ncol), [3, 3]))
      k_scale = max(maxval(abs(k_ref)), tiny(1.0_dp))
      err_k = maxval(abs(tangent - k_ref)) / k_scale
      if (err_k > 1.0e-5_dp) then
        ! Straddling a kink, the library's tangent is one of its one-sided derivatives.
        kinks = kinks + 1
        write (*, '(a,i0,a,es9.2,a,es9.2)') '  point ', nint(row(1)), &
          ': tangent differs by ', err_k, '; from its one-sided differences by ', &
          one_sided_error(mat, solver, s, old, tangent)
        call assert_true(one_sided_error(mat, solver, s, old, tangent) <= 1.0e-5_dp, &
                         'a one-sided derivative at a kink')
      else
        worst_k = max(worst_k, err_k)
      end if
      if (err_sig > 1.0e-10_dp .or. err_state > 1.0e-10_dp) then
        write (*, '(a,i0,a,es9.2,a,es9.2)') '  point ', nint(row(1)), ': traction ', err_sig, &
          ', state ', err_state
        write (*, '(a,3es24.16)') '    sigma ', sigma
        write (*, '(a,3es24.16)') '    ref   ', sig_ref
      end if
    end do
    close (unit)
    write (*, '(a,3es10.2,a,i0)') '  largest differences: traction, state, tangent ', worst_sig, &
      worst_state, worst_k, '; tangents off by more than 1e-5: ', kinks
    call assert_true(worst_sig <= 1.0e-10_dp, 'traction to round-off')
    call assert_true(worst_state <= 1.0e-10_dp, 'state to round-off')
    call assert_true(kinks <= max(2, n_rows / 20), 'at most 5 % of the steps straddle a kink')
  end subroutine check_file

  !> The smallest relative distance of `tangent` to the update's forward or backward
  !> differences, column by column (relative step 1e-9).
  function one_sided_error(mat, solver, s, old, tangent) result(err)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(3), tangent(3, 3)
    type(interlock_state_3d_t), intent(in) :: old
    real(dp) :: err
    type(interlock_state_3d_t) :: new
    type(interlock_info_t) :: info
    real(dp) :: sigma0(3), sigma(3), t(3, 3), sp(3), h, fwd(3), bwd(3), scale
    integer :: j
    call interlock_update_3d(mat, solver, s, old, new, sigma0, t, info)
    scale = max(maxval(abs(tangent)), tiny(1.0_dp))
    err = 0.0_dp
    do j = 1, 3
      h = 1.0e-9_dp * max(maxval(abs(s)), 1.0e-3_dp)
      sp = s
      sp(j) = s(j) + h
      call interlock_update_3d(mat, solver, sp, old, new, sigma, t, info)
      fwd = (sigma - sigma0) / h
      sp(j) = s(j) - h
      call interlock_update_3d(mat, solver, sp, old, new, sigma, t, info)
      bwd = (sigma0 - sigma) / h
      err = max(err, min(maxval(abs(fwd - tangent(:, j))), maxval(abs(bwd - tangent(:, j)))) / &
                     scale)
    end do
  end function one_sided_error

  subroutine unpack_plane(v, k, state)
    real(dp), intent(in) :: v(8)
    integer, intent(in) :: k
    type(interlock_state_3d_t), intent(inout) :: state
    state%damage(k) = v(1)
    state%beta(k) = v(2)
    state%sf(k) = v(3)
    state%sf_strike(k) = v(4)
    state%zeta(k) = v(5)
    state%theta(k) = v(6)
    state%tauf(k) = v(7)
    state%tauf_strike(k) = v(8)
  end subroutine unpack_plane

  function plane_values(state, k) result(v)
    type(interlock_state_3d_t), intent(in) :: state
    integer, intent(in) :: k
    real(dp) :: v(8)
    v = [state%damage(k), state%beta(k), state%sf(k), state%sf_strike(k), state%zeta(k), &
         state%theta(k), state%tauf(k), state%tauf_strike(k)]
  end function plane_values

end program test_reference3d_steps
