!> The R-minimum event collector (Yamada et al. 1968; Xing & Makinouchi 2002, the "R-minimum
!> strategy"). Every module with discrete states (material yield, contact open/close,
!> stick/slip, ...) and every step limit offers the fraction r of the trial increment at which
!> its next event happens; the stepper scales the increment by the smallest r. Events within
!> a relative tolerance of the smallest are taken together in the same increment.
module fcs_rmin_events
  use fcs_kinds, only: dp
  implicit none
  private
  public :: rmin_collector_t, rmin_event_t, event_kind_name
  public :: EVENT_NONE, EVENT_FULL_INCREMENT, EVENT_STRAIN_LIMIT, EVENT_ROTATION_LIMIT
  public :: EVENT_YIELD, EVENT_CONTACT_CLOSE, EVENT_CONTACT_OPEN, EVENT_STICK_TO_SLIP
  public :: EVENT_SLIP_TO_STICK, EVENT_SEGMENT_CHANGE, EVENT_SLIP_RATE_CHANGE
  public :: EVENT_FRICTION_CHANGE, EVENT_STATE_CHANGE, EVENT_PENETRATION_LIMIT
  public :: EVENT_PLASTIC_STRAIN_LIMIT, EVENT_SLIP_INCREMENT
  public :: CONTACT_EVENTS_ALL, CONTACT_EVENTS_NORMAL, CONTACT_EVENTS_CLOSING, contact_events_level

  !> Event kinds. FULL_INCREMENT: nothing limited the trial increment. STRAIN_LIMIT,
  !> ROTATION_LIMIT and PLASTIC_STRAIN_LIMIT are limits (never widened to near-simultaneous
  !> events), the others discrete state changes.
  integer, parameter :: EVENT_NONE = 0, EVENT_FULL_INCREMENT = 1, EVENT_STRAIN_LIMIT = 2, &
    EVENT_ROTATION_LIMIT = 3, EVENT_YIELD = 4, EVENT_CONTACT_CLOSE = 5, EVENT_CONTACT_OPEN = 6, &
    EVENT_STICK_TO_SLIP = 7, EVENT_SLIP_TO_STICK = 8, EVENT_SEGMENT_CHANGE = 9, &
    EVENT_SLIP_RATE_CHANGE = 10, EVENT_FRICTION_CHANGE = 11, EVENT_STATE_CHANGE = 12, &
    EVENT_PENETRATION_LIMIT = 13, EVENT_PLASTIC_STRAIN_LIMIT = 14, EVENT_SLIP_INCREMENT = 15

  !> Which contact state changes are events (*RMIN, CONTACT EVENTS; doc/theory.md 6.9): ALL of
  !> them; NORMAL: closing, opening and leaving the master surface (onsets of slip and segment
  !> hand-overs left to the equilibrium iterations); CLOSING: closing only (opening left to
  !> them too). Ordered: a change is an event when the setting is at most its level.
  integer, parameter :: CONTACT_EVENTS_ALL = 1, CONTACT_EVENTS_NORMAL = 2, CONTACT_EVENTS_CLOSING = 3

  !> One event: its fraction r of the trial increment, kind, and the entity (element or node
  !> index) with a detail (integration point, contact pair).
  type :: rmin_event_t
    real(dp) :: r = huge(1.0_dp)
    integer :: kind = EVENT_NONE
    integer :: entity = 0
    integer :: detail = 0
  end type rmin_event_t

  type :: rmin_collector_t
    !> Smallest fraction offered so far (1 when nothing limits the trial increment).
    real(dp) :: r_min = 1.0_dp
    type(rmin_event_t) :: limiting
    !> Every discrete-state event offered with r <= 1, for the near-simultaneous set.
    type(rmin_event_t), allocatable :: events(:)
    integer :: n_events = 0
  contains
    procedure :: reset => collector_reset
    procedure :: offer => collector_offer
    procedure :: is_taken => collector_is_taken
    procedure :: taken_fraction => collector_taken_fraction
    procedure :: band_fraction => collector_band_fraction
    procedure :: limit_fraction => collector_limit_fraction
  end type rmin_collector_t

