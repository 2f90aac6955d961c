!> Unit test of fcs_mumps (sequential MUMPS): the generic solver checks, plus the name, the
!> default communicator, two solvers alive at the same time, and the block low-rank (BLR)
!> factorisation.
program test_fcs_mumps
  use fcs_kinds, only: dp
  use fcs_sparse, only: sparse_matrix_t
  use fcs_mumps, only: mumps_solver_t, MUMPS_SEQUENTIAL_COMM
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_matrices, only: test_mesh_t, make_grid_mesh, build_pattern, fill_random_dominant, &
    relative_difference, relative_residual
  use fcs_error, only: error_t
  use fcs_test_solver_checks, only: check_linear_solver, solve_and_check
  implicit none
  type(test_suite_t) :: suite
  type(mumps_solver_t) :: solver

  suite%name = 'fcs_mumps'
  call suite%check(solver%name() == 'MUMPS', 'name is MUMPS')
  call suite%equal_int(solver%communicator, MUMPS_SEQUENTIAL_COMM, 'default communicator')
  call check_linear_solver(suite, solver)
  call check_two_instances(suite)
  call check_low_rank(suite)
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

  !> BLR with eps = 1e-8 on a 17 x 17 x 17 grid (17,496 equations, the smallest grid whose
  !> fronts MUMPS compresses: 95 % of the entries kept; 14^3 gave 100 %): the solve's residual ||A x - b|| / ||b|| is within 100 eps, the
  !> backward error of a BLR LU factorisation being of order eps times the growth factor
  !> (Higham and Mary 2022), at most 2 for these diagonally dominant matrices, times a
  !> modest constant; the effective factor entries and flops (INFOG(35), RINFOG(14)) are
  !> reported, at most the full-rank ones (INFOG(29), RINFOG(3)), which equal those of a
  !> full-rank factorisation of the same matrix.
  subroutine check_low_rank(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: EPS = 1.0e-8_dp
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    type(mumps_solver_t) :: blr, full
    type(error_t), allocatable :: err
    real(dp), allocatable :: b(:), x(:)
    integer :: i
    call suite%check(blr%has_low_rank(), 'MUMPS has a block low-rank factorisation')
    mesh = make_grid_mesh(17, 17, 17, shuffle_seed=3)
    call build_pattern(mesh, matrix)
    call fill_random_dominant(matrix, seed=41)
    call blr%set_low_rank_tolerance(EPS)
    call blr%factor(matrix, err)
    call suite%check(.not. allocated(err), 'BLR: factor succeeds')
    if (allocated(err)) then
      print '(a)', '    ' // err%message
      return
    end if
    b = [(sin(real(i, dp)), i = 1, matrix%n)]
    allocate (x(matrix%n))
    call blr%solve(matrix, b, x, err)
    call suite%check(.not. allocated(err), 'BLR: solve succeeds')
    if (allocated(err)) return
    print '(a, es10.3, a, f6.2, a, f6.2, a)', '    BLR eps 1e-8: residual ', &
      relative_residual(matrix, x, b), ', entries ', &
      100.0_dp * blr%stats%low_rank_entries / blr%stats%factor_entries, ' %, flops ', &
      100.0_dp * blr%stats%low_rank_flops / blr%stats%factor_flops, ' % of full rank'
    call suite%check(relative_residual(matrix, x, b) <= 100.0_dp * EPS, &
                     'BLR: ||Ax-b||/||b|| <= 100 eps')
    call suite%check(blr%stats%low_rank_entries > 0.0_dp .and. &
                     blr%stats%low_rank_entries < blr%stats%factor_entries, &
                     'BLR: effective entries reported, fewer than the full-rank ones')
    call suite%check(blr%stats%low_rank_flops > 0.0_dp, 'BLR: effective flops reported')
    call full%factor(matrix, err)
    call suite%check(.not. allocated(err), 'full rank: factor succeeds')
    if (allocated(err)) return
    call suite%check(full%stats%factor_entries == blr%stats%factor_entries, &
                     'full rank: the entries BLR reports as full rank')
    call suite%check(full%stats%low_rank_entries == 0.0_dp, 'full rank: no BLR figures')
    call blr%free()
    call full%free()
  end subroutine check_low_rank

end program test_fcs_mumps
