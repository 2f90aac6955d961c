!> The command line of fcs3d: options, help text, and what main should do.
module fcs_command_line
  use, intrinsic :: iso_fortran_env, only: output_unit
  use fcs_error, only: error_t, input_error, fatal_error
  use fcs_run_options, only: run_options_t
  use fcs_solver_factory, only: is_linear_solver, linear_solver_names_text, DEFAULT_LINEAR_SOLVER
  use fcs_kinds, only: dp
  use fcs_linear_solver, only: MAX_LOW_RANK_TOLERANCE
  use fcs_strings, only: to_upper, basename, path_stem, join_path, parse_real, str
  use fcs_version, only: FCS3D_IDENTITY
  use fcs_files, only: directory_exists
  implicit none
  private
  public :: parse_command_line, ACTION_RUN, ACTION_DONE

  !> What main does after parsing: run a job, or nothing more (help/version/keywords printed).
  integer, parameter :: ACTION_RUN = 1, ACTION_DONE = 2

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
        case ('--solver')
          options%solver = to_upper(argument(i))
          if (.not. is_linear_solver(options%solver)) then
            call input_error(err, '--solver ' // argument(i) // ': unknown solver; expected ' // &
                             'one of ' // linear_solver_names_text())
            return
          end if
        case ('--restart')
          options%restart_file = argument(i)
        case ('--reuse-tolerance')
          call parse_tolerance(arg, argument(i), 1.0e-3_dp, options%reuse_tolerance, err)
          if (allocated(err)) return
        case ('--contact-events')
          options%contact_events = to_upper(argument(i))
          if (all(options%contact_events /= [character(len=7) :: 'ALL', 'NORMAL', 'CLOSING'])) then
            call input_error(err, '--contact-events ' // argument(i) // ': expected ' // &
                             option_value_text('--contact-events'))
            return
          end if
        case ('--low-rank-tolerance')
          call parse_tolerance(arg, argument(i), MAX_LOW_RANK_TOLERANCE, &
                               options%low_rank_tolerance, err)
          if (allocated(err)) return
        case default
          output_dir = argument(i)
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
      '  --restart FILE        continue from a checkpoint (job.rst.h5)', &
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
