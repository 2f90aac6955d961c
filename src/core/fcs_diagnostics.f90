!> Source locations and the collector of input errors (`file:line: message` plus the line).
!>
!> The deck reader and model builder report every problem they find here, up to a limit, and
!> turn the collection into one `error_t` (exit status 2) at the end (STYLE.md, "Errors").
!> Warnings (input that is read, but not quite as written: a parameter CalculiX ignores, an
!> undefined id skipped in a set) are collected apart; they never stop a run, and the caller
!> passes them on to the log.
module fcs_diagnostics
  use fcs_error, only: error_t, input_error
  use fcs_strings, only: string_t, str
  implicit none
  private
  public :: source_loc_t, diagnostics_t, format_location, DEFAULT_MAX_ERRORS

  !> How many errors are collected before the reader gives up.
  integer, parameter :: DEFAULT_MAX_ERRORS = 20
  !> How many warnings are kept; further ones are counted.
  integer, parameter :: MAX_WARNINGS = 100

  !> Where a piece of input came from: file name as given, 1-based line, the line's text.
  type :: source_loc_t
    character(len=:), allocatable :: file
    integer :: line = 0
    character(len=:), allocatable :: text
  end type source_loc_t

  !> A list of input error messages, each already formatted with its location.
  type :: diagnostics_t
    type(string_t), allocatable :: messages(:)
    integer :: count = 0
    integer :: max_errors = DEFAULT_MAX_ERRORS
    !> Warnings, each formatted with its location, and how many were reported.
    type(string_t), allocatable :: warnings(:)
    integer :: n_warnings = 0
  contains
    procedure :: report => diagnostics_report
    procedure :: warn => diagnostics_warn
    procedure :: warning_list => diagnostics_warning_list
    procedure :: report_plain => diagnostics_report_plain
    procedure :: has_errors => diagnostics_has_errors
    procedure :: is_full => diagnostics_is_full
    procedure :: to_error => diagnostics_to_error
  end type diagnostics_t

contains

  !> "file:line: message" followed by "    | text" when the text is known.
  pure function format_location(loc, message) result(out)
    type(source_loc_t), intent(in) :: loc
    character(len=*), intent(in) :: message
    character(len=:), allocatable :: out
    if (.not. allocated(loc%file)) then
      out = message
      return
    end if
    out = loc%file // ':' // str(loc%line) // ': ' // message
    if (allocated(loc%text)) then
      if (len_trim(loc%text) > 0) out = out // new_line('a') // '    | ' // trim(loc%text)
    end if
  end function format_location

  !> Record an error at `loc`. Errors beyond the limit are counted but not stored.
  subroutine diagnostics_report(this, loc, message)
    class(diagnostics_t), intent(inout) :: this
    type(source_loc_t), intent(in) :: loc
    character(len=*), intent(in) :: message
    call this%report_plain(format_location(loc, message))
  end subroutine diagnostics_report

  !> Record an error whose message already says where it is.
  subroutine diagnostics_report_plain(this, message)
    class(diagnostics_t), intent(inout) :: this
    character(len=*), intent(in) :: message
    type(string_t), allocatable :: grown(:)
    this%count = this%count + 1
    if (this%count > this%max_errors) return
    if (.not. allocated(this%messages)) allocate (this%messages(0))
    allocate (grown(size(this%messages) + 1))
    grown(1:size(this%messages)) = this%messages
    grown(size(grown))%s = message
    call move_alloc(grown, this%messages)
  end subroutine diagnostics_report_plain

  !> Record a warning at `loc` ("file:line: message" and the line's text).
  subroutine diagnostics_warn(this, loc, message)
    class(diagnostics_t), intent(inout) :: this
    type(source_loc_t), intent(in) :: loc
    character(len=*), intent(in) :: message
    type(string_t), allocatable :: grown(:)
    this%n_warnings = this%n_warnings + 1
    if (this%n_warnings > MAX_WARNINGS) return
    if (.not. allocated(this%warnings)) allocate (this%warnings(0))
    allocate (grown(size(this%warnings) + 1))
    grown(1:size(this%warnings)) = this%warnings
    grown(size(grown))%s = format_location(loc, message)
    call move_alloc(grown, this%warnings)
  end subroutine diagnostics_warn

  !> The warnings kept, and a last line counting those beyond MAX_WARNINGS.
  function diagnostics_warning_list(this) result(list)
    class(diagnostics_t), intent(in) :: this
    type(string_t), allocatable :: list(:)
    if (allocated(this%warnings)) then
      list = this%warnings
    else
      allocate (list(0))
    end if
    if (this%n_warnings > size(list)) list = [list, string_t('(' // &
      str(this%n_warnings - size(list)) // ' further warnings not shown)')]
  end function diagnostics_warning_list

  logical function diagnostics_has_errors(this)
    class(diagnostics_t), intent(in) :: this
    diagnostics_has_errors = this%count > 0
  end function diagnostics_has_errors

  !> True once the limit is reached: callers may stop reading.
  logical function diagnostics_is_full(this)
    class(diagnostics_t), intent(in) :: this
    diagnostics_is_full = this%count >= this%max_errors
  end function diagnostics_is_full

  !> All collected messages as one input error (exit status 2), with a count line.
  subroutine diagnostics_to_error(this, err)
    class(diagnostics_t), intent(in) :: this
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: text
    integer :: i
    text = ''
    do i = 1, min(this%count, size(this%messages))
      if (i > 1) text = text // new_line('a')
      text = text // this%messages(i)%s
    end do
    if (this%count > size(this%messages)) then
      text = text // new_line('a') // '(' // str(this%count - size(this%messages)) // &
             ' further errors not shown)'
    end if
    text = text // new_line('a') // str(this%count) // ' error(s) in the input; nothing was run'
    call input_error(err, text)
  end subroutine diagnostics_to_error

end module fcs_diagnostics
