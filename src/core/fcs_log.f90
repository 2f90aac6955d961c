!> The run log: messages to the terminal and to `<job>.log`, and a rate-limited progress line
!> with an estimate of the time left.
module fcs_log
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error
  use fcs_timer, only: wall_time
  use fcs_strings, only: str
  implicit none
  private
  public :: logger_t, format_duration

  !> Where messages go. `quiet` silences the terminal except warnings and errors.
  type :: logger_t
    !> Fortran unit of the log file; -1 when closed (NEWUNIT numbers are negative, never -1).
    integer :: file_unit = -1
    logical :: quiet = .false.
    logical :: terminal = .true.
    real(dp) :: last_progress = -1.0e30_dp
    real(dp) :: progress_interval = 2.0_dp
  contains
    procedure :: open => logger_open
    procedure :: close => logger_close
    procedure :: info => logger_info
    procedure :: detail => logger_detail
    procedure :: warn => logger_warn
    procedure :: progress => logger_progress
  end type logger_t

contains

  !> Open the log file `path` (truncated, or appended when `append`).
  subroutine logger_open(this, path, quiet, err, append)
    class(logger_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    logical, intent(in) :: quiet
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: append
    integer :: stat
    character(len=256) :: msg
    character(len=8) :: position
    position = 'rewind'
    if (present(append)) then
      if (append) position = 'append'
    end if
    this%quiet = quiet
    open (newunit=this%file_unit, file=path, action='write', position=trim(position), &
          iostat=stat, iomsg=msg)
    if (stat /= 0) then
      this%file_unit = -1
      call fatal_error(err, 'opening log file ' // path // ': ' // trim(msg))
    end if
  end subroutine logger_open

  subroutine logger_close(this)
    class(logger_t), intent(inout) :: this
    if (this%file_unit /= -1) close (this%file_unit)
    this%file_unit = -1
  end subroutine logger_close

  !> A message for the terminal (unless quiet) and the log file.
  subroutine logger_info(this, message)
    class(logger_t), intent(inout) :: this
    character(len=*), intent(in) :: message
    if (this%terminal .and. .not. this%quiet) then
      write (output_unit, '(a)') message
      flush (output_unit)
    end if
    call this%detail(message)
  end subroutine logger_info

  !> A message for the log file only (per-increment records), flushed at once so that
  !> `tail -f job.log` follows a long run line by line.
  subroutine logger_detail(this, message)
    class(logger_t), intent(inout) :: this
    character(len=*), intent(in) :: message
    if (this%file_unit /= -1) then
      write (this%file_unit, '(a)') message
      flush (this%file_unit)
    end if
  end subroutine logger_detail

  !> A warning: always on standard error, and in the log file.
  subroutine logger_warn(this, message)
    class(logger_t), intent(inout) :: this
    character(len=*), intent(in) :: message
    if (this%terminal) write (error_unit, '(a)') 'warning: ' // message
    call this%detail('warning: ' // message)
  end subroutine logger_warn

  !> A progress line on the terminal, at most once per `progress_interval` seconds unless
  !> `force`. `fraction` is the share of the whole run done (0..1) and `elapsed` the wall
  !> seconds so far; the time left is estimated linearly from them.
  subroutine logger_progress(this, message, fraction, elapsed, force)
    class(logger_t), intent(inout) :: this
    character(len=*), intent(in) :: message
    real(dp), intent(in) :: fraction, elapsed
    logical, intent(in), optional :: force
    real(dp) :: now
    logical :: must
    character(len=:), allocatable :: eta
    must = .false.
    if (present(force)) must = force
    now = wall_time()
    if (.not. must .and. now - this%last_progress < this%progress_interval) return
    this%last_progress = now
    if (fraction > 1.0e-6_dp .and. fraction < 1.0_dp) then
      eta = ', about ' // format_duration(elapsed * (1.0_dp - fraction) / fraction) // ' left'
    else
      eta = ''
    end if
    if (this%terminal .and. .not. this%quiet) then
      write (output_unit, '(a)') message // ' [' // str(nint(100.0_dp * fraction)) // '%' // &
        ', ' // format_duration(elapsed) // ' elapsed' // eta // ']'
      flush (output_unit)
    end if
  end subroutine logger_progress

  !> Seconds as "1h 02m", "3m 12s" or "4.2 s".
  function format_duration(seconds) result(out)
    real(dp), intent(in) :: seconds
    character(len=:), allocatable :: out
    character(len=32) :: buffer
    integer :: s
    if (seconds < 60.0_dp) then
      write (buffer, '(f0.1,a)') max(seconds, 0.0_dp), ' s'
    else if (seconds < 3600.0_dp) then
      s = nint(seconds)
      write (buffer, '(i0,a,i2.2,a)') s / 60, 'm ', mod(s, 60), 's'
    else
      s = nint(seconds / 60.0_dp)
      write (buffer, '(i0,a,i2.2,a)') s / 60, 'h ', mod(s, 60), 'm'
    end if
    out = trim(buffer)
    if (out(1:1) == '.') out = '0' // out
  end function format_duration

end module fcs_log
