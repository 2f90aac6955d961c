!> The checks every linear solver must pass, run by the unit test of each solver on its own
!> concrete type: accuracy against the residual and a dense oracle, reuse of the analysis for
!> new values, reanalysis after a pattern rebuild, Dirichlet conditions, a singular matrix
!> reported as an error, and misuse reported as an error.
!>
!> Tolerances: ||A x - b|| / ||b|| <= 1e-12 is a backward-stable direct solve (about 1e3 times
!> the unit round-off for these few hundred equations); agreement with the dense
!> partial-pivoting oracle within 1e-10 allows condition numbers up to about 1e5, well above
!> those of these matrices.
module fcs_test_solver_checks
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_linear_solver, only: linear_solver_t
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_matrices, only: test_mesh_t, make_grid_mesh, build_pattern, fill_random_dominant, &
    fill_stiffness_like, dense_solve, relative_residual, relative_difference, base_constraints, &
    contains_text, random_stream_t
  implicit none
  private
  public :: check_linear_solver, solve_and_check, RESIDUAL_TOLERANCE, ORACLE_TOLERANCE

  real(dp), parameter :: RESIDUAL_TOLERANCE = 1.0e-12_dp
  real(dp), parameter :: ORACLE_TOLERANCE = 1.0e-10_dp

