!> What the stepper learns from the trial solution of one increment and keeps until the
!> increment is taken (Xing, Mora & Makinouchi 2003, eq. 10; doc/theory.md 6): the R-minimum
!> events of the trial, the integration points that unload in it, and the nodal temperatures
!> at its end. Refilled every increment; not run state (a checkpoint does not hold it).
module fcs_increment_trial
  use fcs_kinds, only: dp
  use fcs_rmin_events, only: rmin_collector_t
  implicit none
  private
  public :: increment_trial_t

  type :: increment_trial_t
    !> The events and limits of the trial increment, each with its fraction r (10e).
    type(rmin_collector_t) :: collector
    !> Integration points on their yield surface that the trial increment unloads (q, e):
    !> assembled with the elastic tangent for the rest of the increment.
    logical, allocatable :: unloading(:, :)
    !> Nodal temperatures at the end of the trial increment (models with temperatures).
    real(dp), allocatable :: temperature(:)
  contains
    procedure :: reset_unloading => trial_reset_unloading
  end type increment_trial_t

contains

  !> No point unloads at the start of an increment (max_points per element, n_elements).
  subroutine trial_reset_unloading(this, max_points, n_elements)
    class(increment_trial_t), intent(inout) :: this
    integer, intent(in) :: max_points, n_elements
    if (.not. allocated(this%unloading)) allocate (this%unloading(max_points, n_elements))
    this%unloading = .false.
  end subroutine trial_reset_unloading

end module fcs_increment_trial
