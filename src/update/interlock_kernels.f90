!> Specialised one-step updates, chosen once when the material is prepared, so that a scene
!> pays only for the effects it uses (SPEC section 7; one flat plane without finite depth,
!> the bilinear law and the Alfano-Sacco interface, runs in interlock_integrate itself):
!> without wear the inclinations are constant (sines and cosines computed once, at set-up),
!> one flat plane needs no rotation at all, and each plane's law (interlock_plane_law) is
!> taken with its 2x2 tangent only, without the general path's derivative columns of the start
!> state (which substepping needs). The explicit scheme freezes each angle within the step,
!> so with wear it runs the same kernel with the stored angle's sine and cosine, and one
!> exponential per plane that wore; the coupled schemes add the scalar wear equation per
!> wearing plane. Each kernel agrees with the general path (interlock_general_path) to round-off;
!> core_kernels checks it.
module interlock_kernels
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t, interlock_solver_t, scheme_explicit, &
      kernel_flat, max_planes
  use interlock_wear, only: worn_angle
  use interlock_state, only: interlock_state_t
  use interlock_geometry, only: contact_area
  use interlock_plane_law, only: plane_response_t, plane_law, add_rotated, traction_angle_slope, &
      plane_frame, trapezoidal_weight, wear_weights, coupled_wear, wear_angle_error, &
      add_wear_error, wear_error_of
  implicit none
  private
  public :: kernel_step, share_first_plane

