!> Creates a linear solver from its name as the deck spells it (SKYLINE, UMFPACK, MUMPS).
module fcs_solver_factory
  use fcs_error, only: error_t, input_error
  use fcs_strings, only: to_upper
  use fcs_linear_solver, only: linear_solver_t
  use fcs_skyline, only: skyline_solver_t
  use fcs_umfpack, only: umfpack_solver_t
  use fcs_mumps, only: mumps_solver_t
  implicit none
  private
  public :: create_linear_solver, LINEAR_SOLVER_NAMES, DEFAULT_LINEAR_SOLVER

  !> Valid solver names, for --help, the keyword table and messages (blank-padded: trim them).
  character(len=7), parameter :: LINEAR_SOLVER_NAMES(3) = [character(len=7) :: &
    'SKYLINE', 'UMFPACK', 'MUMPS']

  !> The solver used when the deck names none.
  character(len=*), parameter :: DEFAULT_LINEAR_SOLVER = 'UMFPACK'

contains

  !> Allocate `solver` as the solver called `name` (case and surrounding blanks ignored).
  !> An unknown name is an input error that lists the valid names.
  subroutine create_linear_solver(name, solver, err)
    character(len=*), intent(in) :: name
    class(linear_solver_t), allocatable, intent(out) :: solver
    type(error_t), allocatable, intent(out) :: err
    select case (to_upper(trim(adjustl(name))))
    case ('SKYLINE')
      allocate (skyline_solver_t :: solver)
    case ('UMFPACK')
      allocate (umfpack_solver_t :: solver)
    case ('MUMPS')
      allocate (mumps_solver_t :: solver)
    case default
      call input_error(err, 'unknown linear solver "' // trim(adjustl(name)) // &
        '"; expected one of ' // valid_names())
    end select
  end subroutine create_linear_solver

  !> The valid names separated by commas.
  pure function valid_names() result(text)
    character(len=:), allocatable :: text
    integer :: i
    text = trim(LINEAR_SOLVER_NAMES(1))
    do i = 2, size(LINEAR_SOLVER_NAMES)
      text = text // ', ' // trim(LINEAR_SOLVER_NAMES(i))
    end do
  end function valid_names

end module fcs_solver_factory
