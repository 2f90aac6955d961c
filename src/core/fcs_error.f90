!> The error object returned by every fallible procedure, and the program's exit codes.
!>
!> Library code never stops the program: it allocates an `error_t` and returns; `main` turns it
!> into an exit status (STYLE.md, "Errors").
module fcs_error
  implicit none
  private
  public :: error_t, fatal_error, input_error, add_context
  public :: EXIT_OK, EXIT_INTERNAL, EXIT_INPUT, EXIT_INTERRUPTED

  !> Exit status: success.
  integer, parameter :: EXIT_OK = 0
  !> Exit status: internal failure (a library call failed, a bad state during a run).
  integer, parameter :: EXIT_INTERNAL = 1
  !> Exit status: bad input (deck, mesh, command line, restart file that does not match).
  integer, parameter :: EXIT_INPUT = 2
  !> Exit status: stopped by a signal after writing a checkpoint (SIGTERM/SIGINT).
  integer, parameter :: EXIT_INTERRUPTED = 3

  !> An error: a message (possibly several lines) and the exit status it maps to.
  type :: error_t
    character(len=:), allocatable :: message
    integer :: exit_code = EXIT_INTERNAL
    !> Already reported (the other ranks of a parallel run): exit without printing it.
    logical :: silent = .false.
  end type error_t

contains

  !> Create an internal error (exit status 1) with `message`.
  subroutine fatal_error(err, message)
    type(error_t), allocatable, intent(out) :: err
    character(len=*), intent(in) :: message
    allocate (err)
    err%message = message
    err%exit_code = EXIT_INTERNAL
  end subroutine fatal_error

  !> Create an input error (exit status 2) with `message`.
  subroutine input_error(err, message)
    type(error_t), allocatable, intent(out) :: err
    character(len=*), intent(in) :: message
    allocate (err)
    err%message = message
    err%exit_code = EXIT_INPUT
  end subroutine input_error

  !> Prefix an existing error with context, e.g. "writing results run.h5: ".
  subroutine add_context(err, context)
    type(error_t), intent(inout) :: err
    character(len=*), intent(in) :: context
    err%message = context // ': ' // err%message
  end subroutine add_context

end module fcs_error
