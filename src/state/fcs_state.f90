!> The run state: everything that changes during an analysis (doc/architecture.md, "Run
!> state"). This object saves and loads its own part - coordinates, displacements, reactions,
!> time, step and increment counters and the R-minimum bookkeeping (the stepper's state) -
!> through the archive (`save`, `load`); the element fields and the contact states it holds
!> save themselves (element_state_t, contact_state_t).
module fcs_state
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_archive, only: archive_t
  use fcs_element_state, only: element_state_t
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
    !> Stresses, strains and material internal variables at the integration points.
    type(element_state_t) :: elements
    !> Reaction forces at constrained degrees of freedom (3, n_nodes), last computed.
    real(dp), allocatable :: reaction(:, :)
    !> Displacements at the start of the current step (for ramped prescribed displacements).
    real(dp), allocatable :: step_start_u(:, :)
    !> Nodal temperatures now and at the start of the current step (allocated only when the
    !> model has temperatures: `init_temperature`).
    real(dp), allocatable :: temperature(:)
    real(dp), allocatable :: step_start_temperature(:)
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
    procedure :: init_temperature => state_init_temperature
    procedure :: save => state_save
    procedure :: load => state_load
  end type state_t

contains

  !> Initial state: reference geometry, zero stress at the max_points integration points of
  !> each element (the most any element of the model has).
  subroutine state_init(this, x_reference, n_elements, max_points, n_material_state)
    class(state_t), intent(inout) :: this
    real(dp), intent(in) :: x_reference(:, :)
    integer, intent(in) :: n_elements, max_points, n_material_state
    this%n_nodes = size(x_reference, 2)
    this%n_elements = n_elements
    this%x = x_reference
    allocate (this%u(3, this%n_nodes), this%reaction(3, this%n_nodes))
    this%u = 0.0_dp
    this%reaction = 0.0_dp
    this%step_start_u = this%u
    call this%elements%init(max_points, n_elements, n_material_state)
    this%time = 0.0_dp
    this%step_time = 0.0_dp
    this%step = 1
    this%increment = 0
    this%step_increment = 0
  end subroutine state_init

  !> Nodal temperatures for a model that has them: every node at its initial temperature.
  subroutine state_init_temperature(this, initial)
    class(state_t), intent(inout) :: this
    real(dp), intent(in) :: initial(:)
    this%temperature = initial
    this%step_start_temperature = initial
  end subroutine state_init_temperature

  !> Write this state's records into group /state of `archive` (the element fields add theirs
  !> to the group: element_state_t%save).
  subroutine state_save(this, archive, err)
    class(state_t), intent(in) :: this
    class(archive_t), intent(inout) :: archive
    type(error_t), allocatable, intent(out) :: err
    call archive%group('/state', err)
    if (.not. allocated(err)) call archive%put('/state/x', this%x, err)
    if (.not. allocated(err)) call archive%put('/state/u', this%u, err)
    if (.not. allocated(err)) call archive%put('/state/reaction', this%reaction, err)
    if (.not. allocated(err)) call archive%put('/state/step_start_u', this%step_start_u, err)
    if (.not. allocated(err)) call archive%put('/state/scalars', [this%time, this%step_time, &
      this%last_increment, this%last_r, this%residual_norm, this%friction_dt, &
      this%step_worst_residual, this%force_scale], err)
    if (.not. allocated(err)) call archive%put('/state/counters', [this%step, this%increment, &
      this%step_increment, this%friction_kind, this%friction_node, &
      this%step_worst_residual_increment], err)
    if (allocated(this%temperature)) then
      if (.not. allocated(err)) call archive%put('/state/temperature', this%temperature, err)
      if (.not. allocated(err)) call archive%put('/state/step_start_temperature', &
                                                 this%step_start_temperature, err)
    end if
  end subroutine state_save

  !> Read the records `save` wrote into this state, which is set up for the model (`init`), so
  !> that the sizes of the records are checked against it.
  subroutine state_load(this, archive, err)
    class(state_t), intent(inout) :: this
    class(archive_t), intent(inout) :: archive
    type(error_t), allocatable, intent(out) :: err
    real(dp) :: scalars(8)
    integer :: counters(6)
    call archive%get('/state/x', this%x, err)
    if (.not. allocated(err)) call archive%get('/state/u', this%u, err)
    if (.not. allocated(err)) call archive%get('/state/reaction', this%reaction, err)
    if (.not. allocated(err)) call archive%get('/state/step_start_u', this%step_start_u, err)
    if (.not. allocated(err)) call archive%get('/state/scalars', scalars, err)
    if (.not. allocated(err)) call archive%get('/state/counters', counters, err)
    if (allocated(this%temperature)) then
      if (.not. allocated(err)) call archive%get('/state/temperature', this%temperature, err)
      if (.not. allocated(err)) call archive%get('/state/step_start_temperature', &
                                                 this%step_start_temperature, err)
    end if
    if (allocated(err)) return
    this%time = scalars(1)
    this%step_time = scalars(2)
    this%last_increment = scalars(3)
    this%last_r = scalars(4)
    this%residual_norm = scalars(5)
    this%friction_dt = scalars(6)
    this%step_worst_residual = scalars(7)
    this%force_scale = scalars(8)
    this%step = counters(1)
    this%increment = counters(2)
    this%step_increment = counters(3)
    this%friction_kind = counters(4)
    this%friction_node = counters(5)
    this%step_worst_residual_increment = counters(6)
  end subroutine state_load

end module fcs_state
