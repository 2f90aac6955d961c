!> The command-line options that change results (--solver, --reuse-tolerance,
!> --contact-events, --low-rank-tolerance; fcs_command_line, RESULT_OPTIONS) across a restart.
!> A checkpoint records those of the run that wrote it (the /meta attribute `options`,
!> fcs_checkpoint). A restart reads the record before the model is built, so that the options
!> are in effect where the command line's are applied (fcs_driver, read_model): an option not
!> given is taken from the checkpoint; one given with another value (or given when the
!> checkpoint's run had none) is used, with a warning that the continuation will not be
!> bit-identical to the run without interruption. A checkpoint that records nothing (format
!> version 4) restarts with the options given, and the log says so.
module fcs_restart_options
  use fcs_error, only: error_t, add_context
  use fcs_run_options, only: run_options_t
  use fcs_command_line, only: RESULT_OPTIONS, parse_result_options, parse_result_option, &
                              result_option_value, result_options_text
  use fcs_checkpoint, only: checkpoint_info_t, read_checkpoint_info
  use fcs_log, only: logger_t
  implicit none
  private
  public :: take_checkpoint_options

contains

  !> On a restart from `options%restart_file`: complete `options` with the result options the
  !> checkpoint records, and say in the log what was taken and what differs. A checkpoint
  !> that cannot be read is left to the restart proper, which reports it (and offers an
  !> older generation).
  subroutine take_checkpoint_options(options, log, err)
    type(run_options_t), intent(inout) :: options
    type(logger_t), intent(inout) :: log
    type(error_t), allocatable, intent(out) :: err
    type(checkpoint_info_t) :: info
    type(run_options_t) :: recorded
    type(error_t), allocatable :: unreadable
    character(len=:), allocatable :: given
    integer :: k
    if (len(options%restart_file) == 0) return
    call read_checkpoint_info(options%restart_file, info, unreadable)
    if (allocated(unreadable)) return
    if (.not. info%records_options) then
      given = result_options_text(options)
      if (len(given) == 0) given = 'none given'
      call log%info('restart: the checkpoint ' // options%restart_file // ' does not record ' // &
        'the command-line options of the run that wrote it (written by an fcs3d before ' // &
        'checkpoint format 5): the options given now are used (' // given // ')')
      return
    end if
    call parse_result_options(info%options, recorded, err)
    if (allocated(err)) then
      call add_context(err, 'reading checkpoint ' // options%restart_file // ': its record ' // &
        'of the command-line options ("' // info%options // '") cannot be read (the file is ' // &
        'damaged, or was written by another fcs3d)')
      return
    end if
    do k = 1, size(RESULT_OPTIONS)
      call take_option(trim(RESULT_OPTIONS(k)), recorded, options, log, err)
      if (allocated(err)) return
    end do
  end subroutine take_checkpoint_options

  !> Option `name`: taken from `recorded` when `options` does not give it; a warning when
  !> `options` gives it with another value than the checkpoint's run had.
  subroutine take_option(name, recorded, options, log, err)
    character(len=*), intent(in) :: name
    type(run_options_t), intent(in) :: recorded
    type(run_options_t), intent(inout) :: options
    type(logger_t), intent(inout) :: log
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: given, before
    given = result_option_value(options, name)
    before = result_option_value(recorded, name)
    if (given == before) return
    if (len(given) == 0) then
      call parse_result_option(name, before, options, err)
      if (.not. allocated(err)) call log%info('restart: ' // name // ' ' // before // &
                                              ' from the checkpoint')
    else if (len(before) == 0) then
      call log%warn('restart: ' // name // ' ' // given // ' given, but the run that wrote the ' // &
        'checkpoint had no ' // name // ' (the deck''s setting): the continuation will not be ' // &
        'bit-identical to the uninterrupted run unless the deck sets the same')
    else
      call log%warn('restart: ' // name // ' ' // given // ' given, but the run that wrote the ' // &
        'checkpoint had ' // name // ' ' // before // ': the continuation will not be ' // &
        'bit-identical to the uninterrupted run')
    end if
  end subroutine take_option

end module fcs_restart_options
