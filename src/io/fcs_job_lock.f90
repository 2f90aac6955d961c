!> The job lock: one run of a job (one output path stem) at a time.
!>
!> Two runs of the same job in the same directory write the same `.h5`, `.dat`, CSV and
!> checkpoint files and corrupt each other's (HDF5 file locking is off so that viewers can read
!> the results while a job runs). Before it writes anything, a run takes `<job>.lock`:
!>
!> * the file is opened (created if missing, never truncated before the lock is held) and locked
!>   with `flock(LOCK_EX | LOCK_NB)`; the kernel holds that lock for the process and releases it
!>   when the process ends in any way (exit, crash, SIGKILL), so a lock is never stale: a file
!>   left by a killed run is simply locked again by the next one, which notes it;
!> * the holder writes its process id, host and start time into the file, for the message a
!>   second run prints: it is refused with exit status 2 and names that process;
!> * if the holder removed the file between our open and our lock (it was finishing), the lock
!>   is on a deleted file: the path's identity (device, inode) is compared with the locked
!>   descriptor's, and the attempt is repeated;
!> * at the end the holder removes the file while it still holds the lock.
!>
!> flock works on local file systems and on NFS (Linux emulates it with NFS byte-range locks).
module fcs_job_lock
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_ptr, c_size_t, c_long, c_null_char, &
    c_null_ptr, c_associated
  use fcs_kinds, only: i8
  use fcs_error, only: error_t, fatal_error, input_error
  use fcs_strings, only: str
  use fcs_files, only: failure_text, current_errno, file_identity, descriptor_identity, &
    remove_file, file_kind, file_kind_name, FILE_MISSING, FILE_REGULAR
  implicit none
  private
  public :: job_lock_t

  !> flock(2) operations and the errno of a lock held elsewhere (EWOULDBLOCK = EAGAIN).
  integer(c_int), parameter :: LOCK_EX = 2_c_int, LOCK_NB = 4_c_int
  integer, parameter :: ERRNO_WOULD_BLOCK = 11
  !> Attempts when the holder removes the file under us.
  integer, parameter :: MAX_ATTEMPTS = 5
  integer, parameter :: MAX_HOST = 256

  !> The lock of one job, held from `acquire` to `release`.
  type :: job_lock_t
    type(c_ptr) :: stream = c_null_ptr
    character(len=:), allocatable :: path
    !> What the lock file said when this run took it over from a run that had ended without
    !> removing it (empty otherwise), for the log.
    character(len=:), allocatable :: previous_holder
  contains
    procedure :: acquire => lock_acquire
    procedure :: release => lock_release
    procedure :: is_held => lock_is_held
  end type job_lock_t

  interface
    function c_fopen(path, mode) bind(c, name='fopen') result(stream)
      import :: c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*), mode(*)
      type(c_ptr) :: stream
    end function c_fopen
    function c_fileno(stream) bind(c, name='fileno') result(descriptor)
      import :: c_ptr, c_int
      type(c_ptr), value :: stream
      integer(c_int) :: descriptor
    end function c_fileno
    function c_fclose(stream) bind(c, name='fclose') result(status)
      import :: c_ptr, c_int
      type(c_ptr), value :: stream
      integer(c_int) :: status
    end function c_fclose
    function c_fwrite(buffer, size, count, stream) bind(c, name='fwrite') result(written)
      import :: c_char, c_size_t, c_ptr
      character(kind=c_char), intent(in) :: buffer(*)
      integer(c_size_t), value :: size, count
      type(c_ptr), value :: stream
      integer(c_size_t) :: written
    end function c_fwrite
    function c_fflush(stream) bind(c, name='fflush') result(status)
      import :: c_ptr, c_int
      type(c_ptr), value :: stream
      integer(c_int) :: status
    end function c_fflush
    function c_flock(descriptor, operation) bind(c, name='flock') result(status)
      import :: c_int
      integer(c_int), value :: descriptor, operation
      integer(c_int) :: status
    end function c_flock
    function c_ftruncate(descriptor, length) bind(c, name='ftruncate') result(status)
      import :: c_int, c_long
      integer(c_int), value :: descriptor
      integer(c_long), value :: length
      integer(c_int) :: status
    end function c_ftruncate
    function c_getpid() bind(c, name='getpid') result(pid)
      import :: c_int
      integer(c_int) :: pid
    end function c_getpid
    function c_gethostname(name, length) bind(c, name='gethostname') result(status)
      import :: c_char, c_size_t, c_int
      character(kind=c_char), intent(out) :: name(*)
      integer(c_size_t), value :: length
      integer(c_int) :: status
    end function c_gethostname
  end interface

