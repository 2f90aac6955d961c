!> Test matrices for the solver unit tests: node patterns from cliques (a small 3D grid of
!> 8-node elements plus a few 2-node and 5-node cliques, like contact elements), random
!> unsymmetric diagonally dominant values, stiffness-like values (a truss of springs, positive
!> definite once supported, plus an unsymmetric perturbation), and an independent dense oracle.
module fcs_test_matrices
  use fcs_kinds, only: dp, i8
  use fcs_sparse, only: sparse_matrix_t, DOFS_PER_NODE
  implicit none
  private
  public :: random_stream_t, test_mesh_t, make_grid_mesh, make_chain_mesh, build_pattern
  public :: fill_random_dominant, fill_stiffness_like, dense_solve, relative_residual
  public :: relative_difference, base_constraints, contains_text

  !> Park-Miller "minimal standard" generator (Park & Miller 1988): reproducible on every
  !> compiler, 64-bit arithmetic without overflow.
  type :: random_stream_t
    integer(i8) :: state = 12345_i8
  contains
    procedure :: uniform => random_uniform
  end type random_stream_t

  !> Nodes with coordinates and the cliques that couple them.
  type :: test_mesh_t
    integer :: n_nodes = 0
    real(dp), allocatable :: coords(:, :)
    integer, allocatable :: clique_ptr(:), clique_nodes(:)
  end type test_mesh_t

