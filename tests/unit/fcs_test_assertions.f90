!> A tiny assertion module for the unit tests: each check prints a line on failure, and
!> `report` prints "N passed, N failed" and stops with status 1 if anything failed.
module fcs_test_assertions
  use, intrinsic :: iso_fortran_env, only: output_unit
  use fcs_kinds, only: dp
  implicit none
  private
  public :: test_suite_t

  type :: test_suite_t
    character(len=:), allocatable :: name
    integer :: passed = 0
    integer :: failed = 0
  contains
    procedure :: check => suite_check
    procedure :: close_to => suite_close_to
    procedure :: close_array => suite_close_array
    procedure :: equal_int => suite_equal_int
    procedure :: report => suite_report
  end type test_suite_t

contains

  subroutine suite_check(this, condition, what)
    class(test_suite_t), intent(inout) :: this
    logical, intent(in) :: condition
    character(len=*), intent(in) :: what
    if (condition) then
      this%passed = this%passed + 1
    else
      this%failed = this%failed + 1
      write (output_unit, '(a)') '  FAIL ' // this%name // ': ' // what
    end if
  end subroutine suite_check

  !> |actual - expected| <= tolerance * max(|expected|, floor): relative, with an absolute floor.
  subroutine suite_close_to(this, actual, expected, tolerance, what, floor)
    class(test_suite_t), intent(inout) :: this
    real(dp), intent(in) :: actual, expected, tolerance
    character(len=*), intent(in) :: what
    real(dp), intent(in), optional :: floor
    real(dp) :: scale
    character(len=200) :: detail
    scale = abs(expected)
    if (present(floor)) scale = max(scale, floor)
    if (scale == 0.0_dp) scale = 1.0_dp
    if (abs(actual - expected) <= tolerance * scale .and. actual == actual) then
      this%passed = this%passed + 1
    else
      this%failed = this%failed + 1
      write (detail, '(a,es24.16,a,es24.16,a,es10.3)') 'got ', actual, ' expected ', expected, &
        ' rel.err ', abs(actual - expected) / scale
      write (output_unit, '(a)') '  FAIL ' // this%name // ': ' // what // ': ' // trim(detail)
    end if
  end subroutine suite_close_to

  !> Element-wise relative comparison, relative to the largest |expected|.
  subroutine suite_close_array(this, actual, expected, tolerance, what)
    class(test_suite_t), intent(inout) :: this
    real(dp), intent(in) :: actual(:), expected(:), tolerance
    character(len=*), intent(in) :: what
    real(dp) :: scale, worst
    character(len=120) :: detail
    scale = max(maxval(abs(expected)), tiny(1.0_dp))
    worst = maxval(abs(actual - expected)) / scale
    if (size(actual) == size(expected) .and. worst <= tolerance .and. all(actual == actual)) then
      this%passed = this%passed + 1
    else
      this%failed = this%failed + 1
      write (detail, '(a,es10.3)') 'max rel.err ', worst
      write (output_unit, '(a)') '  FAIL ' // this%name // ': ' // what // ': ' // trim(detail)
    end if
  end subroutine suite_close_array

  subroutine suite_equal_int(this, actual, expected, what)
    class(test_suite_t), intent(inout) :: this
    integer, intent(in) :: actual, expected
    character(len=*), intent(in) :: what
    character(len=80) :: detail
    if (actual == expected) then
      this%passed = this%passed + 1
    else
      this%failed = this%failed + 1
      write (detail, '(a,i0,a,i0)') 'got ', actual, ' expected ', expected
      write (output_unit, '(a)') '  FAIL ' // this%name // ': ' // what // ': ' // trim(detail)
    end if
  end subroutine suite_equal_int

  !> Print the summary; stop with status 1 if any check failed.
  subroutine suite_report(this)
    class(test_suite_t), intent(inout) :: this
    write (output_unit, '(a,i0,a,i0,a)') this%name // ': ', this%passed, ' passed, ', &
      this%failed, ' failed'
    if (this%failed > 0) error stop 1
  end subroutine suite_report

end module fcs_test_assertions
