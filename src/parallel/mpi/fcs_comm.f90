!> The communicator of a run, MPI build (Open MPI through mpi_f08): a duplicate of
!> MPI_COMM_WORLD held in a comm_t, with the few collective operations fcs3d needs. The
!> serial build has a module of the same name and interface (src/parallel/serial/).
!>
!> Every MPI status is checked. The communicator returns errors (MPI_ERRORS_RETURN) instead of
!> letting MPI abort on its own; set-up and finalisation return an error_t or report, and a
!> failed collective operation - after which the processes can no longer agree on anything -
!> prints "fcs3d: MPI failure on rank r: <call> failed: <MPI's text>" and stops every process
!> with MPI_Abort (STYLE.md: an internal error on one rank calls MPI_Abort).
module fcs_comm
  use, intrinsic :: iso_fortran_env, only: error_unit
  use mpi_f08, only: MPI_Comm, MPI_COMM_WORLD, MPI_Init, MPI_Initialized, MPI_Finalize, &
                     MPI_Finalized, MPI_Comm_dup, MPI_Comm_free, MPI_Comm_rank, MPI_Comm_size, &
                     MPI_Abort, MPI_Barrier, MPI_Allreduce, MPI_Bcast, MPI_IN_PLACE, MPI_SUM, &
                     MPI_MIN, MPI_MAX, MPI_MINLOC, MPI_DOUBLE_PRECISION, MPI_INTEGER, &
                     MPI_2DOUBLE_PRECISION, MPI_CHARACTER, MPI_SUCCESS, MPI_Comm_set_errhandler, &
                     MPI_ERRORS_RETURN, MPI_Error_string, MPI_MAX_ERROR_STRING
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error
  implicit none
  private
  public :: comm_t, COMM_VARIANT

  character(len=*), parameter :: COMM_VARIANT = 'mpi'

  type :: comm_t
    integer :: rank = 0
    integer :: size = 1
    type(MPI_Comm) :: handle
    logical :: owns_mpi = .false.
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
    generic :: sum_real => sum_real_1, sum_real_2, sum_real_3
    generic :: broadcast_real => broadcast_real_1, broadcast_real_2
  end type comm_t

