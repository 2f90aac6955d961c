!> The command line of fcs3d: options, help text, and what main should do.
module fcs_command_line
  use, intrinsic :: iso_fortran_env, only: output_unit
  use fcs_error, only: error_t, input_error, fatal_error
  use fcs_run_options, only: run_options_t
  use fcs_solver_factory, only: is_linear_solver, linear_solver_names_text, DEFAULT_LINEAR_SOLVER
  use fcs_kinds, only: dp
  use fcs_linear_solver, only: MAX_LOW_RANK_TOLERANCE
  use fcs_strings, only: to_upper, basename, path_stem, join_path, parse_real, str, string_t, &
                         split_words
  use fcs_version, only: FCS3D_IDENTITY
  use fcs_files, only: directory_exists
  implicit none
  private
  public :: parse_command_line, ACTION_RUN, ACTION_DONE
  public :: RESULT_OPTIONS, result_options_text, parse_result_options, parse_result_option, &
            result_option_value

  !> What main does after parsing: run a job, or nothing more (help/version/keywords printed).
  integer, parameter :: ACTION_RUN = 1, ACTION_DONE = 2

  !> The options that change a run's results (recorded in its checkpoints, taken from the
  !> checkpoint by a restart that does not give them; fcs_restart_options).
  character(len=*), parameter :: RESULT_OPTIONS(4) = [character(len=20) :: '--solver', &
    '--reuse-tolerance', '--contact-events', '--low-rank-tolerance']

