!> The share of the work of this process (replicated state, distributed work): the
!> processes of the run, the contact slaves this one assembles, and the pressure faces whose
!> load stiffness rank 0 adds. The elements it assembles and updates are held by the element
!> loops (`element_loops_t%mine`, set by `set_share`). Everything else (displacements, contact
!> states) is the same on every process.
module fcs_work_share
  use fcs_comm, only: comm_t
  implicit none
  private
  public :: work_share_t

  type :: work_share_t
    !> The processes of the run (rank, size, collectives).
    type(comm_t) :: comm
    !> Whether this process assembles contact slave i (equal consecutive blocks of slaves).
    logical, allocatable :: owns_slave(:)
    !> Nodes of the faces loaded by pressures in any step, face k
    !> pressure_nodes(pressure_ptr(k):pressure_ptr(k+1)-1) (their load stiffness goes to rank 0).
    integer, allocatable :: pressure_ptr(:), pressure_nodes(:)
  contains
    procedure :: share_slaves => share_share_slaves
    procedure :: add_pressure_face => share_add_pressure_face
  end type work_share_t

contains

  !> n_slaves contact slaves in equal consecutive blocks, one per process; no pressure faces yet.
  subroutine share_share_slaves(this, n_slaves)
    class(work_share_t), intent(inout) :: this
    integer, intent(in) :: n_slaves
    integer :: i
    allocate (this%owns_slave(n_slaves))
    this%owns_slave = [((i - 1) * this%comm%size / max(n_slaves, 1) == this%comm%rank, i = 1, n_slaves)]
    allocate (this%pressure_ptr(1), this%pressure_nodes(0))
    this%pressure_ptr(1) = 1
  end subroutine share_share_slaves

  !> One more pressure face, with its nodes.
  subroutine share_add_pressure_face(this, nodes)
    class(work_share_t), intent(inout) :: this
    integer, intent(in) :: nodes(:)
    this%pressure_nodes = [this%pressure_nodes, nodes]
    this%pressure_ptr = [this%pressure_ptr, this%pressure_ptr(size(this%pressure_ptr)) + size(nodes)]
  end subroutine share_add_pressure_face

end module fcs_work_share
