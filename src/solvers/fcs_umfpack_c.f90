!> Raw C interfaces to the 64-bit-index ("dl": double, SuiteSparse_long) routines of UMFPACK,
!> and the constants of its header, as shipped by Debian bookworm's libsuitesparse-dev
!> 1:5.12.0 (UMFPACK 5.7.9, /usr/include/suitesparse/umfpack.h and umfpack_*.h).
!>
!> SuiteSparse_long is `long` on Linux (LP64), hence integer(c_long). The Info and Control
!> indices below are the header's 0-based C indices: in Fortran, info(UMFPACK_LNZ + 1).
!> Only the fcs_umfpack wrapper should use this module.
!>
!> Reference: T. A. Davis, "Algorithm 832: UMFPACK V4.3, an unsymmetric-pattern multifrontal
!> method", ACM Trans. Math. Softw. 30(2), 196-199, 2004; UMFPACK User Guide.
module fcs_umfpack_c
  use, intrinsic :: iso_c_binding, only: c_long, c_double, c_ptr
  implicit none
  private
  public :: umfpack_dl_defaults, umfpack_dl_symbolic, umfpack_dl_numeric, umfpack_dl_solve
  public :: umfpack_dl_free_symbolic, umfpack_dl_free_numeric
  public :: UMFPACK_INFO, UMFPACK_CONTROL
  public :: UMFPACK_A, UMFPACK_At
  public :: UMFPACK_STATUS, UMFPACK_NROW, UMFPACK_SIZE_OF_UNIT, UMFPACK_PEAK_MEMORY_ESTIMATE
  public :: UMFPACK_PEAK_MEMORY, UMFPACK_LNZ, UMFPACK_UNZ
  public :: UMFPACK_UDIAG_NZ, UMFPACK_RCOND
  public :: UMFPACK_SYMBOLIC_WALLTIME, UMFPACK_NUMERIC_WALLTIME, UMFPACK_SOLVE_WALLTIME
  public :: UMFPACK_ORDERING_USED, UMFPACK_FLOPS, UMFPACK_IRSTEP
  public :: UMFPACK_ORDERING, UMFPACK_ORDERING_AMD, UMFPACK_ORDERING_METIS
  public :: UMFPACK_OK, UMFPACK_WARNING_singular_matrix, UMFPACK_WARNING_determinant_underflow
  public :: UMFPACK_WARNING_determinant_overflow, UMFPACK_ERROR_out_of_memory
  public :: UMFPACK_ERROR_invalid_Numeric_object, UMFPACK_ERROR_invalid_Symbolic_object
  public :: UMFPACK_ERROR_argument_missing, UMFPACK_ERROR_n_nonpositive
  public :: UMFPACK_ERROR_invalid_matrix, UMFPACK_ERROR_different_pattern
  public :: UMFPACK_ERROR_invalid_system, UMFPACK_ERROR_invalid_permutation
  public :: UMFPACK_ERROR_internal_error, UMFPACK_ERROR_file_IO, UMFPACK_ERROR_ordering_failed

  !> Lengths of the Info and Control arrays (umfpack.h, UMFPACK 5.7.9).
  integer, parameter :: UMFPACK_INFO = 90, UMFPACK_CONTROL = 20

  !> Solve codes (umfpack.h): A x = b, and A' x = b.
  integer(c_long), parameter :: UMFPACK_A = 0_c_long, UMFPACK_At = 1_c_long

  !> Info indices, 0-based as in umfpack.h (UMFPACK 5.7.9).
  integer, parameter :: UMFPACK_STATUS = 0, UMFPACK_NROW = 1, UMFPACK_SIZE_OF_UNIT = 3
  integer, parameter :: UMFPACK_SYMBOLIC_WALLTIME = 17, UMFPACK_PEAK_MEMORY_ESTIMATE = 21
  integer, parameter :: UMFPACK_PEAK_MEMORY = 41, UMFPACK_LNZ = 43, UMFPACK_UNZ = 44
  integer, parameter :: UMFPACK_UDIAG_NZ = 66, UMFPACK_RCOND = 67
  integer, parameter :: UMFPACK_NUMERIC_WALLTIME = 75, UMFPACK_SOLVE_WALLTIME = 86
  integer, parameter :: UMFPACK_ORDERING_USED = 19, UMFPACK_FLOPS = 42
  !> Control entries (0-based) and their values.
  integer, parameter :: UMFPACK_ORDERING = 10, UMFPACK_IRSTEP = 7
  real(c_double), parameter :: UMFPACK_ORDERING_AMD = 1.0_c_double
  real(c_double), parameter :: UMFPACK_ORDERING_METIS = 3.0_c_double

  !> Status codes (umfpack.h, UMFPACK 5.7.9). Positive: warning, the object was still built.
  integer(c_long), parameter :: UMFPACK_OK = 0_c_long
  integer(c_long), parameter :: UMFPACK_WARNING_singular_matrix = 1_c_long
  integer(c_long), parameter :: UMFPACK_WARNING_determinant_underflow = 2_c_long
  integer(c_long), parameter :: UMFPACK_WARNING_determinant_overflow = 3_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_out_of_memory = -1_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_invalid_Numeric_object = -3_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_invalid_Symbolic_object = -4_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_argument_missing = -5_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_n_nonpositive = -6_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_invalid_matrix = -8_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_different_pattern = -11_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_invalid_system = -13_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_invalid_permutation = -15_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_internal_error = -911_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_file_IO = -17_c_long
  integer(c_long), parameter :: UMFPACK_ERROR_ordering_failed = -18_c_long

  interface
    !> void umfpack_dl_defaults(double Control[UMFPACK_CONTROL]);
    subroutine umfpack_dl_defaults(control) bind(c, name='umfpack_dl_defaults')
      import :: c_double, UMFPACK_CONTROL
      real(c_double), intent(out) :: control(UMFPACK_CONTROL)
    end subroutine umfpack_dl_defaults

    !> SuiteSparse_long umfpack_dl_symbolic(SuiteSparse_long n_row, SuiteSparse_long n_col,
    !>   const SuiteSparse_long Ap[], const SuiteSparse_long Ai[], const double Ax[],
    !>   void **Symbolic, const double Control[], double Info[]);
    function umfpack_dl_symbolic(n_row, n_col, ap, ai, ax, symbolic, control, info) &
        result(status) bind(c, name='umfpack_dl_symbolic')
      import :: c_long, c_double, c_ptr, UMFPACK_CONTROL, UMFPACK_INFO
      integer(c_long), value :: n_row, n_col
      integer(c_long), intent(in) :: ap(*), ai(*)
      real(c_double), intent(in) :: ax(*)
      type(c_ptr), intent(out) :: symbolic
      real(c_double), intent(in) :: control(UMFPACK_CONTROL)
      real(c_double), intent(out) :: info(UMFPACK_INFO)
      integer(c_long) :: status
    end function umfpack_dl_symbolic

    !> SuiteSparse_long umfpack_dl_numeric(const SuiteSparse_long Ap[],
    !>   const SuiteSparse_long Ai[], const double Ax[], void *Symbolic, void **Numeric,
    !>   const double Control[], double Info[]);
    function umfpack_dl_numeric(ap, ai, ax, symbolic, numeric, control, info) result(status) &
        bind(c, name='umfpack_dl_numeric')
      import :: c_long, c_double, c_ptr, UMFPACK_CONTROL, UMFPACK_INFO
      integer(c_long), intent(in) :: ap(*), ai(*)
      real(c_double), intent(in) :: ax(*)
      type(c_ptr), value :: symbolic
      type(c_ptr), intent(out) :: numeric
      real(c_double), intent(in) :: control(UMFPACK_CONTROL)
      real(c_double), intent(out) :: info(UMFPACK_INFO)
      integer(c_long) :: status
    end function umfpack_dl_numeric

    !> SuiteSparse_long umfpack_dl_solve(SuiteSparse_long sys, const SuiteSparse_long Ap[],
    !>   const SuiteSparse_long Ai[], const double Ax[], double X[], const double B[],
    !>   void *Numeric, const double Control[], double Info[]);
    function umfpack_dl_solve(sys, ap, ai, ax, x, b, numeric, control, info) result(status) &
        bind(c, name='umfpack_dl_solve')
      import :: c_long, c_double, c_ptr, UMFPACK_CONTROL, UMFPACK_INFO
      integer(c_long), value :: sys
      integer(c_long), intent(in) :: ap(*), ai(*)
      real(c_double), intent(in) :: ax(*)
      real(c_double), intent(out) :: x(*)
      real(c_double), intent(in) :: b(*)
      type(c_ptr), value :: numeric
      real(c_double), intent(in) :: control(UMFPACK_CONTROL)
      real(c_double), intent(out) :: info(UMFPACK_INFO)
      integer(c_long) :: status
    end function umfpack_dl_solve

    !> void umfpack_dl_free_symbolic(void **Symbolic); sets *Symbolic to NULL.
    subroutine umfpack_dl_free_symbolic(symbolic) bind(c, name='umfpack_dl_free_symbolic')
      import :: c_ptr
      type(c_ptr), intent(inout) :: symbolic
    end subroutine umfpack_dl_free_symbolic

    !> void umfpack_dl_free_numeric(void **Numeric); sets *Numeric to NULL.
    subroutine umfpack_dl_free_numeric(numeric) bind(c, name='umfpack_dl_free_numeric')
      import :: c_ptr
      type(c_ptr), intent(inout) :: numeric
    end subroutine umfpack_dl_free_numeric
  end interface

end module fcs_umfpack_c
