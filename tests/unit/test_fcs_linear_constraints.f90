!> Unit test of fcs_linear_constraints: the elimination of linear equations (L1)-(L2) on the
!> sparse matrix equals the dense T^T K T, T^T f and u_D = T u_I, with a cascade (a dependent
!> degree of freedom used in another equation), on a pattern built from expanded cliques; and
!> the input errors (zero first coefficient, a degree of freedom dependent twice, a cycle).
program test_fcs_linear_constraints
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_linear_constraints, only: constraint_term_t, linear_equation_t, constraint_map_t
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite
  integer, parameter :: N_NODES = 5, N = 3 * N_NODES
  integer, parameter :: IDS(N_NODES) = [11, 12, 13, 14, 15]

  suite%name = 'fcs_linear_constraints'
  call check_elimination(suite)
  call check_errors(suite)
  call suite%report()

contains

  !> Equations: A  u5x - 2 u3y = 0  (u5x dependent, uses the dependent u3y: a cascade);
  !> B  2 u3y - u1x - u2z = 0  (u3y = (u1x + u2z) / 2); C  u4z = 0 (one term).
  function equations() result(eq)
    type(linear_equation_t) :: eq(3)
    eq(1)%terms = [constraint_term_t(5, 1, 1.0_dp), constraint_term_t(3, 2, -2.0_dp)]
    eq(2)%terms = [constraint_term_t(3, 2, 2.0_dp), constraint_term_t(1, 1, -1.0_dp), &
                   constraint_term_t(2, 3, -1.0_dp)]
    eq(3)%terms = [constraint_term_t(4, 3, 1.0_dp)]
    eq(1)%origin = '*EQUATION'
    eq(2)%origin = '*EQUATION'
    eq(3)%origin = '*EQUATION'
  end function equations

  subroutine check_elimination(suite)
    type(test_suite_t), intent(inout) :: suite
    type(constraint_map_t) :: map
    type(sparse_matrix_t) :: matrix
    type(error_t), allocatable :: err
    integer, allocatable :: ptr(:), nodes(:)
    real(dp) :: k(N, N), t(N, N), reduced(N, N), expected(N, N), f(N), g(N), u(N), block(6, 6)
    integer :: c, i, j
    logical :: missing, lacking
    call map%init(equations(), N_NODES, IDS, err)
    call suite%check(.not. allocated(err), 'the equations resolve')
    if (allocated(err)) return
    call suite%check(count(map%dependent) == 3 .and. map%dependent(13) .and. map%dependent(8) &
                     .and. map%dependent(12), 'u5x, u3y and u4z are dependent')
    ! A chain of two-node cliques 1-2, 2-3, 3-4, 4-5, expanded by the constraints.
    ptr = [1, 3, 5, 7, 9]
    nodes = [1, 2, 2, 3, 3, 4, 4, 5]
    call map%expand_cliques(ptr, nodes)
    call matrix%build(N_NODES, ptr, nodes)
    ! K: an unsymmetric matrix on the chain's couplings only.
    k = 0.0_dp
    do c = 1, 4
      do i = 1, 6
        do j = 1, 6
          block(i, j) = real(mod(7 * i + 3 * j + 5 * c, 11), dp) - 4.0_dp
        end do
        block(i, i) = block(i, i) + 20.0_dp
      end do
      k(3 * c - 2:3 * c + 3, 3 * c - 2:3 * c + 3) = k(3 * c - 2:3 * c + 3, 3 * c - 2:3 * c + 3) + block
      call matrix%add_matrix([c, c + 1], block, missing)
    end do
    call suite%check(.not. missing, 'the chain is in the expanded pattern')
    ! Dense T: u = T u (identity on the independent degrees of freedom).
    t = 0.0_dp
    do i = 1, N
      if (.not. map%dependent(i)) t(i, i) = 1.0_dp
    end do
    t(13, 1) = 1.0_dp
    t(13, 6) = 1.0_dp
    t(8, 1) = 0.5_dp
    t(8, 6) = 0.5_dp
    expected = matmul(transpose(t), matmul(k, t))
    call map%reduce_matrix(matrix, lacking)
    call suite%check(.not. lacking, 'T^T K T fits the expanded pattern')
    reduced = 0.0_dp
    do i = 1, N
      do j = int(matrix%row_ptr(i)), int(matrix%row_ptr(i + 1)) - 1
        reduced(i, matrix%col(j)) = matrix%val(j)
      end do
    end do
    call suite%close_array(reshape(reduced, [N * N]), reshape(expected, [N * N]), 1.0e-14_dp, &
                           'reduce_matrix = dense T^T K T (dependent rows and columns zero)')
    f = [(real(i, dp), i = 1, N)]
    g = f
    call map%reduce_vector(g)
    call suite%close_array(g, matmul(transpose(t), f), 1.0e-15_dp, 'reduce_vector = T^T f')
    u = [(real(i * i, dp), i = 1, N)]
    u(13) = -1.0_dp
    u(8) = -1.0_dp
    u(12) = -1.0_dp
    call map%expand_vector(u)
    call suite%close_array(u, matmul(t, u), 1.0e-15_dp, 'expand_vector: u_D = T u_I')
    call suite%close_to(u(13), u(1) + u(6), 1.0e-15_dp, 'u5x = u1x + u2z (cascade)')
  end subroutine check_elimination

  subroutine check_errors(suite)
    type(test_suite_t), intent(inout) :: suite
    type(constraint_map_t) :: map
    type(linear_equation_t) :: eq(3)
    type(error_t), allocatable :: err
    eq = equations()
    eq(1)%terms(1)%coefficient = 0.0_dp
    call map%init(eq, N_NODES, IDS, err)
    call suite%check(has(err, 'must not be zero'), 'zero first coefficient refused')
    eq = equations()
    eq(3)%terms(1) = constraint_term_t(5, 1, 1.0_dp)
    call map%init(eq, N_NODES, IDS, err)
    call suite%check(has(err, 'node 15, direction 1 is already the dependent term'), &
                     'a degree of freedom dependent twice refused')
    eq = equations()
    eq(2)%terms(2) = constraint_term_t(5, 1, -1.0_dp)
    call map%init(eq, N_NODES, IDS, err)
    call suite%check(has(err, 'in a cycle'), 'a cycle refused')
  end subroutine check_errors

  logical function has(err, text)
    type(error_t), allocatable, intent(in) :: err
    character(len=*), intent(in) :: text
    has = .false.
    if (allocated(err)) has = index(err%message, text) > 0
  end function has

end program test_fcs_linear_constraints
