!> The law of one microplane of a three-dimensional interface over one step (SPEC section 9),
!> in plain reals with its exact derivatives written out: the plane's frame (m, e, q) from its
!> inclination theta and azimuth phi, the local separation (s_kn, s_kt1, s_kt2), isotropic
!> damage in the microplane (interlock_damage with |s_kt|), Coulomb friction on the damaged part
!> by radial return or D14's mean-direction rule, the traction of eq. 6 with a tangential
!> 2-vector, rotated back to the macro frame (n, t1, t2), and what the schemes' wear drivers and
!> the energy bookkeeping need (the slip in the dip direction, the frictional work, the damage
!> dissipation, the stored energy). Every derivative is with respect to the local separation
!> at a fixed start state (the caller chains the frame and the angle); at a kink the side SPEC
!> section 6 and D13 name: s_kn = 0 is closed for every derivative (<s_kn>_+ has slope 0 there),
!> and so is a positive s_kn within the round-off of its rotation (contact_round_off: a path in
!> the plane's surface gives s_kn = 0 or +-1e-17 from one step to the next, and a chain over
!> such steps must not mix the sides). Every operation on a value is the one of the 2D law
!> (interlock_plane_law) in the same order where the strike components vanish.
module interlock_plane_law_3d
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t
  use interlock_damage, only: damage_growth, damage_may_grow
  use interlock_friction, only: radial_return, vector_norm, norm_gradient, sign_of, &
      slides_at_start, start_direction, mean_direction_return, mean_direction_slide, &
      mean_direction_tie, straight_wear_start
  use interlock_plane_law, only: normal_traction, tangential_traction
  implicit none
  private
  public :: plane_start_3d_t, plane_law_3d_t, plane_law_3d, plane_law_3d_parts, &
            plane_traction_3d, slides_at_start, local_frame, contact_round_off, to_macro

  !> One plane's state at the start of a step (SPEC section 9: D, beta, sf(2), zeta, theta,
  !> tauf(2); vectors in the plane's (e, q) frame).
  type :: plane_start_3d_t
    real(dp) :: beta, dmg, sf(2), zeta, theta, tauf(2)
  end type plane_start_3d_t

  !> One plane at the end of the step from its start state, with the derivatives of each
  !> quantity x as g_x(j) = d x / d sl(j), sl = (s_kn, s_kt1, s_kt2) the local separation.
  !> With `chain` (substepping chains the steps) also g_beta, g_sf and the derivatives with
  !> respect to the start state that the values of sl do not carry: the start slip sf_o
  !> enters friction only through sl_t - sf_o (so d / d sf_o of a friction quantity is minus
  !> its d / d sl_t at fixed D, and D-weighted quantities name their d / d D), the start
  !> damage and history where the step keeps them, and the angle phi_o of the start direction
  !> of slip tauf_o / |tauf_o| where D14's mean-direction rule applied.
  type :: plane_law_3d_t
    real(dp) :: sl(3)                     !< the local separation [mm]
    real(dp) :: beta, dmg, sf(2), tauf(2) !< the end state
    real(dp) :: g_dmg(3), g_tauf(3, 2)
    real(dp) :: g_beta(3), g_sf(3, 2)     !< (chain)
    logical :: beta_kept   !< beta = beta_o (no growth of the equivalent displacement)
    logical :: dmg_kept    !< D = D_o (damage on and beta kept)
    logical :: mean        !< (chain) D14's mean direction was taken (the phi_ derivatives apply)
    !> d / d phi_o (chain, mean): of tau_f, sf, wear_start, wear_end
    real(dp) :: phi_tauf(2), phi_sf(2), phi_wear_start, phi_wear_end
    !> d / d D at fixed friction (chain): of sig_loc, wfric_dip, wear_end
    real(dp) :: dmg_sig(3), dmg_wfric_dip, dmg_wear_end
    real(dp) :: sig_loc(3)   !< the traction (sigma_kn, sigma_kt1, sigma_kt2) [MPa]
    real(dp) :: k_loc(3, 3)  !< k_loc(i, j) = d sig_loc(i) / d sl(j) [MPa/mm]
    real(dp) :: slip_dip     !< |sf_1 - sf_o,1|, the slip of the step along the dip [mm]
    real(dp) :: wfric_dip    !< D |tau_f,1| |d sf_1|, the work that wears [N/mm]
    !> The trapezoidal scheme's wear terms (D14): the slip of the step |d sf| times the squared
    !> dip component of the slip direction at the start, and D |tau_f,1| |d sf| |n_1| with the
    !> direction n at the end. Along a straight local path (radial return) |d sf_1| times the
    !> direction's dip share and wfric_dip.
    real(dp) :: wear_start, wear_end
    !> their derivatives, where the caller asks for them (`drivers`; g_slip_dip and g_wfric_dip
    !> not where D14's mean direction was taken, whose driver is wear_start and wear_end)
    real(dp) :: g_slip_dip(3), g_wfric_dip(3), g_wear_start(3), g_wear_end(3)
    real(dp) :: pos, dpos    !< <s_kn>_+ and its slope (0 at the tie)
    real(dp) :: slip_norm    !< |d sf|, the slip of the step [mm]
    real(dp) :: tauf_norm    !< |tau_f| [MPa]: mu p sliding, |tau_tr| sticking, 0 free
    logical :: dmg_grows     !< D grows below 1 (g_dmg applies)
    real(dp) :: wfric   !< frictional work on the damaged part, D |tau_f| |d sf| [N/mm]
    real(dp) :: wdmg    !< energy dissipated by damage in the step [N/mm]
    real(dp) :: psi     !< stored energy at the end of the step [N/mm]
  end type plane_law_3d_t

  real(dp), parameter :: e_t(3, 2) = reshape([0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], &
                                             [3, 2])

contains

  !> sl = (m . s, e . s, q . s) of a plane of azimuth frame (cp, sp) = (cos, sin)(phi) at
  !> angle theta (frame c, sn): m = cos(theta) n + sin(theta) d, e = -sin(theta) n +
  !> cos(theta) d, q = -sin(phi) t1 + cos(phi) t2, with the dip direction d = cos(phi) t1 +
  !> sin(phi) t2; and the round-off of s_kn = cos(theta) s_N + sin(theta) (cos(phi) s_T1 +
  !> sin(phi) s_T2), tie = 8 eps times the magnitudes summed: an s_kn up to it is at the tie
  !> s_kn = 0 for the derivatives (SPEC D13; its values are kept).
  pure subroutine local_frame(cp, sp, c, sn, s, sl, tie)
    real(dp), intent(in) :: cp, sp, c, sn, s(3)
    real(dp), intent(out) :: sl(3), tie
    real(dp) :: dip
    dip = cp * s(2) + sp * s(3)
    sl(1) = c * s(1) + sn * dip
    sl(2) = -(sn * s(1)) + c * dip
    sl(3) = -(sp * s(2)) + cp * s(3)
    tie = 8.0_dp * epsilon(1.0_dp) * (abs(c * s(1)) + abs(sn * dip))
  end subroutine local_frame

  !> The round-off of s_kn of local_frame.
  pure real(dp) function contact_round_off(cp, sp, c, sn, s) result(tie)
    real(dp), intent(in) :: cp, sp, c, sn, s(3)
    real(dp) :: sl(3)
    call local_frame(cp, sp, c, sn, s, sl, tie)
  end function contact_round_off

  !> A local vector v (components along m, e, q) in the macro frame (n, t1, t2).
  pure function to_macro(cp, sp, c, sn, v) result(w)
    real(dp), intent(in) :: cp, sp, c, sn, v(3)
    real(dp) :: w(3)
    real(dp) :: dip
    dip = sn * v(1) + c * v(2)
    w(1) = c * v(1) - sn * v(2)
    w(2) = cp * dip - sp * v(3)
    w(3) = sp * dip + cp * v(3)
  end function to_macro

  !> A plane at the local separation sl from the start state o (SPEC section 9, one step,
  !> points 3-5 and the energies), plane_law_3d_parts with its traction; s_kn up to tie
  !> (absent: 0) is closed for every derivative.
  pure subroutine plane_law_3d(mat, sl, o, mu_p_o, drivers, chain, p, tie)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: sl(3), mu_p_o
    real(dp), intent(in), optional :: tie
    type(plane_start_3d_t), intent(in) :: o
    logical, intent(in) :: drivers, chain
    type(plane_law_3d_t), intent(out) :: p
    real(dp) :: n_o(2)
    logical :: mean_o
    call start_direction(o%tauf, mu_p_o, mean_o, n_o)
    if (present(tie)) then
      call plane_law_3d_parts(mat, sl, tie, o, mean_o, n_o, drivers, chain, .true., .true., &
                              .false., p)
    else
      call plane_law_3d_parts(mat, sl, 0.0_dp, o, mean_o, n_o, drivers, chain, .true., .true., &
                              .false., p)
    end if
  end subroutine plane_law_3d

  !> plane_law_3d: s_kn up to tie (contact_round_off) is closed for every derivative.
  !> `traction` false: damage, friction and the wear drivers alone (what a wear equation's
  !> iteration needs), plane_traction_3d gives the rest. `mean_o`: the slip direction follows
  !> D14's mean-direction rule (the trapezoidal scheme) from the start direction of slip n_o
  !> (start_direction: the plane slides at the start; n_o is not read where mean_o is false,
  !> radial return alone). `drivers`: the derivatives of the wear drivers are wanted (a scheme
  !> whose angle is coupled to the end of the step, on a plane that wears). `trapezoidal_terms`:
  !> the trapezoidal scheme's wear terms wear_start and wear_end are wanted (true with mean_o;
  !> else they are not set, nor the slip of a free plane's step, which its energies do not need:
  !> slip_norm 0 there). `in_plane`: the strike components vanish (s_kt2 = 0, sf_o,2 = tauf_o,2
  !> = 0) and only the derivatives of the (s_kn, s_kt1) components with respect to (s_kn, s_kt1)
  !> are wanted (the others' are left 0 or as they come): the slip is along the dip (D14's mean
  !> direction is the start direction, tau_tr's: radial return gives its values), |tau_tr| =
  !> |tau_tr,1|, no projector.
  pure subroutine plane_law_3d_parts(mat, sl, tie, o, mean_o, n_o, drivers, chain, traction, &
                                     trapezoidal_terms, in_plane, p)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: sl(3), tie, n_o(2)
    type(plane_start_3d_t), intent(in) :: o
    logical, intent(in) :: mean_o, drivers, chain, traction, trapezoidal_terms, in_plane
    type(plane_law_3d_t), intent(out) :: p
    real(dp) :: pos, dpos, tn, tn2, gd_n, gd_t, mu_p, g_mu(3), tr(2), trn, nv(2), g_nv(3, 2), &
                n_new(2), g_psi(3), dsf(2), slip_norm, g_slip_norm(3), atau, g_atau(3), x, &
                phi_turn, phi_nn(2), phi_slip_norm, phi_x, u(2), cos_psi, sin_psi
    integer :: i
    logical :: closed_at_zero, mean_direction, grows, open

    p%sl = sl
    open = sl(1) > tie

    ! Damage, isotropic in the microplane: beta_eq from <s_kn>_+ and |s_kt| (interlock_damage).
    pos = max(0.0_dp, sl(1))
    dpos = merge(1.0_dp, 0.0_dp, open)
    p%beta = o%beta
    p%g_dmg = 0.0_dp
    if (chain) then
      p%g_beta = 0.0_dp
      p%mean = .false.
      p%phi_tauf = 0.0_dp
      p%phi_sf = 0.0_dp
      p%phi_wear_start = 0.0_dp
      p%phi_wear_end = 0.0_dp
    end if
    grows = .false.
    tn = 0.0_dp
    gd_n = 0.0_dp
    gd_t = 0.0_dp
    if (mat%use_damage) then
      p%dmg = o%dmg
      tn2 = sl(2) * sl(2) + sl(3) * sl(3)
      if (damage_may_grow(pos * mat%inv_s0n, tn2 * (mat%inv_s0t * mat%inv_s0t), o%beta)) then
        tn = sqrt(tn2)
        call damage_growth(pos * mat%inv_s0n, tn * mat%inv_s0t, o%beta, o%dmg, mat%eta, &
                           mat%inv_eta, mat%beta_break, mat%inv_s0n, mat%inv_s0t, p%beta, &
                           p%dmg, gd_n, gd_t)
      end if
      ! (gd_n, gd_t = 0 unless D grows below 1)
      grows = gd_n > 0.0_dp .or. gd_t > 0.0_dp
      if (chain .and. p%beta > o%beta) then
        ! beta = beta_eq = sqrt(an^2 + at^2)
        p%g_beta(1) = (pos * mat%inv_s0n) * mat%inv_s0n * dpos / p%beta
        if (tn > 0.0_dp) then
          p%g_beta(2) = (tn * mat%inv_s0t) * mat%inv_s0t * (sl(2) / tn) / p%beta
          p%g_beta(3) = (tn * mat%inv_s0t) * mat%inv_s0t * (sl(3) / tn) / p%beta
        else
          p%g_beta(2:3) = 0.0_dp
        end if
      end if
      if (grows) then
        p%g_dmg(1) = gd_n * dpos
        if (tn > 0.0_dp) then
          p%g_dmg(2) = gd_t * (sl(2) / tn)
          p%g_dmg(3) = gd_t * (sl(3) / tn)
        end if
      end if
    else
      p%dmg = mat%d_frozen
    end if
    p%beta_kept = .not. p%beta > o%beta
    p%dmg_kept = mat%use_damage .and. p%beta_kept

    ! Friction on the damaged part, to |tau_f| = mu p (p = K_n <-s_kn>_+); free (sf = s_kt,
    ! tau_f = 0) on an open plane or without friction. At the tie s_kn = 0 mu p has the closed
    ! side's derivative (SPEC D13).
    mu_p = 0.0_dp
    g_mu = 0.0_dp
    if (mat%use_friction) then
      mu_p = -mat%mu_eff * mat%kn * min(sl(1), 0.0_dp)
      if (.not. open) g_mu(1) = -mat%mu_eff * mat%kn
    end if
    closed_at_zero = .false.
    mean_direction = .false.
    if (mu_p > 0.0_dp) then
      tr(1) = mat%kt * (sl(2) - o%sf(1))
      tr(2) = mat%kt * (sl(3) - o%sf(2))
      if (in_plane) then
        trn = abs(tr(1))
      else
        trn = vector_norm(tr)
      end if
      if (trn <= mu_p) then
        ! stick
        p%sf = o%sf
        if (chain) p%g_sf = 0.0_dp
        p%tauf = tr
        p%tauf_norm = trn
        p%g_tauf = 0.0_dp
        p%g_tauf(2, 1) = mat%kt
        p%g_tauf(3, 2) = mat%kt
        p%slip_dip = 0.0_dp
        p%g_slip_dip = 0.0_dp
        slip_norm = 0.0_dp
        g_slip_norm = 0.0_dp
      else
        if (mean_o .and. .not. in_plane) &
          call mean_direction_return(mat%kt, n_o, tr, mu_p, g_mu(1), chain, drivers, &
                                     mean_direction, n_new, g_psi, phi_turn, u, cos_psi, sin_psi)
        ! |tau_f| = mu p sliding, in either direction rule
        p%tauf_norm = mu_p
        if (mean_direction) then
          ! D14: the slip increment along the mean of the start and end directions, |tau_f| =
          ! mu p along n_new, and the trapezoidal wear terms (interlock_friction)
          call mean_direction_slide(mu_p, g_mu(1), mat%inv_kt, sl(2:3), tr, n_o, n_new, g_psi, &
                                    u, cos_psi, sin_psi, p%dmg, p%g_dmg, grows, drivers, p%tauf, &
                                    p%g_tauf, p%sf, dsf, slip_norm, p%wear_start, p%wear_end, &
                                    p%g_wear_start, p%g_wear_end)
          p%slip_dip = abs(dsf(1))
          if (chain) then
            ! d / d phi_o: n_new turns with n_o (phi_nn), the slip dsf = (tau_tr - tau_f) / K_t
            x = slip_norm * abs(n_new(1))
            atau = p%dmg * abs(p%tauf(1))
            p%mean = .true.
            phi_nn(1) = -n_new(2) * phi_turn
            phi_nn(2) = n_new(1) * phi_turn
            p%phi_tauf = mu_p * phi_nn
            p%phi_sf = -p%phi_tauf * mat%inv_kt
            phi_slip_norm = 0.0_dp
            if (slip_norm > 0.0_dp) phi_slip_norm = dot_product(dsf, p%phi_sf) / slip_norm
            p%phi_wear_start = phi_slip_norm * (n_o(1) * n_o(1)) - &
                               2.0_dp * slip_norm * n_o(1) * n_o(2)
            phi_x = phi_slip_norm * abs(n_new(1)) + slip_norm * sign_of(n_new(1)) * phi_nn(1)
            p%phi_wear_end = (p%dmg * sign_of(p%tauf(1)) * p%phi_tauf(1)) * x + atau * phi_x
            p%dmg_wear_end = abs(p%tauf(1)) * x
          end if
        else
          ! radial return (interlock_friction): sf - sf_o = n (|tau_tr| - mu p) / K_t along
          ! n = tau_tr / |tau_tr|
          call radial_return(mu_p, g_mu, mat%kt, mat%inv_kt, sl(2:3), tr, trn, nv, g_nv, p%sf, &
                             p%tauf, p%g_tauf, slip_norm, in_plane)
          if (chain) then
            do i = 1, merge(1, 2, in_plane)
              p%g_sf(:, i) = e_t(:, i) - p%g_tauf(:, i) * mat%inv_kt
            end do
          end if
          p%slip_dip = abs(nv(1)) * slip_norm
          if (drivers) then
            ! n - d(mu p) / K_t
            g_slip_norm(1) = -(g_mu(1) * mat%inv_kt)
            g_slip_norm(2) = nv(1) - g_mu(2) * mat%inv_kt
            g_slip_norm(3) = nv(2) - g_mu(3) * mat%inv_kt
            if (in_plane) then
              p%g_slip_dip = g_slip_norm
            else
              p%g_slip_dip = sign_of(nv(1)) * g_nv(:, 1) * slip_norm + abs(nv(1)) * g_slip_norm
            end if
          end if
        end if
      end if
    else
      p%sf(1) = sl(2)
      p%sf(2) = sl(3)
      if (chain) p%g_sf = e_t
      p%tauf = 0.0_dp
      p%tauf_norm = 0.0_dp
      p%g_tauf = 0.0_dp
      dsf(1) = p%sf(1) - o%sf(1)
      dsf(2) = p%sf(2) - o%sf(2)
      p%slip_dip = abs(dsf(1))
      slip_norm = 0.0_dp
      if (trapezoidal_terms .or. drivers) slip_norm = vector_norm(dsf)
      if (drivers) then
        p%g_slip_dip = sign_of(dsf(1)) * e_t(:, 1)
        g_slip_norm = norm_gradient(dsf, slip_norm, e_t)
      end if
      if (mat%use_friction .and. .not. open) then
        ! s_kn = 0 (the tie): in contact for every derivative (SPEC D13). The values are the
        ! free plane's, the same as the slide's with mu p = 0 (tau_f = 0, sf = s_kt); the
        ! derivatives are the slide's: d tau_f = d(mu p) n, the slip shortened by d(mu p) / K_t
        ! along n. At the cone's apex (|tau_tr| = 0) a kink where they stay 0.
        tr(1) = mat%kt * (sl(2) - o%sf(1))
        tr(2) = mat%kt * (sl(3) - o%sf(2))
        trn = vector_norm(tr)
        if (trn > 0.0_dp .and. mean_o .and. .not. in_plane) &
          call mean_direction_return(mat%kt, n_o, tr, mu_p, g_mu(1), .false., .false., &
                                     mean_direction, n_new, g_psi, phi_turn, u, cos_psi, sin_psi)
        if (mean_direction) then
          ! and D14's direction where the plane slid at the start (the trapezoidal scheme):
          ! the slip (tau_tr - mu p n_new) / K_t, its values the free plane's
          call mean_direction_tie(mat%kt, mat%inv_kt, tr, n_o, n_new, g_mu, p%dmg, slip_norm, &
                                  drivers, p%g_tauf, p%wear_start, p%wear_end, p%g_slip_dip, &
                                  p%g_wear_start, p%g_wear_end)
          atau = 0.0_dp
          if (chain) then
            ! (the slide's derivatives with mu p = 0: tau_f and the slip do not turn with n_o)
            p%mean = .true.
            p%phi_wear_start = -2.0_dp * slip_norm * n_o(1) * n_o(2)
            p%dmg_wear_end = 0.0_dp
          end if
          closed_at_zero = .true.
        else if (trn > 0.0_dp) then
          do i = 1, 2
            nv(i) = tr(i) / trn
            p%g_tauf(:, i) = nv(i) * g_mu
            if (chain) p%g_sf(:, i) = e_t(:, i) - p%g_tauf(:, i) * mat%inv_kt
          end do
          atau = 0.0_dp
          if (drivers) then
            g_atau = abs(nv(1)) * g_mu
            g_slip_norm = g_slip_norm - g_mu * mat%inv_kt
            p%g_slip_dip = p%g_slip_dip - g_atau * mat%inv_kt
          end if
          closed_at_zero = .true.
        end if
      end if
    end if
    ! (D14's slide, or its tie: sf = s_kt - tau_f / K_t)
    if (chain .and. mean_direction) then
      do i = 1, 2
        p%g_sf(:, i) = e_t(:, i) - p%g_tauf(:, i) * mat%inv_kt
      end do
    end if
    if (.not. closed_at_zero) then
      atau = abs(p%tauf(1))
      if (drivers) g_atau = sign_of(p%tauf(1)) * p%g_tauf(:, 1)
    end if

    if (chain) then
      p%dmg_wfric_dip = atau * p%slip_dip
      if (.not. p%mean) p%dmg_wear_end = p%dmg_wfric_dip
    end if

    ! The wear drivers in the dip direction.
    p%wfric_dip = p%dmg * atau * p%slip_dip
    if (trapezoidal_terms .and. .not. mean_direction) then
      if (in_plane) then
        ! (in the plane (n, t1) the slip is along the dip: share 1, d share 0)
        p%wear_start = p%slip_dip
      else
        call straight_wear_start(p%slip_dip, slip_norm, p%g_slip_dip, g_slip_norm, drivers, &
                                 p%wear_start, p%g_wear_start)
      end if
      p%wear_end = p%wfric_dip
    end if
    if (drivers) then
      if (.not. mean_direction) then
        if (grows) then
          p%g_wfric_dip = (p%g_dmg * atau + p%dmg * g_atau) * p%slip_dip + &
                          (p%dmg * atau) * p%g_slip_dip
        else
          ! (g_dmg = 0)
          p%g_wfric_dip = (p%dmg * g_atau) * p%slip_dip + (p%dmg * atau) * p%g_slip_dip
        end if
      end if
      if (trapezoidal_terms .and. in_plane) then
        p%g_wear_start = p%g_slip_dip
        p%g_wear_end = p%g_wfric_dip
      else if (trapezoidal_terms .and. .not. mean_direction) then
        p%g_wear_end = p%g_wfric_dip
      end if
    end if

    p%pos = pos
    p%dpos = dpos
    p%slip_norm = slip_norm
    p%dmg_grows = grows
    if (traction) call plane_traction_3d(mat, o, chain, p)
  end subroutine plane_law_3d_parts

  !> The rest of plane_law_3d from its damage and friction in p: the traction (eq. 6, stated in
  !> interlock_plane_law) in the plane's frame with its derivative k_loc, with `chain` its
  !> d / d D at fixed friction, and the energies.
  pure subroutine plane_traction_3d(mat, o, chain, p)
    type(interlock_material_t), intent(in) :: mat
    type(plane_start_3d_t), intent(in) :: o
    logical, intent(in) :: chain
    type(plane_law_3d_t), intent(inout) :: p
    real(dp) :: kpos, kts, tauf_norm, work
    integer :: i

    ! d sigma_kn = K_n (1 - D <s_kn>_+') ds_kn - K_n <s_kn>_+ dD, d sigma_kt = (1 - D) K_t ds_kt
    ! + D d tau_f + (tau_f - K_t s_kt) dD.
    kpos = mat%kn * p%pos
    p%sig_loc(1) = normal_traction(mat%kn, p%sl(1), p%dmg, kpos)
    p%k_loc(1, :) = 0.0_dp
    p%k_loc(1, 1) = mat%kn - (p%dmg * mat%kn) * p%dpos
    do i = 1, 2
      kts = mat%kt * p%sl(1 + i)
      p%sig_loc(1 + i) = tangential_traction(p%dmg, kts, p%tauf(i), .true.)
      p%k_loc(1 + i, :) = p%dmg * p%g_tauf(:, i)
      p%k_loc(1 + i, 1 + i) = p%k_loc(1 + i, 1 + i) + (1.0_dp - p%dmg) * mat%kt
      if (p%dmg_grows) p%k_loc(1 + i, :) = p%k_loc(1 + i, :) + (p%tauf(i) - kts) * p%g_dmg
    end do
    if (p%dmg_grows) p%k_loc(1, :) = p%k_loc(1, :) - kpos * p%g_dmg
    if (chain) then
      p%dmg_sig(1) = -kpos
      p%dmg_sig(2) = p%tauf(1) - mat%kt * p%sl(2)
      p%dmg_sig(3) = p%tauf(2) - mat%kt * p%sl(3)
    end if

    ! Energies, as the 2D law's (interlock_plane_law) with vectors: the frictional work on the
    ! damaged part, the damage dissipation Y dD (the elastic part exact, the friction part at
    ! first order), the stored energy (sigma_k . s_k - D tau_f . sf) / 2.
    tauf_norm = p%tauf_norm
    p%wfric = p%dmg * tauf_norm * p%slip_norm
    p%wdmg = 0.0_dp
    if (p%dmg > o%dmg) then
      p%wdmg = mat%decohesion_energy_factor * (min(max(p%beta, 1.0_dp), mat%beta_break) - &
                                               min(max(o%beta, 1.0_dp), mat%beta_break))
      p%wdmg = p%wdmg - 0.5_dp * tauf_norm**2 * mat%inv_kt * (p%dmg - o%dmg)
    end if
    work = p%sig_loc(1) * p%sl(1) + p%sig_loc(2) * p%sl(2) + p%sig_loc(3) * p%sl(3) - &
           p%dmg * (p%tauf(1) * p%sf(1) + p%tauf(2) * p%sf(2))
    p%psi = 0.5_dp * work
  end subroutine plane_traction_3d

end module interlock_plane_law_3d
