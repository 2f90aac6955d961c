!> Unit test of fcs_gmres on operators whose GMRES behaviour is known in closed form:
!> * a diagonal matrix with k distinct eigenvalues and the identity as preconditioner: the
!>   minimal polynomial has degree k, so the Krylov space is invariant after k steps and GMRES
!>   converges in exactly k iterations (Saad 2003, chapter 6) to x = b / d;
!> * the same with an exact preconditioner (M^-1 = A^-1): one iteration;
!> * restarted GMRES(2) on 4 distinct eigenvalues, all positive: still converges (restarted
!>   GMRES converges when the symmetric part is positive definite, Saad 2003, chapter 6);
!> * the cyclic shift Z (Z e_i = e_(i+1)) with b = e_1: the residual stays |b| for n - 1
!>   iterations (the classic example of complete stagnation; Greenbaum, Ptak & Strakos 1996),
!>   so the rate test must give up early and report it.
program test_fcs_gmres
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_gmres, only: gmres_settings_t, gmres_result_t, gmres_solve, &
                       GMRES_CONVERGED, GMRES_TOO_SLOW, GMRES_ITERATION_LIMIT
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_krylov_operators, only: test_operator_t
  implicit none

  type(test_suite_t) :: suite

  suite%name = 'fcs_gmres'
  call check_distinct_eigenvalues(suite)
  call check_exact_preconditioner(suite)
  call check_restarted(suite)
  call check_stagnation(suite)
  call check_iteration_limit(suite)
  call check_zero_rhs(suite)
  call suite%report()

contains

  !> 12 unknowns, eigenvalues 1, 2 and 5: three iterations, x = b / d to the tolerance.
  subroutine check_distinct_eigenvalues(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_operator_t) :: op
    type(gmres_settings_t) :: settings
    type(gmres_result_t) :: result
    type(error_t), allocatable :: err
    real(dp) :: b(12), x(12)
    integer :: i
    op%d = [(merge(1.0_dp, merge(2.0_dp, 5.0_dp, mod(i, 3) == 1), mod(i, 3) == 0), i = 1, 12)]
    b = [(real(i, dp), i = 1, 12)]
    settings%tolerance = 1.0e-12_dp
    call gmres_solve(op, b, x, settings, result, err)
    call suite%check(.not. allocated(err), 'three eigenvalues: no error')
    call suite%equal_int(result%outcome, GMRES_CONVERGED, 'three eigenvalues: converged')
    call suite%equal_int(result%iterations, 3, 'three eigenvalues: three iterations')
    ! The residual is that of the recomputed b - A x, at most the tolerance; x to 1e-11
    ! relative (condition number 5).
    call suite%check(result%residual_ratio <= 1.0e-12_dp, 'three eigenvalues: residual reported')
    call suite%close_array(x, b / op%d, 1.0e-11_dp, 'three eigenvalues: x = b / d')
  end subroutine check_distinct_eigenvalues

  !> M^-1 = A^-1: one iteration, exact to round-off.
  subroutine check_exact_preconditioner(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_operator_t) :: op
    type(gmres_settings_t) :: settings
    type(gmres_result_t) :: result
    type(error_t), allocatable :: err
    real(dp) :: b(7), x(7)
    integer :: i
    op%d = [(1.0_dp + real(i, dp)**2, i = 1, 7)]
    op%exact = .true.
    b = [(real(8 - i, dp), i = 1, 7)]
    call gmres_solve(op, b, x, settings, result, err)
    call suite%equal_int(result%outcome, GMRES_CONVERGED, 'exact preconditioner: converged')
    call suite%equal_int(result%iterations, 1, 'exact preconditioner: one iteration')
    call suite%close_array(x, b / op%d, 1.0e-14_dp, 'exact preconditioner: x = b / d')
  end subroutine check_exact_preconditioner

  !> GMRES(2) on eigenvalues 1, 1.5, 2, 3: converges across restarts.
  subroutine check_restarted(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_operator_t) :: op
    type(gmres_settings_t) :: settings
    type(gmres_result_t) :: result
    type(error_t), allocatable :: err
    real(dp), parameter :: values(4) = [1.0_dp, 1.5_dp, 2.0_dp, 3.0_dp]
    real(dp) :: b(16), x(16)
    integer :: i
    op%d = [(values(mod(i, 4) + 1), i = 1, 16)]
    b = 1.0_dp
    settings%restart = 2
    settings%max_iterations = 60
    settings%tolerance = 1.0e-10_dp
    call gmres_solve(op, b, x, settings, result, err)
    call suite%equal_int(result%outcome, GMRES_CONVERGED, 'GMRES(2): converged')
    call suite%check(result%iterations > 4 .and. result%iterations <= 60, &
                     'GMRES(2): more than the 4 iterations of full GMRES, within the limit')
    call suite%close_array(x, b / op%d, 1.0e-9_dp, 'GMRES(2): x = b / d')
  end subroutine check_restarted

  !> The cyclic shift with b = e_1: no progress at all; given up at the first rate check.
  subroutine check_stagnation(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_operator_t) :: op
    type(gmres_settings_t) :: settings
    type(gmres_result_t) :: result
    type(error_t), allocatable :: err
    real(dp) :: b(30), x(30)
    op%shift = .true.
    allocate (op%d(30))
    b = 0.0_dp
    b(1) = 1.0_dp
    settings%max_iterations = 25
    settings%restart = 25
    settings%rate_check_from = 3
    call gmres_solve(op, b, x, settings, result, err)
    call suite%equal_int(result%outcome, GMRES_TOO_SLOW, 'cyclic shift: given up as too slow')
    call suite%equal_int(result%iterations, 3, 'cyclic shift: at the first rate check')
    call suite%close_to(result%residual_ratio, 1.0_dp, 1.0e-14_dp, 'cyclic shift: residual |b|')
  end subroutine check_stagnation

  !> Without the rate test, the cyclic shift runs into the iteration limit.
  subroutine check_iteration_limit(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_operator_t) :: op
    type(gmres_settings_t) :: settings
    type(gmres_result_t) :: result
    type(error_t), allocatable :: err
    real(dp) :: b(30), x(30)
    op%shift = .true.
    allocate (op%d(30))
    b = 0.0_dp
    b(1) = 1.0_dp
    settings%max_iterations = 12
    settings%restart = 5
    settings%rate_check_from = huge(1)
    call gmres_solve(op, b, x, settings, result, err)
    call suite%equal_int(result%outcome, GMRES_ITERATION_LIMIT, 'cyclic shift: iteration limit')
    call suite%equal_int(result%iterations, 12, 'cyclic shift: 12 iterations')
  end subroutine check_iteration_limit

  !> b = 0: x = 0 at once.
  subroutine check_zero_rhs(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_operator_t) :: op
    type(gmres_settings_t) :: settings
    type(gmres_result_t) :: result
    type(error_t), allocatable :: err
    real(dp) :: b(5), x(5)
    op%d = [1.0_dp, 2.0_dp, 3.0_dp, 4.0_dp, 5.0_dp]
    b = 0.0_dp
    x = 1.0_dp
    call gmres_solve(op, b, x, settings, result, err)
    call suite%equal_int(result%outcome, GMRES_CONVERGED, 'b = 0: converged')
    call suite%equal_int(result%iterations, 0, 'b = 0: no iteration')
    call suite%check(all(x == 0.0_dp), 'b = 0: x = 0')
  end subroutine check_zero_rhs

end program test_fcs_gmres
