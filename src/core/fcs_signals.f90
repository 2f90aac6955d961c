!> SIGTERM and SIGINT: the run finishes its increment, writes a checkpoint and stops cleanly.
!>
!> A signal handler can only communicate through a global flag, so `received` is the one
!> mutable module variable of fcs3d (an exception to STYLE.md, "Declarations"): the handler
!> writes it, the driver reads it between increments. After the first signal the default
!> action is restored, so a second Ctrl-C ends the program at once.
module fcs_signals
  use, intrinsic :: iso_c_binding, only: c_int, c_funptr, c_funloc, c_intptr_t
  implicit none
  private
  public :: install_signal_handlers, signal_received, SIGINT_NUMBER, SIGTERM_NUMBER

  integer(c_int), parameter :: SIGINT_NUMBER = 2, SIGTERM_NUMBER = 15
  !> Default signal action (SIG_DFL is the null handler).
  integer(c_int), parameter :: SIG_DFL_VALUE = 0

  !> The last signal received (0: none).
  integer(c_int), volatile, save :: received = 0

  interface
    function c_signal(signum, handler) bind(c, name='signal') result(previous)
      import :: c_int, c_funptr
      integer(c_int), value :: signum
      type(c_funptr), value :: handler
      type(c_funptr) :: previous
    end function c_signal
    function c_signal_default(signum, handler) bind(c, name='signal') result(previous)
      import :: c_int, c_funptr, c_intptr_t
      integer(c_int), value :: signum
      integer(c_intptr_t), value :: handler
      type(c_funptr) :: previous
    end function c_signal_default
  end interface

contains

  !> The handler: remember the signal, restore the default action.
  subroutine on_signal(signum) bind(c)
    integer(c_int), value :: signum
    type(c_funptr) :: previous
    received = signum
    previous = c_signal_default(signum, int(SIG_DFL_VALUE, c_intptr_t))
  end subroutine on_signal

  !> Catch SIGTERM and SIGINT from now on.
  subroutine install_signal_handlers()
    type(c_funptr) :: previous
    previous = c_signal(SIGTERM_NUMBER, c_funloc(on_signal))
    previous = c_signal(SIGINT_NUMBER, c_funloc(on_signal))
  end subroutine install_signal_handlers

  !> The signal received since the handlers were installed (0: none).
  integer function signal_received()
    signal_received = received
  end function signal_received

end module fcs_signals
