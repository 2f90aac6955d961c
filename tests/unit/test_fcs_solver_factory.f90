!> Unit test of fcs_solver_factory: every name creates its solver (case-insensitive), an
!> unknown name is an input error listing the valid names, and the three solvers agree. The
!> registry: a test-only dense LAPACK solver (fcs_test_dense_solver) registered at run time is
!> listed by the names and messages, created by name and passes the shared solve checks.
program test_fcs_solver_factory
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, EXIT_INPUT
  use fcs_sparse, only: sparse_matrix_t
  use fcs_linear_solver, only: linear_solver_t
  use fcs_strings, only: string_t
  use fcs_solver_factory, only: create_linear_solver, linear_solver_names, DEFAULT_LINEAR_SOLVER, &
    linear_solver_names_text, is_linear_solver, solver_registry_t, solver_has_low_rank, &
    low_rank_solver_names_text
  use fcs_test_dense_solver, only: dense_solver_entry, DENSE_SOLVER_NAME
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_matrices, only: test_mesh_t, make_grid_mesh, build_pattern, fill_random_dominant, &
    fill_stiffness_like, relative_difference, contains_text
  use fcs_test_solver_checks, only: solve_and_check
  implicit none
  type(test_suite_t) :: suite
  type(string_t), allocatable :: solver_names(:)

  suite%name = 'fcs_solver_factory'
  solver_names = linear_solver_names()
  call check_names(suite)
  call check_unknown_name(suite)
  call check_agreement(suite)
  call check_registered_solver(suite)
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
        call suite%check(solver%name() == solver_names(i)%s, &
                         'name() of "' // SPELLINGS(i) // '"')
      end if
    end do
    call suite%check(is_linear_solver(DEFAULT_LINEAR_SOLVER), 'default is a valid name')
    call suite%check(linear_solver_names_text() == 'SKYLINE, UMFPACK, MUMPS', 'names as text')
    call suite%check(DEFAULT_LINEAR_SOLVER == 'UMFPACK', 'default is UMFPACK')
    call suite%check(solver_has_low_rank(' mumps '), 'MUMPS has a block low-rank factorisation')
    call suite%check(.not. solver_has_low_rank('UMFPACK') .and. .not. solver_has_low_rank('SKYLINE'), &
                     'UMFPACK and SKYLINE have none')
    call suite%check(.not. solver_has_low_rank('PARDISO'), 'an unknown name has none')
    call suite%check(low_rank_solver_names_text() == 'MUMPS', 'the solvers with one, as text')
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
    do i = 1, size(solver_names)
      call suite%check(contains_text(err%message, solver_names(i)%s), &
                       'message lists ' // solver_names(i)%s)
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
    allocate (x(matrix%n, size(solver_names)))
    do i = 1, size(solver_names)
      call create_linear_solver(solver_names(i)%s, solver, err)
      if (allocated(err)) return
      call solve_and_check(suite, solver, matrix, solver_names(i)%s, solution)
      call solver%free()
      if (.not. allocated(solution)) return
      x(:, i) = solution
    end do
    do i = 1, size(solver_names)
      do j = i + 1, size(solver_names)
        call suite%check(relative_difference(x(:, i), x(:, j)) <= 1.0e-10_dp, &
          solver_names(i)%s // ' and ' // solver_names(j)%s // &
          ' agree within 1e-10')
      end do
    end do
  end subroutine compare_solvers

  !> The recipe "How to add a linear solver" on a test-only solver: registered at run time, the
  !> registry lists it (names, messages) and creates it by name (any case); it solves a system
  !> through the shared checks and agrees with UMFPACK. The built-in registry does not know it,
  !> and a second registration of the name is refused.
  subroutine check_registered_solver(suite)
    type(test_suite_t), intent(inout) :: suite
    type(solver_registry_t) :: registry
    class(linear_solver_t), allocatable :: solver
    type(error_t), allocatable :: err
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    real(dp), allocatable :: x_dense(:), x_umfpack(:)
    call registry%init()
    call registry%register(dense_solver_entry(), err)
    call suite%check(.not. allocated(err), 'registry: ' // DENSE_SOLVER_NAME // ' registered')
    call suite%check(is_linear_solver(DENSE_SOLVER_NAME, registry), 'registry: knows it')
    call suite%check(.not. is_linear_solver(DENSE_SOLVER_NAME), 'built-in registry: does not')
    call suite%check(linear_solver_names_text(registry) == 'SKYLINE, UMFPACK, MUMPS, ' // &
                     DENSE_SOLVER_NAME, 'registry: names list it')
    call create_linear_solver('PARDISO', solver, err, registry)
    call suite%check(allocated(err), 'registry: PARDISO still rejected')
    if (allocated(err)) call suite%check(contains_text(err%message, DENSE_SOLVER_NAME), &
                                         'registry: the message lists it')
    call create_linear_solver(' test dense ', solver, err, registry)
    call suite%check(.not. allocated(err) .and. allocated(solver), 'created by name')
    if (.not. allocated(solver)) return
    call suite%check(solver%name() == DENSE_SOLVER_NAME, 'its name()')
    mesh = make_grid_mesh(3, 2, 2, shuffle_seed=5)
    call build_pattern(mesh, matrix)
    call fill_stiffness_like(matrix, mesh, seed=43, supported=.true., perturbation=5.0e-3_dp)
    call solve_and_check(suite, solver, matrix, DENSE_SOLVER_NAME, x_dense)
    call solver%free()
    call create_linear_solver('UMFPACK', solver, err, registry)
    if (allocated(err)) return
    call solve_and_check(suite, solver, matrix, 'UMFPACK (registry)', x_umfpack)
    call solver%free()
    if (allocated(x_dense) .and. allocated(x_umfpack)) &
      call suite%check(relative_difference(x_dense, x_umfpack) <= 1.0e-10_dp, &
                       DENSE_SOLVER_NAME // ' and UMFPACK agree within 1e-10')
    call registry%register(dense_solver_entry(), err)
    call suite%check(allocated(err), 'a second ' // DENSE_SOLVER_NAME // ' refused')
  end subroutine check_registered_solver

end program test_fcs_solver_factory
