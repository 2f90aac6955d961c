!> Reverse Cuthill-McKee ordering of the node graph of a sparse matrix, and the profile
!> (envelope) size that ordering gives.
!>
!> The ordering works on nodes, not on degrees of freedom: the three degrees of freedom of a
!> node stay together and follow their node (dof 3*(k-1)+d of the permuted matrix is direction d
!> of node order(k)). Each connected component is numbered from a pseudo-peripheral node found
!> with the algorithm of Gibbs, Poole and Stockmeyer as refined by George and Liu, then the whole
!> Cuthill-McKee sequence is reversed.
!>
!> References: A. George and J. W.-H. Liu, "Computer Solution of Large Sparse Positive Definite
!> Systems", Prentice-Hall 1981: section 4.3.2 (Cuthill-McKee and its reverse), section 4.3.3
!> (pseudo-peripheral node, subroutine FNROOT), section 4.2 (profile / envelope).
module fcs_rcm
  use fcs_kinds, only: i8
  use fcs_sort, only: argsort_integers
  use fcs_sparse, only: sparse_matrix_t, DOFS_PER_NODE
  implicit none
  private
  public :: rcm_node_order, invert_permutation, dof_order_from_nodes, profile_size

  !> Work arrays of one ordering: node degrees (self excluded), the numbered flags, the current
  !> rooted level structure, visit stamps, and room for the fresh neighbours of one node.
  type :: rcm_work_t
    integer, allocatable :: degree(:)
    logical, allocatable :: numbered(:)
    integer, allocatable :: level_ptr(:), level_nodes(:)
    integer, allocatable :: mark(:)
    integer, allocatable :: fresh(:)
    integer :: stamp = 0
  end type rcm_work_t

