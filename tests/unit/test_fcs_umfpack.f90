!> Unit test of fcs_umfpack: the generic solver checks (UMFPACK factorises A^T from our CSR
!> arrays and solves with UMFPACK_At), plus the name and the singular-matrix wording.
program test_fcs_umfpack
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_umfpack, only: umfpack_solver_t
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_matrices, only: test_mesh_t, make_grid_mesh, build_pattern, fill_random_dominant, &
    contains_text
  use fcs_test_solver_checks, only: check_linear_solver
  implicit none
  type(test_suite_t) :: suite
  type(umfpack_solver_t) :: solver

  suite%name = 'fcs_umfpack'
  call suite%check(solver%name() == 'UMFPACK', 'name is UMFPACK')
  call check_linear_solver(suite, solver)
  call check_singular_wording(suite)
  call suite%report()

contains

  !> A zero row: UMFPACK's warning status is an error for us, and is named.
  subroutine check_singular_wording(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    type(umfpack_solver_t) :: solver
    type(error_t), allocatable :: err
    mesh = make_grid_mesh(2, 2, 2, shuffle_seed=0)
    call build_pattern(mesh, matrix)
    call fill_random_dominant(matrix, seed=4)
    matrix%val(matrix%row_ptr(7):matrix%row_ptr(8) - 1) = 0.0_dp
    call solver%factor(matrix, err)
    call suite%check(allocated(err), 'zero row: error')
    if (allocated(err)) then
      call suite%check(contains_text(err%message, 'UMFPACK_WARNING_singular_matrix'), &
                       'message names UMFPACK_WARNING_singular_matrix')
      call suite%check(contains_text(err%message, ': 1 of 81 pivots are zero'), &
                       'message counts the zero pivots')
    end if
    call solver%free()
  end subroutine check_singular_wording

end program test_fcs_umfpack
