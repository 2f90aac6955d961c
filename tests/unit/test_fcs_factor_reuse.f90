!> Unit test of fcs_factor_reuse with UMFPACK, MUMPS and the skyline solver, on the stiffness-like
!> test matrices (a supported truss with an unsymmetric perturbation, fcs_test_matrices):
!> * a small perturbation of the factorised matrix is solved by GMRES with the old factors, to
!>   the same answer as the dense oracle within what the tolerance allows, without a new
!>   factorisation;
!> * a matrix whose pattern was rebuilt is factorised afresh;
!> * a matrix far from the factorised one (GMRES cannot reach the tolerance) falls back to a
!>   factorisation and a direct solve, with the direct answer;
!> * with a reference norm larger than |b| (the out-of-balance part of an increment beside its
!>   load part) GMRES stops at the tolerance times that norm;
!> * tolerance 0 (reuse off) factorises every matrix;
!> * the same sequence twice gives bit-identical solutions (decisions on iteration counts only).
program test_fcs_factor_reuse
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_linear_solver, only: linear_solver_t
  use fcs_umfpack, only: umfpack_solver_t
  use fcs_skyline, only: skyline_solver_t
  use fcs_mumps, only: mumps_solver_t
  use fcs_factor_reuse, only: factor_reuse_t, reuse_settings_t
  use fcs_comm, only: comm_t
  use fcs_timer, only: phase_timer_t
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_matrices, only: test_mesh_t, make_grid_mesh, build_pattern, fill_stiffness_like, &
    fill_random_dominant, dense_solve, relative_residual, random_stream_t
  implicit none
  type(test_suite_t) :: suite
  type(umfpack_solver_t) :: umfpack
  type(skyline_solver_t) :: skyline
  type(mumps_solver_t) :: mumps

  suite%name = 'fcs_factor_reuse'
  call check_small_change(suite, umfpack, 'UMFPACK')
  call check_small_change(suite, skyline, 'skyline')
  call check_small_change(suite, mumps, 'MUMPS')
  call check_fallback(suite, mumps)
  call check_pattern_change(suite, umfpack)
  call check_reference_norm(suite, umfpack)
  call check_fallback(suite, umfpack)
  call check_reuse_off(suite, umfpack)
  call check_repeatable(suite)
  call suite%report()

