!> Unit test of fcs_solver_factory: every name creates its solver (case-insensitive), an
!> unknown name is an input error listing the valid names, and the three solvers agree.
program test_fcs_solver_factory
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, EXIT_INPUT
  use fcs_sparse, only: sparse_matrix_t
  use fcs_linear_solver, only: linear_solver_t
  use fcs_solver_factory, only: create_linear_solver, LINEAR_SOLVER_NAMES, DEFAULT_LINEAR_SOLVER
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_matrices, only: test_mesh_t, make_grid_mesh, build_pattern, fill_random_dominant, &
    fill_stiffness_like, relative_difference, contains_text
  use fcs_test_solver_checks, only: solve_and_check
  implicit none
  type(test_suite_t) :: suite

  suite%name = 'fcs_solver_factory'
  call check_names(suite)
  call check_unknown_name(suite)
  call check_agreement(suite)
  call suite%report()

contains

  subroutine check_names(suite)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), allocatable :: solver
    type(error_t), allocatable :: err
    character(len=*), parameter :: SPELLINGS(3) = ['skyline  ', ' Umfpack ', 'MUMPS    ']
    integer :: i
    do i = 1, size(SPELLINGS)
      call create_linear_solver(SPELLINGS(i), solver, err)
      call suite%check(.not. allocated(err), 'creates "' // SPELLINGS(i) // '"')
      if (allocated(solver)) then
        call suite%check(solver%name() == trim(LINEAR_SOLVER_NAMES(i)), &
                         'name() of "' // SPELLINGS(i) // '"')
      end if
    end do
    call suite%check(any(LINEAR_SOLVER_NAMES == DEFAULT_LINEAR_SOLVER), 'default is a valid name')
    call suite%check(DEFAULT_LINEAR_SOLVER == 'UMFPACK', 'default is UMFPACK')
  end subroutine check_names

  subroutine check_unknown_name(suite)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), allocatable :: solver
    type(error_t), allocatable :: err
    integer :: i
    call create_linear_solver('PARDISO', solver, err)
    call suite%check(allocated(err), 'PARDISO is rejected')
    call suite%check(.not. allocated(solver), 'no solver allocated for PARDISO')
    if (.not. allocated(err)) return
    call suite%equal_int(err%exit_code, EXIT_INPUT, 'unknown name is an input error')
    call suite%check(contains_text(err%message, '"PARDISO"'), 'message quotes the name')
    do i = 1, size(LINEAR_SOLVER_NAMES)
      call suite%check(contains_text(err%message, trim(LINEAR_SOLVER_NAMES(i))), &
                       'message lists ' // trim(LINEAR_SOLVER_NAMES(i)))
    end do
    print '(a)', '    (expected) ' // err%message
  end subroutine check_unknown_name

  !> The three solvers on the same systems agree within 1e-10 relative (each is within 1e-12
  !> in residual; the condition numbers here are below 1e3).
  subroutine check_agreement(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    integer :: case_number
    mesh = make_grid_mesh(4, 3, 3, shuffle_seed=12)
    call build_pattern(mesh, matrix)
    do case_number = 1, 2
      if (case_number == 1) then
        call fill_random_dominant(matrix, seed=41)
      else
        call fill_stiffness_like(matrix, mesh, seed=42, supported=.true., perturbation=5.0e-3_dp)
      end if
      call compare_solvers(suite, matrix)
    end do
  end subroutine check_agreement

  subroutine compare_solvers(suite, matrix)
    type(test_suite_t), intent(inout) :: suite
    type(sparse_matrix_t), intent(in) :: matrix
    class(linear_solver_t), allocatable :: solver
    type(error_t), allocatable :: err
    real(dp), allocatable :: x(:, :), solution(:)
    integer :: i, j
    allocate (x(matrix%n, size(LINEAR_SOLVER_NAMES)))
    do i = 1, size(LINEAR_SOLVER_NAMES)
      call create_linear_solver(LINEAR_SOLVER_NAMES(i), solver, err)
      if (allocated(err)) return
      call solve_and_check(suite, solver, matrix, trim(LINEAR_SOLVER_NAMES(i)), solution)
      call solver%free()
      if (.not. allocated(solution)) return
      x(:, i) = solution
    end do
    do i = 1, size(LINEAR_SOLVER_NAMES)
      do j = i + 1, size(LINEAR_SOLVER_NAMES)
        call suite%check(relative_difference(x(:, i), x(:, j)) <= 1.0e-10_dp, &
          trim(LINEAR_SOLVER_NAMES(i)) // ' and ' // trim(LINEAR_SOLVER_NAMES(j)) // &
          ' agree within 1e-10')
      end do
    end do
  end subroutine compare_solvers

end program test_fcs_solver_factory
