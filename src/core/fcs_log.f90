!> The run log: messages to the terminal and to `<job>.log`, and a rate-limited progress line
!> with an estimate of the time left.
!>
!> Every line is written and flushed through a checked `text_file_t`. Messages are logged from
!> everywhere, so a failed write does not travel back through each caller: the first failure
!> is kept (the file stays complete up to its last whole line and is no longer written), and
!> `check` returns it; the driver asks after each increment and at the end of the run.
module fcs_log
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error
  use fcs_timer, only: wall_time
  use fcs_strings, only: str
  use fcs_text_file, only: text_file_t
  implicit none
  private
  public :: logger_t, format_duration

  !> Where messages go. `quiet` silences the terminal except warnings and errors.
  type :: logger_t
    !> The log file (not open: terminal only).
    type(text_file_t) :: file
    !> The first failed write to the log file (then no more are tried), empty if none.
    character(len=:), allocatable :: failure
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
    procedure :: check => logger_check
    procedure :: is_open => logger_is_open
  end type logger_t

contains

  !> Open the log file `path` (truncated, or appended when `append`).
  subroutine logger_open(this, path, quiet, err, append)
    class(logger_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    logical, intent(in) :: quiet
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: append
    this%quiet = quiet
    this%failure = ''
    call this%file%open(path, err, append=append)
    if (allocated(err)) err%message = 'log file: ' // err%message
  end subroutine logger_open

  !> Close the log file; `err` (if present) receives a failed write or close of the file.
  subroutine logger_close(this, err)
    class(logger_t), intent(inout) :: this
    type(error_t), allocatable, intent(out), optional :: err
    type(error_t), allocatable :: close_err
    call this%file%close(close_err)
    if (.not. allocated(this%failure)) this%failure = ''
    if (allocated(close_err) .and. len(this%failure) == 0) this%failure = close_err%message
    if (present(err)) call this%check(err)
  end subroutine logger_close

  !> The first failed write to the log file as an error (none if every write succeeded).
  subroutine logger_check(this, err)
    class(logger_t), intent(in) :: this
    type(error_t), allocatable, intent(out) :: err
    if (allocated(this%failure)) then
      if (len(this%failure) > 0) call fatal_error(err, this%failure)
    end if
  end subroutine logger_check

  !> True while the log file is open.
  pure logical function logger_is_open(this)
    class(logger_t), intent(in) :: this
    logger_is_open = this%file%is_open()
  end function logger_is_open

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
    type(error_t), allocatable :: err
    if (.not. this%file%is_open()) return
    call this%file%write(message, err)
    if (.not. allocated(err)) call this%file%commit(err)
    if (allocated(err)) this%failure = err%message
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
