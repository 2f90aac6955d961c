!> A linear solver used only by the tests: the whole matrix as a dense array, factorised by
!> LAPACK's dgetrf (LU with partial pivoting) and solved by dgetrs. It is the test-only solver
!> that test_fcs_solver_factory registers in the solver registry, the way a new solver is
!> added (doc/architecture.md, "How to add a linear solver").
module fcs_test_dense_solver
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, fatal_error
  use fcs_strings, only: str
  use fcs_sparse, only: sparse_matrix_t
  use fcs_linear_solver, only: linear_solver_t
  use fcs_solver_factory, only: linear_solver_entry_t
  implicit none
  private
  public :: dense_solver_t, dense_solver_entry, DENSE_SOLVER_NAME

  character(len=*), parameter :: DENSE_SOLVER_NAME = 'TEST DENSE'

  type, extends(linear_solver_t) :: dense_solver_t
    real(dp), allocatable :: lu(:, :)
    integer, allocatable :: pivots(:)
  contains
    procedure :: factor => dense_factor
    procedure :: solve => dense_solve_system
    procedure :: free => dense_free
    procedure :: name => dense_name
  end type dense_solver_t

  interface
    subroutine dgetrf(m, n, a, lda, ipiv, info)
      import :: dp
      integer, intent(in) :: m, n, lda
      real(dp), intent(inout) :: a(lda, *)
      integer, intent(out) :: ipiv(*)
      integer, intent(out) :: info
    end subroutine dgetrf
    subroutine dgetrs(trans, n, nrhs, a, lda, ipiv, b, ldb, info)
      import :: dp
      character(len=1), intent(in) :: trans
      integer, intent(in) :: n, nrhs, lda, ldb
      real(dp), intent(in) :: a(lda, *)
      integer, intent(in) :: ipiv(*)
      real(dp), intent(inout) :: b(ldb, *)
      integer, intent(out) :: info
    end subroutine dgetrs
  end interface

contains

  !> The registry entry: name TEST DENSE, constructor new_dense_solver.
  function dense_solver_entry() result(entry)
    type(linear_solver_entry_t) :: entry
    entry%name = DENSE_SOLVER_NAME
    entry%construct => new_dense_solver
  end function dense_solver_entry

  subroutine new_dense_solver(solver)
    class(linear_solver_t), allocatable, intent(out) :: solver
    allocate (dense_solver_t :: solver)
  end subroutine new_dense_solver

  !> Copy the matrix into a dense array and factorise it (dgetrf); a zero pivot is an error.
  subroutine dense_factor(this, matrix, err)
    class(dense_solver_t), intent(inout) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    type(error_t), allocatable, intent(out) :: err
    integer :: i, info
    integer(i8) :: p
    call this%free()
    allocate (this%lu(matrix%n, matrix%n), this%pivots(matrix%n))
    this%lu = 0.0_dp
    do i = 1, matrix%n
      do p = matrix%row_ptr(i), matrix%row_ptr(i + 1) - 1
        this%lu(i, matrix%col(p)) = matrix%val(p)
      end do
    end do
    call dgetrf(matrix%n, matrix%n, this%lu, matrix%n, this%pivots, info)
    if (info /= 0) then
      call fatal_error(err, 'dense solver: dgetrf failed with info = ' // str(info))
      call this%free()
      return
    end if
    this%stats%n_factorisations = this%stats%n_factorisations + 1
  end subroutine dense_factor

  !> Solve with the factors of the last `factor` (dgetrs).
  subroutine dense_solve_system(this, matrix, b, x, err)
    class(dense_solver_t), intent(inout) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    real(dp), intent(in) :: b(:)
    real(dp), intent(out) :: x(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: rhs(:, :)
    integer :: info
    if (.not. allocated(this%lu)) then
      call fatal_error(err, 'dense solver: solve before factor')
      return
    end if
    rhs = reshape(b, [matrix%n, 1])
    call dgetrs('N', matrix%n, 1, this%lu, matrix%n, this%pivots, rhs, matrix%n, info)
    if (info /= 0) then
      call fatal_error(err, 'dense solver: dgetrs failed with info = ' // str(info))
      return
    end if
    x = rhs(:, 1)
  end subroutine dense_solve_system

  subroutine dense_free(this)
    class(dense_solver_t), intent(inout) :: this
    if (allocated(this%lu)) deallocate (this%lu)
    if (allocated(this%pivots)) deallocate (this%pivots)
  end subroutine dense_free

  function dense_name(this) result(name)
    class(dense_solver_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = DENSE_SOLVER_NAME
  end function dense_name

end module fcs_test_dense_solver
