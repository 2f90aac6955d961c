!> Compressed sparse row matrix with a node-block structure (3 degrees of freedom per node).
!>
!> The pattern is built once from "cliques" (the node lists of elements and contact elements:
!> every pair of nodes in a clique is coupled) and kept while values are refilled each
!> increment. Rows and columns are numbered by degree of freedom, 3*(node-1)+direction.
!> Each node's three rows share one column structure, so the position of a 3x3 node block is
!> found by one binary search in the node adjacency.
module fcs_sparse
  use fcs_kinds, only: dp, i8
  use fcs_sort, only: sort_integers
  implicit none
  private
  public :: sparse_matrix_t, DOFS_PER_NODE

  !> Degrees of freedom per node (displacement components).
  integer, parameter :: DOFS_PER_NODE = 3

  type :: sparse_matrix_t
    !> Number of rows (= columns) and stored entries.
    integer :: n = 0
    integer(i8) :: nnz = 0
    !> Row i's entries are row_ptr(i) .. row_ptr(i+1)-1 (1-based), columns sorted ascending.
    integer(i8), allocatable :: row_ptr(:)
    integer, allocatable :: col(:)
    real(dp), allocatable :: val(:)
    !> Node graph: neighbours of node a (itself included) are node_adj(node_ptr(a):node_ptr(a+1)-1).
    integer :: n_nodes = 0
    integer(i8), allocatable :: node_ptr(:)
    integer, allocatable :: node_adj(:)
    !> Incremented every time the pattern is rebuilt; solvers redo their analysis when it changes.
    integer :: pattern_version = 0
  contains
    procedure :: build => sparse_build
    procedure :: zero => sparse_zero
    procedure :: add_matrix => sparse_add_matrix
    procedure :: add_value => sparse_add_value
    procedure :: has_block => sparse_has_block
    procedure :: multiply => sparse_multiply
    procedure :: apply_dirichlet => sparse_apply_dirichlet
    procedure :: free_diagonal_sum => sparse_free_diagonal_sum
    procedure :: eliminate => sparse_eliminate
    procedure :: set_diagonal => sparse_set_diagonal
    procedure :: diagonal => sparse_diagonal
    procedure :: free => sparse_free
  end type sparse_matrix_t

