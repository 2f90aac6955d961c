!> The abstract linear solver: every direct solver of fcs3d (skyline, UMFPACK, MUMPS) extends
!> `linear_solver_t` and is created by name through `fcs_solver_factory`.
!>
!> Protocol: `factor` is called after the matrix values change; it redoes the symbolic analysis
!> only when `matrix%pattern_version` differs from the one analysed last. `solve` may then be
!> called any number of times. Matrices are general (unsymmetric): frictional contact makes
!> the tangent unsymmetric.
!>
!> Capabilities beyond that protocol are type-bound hooks with defaults here, so that callers
!> never ask which solver they hold: `set_comm` (run on a communicator's processes; the default
!> accepts one process only), `runs_in_parallel` (false by default), `takes_ordering` and
!> `set_ordering` (a fill-reducing ordering computed by the caller; ignored by default),
!> `has_low_rank` and `set_low_rank_tolerance` (an approximate, block low-rank factorisation;
!> none by default). MUMPS overrides all six.
module fcs_linear_solver
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_comm, only: comm_t
  implicit none
  private
  public :: linear_solver_t, solver_stats_t, NEAR_SINGULAR_PIVOT_RATIO, MAX_LOW_RANK_TOLERANCE

  !> A factorisation whose smallest pivot is below NEAR_SINGULAR_PIVOT_RATIO times the scale
  !> of its matrix (UMFPACK: the reciprocal condition estimate min|u_ii| / max|u_ii|; MUMPS:
  !> null-pivot detection, CNTL(3), relative to the norm of the scaled matrix) is refused as
  !> numerically singular. An unsupported body gives ~1e-16 (round-off of a zero pivot); the
  !> contact models of the test suite 1e-2..1e-6. Below 1e-13 a solution keeps at most 3
  !> significant digits, so nothing usable is lost. The skyline solver's own test is
  !> SKYLINE_PIVOT_TOLERANCE (row-scaled).
  real(dp), parameter :: NEAR_SINGULAR_PIVOT_RATIO = 1.0e-13_dp

  !> Largest dropping parameter of a block low-rank factorisation (*SOLVER, LOW RANK
  !> TOLERANCE; --low-rank-tolerance): a solve with the factors then has a relative error of
  !> order 1e-2 times a condition factor, beyond which the equilibrium iterations that correct
  !> it would converge slowly, if at all.
  real(dp), parameter :: MAX_LOW_RANK_TOLERANCE = 1.0e-2_dp

  !> Figures a solver reports about its last factorisation (0 when unknown).
  type :: solver_stats_t
    real(dp) :: analyse_seconds = 0.0_dp
    real(dp) :: factor_seconds = 0.0_dp
    real(dp) :: solve_seconds = 0.0_dp
    real(dp) :: factor_entries = 0.0_dp
    !> Floating-point operations of the last factorisation (0: not reported by the solver).
    real(dp) :: factor_flops = 0.0_dp
    !> Working memory of the last factorisation as the solver reports it [MiB] (MUMPS:
    !> INFOG(22), the total over the processes; UMFPACK: Info[UMFPACK_PEAK_MEMORY]; 0: not
    !> reported).
    real(dp) :: factor_memory_mib = 0.0_dp
    !> Block low-rank factorisation (0: off, full rank): its dropping parameter, and the
    !> effective entries and flops of the last factorisation with the low-rank blocks
    !> compressed (factor_entries and factor_flops are then those of the full-rank one).
    real(dp) :: low_rank_tolerance = 0.0_dp
    real(dp) :: low_rank_entries = 0.0_dp
    real(dp) :: low_rank_flops = 0.0_dp
    !> The fill-reducing ordering used by the last analysis, as the solver names it.
    character(len=16) :: ordering = ''
    integer :: n_analyses = 0
    integer :: n_factorisations = 0
  end type solver_stats_t

  type, abstract :: linear_solver_t
    type(solver_stats_t) :: stats
    !> The user's node numbers (node_id(k) of the k-th node; degrees of freedom 3k-2..3k), for
    !> messages naming a degree of freedom; unset: the node's index is named instead.
    integer, allocatable :: node_id(:)
  contains
    procedure(factor_interface), deferred :: factor
    procedure(solve_interface), deferred :: solve
    procedure(free_interface), deferred :: free
    procedure(name_interface), deferred :: name
    procedure :: set_comm => default_set_comm
    procedure :: runs_in_parallel => default_runs_in_parallel
    procedure :: takes_ordering => default_takes_ordering
    procedure :: set_ordering => default_set_ordering
    procedure :: has_low_rank => default_has_low_rank
    procedure :: set_low_rank_tolerance => default_set_low_rank_tolerance
  end type linear_solver_t

  abstract interface
    !> Factorise `matrix` (symbolic analysis again only if its pattern changed).
    subroutine factor_interface(this, matrix, err)
      import :: linear_solver_t, sparse_matrix_t, error_t
      class(linear_solver_t), intent(inout) :: this
      type(sparse_matrix_t), intent(in) :: matrix
      type(error_t), allocatable, intent(out) :: err
    end subroutine factor_interface

    !> Solve A x = b with the last factorisation of A = `matrix`.
    subroutine solve_interface(this, matrix, b, x, err)
      import :: linear_solver_t, sparse_matrix_t, error_t, dp
      class(linear_solver_t), intent(inout) :: this
      type(sparse_matrix_t), intent(in) :: matrix
      real(dp), intent(in) :: b(:)
      real(dp), intent(out) :: x(:)
      type(error_t), allocatable, intent(out) :: err
    end subroutine solve_interface

    subroutine free_interface(this)
      import :: linear_solver_t
      class(linear_solver_t), intent(inout) :: this
    end subroutine free_interface

    !> The solver's name as the deck spells it (SKYLINE, UMFPACK, MUMPS).
    function name_interface(this) result(name)
      import :: linear_solver_t
      class(linear_solver_t), intent(in) :: this
      character(len=:), allocatable :: name
    end function name_interface
  end interface