contains

  !> Run all generic checks on `solver` (freshly created, not yet used).
  subroutine check_linear_solver(suite, solver)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    mesh = make_grid_mesh(3, 3, 3, shuffle_seed=7)
    call build_pattern(mesh, matrix)
    call check_misuse_before_factor(suite, solver, matrix)
    call check_values_and_reuse(suite, solver, mesh, matrix)
    call check_pattern_rebuild(suite, solver, mesh, matrix)
    call check_dirichlet(suite, solver, mesh, matrix)
    call check_singular(suite, solver, matrix)
    call check_free_and_restart(suite, solver, matrix)
    call solver%free()
  end subroutine check_linear_solver

  !> Factor `matrix`, solve for a random right-hand side, check the residual and the oracle.
  subroutine solve_and_check(suite, solver, matrix, what, x)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(sparse_matrix_t), intent(in) :: matrix
    character(len=*), intent(in) :: what
    real(dp), allocatable, intent(out), optional :: x(:)
    real(dp), allocatable :: b(:), solution(:)
    type(error_t), allocatable :: err
    call solver%factor(matrix, err)
    call suite%check(.not. allocated(err), what // ': factor succeeds')
    if (allocated(err)) then
      print '(a)', '    ' // err%message
      return
    end if
    b = random_vector(matrix%n, 3)
    allocate (solution(matrix%n))
    call solver%solve(matrix, b, solution, err)
    call suite%check(.not. allocated(err), what // ': solve succeeds')
    if (allocated(err)) return
    call suite%check(relative_residual(matrix, solution, b) <= RESIDUAL_TOLERANCE, &
                     what // ': ||Ax-b||/||b|| <= 1e-12')
    call suite%check(relative_difference(solution, dense_solve(matrix, b)) <= ORACLE_TOLERANCE, &
                     what // ': agrees with the dense oracle within 1e-10')
    if (present(x)) x = solution
  end subroutine solve_and_check

  function random_vector(n, seed) result(v)
    integer, intent(in) :: n, seed
    real(dp), allocatable :: v(:)
    type(random_stream_t) :: random
    integer :: i
    random%state = int(seed, i8)
    allocate (v(n))
    do i = 1, n
      v(i) = random%uniform(-1.0_dp, 1.0_dp)
    end do
  end function random_vector

  !> A solve before any factorisation is an error, not a crash.
  subroutine check_misuse_before_factor(suite, solver, matrix)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(sparse_matrix_t), intent(in) :: matrix
    real(dp), allocatable :: b(:), x(:)
    type(error_t), allocatable :: err
    allocate (b(matrix%n), x(matrix%n))
    b = 1.0_dp
    call solver%solve(matrix, b, x, err)
    call suite%check(allocated(err), 'solve before factor is an error')
  end subroutine check_misuse_before_factor

  !> Random dominant values, then stiffness-like values on the same pattern: one analysis,
  !> two factorisations; several right-hand sides per factorisation.
  subroutine check_values_and_reuse(suite, solver, mesh, matrix)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(test_mesh_t), intent(in) :: mesh
    type(sparse_matrix_t), intent(inout) :: matrix
    integer :: analyses
    analyses = solver%stats%n_analyses
    call fill_random_dominant(matrix, seed=11)
    call solve_and_check(suite, solver, matrix, 'random dominant')
    call suite%equal_int(solver%stats%n_analyses, analyses + 1, 'first factor analyses once')
    call suite%check(solver%stats%factor_entries >= matrix%n, 'factor_entries reported')
    call fill_stiffness_like(matrix, mesh, seed=5, supported=.true., perturbation=1.0e-2_dp)
    call solve_and_check(suite, solver, matrix, 'stiffness-like, same pattern')
    call suite%equal_int(solver%stats%n_analyses, analyses + 1, &
                         'new values on the same pattern: no new analysis')
    call suite%check(solver%stats%n_factorisations >= 2, 'two factorisations counted')
    call fill_random_dominant(matrix, seed=12)
    call solve_and_check(suite, solver, matrix, 'random dominant again')
    call suite%equal_int(solver%stats%n_analyses, analyses + 1, 'third factor: still one analysis')
  end subroutine check_values_and_reuse

  !> Rebuilding the pattern (here with one more clique, and then identically) bumps
  !> pattern_version, which must trigger a new analysis each time.
  subroutine check_pattern_rebuild(suite, solver, mesh, matrix)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(test_mesh_t), intent(in) :: mesh
    type(sparse_matrix_t), intent(inout) :: matrix
    type(test_mesh_t) :: grown
    integer :: analyses, n_cliques
    analyses = solver%stats%n_analyses
    grown = mesh
    n_cliques = size(mesh%clique_ptr) - 1
    grown%clique_nodes = [mesh%clique_nodes, 1, mesh%n_nodes / 2, mesh%n_nodes]
    grown%clique_ptr = [mesh%clique_ptr, mesh%clique_ptr(n_cliques + 1) + 3]
    call build_pattern(grown, matrix)
    call fill_stiffness_like(matrix, grown, seed=6, supported=.true., perturbation=1.0e-2_dp)
    call solve_and_check(suite, solver, matrix, 'after a pattern change')
    call suite%equal_int(solver%stats%n_analyses, analyses + 1, 'pattern change: reanalysis')
    call build_pattern(mesh, matrix)
    call fill_random_dominant(matrix, seed=13)
    call solve_and_check(suite, solver, matrix, 'after a rebuild to the original pattern')
    call suite%equal_int(solver%stats%n_analyses, analyses + 2, 'second rebuild: reanalysis')
  end subroutine check_pattern_rebuild

  !> The unsupported truss (singular: rigid-body modes) with the base nodes prescribed through
  !> apply_dirichlet: solvable, and the prescribed values come out exactly (to round-off).
  subroutine check_dirichlet(suite, solver, mesh, matrix)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(test_mesh_t), intent(in) :: mesh
    type(sparse_matrix_t), intent(inout) :: matrix
    logical, allocatable :: constrained(:)
    real(dp), allocatable :: values(:), rhs(:), x(:)
    type(error_t), allocatable :: err
    call fill_stiffness_like(matrix, mesh, seed=8, supported=.false., perturbation=1.0e-3_dp)
    call base_constraints(mesh, constrained, values)
    rhs = random_vector(matrix%n, 4)
    call matrix%apply_dirichlet(constrained, values, rhs)
    call solver%factor(matrix, err)
    call suite%check(.not. allocated(err), 'apply_dirichlet: factor succeeds')
    if (allocated(err)) then
      print '(a)', '    ' // err%message
      return
    end if
    allocate (x(matrix%n))
    call solver%solve(matrix, rhs, x, err)
    call suite%check(.not. allocated(err), 'apply_dirichlet: solve succeeds')
    if (allocated(err)) return
    call suite%check(relative_residual(matrix, x, rhs) <= RESIDUAL_TOLERANCE, &
                     'apply_dirichlet: ||Ax-b||/||b|| <= 1e-12')
    call suite%check(maxval(abs(x - values), mask=constrained) <= 1.0e-12_dp, &
                     'apply_dirichlet: prescribed values recovered to 1e-12')
    call suite%check(relative_difference(x, dense_solve(matrix, rhs)) <= ORACLE_TOLERANCE, &
                     'apply_dirichlet: agrees with the dense oracle')
  end subroutine check_dirichlet

  !> A zero row makes the matrix singular: factor returns an error with a message, solve then
  !> refuses, and a good matrix can be factorised afterwards.
  subroutine check_singular(suite, solver, matrix)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(sparse_matrix_t), intent(inout) :: matrix
    real(dp), allocatable :: b(:), x(:)
    type(error_t), allocatable :: err
    integer, parameter :: ZERO_ROW = 100
    call fill_random_dominant(matrix, seed=21)
    matrix%val(matrix%row_ptr(ZERO_ROW):matrix%row_ptr(ZERO_ROW + 1) - 1) = 0.0_dp
    call solver%factor(matrix, err)
    call suite%check(allocated(err), 'zero row: factor reports an error')
    if (allocated(err)) then
      call suite%check(contains_text(err%message, 'singular'), 'zero row: message says singular')
      print '(a)', '    (expected) ' // err%message
    end if
    allocate (b(matrix%n), x(matrix%n))
    b = 1.0_dp
    call solver%solve(matrix, b, x, err)
    call suite%check(allocated(err), 'solve after a failed factor is an error')
    call fill_random_dominant(matrix, seed=22)
    call solve_and_check(suite, solver, matrix, 'good matrix after a singular one')
  end subroutine check_singular

  !> After free, the solver starts again from scratch (a new analysis).
  subroutine check_free_and_restart(suite, solver, matrix)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(sparse_matrix_t), intent(inout) :: matrix
    integer :: analyses
    call solver%free()
    call solver%free()
    analyses = solver%stats%n_analyses
    call fill_random_dominant(matrix, seed=23)
    call solve_and_check(suite, solver, matrix, 'after free')
    call suite%equal_int(solver%stats%n_analyses, analyses + 1, 'after free: new analysis')
  end subroutine check_free_and_restart

end module fcs_test_solver_checks
