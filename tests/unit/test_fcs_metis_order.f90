!> Unit test of fcs_metis_order: the equation order is a permutation that keeps each node's
!> three equations together and in order, it is the same when computed again (METIS's fixed
!> seed: the reason fcs3d orders for MUMPS itself), it handles a matrix without couplings and
!> one whose order is not a multiple of 3, and on a randomly numbered 3-D grid it gives less
!> fill than the reverse Cuthill-McKee order: nested dissection of an n-node 3-D grid leaves
!> O(n^(4/3)) entries in the Cholesky factor, a banded (RCM) order O(n^(5/3)) (A. George,
!> "Nested dissection of a regular finite element mesh", SIAM J. Numer. Anal. 10(2), 1973;
!> Lipton, Rose & Tarjan, SIAM J. Numer. Anal. 16(2), 1979). The fill is counted exactly by
!> the elimination tree (J. W. H. Liu, "The role of elimination trees in sparse
!> factorization", SIAM J. Matrix Anal. Appl. 11(1), 1990).
program test_fcs_metis_order
  use fcs_error, only: error_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_rcm, only: rcm_node_order, invert_permutation
  use fcs_metis_order, only: metis_equation_order
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_matrices, only: test_mesh_t, make_grid_mesh, build_pattern
  implicit none
  type(test_suite_t) :: suite

  suite%name = 'fcs_metis_order'
  call check_grid(suite)
  call check_no_couplings(suite)
  call check_order_not_multiple_of_3(suite)
  call suite%report()

contains

  logical function is_permutation(order, n)
    integer, intent(in) :: order(:), n
    logical, allocatable :: seen(:)
    integer :: k
    is_permutation = size(order) == n
    if (.not. is_permutation) return
    allocate (seen(n), source=.false.)
    do k = 1, n
      if (order(k) < 1 .or. order(k) > n) then
        is_permutation = .false.
        return
      end if
      seen(order(k)) = .true.
    end do
    is_permutation = all(seen)
  end function is_permutation

  subroutine check_grid(suite)
    type(test_suite_t), intent(inout) :: suite
    type(test_mesh_t) :: mesh
    type(sparse_matrix_t) :: matrix
    type(error_t), allocatable :: err
    integer, allocatable :: position(:), again(:), node_position(:)
    integer :: k
    integer(kind=8) :: fill_metis, fill_rcm
    mesh = make_grid_mesh(12, 12, 12, 20261121)
    call build_pattern(mesh, matrix)
    call metis_equation_order(matrix, position, err)
    call suite%check(.not. allocated(err), 'grid: METIS ordering succeeds')
    if (allocated(err)) return
    call suite%check(is_permutation(position, matrix%n), 'grid: a permutation of the equations')
    call suite%check(all([(position(3 * k - 1) == position(3 * k - 2) + 1 .and. &
                           position(3 * k) == position(3 * k - 2) + 2 .and. &
                           mod(position(3 * k - 2), 3) == 1, k = 1, mesh%n_nodes)]), &
                     'grid: a node''s three equations stay together, in order')
    call metis_equation_order(matrix, again, err)
    call suite%check(.not. allocated(err) .and. all(again == position), &
                     'grid: the same order when computed again')
    node_position = [((position(3 * k - 2) + 2) / 3, k = 1, mesh%n_nodes)]
    fill_metis = cholesky_entries(matrix, node_position)
    fill_rcm = cholesky_entries(matrix, invert_permutation(rcm_node_order(matrix)))
    print '(a, i0, a, i0, a)', '  grid of 2197 nodes: factor entries (node graph) METIS ', &
      fill_metis, ', RCM ', fill_rcm, ' (nested dissection must give fewer)'
    call suite%check(fill_metis < fill_rcm, 'grid: less fill than reverse Cuthill-McKee')
  end subroutine check_grid

  !> A diagonal matrix (nodes without couplings): the identity order, no METIS call.
  subroutine check_no_couplings(suite)
    type(test_suite_t), intent(inout) :: suite
    type(sparse_matrix_t) :: matrix
    type(error_t), allocatable :: err
    integer, allocatable :: position(:)
    integer :: k
    call matrix%build(4, [(k, k = 1, 5)], [(k, k = 1, 4)])
    call metis_equation_order(matrix, position, err)
    call suite%check(.not. allocated(err), 'no couplings: no error')
    if (allocated(err)) return
    call suite%check(all(position == [(k, k = 1, 12)]), 'no couplings: the identity order')
  end subroutine check_no_couplings

  !> A pattern of 5 equations in a chain (not 3 per node): ordered equation by equation.
  subroutine check_order_not_multiple_of_3(suite)
    type(test_suite_t), intent(inout) :: suite
    type(sparse_matrix_t) :: matrix
    type(error_t), allocatable :: err
    integer, allocatable :: position(:)
    matrix%n = 5
    matrix%nnz = 13
    matrix%row_ptr = [1, 3, 6, 9, 12, 14]
    matrix%col = [1, 2, 1, 2, 3, 2, 3, 4, 3, 4, 5, 4, 5]
    allocate (matrix%val(13), source=1.0d0)
    call metis_equation_order(matrix, position, err)
    call suite%check(.not. allocated(err), '5 equations: no error')
    if (allocated(err)) return
    call suite%check(is_permutation(position, 5), '5 equations: a permutation')
  end subroutine check_order_not_multiple_of_3

  !> Entries of the Cholesky factor L (diagonal included) of the node graph of `matrix`
  !> eliminated in the order `node_position` (node k is eliminated position(k)-th): for each
  !> row i of the permuted graph, the row subtree of L is the union of the elimination-tree
  !> paths from its neighbours j < i up to i (Liu 1990, sec. 3), marked once each.
  function cholesky_entries(matrix, node_position) result(entries)
    type(sparse_matrix_t), intent(in) :: matrix
    integer, intent(in) :: node_position(:)
    integer(kind=8) :: entries
    integer, allocatable :: node_at(:), parent(:), ancestor(:), mark(:)
    integer :: n, i, j, r, next, node
    integer(kind=8) :: p
    n = size(node_position)
    allocate (node_at(n), parent(n), ancestor(n), mark(n))
    node_at(node_position) = [(i, i = 1, n)]
    ! Elimination tree (Liu 1990, algorithm with path compression through `ancestor`).
    parent = 0
    ancestor = 0
    do i = 1, n
      node = node_at(i)
      do p = matrix%row_ptr(3 * node - 2), matrix%row_ptr(3 * node - 1) - 1
        j = node_position((matrix%col(p) + 2) / 3)
        if (j >= i) cycle
        r = j
        do while (ancestor(r) /= 0 .and. ancestor(r) /= i)
          next = ancestor(r)
          ancestor(r) = i
          r = next
        end do
        if (ancestor(r) == 0) then
          ancestor(r) = i
          parent(r) = i
        end if
      end do
    end do
    ! Row counts: walk from each lower neighbour up the tree until a node already marked for i.
    entries = n
    mark = 0
    do i = 1, n
      mark(i) = i
      node = node_at(i)
      do p = matrix%row_ptr(3 * node - 2), matrix%row_ptr(3 * node - 1) - 1
        j = node_position((matrix%col(p) + 2) / 3)
        if (j >= i) cycle
        r = j
        do while (mark(r) /= i)
          mark(r) = i
          entries = entries + 1
          r = parent(r)
        end do
      end do
    end do
  end function cholesky_entries

end program test_fcs_metis_order
