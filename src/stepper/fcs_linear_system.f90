!> The linear system of the static-explicit increment (Xing, Mora & Makinouchi 2003, eq. 10;
!> doc/theory.md 6): the sparse tangent K (+ K_f, + load stiffness), the solver and the reuse
!> of its factors, the linear constraints eliminated from every solve, the force vectors it is
!> assembled with and the increments it is solved for. Working storage, allocated once and
!> refilled every increment; nothing here is run state (a checkpoint does not hold it).
module fcs_linear_system
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error
  use fcs_sparse, only: sparse_matrix_t
  use fcs_linear_solver, only: linear_solver_t
  use fcs_factor_reuse, only: factor_reuse_t
  use fcs_linear_constraints, only: constraint_map_t
  use fcs_nonlinear_constraints, only: nonlinear_set_t
  use fcs_timer, only: phase_timer_t
  use fcs_comm, only: comm_t
  use fcs_strings, only: str
  implicit none
  private
  public :: linear_system_t

  !> Vectors are 3 n_nodes long (node-major: node i, direction j at 3 (i - 1) + j) unless said.
  type :: linear_system_t
    type(sparse_matrix_t) :: matrix
    class(linear_solver_t), allocatable :: solver
    !> Reuse of the solver's factors across tangents (GMRES preconditioned by them).
    type(factor_reuse_t) :: reuse
    !> The linear constraints (*EQUATION) resolved into u_D = T u_I, eliminated from every
    !> solve (fcs_linear_constraints, (L1)-(L2); doc/theory.md 6.2).
    type(constraint_map_t) :: links
    !> The nonlinear constraints of NLGEOM steps (fcs_nonlinear_constraints): `links` is
    !> rebuilt from their linearisation at every state the stepper computes forces on.
    type(nonlinear_set_t) :: nonlinear
    !> A distributed run's pattern changed: the solver needs the whole model's ordering.
    logical :: ordering_due = .false.
    !> Internal and contact forces of the last assembly; external forces at the start (f_ext0)
    !> and end (f_ext1) of the trial increment; the right-hand side of the load part.
    real(dp), allocatable :: f_int(:), f_contact(:), f_ext0(:), f_ext1(:), rhs(:)
    !> The increment applied to the state (du = du_residual + r du_load); the prescribed
    !> increments of the constrained degrees of freedom.
    real(dp), allocatable :: du(:), prescribed(:)
    !> The two parts of the trial solution: du_load for the load increment over the trial
    !> time increment (scaled by r), du_residual for the out-of-balance force of the current
    !> state (applied in full, so that equilibrium errors do not linger); rhs_residual its
    !> right-hand side.
    real(dp), allocatable :: du_load(:), du_residual(:), rhs_residual(:)
    !> Equilibrium iterations: external forces at the end of the increment, nodal force
    !> flux (the force scale, per node: n_nodes long), the correction of one iteration.
    real(dp), allocatable :: f_ext_end(:), flux(:), correction(:)
    !> Degrees of freedom held in the solve: prescribed ones, those of nodes in no element,
    !> and the dependent ones of the linear constraints (`links`).
    logical, allocatable :: constrained(:)
    !> The thermal load of the last trial (models whose materials expand), and its mean nodal
    !> size: a force scale of its own for the out-of-balance tolerance (a freely expanding
    !> body carries no internal force).
    real(dp), allocatable :: f_thermal(:)
    real(dp) :: thermal_scale = 0.0_dp
  contains
    procedure :: allocate_vectors => system_allocate_vectors
    procedure :: constrain => system_constrain
    procedure :: constrain_trial => system_constrain_trial
    procedure :: solve_trial => system_solve_trial
    procedure :: solve_correction => system_solve_correction
  end type linear_system_t

