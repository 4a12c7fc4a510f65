!> Numbers that carry their first derivatives (forward-mode automatic differentiation): a value
!> and its gradient with respect to `n_dual` independent variables. The three-dimensional
!> update states the law once, in these numbers, and gets the exact derivative of what it
!> computes, through every branch, the wear equation's root and the chain over sub-increments,
!> without a hand-written derivative of each. Columns 1-3: the end-of-increment separation
!> (s_N, s_T1, s_T2); column 4: the frictional work zeta of the wear equation being solved.
!> Comparisons, max, min and abs act on the value; at a tie they take one side (SPEC section
!> 6: any one-sided derivative at a kink).
module interlock_dual
  use interlock_kinds, only: dp
  implicit none
  private
  public :: dual_t, n_dual, constant, operator(+), operator(-), operator(*), operator(/)
  public :: sqrt, exp, cos, sin, abs, max, min

  integer, parameter :: n_dual = 4

  !> No default values: the law's many intermediate numbers are each set before use, and a
  !> default would clear them all on every entry.
  type :: dual_t
    real(dp) :: v             !< the value
    real(dp) :: d(n_dual)     !< its derivatives
  end type dual_t

  interface operator(+)
    module procedure add_dd, add_dr, add_rd, plus_d
  end interface
  interface operator(-)
    module procedure sub_dd, sub_dr, sub_rd, neg_d
  end interface
  interface operator(*)
    module procedure mul_dd, mul_dr, mul_rd
  end interface
  interface operator(/)
    module procedure div_dd, div_dr, div_rd
  end interface
  interface sqrt
    module procedure sqrt_d
  end interface
  interface exp
    module procedure exp_d
  end interface
  interface cos
    module procedure cos_d
  end interface
  interface sin
    module procedure sin_d
  end interface
  interface abs
    module procedure abs_d
  end interface
  interface max
    module procedure max_dd, max_dr, max_rd
  end interface
  interface min
    module procedure min_dd, min_dr, min_rd
  end interface

