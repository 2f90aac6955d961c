!> Factorisation reuse: solve a sequence of tangents that change a little from one to the next
!> (the R-minimum increments and their equilibrium iterations) with the factorisation of an
!> earlier one as the preconditioner of restarted GMRES (`fcs_gmres`; Saad & Schultz 1986),
!> and factorise again only when that stops paying.
!>
!> It works with any `linear_solver_t`, which it does not own: the caller keeps its solver and
!> calls `prepare` where it would call `factor`, and `solve` where it would call `solve`.
!>
!> How it decides (every decision depends on iteration counts only, never on timings, so that
!> a run repeats itself bit for bit):
!> * `prepare` on a new matrix factorises it when no factorisation is held, when the pattern
!>   changed since the one held (`pattern_version`, order, entries), or when reuse is off
!>   (tolerance 0); otherwise it keeps the held factors and marks the matrix as not factorised.
!> * `solve` on a factorised matrix is the solver's direct solve. On a matrix that is not, it
!>   runs GMRES preconditioned by the held factors to |b - A x| <= tolerance |b| (or the
!>   caller's larger reference norm, see `solve`):
!>   - converged within `refactor_iterations` iterations: done;
!>   - converged in more: done, and the matrix is factorised now, so that its other
!>     right-hand sides and the next matrices start from fresh factors;
!>   - not converged (the rate of convergence could not reach the tolerance within
!>     `max_iterations`, or the limit was reached): the matrix is factorised and solved
!>     directly (a fallback), as if there had been no reuse.
!>
!> Parallel runs: each process holds its own share of the matrix (its elements and contact
!> elements; the solver sums the shares), and every vector whole. The product A x is each
!> process's share times x, summed over the processes (one MPI_Allreduce of n values per
!> iteration): the distributed matrix is never assembled in one place, as MUMPS never needs
!> it either. GMRES then runs the same arithmetic on every process, and the preconditioner is
!> the solver's collective solve.
module fcs_factor_reuse
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_linear_solver, only: linear_solver_t
  use fcs_gmres, only: krylov_operator_t, gmres_settings_t, gmres_result_t, gmres_solve, &
                       GMRES_CONVERGED
  use fcs_comm, only: comm_t
  use fcs_timer, only: phase_timer_t
  use fcs_strings, only: str
  implicit none
  private
  public :: factor_reuse_t, reuse_settings_t, reuse_stats_t, RECOMMENDED_REUSE_TOLERANCE

  !> Relative residual |b - A x| / |b| recommended for a solve with reused factors (reuse is
  !> off unless the deck or the command line sets a tolerance; doc/theory.md, section 7.1).
  !> Far below what the stepper can see: the equilibrium correction of each increment works
  !> to an out-of-balance force of 1e-3 of the force scale. On the contact deck of the test
  !> suite the .dat values with and without reuse agree within 1e-12 of their scale
  !> (tests/integration/contact_factor_reuse.sh).
  real(dp), parameter :: RECOMMENDED_REUSE_TOLERANCE = 1.0e-10_dp

  !> What reuse may do.
  type :: reuse_settings_t
    !> Relative residual of a solve with reused factors; 0: factorise every matrix.
    real(dp) :: tolerance = RECOMMENDED_REUSE_TOLERANCE
    !> A solve that needed more iterations than this factorises its matrix afterwards.
    integer :: refactor_iterations = 10
    !> GMRES limits (`gmres_settings_t`): a solve that cannot converge within max_iterations
    !> falls back to a factorisation.
    integer :: max_iterations = 20
    integer :: restart = 20
  end type reuse_settings_t

  !> Counts for the log.
  type :: reuse_stats_t
    !> Right-hand sides solved: directly (fresh factors) or by GMRES (reused factors).
    integer :: solves = 0
    integer :: direct_solves = 0
    integer :: krylov_solves = 0
    integer(i8) :: krylov_iterations = 0
    !> Factorisations, and why: first or changed pattern (or reuse off), a solve over the
    !> iteration threshold, a Krylov solve that did not converge (fallback).
    integer :: factorisations = 0
    integer :: pattern_factorisations = 0
    integer :: threshold_factorisations = 0
    integer :: fallbacks = 0
    !> Largest relative residual of an accepted Krylov solve.
    real(dp) :: worst_residual = 0.0_dp
  end type reuse_stats_t

  !> The reuse state next to a solver.
  type :: factor_reuse_t
    type(reuse_settings_t) :: settings
    type(reuse_stats_t) :: stats
    !> The processes over which the matrix is spread (products summed over them).
    type(comm_t) :: comm
    !> The solver holds factors (of a matrix with this pattern), and they are those of the
    !> matrix of the current `prepare`.
    logical, private :: held = .false.
    logical, private :: current = .false.
    integer, private :: held_version = -1
    integer, private :: held_n = -1
    integer(i8), private :: held_nnz = -1
  contains
    procedure :: init => reuse_init
    procedure :: prepare => reuse_prepare
    procedure :: solve => reuse_solve
    procedure :: forget => reuse_forget
    procedure :: summary => reuse_summary
  end type factor_reuse_t

  !> The operator of a reused solve: the new matrix (each process's share, summed) and the
  !> held factors as the preconditioner.
  type, extends(krylov_operator_t) :: reuse_operator_t
    class(linear_solver_t), pointer :: solver => null()
    type(sparse_matrix_t), pointer :: matrix => null()
    type(comm_t) :: comm
  contains
    procedure :: apply => operator_apply
    procedure :: precondition => operator_precondition
  end type reuse_operator_t

contains

  !> Start afresh with `settings` on the processes of `comm`.
  subroutine reuse_init(this, settings, comm)
    class(factor_reuse_t), intent(inout) :: this
    type(reuse_settings_t), intent(in) :: settings
    type(comm_t), intent(in) :: comm
    this%settings = settings
    this%stats = reuse_stats_t()
    this%comm = comm
    call this%forget()
  end subroutine reuse_init

  !> The solver's factors are no longer usable (the solver was freed or replaced).
  subroutine reuse_forget(this)
    class(factor_reuse_t), intent(inout) :: this
    this%held = .false.
    this%current = .false.
    this%held_version = -1
    this%held_n = -1
    this%held_nnz = -1
  end subroutine reuse_forget

  !> `matrix` has new values: factorise it, or keep the held factors for GMRES (see the module).
  subroutine reuse_prepare(this, solver, matrix, timers, err)
    class(factor_reuse_t), intent(inout) :: this
    class(linear_solver_t), intent(inout) :: solver
    type(sparse_matrix_t), intent(in) :: matrix
    type(phase_timer_t), intent(inout) :: timers
    type(error_t), allocatable, intent(out) :: err
    real(dp) :: changed
    this%current = .false.
    ! Collective: a process whose share changed its pattern makes every process factorise.
    changed = merge(0.0_dp, 1.0_dp, this%held .and. same_pattern(this, matrix))
    call this%comm%max_real(changed)
    if (this%settings%tolerance > 0.0_dp .and. changed == 0.0_dp) return
    call factorise(this, solver, matrix, timers, err)
    if (.not. allocated(err)) this%stats%pattern_factorisations = this%stats%pattern_factorisations + 1
  end subroutine reuse_prepare

  !> Solve matrix x = b, `matrix` being the one of the last `prepare` (see the module). A
  !> solve by GMRES stops at |b - A x| <= tolerance max(|b|, reference_norm): a caller that
  !> adds x to a larger solution (the out-of-balance part of an increment to its load part)
  !> gives that one's right-hand side norm, so that the small part is not solved to a far
  !> smaller absolute residual than the large one.
  subroutine reuse_solve(this, solver, matrix, b, x, timers, err, reference_norm)
    class(factor_reuse_t), intent(inout) :: this
    class(linear_solver_t), intent(inout), target :: solver
    type(sparse_matrix_t), intent(in), target :: matrix
    real(dp), intent(in) :: b(:)
    real(dp), intent(out) :: x(:)
    type(phase_timer_t), intent(inout) :: timers
    type(error_t), allocatable, intent(out) :: err
    real(dp), intent(in), optional :: reference_norm
    type(gmres_result_t) :: result
    real(dp) :: b_norm, scale
    this%stats%solves = this%stats%solves + 1
    if (.not. this%current) then
      b_norm = norm2(b)
      scale = b_norm
      if (present(reference_norm)) scale = max(b_norm, reference_norm)
      call krylov_solve(this, solver, matrix, b, x, timers, b_norm, scale, result, err)
      if (allocated(err)) return
      if (result%outcome == GMRES_CONVERGED) then
        this%stats%krylov_solves = this%stats%krylov_solves + 1
        if (scale > 0.0_dp) this%stats%worst_residual = max(this%stats%worst_residual, &
          result%residual_ratio * b_norm / scale)
        if (result%iterations <= this%settings%refactor_iterations) return
        call factorise(this, solver, matrix, timers, err)
        if (.not. allocated(err)) this%stats%threshold_factorisations = &
          this%stats%threshold_factorisations + 1
        return
      end if
      call factorise(this, solver, matrix, timers, err)
      if (allocated(err)) return
      this%stats%fallbacks = this%stats%fallbacks + 1
    end if
    call timers%start('solve')
    call solver%solve(matrix, b, x, err)
    call timers%stop('solve')
    if (.not. allocated(err)) this%stats%direct_solves = this%stats%direct_solves + 1
  end subroutine reuse_solve

  !> GMRES on `matrix` preconditioned by the held factors, to |b - A x| <= tolerance scale
  !> (b_norm = |b| <= scale; the relative tolerance GMRES gets is kept below 0.1, so that
  !> every accepted solve reduces its residual).
  subroutine krylov_solve(this, solver, matrix, b, x, timers, b_norm, scale, result, err)
    class(factor_reuse_t), intent(inout) :: this
    class(linear_solver_t), intent(inout), target :: solver
    type(sparse_matrix_t), intent(in), target :: matrix
    real(dp), intent(in) :: b(:)
    real(dp), intent(out) :: x(:)
    type(phase_timer_t), intent(inout) :: timers
    real(dp), intent(in) :: b_norm, scale
    type(gmres_result_t), intent(out) :: result
    type(error_t), allocatable, intent(out) :: err
    type(reuse_operator_t) :: op
    type(gmres_settings_t) :: settings
    op%solver => solver
    op%matrix => matrix
    op%comm = this%comm
    settings%tolerance = this%settings%tolerance
    if (scale > b_norm .and. b_norm > 0.0_dp) &
      settings%tolerance = min(0.1_dp, this%settings%tolerance * scale / b_norm)
    settings%max_iterations = this%settings%max_iterations
    settings%restart = this%settings%restart
    settings%rate_check_from = 3
    call timers%start('solve')
    call gmres_solve(op, b, x, settings, result, err)
    call timers%stop('solve')
    this%stats%krylov_iterations = this%stats%krylov_iterations + result%iterations
  end subroutine krylov_solve

  !> Factorise `matrix`; its factors are then the held ones.
  subroutine factorise(this, solver, matrix, timers, err)
    class(factor_reuse_t), intent(inout) :: this
    class(linear_solver_t), intent(inout) :: solver
    type(sparse_matrix_t), intent(in) :: matrix
    type(phase_timer_t), intent(inout) :: timers
    type(error_t), allocatable, intent(out) :: err
    call this%forget()
    call timers%start('factorisation')
    call solver%factor(matrix, err)
    call timers%stop('factorisation')
    if (allocated(err)) return
    this%stats%factorisations = this%stats%factorisations + 1
    this%held = .true.
    this%current = .true.
    this%held_version = matrix%pattern_version
    this%held_n = matrix%n
    this%held_nnz = matrix%nnz
  end subroutine factorise

  !> True when `matrix` has the pattern of the held factors.
  pure logical function same_pattern(this, matrix)
    type(factor_reuse_t), intent(in) :: this
    type(sparse_matrix_t), intent(in) :: matrix
    same_pattern = this%held_version == matrix%pattern_version .and. this%held_n == matrix%n .and. &
                   this%held_nnz == matrix%nnz
  end function same_pattern

  !> One line for the run summary.
  function reuse_summary(this) result(line)
    class(factor_reuse_t), intent(in) :: this
    character(len=:), allocatable :: line
    associate (s => this%stats)
      if (this%settings%tolerance <= 0.0_dp) then
        line = 'factorisation reuse: off; ' // str(s%solves) // ' solve(s), ' // &
               str(s%factorisations) // ' factorisation(s)'
        return
      end if
      line = 'factorisation reuse (tolerance ' // str(this%settings%tolerance, 3) // '): ' // &
        str(s%solves) // ' solve(s), ' // str(s%direct_solves) // ' direct, ' // &
        str(s%krylov_solves) // ' by GMRES with ' // str(s%krylov_iterations) // ' iteration(s)'
      if (s%krylov_solves > 0) line = line // ' (largest residual ' // str(s%worst_residual, 3) // ')'
      line = line // '; ' // str(s%factorisations) // ' factorisation(s): ' // &
        str(s%pattern_factorisations) // ' first or new pattern, ' // &
        str(s%threshold_factorisations) // ' over ' // str(this%settings%refactor_iterations) // &
        ' iterations, ' // str(s%fallbacks) // ' fallback(s) after GMRES did not converge'
    end associate
  end function reuse_summary

  !> y = A x: this process's share of the matrix times x, summed over the processes.
  subroutine operator_apply(this, x, y)
    class(reuse_operator_t), intent(inout) :: this
    real(dp), intent(in) :: x(:)
    real(dp), intent(out) :: y(:)
    call this%matrix%multiply(x, y)
    call this%comm%sum_real(y)
  end subroutine operator_apply

  !> z = M^-1 v with the held factors.
  subroutine operator_precondition(this, v, z, err)
    class(reuse_operator_t), intent(inout) :: this
    real(dp), intent(in) :: v(:)
    real(dp), intent(out) :: z(:)
    type(error_t), allocatable, intent(out) :: err
    call this%solver%solve(this%matrix, v, z, err)
  end subroutine operator_precondition

end module fcs_factor_reuse
