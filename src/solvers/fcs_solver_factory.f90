!> Creates a linear solver from its name as the deck spells it (SKYLINE, UMFPACK, MUMPS).
!>
!> The solvers are a registry (`solver_registry_t`): one entry per solver
!> (`linear_solver_entry_t`: name and constructor). The keyword table (*SOLVER, TYPE=), the
!> command line (--solver and its help), and the messages read the names from it
!> (`linear_solver_names`, `linear_solver_names_text`). Every public procedure takes an optional
!> `registry`; without one it uses the built-in solvers (`builtin_solver_registry`). A solver is
!> added by its module and one entry in `builtin_solver_registry`, or at run time with
!> `registry%register` (the unit test registers a test-only dense solver that way).
module fcs_solver_factory
  use fcs_error, only: error_t, input_error, fatal_error
  use fcs_strings, only: string_t, to_upper, join_strings, name_index
  use fcs_linear_solver, only: linear_solver_t
  use fcs_skyline, only: skyline_solver_t
  use fcs_umfpack, only: umfpack_solver_t
  use fcs_mumps, only: mumps_solver_t
  implicit none
  private
  public :: create_linear_solver, DEFAULT_LINEAR_SOLVER
  public :: linear_solver_names, linear_solver_names_text, is_linear_solver
  public :: solver_has_low_rank, low_rank_solver_names_text
  public :: solver_registry_t, linear_solver_entry_t, solver_constructor, builtin_solver_registry

  !> The solver used when the deck names none.
  character(len=*), parameter :: DEFAULT_LINEAR_SOLVER = 'UMFPACK'

  abstract interface
    !> Allocate `solver` as a new solver of one type (not yet factorised).
    subroutine solver_constructor(solver)
      import :: linear_solver_t
      class(linear_solver_t), allocatable, intent(out) :: solver
    end subroutine solver_constructor
  end interface

  !> One solver of the registry: its name (upper case, as the deck spells it; its `name()`)
  !> and its constructor.
  type :: linear_solver_entry_t
    character(len=:), allocatable :: name
    procedure(solver_constructor), pointer, nopass :: construct => null()
  end type linear_solver_entry_t

  !> The linear solvers a run knows, in the order the messages list them.
  type :: solver_registry_t
    type(linear_solver_entry_t), allocatable :: solvers(:)
  contains
    procedure :: init => registry_init
    procedure :: free => registry_free
    procedure :: register => registry_register
    procedure :: find => registry_find
    procedure :: names => registry_names
    procedure :: size => registry_size
  end type solver_registry_t