contains

  !> One increment with a specialised kernel. `done` is false when the kernel does not apply
  !> to this increment (a separated RIA, or a coupled wear equation the bounded iteration did
  !> not solve): the caller then takes the general path, which can also sub-increment.
  !> wear_error: the embedded local error estimate of substepping, as the general path's
  !> one step computes it (interlock_general_path:single_step; every scheme).
  pure subroutine kernel_step(mat, solver, s, old, new, tangent, done, iterations, wear_error)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(out) :: tangent(2, 2)
    logical, intent(out) :: done
    integer, intent(out) :: iterations
    real(dp), intent(out), optional :: wear_error
    type(plane_response_t) :: p
    real(dp) :: area, darea, sigma(2), sl(2), c, sn, gam, theta, slope, zeta, thp, fp, gdrv_n, &
                gdrv_t, dthds(2), dsig_dth(2), err_angle, err_traction, e, a_end, g_slip, &
                wfric, slip, c_o, s_o, c_k(max_planes), sn_k(max_planes)
    integer :: k, scheme, it

    scheme = solver%scheme
    iterations = 0
    err_angle = 0.0_dp
    err_traction = 0.0_dp
    if (present(wear_error)) wear_error = 0.0_dp
    area = 1.0_dp
    darea = 0.0_dp
    if (mat%use_depth) call contact_area(s(1), mat%inv_h_n, area, darea)
    done = area > 0.0_dp
    if (.not. done) return
    new%diss_damage = old%diss_damage
    new%diss_friction = old%diss_friction
    new%stored = 0.0_dp
    sigma = 0.0_dp
    tangent = 0.0_dp
    if (mat%kernel == kernel_flat) then
      ! Every plane flat: one computed, in the global frame, the others share its history.
      call wear_weights(mat, scheme, old%damage(1), old%tauf(1), 1.0_dp, 0.0_dp, old%s(1), &
                        old%s(2), a_end, g_slip)
      call fixed_angle_plane(mat, a_end, g_slip, 1, .true., 1.0_dp, 0.0_dp, area, s, old, new, &
                             sigma, tangent)
      if (mat%n_planes > 1) call share_first_plane(mat%n_planes, old, new)
    else
      ! The start frames of the wearing planes first (the explicit scheme's frozen ones): libm's
      ! sincos sets and restores the rounding mode, which waits for the floating-point work
      ! before it, so that the planes' laws after it overlap (the same values).
      do k = 1, mat%n_planes
        if (mat%plane_wears(k)) call plane_frame(mat, k, old%theta(k), c_k(k), sn_k(k))
      end do
      do k = 1, mat%n_planes
        if (.not. mat%plane_wears(k)) then
          call wear_weights(mat, scheme, old%damage(k), old%tauf(k), mat%cos0(k), mat%sin0(k), &
                            old%s(1), old%s(2), a_end, g_slip)
          if (flat_plane(mat, k)) then
            call fixed_angle_plane(mat, a_end, g_slip, k, .true., 1.0_dp, 0.0_dp, &
                                   mat%gamma_hat(k) * area, s, old, new, sigma, tangent)
          else
            call fixed_angle_plane(mat, a_end, g_slip, k, .false., mat%cos0(k), mat%sin0(k), &
                                   mat%gamma_hat(k) * area, s, old, new, sigma, tangent)
          end if
        else if (scheme == scheme_explicit) then
          ! Explicit (eq. 25): the angle frozen at its stored value within the step, the wear
          ! driven by the start state's friction traction.
          c = c_k(k)
          sn = sn_k(k)
          call wear_weights(mat, scheme, old%damage(k), old%tauf(k), c, sn, old%s(1), old%s(2), &
                            a_end, g_slip)
          gam = mat%gamma_hat(k) * area
          if (present(wear_error)) then
            call fixed_angle_plane(mat, a_end, g_slip, k, .false., c, sn, gam, s, old, new, &
                                   sigma, tangent, wfric, slip, dsig_dth)
          else
            call fixed_angle_plane(mat, a_end, g_slip, k, .false., c, sn, gam, s, old, new, &
                                   sigma, tangent)
          end if
          ! Explicit wear (eq. 22, 25): the angle for the next step.
          if (new%zeta(k) > old%zeta(k)) then
            call worn_angle(mat%theta_init(k), mat%thetaf_eff(k), mat%inv_zeta0(k), new%zeta(k), &
                            theta, slope)
            new%theta(k) = theta
          end if
          if (present(wear_error)) then
            e = wear_angle_error(mat, k, scheme, new%theta(k), old%theta(k), new%zeta(k), &
                                 old%zeta(k), wfric, slip, g_slip, 0.0_dp)
            call add_wear_error(e, gam, dsig_dth, err_angle, err_traction)
          end if
        else
          ! A coupled scheme: the wear equation at the end of the step, at the root's angle,
          ! and d theta / d s by implicit differentiation: d zeta/d s = (grad G . R) / F'.
          theta = old%theta(k)
          c = c_k(k)
          sn = sn_k(k)
          c_o = c
          s_o = sn
          call wear_weights(mat, scheme, old%damage(k), old%tauf(k), c, sn, old%s(1), old%s(2), &
                            a_end, g_slip)
          call coupled_wear(mat, k, s, old%beta(k), old%damage(k), old%sf(k), old%zeta(k), a_end, &
                            g_slip, solver%newton_tol, solver%newton_max_iterations, theta, c, sn, &
                            p, zeta, sl, thp, fp, gdrv_n, gdrv_t, it, done)
          iterations = max(iterations, it)
          if (.not. done) return
          gam = mat%gamma_hat(k) * area
          dthds = thp * [gdrv_n * c - gdrv_t * sn, gdrv_n * sn + gdrv_t * c] / fp
          ! R^T sigma_k and R^T K_k R, and the angle's share: d sigma / d theta (x) d theta / d s.
          call add_rotated(p, .false., c, sn, gam, sigma, tangent)
          dsig_dth = traction_angle_slope(p, c, sn, sl)
          tangent(:, 1) = tangent(:, 1) + gam * dsig_dth * dthds(1)
          tangent(:, 2) = tangent(:, 2) + gam * dsig_dth * dthds(2)
          if (present(wear_error)) then
            e = wear_angle_error(mat, k, scheme, theta, old%theta(k), zeta, old%zeta(k), p%wfric, &
                                 p%slip, g_slip, trapezoidal_weight(mat, old%damage(k), c_o, s_o, &
                                                                    old%s(1), old%s(2)))
            call add_wear_error(e, gam, dsig_dth, err_angle, err_traction)
          end if
          call store_plane(p, k, gam, zeta, theta, new)
        end if
      end do
    end if
    ! d A_g / d s_N times the traction at unit area.
    if (mat%use_depth) tangent(:, 1) = tangent(:, 1) + darea * sigma / area
    new%s = s
    new%sigma = sigma
    new%work = old%work + 0.5_dp * dot_product(old%sigma + sigma, s - old%s)
    if (present(wear_error)) wear_error = wear_error_of(mat, err_angle, err_traction, sigma)
  end subroutine kernel_step

  !> One plane whose angle is fixed within the step (constant, or frozen by the explicit
  !> scheme) with frame (c, sn) and weight w (area fraction x contact area): the plane's law,
  !> its traction and tangent rotated to the global frame and added, its end state into `new`
  !> (angle unchanged; zeta by the wear weights a_end, g_slip of the scheme) and its share of
  !> the energies.
  pure subroutine fixed_angle_plane(mat, a_end, g_slip, k, flat, c, sn, w, s, old, new, sigma, &
                                    tangent, wfric_out, slip_out, dsig_dtheta)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: a_end, g_slip   !< the wear driver a_end D |tau_f| |d sf| + g_slip |d sf|
    integer, intent(in) :: k
    !> c = 1 and sn = 0 exactly (a flat plane: the paper's middle plane, every plane of a flat
    !> RIA): its frame is the global one, no rotation (the same values)
    logical, intent(in) :: flat
    real(dp), intent(in) :: c, sn, w, s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    real(dp), intent(inout) :: sigma(2), tangent(2, 2)
    !> (substepping's error estimate) the plane's frictional work D |tau_f| |d sf|, its slip
    !> |d sf| and d sigma_k / d theta at fixed s in the global frame, unweighted
    real(dp), intent(out), optional :: wfric_out, slip_out, dsig_dtheta(2)
    type(plane_response_t) :: p
    real(dp) :: sl(2)

    if (flat) then
      sl = s
    else
      sl(1) = c * s(1) + sn * s(2)
      sl(2) = -sn * s(1) + c * s(2)
    end if
    call plane_law(mat, sl(1), sl(2), old%beta(k), old%damage(k), old%sf(k), mat%use_friction, p)
    call add_rotated(p, flat, c, sn, w, sigma, tangent)
    new%zeta(k) = old%zeta(k) + (a_end * p%wfric + g_slip * p%slip)
    new%diss_damage = new%diss_damage + w * p%wdmg
    new%diss_friction = new%diss_friction + w * p%wfric
    new%stored = new%stored + w * p%psi
    new%beta(k) = p%beta
    new%damage(k) = p%dmg
    new%sf(k) = p%sf
    new%theta(k) = old%theta(k)
    new%tauf(k) = p%tauf
    if (present(wfric_out)) wfric_out = p%wfric
    if (present(slip_out)) slip_out = p%slip
    if (present(dsig_dtheta)) dsig_dtheta = traction_angle_slope(p, c, sn, sl)
  end subroutine fixed_angle_plane

  !> The plane's end-of-step state into `new` (frictional work zeta, angle theta), and its
  !> share (weight g) of the energies.
  pure subroutine store_plane(p, k, g, zeta, theta, new)
    type(plane_response_t), intent(in) :: p
    integer, intent(in) :: k
    real(dp), intent(in) :: g, zeta, theta
    type(interlock_state_t), intent(inout) :: new
    new%beta(k) = p%beta
    new%damage(k) = p%dmg
    new%sf(k) = p%sf
    new%zeta(k) = zeta
    new%theta(k) = theta
    new%tauf(k) = p%tauf
    new%diss_damage = new%diss_damage + g * p%wdmg
    new%diss_friction = new%diss_friction + g * p%wfric
    new%stored = new%stored + g * p%psi
  end subroutine store_plane

  !> Plane k's constant frame is the global one: sin theta_0 = 0 and cos theta_0 = 1 exactly.
  pure logical function flat_plane(mat, k)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    flat_plane = abs(mat%sin0(k)) <= 0.0_dp .and. mat%cos0(k) >= 1.0_dp
  end function flat_plane

  !> A flat RIA of several planes: planes 2..n take plane 1's history (their angles stay).
  pure subroutine share_first_plane(n, old, new)
    integer, intent(in) :: n
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(inout) :: new
    integer :: k
    do k = 2, n
      new%beta(k) = new%beta(1)
      new%damage(k) = new%damage(1)
      new%sf(k) = new%sf(1)
      new%zeta(k) = new%zeta(1)
      new%theta(k) = old%theta(k)
      new%tauf(k) = new%tauf(1)
    end do
  end subroutine share_first_plane

end module interlock_kernels
