!> A symmetric tangent for hosts that keep only the symmetric part of DDSDDE (CalculiX 2.20
!> averages every user material's tangent, umat_abaqus.f, and has no UNSYMM).
!>
!> The law's exact 2 x 2 tangent D (normal, shear) is unsymmetric once friction acts: on a
!> sliding plane the shear traction follows the normal one through the friction bound, so
!> D21 ~ mu K_n, while the normal traction depends on the slip only through the plane's
!> inclination (D12, small on flat planes). The plain symmetric part (D + D^T)/2 puts half of
!> the friction coupling on both sides and can become indefinite where D is not: a sliding
!> clay-bar point with D = [[161.5, 4.87], [103.7, 3.12]] MPa/mm (eigenvalues 0.0002 and
!> 164.6) becomes [[161.5, 54.3], [54.3, 3.12]], eigenvalues -13.7 and 178.3, and the host's
!> Newton iteration stalls.
!>
!> Here: S = [[D11, c], [c, D22]] with c the SMALLER of the two couplings (by magnitude, with
!> its sign), clipped to |c| <= sqrt(D11 D22); and where D has no eigenvalue with a negative
!> real part (det D >= 0 and trace D >= 0), a negative diagonal entry is raised to 0. So
!>  - S is positive semi-definite wherever D's eigenvalues are >= 0 (never indefinite where
!>    D is not); where D softens (an eigenvalue < 0) the diagonal is kept and S shows it;
!>  - where one coupling dominates (friction), S = D minus that coupling's excess: the Newton
!>    iteration's error matrix I - (S + K_host)^-1 (D + K_host) has rank one and a small
!>    spectral radius when the host's own stiffness K_host is not negligible.
!> The choice is measured against the plain symmetric part, dropping the coupling in
!> compression, the clipped symmetric part and a similarity transform of D (which keeps D's
!> eigenvalues exactly): tests/api/tangent_newton.f90, docs/calculix.md.
!> A three-dimensional tangent (normal, shear 1, shear 2) is treated pair by pair, in the order
!> (N, T1), (N, T2), (T1, T2), each 2 x 2 block by the rule above: with no T2 coupling (a point
!> in the (n, t1) plane of the paper's RIA) the (N, T1) block is the 2D one to the bit. The pairs
!> are PSD one by one; the 3 x 3 matrix is not guaranteed to be.
!> The stress update is not touched: only the matrix handed to the host changes, so the
!> converged answer of the host's iteration is the same; its rate is no longer quadratic.
module interlock_host_tangent
  use interlock_kinds, only: dp
  implicit none
  private
  public :: interlock_symmetric_tangent, interlock_symmetric_tangent_3d

contains

  !> Replace the 2 x 2 tangent (normal, shear) by its symmetric counterpart (see the header).
  pure subroutine interlock_symmetric_tangent(tangent)
    real(dp), intent(inout) :: tangent(2, 2)
    real(dp) :: coupling, bound
    logical :: stable
    stable = tangent(1, 1) * tangent(2, 2) - tangent(1, 2) * tangent(2, 1) >= 0.0_dp .and. &
             tangent(1, 1) + tangent(2, 2) >= 0.0_dp
    if (stable) then
      tangent(1, 1) = max(tangent(1, 1), 0.0_dp)
      tangent(2, 2) = max(tangent(2, 2), 0.0_dp)
    end if
    coupling = tangent(1, 2)
    if (abs(tangent(2, 1)) < abs(coupling)) coupling = tangent(2, 1)
    bound = sqrt(max(tangent(1, 1), 0.0_dp) * max(tangent(2, 2), 0.0_dp))
    coupling = max(-bound, min(bound, coupling))
    tangent(1, 2) = coupling
    tangent(2, 1) = coupling
  end subroutine interlock_symmetric_tangent

  !> Replace the 3 x 3 tangent (normal, shear 1, shear 2) by a symmetric one, pair by pair
  !> (see the header).
  pure subroutine interlock_symmetric_tangent_3d(tangent)
    real(dp), intent(inout) :: tangent(3, 3)
    integer, parameter :: pairs(2, 3) = reshape([1, 2, 1, 3, 2, 3], [2, 3])
    real(dp) :: block(2, 2)
    integer :: p
    do p = 1, 3
      block = tangent(pairs(:, p), pairs(:, p))
      call interlock_symmetric_tangent(block)
      tangent(pairs(:, p), pairs(:, p)) = block
    end do
  end subroutine interlock_symmetric_tangent_3d

end module interlock_host_tangent
