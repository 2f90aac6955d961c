!> Skyline (variable band, profile) direct solver for unsymmetric matrices whose pattern is
!> structurally symmetric, as the finite element and contact matrices of fcs3d are.
!>
!> The matrix is renumbered node by node in reverse Cuthill-McKee order (`fcs_rcm`) to make
!> the profile small, then factorised as A = L U (L unit lower triangular, U upper triangular)
!> without pivoting, in the active-column (Crout) order: at step j, column j of U and row j of
!> L are computed from the finished columns and rows to their left. Column j of U is stored
!> from its first structural nonzero row f(j) down to the diagonal, row j of L from column f(j)
!> to just left of the diagonal; the pattern being symmetric, both start at the same f(j), and
!> the factors fill exactly this envelope. This is the scheme of the skyline solvers of
!> K. J. Bathe, "Finite Element Procedures", Prentice-Hall 1996, section 8.2.3 (COLSOL, there
!> for symmetric matrices), extended to unsymmetric matrices with a symmetric profile as in the
!> DATRI/DASOL routines of R. L. Taylor's FEAP (Zienkiewicz & Taylor, "The Finite Element
!> Method", vol. 1, 5th ed. 2000, chapter 20). Written for fcs3d from those descriptions.
!>
!> Without pivoting, the factorisation is stable for the diagonally dominant or positive
!> definite (plus small unsymmetric part) matrices met in quasi-static contact; a zero or tiny
!> pivot is reported as an error naming the degree of freedom.
module fcs_skyline
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, fatal_error
  use fcs_strings, only: str
  use fcs_timer, only: wall_time
  use fcs_sparse, only: sparse_matrix_t, DOFS_PER_NODE
  use fcs_linear_solver, only: linear_solver_t
  use fcs_rcm, only: rcm_node_order, dof_order_from_nodes, invert_permutation
  implicit none
  private
  public :: skyline_solver_t, SKYLINE_PIVOT_TOLERANCE

  !> A pivot u_jj with |u_jj| <= SKYLINE_PIVOT_TOLERANCE * max_k |a_jk| (largest entry of the
  !> original row j) is taken as zero: the matrix is then singular to working precision.
  real(dp), parameter :: SKYLINE_PIVOT_TOLERANCE = 1.0e-14_dp

  !> Bytes per stored value and per 64-bit pointer, for the memory estimate of the profile.
  integer, parameter :: BYTES_PER_REAL = 8, BYTES_PER_POINTER = 8, BYTES_PER_INTEGER = 4

  !> Names of the directions of a node's degrees of freedom, for messages.
  character(len=1), parameter :: DIRECTION_NAMES(DOFS_PER_NODE) = ['x', 'y', 'z']

  !> The skyline solver. All arrays are indexed by the renumbered degrees of freedom except
  !> `dof_position`, which maps an original degree of freedom to its new number.
  type, extends(linear_solver_t) :: skyline_solver_t
    private
    !> Order of the analysed matrix, its stored entries and pattern version (-1: none yet).
    integer :: n = 0
    integer(i8) :: nnz = -1
    integer :: analysed_version = -1
    !> True after a successful `factor`, until the next one starts.
    logical :: factored = .false.
    !> dof_order(k): original dof numbered k; dof_position(old): its new number.
    integer, allocatable :: dof_order(:), dof_position(:)
    !> first(j): first row of column j of U, equal to the first column of row j of L.
    integer, allocatable :: first(:)
    !> Column j of U (rows first(j)..j) is upper(upper_ptr(j):upper_ptr(j+1)-1); row i of L
    !> (columns first(i)..i-1) is lower(lower_ptr(i):lower_ptr(i+1)-1).
    integer(i8), allocatable :: upper_ptr(:), lower_ptr(:)
    real(dp), allocatable :: upper(:), lower(:)
    !> Largest |a_ij| of each original row (new numbering), the scale of the pivot test.
    real(dp), allocatable :: row_scale(:)
  contains
    procedure :: factor => skyline_factor
    procedure :: solve => skyline_solve
    procedure :: free => skyline_free
    procedure :: name => skyline_name
  end type skyline_solver_t