contains

  !> Parse the arguments into `options`; `action` says whether to run.
  subroutine parse_command_line(options, action, err)
    type(run_options_t), intent(out) :: options
    integer, intent(out) :: action
    type(error_t), allocatable, intent(out) :: err
    integer :: i, n
    character(len=:), allocatable :: arg, output_dir
    logical :: markdown, list_keywords
    options%deck_path = ''
    options%solver = ''
    options%restart_file = ''
    options%contact_events = ''
    output_dir = ''
    markdown = .false.
    list_keywords = .false.
    action = ACTION_RUN
    n = command_argument_count()
    i = 0
    do while (i < n)
      i = i + 1
      arg = argument(i)
      select case (arg)
      case ('-h', '--help')
        call print_help(err)
        action = ACTION_DONE
        return
      case ('--version')
        write (output_unit, '(a)') FCS3D_IDENTITY
        action = ACTION_DONE
        return
      case ('--list-keywords')
        list_keywords = .true.
      case ('--markdown')
        markdown = .true.
      case ('--check')
        options%check_only = .true.
      case ('-q', '--quiet')
        options%quiet = .true.
      case ('--solver', '--restart', '-o', '--output-dir', '--reuse-tolerance', '--contact-events', &
            '--low-rank-tolerance')
        if (i == n) then
          call input_error(err, 'option ' // arg // ' needs a value (fcs3d --help)')
          return
        end if
        i = i + 1
        if (len(argument(i)) == 0) then
          call input_error(err, 'option ' // arg // ' needs a value, got an empty string (' // &
            trim(option_value_text(arg)) // ')')
          return
        end if
        select case (arg)
        case ('--restart')
          options%restart_file = argument(i)
        case ('-o', '--output-dir')
          output_dir = argument(i)
        case default
          call parse_result_option(arg, argument(i), options, err)
          if (allocated(err)) return
        end select
      case default
        if (arg(1:1) == '-') then
          call input_error(err, 'unknown option ' // arg // ' (fcs3d --help lists the options)')
          return
        end if
        if (len(options%deck_path) > 0) then
          call input_error(err, 'more than one deck given (' // options%deck_path // ', ' // arg // ')')
          return
        end if
        options%deck_path = arg
      end select
    end do
    if (list_keywords) then
      call print_keywords(markdown)
      action = ACTION_DONE
      return
    end if
    if (len(options%deck_path) == 0) then
      call input_error(err, 'no input deck given; usage: fcs3d [options] job.inp (fcs3d --help)')
      return
    end if
    if (len(output_dir) == 0) then
      options%job = path_stem(options%deck_path)
    else if (.not. directory_exists(output_dir)) then
      call input_error(err, 'output directory "' // output_dir // '" does not exist (-o needs ' // &
                       'an existing directory)')
      return
    else
      options%job = join_path(output_dir, path_stem(basename(options%deck_path)))
    end if
  end subroutine parse_command_line

  !> Set result option `name` (one of RESULT_OPTIONS) of `options` from its value `text`, as
  !> the command line gives it; a value it does not accept is a command-line error.
  subroutine parse_result_option(name, text, options, err)
    character(len=*), intent(in) :: name, text
    type(run_options_t), intent(inout) :: options
    type(error_t), allocatable, intent(out) :: err
    select case (name)
    case ('--solver')
      options%solver = to_upper(text)
      if (.not. is_linear_solver(options%solver)) call input_error(err, '--solver ' // text // &
        ': unknown solver; expected one of ' // linear_solver_names_text())
    case ('--reuse-tolerance')
      call parse_tolerance(name, text, 1.0e-3_dp, options%reuse_tolerance, err)
    case ('--contact-events')
      options%contact_events = to_upper(text)
      if (all(options%contact_events /= [character(len=7) :: 'ALL', 'NORMAL', 'CLOSING'])) &
        call input_error(err, '--contact-events ' // text // ': expected ' // &
                         option_value_text('--contact-events'))
    case ('--low-rank-tolerance')
      call parse_tolerance(name, text, MAX_LOW_RANK_TOLERANCE, options%low_rank_tolerance, err)
    case default
      call input_error(err, name // ' is not an option that changes results (expected one of ' // &
                       '--solver, --reuse-tolerance, --contact-events, --low-rank-tolerance)')
    end select
  end subroutine parse_result_option

  !> The value of result option `name` in `options` as the command line would give it ('' when
  !> it was not given): names in capitals, tolerances in the fewest digits that read back to
  !> the same number, so that equal settings have equal texts.
  function result_option_value(options, name) result(text)
    type(run_options_t), intent(in) :: options
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: text
    text = ''
    select case (name)
    case ('--solver')
      if (allocated(options%solver)) text = to_upper(options%solver)
    case ('--reuse-tolerance')
      if (options%reuse_tolerance >= 0.0_dp) text = exact_text(options%reuse_tolerance)
    case ('--contact-events')
      if (allocated(options%contact_events)) text = to_upper(options%contact_events)
    case ('--low-rank-tolerance')
      if (options%low_rank_tolerance >= 0.0_dp) text = exact_text(options%low_rank_tolerance)
    end select
  end function result_option_value

  !> The result options of `options` that were given, as a command line would give them
  !> ("--reuse-tolerance 1E-10 --contact-events CLOSING"; '' when none was).
  function result_options_text(options) result(text)
    type(run_options_t), intent(in) :: options
    character(len=:), allocatable :: text, value
    integer :: k
    text = ''
    do k = 1, size(RESULT_OPTIONS)
      value = result_option_value(options, trim(RESULT_OPTIONS(k)))
      if (len(value) > 0) text = text // ' ' // trim(RESULT_OPTIONS(k)) // ' ' // value
    end do
    if (len(text) > 0) text = text(2:)
  end function result_options_text

  !> Read `text` (as result_options_text writes it: option and value, separated by spaces)
  !> into the result options of `options` (the others untouched); an option or value the
  !> command line would refuse is an error.
  subroutine parse_result_options(text, options, err)
    character(len=*), intent(in) :: text
    type(run_options_t), intent(inout) :: options
    type(error_t), allocatable, intent(out) :: err
    type(string_t), allocatable :: words(:)
    integer :: k
    words = split_words(text)
    options%solver = ''
    options%contact_events = ''
    options%reuse_tolerance = -1.0_dp
    options%low_rank_tolerance = -1.0_dp
    if (mod(size(words), 2) /= 0) then
      call input_error(err, 'options "' // text // '": an option without its value')
      return
    end if
    do k = 1, size(words), 2
      call parse_result_option(words(k)%s, words(k + 1)%s, options, err)
      if (allocated(err)) return
    end do
  end subroutine parse_result_options

  !> `value` in the fewest significant digits (up to 17) that read back to it exactly.
  function exact_text(value) result(text)
    real(dp), intent(in) :: value
    character(len=:), allocatable :: text
    real(dp) :: back
    integer :: digits
    logical :: ok
    do digits = 1, 17
      text = str(value, digits)
      call parse_real(text, back, ok)
      if (ok .and. back == value) return
    end do
  end function exact_text

  !> What option `name` expects, for the message about an empty value.
  function option_value_text(name) result(text)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: text
    select case (name)
    case ('--solver')
      text = 'UMFPACK, SKYLINE or MUMPS'
    case ('--restart')
      text = 'the checkpoint to continue from, e.g. job.rst.h5; without --restart the run starts afresh'
    case ('--reuse-tolerance')
      text = 'a number in [0, 1e-3], e.g. 1e-10 (0: factorise every tangent)'
    case ('--contact-events')
      text = 'ALL, NORMAL or CLOSING (as *RMIN, CONTACT EVENTS)'
    case ('--low-rank-tolerance')
      text = 'a number in [0, 1e-2], e.g. 1e-8 (0: full-rank factorisation)'
    case default
      text = 'an existing directory for the output files; without -o they go next to the deck'
    end select
  end function option_value_text

  !> The value of option `name` (--reuse-tolerance: a relative residual in [0, 1e-3], as
  !> *SOLVER, REUSE TOLERANCE; --low-rank-tolerance: the BLR dropping parameter in [0,
  !> MAX_LOW_RANK_TOLERANCE], as *SOLVER, LOW RANK TOLERANCE, whether the run's solver has BLR
  !> being checked with the deck): a number in [0, upper], else a command-line error.
  subroutine parse_tolerance(name, text, upper, value, err)
    character(len=*), intent(in) :: name, text
    real(dp), intent(in) :: upper
    real(dp), intent(out) :: value
    type(error_t), allocatable, intent(out) :: err
    logical :: ok
    call parse_real(text, value, ok)
    if (.not. ok .or. .not. (value >= 0.0_dp .and. value <= upper)) &
      call input_error(err, name // ' ' // text // ': expected ' // option_value_text(name))
  end subroutine parse_tolerance

  subroutine print_keywords(markdown)
    use fcs_keyword_docs, only: print_keyword_list, print_keyword_reference
    logical, intent(in) :: markdown
    if (markdown) then
      call print_keyword_reference()
    else
      call print_keyword_list()
    end if
  end subroutine print_keywords

  function argument(i) result(arg)
    integer, intent(in) :: i
    character(len=:), allocatable :: arg
    integer :: length
    call get_command_argument(i, length=length)
    allocate (character(len=length) :: arg)
    call get_command_argument(i, arg)
  end function argument

  subroutine print_help(err)
    type(error_t), allocatable, intent(out) :: err
    character(len=*), parameter :: lines(*) = [character(len=100) :: &
      'fcs3d - frictional contact systems in 3D (static-explicit, R-minimum, node-to-point contact)', &
      '', &
      'usage: fcs3d [options] job.inp', &
      '', &
      'Reads the keyword deck job.inp (Abaqus/CalculiX conventions) and writes, next to it', &
      '(or in the output directory): job.echo (the deck with defaults filled in), job.log', &
      '(run log, one line per increment), job.dat (*NODE PRINT/*EL PRINT tables in CalculiX''s', &
      'layout), job.h5 + job.xdmf (results; open job.xdmf in ParaView).', &
      '', &
      'options:', &
      '  -h, --help            this text', &
      '  --version             version and git revision', &
      '  --list-keywords       the keywords the deck may use, with their parameters', &
      '  --markdown            with --list-keywords: the deck reference in Markdown', &
      '  --check               read and check the deck and the model, write job.echo, do not run', &
      '  --restart FILE        continue from a checkpoint (job.rst.h5); --solver, --reuse-tolerance,', &
      '                        --contact-events and --low-rank-tolerance not given are taken', &
      '                        from it (the interrupted run''s), one given with another value', &
      '                        is used with a warning', &
      '  --reuse-tolerance TOL', &
      '                        relative residual of a tangent solved by GMRES with the factors', &
      '                        of an earlier one (default 0: factorise every tangent; 1e-10', &
      '                        recommended when on); overrides *SOLVER, REUSE TOLERANCE', &
      '  --contact-events ALL|NORMAL|CLOSING', &
      '                        which contact state changes end an increment: ALL (the', &
      '                        R-minimum default), only opening and closing (NORMAL: onsets', &
      '                        of slip and segment hand-overs left to the equilibrium', &
      '                        iterations, fewer increments) or only closing (CLOSING: openings', &
      '                        too); overrides *RMIN, CONTACT EVENTS in every step', &
      '  --low-rank-tolerance EPS', &
      '                        MUMPS block low-rank factorisation with dropping parameter EPS', &
      '                        in [0, 1e-2] (default 0: full rank; approximate factors, which', &
      '                        the equilibrium iterations correct); overrides *SOLVER, LOW', &
      '                        RANK TOLERANCE; needs the MUMPS solver', &
      '  -o, --output-dir DIR  write the output files into DIR (which must exist)', &
      '  -q, --quiet           no progress on the terminal (warnings and errors still shown)', &
      '', &
      'exit status: 0 success; 1 run failure (solver, bad state during the run, full disk or', &
      'other failed write, too little memory); 2 bad input (deck, mesh, command line, checkpoint', &
      'that does not match, the same job already running in the output directory); 3 stopped by', &
      'SIGTERM/SIGINT after writing a checkpoint.', &
      '', &
      'environment: OPENBLAS_NUM_THREADS (default 1: fcs3d sets it and restarts itself).', &
      '', &
      'documentation: doc/user_guide.md, doc/deck_reference.md, doc/theory.md']
    integer :: i, status
    do i = 1, size(lines)
      call help_line(trim(lines(i)), err)
      if (allocated(err)) return
      ! The solver names come from the solver factory's registry.
      if (index(lines(i), '  --check ') == 1) then
        call help_line('  --solver NAME         linear solver: ' // linear_solver_names_text() // &
                       ' (default ' // DEFAULT_LINEAR_SOLVER // ';', err)
        if (.not. allocated(err)) &
          call help_line('                        MUMPS in a parallel run)', err)
        if (allocated(err)) return
      end if
    end do
    flush (output_unit, iostat=status)
    if (status /= 0) call fatal_error(err, 'writing the help text to standard output failed ' // &
                                      '(iostat ' // str(status) // ')')
  end subroutine print_help

  !> One line of the help text on standard output; a failed write (a closed pipe, a full
  !> disk behind a redirection) is a run failure.
  subroutine help_line(text, err)
    character(len=*), intent(in) :: text
    type(error_t), allocatable, intent(inout) :: err
    integer :: status
    write (output_unit, '(a)', iostat=status) text
    if (status /= 0) call fatal_error(err, 'writing the help text to standard output failed ' // &
                                      '(iostat ' // str(status) // ')')
  end subroutine help_line

end module fcs_command_line
