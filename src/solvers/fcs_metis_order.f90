!> Fill-reducing ordering of a sparse matrix by METIS nested dissection (METIS_NodeND;
!> G. Karypis and V. Kumar, "A fast and high quality multilevel scheme for partitioning
!> irregular graphs", SIAM J. Sci. Comput. 20(1), 359-392, 1998; METIS 5.1 manual, sec. 5.7).
!>
!> The matrices of fcs3d have three degrees of freedom per node, coupled in full 3x3 blocks,
!> so the graph ordered is that of the nodes (rows 3k-2..3k give node k's neighbours), which
!> has 9x fewer edges than that of the equations; the equations of a node stay together. METIS's
!> default options use a fixed random seed, so the ordering is the same in every run and on
!> any number of processes (doc/theory.md, section 7).
module fcs_metis_order
  use, intrinsic :: iso_c_binding, only: c_int, c_ptr, c_null_ptr
  use fcs_kinds, only: i8
  use fcs_error, only: error_t, fatal_error
  use fcs_strings, only: str
  use fcs_sparse, only: sparse_matrix_t
  use fcs_sort, only: sort_integers, unique_sorted
  implicit none
  private
  public :: metis_equation_order

  !> metis.h (METIS 5.1, IDXTYPEWIDTH 32): options array length, return codes, and the
  !> index of the numbering option (0: C numbering).
  integer, parameter :: METIS_NOPTIONS = 40
  integer(c_int), parameter :: METIS_OK = 1_c_int, METIS_ERROR_INPUT = -2_c_int
  integer(c_int), parameter :: METIS_ERROR_MEMORY = -3_c_int

  interface
    !> int METIS_SetDefaultOptions(idx_t *options);
    function metis_set_default_options(options) result(status) &
        bind(c, name='METIS_SetDefaultOptions')
      import :: c_int, METIS_NOPTIONS
      integer(c_int), intent(out) :: options(METIS_NOPTIONS)
      integer(c_int) :: status
    end function metis_set_default_options

    !> int METIS_NodeND(idx_t *nvtxs, idx_t *xadj, idx_t *adjncy, idx_t *vwgt,
    !>                  idx_t *options, idx_t *perm, idx_t *iperm);
    function metis_node_nd(nvtxs, xadj, adjncy, vwgt, options, perm, iperm) result(status) &
        bind(c, name='METIS_NodeND')
      import :: c_int, c_ptr, METIS_NOPTIONS
      integer(c_int), intent(in) :: nvtxs
      integer(c_int), intent(in) :: xadj(*), adjncy(*)
      type(c_ptr), value :: vwgt
      integer(c_int), intent(in) :: options(METIS_NOPTIONS)
      integer(c_int), intent(out) :: perm(*), iperm(*)
      integer(c_int) :: status
    end function metis_node_nd
  end interface

contains

  !> position(i): the place of equation i in the elimination order (1-based; MUMPS's
  !> PERM_IN). For a matrix whose order is not a multiple of 3, the graph of the equations
  !> themselves is ordered.
  subroutine metis_equation_order(matrix, position, err)
    type(sparse_matrix_t), intent(in) :: matrix
    integer, allocatable, intent(out) :: position(:)
    type(error_t), allocatable, intent(out) :: err
    integer :: block, n_vertices, k, c
    integer(c_int), allocatable :: xadj(:), adjncy(:), perm(:), iperm(:)
    integer(c_int) :: options(METIS_NOPTIONS), status
    block = 3
    if (mod(matrix%n, 3) /= 0) block = 1
    n_vertices = matrix%n / block
    call block_graph(matrix, block, xadj, adjncy)
    allocate (perm(n_vertices), iperm(n_vertices), position(matrix%n))
    if (size(adjncy) == 0) then
      ! No couplings (a diagonal matrix): any order is as good; METIS refuses an empty graph.
      position = [(k, k = 1, matrix%n)]
      return
    end if
    status = metis_set_default_options(options)
    if (status == METIS_OK) status = metis_node_nd(int(n_vertices, c_int), xadj, adjncy, &
                                                   c_null_ptr, options, perm, iperm)
    if (status /= METIS_OK) then
      call fatal_error(err, 'METIS nested-dissection ordering (METIS_NodeND) of ' // &
        str(n_vertices) // ' vertices: ' // status_text(status))
      return
    end if
    do k = 1, n_vertices
      do c = 1, block
        position(block * (k - 1) + c) = block * int(iperm(k)) + c
      end do
    end do
  end subroutine metis_equation_order

  !> The graph of the vertices (groups of `block` consecutive equations) in METIS's 0-based
  !> compressed form: symmetric (an edge for every coupling in either direction, as METIS
  !> requires), without self loops or repeats, from all the rows of each group.
  subroutine block_graph(matrix, block, xadj, adjncy)
    type(sparse_matrix_t), intent(in) :: matrix
    integer, intent(in) :: block
    integer(c_int), allocatable, intent(out) :: xadj(:), adjncy(:)
    integer, allocatable :: degree(:), fill(:), edges(:), unique(:)
    integer :: n_vertices, k, neighbour, first, last, n_kept
    integer(i8) :: p
    n_vertices = matrix%n / block
    allocate (degree(n_vertices), source=0)
    do k = 1, n_vertices
      do p = first_row_start(k), first_row_start(k + 1) - 1
        neighbour = (matrix%col(p) - 1) / block + 1
        if (neighbour == k) cycle
        degree(k) = degree(k) + 1
        degree(neighbour) = degree(neighbour) + 1
      end do
    end do
    allocate (fill(n_vertices + 1))
    fill(1) = 1
    do k = 1, n_vertices
      fill(k + 1) = fill(k) + degree(k)
    end do
    allocate (edges(fill(n_vertices + 1) - 1))
    degree = 0
    do k = 1, n_vertices
      do p = first_row_start(k), first_row_start(k + 1) - 1
        neighbour = (matrix%col(p) - 1) / block + 1
        if (neighbour == k) cycle
        edges(fill(k) + degree(k)) = neighbour
        degree(k) = degree(k) + 1
        edges(fill(neighbour) + degree(neighbour)) = k
        degree(neighbour) = degree(neighbour) + 1
      end do
    end do
    allocate (xadj(n_vertices + 1), adjncy(size(edges)))
    xadj(1) = 0
    n_kept = 0
    do k = 1, n_vertices
      first = fill(k)
      last = fill(k + 1) - 1
      if (last >= first) then
        call sort_integers(edges(first:last))
        unique = unique_sorted(edges(first:last))
        adjncy(n_kept + 1:n_kept + size(unique)) = int(unique - 1, c_int)
        n_kept = n_kept + size(unique)
      end if
      xadj(k + 1) = int(n_kept, c_int)
    end do
    adjncy = adjncy(1:n_kept)
  contains
    !> Start of vertex k's rows in the matrix (k = n_vertices + 1: the end of the matrix).
    integer(i8) function first_row_start(k)
      integer, intent(in) :: k
      first_row_start = matrix%row_ptr(block * (k - 1) + 1)
    end function first_row_start
  end subroutine block_graph

  pure function status_text(status) result(text)
    integer(c_int), intent(in) :: status
    character(len=:), allocatable :: text
    select case (status)
    case (METIS_ERROR_INPUT)
      text = 'input error (METIS_ERROR_INPUT)'
    case (METIS_ERROR_MEMORY)
      text = 'out of memory (METIS_ERROR_MEMORY)'
    case default
      text = 'error (status ' // str(int(status)) // ')'
    end select
  end function status_text

end module fcs_metis_order