contains

  !> Take the lock of job `job` (file `<job>.lock`). Another run holding it is an input error
  !> (exit status 2) that names it; a file that cannot be created is an internal error.
  subroutine lock_acquire(this, job, err)
    class(job_lock_t), intent(inout) :: this
    character(len=*), intent(in) :: job
    type(error_t), allocatable, intent(out) :: err
    integer :: attempt
    logical :: taken
    call this%release()
    this%path = job // '.lock'
    this%previous_holder = ''
    do attempt = 1, MAX_ATTEMPTS
      call try_lock(this, taken, err)
      if (allocated(err) .or. taken) exit
    end do
    if (.not. allocated(err) .and. .not. taken) call fatal_error(err, this%path // &
      ': the lock file keeps being removed and created again by other processes')
    if (allocated(err)) return
    call write_holder(this, err)
  end subroutine lock_acquire

  !> One attempt: open, lock without waiting, check that the locked file is still the one the
  !> path names. `taken` is false when the attempt must be repeated.
  subroutine try_lock(this, taken, err)
    class(job_lock_t), intent(inout) :: this
    logical, intent(out) :: taken
    type(error_t), allocatable, intent(out) :: err
    integer :: kind, code, status
    character(len=:), allocatable :: reason
    taken = .false.
    kind = file_kind(this%path)
    if (kind /= FILE_MISSING .and. kind /= FILE_REGULAR) then
      call fatal_error(err, 'the lock file ' // this%path // ' is ' // file_kind_name(kind) // &
        '; remove it')
      return
    end if
    this%stream = c_fopen(this%path // c_null_char, 'a+' // c_null_char)
    if (.not. c_associated(this%stream)) then
      reason = failure_text()
      call fatal_error(err, 'creating the lock file ' // this%path // ': ' // reason)
      return
    end if
    if (c_flock(c_fileno(this%stream), ior(LOCK_EX, LOCK_NB)) /= 0) then
      code = current_errno()
      reason = failure_text(code)
      status = c_fclose(this%stream)
      this%stream = c_null_ptr
      if (code == ERRNO_WOULD_BLOCK) then
        call refuse(this, err)
      else
        call fatal_error(err, 'locking ' // this%path // ': ' // reason)
      end if
      return
    end if
    if (any(file_identity(this%path) /= descriptor_identity(c_fileno(this%stream)))) then
      status = c_fclose(this%stream)
      this%stream = c_null_ptr
      return
    end if
    this%previous_holder = holder_text(this%path)
    taken = .true.
  end subroutine try_lock

  !> Another process holds the lock: say which, and what to do.
  subroutine refuse(this, err)
    class(job_lock_t), intent(in) :: this
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: holder
    holder = holder_text(this%path)
    if (len(holder) == 0) holder = 'a process that is just starting or ending'
    call input_error(err, this%path // ': this job is already running in this directory (' // &
      holder // '); a second run would overwrite its outputs. Wait until it ends, or run ' // &
      'this one under another name or in another directory (-o DIR)')
  end subroutine refuse

  !> Replace the file's text by this process's id, host and start time.
  subroutine write_holder(this, err)
    class(job_lock_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: text, reason
    character(len=8) :: date
    character(len=10) :: time
    call date_and_time(date, time)
    text = 'process ' // str(int(c_getpid())) // ' on host ' // host_name() // ', started ' // &
      date(1:4) // '-' // date(5:6) // '-' // date(7:8) // ' ' // time(1:2) // ':' // &
      time(3:4) // ':' // time(5:6) // achar(10)
    if (c_ftruncate(c_fileno(this%stream), 0_c_long) == 0) then
      if (c_fwrite(text, 1_c_size_t, int(len(text), c_size_t), this%stream) == &
          int(len(text), c_size_t)) then
        if (c_fflush(this%stream) == 0) return
      end if
    end if
    reason = failure_text()
    call fatal_error(err, 'writing the lock file ' // this%path // ': ' // reason)
    call this%release()
  end subroutine write_holder

  !> Remove the lock file and release the lock (nothing to do when not held).
  subroutine lock_release(this)
    class(job_lock_t), intent(inout) :: this
    type(error_t), allocatable :: ignored
    integer(c_int) :: status
    if (.not. c_associated(this%stream)) return
    call remove_file(this%path, ignored)
    status = c_fclose(this%stream)
    this%stream = c_null_ptr
  end subroutine lock_release

  pure logical function lock_is_held(this)
    class(job_lock_t), intent(in) :: this
    lock_is_held = c_associated(this%stream)
  end function lock_is_held

  !> The first line of the lock file (empty if none).
  function holder_text(path) result(text)
    character(len=*), intent(in) :: path
    character(len=:), allocatable :: text
    character(len=512) :: line
    integer :: unit, status
    text = ''
    open (newunit=unit, file=path, action='read', status='old', iostat=status)
    if (status /= 0) return
    read (unit, '(a)', iostat=status) line
    if (status == 0) text = trim(line)
    close (unit, iostat=status)
  end function holder_text

  !> This machine's host name ("unknown" if it cannot be had).
  function host_name() result(name)
    character(len=:), allocatable :: name
    character(kind=c_char) :: buffer(MAX_HOST)
    integer :: i
    buffer = c_null_char
    name = 'unknown'
    if (c_gethostname(buffer, int(MAX_HOST - 1, c_size_t)) /= 0) return
    name = ''
    do i = 1, MAX_HOST
      if (buffer(i) == c_null_char) exit
      name = name // buffer(i)
    end do
  end function host_name

end module fcs_job_lock
