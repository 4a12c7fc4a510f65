!> The thin-layer entry (umat/interlock_umat_layer.f90) against the 2D law's body: for every
!> choice of normal and slip axes, NTENS = 6 and 4, the layer's tractions, STATEV and energies
!> are the law's at separation h * strain; its DDSDDE matches central differences of its own
!> STRESS; bad layer PROPS are named with their range; both hosts' PNEWDT conventions; the
!> symmetric tangent option changes DDSDDE only (bitwise STRESS and STATEV) and is never
!> indefinite where the exact tangent is not.
module test_umat_layer_cases
  use, intrinsic :: ieee_arithmetic, only: ieee_value, ieee_positive_inf
  use interlock
  use interlock_assert
  use interlock_umat_body, only: interlock_umat_cohesive
  use interlock_umat_layer, only: interlock_umat_layer_point, host_abaqus, host_calculix, &
      layer_components, pnewdt_calculix_stop
  implicit none
  private
  public :: collect_umat_layer

  real(dp), parameter :: h = 0.01_dp, e_other = 7.0_dp
  !> Table 1 interface, theta_0 = 25 deg, H_N = 0.5 mm, wear (zeta_0 = 2), implicit scheme.
  real(dp), parameter :: interlock_props(11) = [3.0_dp, 3.0_dp, 0.3_dp, 0.9_dp, 0.5_dp, &
      0.5_dp, 25.0_dp, 10.0_dp, 2.0_dp, 0.0_dp, 2.0_dp]
  integer, parameter :: n_steps = 60

  !> One layer point (host side).
  type :: point_t
    real(dp), allocatable :: stress(:), ddsdde(:, :)
    real(dp) :: statev(26) = 0.0_dp
    real(dp) :: sse = 0.0_dp, spd = 0.0_dp, scd = 0.0_dp, pnewdt = 1.0_dp
  end type point_t

