!> A test operator for the fcs_gmres unit test: a diagonal matrix or the cyclic shift, with the
!> identity or the exact inverse of the diagonal as the preconditioner.
module fcs_test_krylov_operators
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_gmres, only: krylov_operator_t
  implicit none
  private
  public :: test_operator_t

  !> y = diag(d) x, or y = Z x (cyclic shift) when `shift`; preconditioner identity, or the
  !> exact inverse of the diagonal when `exact`.
  type, extends(krylov_operator_t) :: test_operator_t
    real(dp), allocatable :: d(:)
    logical :: shift = .false.
    logical :: exact = .false.
  contains
    procedure :: apply => test_apply
    procedure :: precondition => test_precondition
  end type test_operator_t

contains

  subroutine test_apply(this, x, y)
    class(test_operator_t), intent(inout) :: this
    real(dp), intent(in) :: x(:)
    real(dp), intent(out) :: y(:)
    if (this%shift) then
      y = cshift(x, -1)
    else
      y = this%d * x
    end if
  end subroutine test_apply

  subroutine test_precondition(this, v, z, err)
    class(test_operator_t), intent(inout) :: this
    real(dp), intent(in) :: v(:)
    real(dp), intent(out) :: z(:)
    type(error_t), allocatable, intent(out) :: err
    if (this%exact) then
      z = v / this%d
    else
      z = v
    end if
  end subroutine test_precondition

end module fcs_test_krylov_operators