contains

  !> Allocate the vectors for n_nodes nodes; forces start at zero, nothing constrained.
  subroutine system_allocate_vectors(this, n_nodes)
    class(linear_system_t), intent(inout) :: this
    integer, intent(in) :: n_nodes
    integer :: n
    n = 3 * n_nodes
    allocate (this%f_int(n), this%f_ext0(n), this%f_ext1(n), this%rhs(n), this%du(n), &
              this%prescribed(n), this%constrained(n), this%f_contact(n), this%du_load(n), &
              this%du_residual(n), this%rhs_residual(n), this%f_ext_end(n), this%correction(n), &
              this%flux(n_nodes))
    this%f_int = 0.0_dp
    this%f_contact = 0.0_dp
    this%f_ext_end = 0.0_dp
    this%constrained = .false.
  end subroutine system_allocate_vectors

  !> Eliminate the dependent degrees of freedom of the linear constraints (K <- T^T K T,
  !> fcs_linear_constraints (L2); each process its own share), then the prescribed ones
  !> (values `values`) from the matrix: rhs gets the eliminated columns' contribution on the
  !> free rows and scale * value on the constrained ones, whose diagonals become `scale`. On
  !> a system spread over processes each eliminates the known values from its own entries
  !> (their right-hand-side parts are summed) and rank 0 puts `scale` on the constrained
  !> diagonals, scale being the mean absolute diagonal of the free rows of the summed matrix
  !> (approximated by the sum of the processes' diagonals).
  subroutine system_constrain(this, comm, values, err)
    class(linear_system_t), intent(inout) :: this
    type(comm_t), intent(in) :: comm
    real(dp), intent(in) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp) :: total(2), scale
    integer :: n_free
    logical :: missing
    call this%links%reduce_matrix(this%matrix, missing)
    if (missing) then
      call fatal_error(err, 'eliminating the linear constraints: the sparse pattern lacks ' // &
                       'an entry of T^T K T (internal error: cliques not expanded)')
      return
    end if
    call this%matrix%free_diagonal_sum(this%constrained, total(1), n_free)
    total(2) = real(n_free, dp)
    call comm%sum_real(total)
    scale = 1.0_dp
    if (total(2) > 0.0_dp) scale = total(1) / (total(2) / comm%size)
    if (.not. (scale > 0.0_dp)) scale = 1.0_dp
    this%rhs = 0.0_dp
    call this%matrix%eliminate(this%constrained, values, this%rhs)
    call comm%sum_real(this%rhs)
    where (this%constrained) this%rhs = scale * values
    if (comm%is_root()) call this%matrix%set_diagonal(this%constrained, scale)
  end subroutine system_constrain

  !> The system of the load part of the trial increment: the prescribed increments imposed
  !> (`constrain`) and the load increment f_ext1 - f_ext0 added on the free rows of rhs.
  subroutine system_constrain_trial(this, comm, err)
    class(linear_system_t), intent(inout) :: this
    type(comm_t), intent(in) :: comm
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: load(:)
    call this%constrain(comm, this%prescribed, err)
    if (allocated(err)) return
    if (this%links%active()) then
      load = this%f_ext1 - this%f_ext0
      call this%links%reduce_vector(load)
      where (.not. this%constrained) this%rhs = this%rhs + load
    else
      ! The same operations, in the same order, as before the constraints: a model without
      ! them gives the results of earlier versions bit for bit.
      where (.not. this%constrained) this%rhs = this%rhs + this%f_ext1 - this%f_ext0
    end if
  end subroutine system_constrain_trial

  !> Factorise once (or reuse the factors, `fcs_factor_reuse`) and solve for both parts of the
  !> trial increment (rhs -> du_load, rhs_residual -> du_residual); a non-finite solution is an
  !> error (`node_id` names its node). With reused factors the out-of-balance part, which is
  !> added to the load part, is solved to the tolerance relative to the load part's
  !> right-hand side.
  subroutine system_solve_trial(this, timers, node_id, err)
    class(linear_system_t), intent(inout) :: this
    type(phase_timer_t), intent(inout) :: timers
    integer, intent(in) :: node_id(:)
    type(error_t), allocatable, intent(out) :: err
    call this%reuse%prepare(this%solver, this%matrix, timers, err)
    if (allocated(err)) return
    call this%reuse%solve(this%solver, this%matrix, this%rhs, this%du_load, timers, err)
    if (.not. allocated(err)) &
      call this%reuse%solve(this%solver, this%matrix, this%rhs_residual, this%du_residual, timers, &
                            err, reference_norm=norm2(this%rhs))
    if (allocated(err)) return
    call this%links%expand_vector(this%du_load)
    call this%links%expand_vector(this%du_residual)
    call check_finite(this%du_load, node_id, err)
    if (.not. allocated(err)) call check_finite(this%du_residual, node_id, err)
  end subroutine system_solve_trial

  !> Solve the constrained system for one equilibrium correction (rhs -> correction); a
  !> non-finite solution is an error.
  subroutine system_solve_correction(this, timers, node_id, err)
    class(linear_system_t), intent(inout) :: this
    type(phase_timer_t), intent(inout) :: timers
    integer, intent(in) :: node_id(:)
    type(error_t), allocatable, intent(out) :: err
    call this%reuse%prepare(this%solver, this%matrix, timers, err)
    if (.not. allocated(err)) call this%reuse%solve(this%solver, this%matrix, this%rhs, &
                                                    this%correction, timers, err)
    if (.not. allocated(err)) call this%links%expand_vector(this%correction)
    if (.not. allocated(err)) call check_finite(this%correction, node_id, err)
  end subroutine system_solve_correction

  subroutine check_finite(du, node_id, err)
    real(dp), intent(in) :: du(:)
    integer, intent(in) :: node_id(:)
    type(error_t), allocatable, intent(out) :: err
    integer :: i
    do i = 1, size(du)
      if (.not. (abs(du(i)) <= huge(1.0_dp))) then
        call fatal_error(err, 'the solution is not finite (NaN or Inf) at node ' // &
          str(node_id((i - 1) / 3 + 1)) // ', direction ' // str(i - 3 * ((i - 1) / 3)) // &
          ': a load or prescribed value overflows, or the system is badly conditioned (a ' // &
          'penalty stiffness far larger than the material stiffness)')
        return
      end if
    end do
  end subroutine check_finite

end module fcs_linear_system
