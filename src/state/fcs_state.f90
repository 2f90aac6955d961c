!> The run state: everything that changes during an analysis, in one object, so that a
!> checkpoint is "write state_t" and a restart is "read state_t" (doc/architecture.md).
module fcs_state
  use fcs_kinds, only: dp
  use fcs_hex8_shape, only: N_GAUSS_HEX8
  use fcs_contact_state, only: contact_state_t
  implicit none
  private
  public :: state_t

  type :: state_t
    integer :: n_nodes = 0
    integer :: n_elements = 0
    !> Current coordinates (3, n_nodes) and total displacements from the reference.
    real(dp), allocatable :: x(:, :)
    real(dp), allocatable :: u(:, :)
    !> Cauchy stress and accumulated strain at the integration points (6, 8, n_elements),
    !> Voigt order 11, 22, 33, 12, 13, 23; strains with engineering shear.
    real(dp), allocatable :: stress(:, :, :)
    real(dp), allocatable :: strain(:, :, :)
    !> Material internal variables (n_state, 8, n_elements); n_state may be 0.
    real(dp), allocatable :: material_state(:, :, :)
    !> Reaction forces at constrained degrees of freedom (3, n_nodes), last computed.
    real(dp), allocatable :: reaction(:, :)
    !> Displacements at the start of the current step (for ramped prescribed displacements).
    real(dp), allocatable :: step_start_u(:, :)
    !> Total time, time within the current step, current step (1-based).
    real(dp) :: time = 0.0_dp
    real(dp) :: step_time = 0.0_dp
    integer :: step = 1
    !> Increments done in total and in the current step.
    integer :: increment = 0
    integer :: step_increment = 0
    !> Size of the last increment and its R-minimum factor.
    real(dp) :: last_increment = 0.0_dp
    real(dp) :: last_r = 1.0_dp
    !> Out-of-balance force left by the last increment (ratio to the force scale), and the
    !> largest ratio of the current step with the increment that left it.
    real(dp) :: residual_norm = 0.0_dp
    real(dp) :: step_worst_residual = 0.0_dp
    !> Mean over the increments of the run of the mean nodal force flux (the force scale of
    !> the out-of-balance tolerance).
    real(dp) :: force_scale = 0.0_dp
    integer :: step_worst_residual_increment = 0
    !> Trial time increment allowed by the friction-rate limits (0: no limit), and what set
    !> it (event kind and node), from the changes over the last increment.
    real(dp) :: friction_dt = 0.0_dp
    integer :: friction_kind = 0
    integer :: friction_node = 0
    !> State of every contact slave node.
    type(contact_state_t) :: contact
  contains
    procedure :: init => state_init
  end type state_t

contains

  !> Initial state: reference geometry, zero stress.
  subroutine state_init(this, x_reference, n_elements, n_material_state)
    class(state_t), intent(inout) :: this
    real(dp), intent(in) :: x_reference(:, :)
    integer, intent(in) :: n_elements, n_material_state
    this%n_nodes = size(x_reference, 2)
    this%n_elements = n_elements
    this%x = x_reference
    allocate (this%u(3, this%n_nodes), this%reaction(3, this%n_nodes))
    this%u = 0.0_dp
    this%reaction = 0.0_dp
    this%step_start_u = this%u
    allocate (this%stress(6, N_GAUSS_HEX8, n_elements), this%strain(6, N_GAUSS_HEX8, n_elements))
    this%stress = 0.0_dp
    this%strain = 0.0_dp
    allocate (this%material_state(n_material_state, N_GAUSS_HEX8, n_elements))
    this%material_state = 0.0_dp
    this%time = 0.0_dp
    this%step_time = 0.0_dp
    this%step = 1
    this%increment = 0
    this%step_increment = 0
  end subroutine state_init

end module fcs_state
