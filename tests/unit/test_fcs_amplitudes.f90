!> Unit test of the amplitudes of fcs_loading: a tabular amplitude is linear between its points
!> and constant beyond them, and its integral (which drives velocity boundary conditions) is
!> the exact integral of that piecewise-linear function; CalculiX's user amplitude QUADRATIC
!> (`*AMPLITUDE, NAME=QUADRATIC, USER`, ccx's uamplitude.f) is t^2 and its integral t^3/3, in
!> step time or, with TIME=TOTAL TIME, in total time. The integrals are checked against a
!> composite Simpson rule, exact for the quadratic and, piece by piece, for the tabular one.
program test_fcs_amplitudes
  use fcs_kinds, only: dp
  use fcs_model, only: amplitude_t
  use fcs_loading, only: amplitude_value, amplitude_integral
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite
  !> A few operations on numbers of order one: 1e-13 relative.
  real(dp), parameter :: EXACT = 1.0e-13_dp

  suite%name = 'fcs_amplitudes'
  call check_tabular(suite)
  call check_quadratic(suite)
  call suite%report()

contains

  subroutine check_tabular(suite)
    type(test_suite_t), intent(inout) :: suite
    type(amplitude_t) :: a
    a%name = 'A'
    a%time = [0.5_dp, 1.0_dp, 3.0_dp]
    a%value = [1.0_dp, 3.0_dp, 2.0_dp]
    call suite%close_to(amplitude_value(a, 0.2_dp, 0.0_dp), 1.0_dp, EXACT, 'tabular: constant before')
    call suite%close_to(amplitude_value(a, 2.0_dp, 0.0_dp), 2.5_dp, EXACT, 'tabular: linear')
    call suite%close_to(amplitude_value(a, 5.0_dp, 0.0_dp), 2.0_dp, EXACT, 'tabular: constant after')
    call suite%close_to(amplitude_integral(a, 4.0_dp, 0.0_dp), simpson(a, 0.0_dp, 4.0_dp), EXACT, &
                        'tabular: integral')
  end subroutine check_tabular

  subroutine check_quadratic(suite)
    type(test_suite_t), intent(inout) :: suite
    type(amplitude_t) :: a
    a%name = 'QUADRATIC'
    a%quadratic = .true.
    allocate (a%time(0), a%value(0))
    call suite%close_to(amplitude_value(a, 1.5_dp, 0.0_dp), 2.25_dp, EXACT, 'quadratic: t^2')
    call suite%close_to(amplitude_integral(a, 1.5_dp, 0.0_dp), 1.125_dp, EXACT, 'quadratic: t^3/3')
    call suite%close_to(amplitude_integral(a, 2.0_dp, 0.0_dp) - amplitude_integral(a, 0.5_dp, 0.0_dp), &
                        simpson(a, 0.5_dp, 2.0_dp), EXACT, 'quadratic: integral over an increment')
    a%total_time = .true.
    call suite%close_to(amplitude_value(a, 0.5_dp, 2.0_dp), 6.25_dp, EXACT, 'quadratic: total time')
  end subroutine check_quadratic

  !> Composite Simpson rule of a over [t0, t1] on 4000 panels, in pairs whose ends include every point
  !> of the amplitude in (t0, t1) here (0.5, 1, 3 are multiples of the pair width 1/500 for
  !> [0, 4]): exact for each quadratic or linear piece.
  real(dp) function simpson(a, t0, t1) result(total)
    type(amplitude_t), intent(in) :: a
    real(dp), intent(in) :: t0, t1
    integer, parameter :: N = 4000
    real(dp) :: h
    integer :: i
    h = (t1 - t0) / N
    total = 0.0_dp
    do i = 0, N - 2, 2
      total = total + h / 3.0_dp * (amplitude_value(a, t0 + i * h, 0.0_dp) + &
              4.0_dp * amplitude_value(a, t0 + (i + 1) * h, 0.0_dp) + &
              amplitude_value(a, t0 + (i + 2) * h, 0.0_dp))
    end do
  end function simpson
end program test_fcs_amplitudes
