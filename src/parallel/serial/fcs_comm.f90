!> The communicator of a run, serial build: one process, every reduction is the identity.
!> The MPI build has a module of the same name and interface (src/parallel/mpi/fcs_comm.f90);
!> the Makefile compiles one of the two.
module fcs_comm
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  implicit none
  private
  public :: comm_t, COMM_VARIANT

  !> Which variant this build holds.
  character(len=*), parameter :: COMM_VARIANT = 'serial'

  type :: comm_t
    integer :: rank = 0
    integer :: size = 1
  contains
    procedure :: init => comm_init
    procedure :: finalize => comm_finalize
    procedure :: is_root => comm_is_root
    procedure :: fortran_handle => comm_fortran_handle
    procedure :: abort => comm_abort
    procedure :: barrier => comm_barrier
    procedure :: sum_int => comm_sum_int
    procedure :: min_real => comm_min_real
    procedure :: max_real => comm_max_real
    procedure :: broadcast_int => comm_broadcast_int
    procedure :: agree_error => comm_agree_error
    procedure, private :: sum_real_1, sum_real_2, sum_real_3
    procedure, private :: broadcast_real_1, broadcast_real_2
    !> In-place sum over all ranks of a real array (rank 1-3).
    generic :: sum_real => sum_real_1, sum_real_2, sum_real_3
    !> Copy a real array from rank 0 to all ranks.
    generic :: broadcast_real => broadcast_real_1, broadcast_real_2
  end type comm_t

contains

  subroutine comm_init(this, err)
    class(comm_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    this%rank = 0
    this%size = 1
  end subroutine comm_init

  subroutine comm_finalize(this)
    class(comm_t), intent(inout) :: this
  end subroutine comm_finalize

  pure logical function comm_is_root(this)
    class(comm_t), intent(in) :: this
    comm_is_root = this%rank == 0
  end function comm_is_root

  !> The Fortran (mpif.h) handle of the communicator, for MUMPS (sequential MUMPS ignores it).
  pure integer function comm_fortran_handle(this)
    class(comm_t), intent(in) :: this
    comm_fortran_handle = 0
  end function comm_fortran_handle

  subroutine comm_abort(this, code)
    class(comm_t), intent(in) :: this
    integer, intent(in) :: code
  end subroutine comm_abort

  subroutine comm_barrier(this)
    class(comm_t), intent(in) :: this
  end subroutine comm_barrier

  subroutine comm_sum_int(this, value)
    class(comm_t), intent(in) :: this
    integer, intent(inout) :: value
  end subroutine comm_sum_int

  !> Global minimum of `value`; `owner` returns the lowest rank holding it.
  subroutine comm_min_real(this, value, owner)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: value
    integer, intent(out), optional :: owner
    if (present(owner)) owner = 0
  end subroutine comm_min_real

  subroutine comm_max_real(this, value)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: value
  end subroutine comm_max_real

  subroutine comm_broadcast_int(this, values, root)
    class(comm_t), intent(in) :: this
    integer, intent(inout) :: values(:)
    integer, intent(in) :: root
  end subroutine comm_broadcast_int

  !> After a step every rank did: if any rank has an error, every rank gets it (the message
  !> of the lowest such rank), so that all stop together.
  subroutine comm_agree_error(this, err)
    class(comm_t), intent(in) :: this
    type(error_t), allocatable, intent(inout) :: err
  end subroutine comm_agree_error

  subroutine sum_real_1(this, values)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: values(:)
  end subroutine sum_real_1

  subroutine sum_real_2(this, values)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: values(:, :)
  end subroutine sum_real_2

  subroutine sum_real_3(this, values)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: values(:, :, :)
  end subroutine sum_real_3

  subroutine broadcast_real_1(this, values)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: values(:)
  end subroutine broadcast_real_1

  subroutine broadcast_real_2(this, values)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: values(:, :)
  end subroutine broadcast_real_2

end module fcs_comm