contains

  subroutine collector_reset(this)
    class(rmin_collector_t), intent(inout) :: this
    this%r_min = 1.0_dp
    this%limiting = rmin_event_t(1.0_dp, EVENT_FULL_INCREMENT, 0, 0)
    this%n_events = 0
    if (.not. allocated(this%events)) allocate (this%events(64))
  end subroutine collector_reset

  !> Offer an event at fraction r (ignored unless 0 <= r <= 1). Limits that are not state
  !> changes (strain, rotation) are offered the same way.
  subroutine collector_offer(this, r, kind, entity, detail)
    class(rmin_collector_t), intent(inout) :: this
    real(dp), intent(in) :: r
    integer, intent(in) :: kind, entity
    integer, intent(in), optional :: detail
    type(rmin_event_t) :: event
    type(rmin_event_t), allocatable :: grown(:)
    if (.not. (r >= 0.0_dp .and. r <= 1.0_dp)) return
    event = rmin_event_t(r, kind, entity, 0)
    if (present(detail)) event%detail = detail
    if (r < this%r_min) then
      this%r_min = r
      this%limiting = event
    end if
    if (this%n_events == size(this%events)) then
      allocate (grown(2 * size(this%events)))
      grown(1:this%n_events) = this%events(1:this%n_events)
      call move_alloc(grown, this%events)
    end if
    this%n_events = this%n_events + 1
    this%events(this%n_events) = event
  end subroutine collector_offer

  !> True when an event at fraction r happens within the increment actually taken, whose
  !> fraction is `r_taken`, with relative tolerance `tolerance` (near-simultaneous events).
  pure logical function collector_is_taken(this, r, r_taken, tolerance)
    class(rmin_collector_t), intent(in) :: this
    real(dp), intent(in) :: r, r_taken, tolerance
    collector_is_taken = r <= r_taken * (1.0_dp + tolerance) .and. this%n_events >= 0
  end function collector_is_taken

  !> The fraction of the trial increment to take: r_min, widened to the last discrete event
  !> within the relative `tolerance` of it, so that near-simultaneous events all happen in
  !> this increment. Limits that are not events (strain, rotation) are never widened.
  pure real(dp) function collector_taken_fraction(this, tolerance) result(r)
    class(rmin_collector_t), intent(in) :: this
    real(dp), intent(in) :: tolerance
    integer :: i
    r = this%r_min
    if (is_limit(this%limiting%kind) .or. this%limiting%kind == EVENT_FULL_INCREMENT) return
    do i = 1, this%n_events
      if (is_limit(this%events(i)%kind)) cycle
      if (this%events(i)%r <= this%r_min * (1.0_dp + tolerance)) r = max(r, this%events(i)%r)
    end do
    do i = 1, this%n_events
      if (is_limit(this%events(i)%kind)) r = min(r, this%events(i)%r)
    end do
  end function collector_taken_fraction

  !> The largest discrete-event fraction within `tolerance` of r_min (r_min if none): the
  !> widening of the increment to near-simultaneous events, before the limits cap it.
  pure real(dp) function collector_band_fraction(this, tolerance) result(r)
    class(rmin_collector_t), intent(in) :: this
    real(dp), intent(in) :: tolerance
    integer :: i
    r = this%r_min
    do i = 1, this%n_events
      if (is_limit(this%events(i)%kind)) cycle
      if (this%events(i)%r <= this%r_min * (1.0_dp + tolerance)) r = max(r, this%events(i)%r)
    end do
  end function collector_band_fraction

  !> The smallest fraction of the limits that are not events (strain, rotation); 1 if none.
  pure real(dp) function collector_limit_fraction(this) result(r)
    class(rmin_collector_t), intent(in) :: this
    integer :: i
    r = 1.0_dp
    do i = 1, this%n_events
      if (is_limit(this%events(i)%kind)) r = min(r, this%events(i)%r)
    end do
  end function collector_limit_fraction

  pure logical function is_limit(kind)
    integer, intent(in) :: kind
    is_limit = kind == EVENT_STRAIN_LIMIT .or. kind == EVENT_ROTATION_LIMIT .or. &
               kind == EVENT_PLASTIC_STRAIN_LIMIT
  end function is_limit

  !> Name of an event kind, for the log.
  pure function event_kind_name(kind) result(name)
    integer, intent(in) :: kind
    character(len=:), allocatable :: name
    select case (kind)
    case (EVENT_FULL_INCREMENT)
      name = 'full'
    case (EVENT_STRAIN_LIMIT)
      name = 'strain-limit'
    case (EVENT_ROTATION_LIMIT)
      name = 'rotation-limit'
    case (EVENT_YIELD)
      name = 'yield'
    case (EVENT_CONTACT_CLOSE)
      name = 'close'
    case (EVENT_CONTACT_OPEN)
      name = 'open'
    case (EVENT_STICK_TO_SLIP)
      name = 'stick->slip'
    case (EVENT_SLIP_TO_STICK)
      name = 'slip->stick'
    case (EVENT_SEGMENT_CHANGE)
      name = 'segment-change'
    case (EVENT_SLIP_RATE_CHANGE)
      name = 'slip-rate-change'
    case (EVENT_FRICTION_CHANGE)
      name = 'friction-change'
    case (EVENT_STATE_CHANGE)
      name = 'state-change'
    case (EVENT_PENETRATION_LIMIT)
      name = 'penetration-limit'
    case (EVENT_PLASTIC_STRAIN_LIMIT)
      name = 'plastic-strain-limit'
    case (EVENT_SLIP_INCREMENT)
      name = 'slip-increment'
    case default
      name = 'none'
    end select
  end function event_kind_name

  !> The CONTACT_EVENTS_* level of a value of *RMIN, CONTACT EVENTS or --contact-events (ALL
  !> when absent; the keyword table has checked the value).
  pure integer function contact_events_level(value) result(level)
    character(len=*), intent(in) :: value
    select case (value)
    case ('NORMAL')
      level = CONTACT_EVENTS_NORMAL
    case ('CLOSING')
      level = CONTACT_EVENTS_CLOSING
    case default
      level = CONTACT_EVENTS_ALL
    end select
  end function contact_events_level

end module fcs_rmin_events