contains

  !> Uniform number in (lo, hi).
  function random_uniform(this, lo, hi) result(value)
    class(random_stream_t), intent(inout) :: this
    real(dp), intent(in) :: lo, hi
    real(dp) :: value
    integer(i8), parameter :: MULTIPLIER = 16807_i8, MODULUS = 2147483647_i8
    this%state = mod(MULTIPLIER * this%state, MODULUS)
    value = lo + (hi - lo) * real(this%state, dp) / real(MODULUS, dp)
  end function random_uniform

  !> A grid of nx*ny*nz 8-node elements (unit spacing), one 2-node clique coupling two
  !> opposite corners and one 5-node clique (a node and the four corners of a top face), like
  !> a spring and a node-to-surface contact element. With `shuffle_seed` > 0 the node numbers
  !> are randomly permuted.
  function make_grid_mesh(nx, ny, nz, shuffle_seed) result(mesh)
    integer, intent(in) :: nx, ny, nz, shuffle_seed
    type(test_mesh_t) :: mesh
    integer, allocatable :: number(:), nodes(:)
    integer :: i, j, k, c, n_cliques
    mesh%n_nodes = (nx + 1) * (ny + 1) * (nz + 1)
    call node_numbering(mesh%n_nodes, shuffle_seed, number)
    allocate (mesh%coords(3, mesh%n_nodes))
    do k = 0, nz
      do j = 0, ny
        do i = 0, nx
          mesh%coords(:, number(grid_node(i, j, k))) = [real(i, dp), real(j, dp), real(k, dp)]
        end do
      end do
    end do
    n_cliques = nx * ny * nz + 2
    allocate (mesh%clique_ptr(n_cliques + 1), nodes(0))
    mesh%clique_ptr(1) = 1
    c = 0
    do k = 0, nz - 1
      do j = 0, ny - 1
        do i = 0, nx - 1
          nodes = [nodes, grid_node(i, j, k), grid_node(i + 1, j, k), grid_node(i + 1, j + 1, k), &
                   grid_node(i, j + 1, k), grid_node(i, j, k + 1), grid_node(i + 1, j, k + 1), &
                   grid_node(i + 1, j + 1, k + 1), grid_node(i, j + 1, k + 1)]
          c = c + 1
          mesh%clique_ptr(c + 1) = size(nodes) + 1
        end do
      end do
    end do
    nodes = [nodes, grid_node(0, 0, 0), grid_node(nx, ny, nz)]
    c = c + 1
    mesh%clique_ptr(c + 1) = size(nodes) + 1
    nodes = [nodes, grid_node(0, ny, nz), grid_node(nx - 1, 0, nz), grid_node(nx, 0, nz), &
             grid_node(nx, 1, nz), grid_node(nx - 1, 1, nz)]
    c = c + 1
    mesh%clique_ptr(c + 1) = size(nodes) + 1
    mesh%clique_nodes = number(nodes)
  contains
    pure integer function grid_node(ii, jj, kk)
      integer, intent(in) :: ii, jj, kk
      grid_node = 1 + ii + (nx + 1) * (jj + (ny + 1) * kk)
    end function grid_node
  end function make_grid_mesh

  !> A chain of `n_nodes` nodes along x joined by 2-node cliques, randomly numbered when
  !> `shuffle_seed` > 0.
  function make_chain_mesh(n_nodes, shuffle_seed) result(mesh)
    integer, intent(in) :: n_nodes, shuffle_seed
    type(test_mesh_t) :: mesh
    integer, allocatable :: number(:)
    integer :: i
    mesh%n_nodes = n_nodes
    call node_numbering(n_nodes, shuffle_seed, number)
    allocate (mesh%coords(3, n_nodes), mesh%clique_ptr(n_nodes))
    allocate (mesh%clique_nodes(2 * (n_nodes - 1)))
    do i = 1, n_nodes
      mesh%coords(:, number(i)) = [real(i, dp), 0.0_dp, 0.0_dp]
    end do
    do i = 1, n_nodes - 1
      mesh%clique_ptr(i) = 2 * i - 1
      mesh%clique_nodes(2 * i - 1:2 * i) = [number(i), number(i + 1)]
    end do
    mesh%clique_ptr(n_nodes) = 2 * n_nodes - 1
  end function make_chain_mesh

  !> number(old) = new: identity, or a random permutation (Fisher-Yates) when seed > 0.
  subroutine node_numbering(n, seed, number)
    integer, intent(in) :: n, seed
    integer, allocatable, intent(out) :: number(:)
    type(random_stream_t) :: random
    integer :: i, j, tmp
    number = [(i, i = 1, n)]
    if (seed <= 0) return
    random%state = int(seed, i8)
    do i = n, 2, -1
      j = min(i, 1 + int(random%uniform(0.0_dp, 1.0_dp) * i))
      tmp = number(i)
      number(i) = number(j)
      number(j) = tmp
    end do
  end subroutine node_numbering

  !> Build the pattern of `matrix` from the cliques of `mesh`.
  subroutine build_pattern(mesh, matrix)
    type(test_mesh_t), intent(in) :: mesh
    type(sparse_matrix_t), intent(inout) :: matrix
    call matrix%build(mesh%n_nodes, mesh%clique_ptr, mesh%clique_nodes)
  end subroutine build_pattern

  !> Random values in (-1, 1) on the whole pattern, then each diagonal set to 1 plus the sum of
  !> the magnitudes of its row: unsymmetric, strictly diagonally dominant, so LU without
  !> pivoting is stable.
  subroutine fill_random_dominant(matrix, seed)
    type(sparse_matrix_t), intent(inout) :: matrix
    integer, intent(in) :: seed
    type(random_stream_t) :: random
    integer :: i
    integer(i8) :: p, diagonal
    random%state = int(seed, i8)
    do i = 1, matrix%n
      diagonal = -1
      do p = matrix%row_ptr(i), matrix%row_ptr(i + 1) - 1
        matrix%val(p) = random%uniform(-1.0_dp, 1.0_dp)
        if (matrix%col(p) == i) diagonal = p
      end do
      matrix%val(diagonal) = 0.0_dp
      matrix%val(diagonal) = 1.0_dp + &
        sum(abs(matrix%val(matrix%row_ptr(i):matrix%row_ptr(i + 1) - 1)))
    end do
  end subroutine fill_random_dominant

  !> Stiffness-like values: every pair of nodes of every clique is joined by an axial spring
  !> of stiffness E A / L = 1/L (E A = 1 N), k = (1/L) n n^T with n the unit vector between the
  !> nodes. With `supported`, the nodes on z = 0 also get a grounded spring of stiffness 1 N/m
  !> in each direction (the truss is otherwise free: six rigid-body modes). Then every entry
  !> gets an unsymmetric random perturbation of relative size `perturbation` (of the mean
  !> diagonal), as friction makes a tangent unsymmetric.
  subroutine fill_stiffness_like(matrix, mesh, seed, supported, perturbation)
    type(sparse_matrix_t), intent(inout) :: matrix
    type(test_mesh_t), intent(in) :: mesh
    integer, intent(in) :: seed
    logical, intent(in) :: supported
    real(dp), intent(in) :: perturbation
    type(random_stream_t) :: random
    real(dp) :: k_e(6, 6), k_s(3, 3), direction(3), length, scale
    integer :: c, i, j, a, b, d
    integer(i8) :: p
    logical :: missing
    call matrix%zero()
    do c = 1, size(mesh%clique_ptr) - 1
      do i = mesh%clique_ptr(c), mesh%clique_ptr(c + 1) - 1
        do j = i + 1, mesh%clique_ptr(c + 1) - 1
          a = mesh%clique_nodes(i)
          b = mesh%clique_nodes(j)
          direction = mesh%coords(:, b) - mesh%coords(:, a)
          length = norm2(direction)
          direction = direction / length
          k_s = spread(direction, 2, 3) * spread(direction, 1, 3) / length
          k_e(1:3, 1:3) = k_s
          k_e(4:6, 4:6) = k_s
          k_e(1:3, 4:6) = -k_s
          k_e(4:6, 1:3) = -k_s
          call matrix%add_matrix([a, b], k_e, missing)
        end do
      end do
    end do
    if (supported) then
      k_s = 0.0_dp
      do d = 1, 3
        k_s(d, d) = 1.0_dp
      end do
      do a = 1, mesh%n_nodes
        if (mesh%coords(3, a) == 0.0_dp) call matrix%add_matrix([a], k_s, missing)
      end do
    end if
    scale = perturbation * sum(abs(matrix%diagonal())) / matrix%n
    random%state = int(seed, i8)
    do p = 1, matrix%nnz
      matrix%val(p) = matrix%val(p) + scale * random%uniform(-1.0_dp, 1.0_dp)
    end do
  end subroutine fill_stiffness_like

  !> Constrained flags and prescribed values for the three directions of every node on z = 0.
  subroutine base_constraints(mesh, constrained, values)
    type(test_mesh_t), intent(in) :: mesh
    logical, allocatable, intent(out) :: constrained(:)
    real(dp), allocatable, intent(out) :: values(:)
    integer :: a, d, dof
    allocate (constrained(DOFS_PER_NODE * mesh%n_nodes), values(DOFS_PER_NODE * mesh%n_nodes))
    constrained = .false.
    values = 0.0_dp
    do a = 1, mesh%n_nodes
      if (mesh%coords(3, a) /= 0.0_dp) cycle
      do d = 1, DOFS_PER_NODE
        dof = DOFS_PER_NODE * (a - 1) + d
        constrained(dof) = .true.
        values(dof) = 0.01_dp * d + 0.001_dp * a
      end do
    end do
  end subroutine base_constraints

  !> Oracle: x solving A x = b by dense Gaussian elimination with partial pivoting.
  function dense_solve(matrix, b) result(x)
    type(sparse_matrix_t), intent(in) :: matrix
    real(dp), intent(in) :: b(:)
    real(dp), allocatable :: x(:)
    real(dp), allocatable :: a(:, :), row(:)
    real(dp) :: factor, rhs
    integer :: i, j, k, pivot
    integer(i8) :: p
    allocate (a(matrix%n, matrix%n))
    a = 0.0_dp
    do i = 1, matrix%n
      do p = matrix%row_ptr(i), matrix%row_ptr(i + 1) - 1
        a(i, matrix%col(p)) = matrix%val(p)
      end do
    end do
    x = b
    do k = 1, matrix%n - 1
      pivot = k - 1 + maxloc(abs(a(k:, k)), dim=1)
      if (pivot /= k) then
        row = a(k, :)
        a(k, :) = a(pivot, :)
        a(pivot, :) = row
        rhs = x(k)
        x(k) = x(pivot)
        x(pivot) = rhs
      end if
      do i = k + 1, matrix%n
        factor = a(i, k) / a(k, k)
        a(i, k + 1:) = a(i, k + 1:) - factor * a(k, k + 1:)
        x(i) = x(i) - factor * x(k)
      end do
    end do
    do j = matrix%n, 1, -1
      x(j) = (x(j) - dot_product(a(j, j + 1:), x(j + 1:))) / a(j, j)
    end do
  end function dense_solve

  !> ||A x - b|| / ||b|| (Euclidean norms).
  function relative_residual(matrix, x, b) result(ratio)
    type(sparse_matrix_t), intent(in) :: matrix
    real(dp), intent(in) :: x(:), b(:)
    real(dp) :: ratio
    real(dp), allocatable :: ax(:)
    allocate (ax(matrix%n))
    call matrix%multiply(x, ax)
    ratio = norm2(ax - b) / norm2(b)
  end function relative_residual

  !> ||x - y|| / ||y||.
  pure real(dp) function relative_difference(x, y)
    real(dp), intent(in) :: x(:), y(:)
    relative_difference = norm2(x - y) / norm2(y)
  end function relative_difference

  !> True when `text` contains `part`.
  pure logical function contains_text(text, part)
    character(len=*), intent(in) :: text, part
    contains_text = index(text, part) > 0
  end function contains_text

end module fcs_test_matrices
