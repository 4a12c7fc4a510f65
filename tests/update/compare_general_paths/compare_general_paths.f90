!> The 2D general path before (legacy_general_update: ria_step, plane_step, microplane) and
!> after (interlock_general_update over interlock_general_path) from the same start states.
program compare_general_paths
  use interlock_kinds, only: dp
  use interlock_material
  use interlock_state, only: interlock_state_t, interlock_state_init
  use interlock_status, only: interlock_info_t, status_ok
  use interlock_general_update, only: general_update
  use legacy_general_update, only: legacy_update => general_update
  implicit none
  integer, parameter :: nq = 16
  character(len=12), parameter :: qname(nq) = [character(len=12) :: 'sigma', 'tangent', &
      'damage', 'beta', 'sf', 'zeta', 'theta', 'tauf', 'work', 'stored', 'diss_dmg', &
      'diss_fric', 'max_dD', 'max_dth', 'iters', 'substeps']
  real(dp) :: dmax(nq), vmax(nq)
  character(len=100) :: where(nq), here
  integer :: hist(0:20) = 0
  real(dp) :: hd1, hv1, hd2, hv2, wh1 = 0, wh2 = 0
  character(len=100) :: wh1_at, wh2_at
  integer :: n_hist = 0, n_hist_over = 0
  real(dp) :: worst_rel = 0, worst_single = 0, worst_single_k = 0, worst_sub_k = 0
  integer(8) :: seed
  integer :: n_cases, n_status_diff, n_fail, n_sub, n_fallback, n_sep, n_attempt_diff, n_iter_diff
  integer :: rset, eset, pf, scheme, itol, mode, n_mat, n_sub_diff
  real(dp), parameter :: tols(4) = [0.0_dp, 1.0e-2_dp, 1.0e-4_dp, 1.0e-6_dp]
  type(interlock_material_t) :: mat
  type(interlock_solver_t) :: solver
  character(len=200) :: msg
  integer :: stat

  seed = 12345_8
  dmax = 0; vmax = 0
  n_cases = 0; n_status_diff = 0; n_fail = 0; n_sub = 0; n_fallback = 0; n_sep = 0
  n_attempt_diff = 0; n_iter_diff = 0; n_mat = 0; n_sub_diff = 0
  do rset = 1, 27
    do eset = 0, 31
      do pf = 0, 1
        call make_material(rset, eset, pf == 1, mat)
        call interlock_material_prepare(mat, stat, msg)
        if (stat /= status_ok) cycle
        n_mat = n_mat + 1
        do scheme = 1, n_schemes
          do itol = 1, size(tols)
            do mode = 1, 3
              if (mode == 2 .and. itol > 1) cycle
              if (mode == 3 .and. itol < 3) cycle
              solver%scheme = scheme
              solver%substep_tol = tols(itol)
              solver%max_substeps = merge(12, 100000, mode == 3)
              call run_history(mat, solver, mode == 2)
              solver%max_substeps = 100000
            end do
          end do
        end do
      end do
    end do
  end do
  write (*, '(a,i0,a,i0,a)') 'materials ', n_mat, ', updates compared ', n_cases, ''
  write (*, '(a,i0,a,i0,a,i0,a,i0)') 'failed (both) ', n_fail, ', substepped ', n_sub, &
    ', one-step fallbacks ', n_fallback, ', separated (s_N >= H_N) ', n_sep
  write (*, '(a,i0,a,i0,a,i0,a,i0)') 'status differs ', n_status_diff, ', attempts differ ', &
    n_attempt_diff, ', newton iterations differ ', n_iter_diff, ', substeps differ ', n_sub_diff
  write (*, '(a)') 'per-update tangent relative difference: count with 10^-(b+1) < r <= 10^-b (b=0 exact)'
  do stat = 0, 20
    if (hist(stat) > 0) write (*, '(i3,i9)') stat, hist(stat)
  end do
  write (*, '(a,es10.3)') 'largest per-update tangent relative difference of one-step updates ', worst_single
  write (*, '(a,es10.3,1x,a)') 'tangent, per history, relative to its largest entry: one-step updates ', wh1, trim(wh1_at)
  write (*, '(a,es10.3,1x,a)') 'tangent, per history, relative to its largest entry: substepped updates ', wh2, trim(wh2_at)
  write (*, '(a,i0,a,i0)') 'histories ', n_hist, ', with substepped tangent difference > 1e-14 of its largest entry ', n_hist_over
  write (*, '(a,2es10.3)') 'largest tangent difference / max(K_n, K_t): one step, substepped ', worst_single_k, worst_sub_k
  do stat = 1, nq
    write (*, '(a12,a,es10.3,a,es10.3,a,es10.3,2a)') qname(stat), ': largest |diff| ', dmax(stat), &
      ' largest |value| ', vmax(stat), ' relative ', dmax(stat) / max(vmax(stat), tiny(1.0_dp)), &
      ' at ', trim(where(stat))
  end do

