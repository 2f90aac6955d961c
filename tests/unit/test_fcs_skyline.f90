!> Unit test of fcs_skyline: the generic solver checks, plus the skyline specifics (profile
!> size reported, the singular pivot named by degree of freedom, node and direction).
program test_fcs_skyline
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t
  use fcs_strings, only: str
  use fcs_sparse, only: sparse_matrix_t
  use fcs_rcm, only: rcm_node_order, profile_size
  use fcs_skyline, only: skyline_solver_t
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_matrices, only: test_mesh_t, make_grid_mesh, build_pattern, fill_random_dominant, &
    contains_text
  use fcs_test_solver_checks, only: check_linear_solver, solve_and_check
  implicit none
  type(test_suite_t) :: suite
  type(skyline_solver_t) :: solver

  suite%name = 'fcs_skyline'
  call suite%check(solver%name() == 'SKYLINE', 'name is SKYLINE')
  call check_linear_solver(suite, solver)
  call check_profile_entries(suite)
  call check_pivot_message(suite)
  call suite%report()

contains

  !> factor_entries = n + 2 * profile of the RCM-ordered matrix.
  subroutine check_profile_entries(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    type(skyline_solver_t) :: solver
    integer(i8) :: profile
    mesh = make_grid_mesh(4, 3, 2, shuffle_seed=3)
    call build_pattern(mesh, matrix)
    call fill_random_dominant(matrix, seed=2)
    call solve_and_check(suite, solver, matrix, 'skyline 4x3x2 grid')
    profile = profile_size(matrix, rcm_node_order(matrix))
    call suite%close_to(solver%stats%factor_entries, real(matrix%n + 2 * profile, dp), 0.0_dp, &
                        'factor_entries = n + 2 * profile_size (exact count)')
    call solver%free()
  end subroutine check_profile_entries

  !> A zero row at dof 3*(41-1)+2 = 122 (node 41, direction y) is named in the message.
  subroutine check_pivot_message(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    type(skyline_solver_t) :: solver
    type(error_t), allocatable :: err
    integer, parameter :: DOF = 122
    mesh = make_grid_mesh(3, 3, 3, shuffle_seed=9)
    call build_pattern(mesh, matrix)
    call fill_random_dominant(matrix, seed=4)
    matrix%val(matrix%row_ptr(DOF):matrix%row_ptr(DOF + 1) - 1) = 0.0_dp
    call solver%factor(matrix, err)
    call suite%check(allocated(err), 'zero row: error')
    if (.not. allocated(err)) return
    call suite%check(contains_text(err%message, 'degree of freedom ' // str(DOF) // ' '), &
                     'message names the degree of freedom')
    call suite%check(contains_text(err%message, '(node 41, direction y)'), &
                     'message names node and direction')
    call suite%check(contains_text(err%message, 'the matrix is singular or nearly so: check ' // &
      'that every body is supported (rigid-body modes) and that contact is closed'), &
      'message gives the advice')
    call solver%free()
  end subroutine check_pivot_message

end program test_fcs_skyline