contains

  !> Build the pattern for `n_nodes` nodes from cliques: clique c holds the nodes
  !> clique_nodes(clique_ptr(c):clique_ptr(c+1)-1). Every node is coupled to itself.
  subroutine sparse_build(this, n_nodes, clique_ptr, clique_nodes)
    class(sparse_matrix_t), intent(inout) :: this
    integer, intent(in) :: n_nodes
    integer, intent(in) :: clique_ptr(:), clique_nodes(:)
    integer, allocatable :: incidence_ptr(:), incidence(:), fill(:), marker(:), buffer(:)
    integer :: n_cliques, c, j, a, b, k, m, count
    integer(i8) :: total, pos
    integer :: row, d
    n_cliques = size(clique_ptr) - 1
    allocate (incidence_ptr(n_nodes + 1), fill(n_nodes), marker(n_nodes), buffer(n_nodes))
    incidence_ptr = 0
    do c = 1, n_cliques
      do j = clique_ptr(c), clique_ptr(c + 1) - 1
        incidence_ptr(clique_nodes(j) + 1) = incidence_ptr(clique_nodes(j) + 1) + 1
      end do
    end do
    incidence_ptr(1) = 1
    do a = 1, n_nodes
      incidence_ptr(a + 1) = incidence_ptr(a + 1) + incidence_ptr(a)
    end do
    allocate (incidence(incidence_ptr(n_nodes + 1) - 1))
    fill = incidence_ptr(1:n_nodes)
    do c = 1, n_cliques
      do j = clique_ptr(c), clique_ptr(c + 1) - 1
        a = clique_nodes(j)
        incidence(fill(a)) = c
        fill(a) = fill(a) + 1
      end do
    end do
    ! Two passes over the node graph: count, then fill.
    if (allocated(this%node_ptr)) deallocate (this%node_ptr)
    allocate (this%node_ptr(n_nodes + 1))
    marker = 0
    this%node_ptr(1) = 1
    do a = 1, n_nodes
      call neighbours(a, count)
      this%node_ptr(a + 1) = this%node_ptr(a) + count
    end do
    if (allocated(this%node_adj)) deallocate (this%node_adj)
    allocate (this%node_adj(this%node_ptr(n_nodes + 1) - 1))
    marker = 0
    do a = 1, n_nodes
      call neighbours(a, count)
      call sort_integers(buffer(1:count))
      this%node_adj(this%node_ptr(a):this%node_ptr(a + 1) - 1) = buffer(1:count)
    end do
    ! Degree-of-freedom rows.
    this%n_nodes = n_nodes
    this%n = DOFS_PER_NODE * n_nodes
    total = DOFS_PER_NODE**2 * (this%node_ptr(n_nodes + 1) - 1)
    this%nnz = total
    if (allocated(this%row_ptr)) deallocate (this%row_ptr)
    if (allocated(this%col)) deallocate (this%col)
    if (allocated(this%val)) deallocate (this%val)
    allocate (this%row_ptr(this%n + 1), this%col(total), this%val(total))
    pos = 1
    do a = 1, n_nodes
      m = int(this%node_ptr(a + 1) - this%node_ptr(a))
      do d = 1, DOFS_PER_NODE
        row = DOFS_PER_NODE * (a - 1) + d
        this%row_ptr(row) = pos
        do k = 1, m
          b = this%node_adj(this%node_ptr(a) + k - 1)
          this%col(pos:pos + DOFS_PER_NODE - 1) = [(DOFS_PER_NODE * (b - 1) + j, j = 1, DOFS_PER_NODE)]
          pos = pos + DOFS_PER_NODE
        end do
      end do
    end do
    this%row_ptr(this%n + 1) = pos
    this%val = 0.0_dp
    this%pattern_version = this%pattern_version + 1
  contains
    subroutine neighbours(node, n_found)
      integer, intent(in) :: node
      integer, intent(out) :: n_found
      integer :: i, jj, other
      n_found = 1
      buffer(1) = node
      marker(node) = node
      do i = incidence_ptr(node), incidence_ptr(node + 1) - 1
        c = incidence(i)
        do jj = clique_ptr(c), clique_ptr(c + 1) - 1
          other = clique_nodes(jj)
          if (marker(other) /= node) then
            marker(other) = node
            n_found = n_found + 1
            buffer(n_found) = other
          end if
        end do
      end do
    end subroutine neighbours
  end subroutine sparse_build

  !> Offset (0-based) of node b in the adjacency list of node a, or -1 if not coupled.
  pure integer function block_offset(this, a, b) result(k)
    type(sparse_matrix_t), intent(in) :: this
    integer, intent(in) :: a, b
    integer(i8) :: lo, hi, mid
    lo = this%node_ptr(a)
    hi = this%node_ptr(a + 1) - 1
    do while (lo <= hi)
      mid = (lo + hi) / 2
      if (this%node_adj(mid) == b) then
        k = int(mid - this%node_ptr(a))
        return
      else if (this%node_adj(mid) < b) then
        lo = mid + 1
      else
        hi = mid - 1
      end if
    end do
    k = -1
  end function block_offset

  !> True when nodes a and b are coupled in the pattern.
  pure logical function sparse_has_block(this, a, b)
    class(sparse_matrix_t), intent(in) :: this
    integer, intent(in) :: a, b
    sparse_has_block = block_offset(this, a, b) >= 0
  end function sparse_has_block

  !> Set all values to zero, keeping the pattern.
  subroutine sparse_zero(this)
    class(sparse_matrix_t), intent(inout) :: this
    this%val = 0.0_dp
  end subroutine sparse_zero

  !> Add a dense matrix `k` (3m x 3m, dof order node-major) coupling `nodes(1:m)`.
  !> `missing` is true if a pair of nodes is not in the pattern (nothing is added for it).
  subroutine sparse_add_matrix(this, nodes, k, missing)
    class(sparse_matrix_t), intent(inout) :: this
    integer, intent(in) :: nodes(:)
    real(dp), intent(in) :: k(:, :)
    logical, intent(out) :: missing
    integer :: i, j, d, e, offset
    integer(i8) :: pos
    missing = .false.
    do i = 1, size(nodes)
      do j = 1, size(nodes)
        offset = block_offset(this, nodes(i), nodes(j))
        if (offset < 0) then
          missing = .true.
          cycle
        end if
        do d = 1, DOFS_PER_NODE
          pos = this%row_ptr(DOFS_PER_NODE * (nodes(i) - 1) + d) + DOFS_PER_NODE * offset
          do e = 1, DOFS_PER_NODE
            this%val(pos + e - 1) = this%val(pos + e - 1) + &
              k(DOFS_PER_NODE * (i - 1) + d, DOFS_PER_NODE * (j - 1) + e)
          end do
        end do
      end do
    end do
  end subroutine sparse_add_matrix

  !> a_ij = a_ij + value (row i, column j: degrees of freedom). `missing` is true, and
  !> nothing is added, if nodes of i and j are not coupled in the pattern.
  subroutine sparse_add_value(this, i, j, value, missing)
    class(sparse_matrix_t), intent(inout) :: this
    integer, intent(in) :: i, j
    real(dp), intent(in) :: value
    logical, intent(out) :: missing
    integer :: offset
    integer(i8) :: pos
    offset = block_offset(this, (i - 1) / DOFS_PER_NODE + 1, (j - 1) / DOFS_PER_NODE + 1)
    missing = offset < 0
    if (missing) return
    pos = this%row_ptr(i) + DOFS_PER_NODE * offset + (j - 1 - DOFS_PER_NODE * ((j - 1) / DOFS_PER_NODE))
    this%val(pos) = this%val(pos) + value
  end subroutine sparse_add_value

  !> y = A x.
  subroutine sparse_multiply(this, x, y)
    class(sparse_matrix_t), intent(in) :: this
    real(dp), intent(in) :: x(:)
    real(dp), intent(out) :: y(:)
    integer :: i
    integer(i8) :: p
    do i = 1, this%n
      y(i) = 0.0_dp
      do p = this%row_ptr(i), this%row_ptr(i + 1) - 1
        y(i) = y(i) + this%val(p) * x(this%col(p))
      end do
    end do
  end subroutine sparse_multiply

  !> Diagonal entries.
  function sparse_diagonal(this) result(d)
    class(sparse_matrix_t), intent(in) :: this
    real(dp), allocatable :: d(:)
    integer :: i
    integer(i8) :: p
    allocate (d(this%n))
    d = 0.0_dp
    do i = 1, this%n
      do p = this%row_ptr(i), this%row_ptr(i + 1) - 1
        if (this%col(p) == i) d(i) = this%val(p)
      end do
    end do
  end function sparse_diagonal

  !> Impose prescribed values: for every constrained dof j, x_j = values(j). The known
  !> values move to the right-hand side of the free rows (rhs_i -= a_ij x_j, a_ij = 0), and each
  !> constrained row becomes `scale` times the identity with rhs = scale * value, `scale` being
  !> the mean absolute diagonal of the free rows (keeps the conditioning of the system).
  !> (A distributed system calls the three steps below separately, summing between them.)
  subroutine sparse_apply_dirichlet(this, constrained, values, rhs)
    class(sparse_matrix_t), intent(inout) :: this
    logical, intent(in) :: constrained(:)
    real(dp), intent(in) :: values(:)
    real(dp), intent(inout) :: rhs(:)
    real(dp) :: scale, total
    integer :: n_free
    call this%free_diagonal_sum(constrained, total, n_free)
    scale = 1.0_dp
    if (n_free > 0) scale = total / n_free
    if (scale <= 0.0_dp) scale = 1.0_dp
    call this%eliminate(constrained, values, rhs)
    call this%set_diagonal(constrained, scale)
    where (constrained) rhs = scale * values
  end subroutine sparse_apply_dirichlet

  !> Sum of |a_ii| over the free rows, and their number.
  subroutine sparse_free_diagonal_sum(this, constrained, total, n_free)
    class(sparse_matrix_t), intent(in) :: this
    logical, intent(in) :: constrained(:)
    real(dp), intent(out) :: total
    integer, intent(out) :: n_free
    integer :: i
    integer(i8) :: p
    total = 0.0_dp
    n_free = 0
    do i = 1, this%n
      if (constrained(i)) cycle
      do p = this%row_ptr(i), this%row_ptr(i + 1) - 1
        if (this%col(p) == i) total = total + abs(this%val(p))
      end do
      n_free = n_free + 1
    end do
  end subroutine sparse_free_diagonal_sum

  !> Move the known values of constrained columns to the right-hand side of the free rows
  !> (rhs_i -= a_ij x_j) and zero those entries and every entry of the constrained rows.
  subroutine sparse_eliminate(this, constrained, values, rhs)
    class(sparse_matrix_t), intent(inout) :: this
    logical, intent(in) :: constrained(:)
    real(dp), intent(in) :: values(:)
    real(dp), intent(inout) :: rhs(:)
    integer :: i
    integer(i8) :: p
    do i = 1, this%n
      if (constrained(i)) then
        this%val(this%row_ptr(i):this%row_ptr(i + 1) - 1) = 0.0_dp
        cycle
      end if
      do p = this%row_ptr(i), this%row_ptr(i + 1) - 1
        if (constrained(this%col(p))) then
          rhs(i) = rhs(i) - this%val(p) * values(this%col(p))
          this%val(p) = 0.0_dp
        end if
      end do
    end do
  end subroutine sparse_eliminate

  !> a_ii = value on the constrained rows (the pattern must hold their diagonals).
  subroutine sparse_set_diagonal(this, constrained, value)
    class(sparse_matrix_t), intent(inout) :: this
    logical, intent(in) :: constrained(:)
    real(dp), intent(in) :: value
    integer :: i
    integer(i8) :: p
    do i = 1, this%n
      if (.not. constrained(i)) cycle
      do p = this%row_ptr(i), this%row_ptr(i + 1) - 1
        if (this%col(p) == i) this%val(p) = value
      end do
    end do
  end subroutine sparse_set_diagonal

  subroutine sparse_free(this)
    class(sparse_matrix_t), intent(inout) :: this
    if (allocated(this%row_ptr)) deallocate (this%row_ptr)
    if (allocated(this%col)) deallocate (this%col)
    if (allocated(this%val)) deallocate (this%val)
    if (allocated(this%node_ptr)) deallocate (this%node_ptr)
    if (allocated(this%node_adj)) deallocate (this%node_adj)
    this%n = 0
    this%nnz = 0
    this%n_nodes = 0
  end subroutine sparse_free

end module fcs_sparse
