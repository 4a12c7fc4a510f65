!> The law of one microplane of a three-dimensional interface over one step (SPEC section 9):
!> the plane's frame (m, e, q) from its inclination theta and azimuth phi, the local separation
!> (s_kn, s_kt1, s_kt2), isotropic damage in the microplane (eq. 9-11 with |s_kt|), Coulomb
!> friction on the damaged part by radial return (or D14's mean-direction rule), the traction of eq. 6 with a tangential
!> 2-vector, rotated back to the macro frame (n, t1, t2), and what the schemes' wear drivers and
!> the energy bookkeeping need (the slip in the dip direction, the frictional work, the damage
!> dissipation, the stored energy). In numbers that carry their derivatives (interlock_dual), so
!> that the update returns the exact derivative of what it computes. Every operation is the one
!> of the 2D law (interlock_plane_law) in the same order where the strike components vanish: with
!> phi = 0 and s_T2 = 0 both give the same values.
module interlock_plane_law_3d_dual
  use interlock_kinds, only: dp
  use interlock_dual, only: dual_t, constant, operator(+), operator(-), operator(*), &
      operator(/), sqrt, exp, cos, sin, abs, max, min
  use interlock_material, only: interlock_material_t
  use interlock_plane_law_3d, only: slides_at_start
  implicit none
  private
  public :: plane_dual_t, plane_response_3d_t, plane_law_3d, plane_angle_frame, worn_angle_3d, &
            start_pressure_3d

  !> One plane's state (SPEC section 9: D, beta, sf(2), zeta, theta, tauf(2); vectors in the
  !> plane's (e, q) frame), with its derivatives.
  type :: plane_dual_t
    type(dual_t) :: beta, dmg, sf(2), zeta, theta, tauf(2)
  end type plane_dual_t

  !> One plane at the end of the step, from its start state: the end state's damage, history,
  !> slip and friction traction, the traction in the macro frame (n, t1, t2), unweighted, and
  !> the wear drivers in the dip direction.
  type :: plane_response_3d_t
    type(dual_t) :: beta, dmg, sf(2), tauf(2)
    type(dual_t) :: sig(3)        !< the plane's traction in the macro frame [MPa]
    type(dual_t) :: slip_dip      !< |sf_1 - sf_o,1|, the slip of the step along the dip [mm]
    !> |sf_1 - sf_o,1| / |sf - sf_o|: the dip share of the step's slip direction (1 without slip)
    type(dual_t) :: dip_share
    type(dual_t) :: wfric_dip     !< D |tau_f,1| |d sf_1|, the work that wears [N/mm]
    !> The trapezoidal scheme's wear terms (SPEC section 9 with D14): the slip of the step
    !> |d sf| times the squared dip component of the slip direction at the start, and
    !> D |tau_f,1| |d sf| |n_1| with the direction n at the end. Along a straight local path
    !> (radial return: one direction for the step) |d sf_1| times the direction's dip share
    !> and wfric_dip.
    type(dual_t) :: wear_start, wear_end
    real(dp) :: wfric   !< frictional work on the damaged part, D |tau_f| |d sf| [N/mm]
    real(dp) :: wdmg    !< energy dissipated by damage in the step [N/mm]
    real(dp) :: psi     !< stored energy at the end of the step [N/mm]
  end type plane_response_3d_t

contains

  !> cos and sin of plane k's inclination theta: while unworn (theta = theta_0 to the bit) the
  !> material's values, as the 2D law takes them.
  pure subroutine plane_angle_frame(mat, k, theta, c, sn)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    type(dual_t), intent(in) :: theta
    type(dual_t), intent(out) :: c, sn
    if (theta%v >= mat%theta_init(k) .and. theta%v <= mat%theta_init(k)) then
      c%v = mat%cos0(k)
      c%d = -mat%sin0(k) * theta%d
      sn%v = mat%sin0(k)
      sn%d = mat%cos0(k) * theta%d
    else
      c = cos(theta)
      sn = sin(theta)
    end if
  end subroutine plane_angle_frame

  !> theta(zeta) of a wearing plane k (eq. 22).
  elemental type(dual_t) function worn_angle_3d(mat, k, zeta) result(theta)
    type(interlock_material_t), intent(in) :: mat
    integer, intent(in) :: k
    type(dual_t), intent(in) :: zeta
    theta = (mat%theta_init(k) - mat%thetaf_eff(k)) * exp((-zeta) * mat%inv_zeta0(k)) + &
            mat%thetaf_eff(k)
  end function worn_angle_3d

  !> mu p of the start state on a plane of azimuth frame (cp, sp) at its start angle (frame c,
  !> sn), s_o the start
  !> separation; 0 when the start state is separated (decision D7): the trapezoidal scheme's
  !> start value.
  pure type(dual_t) function start_pressure_3d(mat, cp, sp, c, sn, s_o) result(mu_p)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: cp, sp
    type(dual_t), intent(in) :: c, sn, s_o(3)
    type(dual_t) :: dip
    mu_p = constant(0.0_dp)
    if (s_o(1)%v * mat%inv_h_n < 1.0_dp) then
      dip = cp * s_o(2) + sp * s_o(3)
      ! (max takes its first argument at a tie: at s_kn = 0 the closed side's derivative,
      ! SPEC D13)
      mu_p = mat%mu_eff * mat%kn * max(-normal_separation(c, sn, s_o(1), dip), 0.0_dp)
    end if
  end function start_pressure_3d

  !> s_kn = c s_N + sn s_dip, its value 0 within its round-off 8 eps (|c s_N| + |sn s_dip|): a
  !> path in the plane's surface gives 0 or +-1e-17 from one step to the next, all of them the
  !> tie s_kn = 0 whose derivatives are the closed side's (SPEC D13).
  pure type(dual_t) function normal_separation(c, sn, s_n, dip) result(sl_n)
    type(dual_t), intent(in) :: c, sn, s_n, dip
    sl_n = c * s_n + sn * dip
    if (abs(sl_n%v) <= 8.0_dp * epsilon(1.0_dp) * (abs(c%v * s_n%v) + abs(sn%v * dip%v))) &
      sl_n%v = 0.0_dp
  end function normal_separation

  !> A plane of azimuth frame (cp, sp) = (cos, sin)(phi) at angle theta (frame c, sn) from the
  !> start state o to the macro separation s (SPEC section 9, one step, points 2-6 and the
  !> energies).
  !> mu_p_o: the start state's mu p (start_pressure_3d) where the slip direction follows D14's
  !> mean-direction rule (the trapezoidal scheme), 0 for radial return alone.
  pure subroutine plane_law_3d(mat, cp, sp, c, sn, s, o, mu_p_o, p)
    type(interlock_material_t), intent(in) :: mat
    real(dp), intent(in) :: cp, sp
    type(dual_t), intent(in) :: c, sn, s(3), mu_p_o
    type(plane_dual_t), intent(in) :: o
    type(plane_response_3d_t), intent(out) :: p
    type(dual_t) :: dip, sl_n, sl_t(2), pos, an, at, beq2, beq, mu_p, tr(2), tr_norm, dsf(2), &
                    slip_norm, kpos, sig_n, sig_t(2), sig_dip, atau_dip, n_new(2), n_o(2)
    real(dp) :: work, tauf_norm
    logical :: closed_at_zero, mean_direction

    ! Kinematics: the separation's component along the dip direction d = cos(phi) t1 +
    ! sin(phi) t2, then m = cos(theta) n + sin(theta) d, e = -sin(theta) n + cos(theta) d and
    ! the strike q = -sin(phi) t1 + cos(phi) t2.
    dip = cp * s(2) + sp * s(3)
    sl_n = normal_separation(c, sn, s(1), dip)
    sl_t(1) = -(sn * s(1)) + c * dip
    sl_t(2) = -(sp * s(2)) + cp * s(3)

    ! Damage, isotropic in the microplane: beta_eq from <s_kn>_+ and |s_kt|.
    pos = max(0.0_dp, sl_n)
    p%beta = o%beta
    if (mat%use_damage) then
      p%dmg = o%dmg
      an = pos * mat%inv_s0n
      at = sqrt(sl_t(1) * sl_t(1) + sl_t(2) * sl_t(2)) * mat%inv_s0t
      beq2 = an * an + at * at
      if (beq2%v > o%beta%v * o%beta%v) then
        beq = sqrt(beq2)
        if (beq%v > o%beta%v) then
          p%beta = beq
          if (beq%v >= mat%beta_break) then
            p%dmg = constant(1.0_dp)
          else if (beq%v > 1.0_dp) then
            p%dmg = (beq - 1.0_dp) / (mat%eta * beq)
          else
            p%dmg = constant(0.0_dp)
          end if
        end if
      end if
    else
      p%dmg = constant(mat%d_frozen)
    end if

    ! Friction on the damaged part, radial return to |tau_f| = mu p (p = K_n <-s_kn>_+);
    ! free (sf = s_kt, tau_f = 0) on an open plane or without friction. At s_kn = 0 exactly
    ! mu p carries the closed side's derivative (SPEC D13: min takes its first argument at a
    ! tie).
    mu_p = constant(0.0_dp)
    if (mat%use_friction) mu_p = -mat%mu_eff * mat%kn * min(sl_n, 0.0_dp)
    p%dip_share = constant(1.0_dp)
    closed_at_zero = .false.
    mean_direction = .false.
    if (mu_p%v > 0.0_dp) then
      tr(1) = mat%kt * (sl_t(1) - o%sf(1))
      tr(2) = mat%kt * (sl_t(2) - o%sf(2))
      tr_norm = vector_norm(tr)
      if (tr_norm%v <= mu_p%v) then
        p%sf = o%sf
        p%tauf = tr
        p%slip_dip = constant(0.0_dp)
        slip_norm = constant(0.0_dp)
      else
        if (mu_p_o%v > 0.0_dp) call mean_direction_return(o%tauf, mu_p_o%v, tr, mu_p, &
                                                          mean_direction, n_o, n_new)
        if (mean_direction) then
          ! D14: the slip increment along the mean of the start and end directions, |tau_f| =
          ! mu p along n_new; the slip of the step is what the trial traction exceeds it by.
          p%tauf(1) = mu_p * n_new(1)
          p%tauf(2) = mu_p * n_new(2)
          dsf(1) = (tr(1) - p%tauf(1)) * mat%inv_kt
          dsf(2) = (tr(2) - p%tauf(2)) * mat%inv_kt
          p%sf(1) = sl_t(1) - p%tauf(1) * mat%inv_kt
          p%sf(2) = sl_t(2) - p%tauf(2) * mat%inv_kt
          slip_norm = vector_norm(dsf)
          p%slip_dip = abs(dsf(1))
          ! the flow is along the friction traction: the wear rate D mu p n_1^2 |d sf| / dt
          ! at the start and at the end of the step, for the trapezoidal rule
          p%wear_start = slip_norm * (n_o(1) * n_o(1))
          p%wear_end = p%dmg * abs(p%tauf(1)) * (slip_norm * abs(n_new(1)))
        else
          ! sf - sf_o = n (|tau_tr| - mu p) / K_t along n = tau_tr / |tau_tr|
          p%tauf(1) = mu_p * (tr(1) / tr_norm)
          p%tauf(2) = mu_p * (tr(2) / tr_norm)
          p%sf(1) = sl_t(1) - p%tauf(1) * mat%inv_kt
          p%sf(2) = sl_t(2) - p%tauf(2) * mat%inv_kt
          slip_norm = (tr_norm - mu_p) * mat%inv_kt
          p%slip_dip = abs(tr(1) / tr_norm) * slip_norm
        end if
      end if
    else
      p%sf = sl_t
      p%tauf(1) = constant(0.0_dp)
      p%tauf(2) = constant(0.0_dp)
      dsf(1) = p%sf(1) - o%sf(1)
      dsf(2) = p%sf(2) - o%sf(2)
      p%slip_dip = abs(dsf(1))
      slip_norm = vector_norm(dsf)
      if (mat%use_friction .and. .not. sl_n%v > 0.0_dp) then
        ! s_kn = 0 exactly: in contact for every derivative (SPEC D13). The values are the
        ! free plane's, the same as the slide's with mu p = 0 (tau_f = 0, sf = s_kt); the
        ! derivatives are the slide's: d tau_f = d(mu p) n, the slip shortened by d(mu p) / K_t
        ! along n. At the cone's apex (|tau_tr| = 0) a kink where they stay 0.
        tr(1) = mat%kt * (sl_t(1) - o%sf(1))
        tr(2) = mat%kt * (sl_t(2) - o%sf(2))
        tr_norm = vector_norm(tr)
        if (tr_norm%v > 0.0_dp .and. mu_p_o%v > 0.0_dp) &
          call mean_direction_return(o%tauf, mu_p_o%v, tr, mu_p, mean_direction, n_o, n_new)
        if (mean_direction) then
          ! and D14's direction where the plane slid at the start (the trapezoidal scheme):
          ! the slip (tau_tr - mu p n_new) / K_t, its values the free plane's
          p%tauf(1) = mu_p * n_new(1)
          p%tauf(2) = mu_p * n_new(2)
          p%tauf(1)%v = 0.0_dp
          p%tauf(2)%v = 0.0_dp
          p%sf(1) = sl_t(1) - p%tauf(1) * mat%inv_kt
          p%sf(2) = sl_t(2) - p%tauf(2) * mat%inv_kt
          dsf(1) = (tr(1) - p%tauf(1)) * mat%inv_kt
          dsf(2) = (tr(2) - p%tauf(2)) * mat%inv_kt
          tr_norm = slip_norm
          slip_norm = vector_norm(dsf)
          slip_norm%v = tr_norm%v
          tr_norm = p%slip_dip
          p%slip_dip = abs(dsf(1))
          p%slip_dip%v = tr_norm%v
          atau_dip = mu_p * abs(n_new(1))
          atau_dip%v = 0.0_dp
          p%wear_start = slip_norm * (n_o(1) * n_o(1))
          p%wear_end = p%dmg * atau_dip * (slip_norm * abs(n_new(1)))
          closed_at_zero = .true.
        else if (tr_norm%v > 0.0_dp) then
          atau_dip = mu_p * abs(tr(1) / tr_norm)
          p%tauf(1) = mu_p * (tr(1) / tr_norm)
          p%tauf(2) = mu_p * (tr(2) / tr_norm)
          p%tauf(1)%v = 0.0_dp
          p%tauf(2)%v = 0.0_dp
          p%sf(1) = sl_t(1) - p%tauf(1) * mat%inv_kt
          p%sf(2) = sl_t(2) - p%tauf(2) * mat%inv_kt
          slip_norm = slip_norm - mu_p * mat%inv_kt
          p%slip_dip = p%slip_dip - atau_dip * mat%inv_kt
          atau_dip%v = 0.0_dp
          closed_at_zero = .true.
        end if
      end if
    end if
    if (slip_norm%v > 0.0_dp) p%dip_share = p%slip_dip / slip_norm
    if (.not. closed_at_zero) atau_dip = abs(p%tauf(1))

    ! The traction (eq. 6) in the plane's frame and back in the macro one.
    kpos = mat%kn * pos
    sig_n = mat%kn * sl_n - p%dmg * kpos
    sig_t(1) = (1.0_dp - p%dmg) * (mat%kt * sl_t(1)) + p%dmg * p%tauf(1)
    sig_t(2) = (1.0_dp - p%dmg) * (mat%kt * sl_t(2)) + p%dmg * p%tauf(2)
    sig_dip = sn * sig_n + c * sig_t(1)
    p%sig(1) = c * sig_n - sn * sig_t(1)
    p%sig(2) = cp * sig_dip - sp * sig_t(2)
    p%sig(3) = sp * sig_dip + cp * sig_t(2)

    ! Energies, as the 2D law's (interlock_plane_law) with vectors: the frictional work on the
    ! damaged part, the damage dissipation Y dD (the elastic part exact, the friction part at
    ! first order), the stored energy (sigma_k . s_k - D tau_f . sf) / 2.
    p%wfric_dip = p%dmg * atau_dip * p%slip_dip
    if (.not. mean_direction) then
      p%wear_start = p%slip_dip * p%dip_share
      p%wear_end = p%wfric_dip
    end if
    tauf_norm = sqrt(p%tauf(1)%v**2 + p%tauf(2)%v**2)
    p%wfric = p%dmg%v * tauf_norm * slip_norm%v
    p%wdmg = 0.0_dp
    if (p%dmg%v > o%dmg%v) then
      p%wdmg = mat%decohesion_energy_factor * (min(max(p%beta%v, 1.0_dp), mat%beta_break) - &
                                               min(max(o%beta%v, 1.0_dp), mat%beta_break))
      p%wdmg = p%wdmg - 0.5_dp * tauf_norm**2 * mat%inv_kt * (p%dmg%v - o%dmg%v)
    end if
    work = sig_n%v * sl_n%v + sig_t(1)%v * sl_t(1)%v + sig_t(2)%v * sl_t(2)%v - &
           p%dmg%v * (p%tauf(1)%v * p%sf(1)%v + p%tauf(2)%v * p%sf(2)%v)
    p%psi = 0.5_dp * work
  end subroutine plane_law_3d

  !> D14's slip direction of a plane that slides over the whole step (SPEC decision D14): with
  !> the start direction n_o = tauf_o / |tauf_o| and the trial traction tau_tr, the slip
  !> increment along the mean direction (n_o + n_new) / |n_o + n_new| and tau_f = mu p n_new
  !> make tau_tr - mu p n_new parallel to that mean, which is then the direction of
  !> v = tau_tr + mu p n_o; n_new is n_o turned by twice v's angle from n_o. In n_o's frame,
  !> v = (a, b) with a = tau_tr . n_o + mu p, b = n_o x tau_tr: n_new = ((a^2 - b^2) n_o +
  !> 2 a b n_o') / (a^2 + b^2), n_o' = n_o turned by +90 deg; closed form, no iteration (with
  !> b = 0, as in every 2D step, n_new = n_o to the bit), and the slip |tau_tr - mu p n_new| /
  !> K_t = (|tau_tr|^2 - (mu p)^2) / (K_t |v|) >= 0 exactly where the plane slides at the end.
  !> Applies (`ok`) where the plane slides at the start (slides_at_start) and the turn
  !> 2 atan(b / a) is at most 90 deg (a >= |b|); else radial return (a reversal turns by
  !> 180 deg). The caller has |tau_tr| > mu p > 0 (sliding at the end).
  pure subroutine mean_direction_return(tauf_o, mu_p_o, tr, mu_p, ok, n_o, n_new)
    type(dual_t), intent(in) :: tauf_o(2), tr(2), mu_p
    real(dp), intent(in) :: mu_p_o
    logical, intent(out) :: ok
    type(dual_t), intent(out) :: n_o(2), n_new(2)
    type(dual_t) :: t_norm, a, b, a2, b2, v2
    real(dp) :: m
    ok = .false.
    t_norm = vector_norm(tauf_o)
    if (.not. slides_at_start(t_norm%v, mu_p_o)) return
    n_o(1) = tauf_o(1) / t_norm
    n_o(2) = tauf_o(2) / t_norm
    a = tr(1) * n_o(1) + tr(2) * n_o(2) + mu_p
    b = n_o(1) * tr(2) - n_o(2) * tr(1)
    if (.not. (a%v > 0.0_dp .and. a%v >= abs(b%v))) return
    ok = .true.
    ! n_new depends on the direction of (a, b) only: scaled where the squares would overflow
    ! (a trial traction from a huge admissible slip, as vector_norm)
    m = max(abs(a%v), abs(b%v))
    if (m >= 1.0e150_dp) then
      a = a / m
      b = b / m
    end if
    a2 = a * a
    b2 = b * b
    v2 = a2 + b2
    n_new(1) = ((a2 - b2) * n_o(1) - (2.0_dp * a * b) * n_o(2)) / v2
    n_new(2) = ((a2 - b2) * n_o(2) + (2.0_dp * a * b) * n_o(1)) / v2
  end subroutine mean_direction_return

  !> |a| of a tangential 2-vector. Its squares are taken as they are while they stay far from
  !> overflow, else scaled by the larger component: an admissible state (a frictional slip of
  !> 1e150 mm) times a stiff interface's K_t gives a trial traction whose square is beyond the
  !> largest number.
  pure type(dual_t) function vector_norm(a) result(r)
    type(dual_t), intent(in) :: a(2)
    type(dual_t) :: b(2)
    real(dp) :: m
    m = max(abs(a(1)%v), abs(a(2)%v))
    if (m < 1.0e150_dp) then
      r = sqrt(a(1) * a(1) + a(2) * a(2))
    else
      b(1) = a(1) / m
      b(2) = a(2) / m
      r = m * sqrt(b(1) * b(1) + b(2) * b(2))
    end if
  end function vector_norm

end module interlock_plane_law_3d_dual