contains

  !> Factorise `matrix`: renumber and size the profile if its pattern changed, copy the values
  !> into the profile and decompose A = L U.
  subroutine skyline_factor(this, matrix, err)
    class(skyline_solver_t), intent(inout) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    type(error_t), allocatable, intent(out) :: err
    real(dp) :: started
    this%factored = .false.
    if (needs_analysis(this, matrix)) then
      started = wall_time()
      call skyline_analyse(this, matrix, err)
      if (allocated(err)) return
      this%stats%analyse_seconds = wall_time() - started
      this%stats%n_analyses = this%stats%n_analyses + 1
      this%stats%ordering = 'RCM'
    end if
    started = wall_time()
    call scatter_values(this, matrix)
    call decompose(this, err)
    if (allocated(err)) return
    this%factored = .true.
    this%stats%factor_seconds = wall_time() - started
    this%stats%n_factorisations = this%stats%n_factorisations + 1
    this%stats%factor_entries = real(this%upper_ptr(this%n + 1) - 1, dp) + &
                                real(this%lower_ptr(this%n + 1) - 1, dp)
  end subroutine skyline_factor

  !> True when `matrix` is not the pattern analysed last.
  pure logical function needs_analysis(this, matrix)
    class(skyline_solver_t), intent(in) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    needs_analysis = this%analysed_version /= matrix%pattern_version .or. &
                     this%n /= matrix%n .or. this%nnz /= matrix%nnz
  end function needs_analysis

  !> Renumber the nodes in reverse Cuthill-McKee order, find the envelope of the renumbered
  !> matrix and allocate the profile storage.
  subroutine skyline_analyse(this, matrix, err)
    class(skyline_solver_t), intent(inout) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    type(error_t), allocatable, intent(out) :: err
    integer :: i, j, r
    integer(i8) :: p
    call release_arrays(this)
    this%n = matrix%n
    this%dof_order = dof_order_from_nodes(rcm_node_order(matrix))
    allocate (this%dof_position(this%n))
    this%dof_position(:) = invert_permutation(this%dof_order)
    allocate (this%first(this%n), this%upper_ptr(this%n + 1), this%lower_ptr(this%n + 1))
    this%first = [(i, i = 1, this%n)]
    do r = 1, this%n
      i = this%dof_position(r)
      do p = matrix%row_ptr(r), matrix%row_ptr(r + 1) - 1
        j = this%dof_position(matrix%col(p))
        this%first(max(i, j)) = min(this%first(max(i, j)), min(i, j))
      end do
    end do
    this%upper_ptr(1) = 1
    this%lower_ptr(1) = 1
    do j = 1, this%n
      this%upper_ptr(j + 1) = this%upper_ptr(j) + (j - this%first(j) + 1)
      this%lower_ptr(j + 1) = this%lower_ptr(j) + (j - this%first(j))
    end do
    call allocate_profile(this, err)
    if (allocated(err)) then
      call release_arrays(this)
      return
    end if
    this%nnz = matrix%nnz
    this%analysed_version = matrix%pattern_version
  end subroutine skyline_analyse

  !> Allocate the profile after checking its size against the physical memory of the machine
  !> (Linux over-commits memory, so a too large `allocate` may succeed and the process be killed
  !> later while the factors are filled).
  subroutine allocate_profile(this, err)
    class(skyline_solver_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    integer(i8) :: n_upper, n_lower
    real(dp) :: bytes, available
    integer :: stat
    character(len=200) :: message
    n_upper = this%upper_ptr(this%n + 1) - 1
    n_lower = this%lower_ptr(this%n + 1) - 1
    bytes = real(BYTES_PER_REAL, dp) * (real(n_upper, dp) + real(n_lower, dp) + this%n) + &
            real(BYTES_PER_POINTER, dp) * 2 * (this%n + 1) + &
            real(BYTES_PER_INTEGER, dp) * 3 * this%n
    available = physical_memory_bytes()
    if (available > 0.0_dp .and. bytes > available) then
      call fatal_error(err, 'skyline solver: the profile of the renumbered matrix needs ' // &
        format_bytes(bytes) // ' (' // str(n_upper + n_lower) // ' values for ' // &
        str(this%n) // ' equations), more than the ' // format_bytes(available) // &
        ' of memory of this machine; use the UMFPACK solver, which stores only the nonzeros' // &
        ' of the factors')
      return
    end if
    message = ''
    allocate (this%upper(n_upper), this%lower(n_lower), this%row_scale(this%n), stat=stat, &
              errmsg=message)
    if (stat /= 0) then
      call fatal_error(err, 'skyline solver: could not allocate ' // format_bytes(bytes) // &
        ' for the profile of the renumbered matrix (' // str(n_upper + n_lower) // &
        ' values for ' // str(this%n) // ' equations): ' // trim(message) // &
        '; use the UMFPACK solver, which stores only the nonzeros of the factors')
    end if
  end subroutine allocate_profile

  !> Copy the values of `matrix` into the renumbered profile and record each row's largest
  !> magnitude. Entries of the envelope outside the pattern start at zero.
  subroutine scatter_values(this, matrix)
    class(skyline_solver_t), intent(inout) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    integer :: i, j, r
    integer(i8) :: p
    this%upper = 0.0_dp
    this%lower = 0.0_dp
    this%row_scale = 0.0_dp
    do r = 1, this%n
      i = this%dof_position(r)
      do p = matrix%row_ptr(r), matrix%row_ptr(r + 1) - 1
        j = this%dof_position(matrix%col(p))
        this%row_scale(i) = max(this%row_scale(i), abs(matrix%val(p)))
        if (i <= j) then
          this%upper(this%upper_ptr(j) + (i - this%first(j))) = matrix%val(p)
        else
          this%lower(this%lower_ptr(i) + (j - this%first(i))) = matrix%val(p)
        end if
      end do
    end do
  end subroutine scatter_values

  !> A = L U in place, active-column (Crout) order, no pivoting (Bathe 1996, section 8.2.3;
  !> Taylor's DATRI). For each column j and each row i = f(j)..j-1, with m = max(f(i), f(j)):
  !>   u_ij = a_ij - sum_{k=m}^{i-1} l_ik u_kj,
  !>   l_ji = (a_ji - sum_{k=m}^{i-1} l_jk u_ki) / u_ii,
  !> then the pivot u_jj = a_jj - sum_{k=f(j)}^{j-1} l_jk u_kj. Each sum is a dot product of
  !> two contiguous stored segments.
  subroutine decompose(this, err)
    class(skyline_solver_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    integer :: i, j, m, fj
    integer(i8) :: col_j, row_j, col_i, row_i
    do j = 1, this%n
      fj = this%first(j)
      col_j = this%upper_ptr(j) - fj
      row_j = this%lower_ptr(j) - fj
      do i = fj, j - 1
        m = max(this%first(i), fj)
        col_i = this%upper_ptr(i) - this%first(i)
        row_i = this%lower_ptr(i) - this%first(i)
        if (m < i) then
          this%upper(col_j + i) = this%upper(col_j + i) - &
            dot_product(this%lower(row_i + m:row_i + i - 1), this%upper(col_j + m:col_j + i - 1))
          this%lower(row_j + i) = this%lower(row_j + i) - &
            dot_product(this%lower(row_j + m:row_j + i - 1), this%upper(col_i + m:col_i + i - 1))
        end if
        this%lower(row_j + i) = this%lower(row_j + i) / this%upper(col_i + i)
      end do
      if (fj < j) then
        this%upper(col_j + j) = this%upper(col_j + j) - &
          dot_product(this%lower(row_j + fj:row_j + j - 1), this%upper(col_j + fj:col_j + j - 1))
      end if
      if (.not. (abs(this%upper(col_j + j)) > SKYLINE_PIVOT_TOLERANCE * this%row_scale(j))) then
        call singular_pivot_error(this, j, this%upper(col_j + j), err)
        return
      end if
    end do
  end subroutine decompose

  !> The error for a zero or tiny pivot at renumbered equation `j`, naming the original degree
  !> of freedom, its node and direction.
  subroutine singular_pivot_error(this, j, pivot, err)
    class(skyline_solver_t), intent(in) :: this
    integer, intent(in) :: j
    real(dp), intent(in) :: pivot
    type(error_t), allocatable, intent(out) :: err
    integer :: dof, node, direction
    dof = this%dof_order(j)
    node = (dof - 1) / DOFS_PER_NODE + 1
    direction = mod(dof - 1, DOFS_PER_NODE) + 1
    if (allocated(this%node_id)) node = this%node_id(node)
    call fatal_error(err, 'skyline solver: zero or tiny pivot ' // str(pivot, 3) // &
      ' (largest entry of the row ' // str(this%row_scale(j), 3) // ') at degree of freedom ' // &
      str(dof) // ' (node ' // str(node) // ', direction ' // DIRECTION_NAMES(direction) // &
      '): the matrix is singular or nearly so: check that every body is supported ' // &
      '(rigid-body modes) and that contact is closed')
  end subroutine singular_pivot_error

  !> Solve A x = b with the factors: forward substitution L y = P b by rows, back substitution
  !> U z = y by columns, x = P^T z (Bathe 1996, section 8.2.3, "reduction and back-substitution").
  subroutine skyline_solve(this, matrix, b, x, err)
    class(skyline_solver_t), intent(inout) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    real(dp), intent(in) :: b(:)
    real(dp), intent(out) :: x(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: y(:)
    real(dp) :: started
    integer :: i, j, fi, k
    integer(i8) :: row_i, col_j
    started = wall_time()
    call check_solve_arguments(this, matrix, size(b), size(x), err)
    if (allocated(err)) return
    allocate (y(this%n))
    do k = 1, this%n
      y(k) = b(this%dof_order(k))
    end do
    do i = 1, this%n
      fi = this%first(i)
      row_i = this%lower_ptr(i) - fi
      if (fi < i) y(i) = y(i) - dot_product(this%lower(row_i + fi:row_i + i - 1), y(fi:i - 1))
    end do
    do j = this%n, 1, -1
      col_j = this%upper_ptr(j) - this%first(j)
      y(j) = y(j) / this%upper(col_j + j)
      y(this%first(j):j - 1) = y(this%first(j):j - 1) - &
                                y(j) * this%upper(col_j + this%first(j):col_j + j - 1)
    end do
    do k = 1, this%n
      x(this%dof_order(k)) = y(k)
    end do
    this%stats%solve_seconds = wall_time() - started
  end subroutine skyline_solve

  !> Errors for a solve without factors or with vectors of the wrong length.
  subroutine check_solve_arguments(this, matrix, n_b, n_x, err)
    class(skyline_solver_t), intent(in) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    integer, intent(in) :: n_b, n_x
    type(error_t), allocatable, intent(out) :: err
    if (.not. this%factored) then
      call fatal_error(err, 'skyline solver: solve called without a successful factorisation')
    else if (matrix%n /= this%n .or. matrix%pattern_version /= this%analysed_version) then
      call fatal_error(err, 'skyline solver: solve called with a matrix other than the one ' // &
        'factorised (' // str(matrix%n) // ' equations, ' // str(this%n) // ' factorised)')
    else if (n_b /= this%n .or. n_x /= this%n) then
      call fatal_error(err, 'skyline solver: right-hand side of length ' // str(n_b) // &
        ' and solution of length ' // str(n_x) // ' for ' // str(this%n) // ' equations')
    end if
  end subroutine check_solve_arguments

  !> Release all storage; the next `factor` analyses again. Statistics are kept.
  subroutine skyline_free(this)
    class(skyline_solver_t), intent(inout) :: this
    call release_arrays(this)
    this%n = 0
    this%nnz = -1
    this%analysed_version = -1
  end subroutine skyline_free

  !> Deallocate the ordering, the profile and its pointers; forget the analysis.
  subroutine release_arrays(this)
    class(skyline_solver_t), intent(inout) :: this
    this%factored = .false.
    this%analysed_version = -1
    if (allocated(this%dof_order)) deallocate (this%dof_order)
    if (allocated(this%dof_position)) deallocate (this%dof_position)
    if (allocated(this%first)) deallocate (this%first)
    if (allocated(this%upper_ptr)) deallocate (this%upper_ptr)
    if (allocated(this%lower_ptr)) deallocate (this%lower_ptr)
    if (allocated(this%upper)) deallocate (this%upper)
    if (allocated(this%lower)) deallocate (this%lower)
    if (allocated(this%row_scale)) deallocate (this%row_scale)
  end subroutine release_arrays

  !> The solver's name as the deck spells it.
  function skyline_name(this) result(name)
    class(skyline_solver_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'SKYLINE'
  end function skyline_name

  !> Physical memory of the machine in bytes (MemTotal of /proc/meminfo), 0 if unknown.
  function physical_memory_bytes() result(bytes)
    real(dp) :: bytes
    integer :: unit, stat
    integer(i8) :: kib
    character(len=256) :: line
    bytes = 0.0_dp
    open (newunit=unit, file='/proc/meminfo', action='read', status='old', iostat=stat)
    if (stat /= 0) return
    do
      read (unit, '(a)', iostat=stat) line
      if (stat /= 0) exit
      if (line(1:9) == 'MemTotal:') then
        read (line(10:), *, iostat=stat) kib
        if (stat == 0) bytes = 1024.0_dp * real(kib, dp)
        exit
      end if
    end do
    close (unit)
  end function physical_memory_bytes

  !> A byte count as text in MiB or GiB.
  function format_bytes(bytes) result(text)
    real(dp), intent(in) :: bytes
    character(len=:), allocatable :: text
    real(dp), parameter :: MIB = 1024.0_dp**2, GIB = 1024.0_dp**3
    if (bytes >= GIB) then
      text = str(bytes / GIB, 3) // ' GiB'
    else
      text = str(bytes / MIB, 3) // ' MiB'
    end if
  end function format_bytes

end module fcs_skyline
