!> The contact state of every slave node of every contact pair (part of the run state, so
!> that checkpoints hold it): status, current master face and natural coordinates, gap,
!> forces, accumulated slip and slip rate, friction coefficient and friction state.
module fcs_contact_state
  use fcs_kinds, only: dp
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
  end type contact_state_t

contains

  subroutine contact_state_init(this, n)
    class(contact_state_t), intent(inout) :: this
    integer, intent(in) :: n
    this%n = n
    allocate (this%status(n), this%face(n), this%xi(2, n), this%gap(n), this%normal_force(n), &
              this%friction(2, n), this%trial_norm(n), this%slip(n), this%slip_rate(n), this%mu(n), &
              this%friction_state(n), this%tied_gap(n), this%tangential_displacement(3, n), &
              this%work(n))
    this%status = 0
    this%face = 0
    this%xi = 0.0_dp
    this%gap = huge(1.0_dp)
    this%normal_force = 0.0_dp
    this%friction = 0.0_dp
    this%trial_norm = 0.0_dp
    this%slip = 0.0_dp
    this%slip_rate = 0.0_dp
    this%mu = 0.0_dp
    this%friction_state = 0.0_dp
    this%tied_gap = 0.0_dp
    this%tangential_displacement = 0.0_dp
    this%work = 0.0_dp
  end subroutine contact_state_init

end module fcs_contact_state