contains

  !> Allocate `solver` as the solver called `name` (case and surrounding blanks ignored) of
  !> `registry` (by default the built-in solvers). An unknown name is an input error that
  !> lists the valid names.
  subroutine create_linear_solver(name, solver, err, registry)
    character(len=*), intent(in) :: name
    class(linear_solver_t), allocatable, intent(out) :: solver
    type(error_t), allocatable, intent(out) :: err
    type(solver_registry_t), intent(in), optional :: registry
    type(solver_registry_t) :: solvers
    integer :: k
    solvers = registry_or_builtin(registry)
    k = solvers%find(name)
    if (k == 0) then
      call input_error(err, 'unknown linear solver "' // trim(adjustl(name)) // &
        '"; expected one of ' // join_strings(solvers%names(), ', '))
      return
    end if
    call solvers%solvers(k)%construct(solver)
  end subroutine create_linear_solver

  !> The built-in solvers, one entry each: adding a solver is its module and one entry here.
  function builtin_solver_registry() result(registry)
    type(solver_registry_t) :: registry
    registry%solvers = [entry('SKYLINE', new_skyline), entry('UMFPACK', new_umfpack), &
                        entry('MUMPS', new_mumps)]
  contains
    function entry(name, construct) result(e)
      character(len=*), intent(in) :: name
      procedure(solver_constructor) :: construct
      type(linear_solver_entry_t) :: e
      e%name = name
      e%construct => construct
    end function entry
  end function builtin_solver_registry

  subroutine new_skyline(solver)
    class(linear_solver_t), allocatable, intent(out) :: solver
    allocate (skyline_solver_t :: solver)
  end subroutine new_skyline

  subroutine new_umfpack(solver)
    class(linear_solver_t), allocatable, intent(out) :: solver
    allocate (umfpack_solver_t :: solver)
  end subroutine new_umfpack

  subroutine new_mumps(solver)
    class(linear_solver_t), allocatable, intent(out) :: solver
    allocate (mumps_solver_t :: solver)
  end subroutine new_mumps

  !> The solver names of `registry` (by default the built-in solvers), in registry order: the
  !> choices of *SOLVER, TYPE= and --solver.
  function linear_solver_names(registry) result(names)
    type(solver_registry_t), intent(in), optional :: registry
    type(string_t), allocatable :: names(:)
    type(solver_registry_t) :: solvers
    solvers = registry_or_builtin(registry)
    names = solvers%names()
  end function linear_solver_names

  !> The solver names as text, "SKYLINE, UMFPACK, MUMPS", for messages and help.
  function linear_solver_names_text(registry) result(text)
    type(solver_registry_t), intent(in), optional :: registry
    character(len=:), allocatable :: text
    text = join_strings(linear_solver_names(registry), ', ')
  end function linear_solver_names_text

  !> Whether `name` (case and surrounding blanks ignored) names a solver of `registry`.
  logical function is_linear_solver(name, registry)
    character(len=*), intent(in) :: name
    type(solver_registry_t), intent(in), optional :: registry
    type(solver_registry_t) :: solvers
    solvers = registry_or_builtin(registry)
    is_linear_solver = solvers%find(name) /= 0
  end function is_linear_solver

  !> Whether the solver called `name` (case and surrounding blanks ignored) of `registry` has a
  !> block low-rank factorisation (false for an unknown name).
  logical function solver_has_low_rank(name, registry) result(has)
    character(len=*), intent(in) :: name
    type(solver_registry_t), intent(in), optional :: registry
    type(solver_registry_t) :: solvers
    class(linear_solver_t), allocatable :: solver
    integer :: k
    solvers = registry_or_builtin(registry)
    has = .false.
    k = solvers%find(name)
    if (k == 0) return
    call solvers%solvers(k)%construct(solver)
    has = solver%has_low_rank()
  end function solver_has_low_rank

  !> The names of the solvers with a block low-rank factorisation, "MUMPS", for messages.
  function low_rank_solver_names_text(registry) result(text)
    type(solver_registry_t), intent(in), optional :: registry
    character(len=:), allocatable :: text
    type(string_t), allocatable :: names(:), with_low_rank(:)
    integer :: i
    names = linear_solver_names(registry)
    allocate (with_low_rank(0))
    do i = 1, size(names)
      if (solver_has_low_rank(names(i)%s, registry)) with_low_rank = [with_low_rank, names(i)]
    end do
    text = join_strings(with_low_rank, ' or ')
  end function low_rank_solver_names_text

  !> The built-in solvers.
  subroutine registry_init(this)
    class(solver_registry_t), intent(inout) :: this
    type(solver_registry_t) :: builtin
    call this%free()
    builtin = builtin_solver_registry()
    call move_alloc(builtin%solvers, this%solvers)
  end subroutine registry_init

  !> Forget every solver.
  subroutine registry_free(this)
    class(solver_registry_t), intent(inout) :: this
    if (allocated(this%solvers)) deallocate (this%solvers)
  end subroutine registry_free

  !> Add solver `entry`. An internal error if it has no name or constructor, or if its name is
  !> already registered.
  subroutine registry_register(this, entry, err)
    class(solver_registry_t), intent(inout) :: this
    type(linear_solver_entry_t), intent(in) :: entry
    type(error_t), allocatable, intent(out) :: err
    if (.not. allocated(this%solvers)) allocate (this%solvers(0))
    if (.not. allocated(entry%name) .or. .not. associated(entry%construct)) then
      call fatal_error(err, 'solver registry: a solver needs a name and a constructor')
      return
    end if
    if (this%find(entry%name) /= 0) then
      call fatal_error(err, 'solver registry: solver ' // entry%name // ' is already registered')
      return
    end if
    this%solvers = [this%solvers, entry]
  end subroutine registry_register

  !> Index of solver `name` (case and surrounding blanks ignored), 0 if none.
  pure integer function registry_find(this, name) result(index)
    class(solver_registry_t), intent(in) :: this
    character(len=*), intent(in) :: name
    index = name_index(this%names(), name)
  end function registry_find

  !> The solver names in registry order.
  pure function registry_names(this) result(names)
    class(solver_registry_t), intent(in) :: this
    type(string_t), allocatable :: names(:)
    integer :: i
    allocate (names(this%size()))
    do i = 1, size(names)
      names(i)%s = this%solvers(i)%name
    end do
  end function registry_names

  !> Number of solvers.
  pure integer function registry_size(this) result(n)
    class(solver_registry_t), intent(in) :: this
    n = 0
    if (allocated(this%solvers)) n = size(this%solvers)
  end function registry_size

  !> `registry` if present, else the built-in solvers.
  function registry_or_builtin(registry) result(solvers)
    type(solver_registry_t), intent(in), optional :: registry
    type(solver_registry_t) :: solvers
    if (present(registry)) then
      solvers = registry
    else
      solvers = builtin_solver_registry()
    end if
  end function registry_or_builtin

end module fcs_solver_factory
