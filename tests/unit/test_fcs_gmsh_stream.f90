!> Unit tests of fcs_gmsh_stream's number parsing: the fast real conversion must give exactly
!> the value of Fortran's own conversion (oracle: list-directed READ, correctly rounded in
!> gfortran/glibc), and malformed numbers must be rejected.
program test_fcs_gmsh_stream
  use fcs_kinds, only: dp, i8
  use fcs_gmsh_stream, only: parse_int8, parse_real_fast, is_finite_bits
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite

  suite%name = 'fcs_gmsh_stream'
  call test_integers(suite)
  call test_reals_against_read(suite)
  call test_bad_reals(suite)
  call test_finite_bits(suite)
  call suite%report()

contains

  subroutine test_integers(suite)
    type(test_suite_t), intent(inout) :: suite
    integer(i8) :: value
    logical :: ok
    call parse_int8('1000000000', value, ok)
    call suite%check(ok .and. value == 1000000000_i8, 'int 1000000000')
    call parse_int8('-42', value, ok)
    call suite%check(ok .and. value == -42_i8, 'int -42')
    call parse_int8('9223372036854775807', value, ok)
    call suite%check(ok .and. value == huge(value), 'int huge')
    call parse_int8('9223372036854775808', value, ok)
    call suite%check(.not. ok, 'int overflow rejected')
    call parse_int8('12a', value, ok)
    call suite%check(.not. ok, 'int 12a rejected')
    call parse_int8('-', value, ok)
    call suite%check(.not. ok, 'int - rejected')
    call parse_int8('1.0', value, ok)
    call suite%check(.not. ok, 'int 1.0 rejected')
  end subroutine test_integers

  !> Typical gmsh output (%.16g) and random decimal texts: bitwise equal to READ.
  subroutine test_reals_against_read(suite)
    type(test_suite_t), intent(inout) :: suite
    character(len=*), parameter :: SAMPLES(12) = [character(len=24) :: '0', '-0', '10', &
      '0.499999999999551', '9.49999999999924', '-9.999999994736442e-08', '1e-07', &
      '2.000000000000716', '1.0000001', '0.9999999000000001', '123456789012345678', '.5']
    integer :: i, mismatches
    real(dp) :: r, value, expected
    logical :: ok
    character(len=60) :: text
    do i = 1, size(SAMPLES)
      mismatches = 0
      call check_one(trim(SAMPLES(i)), mismatches)
      call suite%check(mismatches == 0, 'real "' // trim(SAMPLES(i)) // '" as READ gives it')
    end do
    mismatches = 0
    do i = 1, 20000
      call random_number(r)
      value = (r - 0.5_dp) * 10.0_dp**(int(40 * r) - 20)
      select case (mod(i, 3))
      case (0)
        write (text, '(es24.16e3)') value
      case (1)
        write (text, '(g0)') value
      case default
        write (text, '(f0.12)') value
      end select
      call check_one(trim(adjustl(text)), mismatches)
    end do
    call suite%equal_int(mismatches, 0, '20000 random reals as READ gives them')
    call parse_real_fast('1.5E+2', expected, ok)
    call suite%check(ok .and. expected == 150.0_dp, 'real 1.5E+2')
  end subroutine test_reals_against_read

  subroutine check_one(text, mismatches)
    character(len=*), intent(in) :: text
    integer, intent(inout) :: mismatches
    real(dp) :: value, expected
    logical :: ok
    integer :: stat
    call parse_real_fast(text, value, ok)
    read (text, *, iostat=stat) expected
    if (.not. ok .or. stat /= 0) then
      mismatches = mismatches + 1
    else if (value /= expected) then
      mismatches = mismatches + 1
    end if
  end subroutine check_one

  subroutine test_bad_reals(suite)
    type(test_suite_t), intent(inout) :: suite
    character(len=*), parameter :: BAD(10) = [character(len=12) :: '', '.', '-', '1e', '1.2.3', &
      '0.5x', 'nan', 'inf', '1e400', '1,5']
    integer :: i
    real(dp) :: value
    logical :: ok
    do i = 1, size(BAD)
      call parse_real_fast(trim(BAD(i)), value, ok)
      call suite%check(.not. ok, 'real "' // trim(BAD(i)) // '" rejected')
    end do
    call parse_real_fast('1e-400', value, ok)
    call suite%check(ok .and. value == 0.0_dp, 'real 1e-400 is zero')
  end subroutine test_bad_reals

  subroutine test_finite_bits(suite)
    type(test_suite_t), intent(inout) :: suite
    call suite%check(is_finite_bits(huge(1.0_dp)) .and. is_finite_bits(-tiny(1.0_dp)), 'finite bits: finite')
    call suite%check(.not. is_finite_bits(transfer(int(z'7FF0000000000000', i8), 1.0_dp)), 'finite bits: +Inf')
    call suite%check(.not. is_finite_bits(transfer(int(z'7FF4000000000000', i8), 1.0_dp)), 'finite bits: sNaN')
  end subroutine test_finite_bits

end program test_fcs_gmsh_stream
