!> The baseline of the cost benchmark: a minimal bilinear cohesive law (Alfano-Crisfield 2001)
!> as a user would hand-code it. One flat plane, mixed-mode damage with the library's formulas
!> (beta = max of sqrt((<s_N>_+/s_0n)^2 + (s_T/s_0t)^2), D = (beta - 1)/(eta beta) clipped to
!> [0, 1]), no friction, no contact area, traction and the exact tangent. It lives in the
!> benchmark (not in the library) and in its own file, so that the compiler cannot inline it
!> into the timing loop any more than it can inline `interlock_update`.
module interlock_bench_bilinear
  use interlock, only: dp, interlock_material_t
  implicit none
  private
  public :: bilinear_t, bilinear_state_t, bilinear_setup, bilinear_update

  !> Constants of the law, derived once from a prepared material.
  type :: bilinear_t
    real(dp) :: kn = 0.0_dp, kt = 0.0_dp         !< penalty stiffnesses [MPa/mm]
    real(dp) :: inv_s0n = 0.0_dp, inv_s0t = 0.0_dp !< 1/s_0n, 1/s_0t [1/mm]
    real(dp) :: eta = 0.0_dp                      !< ductility parameter [-]
  end type bilinear_t

  !> History of one point: the largest equivalent displacement reached and the damage.
  type :: bilinear_state_t
    real(dp) :: beta = 0.0_dp
    real(dp) :: damage = 0.0_dp
  end type bilinear_state_t

contains

  !> Take the stiffnesses and onset displacements of a prepared material.
  pure subroutine bilinear_setup(mat, law)
    type(interlock_material_t), intent(in) :: mat
    type(bilinear_t), intent(out) :: law
    law%kn = mat%kn
    law%kt = mat%kt
    law%inv_s0n = 1.0_dp / mat%s0n
    law%inv_s0t = 1.0_dp / mat%s0t
    law%eta = mat%eta
  end subroutine bilinear_setup

  !> Traction and tangent d sigma / d s at the end-of-increment separation s = (s_N, s_T).
  pure subroutine bilinear_update(law, s, old, new, sigma, tangent)
    type(bilinear_t), intent(in) :: law
    real(dp), intent(in) :: s(2)
    type(bilinear_state_t), intent(in) :: old
    type(bilinear_state_t), intent(out) :: new
    real(dp), intent(out) :: sigma(2), tangent(2, 2)
    real(dp) :: an, at, beq, d, dd_dbeta, pos, g(2)
    logical :: loading

    pos = max(0.0_dp, s(1))
    an = pos * law%inv_s0n
    at = s(2) * law%inv_s0t
    beq = sqrt(an * an + at * at)
    loading = beq > old%beta
    new%beta = merge(beq, old%beta, loading)
    d = 0.0_dp
    dd_dbeta = 0.0_dp
    if (new%beta > 1.0_dp) then
      d = (new%beta - 1.0_dp) / (law%eta * new%beta)
      if (d >= 1.0_dp) then
        d = 1.0_dp
      else if (loading) then
        dd_dbeta = 1.0_dp / (law%eta * new%beta * new%beta)
      end if
    end if
    new%damage = d

    sigma(1) = law%kn * (s(1) - d * pos)
    sigma(2) = (1.0_dp - d) * law%kt * s(2)
    tangent(1, 1) = merge((1.0_dp - d) * law%kn, law%kn, s(1) > 0.0_dp)
    tangent(2, 1) = 0.0_dp
    tangent(1, 2) = 0.0_dp
    tangent(2, 2) = (1.0_dp - d) * law%kt
    if (dd_dbeta > 0.0_dp) then
      ! Damage loading: dD/ds = dD/dbeta * dbeta/ds (beq > old%beta >= 0 here).
      g = dd_dbeta * [an * law%inv_s0n, at * law%inv_s0t] / beq
      tangent(1, :) = tangent(1, :) - law%kn * pos * g
      tangent(2, :) = tangent(2, :) - law%kt * s(2) * g
    end if
  end subroutine bilinear_update

end module interlock_bench_bilinear
