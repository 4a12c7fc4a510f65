!> The state of one material point: per microplane (damage, history variable, frictional slip,
!> frictional work, inclination, friction traction) and the point's relative displacement,
!> traction and energies at the end of the last update.
module interlock_state
  use interlock_kinds, only: dp
  use interlock_material, only: interlock_material_t, max_planes
  implicit none
  private
  public :: interlock_state_t, interlock_state_init, interlock_state_3d_t, interlock_state_3d_init
  public :: state_take, state_3d_take, state_3d_end_point

  !> The per-plane values have no default value (interlock_state_init sets every one, the
  !> update every one of the material's planes), so that a state declared on every call, the
  !> UMAT's, is not filled twice; the values of planes beyond the material's n_planes are
  !> defined only by interlock_state_init.
  type :: interlock_state_t
    real(dp), dimension(max_planes) :: damage  !< D_k [-]
    real(dp), dimension(max_planes) :: beta    !< history max of equivalent displacement [-]
    real(dp), dimension(max_planes) :: sf      !< frictional slip [mm]
    real(dp), dimension(max_planes) :: zeta    !< frictional work [N/mm]
    real(dp), dimension(max_planes) :: theta   !< inclination [rad]
    real(dp), dimension(max_planes) :: tauf    !< friction traction K_t (s_kt - sf_k) [MPa]
    real(dp) :: s(2) = 0.0_dp       !< relative displacement (normal, tangential) [mm]
    real(dp) :: sigma(2) = 0.0_dp   !< traction (normal, tangential) [MPa]
    real(dp) :: work = 0.0_dp            !< work done on the interface [N/mm]
    real(dp) :: stored = 0.0_dp          !< stored (free) energy [N/mm]
    real(dp) :: diss_damage = 0.0_dp     !< damage dissipation [N/mm]
    real(dp) :: diss_friction = 0.0_dp   !< friction dissipation [N/mm]
  end type interlock_state_t

  !> The state of a point of a three-dimensional interface (SPEC section 9): the components
  !> of the 2D state are the normal and the first in-plane direction t1 (each plane's dip
  !> components: sf and tauf along e_k), those below the strike components (along q_k) and the
  !> second in-plane direction t2; the energies are the 2D state's, over all three.
  type, extends(interlock_state_t) :: interlock_state_3d_t
    real(dp), dimension(max_planes) :: sf_strike    !< frictional slip along the strike [mm]
    real(dp), dimension(max_planes) :: tauf_strike  !< friction traction along the strike [MPa]
    real(dp) :: s_t2 = 0.0_dp       !< relative displacement along t2 [mm]
    real(dp) :: sigma_t2 = 0.0_dp   !< traction along t2 [MPa]
  end type interlock_state_3d_t

contains

  !> The virgin state (SPEC section 3); pre-fractured: D = 1, beta = 1/(1 - eta).
  pure subroutine interlock_state_init(mat, state)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_state_t), intent(out) :: state
    state%damage = 0.0_dp
    state%beta = 0.0_dp
    state%sf = 0.0_dp
    state%zeta = 0.0_dp
    state%theta = mat%theta_init
    state%tauf = 0.0_dp
    if (mat%prefractured) then
      state%damage(1:mat%n_planes) = 1.0_dp
      state%beta(1:mat%n_planes) = mat%beta_break
    end if
  end subroutine interlock_state_init

  !> The virgin or pre-fractured state of a three-dimensional point (the strike components 0).
  pure subroutine interlock_state_3d_init(mat, state)
    type(interlock_material_t), intent(in) :: mat
    type(interlock_state_3d_t), intent(out) :: state
    call interlock_state_init(mat, state%interlock_state_t)
    state%sf_strike = 0.0_dp
    state%tauf_strike = 0.0_dp
  end subroutine interlock_state_3d_init

  !> `to` = `from` in every value but those of the planes beyond n, which stay `to`'s (an update
  !> defines the values of the material's planes alone).
  pure subroutine state_take(n, from, to)
    integer, intent(in) :: n
    type(interlock_state_t), intent(in) :: from
    type(interlock_state_t), intent(inout) :: to
    integer :: k
    do k = 1, n
      to%damage(k) = from%damage(k)
      to%beta(k) = from%beta(k)
      to%sf(k) = from%sf(k)
      to%zeta(k) = from%zeta(k)
      to%theta(k) = from%theta(k)
      to%tauf(k) = from%tauf(k)
    end do
    to%s = from%s
    to%sigma = from%sigma
    to%work = from%work
    to%stored = from%stored
    to%diss_damage = from%diss_damage
    to%diss_friction = from%diss_friction
  end subroutine state_take

  !> state_take of a three-dimensional point.
  pure subroutine state_3d_take(n, from, to)
    integer, intent(in) :: n
    type(interlock_state_3d_t), intent(in) :: from
    type(interlock_state_3d_t), intent(inout) :: to
    integer :: k
    call state_take(n, from%interlock_state_t, to%interlock_state_t)
    do k = 1, n
      to%sf_strike(k) = from%sf_strike(k)
      to%tauf_strike(k) = from%tauf_strike(k)
    end do
    to%s_t2 = from%s_t2
    to%sigma_t2 = from%sigma_t2
  end subroutine state_3d_take

  !> The end point of a three-dimensional step from `old` to the separation s with traction
  !> sigma into `new`: s, sigma and the work, old's plus the trapezoidal sum of sigma . ds.
  pure subroutine state_3d_end_point(old, s, sigma, new)
    type(interlock_state_3d_t), intent(in) :: old
    real(dp), intent(in) :: s(3), sigma(3)
    type(interlock_state_3d_t), intent(inout) :: new
    real(dp) :: s_o(3), sigma_o(3)
    s_o = [old%s(1), old%s(2), old%s_t2]
    sigma_o = [old%sigma(1), old%sigma(2), old%sigma_t2]
    new%s = s(1:2)
    new%s_t2 = s(3)
    new%sigma = sigma(1:2)
    new%sigma_t2 = sigma(3)
    new%work = old%work + 0.5_dp * dot_product(sigma_o + sigma, s - s_o)
  end subroutine state_3d_end_point

end module interlock_state