contains

  subroutine collect_umat_layer()
    call run_case('layer_equals_law_every_axis_pair', layer_equals_law_every_axis_pair)
    call run_case('ddsdde_matches_central_differences', ddsdde_matches_central_differences)
    call run_case('bad_layer_props_named', bad_layer_props_named)
    call run_case('pnewdt_conventions', pnewdt_conventions)
    call run_case('symmetric_option_same_update', symmetric_option_same_update)
    call run_case('symmetric_tangent_never_indefinite', symmetric_tangent_never_indefinite)
  end subroutine collect_umat_layer

  !> The separation history (normal, slip) at step j: compression, slip forth, back, opening.
  pure function separation_at(j) result(s)
    integer, intent(in) :: j
    real(dp) :: s(2), x
    x = real(j, dp) / real(n_steps, dp)
    if (x <= 0.5_dp) then
      s = [-0.002_dp, 0.5_dp * x]
    else if (x <= 0.8_dp) then
      s = [-0.002_dp + 0.01_dp * (x - 0.5_dp), 0.25_dp - 0.4_dp * (x - 0.5_dp)]
    else
      s = [0.001_dp + 0.2_dp * (x - 0.8_dp), 0.13_dp]
    end if
  end function separation_at

  !> The strain vector (NTENS) of separation s on components comp, other strains `other`.
  pure function strain_of(ntens, comp, s, other) result(e)
    integer, intent(in) :: ntens, comp(2)
    real(dp), intent(in) :: s(2), other
    real(dp) :: e(ntens)
    integer :: i
    do i = 1, ntens
      e(i) = other * real(i, dp)
    end do
    e(comp) = s / h
  end function strain_of

  !> True for the components that are not the interface's.
  pure function other_mask(ntens, comp) result(mask)
    integer, intent(in) :: ntens, comp(2)
    logical :: mask(ntens)
    mask = .true.
    mask(comp) = .false.
  end function other_mask

  function new_point(ntens) result(pt)
    integer, intent(in) :: ntens
    type(point_t) :: pt
    allocate (pt%stress(ntens), pt%ddsdde(ntens, ntens))
    pt%stress = 0.0_dp
    pt%ddsdde = 0.0_dp
  end function new_point

  subroutine call_layer(pt, props, stran, dstran, host, kinc)
    type(point_t), intent(inout) :: pt
    real(dp), intent(in) :: props(:), stran(:), dstran(:)
    integer, intent(in) :: host, kinc
    real(dp) :: rpl, drpldt, ddsddt(size(stran)), drplde(size(stran)), time(2), predef(1), &
                dpred(1), coords(3), drot(3, 3)
    integer :: k
    time = 0.0_dp
    predef = 0.0_dp
    dpred = 0.0_dp
    coords = 0.0_dp
    drot = 0.0_dp
    do k = 1, 3
      drot(k, k) = 1.0_dp
    end do
    rpl = 0.0_dp
    drpldt = 0.0_dp
    ddsddt = 0.0_dp
    drplde = 0.0_dp
    call interlock_umat_layer_point(pt%stress, pt%statev, pt%ddsdde, pt%sse, pt%spd, pt%scd, &
      rpl, ddsddt, drplde, drpldt, stran, dstran, time, 1.0_dp, 0.0_dp, 0.0_dp, predef, dpred, &
      'LAYER', 3, size(stran) - 3, size(stran), size(pt%statev), props, size(props), coords, &
      drot, pt%pnewdt, 1.0_dp, drot, drot, 9, 4, 1, 1, [1, 1, 0, 0], kinc, host)
  end subroutine call_layer

  subroutine call_law(stress, statev, ddsdde, sse, spd, scd, props, stran, dstran, pnewdt)
    real(dp), intent(inout) :: stress(2), statev(22), ddsdde(2, 2), sse, spd, scd, pnewdt
    real(dp), intent(in) :: props(:), stran(2), dstran(2)
    real(dp) :: rpl, drpldt, ddsddt(2), drplde(2), time(2), predef(1), dpred(1), coords(3), &
                drot(3, 3)
    time = 0.0_dp
    predef = 0.0_dp
    dpred = 0.0_dp
    coords = 0.0_dp
    drot = 0.0_dp
    rpl = 0.0_dp
    drpldt = 0.0_dp
    ddsddt = 0.0_dp
    drplde = 0.0_dp
    call interlock_umat_cohesive(stress, statev, ddsdde, sse, spd, scd, rpl, ddsddt, drplde, &
      drpldt, stran, dstran, time, 1.0_dp, 0.0_dp, 0.0_dp, predef, dpred, 'LAW', 1, 1, 2, 22, &
      props, size(props), coords, drot, pnewdt, 1.0_dp, drot, drot, 1, 1, 1, 1, [1, 1, 0, 0], 1)
  end subroutine call_law

  function layer_props(normal, slip, tangent) result(p)
    integer, intent(in) :: normal, slip, tangent
    real(dp), allocatable :: p(:)
    p = [h, e_other, real(normal, dp), real(slip, dp), interlock_props]
    if (tangent > 0) then
      p = [h, e_other, real(normal, dp), real(slip, dp), interlock_props, &
           properties(12:19)%default, real(tangent, dp)]
    end if
  end function layer_props

  subroutine layer_equals_law_every_axis_pair()
    integer :: ntens, normal, slip, j, comp(2)
    type(point_t) :: pt
    real(dp) :: stress(2), statev(22), d(2, 2), sse, spd, scd, pnewdt, s_old(2), s_new(2), &
                e_old(6), e_new(6), elastic
    character(len=64) :: what
    do ntens = 4, 6, 2
      do normal = 1, 3
        do slip = 1, 3
          comp = layer_components(ntens, normal, slip)
          if (comp(1) == 0) cycle
          write (what, '(a,i0,a,i0,a,i0)') 'NTENS ', ntens, ', normal ', normal, ', slip ', slip
          pt = new_point(ntens)
          stress = 0.0_dp
          statev = 0.0_dp
          sse = 0.0_dp
          spd = 0.0_dp
          scd = 0.0_dp
          do j = 1, n_steps
            s_old = separation_at(j - 1)
            s_new = separation_at(j)
            e_old(1:ntens) = strain_of(ntens, comp, s_old, 1.0e-4_dp * (j - 1))
            e_new(1:ntens) = strain_of(ntens, comp, s_new, 1.0e-4_dp * j)
            ! The separations the layer forms (h * strain, rounded as it rounds them).
            pnewdt = 1.0_dp
            call call_law(stress, statev, d, sse, spd, scd, interlock_props, h * e_old(comp), &
                          h * (e_new(comp) - e_old(comp)), pnewdt)
            pt%pnewdt = 1.0_dp
            call call_layer(pt, layer_props(normal, slip, 0), e_old(1:ntens), &
                            e_new(1:ntens) - e_old(1:ntens), host_abaqus, j)
            call assert_equal(stress, pt%stress(comp), 0.0_dp, trim(what) // ': tractions')
            call assert_equal(statev, pt%statev(1:22), 0.0_dp, trim(what) // ': STATEV')
            call assert_equal(s_new, pt%statev(23:24), 1.0e-15_dp, trim(what) // ': STATEV 23-24')
            call assert_equal(reshape(h * d, [4]), reshape(pt%ddsdde(comp, comp), [4]), 0.0_dp, &
                              trim(what) // ': DDSDDE block = h * tangent')
            call assert_equal(stress, pt%statev(25:26), 0.0_dp, trim(what) // ': STATEV 25-26')
            elastic = 0.5_dp * e_other * sum(e_new(1:ntens)**2, mask=other_mask(ntens, comp))
            call assert_close_rel(sse / h + elastic, pt%sse, 1.0e-13_dp, 1.0e-12_dp, &
                                  trim(what) // ': SSE')
            call assert_close_rel(scd / h, pt%scd, 1.0e-13_dp, 1.0e-12_dp, trim(what) // ': SCD')
            call assert_equal(0.0_dp, pt%spd, 0.0_dp, trim(what) // ': SPD')
            call assert_equal(pnewdt, pt%pnewdt, 0.0_dp, trim(what) // ': PNEWDT as the law')
          end do
        end do
      end do
    end do
  end subroutine layer_equals_law_every_axis_pair

  !> DDSDDE(:, j) = d STRESS / d strain_j by central differences of the layer's own update,
  !> from the state after k steps, at several points of the history (contact, sliding,
  !> reversal, opening), for every axis pair with NTENS = 6.
  subroutine ddsdde_matches_central_differences()
    integer :: normal, slip, j, k, i, comp(2)
    type(point_t) :: pt, base, plus, minus
    real(dp) :: e_old(6), e_new(6), de(6), fd(6), delta, scale
    character(len=80) :: what
    integer, parameter :: probe_steps(4) = [5, 20, 40, 55]
    do normal = 1, 3
      do slip = 1, 3
        comp = layer_components(6, normal, slip)
        if (comp(1) == 0) cycle
        pt = new_point(6)
        k = 0
        do j = 1, n_steps
          e_old = strain_of(6, comp, separation_at(j - 1), 1.0e-4_dp * (j - 1))
          e_new = strain_of(6, comp, separation_at(j), 1.0e-4_dp * j)
          base = pt
          call call_layer(pt, layer_props(normal, slip, 0), e_old, e_new - e_old, host_abaqus, j)
          if (.not. any(j == probe_steps)) cycle
          scale = maxval(abs(pt%ddsdde))
          do i = 1, 6
            delta = 1.0e-9_dp / h
            de = 0.0_dp
            de(i) = delta
            plus = base
            minus = base
            call call_layer(plus, layer_props(normal, slip, 0), e_old, e_new - e_old + de, &
                            host_abaqus, j)
            call call_layer(minus, layer_props(normal, slip, 0), e_old, e_new - e_old - de, &
                            host_abaqus, j)
            fd = (plus%stress - minus%stress) / (2.0_dp * delta)
            write (what, '(a,i0,a,i0,a,i0,a,i0)') 'normal ', normal, ', slip ', slip, &
              ', step ', j, ', column ', i
            call assert_equal(fd, pt%ddsdde(:, i), 1.0e-5_dp * scale, trim(what))
          end do
        end do
      end do
    end do
  end subroutine ddsdde_matches_central_differences

  !> Every bad layer value is rejected with its name, value and range (the messages are
  !> checked by the test's PASS_REGULAR_EXPRESSION too); STRESS and STATEV stay as they came.
  subroutine bad_layer_props_named()
    type(point_t) :: pt
    real(dp) :: good(24)
    real(dp), allocatable :: bad(:)
    real(dp) :: e(6)
    integer :: case_index
    good = layer_props(3, 1, 1)
    e = 0.0_dp
    e(3) = -0.1_dp
    do case_index = 1, 7
      bad = good
      select case (case_index)
      case (1)
        bad(1) = 0.0_dp                 ! h
      case (2)
        bad(2) = -5.0_dp                ! e_other
      case (3)
        bad(3) = 4.0_dp                 ! normal_axis
      case (4)
        bad(4) = 3.0_dp                 ! slip_axis = normal_axis
      case (5)
        bad(8) = 1.5_dp                 ! interlock eta (PROPS 4 of the law = 8 of the layer)
      case (6)
        bad(24) = 3.0_dp                ! tangent
      case (7)
        bad = good(1:12)                ! NPROPS = 12
      end select
      pt = new_point(6)
      pt%stress = 1.25_dp
      pt%statev = 0.5_dp
      pt%pnewdt = 1.0_dp
      call call_layer(pt, bad, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], e, &
                      host_abaqus, 1)
      call assert_equal(-1.0_dp, pt%pnewdt, 0.0_dp, 'bad input: PNEWDT = -1 (Abaqus)')
      call assert_equal(spread(1.25_dp, 1, 6), pt%stress, 0.0_dp, 'bad input: STRESS untouched')
      call assert_equal(spread(0.5_dp, 1, 26), pt%statev, 0.0_dp, 'bad input: STATEV untouched')
    end do
    ! NTENS = 4: only the 1-2 pair is an interface.
    pt = new_point(4)
    call call_layer(pt, layer_props(1, 3, 0), [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], &
                    [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], host_abaqus, 1)
    call assert_equal(-1.0_dp, pt%pnewdt, 0.0_dp, 'NTENS 4 with axes 1, 3: bad input')
  end subroutine bad_layer_props_named

  !> ccx: -1 ("no request") stays when all is well; bad input asks for a stop-size cutback; a
  !> positive request from another point is only lowered. Abaqus: only lowered.
  subroutine pnewdt_conventions()
    type(point_t) :: pt
    real(dp) :: e(6)
    real(dp), allocatable :: bad(:)
    e = 0.0_dp
    e(3) = -0.1_dp
    pt = new_point(6)
    pt%pnewdt = -1.0_dp
    call call_layer(pt, layer_props(3, 1, 1), [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], &
                    e, host_calculix, 1)
    call assert_equal(-1.0_dp, pt%pnewdt, 0.0_dp, 'ccx: no request stays -1')
    bad = layer_props(3, 1, 1)
    bad(1) = -1.0_dp
    pt = new_point(6)
    pt%pnewdt = -1.0_dp
    call call_layer(pt, bad, [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], e, &
                    host_calculix, 1)
    call assert_equal(pnewdt_calculix_stop, pt%pnewdt, 0.0_dp, 'ccx: bad input asks to stop')
    pt = new_point(6)
    pt%pnewdt = 0.25_dp
    call call_layer(pt, layer_props(3, 1, 1), [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], &
                    e, host_calculix, 1)
    call assert_equal(0.25_dp, pt%pnewdt, 0.0_dp, "ccx: another point's request kept")
    ! A local failure: a non-finite strain from a diverged iteration -> 0.5.
    e(3) = ieee_value(1.0_dp, ieee_positive_inf)
    pt = new_point(6)
    pt%pnewdt = -1.0_dp
    call call_layer(pt, layer_props(3, 1, 1), [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], &
                    e, host_calculix, 1)
    call assert_equal(0.5_dp, pt%pnewdt, 0.0_dp, 'ccx: local failure asks for 0.5')
    pt = new_point(6)
    pt%pnewdt = 1.0_dp
    call call_layer(pt, layer_props(3, 1, 1), [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], &
                    e, host_abaqus, 1)
    call assert_equal(0.5_dp, pt%pnewdt, 0.0_dp, 'Abaqus: local failure 0.5')
  end subroutine pnewdt_conventions

  !> tangent = 2 gives bitwise the same STRESS, STATEV and energies as tangent = 1, a
  !> symmetric DDSDDE, and the exact one's diagonal.
  subroutine symmetric_option_same_update()
    type(point_t) :: exact, sym
    real(dp) :: e_old(6), e_new(6)
    integer :: j, comp(2)
    comp = layer_components(6, 1, 3)
    exact = new_point(6)
    sym = new_point(6)
    do j = 1, n_steps
      e_old = strain_of(6, comp, separation_at(j - 1), 0.0_dp)
      e_new = strain_of(6, comp, separation_at(j), 0.0_dp)
      call call_layer(exact, layer_props(1, 3, 1), e_old, e_new - e_old, host_calculix, j)
      call call_layer(sym, layer_props(1, 3, 2), e_old, e_new - e_old, host_calculix, j)
      call assert_equal(exact%stress, sym%stress, 0.0_dp, 'STRESS bitwise')
      call assert_equal(exact%statev, sym%statev, 0.0_dp, 'STATEV bitwise')
      call assert_equal([exact%sse, exact%scd], [sym%sse, sym%scd], 0.0_dp, 'energies bitwise')
      call assert_equal(reshape(sym%ddsdde, [36]), reshape(transpose(sym%ddsdde), [36]), &
                        0.0_dp, 'DDSDDE symmetric')
      ! The diagonal is kept (a negative entry is raised to 0 where the law is stable).
      call assert_equal(max(exact%ddsdde(1, 1), 0.0_dp), max(sym%ddsdde(1, 1), 0.0_dp), 0.0_dp, &
                        'normal diagonal kept')
      call assert_equal(max(exact%ddsdde(5, 5), 0.0_dp), max(sym%ddsdde(5, 5), 0.0_dp), 0.0_dp, &
                        'shear diagonal kept')
    end do
  end subroutine symmetric_option_same_update

  !> Over the law's tangents along a history with damage, friction, interlocking, reversal and
  !> opening, and over random 2 x 2 matrices: where the exact tangent has no eigenvalue with a
  !> negative real part, the symmetric one has none either (its smallest eigenvalue >= -1e-12
  !> of its scale).
  subroutine symmetric_tangent_never_indefinite()
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(umat_controls_t) :: controls
    type(interlock_state_t) :: old, new
    type(interlock_info_t) :: info
    real(dp) :: sigma(2), d(2, 2), u(4)
    integer :: stat, j, sample, n_stable
    character(len=message_len) :: message
    call props_to_material(interlock_props, mat, solver, controls, stat, message)
    call interlock_state_init(mat, old)
    n_stable = 0
    do j = 1, n_steps
      call interlock_update(mat, solver, separation_at(j), old, new, sigma, d, info)
      old = new
      call check_matrix(d)
    end do
    do sample = 1, 20000
      call random_number(u)
      d = reshape(200.0_dp * (u - 0.3_dp), [2, 2])
      call check_matrix(d)
    end do
    call assert_true(n_stable > 1000, 'enough stable samples')
  contains
    subroutine check_matrix(dm)
      real(dp), intent(in) :: dm(2, 2)
      real(dp) :: s(2, 2), tr, det, lowest
      tr = dm(1, 1) + dm(2, 2)
      det = dm(1, 1) * dm(2, 2) - dm(1, 2) * dm(2, 1)
      if (tr < 0.0_dp .or. det < 0.0_dp) return
      n_stable = n_stable + 1
      s = dm
      call interlock_symmetric_tangent(s)
      lowest = 0.5_dp * (s(1, 1) + s(2, 2)) - sqrt(0.25_dp * (s(1, 1) - s(2, 2))**2 + s(1, 2)**2)
      call assert_true(lowest >= -1.0e-12_dp * maxval(abs(dm)), &
                       'symmetric tangent positive semi-definite where D is stable')
      call assert_equal(s(1, 2), s(2, 1), 0.0_dp, 'symmetric')
    end subroutine check_matrix
  end subroutine symmetric_tangent_never_indefinite

end module test_umat_layer_cases

program test_umat_layer
  use test_umat_layer_cases, only: collect_umat_layer
  use interlock_assert, only: suite_summary
  implicit none
  call collect_umat_layer()
  if (suite_summary('umat_layer') /= 0) error stop 1
end program test_umat_layer
