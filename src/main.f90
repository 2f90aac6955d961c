!> fcs3d: reads the command line, runs the job, turns an error into an exit status
!> (0 success, 1 internal failure, 2 bad input, 3 stopped by a signal).
program fcs3d
  use, intrinsic :: iso_fortran_env, only: error_unit, output_unit
  use, intrinsic :: iso_c_binding, only: c_int
  use fcs_error, only: error_t
  use fcs_run_options, only: run_options_t
  use fcs_command_line, only: parse_command_line, ACTION_RUN
  use fcs_driver, only: run_job
  use fcs_memory, only: pin_blas_threads, mark_normal_exit
  implicit none
  interface
    !> libc exit(): ends the process with a status and no further message (Fortran 2008's
    !> ERROR STOP would add "ERROR STOP n" and a backtrace to a plain input error).
    subroutine c_exit(status) bind(c, name='exit')
      import :: c_int
      integer(c_int), value :: status
    end subroutine c_exit
  end interface
  type(run_options_t) :: options
  type(error_t), allocatable :: err
  integer :: action
  call pin_blas_threads()
  call parse_command_line(options, action, err)
  if (.not. allocated(err) .and. action == ACTION_RUN) call run_job(options, err)
  call mark_normal_exit()
  if (allocated(err)) then
    flush (output_unit)
    if (.not. err%silent) write (error_unit, '(a)') 'fcs3d: ' // err%message
    flush (error_unit)
    call c_exit(int(err%exit_code, c_int))
  end if
end program fcs3d