contains

  !> A solver without a parallel mode runs on the calling process whatever `comm` is (the
  !> caller checks `runs_in_parallel` before giving it several processes).
  subroutine default_set_comm(this, comm)
    class(linear_solver_t), intent(inout) :: this
    type(comm_t), intent(in) :: comm
  end subroutine default_set_comm

  !> Whether the solver can share one system over several processes.
  pure logical function default_runs_in_parallel(this) result(parallel)
    class(linear_solver_t), intent(in) :: this
    parallel = .false.
  end function default_runs_in_parallel

  !> Whether the solver uses an ordering given by `set_ordering` (else it orders by itself).
  pure logical function default_takes_ordering(this) result(takes)
    class(linear_solver_t), intent(in) :: this
    takes = .false.
  end function default_takes_ordering

  !> The fill-reducing ordering of the next analysis (position(i): the place of equation i).
  subroutine default_set_ordering(this, position)
    class(linear_solver_t), intent(inout) :: this
    integer, intent(in) :: position(:)
  end subroutine default_set_ordering

  !> Whether the solver has a block low-rank (approximate) factorisation.
  pure logical function default_has_low_rank(this) result(has)
    class(linear_solver_t), intent(in) :: this
    has = .false.
  end function default_has_low_rank

  !> The dropping parameter of the block low-rank factorisation, in [0,
  !> MAX_LOW_RANK_TOLERANCE] (0: full rank), set before the first factorisation. A solver
  !> without one (`has_low_rank` false) is only ever given 0, which it ignores.
  subroutine default_set_low_rank_tolerance(this, tolerance)
    class(linear_solver_t), intent(inout) :: this
    real(dp), intent(in) :: tolerance
  end subroutine default_set_low_rank_tolerance

end module fcs_linear_solver
