!> The representative interface area (eq. 24, 26-28): every microplane integrated over one
!> (sub-)increment, the macro traction and its exact tangent assembled with the contact area
!> A_g of the finite asperity depth, and the energy bookkeeping.
module interlock_ria
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t, interlock_solver_t, max_planes
  use interlock_state, only: interlock_state_t
  use interlock_geometry, only: contact_area
  use interlock_schemes, only: plane_t, plane_step
  use interlock_plane_law, only: add_wear_error, wear_error_of
  implicit none
  private
  public :: ria_step

contains

  !> One increment from `old` to the relative displacement `s`.
  !> Without `jac_in`: `tangent` = d sigma / d s at fixed start state.
  !> With `jac_in` (substepping): s = s_start + alpha (s_end - s_start) and `jac_in(:,:,k)` =
  !> d q_old,k / d s_end for q = (beta, sf, zeta, tauf); then `tangent` = d sigma / d s_end and
  !> `jac_out` = d q_new / d s_end, so that the chain over sub-increments stays exact (planes
  !> 1..n_planes only: the others are not set).
  pure subroutine ria_step(mat, solver, s, old, new, tangent, iterations, ok, jac_in, alpha, &
                           jac_out, alpha_start, wear_error)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_solver_t), intent(in) :: solver
    real(dp), intent(in) :: s(2)
    type(interlock_state_t), intent(in) :: old
    type(interlock_state_t), intent(out) :: new
    real(dp), intent(out) :: tangent(2, 2)
    integer, intent(out) :: iterations
    logical, intent(out) :: ok
    real(dp), intent(in), optional :: jac_in(4, 2, max_planes), alpha
    real(dp), intent(out), optional :: jac_out(4, 2, max_planes)
    real(dp), intent(in), optional :: alpha_start   !< fraction of the increment at `old`
    !> with the chain: the embedded local error estimate of the wear (interlock_schemes), the
    !> larger of the angle error [rad] and the traction error it causes relative to the peak
    !> traction plus the current one
    real(dp), intent(out), optional :: wear_error
    type(plane_t) :: p
    real(dp) :: area, darea, gam, sigma(2), a, so_ratio, err_angle, err_traction
    integer :: k, n_eval, ncol
    logical :: chain

    chain = present(jac_in)
    ! From the start of the increment (alpha_start = 0) the incoming chain is zero: the columns
    ! of the start state are not needed.
    ncol = 2
    if (chain .and. present(alpha_start)) then
      if (alpha_start > 0.0_dp) ncol = 6
    else if (chain) then
      ncol = 6
    end if
    a = 1.0_dp
    if (present(alpha)) a = alpha
    ! d s_o / d s_end = alpha_start, in the columns that ria_step scales by alpha
    so_ratio = 0.0_dp
    if (chain .and. present(alpha_start)) so_ratio = alpha_start / a
    new = old
    ok = .true.
    iterations = 0
    sigma = 0.0_dp
    tangent = 0.0_dp
    err_angle = 0.0_dp
    err_traction = 0.0_dp
    new%stored = 0.0_dp

    area = 1.0_dp
    darea = 0.0_dp
    if (mat%use_depth) call contact_area(s(1), mat%inv_h_n, area, darea)

    if (area <= 0.0_dp) then
      ! Separated (decision D7): nothing transmitted, no bond survives, nothing slides.
      do k = 1, mat%n_planes
        if (mat%use_damage) then
          new%beta(k) = max(old%beta(k), mat%beta_break)
          new%damage(k) = 1.0_dp
        end if
        new%tauf(k) = 0.0_dp
        if (chain) then
          jac_out(:, :, k) = 0.0_dp
          if (old%beta(k) >= mat%beta_break .or. .not. mat%use_damage) then
            jac_out(1, :, k) = jac_in(1, :, k)
          end if
          jac_out(2:3, :, k) = jac_in(2:3, :, k)
        end if
      end do
    else
      n_eval = merge(1, mat%n_planes, mat%flat)
      do k = 1, n_eval
        call plane_step(mat, solver, k, s, old%s, so_ratio, old%beta(k), old%sf(k), old%zeta(k), &
                        old%tauf(k), old%damage(k), old%theta(k), ncol, present(wear_error), p)
        if (.not. p%ok) then
          ok = .false.
          return
        end if
        iterations = max(iterations, p%iterations)
        gam = merge(1.0_dp, mat%gamma_hat(k), mat%flat)
        call add_wear_error(p%wear_error, gam * area, p%dsig_dtheta, err_angle, err_traction)
        sigma = sigma + gam * area * p%sig
        if (chain .and. ncol > 2) then
          tangent = tangent + gam * (area * (a * p%gsig(:, 1:2) + &
                    matmul(p%gsig(:, 3:6), jac_in(:, :, k))))
          jac_out(:, :, k) = a * p%gq(:, 1:2) + matmul(p%gq(:, 3:6), jac_in(:, :, k))
        else if (chain) then
          tangent = tangent + gam * area * a * p%gsig(:, 1:2)
          jac_out(:, :, k) = a * p%gq(:, 1:2)
        else
          tangent = tangent + gam * area * p%gsig(:, 1:2)
        end if
        tangent(:, 1) = tangent(:, 1) + gam * a * darea * p%sig
        new%diss_damage = new%diss_damage + gam * area * p%wdmg
        new%diss_friction = new%diss_friction + gam * area * p%wfric
        new%stored = new%stored + gam * area * p%psi
        new%beta(k) = p%beta
        new%damage(k) = p%dmg
        new%sf(k) = p%sf
        new%zeta(k) = p%zeta
        new%theta(k) = p%theta
        new%tauf(k) = p%tauf
      end do
      if (mat%flat) then
        ! Identical flat planes share one history: computed once, copied (SPEC section 7).
        do k = 2, mat%n_planes
          new%beta(k) = new%beta(1)
          new%damage(k) = new%damage(1)
          new%sf(k) = new%sf(1)
          new%zeta(k) = new%zeta(1)
          new%theta(k) = new%theta(1)
          new%tauf(k) = new%tauf(1)
          if (chain) jac_out(:, :, k) = jac_out(:, :, 1)
        end do
      end if
    end if
    new%s = s
    new%sigma = sigma
    new%work = old%work + 0.5_dp * dot_product(old%sigma + sigma, s - old%s)
    if (present(wear_error)) wear_error = wear_error_of(mat, err_angle, err_traction, sigma)
  end subroutine ria_step

end module interlock_ria