contains

  real(dp) function uni()
    seed = seed * 6364136223846793005_8 + 1442695040888963407_8
    uni = real(ishft(seed, -11), dp) * 2.0_dp**(-53)
    if (uni < 0) uni = uni + 1.0_dp
  end function uni

  subroutine make_material(rset, eset, prefractured, mat)
    integer, intent(in) :: rset, eset
    logical, intent(in) :: prefractured
    type(interlock_material_t), intent(out) :: mat
    integer :: e
    real(dp), parameter :: deg = acos(-1.0_dp) / 180.0_dp
    mat%sigma0_n = 3.0_dp
    mat%sigma0_t = 2.0_dp
    mat%gc = 0.3_dp
    mat%eta = 0.9_dp
    mat%mu = 0.5_dp
    mat%h_n = 0.05_dp
    select case (rset)
    case (1)
      call interlock_paper_ria(mat, 30.0_dp * deg, 7.0_dp * deg, 0.05_dp)
    case (2)
      call interlock_paper_ria(mat, 20.0_dp * deg, 5.0_dp * deg, 0.5_dp)
      mat%h_n = 0.2_dp
    case (3)
      call interlock_general_ria(mat, 5, [0.1_dp, 0.2_dp, 0.3_dp, 0.25_dp, 0.15_dp], &
        [-35.0_dp, -10.0_dp, 0.0_dp, 15.0_dp, 40.0_dp] * deg, [-5.0_dp, -2.0_dp, 0.0_dp, 3.0_dp, 8.0_dp] * deg, &
        [0.02_dp, 0.1_dp, huge(1.0_dp), 0.05_dp, 0.01_dp])
      mat%mu = 0.3_dp
    case (4)
      call interlock_general_ria(mat, 1, [1.0_dp], [0.0_dp], [0.0_dp])
    case (6)
      call interlock_paper_ria(mat, 50.0_dp * deg, 0.0_dp, 1.0e-4_dp)
      mat%mu = 1.2_dp
    case (7)
      call interlock_general_ria(mat, 2, [0.5_dp, 0.5_dp], [-45.0_dp, 45.0_dp] * deg, [-1.0_dp, 1.0_dp] * deg, &
        [1.0e-5_dp, 1.0e-3_dp])
      mat%mu = 0.9_dp
      mat%h_n = huge(1.0_dp)
    case (8:)
      block
        real(dp) :: t0(4), tf(4), z0(4), g(4)
        integer :: j
        do j = 1, 4
          t0(j) = (uni() - 0.5_dp) * 120.0_dp * deg
          tf(j) = t0(j) * uni()
          z0(j) = 10.0_dp**(-6.0_dp + 6.0_dp * uni())
          g(j) = 0.1_dp + uni()
        end do
        g = g / sum(g)
        call interlock_general_ria(mat, 4, g, t0, tf, z0)
        mat%mu = 1.5_dp * uni()
        mat%h_n = 10.0_dp**(-2.5_dp + 2.0_dp * uni())
      end block
    case (5)
      call interlock_general_ria(mat, 2, [0.5_dp, 0.5_dp], [25.0_dp, 25.0_dp] * deg, [10.0_dp, 10.0_dp] * deg, &
        [0.03_dp, 0.03_dp])
      mat%h_n = 0.1_dp
    end select
    do e = 1, 5
      mat%effect(e) = btest(eset, e - 1)
    end do
    mat%prefractured = prefractured
  end subroutine make_material

  subroutine run_history(mat0, solver, force_general)
    type(interlock_material_t), intent(in) :: mat0
    type(interlock_solver_t), intent(in) :: solver
    logical, intent(in) :: force_general
    type(interlock_material_t) :: mat
    type(interlock_state_t) :: old, new_a, new_b
    type(interlock_info_t) :: ia, ib
    real(dp) :: s(2), sa(2), sb(2), ka(2, 2), kb(2, 2), u, target, hn
    integer :: i, n
    mat = mat0
    if (force_general) mat%kernel = kernel_general
    n = mat%n_planes
    hd1 = 0; hv1 = 0; hd2 = 0; hv2 = 0
    call interlock_state_init(mat, old)
    s = 0
    hn = min(mat%h_n, 1.0_dp)
    do i = 1, 400
      u = uni()
      if (u < 0.05_dp) then
        s(2) = s(2) + (uni() - 0.5_dp) * 40.0_dp * mat%s0t
      else
        s(2) = s(2) + (uni() - 0.5_dp) * 1.5_dp * mat%s0t
      end if
      target = merge(-2.0_dp * mat%s0n, 0.6_dp * hn, mod(i / 60, 2) == 0)
      s(1) = 0.7_dp * s(1) + 0.3_dp * target + (uni() - 0.5_dp) * mat%s0n
      if (uni() < 0.03_dp) s(1) = s(1) + (uni() - 0.3_dp) * 2.0_dp * hn
      if (uni() < 0.01_dp) then
        s(2) = s(2) + (uni() - 0.5_dp) * 4000.0_dp * mat%s0t
        s(1) = -(uni() * 60.0_dp) * mat%s0n
      end if
      new_a = old
      new_b = old
      call reset(ia)
      call reset(ib)
      call legacy_update(mat, solver, s, old, new_a, sa, ka, ia)
      call general_update(mat, solver, s, old, new_b, sb, kb, ib)
      n_cases = n_cases + 1
      if (s(1) >= mat%h_n) n_sep = n_sep + 1
      if (ia%status /= ib%status) then
        n_status_diff = n_status_diff + 1
        if (n_status_diff < 20) write (*, '(a,4i3,2(1x,a))') 'status differs ', i, solver%scheme, ia%status, &
          ib%status, trim(ia%message), trim(ib%message)
        old = new_a
        cycle
      end if
      if (ia%status /= status_ok) then
        n_fail = n_fail + 1
        if (ia%message /= ib%message) then
          n_status_diff = n_status_diff + 1
          write (*, '(2a,1x,a)') 'message differs ', trim(ia%message), trim(ib%message)
        end if
      else
        if (ia%substeps > 1 .and. solver%substep_tol > 0) n_sub = n_sub + 1
        if (ia%substeps > 1 .and. solver%substep_tol <= 0) n_fallback = n_fallback + 1
      end if
      if (ia%attempts /= ib%attempts) then
        n_attempt_diff = n_attempt_diff + 1
        write (*, '(a,9i7,es9.1,2(1x,a))') 'attempts differ ', rset, eset, pf, solver%scheme, i, ia%attempts, ib%attempts, &
          ia%status, solver%max_substeps, solver%substep_tol, trim(ia%message), trim(ib%message)
      end if
      if (ia%newton_iterations /= ib%newton_iterations) n_iter_diff = n_iter_diff + 1
      if (ia%substeps /= ib%substeps) n_sub_diff = n_sub_diff + 1
      write (here, '(a,7i6,es9.1,2i5)') 'rset eset pf scheme mode step sub ', rset, eset, pf, solver%scheme, &
        merge(2, 1, force_general), i, ia%substeps, solver%substep_tol, n
      call acc(1, sa, sb)
      call acc(2, reshape(ka, [4]), reshape(kb, [4]))
      block
        real(dp) :: r
        integer :: b
        r = maxval(abs(ka - kb)) / max(maxval(abs(ka)), tiny(1.0_dp))
        if (r > worst_rel) then
          worst_rel = r
          write (*, '(a,es10.3,1x,a,1x,4es12.4)') 'per-update tangent rel ', r, trim(here), ka
        end if
        if (ia%substeps == 1) worst_single = max(worst_single, r)
        if (ia%substeps == 1) then
          hd1 = max(hd1, maxval(abs(ka - kb)))
          hv1 = max(hv1, maxval(abs(ka)))
        else
          hd2 = max(hd2, maxval(abs(ka - kb)))
          hv2 = max(hv2, maxval(abs(ka)))
        end if
        if (ia%substeps == 1) worst_single_k = max(worst_single_k, maxval(abs(ka - kb)) / max(mat%kn, mat%kt))
        if (ia%substeps > 1) worst_sub_k = max(worst_sub_k, maxval(abs(ka - kb)) / max(mat%kn, mat%kt))
        if (r > 1.0e-12_dp) call fd_check(mat, solver, s, old, ka, kb)
        b = 0
        if (r > 0) b = min(20, max(1, int(-log10(r))))
        hist(b) = hist(b) + 1
      end block
      call acc(3, new_a%damage(1:n), new_b%damage(1:n))
      call acc(4, new_a%beta(1:n), new_b%beta(1:n))
      call acc(5, new_a%sf(1:n), new_b%sf(1:n))
      call acc(6, new_a%zeta(1:n), new_b%zeta(1:n))
      call acc(7, new_a%theta(1:n), new_b%theta(1:n))
      call acc(8, new_a%tauf(1:n), new_b%tauf(1:n))
      call acc(9, [new_a%work], [new_b%work])
      call acc(10, [new_a%stored], [new_b%stored])
      call acc(11, [new_a%diss_damage], [new_b%diss_damage])
      call acc(12, [new_a%diss_friction], [new_b%diss_friction])
      call acc(13, [ia%max_damage_increment], [ib%max_damage_increment])
      call acc(14, [ia%max_angle_increment], [ib%max_angle_increment])
      call acc(15, [real(ia%newton_iterations, dp)], [real(ib%newton_iterations, dp)])
      call acc(16, [real(ia%substeps, dp)], [real(ib%substeps, dp)])
      if (any(new_a%s /= new_b%s) .or. any(new_a%sigma /= new_b%sigma)) then
        call acc(1, new_a%sigma, new_b%sigma)
      end if
      old = new_a
    end do
    if (hd1 / max(hv1, tiny(1.0_dp)) > wh1) then
      wh1 = hd1 / max(hv1, tiny(1.0_dp))
      wh1_at = here
    end if
    if (hd2 / max(hv2, tiny(1.0_dp)) > wh2) then
      wh2 = hd2 / max(hv2, tiny(1.0_dp))
      wh2_at = here
    end if
    n_hist = n_hist + 1
    if (hd2 / max(hv2, tiny(1.0_dp)) > 1.0e-14_dp) then
      n_hist_over = n_hist_over + 1
      write (*, '(a,es10.3,1x,a)') 'history over 1e-14 ', hd2 / hv2, trim(here)
    end if
  end subroutine run_history

  subroutine fd_check(mat, solver, s, old, ka, kb)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2), ka(2, 2), kb(2, 2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t) :: nw
    type(interlock_info_t) :: inf
    real(dp) :: kfd(2, 2), sp(2), sm(2), kk(2, 2), h(2), e(2)
    integer :: j
    h = [mat%s0n, mat%s0t] * 1.0e-6_dp
    do j = 1, 2
      e = 0
      e(j) = h(j)
      call reset(inf)
      call general_update(mat, solver, s + e, old, nw, sp, kk, inf)
      call reset(inf)
      call general_update(mat, solver, s - e, old, nw, sm, kk, inf)
      kfd(:, j) = (sp - sm) / (2 * h(j))
    end do
    write (*, '(a,2es10.3,a,es10.3)') '  fd check: |K_old - FD|, |K_new - FD| ', maxval(abs(ka - kfd)), &
      maxval(abs(kb - kfd)), ' |K| ', maxval(abs(ka))
  end subroutine fd_check

  subroutine reset(info)
    type(interlock_info_t), intent(out) :: info
    info%status = status_ok
    info%newton_iterations = 0
    info%substeps = 1
    info%attempts = 1
    info%max_angle_increment = 0
    info%max_damage_increment = 0
    info%message = ''
  end subroutine reset

  subroutine acc(q, a, b)
    integer, intent(in) :: q
    real(dp), intent(in) :: a(:), b(:)
    if (maxval(abs(a - b)) > dmax(q)) where(q) = here
    dmax(q) = max(dmax(q), maxval(abs(a - b)))
    vmax(q) = max(vmax(q), maxval(abs(a)))
  end subroutine acc

end program compare_general_paths