contains

  !> Start MPI (if nobody did) and duplicate MPI_COMM_WORLD.
  subroutine comm_init(this, err)
    class(comm_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    logical :: started
    integer :: status
    call MPI_Initialized(started, status)
    if (status /= MPI_SUCCESS) then
      call fatal_error(err, 'MPI_Initialized failed: ' // error_text(status))
      return
    end if
    if (.not. started) then
      call MPI_Init(status)
      if (status /= MPI_SUCCESS) then
        call fatal_error(err, 'MPI_Init failed: ' // error_text(status))
        return
      end if
      this%owns_mpi = .true.
    end if
    call MPI_Comm_dup(MPI_COMM_WORLD, this%handle, status)
    if (status /= MPI_SUCCESS) then
      call fatal_error(err, 'MPI_Comm_dup of MPI_COMM_WORLD failed: ' // error_text(status))
      return
    end if
    call MPI_Comm_set_errhandler(this%handle, MPI_ERRORS_RETURN, status)
    if (status == MPI_SUCCESS) call MPI_Comm_rank(this%handle, this%rank, status)
    if (status == MPI_SUCCESS) call MPI_Comm_size(this%handle, this%size, status)
    if (status /= MPI_SUCCESS) call fatal_error(err, 'setting up the MPI communicator ' // &
      '(MPI_Comm_set_errhandler, MPI_Comm_rank, MPI_Comm_size) failed: ' // error_text(status))
  end subroutine comm_init

  !> Free the communicator and end MPI (if this object started it). Failures are reported on
  !> standard error: the run's outcome is decided by then.
  subroutine comm_finalize(this)
    class(comm_t), intent(inout) :: this
    logical :: finished
    integer :: status
    call MPI_Finalized(finished, status)
    if (status /= MPI_SUCCESS) call report(this, 'MPI_Finalized', status)
    if (finished .or. status /= MPI_SUCCESS) return
    call MPI_Comm_free(this%handle, status)
    if (status /= MPI_SUCCESS) call report(this, 'MPI_Comm_free', status)
    if (.not. this%owns_mpi) return
    call MPI_Finalize(status)
    if (status /= MPI_SUCCESS) call report(this, 'MPI_Finalize', status)
  end subroutine comm_finalize

  !> After a collective operation: on failure say so and stop every process.
  subroutine check(this, status, what)
    class(comm_t), intent(in) :: this
    integer, intent(in) :: status
    character(len=*), intent(in) :: what
    integer :: abort_status
    if (status == MPI_SUCCESS) return
    call report(this, what, status)
    call MPI_Abort(this%handle, 1, abort_status)
  end subroutine check

  !> "fcs3d: MPI failure on rank r: <what> failed: <MPI's text>" on standard error.
  subroutine report(this, what, status)
    class(comm_t), intent(in) :: this
    character(len=*), intent(in) :: what
    integer, intent(in) :: status
    write (error_unit, '(a)') 'fcs3d: MPI failure on rank ' // itoa(this%rank) // ': ' // what // &
      ' failed: ' // error_text(status)
    flush (error_unit)
  end subroutine report

  !> MPI's text for an error code, with the code.
  function error_text(status) result(text)
    integer, intent(in) :: status
    character(len=:), allocatable :: text
    character(len=MPI_MAX_ERROR_STRING) :: buffer
    integer :: length, ignored
    buffer = ''
    length = 0
    call MPI_Error_string(status, buffer, length, ignored)
    text = buffer(1:max(0, min(length, len(buffer)))) // ' (error code ' // itoa(status) // ')'
  end function error_text

  pure logical function comm_is_root(this)
    class(comm_t), intent(in) :: this
    comm_is_root = this%rank == 0
  end function comm_is_root

  !> The Fortran (mpif.h) handle of the communicator, for MUMPS.
  pure integer function comm_fortran_handle(this)
    class(comm_t), intent(in) :: this
    comm_fortran_handle = this%handle%MPI_VAL
  end function comm_fortran_handle

  !> Stop every rank (an internal error on one rank; STYLE.md "Errors").
  subroutine comm_abort(this, code)
    class(comm_t), intent(in) :: this
    integer, intent(in) :: code
    integer :: status
    call MPI_Abort(this%handle, code, status)
    if (status /= MPI_SUCCESS) call report(this, 'MPI_Abort', status)
  end subroutine comm_abort

  subroutine comm_barrier(this)
    class(comm_t), intent(in) :: this
    integer :: status
    call MPI_Barrier(this%handle, status)
    call check(this, status, 'MPI_Barrier')
  end subroutine comm_barrier

  subroutine comm_sum_int(this, value)
    class(comm_t), intent(in) :: this
    integer, intent(inout) :: value
    integer :: status
    call MPI_Allreduce(MPI_IN_PLACE, value, 1, MPI_INTEGER, MPI_SUM, this%handle, status)
    call check(this, status, 'MPI_Allreduce (integer sum)')
  end subroutine comm_sum_int

  !> Global minimum of `value`; `owner` returns the lowest rank holding it.
  subroutine comm_min_real(this, value, owner)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: value
    integer, intent(out), optional :: owner
    real(dp) :: pair(2)
    integer :: status
    pair = [value, real(this%rank, dp)]
    call MPI_Allreduce(MPI_IN_PLACE, pair, 1, MPI_2DOUBLE_PRECISION, MPI_MINLOC, this%handle, status)
    call check(this, status, 'MPI_Allreduce (minimum)')
    value = pair(1)
    if (present(owner)) owner = nint(pair(2))
  end subroutine comm_min_real

  subroutine comm_max_real(this, value)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: value
    integer :: status
    call MPI_Allreduce(MPI_IN_PLACE, value, 1, MPI_DOUBLE_PRECISION, MPI_MAX, this%handle, status)
    call check(this, status, 'MPI_Allreduce (maximum)')
  end subroutine comm_max_real

  subroutine comm_broadcast_int(this, values, root)
    class(comm_t), intent(in) :: this
    integer, intent(inout) :: values(:)
    integer, intent(in) :: root
    integer :: status
    call MPI_Bcast(values, size(values), MPI_INTEGER, root, this%handle, status)
    call check(this, status, 'MPI_Bcast (integers)')
  end subroutine comm_broadcast_int

  !> If any rank has an error, every rank gets it (the message of the lowest such rank).
  subroutine comm_agree_error(this, err)
    class(comm_t), intent(in) :: this
    type(error_t), allocatable, intent(inout) :: err
    integer :: failing, status, length, code(2)
    character(len=:), allocatable :: message
    failing = this%size
    if (allocated(err)) failing = this%rank
    call MPI_Allreduce(MPI_IN_PLACE, failing, 1, MPI_INTEGER, MPI_MIN, this%handle, status)
    call check(this, status, 'MPI_Allreduce (agreeing on errors)')
    if (failing == this%size) return
    code = 0
    if (this%rank == failing) code = [len(err%message), err%exit_code]
    call MPI_Bcast(code, 2, MPI_INTEGER, failing, this%handle, status)
    call check(this, status, 'MPI_Bcast (error code)')
    length = code(1)
    allocate (character(len=length) :: message)
    if (this%rank == failing) message = err%message
    call MPI_Bcast(message, length, MPI_CHARACTER, failing, this%handle, status)
    call check(this, status, 'MPI_Bcast (error message)')
    if (.not. allocated(err)) allocate (err)
    err%message = message
    err%exit_code = code(2)
  end subroutine comm_agree_error

  subroutine sum_real_1(this, values)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: values(:)
    integer :: status
    call MPI_Allreduce(MPI_IN_PLACE, values, size(values), MPI_DOUBLE_PRECISION, MPI_SUM, &
                       this%handle, status)
    call check(this, status, 'MPI_Allreduce (sum of reals)')
  end subroutine sum_real_1

  subroutine sum_real_2(this, values)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: values(:, :)
    integer :: status
    call MPI_Allreduce(MPI_IN_PLACE, values, size(values), MPI_DOUBLE_PRECISION, MPI_SUM, &
                       this%handle, status)
    call check(this, status, 'MPI_Allreduce (sum of reals)')
  end subroutine sum_real_2

  subroutine sum_real_3(this, values)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: values(:, :, :)
    integer :: status
    call MPI_Allreduce(MPI_IN_PLACE, values, size(values), MPI_DOUBLE_PRECISION, MPI_SUM, &
                       this%handle, status)
    call check(this, status, 'MPI_Allreduce (sum of reals)')
  end subroutine sum_real_3

  subroutine broadcast_real_1(this, values)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: values(:)
    integer :: status
    call MPI_Bcast(values, size(values), MPI_DOUBLE_PRECISION, 0, this%handle, status)
    call check(this, status, 'MPI_Bcast (reals)')
  end subroutine broadcast_real_1

  subroutine broadcast_real_2(this, values)
    class(comm_t), intent(in) :: this
    real(dp), intent(inout) :: values(:, :)
    integer :: status
    call MPI_Bcast(values, size(values), MPI_DOUBLE_PRECISION, 0, this%handle, status)
    call check(this, status, 'MPI_Bcast (reals)')
  end subroutine broadcast_real_2

  pure function itoa(value) result(text)
    integer, intent(in) :: value
    character(len=:), allocatable :: text
    character(len=16) :: buffer
    write (buffer, '(i0)') value
    text = trim(buffer)
  end function itoa

end module fcs_comm
