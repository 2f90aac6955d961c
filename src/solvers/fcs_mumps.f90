!> MUMPS direct solver (multifrontal LU with threshold partial pivoting), sequential library
!> of Debian bookworm's libmumps-seq-dev 5.5.1: P. R. Amestoy, I. S. Duff, J.-Y. L'Excellent and
!> J. Koster, "A fully asynchronous multifrontal solver using distributed dynamic scheduling",
!> SIAM J. Matrix Anal. Appl. 23(1), 15-41, 2001; MUMPS 5.5 User's Guide.
!>
!> The matrix is given unsymmetric (SYM = 0), assembled and centralised on the host
!> (ICNTL(5) = 0, ICNTL(18) = 0) in coordinate form: IRN/JCN/A built from our CSR, 1-based.
!> Phases: JOB = -1 (initialise) on the first `factor`, JOB = 1 (analysis) only when the pattern
!> changes, JOB = 2 (factorisation) at every `factor`, JOB = 3 (solve), JOB = -2 in `free`.
!> All MUMPS output is silenced; INFOG(1) is checked after every call and turned into words.
!>
!> Block low-rank (BLR) factorisation, on when `set_low_rank_tolerance` gives eps > 0 (*SOLVER,
!> LOW RANK TOLERANCE; --low-rank-tolerance): the off-diagonal blocks of the large frontal
!> matrices are compressed to low rank, dropping what is below eps (P. R. Amestoy, C. Ashcraft,
!> O. Boiteau, A. Buttari, J.-Y. L'Excellent and C. Weisbecker, "Improving multifrontal methods
!> by means of block low-rank representations", SIAM J. Sci. Comput. 37(3), A1451-A1474,
!> 2015). The factorisation is then approximate, with a backward error of order eps (N. J.
!> Higham and T. Mary, "Solving block low-rank linear systems by LU factorization is
!> numerically stable", IMA J. Numer. Anal. 42(2), 951-980, 2022).
!>
!> The MUMPS instance is the library's own derived type DMUMPS_STRUC, taken from its header
!> /usr/include/dmumps_struc.h: this is the only `include` line of fcs3d, allowed here because
!> the layout must be exactly the library's. Its pointer components IRN, JCN, A and RHS are
!> allocated by this wrapper and deallocated in `free`; an object of this type must not be
!> copied by assignment (the copy would share them).
module fcs_mumps
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, fatal_error
  use fcs_memory, only: memory_error
  use fcs_strings, only: str
  use fcs_timer, only: wall_time
  use fcs_sparse, only: sparse_matrix_t
  use fcs_metis_order, only: metis_equation_order
  use fcs_linear_solver, only: linear_solver_t, NEAR_SINGULAR_PIVOT_RATIO
  use fcs_comm, only: comm_t, COMM_VARIANT
  implicit none
  private
  public :: mumps_solver_t, MUMPS_SEQUENTIAL_COMM

  include 'dmumps_struc.h'

  !> Communicator for the sequential library: MPI_COMM_WORLD of the stub mpif.h shipped with
  !> libmumps-seq-dev 5.5.1 (/usr/include/mumps_seq/mpif.h), which ignores it.
  integer, parameter :: MUMPS_SEQUENTIAL_COMM = 9

  !> JOB values (MUMPS 5.5 User's Guide, section 5.1).
  integer, parameter :: JOB_INITIALISE = -1, JOB_TERMINATE = -2
  integer, parameter :: JOB_ANALYSE = 1, JOB_FACTORISE = 2, JOB_SOLVE = 3
  !> SYM = 0: unsymmetric matrix; PAR = 1: the host takes part in the factorisation.
  integer, parameter :: MUMPS_UNSYMMETRIC = 0, MUMPS_HOST_WORKS = 1
  !> ICNTL(1..3) < 0: no error, diagnostic or statistics output; ICNTL(4) = 0: print nothing.
  integer, parameter :: MUMPS_NO_OUTPUT = -1, MUMPS_PRINT_NOTHING = 0
  !> ICNTL(5) = 0: assembled matrix; ICNTL(18) = 0: centralised on the host.
  integer, parameter :: MUMPS_ASSEMBLED = 0, MUMPS_CENTRALISED = 0
  !> ICNTL(18) = 3: each process gives its own entries (distributed assembled input).
  integer, parameter :: MUMPS_DISTRIBUTED = 3
  !> ICNTL(24) = 1: null-pivot detection; with CNTL(3) > 0 a pivot is null when its row is
  !> below CNTL(3) times the norm of the scaled matrix, and INFOG(28) counts them.
  integer, parameter :: MUMPS_DETECT_NULL_PIVOTS = 1
  !> ICNTL(28) = 1: sequential analysis; ICNTL(7) = 1: the ordering given in PERM_IN, ours
  !> by METIS (fcs_metis_order). MUMPS's automatic choice took SCOTCH (Debian's MUMPS is built
  !> without METIS), whose ordering changes from run to run: the factors, hence the
  !> round-off, differed between two runs of the same deck, and the fault-bend model's slip
  !> events (a bifurcating sequence) with them. METIS is deterministic, and gives the same
  !> ordering on any number of processes.
  integer, parameter :: MUMPS_SEQUENTIAL_ANALYSIS = 1, MUMPS_ORDERING_GIVEN = 1
  !> Automatic retries of a factorisation that ran out of workspace, each doubling the
  !> relaxation ICNTL(14) (percent of extra workspace over the analysis estimate).
  integer, parameter :: MAX_WORKSPACE_RETRIES = 2
  integer, parameter :: MINIMUM_RELAXATION_PERCENT = 20
  !> ICNTL(35), the BLR feature (MUMPS 5.5 User's Guide, ICNTL(35)): 0 off (full rank); 1 on,
  !> the option chosen by MUMPS (currently 2); 2 on in the factorisation and the solve, the
  !> factors stored in low-rank form (memory gains); 3 on in the factorisation only, the
  !> factors kept full rank (no memory gain). We ask for 2 by name rather than 1, so that the
  !> factors' storage does not change with a later MUMPS's automatic choice. It must be set
  !> before the analysis, which clusters the variables into blocks (INFOG(1) = -54 otherwise).
  integer, parameter :: MUMPS_BLR_FACTORS_AND_SOLVE = 2
  !> The guide's other BLR controls keep their defaults: ICNTL(36) = 0, the standard UFSC
  !> variant (ICNTL(36) = 1, UCFS, compresses before the pivots are chosen, which the guide
  !> says "may have a numerical impact"; our unsymmetric contact tangents rely on threshold
  !> pivoting, CNTL(1)); ICNTL(38) = 600, the compression rate of the factors (per mille)
  !> that the analysis assumes for its memory estimates INFOG(36..39), a figure only: a
  !> factorisation that needs more workspace gets it (dynamic storage since MUMPS 5.2, and
  !> our retries with a larger ICNTL(14)). ICNTL(37) (compression of the contribution
  !> blocks) is unused in 5.5.1: its ChangeLog has no such feature.

  !> Error values of INFOG(1) (MUMPS 5.5 User's Guide, section "Error diagnostics").
  integer, parameter :: MUMPS_ERROR_NNZ_RANGE = -2, MUMPS_ERROR_JOB = -3
  integer, parameter :: MUMPS_ERROR_ANALYSIS_REAL_ALLOCATION = -5
  integer, parameter :: MUMPS_ERROR_STRUCTURALLY_SINGULAR = -6
  integer, parameter :: MUMPS_ERROR_ANALYSIS_INTEGER_ALLOCATION = -7
  integer, parameter :: MUMPS_ERROR_FACTOR_INTEGER_WORKSPACE = -8
  integer, parameter :: MUMPS_ERROR_FACTOR_REAL_WORKSPACE = -9
  integer, parameter :: MUMPS_ERROR_NUMERICALLY_SINGULAR = -10
  integer, parameter :: MUMPS_ERROR_SOLVE_REAL_WORKSPACE = -11
  integer, parameter :: MUMPS_ERROR_REFINEMENT_REAL_WORKSPACE = -12
  integer, parameter :: MUMPS_ERROR_ALLOCATION = -13
  integer, parameter :: MUMPS_ERROR_SOLVE_INTEGER_WORKSPACE = -14
  integer, parameter :: MUMPS_ERROR_REFINEMENT_INTEGER_WORKSPACE = -15
  integer, parameter :: MUMPS_ERROR_N_RANGE = -16
  integer, parameter :: MUMPS_ERROR_SEND_BUFFER = -17
  integer, parameter :: MUMPS_ERROR_RECEIVE_BUFFER = -20
  integer, parameter :: MUMPS_ERROR_USER_ARRAY = -22
  integer, parameter :: MUMPS_ERROR_MPI_NOT_INITIALISED = -23
  integer, parameter :: MUMPS_ERROR_ORDERING = -50
  integer, parameter :: MUMPS_ERROR_ORDERING_INTEGER_OVERFLOW = -51
  integer, parameter :: MUMPS_ERROR_ORDERING_NEEDS_64BIT = -52

  interface
    !> The MUMPS driver, double precision: one entry point, the phase chosen by id%JOB.
    subroutine dmumps(id)
      import :: dmumps_struc
      type(dmumps_struc), intent(inout) :: id
    end subroutine dmumps
  end interface

  !> The MUMPS solver. `communicator` is the Fortran MPI handle given to MUMPS at
  !> initialisation (the first `factor`); an MPI variant sets it before, the sequential one
  !> keeps the default.
  type, extends(linear_solver_t) :: mumps_solver_t
    integer :: communicator = MUMPS_SEQUENTIAL_COMM
    !> With more than one process (MPI build): every rank passes the entries of its own
    !> matrix (summed by MUMPS), the right-hand side is read on rank 0 and the solution
    !> broadcast to every rank. Set with `set_comm` before the first factorisation.
    type(comm_t) :: comm
    logical :: distributed = .false.
    type(dmumps_struc), allocatable, private :: id
    !> Order, stored entries and pattern version of the analysed matrix (-1: none yet).
    integer, private :: n = 0
    integer(i8), private :: nnz = -1
    integer, private :: analysed_version = -1
    logical, private :: factored = .false.
    !> Fill-reducing ordering for the next analysis, given by the caller (`set_ordering`):
    !> a process of a distributed run holds only its share of the matrix, so the host's
    !> matrix alone would give METIS a partial graph (and MUMPS up to 30 times the flops).
    integer, allocatable, private :: given_order(:)
  contains
    procedure :: factor => mumps_factor
    procedure :: set_ordering => mumps_set_ordering
    procedure :: solve => mumps_solve
    procedure :: free => mumps_free
    procedure :: name => mumps_name
    procedure :: set_comm => mumps_set_comm
    procedure :: runs_in_parallel => mumps_runs_in_parallel
    procedure :: takes_ordering => mumps_takes_ordering
    procedure :: has_low_rank => mumps_has_low_rank
    procedure :: set_low_rank_tolerance => mumps_set_low_rank_tolerance
  end type mumps_solver_t

contains

  !> Factorise `matrix`: initialise MUMPS on first use, analyse if the pattern changed, then
  !> factorise, retrying with more workspace if MUMPS asks for it.
  subroutine mumps_factor(this, matrix, err)
    class(mumps_solver_t), intent(inout) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    type(error_t), allocatable, intent(out) :: err
    real(dp) :: started
    this%factored = .false.
    if (.not. allocated(this%id)) then
      call mumps_initialise(this, err)
      if (allocated(err)) return
    end if
    if (needs_analysis(this, matrix)) then
      started = wall_time()
      call mumps_analyse(this, matrix, err)
      if (allocated(err)) return
      this%stats%analyse_seconds = wall_time() - started
      this%stats%n_analyses = this%stats%n_analyses + 1
      this%stats%ordering = ordering_name(this%id%INFOG(7))
    end if
    started = wall_time()
    if (this%distributed) then
      this%id%A_loc(:) = matrix%val
    else
      this%id%A(:) = matrix%val
    end if
    call factorise_with_retries(this, err)
    if (allocated(err)) return
    if (this%id%INFOG(28) > 0) then
      call fatal_error(err, 'MUMPS factorisation: the matrix is singular or nearly so (' // &
        str(this%id%INFOG(28)) // ' null pivot(s) below ' // str(NEAR_SINGULAR_PIVOT_RATIO, 3) // &
        ' times the norm of the scaled matrix); check that every body is supported ' // &
        '(rigid-body modes) and that contact is closed')
      return
    end if
    this%factored = .true.
    this%stats%factor_seconds = wall_time() - started
    this%stats%n_factorisations = this%stats%n_factorisations + 1
    ! INFOG(29), RINFOG(3): entries and flops of the full-rank factorisation, also with BLR on
    ! (its theoretical figures); INFOG(35), RINFOG(14): the effective ones, with the low-rank
    ! blocks compressed (equal to the former with BLR off).
    this%stats%factor_entries = factor_entries(this%id%INFOG(29))
    this%stats%factor_flops = real(this%id%RINFOG(3), dp)
    if (this%stats%low_rank_tolerance > 0.0_dp) then
      this%stats%low_rank_entries = factor_entries(this%id%INFOG(35))
      this%stats%low_rank_flops = real(this%id%RINFOG(14), dp)
    end if
    ! INFOG(22): millions of bytes effectively used by the factorisation, all processes.
    this%stats%factor_memory_mib = real(this%id%INFOG(22), dp) * 1.0e6_dp / 2.0_dp**20
  end subroutine mumps_factor

  !> The fill-reducing ordering of the next analysis (position(i): the place of equation i
  !> in the elimination order; used once, on the host).
  subroutine mumps_set_ordering(this, position)
    class(mumps_solver_t), intent(inout) :: this
    integer, intent(in) :: position(:)
    this%given_order = position
  end subroutine mumps_set_ordering

  !> Run on the processes of `comm`; with more than one, in distributed mode.
  subroutine mumps_set_comm(this, comm)
    class(mumps_solver_t), intent(inout) :: this
    type(comm_t), intent(in) :: comm
    this%comm = comm
    this%distributed = comm%size > 1
    ! The parallel library needs the real communicator even on one process (MUMPS
    ! duplicates it); the sequential one keeps its stub handle.
    if (COMM_VARIANT == 'mpi') this%communicator = comm%fortran_handle()
  end subroutine mumps_set_comm

  !> MUMPS shares a system over the processes of its communicator.
  pure logical function mumps_runs_in_parallel(this) result(parallel)
    class(mumps_solver_t), intent(in) :: this
    parallel = .true.
  end function mumps_runs_in_parallel

  !> MUMPS takes the caller's ordering (fcs3d's METIS ordering of the whole model).
  pure logical function mumps_takes_ordering(this) result(takes)
    class(mumps_solver_t), intent(in) :: this
    takes = .true.
  end function mumps_takes_ordering

  !> MUMPS has a block low-rank factorisation (ICNTL(35), CNTL(7)).
  pure logical function mumps_has_low_rank(this) result(has)
    class(mumps_solver_t), intent(in) :: this
    has = .true.
  end function mumps_has_low_rank

  !> BLR with dropping parameter `tolerance` (0: full rank), from the next initialisation on:
  !> set before the first factorisation, since the analysis must know it.
  subroutine mumps_set_low_rank_tolerance(this, tolerance)
    class(mumps_solver_t), intent(inout) :: this
    real(dp), intent(in) :: tolerance
    this%stats%low_rank_tolerance = max(tolerance, 0.0_dp)
  end subroutine mumps_set_low_rank_tolerance

  !> True when `matrix` is not the pattern analysed last.
  pure logical function needs_analysis(this, matrix)
    class(mumps_solver_t), intent(in) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    needs_analysis = this%analysed_version /= matrix%pattern_version .or. &
                     this%n /= matrix%n .or. this%nnz /= matrix%nnz
  end function needs_analysis

  !> JOB = -1: create the MUMPS instance on `communicator`, then silence its output.
  subroutine mumps_initialise(this, err)
    class(mumps_solver_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    allocate (this%id)
    nullify (this%id%IRN, this%id%JCN, this%id%A, this%id%RHS, this%id%IRN_loc, this%id%JCN_loc, &
             this%id%A_loc, this%id%PERM_IN)
    ! JOB = -1 reads KEEP (to tell a fresh instance from a live one) before setting it.
    this%id%KEEP = 0
    this%id%COMM = this%communicator
    this%id%SYM = MUMPS_UNSYMMETRIC
    this%id%PAR = MUMPS_HOST_WORKS
    call run_job(this, JOB_INITIALISE, 'initialisation', err)
    if (allocated(err)) then
      deallocate (this%id)
      return
    end if
    this%id%ICNTL(1:3) = MUMPS_NO_OUTPUT
    this%id%ICNTL(4) = MUMPS_PRINT_NOTHING
    this%id%ICNTL(5) = MUMPS_ASSEMBLED
    this%id%ICNTL(18) = MUMPS_CENTRALISED
    if (this%distributed) this%id%ICNTL(18) = MUMPS_DISTRIBUTED
    this%id%ICNTL(24) = MUMPS_DETECT_NULL_PIVOTS
    this%id%ICNTL(28) = MUMPS_SEQUENTIAL_ANALYSIS
    this%id%ICNTL(7) = MUMPS_ORDERING_GIVEN
    this%id%CNTL(3) = NEAR_SINGULAR_PIVOT_RATIO
    if (this%stats%low_rank_tolerance > 0.0_dp) then
      this%id%ICNTL(35) = MUMPS_BLR_FACTORS_AND_SOLVE
      ! CNTL(7): the dropping parameter eps of the low-rank compressions (default 0, no BLR).
      this%id%CNTL(7) = this%stats%low_rank_tolerance
    end if
  end subroutine mumps_initialise

  !> JOB = 1: coordinate copy of the pattern (and the current values, which the automatic
  !> choice of column permutation may use), then the analysis.
  subroutine mumps_analyse(this, matrix, err)
    class(mumps_solver_t), intent(inout) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    type(error_t), allocatable, intent(out) :: err
    integer :: row
    integer(i8) :: p
    integer, allocatable :: position(:)
    this%analysed_version = -1
    call release_matrix_arrays(this)
    if (this%distributed) then
      call distributed_entries(this, matrix)
    else
      allocate (this%id%IRN(matrix%nnz), this%id%JCN(matrix%nnz), this%id%A(matrix%nnz))
      do row = 1, matrix%n
        do p = matrix%row_ptr(row), matrix%row_ptr(row + 1) - 1
          this%id%IRN(p) = row
        end do
      end do
      this%id%JCN(:) = matrix%col(1:matrix%nnz)
      this%id%A(:) = matrix%val(1:matrix%nnz)
      this%id%NNZ = matrix%nnz
      this%id%NZ = 0
      if (matrix%nnz <= huge(this%id%NZ)) this%id%NZ = int(matrix%nnz)
    end if
    this%id%N = matrix%n
    if (allocated(this%given_order)) then
      if (size(this%given_order) /= matrix%n) then
        call fatal_error(err, 'MUMPS analysis: the ordering given has ' // &
          str(size(this%given_order)) // ' entries for ' // str(matrix%n) // ' equations')
        return
      end if
      call move_alloc(this%given_order, position)
    else
      call metis_equation_order(matrix, position, err)
      if (allocated(err)) return
    end if
    allocate (this%id%PERM_IN(matrix%n))
    this%id%PERM_IN(:) = position
    call run_job(this, JOB_ANALYSE, 'analysis of ' // str(matrix%n) // ' equations', err)
    if (allocated(err)) return
    this%n = matrix%n
    this%nnz = matrix%nnz
    this%analysed_version = matrix%pattern_version
  end subroutine mumps_analyse

  !> This rank's entries, in coordinate form (distributed assembled input, ICNTL(18) = 3).
  subroutine distributed_entries(this, matrix)
    class(mumps_solver_t), intent(inout) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    integer :: row
    integer(i8) :: p
    allocate (this%id%IRN_loc(matrix%nnz), this%id%JCN_loc(matrix%nnz), this%id%A_loc(matrix%nnz))
    do row = 1, matrix%n
      do p = matrix%row_ptr(row), matrix%row_ptr(row + 1) - 1
        this%id%IRN_loc(p) = row
      end do
    end do
    this%id%JCN_loc(:) = matrix%col(1:matrix%nnz)
    this%id%A_loc(:) = matrix%val(1:matrix%nnz)
    this%id%NNZ_loc = matrix%nnz
    this%id%NZ_loc = 0
    if (matrix%nnz <= huge(this%id%NZ_loc)) this%id%NZ_loc = int(matrix%nnz)
  end subroutine distributed_entries

  !> JOB = 2, repeated up to MAX_WORKSPACE_RETRIES times with a doubled ICNTL(14) when MUMPS
  !> reports a workspace too small for the factorisation (INFOG(1) = -8, -9, -17, -20). The
  !> larger ICNTL(14) is kept for the later factorisations of this instance.
  subroutine factorise_with_retries(this, err)
    class(mumps_solver_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    integer :: attempt
    do attempt = 0, MAX_WORKSPACE_RETRIES
      call run_job(this, JOB_FACTORISE, 'factorisation', err)
      if (.not. allocated(err)) return
      if (.not. is_workspace_shortage(this%id%INFOG(1))) return
      if (attempt == MAX_WORKSPACE_RETRIES) then
        call add_retry_note(err, this%id%ICNTL(14))
        return
      end if
      this%id%ICNTL(14) = 2 * max(this%id%ICNTL(14), MINIMUM_RELAXATION_PERCENT)
      deallocate (err)
    end do
  end subroutine factorise_with_retries

  !> True for the INFOG(1) values cured by a larger ICNTL(14).
  pure logical function is_workspace_shortage(code)
    integer, intent(in) :: code
    is_workspace_shortage = any(code == [MUMPS_ERROR_FACTOR_INTEGER_WORKSPACE, &
      MUMPS_ERROR_FACTOR_REAL_WORKSPACE, MUMPS_ERROR_SEND_BUFFER, MUMPS_ERROR_RECEIVE_BUFFER])
  end function is_workspace_shortage

  !> Say in `err` that the automatic retries with more workspace were used up.
  subroutine add_retry_note(err, relaxation)
    type(error_t), intent(inout) :: err
    integer, intent(in) :: relaxation
    err%message = err%message // ' (after ' // str(MAX_WORKSPACE_RETRIES) // &
      ' retries with more workspace, last ICNTL(14) = ' // str(relaxation) // '%)'
  end subroutine add_retry_note

  !> Solve A x = b (JOB = 3, dense centralised right-hand side overwritten by the solution).
  subroutine mumps_solve(this, matrix, b, x, err)
    class(mumps_solver_t), intent(inout) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    real(dp), intent(in) :: b(:)
    real(dp), intent(out) :: x(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp) :: started
    started = wall_time()
    if (.not. this%factored) then
      call fatal_error(err, 'MUMPS solve: called without a successful factorisation')
      return
    else if (matrix%n /= this%n .or. matrix%pattern_version /= this%analysed_version) then
      call fatal_error(err, 'MUMPS solve: called with a matrix other than the one ' // &
        'factorised (' // str(matrix%n) // ' equations, ' // str(this%n) // ' factorised)')
      return
    else if (size(b) /= this%n .or. size(x) /= this%n) then
      call fatal_error(err, 'MUMPS solve: right-hand side of length ' // str(size(b)) // &
        ' and solution of length ' // str(size(x)) // ' for ' // str(this%n) // ' equations')
      return
    end if
    if (associated(this%id%RHS)) then
      if (size(this%id%RHS) /= this%n) deallocate (this%id%RHS)
    end if
    if (.not. associated(this%id%RHS)) allocate (this%id%RHS(this%n))
    ! Distributed: the right-hand side is read and the solution returned on rank 0 only.
    this%id%RHS(:) = b
    this%id%NRHS = 1
    this%id%LRHS = this%n
    call run_job(this, JOB_SOLVE, 'solve', err)
    if (allocated(err)) return
    x(:) = this%id%RHS
    if (this%distributed) call this%comm%broadcast_real(x)
    this%stats%solve_seconds = wall_time() - started
  end subroutine mumps_solve

  !> Terminate the MUMPS instance (JOB = -2, which frees the library's own storage), then
  !> deallocate the arrays this wrapper gave it. Statistics are kept.
  subroutine mumps_free(this)
    class(mumps_solver_t), intent(inout) :: this
    type(error_t), allocatable :: err
    if (allocated(this%id)) then
      ! A failure to terminate cannot be reported from `free`; the storage is released anyway.
      call run_job(this, JOB_TERMINATE, 'termination', err)
      call release_matrix_arrays(this)
      if (associated(this%id%RHS)) deallocate (this%id%RHS)
      deallocate (this%id)
    end if
    this%n = 0
    this%nnz = -1
    this%analysed_version = -1
    this%factored = .false.
  end subroutine mumps_free

  !> Deallocate the coordinate copy of the matrix given to MUMPS (IRN, JCN, A).
  subroutine release_matrix_arrays(this)
    class(mumps_solver_t), intent(inout) :: this
    if (associated(this%id%IRN)) deallocate (this%id%IRN)
    if (associated(this%id%JCN)) deallocate (this%id%JCN)
    if (associated(this%id%A)) deallocate (this%id%A)
    if (associated(this%id%IRN_loc)) deallocate (this%id%IRN_loc)
    if (associated(this%id%JCN_loc)) deallocate (this%id%JCN_loc)
    if (associated(this%id%A_loc)) deallocate (this%id%A_loc)
    if (associated(this%id%PERM_IN)) deallocate (this%id%PERM_IN)
  end subroutine release_matrix_arrays

  !> The solver's name as the deck spells it.
  function mumps_name(this) result(name)
    class(mumps_solver_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'MUMPS'
  end function mumps_name

  !> Run one MUMPS phase and turn a negative INFOG(1) into an error naming the phase.
  subroutine run_job(this, job, phase, err)
    class(mumps_solver_t), intent(inout) :: this
    integer, intent(in) :: job
    character(len=*), intent(in) :: phase
    type(error_t), allocatable, intent(out) :: err
    this%id%JOB = job
    call dmumps(this%id)
    if (this%id%INFOG(1) < 0) then
      if (any(this%id%INFOG(1) == [MUMPS_ERROR_ANALYSIS_REAL_ALLOCATION, &
              MUMPS_ERROR_ANALYSIS_INTEGER_ALLOCATION, MUMPS_ERROR_ALLOCATION])) then
        call memory_error(err, 'MUMPS ran its ' // phase // ' (JOB=' // str(job) // '; ' // &
          'an allocation of ' // workspace_size(this%id%INFOG(2)) // ' failed, INFOG(1)=' // &
          str(this%id%INFOG(1)) // ')', 8_i8 * workspace_entries(this%id%INFOG(2)))
      else
        call fatal_error(err, 'MUMPS ' // phase // ' (JOB=' // str(job) // '): ' // &
          infog_text(this%id%INFOG(1), this%id%INFOG(2)))
      end if
    end if
  end subroutine run_job

  !> A workspace size as MUMPS reports it in INFO(2)/INFOG(2), in entries.
  pure integer(i8) function workspace_entries(detail)
    integer, intent(in) :: detail
    if (detail < 0) then
      workspace_entries = 1000000_i8 * int(-detail, i8)
    else
      workspace_entries = int(detail, i8)
    end if
  end function workspace_entries

  !> The ordering MUMPS used, from INFOG(7) (MUMPS 5.5 User's Guide, ICNTL(7)).
  pure function ordering_name(code) result(name)
    integer, intent(in) :: code
    character(len=:), allocatable :: name
    select case (code)
    case (0)
      name = 'AMD'
    case (2)
      name = 'AMF'
    case (3)
      name = 'SCOTCH'
    case (4)
      name = 'PORD'
    case (5)
      name = 'METIS'
    case (1)
      name = 'METIS (fcs3d)'
    case (6)
      name = 'QAMD'
    case default
      name = 'code ' // str(code)
    end select
  end function ordering_name

  !> Number of entries in the factors from INFOG(29) (negative: millions of entries).
  pure real(dp) function factor_entries(infog29)
    integer, intent(in) :: infog29
    if (infog29 < 0) then
      factor_entries = 1.0e6_dp * real(-infog29, dp)
    else
      factor_entries = real(infog29, dp)
    end if
  end function factor_entries

  !> An error INFOG(1) (with its detail INFOG(2)) in words (MUMPS 5.5 User's Guide, section
  !> "Error diagnostics"). Only the codes an assembled, centralised, unsymmetric run can meet
  !> are spelled out.
  function infog_text(code, detail) result(text)
    integer, intent(in) :: code, detail
    character(len=:), allocatable :: text
    character(len=:), allocatable :: codes
    codes = ' (INFOG(1)=' // str(code) // ', INFOG(2)=' // str(detail) // ')'
    select case (code)
    case (MUMPS_ERROR_NNZ_RANGE)
      text = 'the number of entries NNZ is out of range'
    case (MUMPS_ERROR_JOB)
      text = 'invalid JOB or phases called out of order'
    case (MUMPS_ERROR_ANALYSIS_REAL_ALLOCATION, MUMPS_ERROR_ANALYSIS_INTEGER_ALLOCATION, &
          MUMPS_ERROR_ALLOCATION)
      text = 'out of memory: allocation of ' // workspace_size(detail) // ' failed'
    case (MUMPS_ERROR_STRUCTURALLY_SINGULAR)
      text = 'the matrix is structurally singular (structural rank ' // str(detail) // &
             '): check that every body is supported (rigid-body modes) and that contact is closed'
    case (MUMPS_ERROR_FACTOR_INTEGER_WORKSPACE, MUMPS_ERROR_FACTOR_REAL_WORKSPACE, &
          MUMPS_ERROR_SEND_BUFFER, MUMPS_ERROR_RECEIVE_BUFFER)
      text = 'internal workspace too small for the factorisation'
    case (MUMPS_ERROR_NUMERICALLY_SINGULAR)
      text = 'the matrix is numerically singular (' // str(detail) // &
             ' pivots eliminated): check that every body is supported (rigid-body modes) and ' // &
             'that contact is closed'
    case (MUMPS_ERROR_SOLVE_REAL_WORKSPACE, MUMPS_ERROR_REFINEMENT_REAL_WORKSPACE, &
          MUMPS_ERROR_SOLVE_INTEGER_WORKSPACE, MUMPS_ERROR_REFINEMENT_INTEGER_WORKSPACE)
      text = 'internal workspace too small for the solve'
    case (MUMPS_ERROR_N_RANGE)
      text = 'the order N of the matrix is out of range'
    case (MUMPS_ERROR_USER_ARRAY)
      text = 'an array given to MUMPS is missing or has the wrong size (array number ' // &
             str(detail) // ' in the list of the User''s Guide)'
    case (MUMPS_ERROR_MPI_NOT_INITIALISED)
      text = 'MPI was not initialised before MUMPS'
    case (MUMPS_ERROR_ORDERING, MUMPS_ERROR_ORDERING_INTEGER_OVERFLOW, &
          MUMPS_ERROR_ORDERING_NEEDS_64BIT)
      text = 'the fill-reducing ordering failed'
    case default
      text = 'MUMPS error; see "Error diagnostics" in the MUMPS 5.5 User''s Guide'
    end select
    text = text // codes
  end function infog_text

  !> A workspace size as MUMPS reports it in INFO(2)/INFOG(2): entries, negative for millions.
  function workspace_size(detail) result(text)
    integer, intent(in) :: detail
    character(len=:), allocatable :: text
    if (detail < 0) then
      text = str(-detail) // ' million entries'
    else
      text = str(detail) // ' entries'
    end if
  end function workspace_size

end module fcs_mumps