contains

  !> A supported truss (3 x 3 x 2 grid with a spring and a contact-like clique) with a 1 %
  !> unsymmetric perturbation.
  subroutine make_matrix(mesh, matrix)
    type(test_mesh_t), intent(out) :: mesh
    type(sparse_matrix_t), intent(out) :: matrix
    mesh = make_grid_mesh(3, 3, 2, shuffle_seed=3)
    call build_pattern(mesh, matrix)
    call fill_stiffness_like(matrix, mesh, seed=7, supported=.true., perturbation=0.01_dp)
  end subroutine make_matrix

  !> Every entry scaled by (1 + size u), u uniform in (-1, 1): a nearby tangent.
  subroutine perturb(matrix, size, seed)
    type(sparse_matrix_t), intent(inout) :: matrix
    real(dp), intent(in) :: size
    integer, intent(in) :: seed
    type(random_stream_t) :: random
    integer :: p
    random%state = seed
    do p = 1, int(matrix%nnz)
      matrix%val(p) = matrix%val(p) * (1.0_dp + size * random%uniform(-1.0_dp, 1.0_dp))
    end do
  end subroutine perturb

  function right_hand_side(n) result(b)
    integer, intent(in) :: n
    real(dp) :: b(n)
    integer :: i
    b = [(sin(real(i, dp)), i = 1, n)]
  end function right_hand_side

  !> Factorise A, then solve A + dA (|dA| ~ 1e-3 |A| entry-wise) with the old factors.
  subroutine check_small_change(suite, solver, label)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    character(len=*), intent(in) :: label
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    type(factor_reuse_t) :: reuse
    type(phase_timer_t) :: timers
    type(comm_t) :: comm
    type(error_t), allocatable :: err
    real(dp), allocatable :: b(:), x(:), expected(:)
    call make_matrix(mesh, matrix)
    call reuse%init(reuse_settings_t(tolerance=1.0e-10_dp), comm)
    b = right_hand_side(matrix%n)
    allocate (x(matrix%n))
    call reuse%prepare(solver, matrix, timers, err)
    if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err)
    call suite%check(.not. allocated(err), label // ': first matrix factorised and solved')
    call perturb(matrix, 1.0e-3_dp, seed=11)
    call reuse%prepare(solver, matrix, timers, err)
    if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err)
    call suite%check(.not. allocated(err), label // ': perturbed matrix solved')
    call suite%equal_int(reuse%stats%factorisations, 1, label // ': one factorisation only')
    call suite%equal_int(reuse%stats%krylov_solves, 1, label // ': solved by GMRES')
    call suite%check(reuse%stats%krylov_iterations >= 1 .and. reuse%stats%krylov_iterations <= 10, &
                     label // ': within the refactorisation threshold (10 iterations)')
    ! The residual to the tolerance 1e-10; the solution then differs from the oracle's by at
    ! most the condition number times that (this truss: about 1e3), so 1e-6 is safe.
    call suite%check(relative_residual(matrix, x, b) <= 1.0e-10_dp, &
                     label // ': residual within the tolerance')
    expected = dense_solve(matrix, b)
    call suite%close_array(x, expected, 1.0e-6_dp, label // ': x as the dense oracle')
    call solver%free()
  end subroutine check_small_change

  !> Rebuilding the pattern (a new pattern version, as after a contact search) factorises.
  subroutine check_pattern_change(suite, solver)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    type(factor_reuse_t) :: reuse
    type(phase_timer_t) :: timers
    type(comm_t) :: comm
    type(error_t), allocatable :: err
    real(dp), allocatable :: b(:), x(:)
    call make_matrix(mesh, matrix)
    call reuse%init(reuse_settings_t(tolerance=1.0e-10_dp), comm)
    b = right_hand_side(matrix%n)
    allocate (x(matrix%n))
    call reuse%prepare(solver, matrix, timers, err)
    if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err)
    call build_pattern(mesh, matrix)
    call fill_stiffness_like(matrix, mesh, seed=7, supported=.true., perturbation=0.01_dp)
    call perturb(matrix, 1.0e-3_dp, seed=11)
    call reuse%prepare(solver, matrix, timers, err)
    if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err)
    call suite%check(.not. allocated(err), 'new pattern: solved')
    call suite%equal_int(reuse%stats%factorisations, 2, 'new pattern: factorised again')
    call suite%equal_int(reuse%stats%pattern_factorisations, 2, 'new pattern: counted as such')
    call suite%equal_int(reuse%stats%krylov_solves, 0, 'new pattern: no GMRES')
    call suite%check(relative_residual(matrix, x, b) <= 1.0e-12_dp, 'new pattern: direct accuracy')
    call solver%free()
  end subroutine check_pattern_change

  !> The same perturbed matrix solved twice with the old factors, the second time with a
  !> reference norm 1e4 |b|: the residual meets 1e-10 x 1e4 |b|, in fewer iterations.
  subroutine check_reference_norm(suite, solver)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    type(factor_reuse_t) :: reuse
    type(phase_timer_t) :: timers
    type(comm_t) :: comm
    type(error_t), allocatable :: err
    real(dp), allocatable :: b(:), x(:)
    integer :: plain
    call make_matrix(mesh, matrix)
    call reuse%init(reuse_settings_t(tolerance=1.0e-10_dp), comm)
    b = right_hand_side(matrix%n)
    allocate (x(matrix%n))
    call reuse%prepare(solver, matrix, timers, err)
    if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err)
    call perturb(matrix, 1.0e-3_dp, seed=11)
    call reuse%prepare(solver, matrix, timers, err)
    if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err)
    plain = int(reuse%stats%krylov_iterations)
    if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err, &
                                               reference_norm=1.0e4_dp * norm2(b))
    call suite%check(.not. allocated(err), 'reference norm: solved')
    call suite%equal_int(reuse%stats%krylov_solves, 2, 'reference norm: both by GMRES')
    call suite%check(int(reuse%stats%krylov_iterations) - plain < plain, &
                     'reference norm: fewer iterations than to 1e-10 |b|')
    call suite%check(relative_residual(matrix, x, b) <= 1.0e-6_dp, &
                     'reference norm: residual within 1e-10 x 1e4 |b|')
    call solver%free()
  end subroutine check_reference_norm

  !> Factors of an unrelated matrix (random diagonally dominant values on the same pattern):
  !> GMRES stagnates far from the tolerance, gives up, and the matrix is factorised and solved
  !> directly.
  subroutine check_fallback(suite, solver)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    type(factor_reuse_t) :: reuse
    type(phase_timer_t) :: timers
    type(comm_t) :: comm
    type(error_t), allocatable :: err
    real(dp), allocatable :: b(:), x(:), expected(:)
    call make_matrix(mesh, matrix)
    call fill_random_dominant(matrix, seed=5)
    call reuse%init(reuse_settings_t(tolerance=1.0e-10_dp), comm)
    b = right_hand_side(matrix%n)
    allocate (x(matrix%n))
    call reuse%prepare(solver, matrix, timers, err)
    if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err)
    call fill_stiffness_like(matrix, mesh, seed=7, supported=.true., perturbation=0.01_dp)
    call reuse%prepare(solver, matrix, timers, err)
    if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err)
    call suite%check(.not. allocated(err), 'far matrix: solved')
    call suite%equal_int(reuse%stats%fallbacks, 1, 'far matrix: one fallback')
    call suite%equal_int(reuse%stats%factorisations, 2, 'far matrix: factorised again')
    call suite%equal_int(reuse%stats%krylov_solves, 0, 'far matrix: no accepted GMRES solve')
    call suite%check(reuse%stats%krylov_iterations >= 1 .and. reuse%stats%krylov_iterations <= 20, &
                     'far matrix: GMRES gave up within its limit')
    expected = dense_solve(matrix, b)
    call suite%check(relative_residual(matrix, x, b) <= 1.0e-12_dp, 'far matrix: direct accuracy')
    call suite%close_array(x, expected, 1.0e-9_dp, 'far matrix: x as the dense oracle')
    ! The next nearby matrix reuses the new factors.
    call perturb(matrix, 1.0e-4_dp, seed=13)
    call reuse%prepare(solver, matrix, timers, err)
    if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err)
    call suite%equal_int(reuse%stats%krylov_solves, 1, 'after the fallback: reuse again')
    call suite%equal_int(reuse%stats%factorisations, 2, 'after the fallback: no factorisation')
    call solver%free()
  end subroutine check_fallback

  !> Tolerance 0: every prepare factorises, every solve is direct.
  subroutine check_reuse_off(suite, solver)
    type(test_suite_t), intent(inout) :: suite
    class(linear_solver_t), intent(inout) :: solver
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    type(factor_reuse_t) :: reuse
    type(phase_timer_t) :: timers
    type(comm_t) :: comm
    type(error_t), allocatable :: err
    real(dp), allocatable :: b(:), x(:)
    integer :: k
    call make_matrix(mesh, matrix)
    call reuse%init(reuse_settings_t(tolerance=0.0_dp), comm)
    b = right_hand_side(matrix%n)
    allocate (x(matrix%n))
    do k = 1, 3
      call perturb(matrix, 1.0e-4_dp, seed=20 + k)
      call reuse%prepare(solver, matrix, timers, err)
      if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err)
    end do
    call suite%check(.not. allocated(err), 'reuse off: solved')
    call suite%equal_int(reuse%stats%factorisations, 3, 'reuse off: three factorisations')
    call suite%equal_int(reuse%stats%direct_solves, 3, 'reuse off: three direct solves')
    call suite%equal_int(int(reuse%stats%krylov_iterations), 0, 'reuse off: no GMRES')
    call solver%free()
  end subroutine check_reuse_off

  !> Two identical sequences of five nearby matrices: bit-identical answers and counts.
  subroutine check_repeatable(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), allocatable :: first(:), second(:)
    integer :: counts(2, 2)
    call run_sequence(first, counts(:, 1))
    call run_sequence(second, counts(:, 2))
    call suite%check(all(first == second), 'repeatable: identical solutions')
    call suite%check(all(counts(:, 1) == counts(:, 2)), 'repeatable: identical counts')
  end subroutine check_repeatable

  subroutine run_sequence(x_all, counts)
    real(dp), allocatable, intent(out) :: x_all(:)
    integer, intent(out) :: counts(2)
    type(umfpack_solver_t) :: solver
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    type(factor_reuse_t) :: reuse
    type(phase_timer_t) :: timers
    type(comm_t) :: comm
    type(error_t), allocatable :: err
    real(dp), allocatable :: b(:), x(:)
    integer :: k
    call make_matrix(mesh, matrix)
    call reuse%init(reuse_settings_t(tolerance=1.0e-10_dp), comm)
    b = right_hand_side(matrix%n)
    allocate (x(matrix%n), x_all(0))
    do k = 1, 5
      call perturb(matrix, 3.0e-3_dp, seed=30 + k)
      call reuse%prepare(solver, matrix, timers, err)
      if (.not. allocated(err)) call reuse%solve(solver, matrix, b, x, timers, err)
      x_all = [x_all, x]
    end do
    counts = [reuse%stats%factorisations, int(reuse%stats%krylov_iterations)]
    call solver%free()
  end subroutine run_sequence

end program test_fcs_factor_reuse
