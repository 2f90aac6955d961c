!> Piecewise-linear hardening curves: a yield stress as a function of the equivalent plastic
!> strain, given as (plastic strain, stress) points as `*PLASTIC`, `*CYCLIC HARDENING` and
!> `*DRUCKER PRAGER HARDENING` read them; linear between the points, constant beyond the last
!> (perfectly plastic), as CalculiX and Abaqus extrapolate.
!>
!> `solve_flow_equation` solves the scalar consistency equation of the return mappings
!> (Simo & Hughes 1998, Box 3.1 step 3; de Souza Neto, Peric & Owen 2008, section 8.3.3)
!> exactly: on each segment of the curves the equation is linear, so the root is found by
!> walking the segments, without iterations or tolerances.
module fcs_hardening_table
  use fcs_kinds, only: dp
  implicit none
  private
  public :: hardening_table_t, constant_table, solve_flow_equation

  !> A curve y(x) through the points (x(i), y(i)), x strictly increasing from 0.
  type :: hardening_table_t
    real(dp), allocatable :: strain(:)
    real(dp), allocatable :: stress(:)
  contains
    procedure :: value => table_value
    procedure :: slope => table_slope
    procedure :: n_points => table_n_points
  end type hardening_table_t

contains

  !> A constant curve y = value (perfect plasticity, or a fixed yield-surface radius).
  pure function constant_table(value) result(table)
    real(dp), intent(in) :: value
    type(hardening_table_t) :: table
    table%strain = [0.0_dp]
    table%stress = [value]
  end function constant_table

  pure integer function table_n_points(this)
    class(hardening_table_t), intent(in) :: this
    table_n_points = 0
    if (allocated(this%strain)) table_n_points = size(this%strain)
  end function table_n_points

  !> y(x): linear interpolation, the end values outside the points.
  pure real(dp) function table_value(this, x) result(y)
    class(hardening_table_t), intent(in) :: this
    real(dp), intent(in) :: x
    integer :: i, n
    n = size(this%strain)
    if (x <= this%strain(1)) then
      y = this%stress(1)
      return
    end if
    do i = 1, n - 1
      if (x < this%strain(i + 1)) then
        y = this%stress(i) + (this%stress(i + 1) - this%stress(i)) * (x - this%strain(i)) / &
            (this%strain(i + 1) - this%strain(i))
        return
      end if
    end do
    y = this%stress(n)
  end function table_value

  !> dy/dx ahead of x (the slope of the segment that x enters as it grows; 0 beyond the last
  !> point): the hardening modulus of continued loading.
  pure real(dp) function table_slope(this, x) result(h)
    class(hardening_table_t), intent(in) :: this
    real(dp), intent(in) :: x
    integer :: i
    h = 0.0_dp
    do i = 1, size(this%strain) - 1
      if (x < this%strain(i + 1)) then
        h = (this%stress(i + 1) - this%stress(i)) / (this%strain(i + 1) - this%strain(i))
        return
      end if
    end do
  end function table_slope

  !> The smallest x >= x0 with  g(x) = a - b (x - x0) - sum_k w_k y_k(x) = 0, given
  !> g(x0) > 0 and b > 0. Between consecutive breakpoints of the curves g is linear, so the
  !> root is that of the first segment on which g reaches 0 (exact to round-off). `slope`
  !> returns sum_k w_k dy_k/dx on that segment (the hardening modulus of the consistent
  !> tangent). `ok` is false when no root exists (cannot happen for b > 0: beyond the last
  !> points the curves are constant).
  pure subroutine solve_flow_equation(a, b, x0, tables, weights, x, slope, ok)
    real(dp), intent(in) :: a, b, x0
    type(hardening_table_t), intent(in) :: tables(:)
    real(dp), intent(in) :: weights(:)
    real(dp), intent(out) :: x, slope
    logical, intent(out) :: ok
    real(dp) :: left, right, g_left, g_right, total
    integer :: k
    ok = .false.
    left = x0
    g_left = g(left)
    slope = 0.0_dp
    if (.not. (b > 0.0_dp)) then
      x = x0
      return
    end if
    do
      right = next_breakpoint(left)
      slope = 0.0_dp
      do k = 1, size(tables)
        slope = slope + weights(k) * tables(k)%slope(left)
      end do
      total = b + slope
      if (right >= huge(1.0_dp)) then
        ! Beyond every point the curves are constant: g falls with slope b.
        x = left + g_left / total
        ok = total > 0.0_dp
        return
      end if
      g_right = g(right)
      if (g_right <= 0.0_dp .and. total > 0.0_dp) then
        x = min(right, left + g_left / total)
        ok = .true.
        return
      end if
      left = right
      g_left = g_right
    end do
  contains
    pure real(dp) function g(y)
      real(dp), intent(in) :: y
      integer :: j
      g = a - b * (y - x0)
      do j = 1, size(tables)
        g = g - weights(j) * tables(j)%value(y)
      end do
    end function g

    !> The first breakpoint of any curve beyond y (huge if none).
    pure real(dp) function next_breakpoint(y) result(z)
      real(dp), intent(in) :: y
      integer :: j, i
      z = huge(1.0_dp)
      do j = 1, size(tables)
        do i = 1, size(tables(j)%strain)
          if (tables(j)%strain(i) > y) then
            z = min(z, tables(j)%strain(i))
            exit
          end if
        end do
      end do
    end function next_breakpoint
  end subroutine solve_flow_equation

end module fcs_hardening_table
