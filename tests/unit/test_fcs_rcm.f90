!> Unit test of fcs_rcm: the ordering is a permutation, it is optimal on a randomly numbered
!> chain (closed form), it reduces the profile of a randomly numbered grid, and it handles
!> disconnected graphs and isolated nodes.
program test_fcs_rcm
  use fcs_kinds, only: i8
  use fcs_sparse, only: sparse_matrix_t
  use fcs_rcm, only: rcm_node_order, invert_permutation, dof_order_from_nodes, profile_size
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_matrices, only: test_mesh_t, make_grid_mesh, make_chain_mesh, build_pattern
  implicit none
  type(test_suite_t) :: suite

  suite%name = 'fcs_rcm'
  call check_helpers(suite)
  call check_chain(suite)
  call check_grid(suite)
  call check_disconnected(suite)
  call suite%report()

contains

  logical function is_permutation(order, n)
    integer, intent(in) :: order(:), n
    logical, allocatable :: seen(:)
    integer :: k
    is_permutation = size(order) == n
    if (.not. is_permutation) return
    allocate (seen(n))
    seen = .false.
    do k = 1, n
      if (order(k) < 1 .or. order(k) > n) then
        is_permutation = .false.
        return
      end if
      seen(order(k)) = .true.
    end do
    is_permutation = all(seen)
  end function is_permutation

  function identity(n) result(order)
    integer, intent(in) :: n
    integer, allocatable :: order(:)
    integer :: k
    order = [(k, k = 1, n)]
  end function identity

  subroutine check_helpers(suite)
    type(test_suite_t), intent(inout) :: suite
    call suite%check(all(invert_permutation([3, 1, 2]) == [2, 3, 1]), 'invert_permutation')
    call suite%check(all(dof_order_from_nodes([2, 1]) == [4, 5, 6, 1, 2, 3]), &
                     'dofs follow their node')
  end subroutine check_helpers

  !> A chain of n nodes, randomly numbered: RCM must find an end (pseudo-peripheral node) and
  !> number along the chain, giving the optimal profile 3 + 12 (n - 1): the first node's three
  !> rows contribute 0+1+2, every other node (previous neighbour one position back) 9+3.
  subroutine check_chain(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    integer, allocatable :: order(:)
    integer, parameter :: N_NODES = 40
    integer(i8) :: expected
    mesh = make_chain_mesh(N_NODES, shuffle_seed=17)
    call build_pattern(mesh, matrix)
    order = rcm_node_order(matrix)
    call suite%check(is_permutation(order, N_NODES), 'chain: permutation')
    expected = 3 + 12 * (N_NODES - 1)
    call suite%check(profile_size(matrix, order) == expected, 'chain: optimal profile 3+12(n-1)')
    call suite%check(profile_size(matrix, identity(N_NODES)) > expected, &
                     'chain: random numbering is worse')
  end subroutine check_chain

  !> A randomly numbered 6x5x4 grid (210 nodes): RCM must at least halve the profile (it
  !> gives 2.5 times less here; the gain grows with the size) and do no worse than the natural
  !> lexicographic numbering of the grid, the best simple numbering of a box.
  subroutine check_grid(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_mesh_t) :: shuffled, natural
    type(sparse_matrix_t) :: matrix, natural_matrix
    integer, allocatable :: order(:)
    integer(i8) :: random_profile, rcm_profile, natural_profile
    character(len=120) :: line
    shuffled = make_grid_mesh(6, 5, 4, shuffle_seed=5)
    natural = make_grid_mesh(6, 5, 4, shuffle_seed=0)
    call build_pattern(shuffled, matrix)
    call build_pattern(natural, natural_matrix)
    order = rcm_node_order(matrix)
    call suite%check(is_permutation(order, matrix%n_nodes), 'grid: permutation')
    random_profile = profile_size(matrix, identity(matrix%n_nodes))
    rcm_profile = profile_size(matrix, order)
    natural_profile = profile_size(natural_matrix, identity(natural_matrix%n_nodes))
    write (line, '(a,i0,a,i0,a,i0)') '    grid profile: random ', random_profile, ', RCM ', &
      rcm_profile, ', natural ', natural_profile
    print '(a)', trim(line)
    call suite%check(2 * rcm_profile < random_profile, 'grid: RCM at least halves the profile')
    call suite%check(rcm_profile <= natural_profile, &
                     'grid: RCM no worse than the natural numbering')
  end subroutine check_grid

  !> Two grids and two isolated nodes in one graph: every node numbered once, the profile no
  !> larger than the sum over the parts ordered separately.
  subroutine check_disconnected(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_mesh_t) :: a, b
    type(sparse_matrix_t) :: matrix, matrix_a, matrix_b
    integer, allocatable :: order(:), clique_ptr(:), clique_nodes(:)
    integer :: n_a, n_b, n_total
    a = make_grid_mesh(3, 2, 2, shuffle_seed=2)
    b = make_grid_mesh(2, 2, 3, shuffle_seed=4)
    n_a = a%n_nodes
    n_b = b%n_nodes
    n_total = n_a + n_b + 2
    clique_ptr = [a%clique_ptr, b%clique_ptr(2:) + a%clique_ptr(size(a%clique_ptr)) - 1]
    clique_nodes = [a%clique_nodes, b%clique_nodes + n_a + 1]
    call matrix%build(n_total, clique_ptr, clique_nodes)
    call build_pattern(a, matrix_a)
    call build_pattern(b, matrix_b)
    order = rcm_node_order(matrix)
    call suite%check(is_permutation(order, n_total), 'disconnected: permutation')
    call suite%check(profile_size(matrix, order) <= &
                     profile_size(matrix_a, rcm_node_order(matrix_a)) + &
                     profile_size(matrix_b, rcm_node_order(matrix_b)) + 2 * 3, &
                     'disconnected: profile is the sum of the parts')
  end subroutine check_disconnected

end program test_fcs_rcm