contains

  !> Reverse Cuthill-McKee order of the nodes of `matrix`: `order(k)` is the original number of
  !> the node placed k-th. Disconnected components are numbered one after the other, each from
  !> its own pseudo-peripheral node (George & Liu 1981, sections 4.3.2-4.3.3). The cost is
  !> proportional to the size of the graph times the number of root searches per component.
  function rcm_node_order(matrix) result(order)
    type(sparse_matrix_t), intent(in) :: matrix
    integer, allocatable :: order(:)
    type(rcm_work_t) :: work
    integer :: n_nodes, n_done, node, root
    n_nodes = matrix%n_nodes
    allocate (order(n_nodes), work%degree(n_nodes), work%numbered(n_nodes), work%mark(n_nodes))
    allocate (work%level_ptr(n_nodes + 1), work%level_nodes(n_nodes))
    do node = 1, n_nodes
      work%degree(node) = node_degree(matrix, node)
    end do
    allocate (work%fresh(max(0, maxval(work%degree)) + 1))
    work%numbered = .false.
    work%mark = 0
    n_done = 0
    do node = 1, n_nodes
      if (work%numbered(node)) cycle
      root = pseudo_peripheral_node(matrix, node, work)
      call cuthill_mckee_component(matrix, root, work, order, n_done)
    end do
    order = order(n_nodes:1:-1)
  end function rcm_node_order

  !> Number of neighbours of `node` in the node graph, the node itself excluded.
  pure integer function node_degree(matrix, node) result(degree)
    type(sparse_matrix_t), intent(in) :: matrix
    integer, intent(in) :: node
    integer(i8) :: p
    degree = 0
    do p = matrix%node_ptr(node), matrix%node_ptr(node + 1) - 1
      if (matrix%node_adj(p) /= node) degree = degree + 1
    end do
  end function node_degree

  !> Rooted level structure of the component of `root` among the nodes not yet numbered:
  !> level k holds work%level_nodes(work%level_ptr(k):work%level_ptr(k+1)-1) (George & Liu
  !> 1981, section 4.3.3, subroutine ROOTLS). `n_levels` is the eccentricity of `root` plus one.
  !> Visited nodes are marked with a fresh stamp, so the cost is that of the component only.
  pure subroutine rooted_level_structure(matrix, root, work, n_levels)
    type(sparse_matrix_t), intent(in) :: matrix
    integer, intent(in) :: root
    type(rcm_work_t), intent(inout) :: work
    integer, intent(out) :: n_levels
    integer :: level_start, level_end, n_found, i, other, node
    integer(i8) :: p
    work%stamp = work%stamp + 1
    work%mark(root) = work%stamp
    work%level_nodes(1) = root
    n_found = 1
    level_start = 1
    n_levels = 0
    do while (level_start <= n_found)
      level_end = n_found
      n_levels = n_levels + 1
      work%level_ptr(n_levels) = level_start
      do i = level_start, level_end
        node = work%level_nodes(i)
        do p = matrix%node_ptr(node), matrix%node_ptr(node + 1) - 1
          other = matrix%node_adj(p)
          if (work%numbered(other) .or. work%mark(other) == work%stamp) cycle
          work%mark(other) = work%stamp
          n_found = n_found + 1
          work%level_nodes(n_found) = other
        end do
      end do
      level_start = level_end + 1
    end do
    work%level_ptr(n_levels + 1) = n_found + 1
  end subroutine rooted_level_structure

  !> A pseudo-peripheral node of the component of `start` (George & Liu 1981, section 4.3.3,
  !> subroutine FNROOT): build the level structure rooted at the current node, move to a node of
  !> minimum degree in its last level, and repeat while the number of levels grows.
  function pseudo_peripheral_node(matrix, start, work) result(root)
    type(sparse_matrix_t), intent(in) :: matrix
    integer, intent(in) :: start
    type(rcm_work_t), intent(inout) :: work
    integer :: root, n_levels, previous_levels, component_size, i, last_first
    root = start
    call rooted_level_structure(matrix, root, work, n_levels)
    component_size = work%level_ptr(n_levels + 1) - 1
    do while (n_levels > 1 .and. n_levels < component_size)
      last_first = work%level_ptr(n_levels)
      root = work%level_nodes(last_first)
      do i = last_first + 1, work%level_ptr(n_levels + 1) - 1
        if (work%degree(work%level_nodes(i)) < work%degree(root)) root = work%level_nodes(i)
      end do
      previous_levels = n_levels
      call rooted_level_structure(matrix, root, work, n_levels)
      if (n_levels <= previous_levels) exit
    end do
  end function pseudo_peripheral_node

  !> Cuthill-McKee numbering of the component of `root`: breadth-first from `root`, the
  !> unnumbered neighbours of each node taken in increasing degree, ties in increasing node
  !> number (George & Liu 1981, section 4.3.2, subroutine RCM before the reversal). Appends the
  !> component to order(n_done+1:).
  subroutine cuthill_mckee_component(matrix, root, work, order, n_done)
    type(sparse_matrix_t), intent(in) :: matrix
    integer, intent(in) :: root
    type(rcm_work_t), intent(inout) :: work
    integer, intent(inout) :: order(:)
    integer, intent(inout) :: n_done
    integer, allocatable :: by_degree(:)
    integer :: head, node, n_fresh, other, k
    integer(i8) :: p
    work%numbered(root) = .true.
    n_done = n_done + 1
    order(n_done) = root
    head = n_done
    do while (head <= n_done)
      node = order(head)
      head = head + 1
      n_fresh = 0
      do p = matrix%node_ptr(node), matrix%node_ptr(node + 1) - 1
        other = matrix%node_adj(p)
        if (work%numbered(other)) cycle
        work%numbered(other) = .true.
        n_fresh = n_fresh + 1
        work%fresh(n_fresh) = other
      end do
      by_degree = argsort_integers(work%degree(work%fresh(1:n_fresh)))
      do k = 1, n_fresh
        order(n_done + k) = work%fresh(by_degree(k))
      end do
      n_done = n_done + n_fresh
    end do
  end subroutine cuthill_mckee_component

  !> Inverse of a permutation: position(order(k)) = k.
  pure function invert_permutation(order) result(position)
    integer, intent(in) :: order(:)
    integer, allocatable :: position(:)
    integer :: k
    allocate (position(size(order)))
    do k = 1, size(order)
      position(order(k)) = k
    end do
  end function invert_permutation

  !> Degree-of-freedom order that follows a node order: dof_order(3*(k-1)+d) is the original
  !> number of direction d of node node_order(k).
  pure function dof_order_from_nodes(node_order) result(dof_order)
    integer, intent(in) :: node_order(:)
    integer, allocatable :: dof_order(:)
    integer :: k, d
    allocate (dof_order(DOFS_PER_NODE * size(node_order)))
    do k = 1, size(node_order)
      do d = 1, DOFS_PER_NODE
        dof_order(DOFS_PER_NODE * (k - 1) + d) = DOFS_PER_NODE * (node_order(k) - 1) + d
      end do
    end do
  end function dof_order_from_nodes

  !> Profile (envelope) size of `matrix` renumbered by the node order `node_order`: the sum over
  !> the degree-of-freedom rows i of the row bandwidth i - f(i), f(i) being the first column of
  !> row i in the lower triangle (George & Liu 1981, section 4.2, |Env(A)|). A skyline solver
  !> stores n + 2 * profile_size values for an unsymmetric matrix with this symmetric pattern.
  !> A node at position k whose lowest-numbered neighbour is at position q contributes, over its
  !> three rows, sum_{d=1..3} (3(k-q) + d - 1) = 9(k-q) + 3.
  function profile_size(matrix, node_order) result(profile)
    type(sparse_matrix_t), intent(in) :: matrix
    integer, intent(in) :: node_order(:)
    integer(i8) :: profile
    integer, allocatable :: position(:)
    integer :: k, first, d
    integer(i8) :: p
    allocate (position(size(node_order)))
    position(:) = invert_permutation(node_order)
    profile = 0
    do k = 1, size(node_order)
      first = k
      do p = matrix%node_ptr(node_order(k)), matrix%node_ptr(node_order(k) + 1) - 1
        first = min(first, position(matrix%node_adj(p)))
      end do
      do d = 1, DOFS_PER_NODE
        profile = profile + int(DOFS_PER_NODE * (k - first) + d - 1, i8)
      end do
    end do
  end function profile_size

end module fcs_rcm
