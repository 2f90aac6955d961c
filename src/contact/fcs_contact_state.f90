!> The contact state of every slave node of every contact pair (part of the run state, so
!> that checkpoints hold it): status, current master face and natural coordinates, gap,
!> forces, accumulated slip and slip rate, friction coefficient and friction state. The
!> friction laws keep no run state of their own: the friction state of every node is here, and
!> it saves and loads itself with the rest (`save`, `load`, group /contact of a checkpoint).
module fcs_contact_state
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_archive, only: archive_t
  implicit none
  private
  public :: contact_state_t

  type :: contact_state_t
    !> Number of slave entries (one per slave node per pair).
    integer :: n = 0
    !> CONTACT_OPEN/STICK/SLIP/TIED (fcs_contact_element).
    integer, allocatable :: status(:)
    !> Candidate or current master face (index in the pair's face list; 0: none in reach).
    integer, allocatable :: face(:)
    real(dp), allocatable :: xi(:, :)
    real(dp), allocatable :: gap(:)
    !> Normal force f_n >= 0 (tied: may be negative) and friction components in the frame e_m
    !> of the master face [force].
    real(dp), allocatable :: normal_force(:)
    real(dp), allocatable :: friction(:, :)
    !> |f^tr| of the last return mapping (for the slip tangent).
    real(dp), allocatable :: trial_norm(:)
    !> Accumulated irreversible slip [length] and the slip rate of the last increment.
    real(dp), allocatable :: slip(:)
    real(dp), allocatable :: slip_rate(:)
    !> Norm of the total relative tangential velocity of the last increment (elastic + slip)
    !> [length/time]: the V of a law read with VELOCITY=RELATIVE.
    real(dp), allocatable :: relative_rate(:)
    !> Friction coefficient in use and the friction law's state variable.
    real(dp), allocatable :: mu(:)
    real(dp), allocatable :: friction_state(:)
    !> Tied pairs: the gap at which the node was tied.
    real(dp), allocatable :: tied_gap(:)
    !> Frictional work dissipated at the node, sum of |f_t| x slip [force x length].
    real(dp), allocatable :: work(:)
    !> Relative tangential displacement of the slave over the master accumulated while in
    !> contact (elastic + slip), as a vector [length].
    real(dp), allocatable :: tangential_displacement(:, :)
  contains
    procedure :: init => contact_state_init
    procedure :: save => contact_state_save
    procedure :: load => contact_state_load
  end type contact_state_t

  !> The scalar fields of a node, as the columns of /contact/scalars (this type's own layout,
  !> read back only by `load`).
  integer, parameter :: N_SCALARS = 9

contains

  subroutine contact_state_init(this, n)
    class(contact_state_t), intent(inout) :: this
    integer, intent(in) :: n
    this%n = n
    allocate (this%status(n), this%face(n), this%xi(2, n), this%gap(n), this%normal_force(n), &
              this%friction(2, n), this%trial_norm(n), this%slip(n), this%slip_rate(n), this%mu(n), &
              this%friction_state(n), this%tied_gap(n), this%tangential_displacement(3, n), &
              this%work(n), this%relative_rate(n))
    this%status = 0
    this%face = 0
    this%xi = 0.0_dp
    this%gap = huge(1.0_dp)
    this%normal_force = 0.0_dp
    this%friction = 0.0_dp
    this%trial_norm = 0.0_dp
    this%slip = 0.0_dp
    this%slip_rate = 0.0_dp
    this%relative_rate = 0.0_dp
    this%mu = 0.0_dp
    this%friction_state = 0.0_dp
    this%tied_gap = 0.0_dp
    this%tangential_displacement = 0.0_dp
    this%work = 0.0_dp
  end subroutine contact_state_init

  !> Write the states into group /contact of `archive` (nothing without slave nodes).
  subroutine contact_state_save(this, archive, err)
    class(contact_state_t), intent(in) :: this
    class(archive_t), intent(inout) :: archive
    type(error_t), allocatable, intent(out) :: err
    if (this%n == 0) return
    call archive%group('/contact', err)
    if (.not. allocated(err)) call archive%put('/contact/status', this%status, err)
    if (.not. allocated(err)) call archive%put('/contact/face', this%face, err)
    if (.not. allocated(err)) call archive%put('/contact/xi', this%xi, err)
    if (.not. allocated(err)) call archive%put('/contact/friction', this%friction, err)
    if (.not. allocated(err)) call archive%put('/contact/tangential_displacement', &
                                               this%tangential_displacement, err)
    if (.not. allocated(err)) call archive%put('/contact/scalars', reshape([this%gap, &
      this%normal_force, this%trial_norm, this%slip, this%slip_rate, this%mu, &
      this%friction_state, this%tied_gap, this%work], [this%n, N_SCALARS]), err)
    if (.not. allocated(err)) call archive%put('/contact/relative_rate', this%relative_rate, err)
  end subroutine contact_state_save

  !> Read what `save` wrote into states set up for the same slave nodes (`init`).
  subroutine contact_state_load(this, archive, err)
    class(contact_state_t), intent(inout) :: this
    class(archive_t), intent(inout) :: archive
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: scalars(:, :)
    if (this%n == 0) return
    call archive%get('/contact/status', this%status, err)
    if (.not. allocated(err)) call archive%get('/contact/face', this%face, err)
    if (.not. allocated(err)) call archive%get('/contact/xi', this%xi, err)
    if (.not. allocated(err)) call archive%get('/contact/friction', this%friction, err)
    if (.not. allocated(err)) call archive%get('/contact/tangential_displacement', &
                                               this%tangential_displacement, err)
    if (allocated(err)) return
    allocate (scalars(this%n, N_SCALARS))
    call archive%get('/contact/scalars', scalars, err)
    if (allocated(err)) return
    this%gap = scalars(:, 1)
    this%normal_force = scalars(:, 2)
    this%trial_norm = scalars(:, 3)
    this%slip = scalars(:, 4)
    this%slip_rate = scalars(:, 5)
    this%mu = scalars(:, 6)
    this%friction_state = scalars(:, 7)
    this%tied_gap = scalars(:, 8)
    this%work = scalars(:, 9)
    ! Checkpoints written before VELOCITY=RELATIVE existed have no relative rate: 0 (the laws
    ! that read it could not be in them).
    this%relative_rate = 0.0_dp
    if (archive%exists('/contact/relative_rate')) &
      call archive%get('/contact/relative_rate', this%relative_rate, err)
  end subroutine contact_state_load

end module fcs_contact_state