contains

  !> A number without derivatives (a constant, or the start of an independent variable whose
  !> derivative column the caller sets).
  elemental type(dual_t) function constant(v) result(r)
    real(dp), intent(in) :: v
    r%v = v
    r%d = 0.0_dp
  end function constant

  elemental type(dual_t) function add_dd(a, b) result(r)
    type(dual_t), intent(in) :: a, b
    r%v = a%v + b%v
    r%d = a%d + b%d
  end function add_dd

  elemental type(dual_t) function add_dr(a, b) result(r)
    type(dual_t), intent(in) :: a
    real(dp), intent(in) :: b
    r%v = a%v + b
    r%d = a%d
  end function add_dr

  elemental type(dual_t) function add_rd(a, b) result(r)
    real(dp), intent(in) :: a
    type(dual_t), intent(in) :: b
    r%v = a + b%v
    r%d = b%d
  end function add_rd

  elemental type(dual_t) function plus_d(a) result(r)
    type(dual_t), intent(in) :: a
    r = a
  end function plus_d

  elemental type(dual_t) function sub_dd(a, b) result(r)
    type(dual_t), intent(in) :: a, b
    r%v = a%v - b%v
    r%d = a%d - b%d
  end function sub_dd

  elemental type(dual_t) function sub_dr(a, b) result(r)
    type(dual_t), intent(in) :: a
    real(dp), intent(in) :: b
    r%v = a%v - b
    r%d = a%d
  end function sub_dr

  elemental type(dual_t) function sub_rd(a, b) result(r)
    real(dp), intent(in) :: a
    type(dual_t), intent(in) :: b
    r%v = a - b%v
    r%d = -b%d
  end function sub_rd

  elemental type(dual_t) function neg_d(a) result(r)
    type(dual_t), intent(in) :: a
    r%v = -a%v
    r%d = -a%d
  end function neg_d

  elemental type(dual_t) function mul_dd(a, b) result(r)
    type(dual_t), intent(in) :: a, b
    r%v = a%v * b%v
    r%d = a%d * b%v + a%v * b%d
  end function mul_dd

  elemental type(dual_t) function mul_dr(a, b) result(r)
    type(dual_t), intent(in) :: a
    real(dp), intent(in) :: b
    r%v = a%v * b
    r%d = a%d * b
  end function mul_dr

  elemental type(dual_t) function mul_rd(a, b) result(r)
    real(dp), intent(in) :: a
    type(dual_t), intent(in) :: b
    r%v = a * b%v
    r%d = a * b%d
  end function mul_rd

  elemental type(dual_t) function div_dd(a, b) result(r)
    type(dual_t), intent(in) :: a, b
    r%v = a%v / b%v
    r%d = (a%d - r%v * b%d) / b%v
  end function div_dd

  elemental type(dual_t) function div_dr(a, b) result(r)
    type(dual_t), intent(in) :: a
    real(dp), intent(in) :: b
    r%v = a%v / b
    r%d = a%d / b
  end function div_dr

  elemental type(dual_t) function div_rd(a, b) result(r)
    real(dp), intent(in) :: a
    type(dual_t), intent(in) :: b
    r%v = a / b%v
    r%d = -(r%v / b%v) * b%d
  end function div_rd

  !> sqrt; at 0 the derivative is taken as 0 (the one-sided choice of a norm at its kink).
  elemental type(dual_t) function sqrt_d(a) result(r)
    type(dual_t), intent(in) :: a
    r%v = sqrt(a%v)
    if (r%v > 0.0_dp) then
      r%d = a%d / (2.0_dp * r%v)
    else
      r%d = 0.0_dp
    end if
  end function sqrt_d

  elemental type(dual_t) function exp_d(a) result(r)
    type(dual_t), intent(in) :: a
    r%v = exp(a%v)
    r%d = r%v * a%d
  end function exp_d

  elemental type(dual_t) function cos_d(a) result(r)
    type(dual_t), intent(in) :: a
    r%v = cos(a%v)
    r%d = -sin(a%v) * a%d
  end function cos_d

  elemental type(dual_t) function sin_d(a) result(r)
    type(dual_t), intent(in) :: a
    r%v = sin(a%v)
    r%d = cos(a%v) * a%d
  end function sin_d

  !> |a|; at 0 the side of a non-negative value.
  elemental type(dual_t) function abs_d(a) result(r)
    type(dual_t), intent(in) :: a
    if (a%v < 0.0_dp) then
      r = neg_d(a)
    else
      r = a
    end if
  end function abs_d

  !> max and min take the first argument at a tie.
  elemental type(dual_t) function max_dd(a, b) result(r)
    type(dual_t), intent(in) :: a, b
    if (b%v > a%v) then
      r = b
    else
      r = a
    end if
  end function max_dd

  elemental type(dual_t) function max_dr(a, b) result(r)
    type(dual_t), intent(in) :: a
    real(dp), intent(in) :: b
    if (b > a%v) then
      r = constant(b)
    else
      r = a
    end if
  end function max_dr

  elemental type(dual_t) function max_rd(a, b) result(r)
    real(dp), intent(in) :: a
    type(dual_t), intent(in) :: b
    if (b%v > a) then
      r = b
    else
      r = constant(a)
    end if
  end function max_rd

  elemental type(dual_t) function min_dd(a, b) result(r)
    type(dual_t), intent(in) :: a, b
    if (b%v < a%v) then
      r = b
    else
      r = a
    end if
  end function min_dd

  elemental type(dual_t) function min_dr(a, b) result(r)
    type(dual_t), intent(in) :: a
    real(dp), intent(in) :: b
    if (b < a%v) then
      r = constant(b)
    else
      r = a
    end if
  end function min_dr

  elemental type(dual_t) function min_rd(a, b) result(r)
    real(dp), intent(in) :: a
    type(dual_t), intent(in) :: b
    if (b%v < a) then
      r = b
    else
      r = constant(a)
    end if
  end function min_rd

end module interlock_dual
