!> Unit test of fcs_mumps (sequential MUMPS): the generic solver checks, plus the name, the
!> default communicator and two solvers alive at the same time.
program test_fcs_mumps
  use fcs_kinds, only: dp
  use fcs_sparse, only: sparse_matrix_t
  use fcs_mumps, only: mumps_solver_t, MUMPS_SEQUENTIAL_COMM
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_matrices, only: test_mesh_t, make_grid_mesh, build_pattern, fill_random_dominant, &
    relative_difference
  use fcs_test_solver_checks, only: check_linear_solver, solve_and_check
  implicit none
  type(test_suite_t) :: suite
  type(mumps_solver_t) :: solver

  suite%name = 'fcs_mumps'
  call suite%check(solver%name() == 'MUMPS', 'name is MUMPS')
  call suite%equal_int(solver%communicator, MUMPS_SEQUENTIAL_COMM, 'default communicator')
  call check_linear_solver(suite, solver)
  call check_two_instances(suite)
  call suite%report()

contains

  !> Two MUMPS instances on different matrices, alive together, give independent answers.
  subroutine check_two_instances(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_mesh_t) :: mesh_a, mesh_b
    type(sparse_matrix_t) :: matrix_a, matrix_b
    type(mumps_solver_t) :: first, second
    real(dp), allocatable :: x_a(:), x_a_again(:), x_b(:)
    mesh_a = make_grid_mesh(2, 2, 2, shuffle_seed=1)
    mesh_b = make_grid_mesh(3, 2, 1, shuffle_seed=2)
    call build_pattern(mesh_a, matrix_a)
    call build_pattern(mesh_b, matrix_b)
    call fill_random_dominant(matrix_a, seed=31)
    call fill_random_dominant(matrix_b, seed=32)
    call solve_and_check(suite, first, matrix_a, 'instance 1', x_a)
    call solve_and_check(suite, second, matrix_b, 'instance 2', x_b)
    call solve_and_check(suite, first, matrix_a, 'instance 1 again', x_a_again)
    if (allocated(x_a) .and. allocated(x_a_again)) then
      call suite%check(relative_difference(x_a_again, x_a) <= 1.0e-14_dp, &
                       'instance 1 unaffected by instance 2')
    end if
    call first%free()
    call second%free()
  end subroutine check_two_instances

end program test_fcs_mumps
