!> Friction laws by name: the parameters a deck gives (*FRICTION), their catalogue (names, units,
!> ranges, which law takes which), their validation, and the factory that turns them into a
!> friction_law_t.
!>
!> The catalogue is what the deck's keyword table and messages are built from:
!> `friction_parameters()` lists every parameter with its unit, description and (for the two
!> choice parameters) valid values; `friction_required_parameters(law)` and
!> `friction_optional_parameters(law)` say which belong to a law; `friction_parameter_names(law)`
!> gives them as text for "expected one of ..."; `set_friction_parameter` stores one deck
!> parameter by name; `friction_def_problems` lists every problem of a definition (each message
!> names the parameter and its valid range) and `create_friction_law` refuses a definition with
!> any. Messages carry no file:line; the deck handler prefixes it.
!>
!> The laws themselves are a registry (`friction_registry_t`): one entry per law
!> (`friction_law_entry_t`: name, required and optional parameters, default RATE UPDATE, the
!> constructor from a checked `friction_def_t`, and any law-specific check). The law names, the
!> per-law parameter lists, the messages and the keyword table (fcs_keywords) read it. Every
!> public procedure takes an optional `registry`; without one it uses the built-in laws
!> (`builtin_friction_registry`). A law is added by its module and one entry in
!> `builtin_friction_registry`, or at run time with `registry%register` (the unit test
!> registers a test-only law that way).
module fcs_friction_factory
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error, fatal_error
  use fcs_strings, only: string_t, str, join_strings, to_upper, split_fields, name_index
  use fcs_diagnostics, only: source_loc_t
  use fcs_friction_law, only: friction_law_t
  use fcs_coulomb, only: coulomb_t
  use fcs_static_kinetic, only: static_kinetic_t
  use fcs_slip_weakening, only: slip_weakening_t
  use fcs_rate_dependent, only: rate_dependent_t, REGULARISATION_FLOOR, REGULARISATION_LINEAR
  use fcs_rate_state_base, only: STATE_LAW_AGEING, STATE_LAW_SLIP
  use fcs_rate_state, only: rate_state_t
  use fcs_rate_state_arcsinh, only: rate_state_arcsinh_t
  implicit none
  private
  public :: friction_def_t, friction_parameter_t, create_friction_law, friction_def_problems
  public :: set_friction_parameter, friction_parameters, friction_laws
  public :: friction_required_parameters, friction_optional_parameters, friction_parameter_names
  public :: friction_registry_t, friction_law_entry_t, friction_law_entry
  public :: builtin_friction_registry, friction_constructor, friction_check
  public :: FRICTION_UNSET

  !> The value of a real parameter the deck did not give.
  real(dp), parameter :: FRICTION_UNSET = -huge(1.0_dp)

  !> Valid values of the two choice parameters.
  character(len=*), parameter :: STATE_LAW_NAMES = 'AGEING, SLIP'
  character(len=*), parameter :: REGULARISATION_NAMES = 'FLOOR, LINEAR'
  character(len=*), parameter :: RATE_UPDATE_NAMES = 'EXPLICIT, IMPLICIT'
  character(len=*), parameter :: VELOCITY_NAMES = 'SLIP, RELATIVE'

  !> A friction law as the deck defines it: its name and parameters in deck units. A real
  !> parameter the deck did not give is FRICTION_UNSET, a text one is unallocated. Deck names:
  !> MU0 mu0, MUK mu_kinetic, DECAY decay, DC dc, A a, B b, V0 v0, VC cutoff_rate,
  !> REGULARISATION regularisation, STATE LAW state_law, THETA0 initial_state,
  !> VINIT initial_rate, RATE UPDATE rate_update, VELOCITY velocity.
  type :: friction_def_t
    !> Law name, upper case (a name of the registry, friction_laws()).
    character(len=:), allocatable :: law
    !> MU0 [-]: Coulomb coefficient; static coefficient (STATIC KINETIC, SLIP WEAKENING);
    !> steady-state friction at V0 (rate laws).
    real(dp) :: mu0 = FRICTION_UNSET
    !> A, B [-]: direct and evolution effects of the rate laws.
    real(dp) :: a = FRICTION_UNSET
    real(dp) :: b = FRICTION_UNSET
    !> DC [length]: slip-weakening distance, or characteristic slip of the state evolution.
    real(dp) :: dc = FRICTION_UNSET
    !> V0 [length/time]: reference slip rate of the rate laws.
    real(dp) :: v0 = FRICTION_UNSET
    !> MUK [-]: kinetic (residual) coefficient, 0 <= MUK <= MU0.
    real(dp) :: mu_kinetic = FRICTION_UNSET
    !> DECAY [time/length]: exponential decay coefficient of STATIC KINETIC.
    real(dp) :: decay = FRICTION_UNSET
    !> THETA0 [time]: initial state theta of the Dieterich-Ruina laws.
    real(dp) :: initial_state = FRICTION_UNSET
    !> STATE LAW: AGEING or SLIP.
    character(len=:), allocatable :: state_law
    !> REGULARISATION: FLOOR or LINEAR (RATE DEPENDENT below VC).
    character(len=:), allocatable :: regularisation
    !> RATE UPDATE: EXPLICIT or IMPLICIT (rate laws; default by law, explicit_rate_of).
    character(len=:), allocatable :: rate_update
    !> VELOCITY: SLIP (the law's V is the slip rate; default) or RELATIVE (the norm of the
    !> total relative tangential velocity, elastic + slip: the literal reading of Xing et al.
    !> 2003, eq. 3).
    character(len=:), allocatable :: velocity
    !> VC [length/time]: cut-off slip rate of the regularisation (RATE DEPENDENT, RATE STATE).
    real(dp) :: cutoff_rate = FRICTION_UNSET
    !> VINIT [length/time]: initial slip rate; the initial state is steady state at it,
    !> theta0 = DC/VINIT (alternative to THETA0).
    real(dp) :: initial_rate = FRICTION_UNSET
    !> Where the deck defined the law, for messages.
    type(source_loc_t) :: loc
  end type friction_def_t

  !> One deck parameter of *FRICTION: its name, unit ('' if dimensionless), what it is and its
  !> valid range, and for a choice parameter its valid values (empty for a real parameter).
  type :: friction_parameter_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: unit
    character(len=:), allocatable :: description
    type(string_t), allocatable :: choices(:)
  end type friction_parameter_t

  abstract interface
    !> Build the law of a definition with no problems (friction_def_problems): allocate `law`
    !> from the parameters of `def` (the factory then sets its explicit_rate).
    subroutine friction_constructor(def, law)
      import :: friction_def_t, friction_law_t
      type(friction_def_t), intent(in) :: def
      class(friction_law_t), allocatable, intent(out) :: law
    end subroutine friction_constructor

    !> Append the problems of `def` particular to one law (beyond its required parameters and
    !> the catalogue's ranges) to `problems`.
    pure subroutine friction_check(def, problems)
      import :: friction_def_t, string_t
      type(friction_def_t), intent(in) :: def
      type(string_t), allocatable, intent(inout) :: problems(:)
    end subroutine friction_check
  end interface

  !> One friction law of the registry: its deck name, the parameters it requires and those it
  !> may take (names of the catalogue friction_parameters()), its RATE UPDATE when the deck
  !> gives none (.true. EXPLICIT, .false. IMPLICIT), its constructor, and an optional check of
  !> what is particular to it.
  type :: friction_law_entry_t
    character(len=:), allocatable :: name
    type(string_t), allocatable :: required(:)
    type(string_t), allocatable :: optional(:)
    logical :: explicit_rate = .false.
    procedure(friction_constructor), pointer, nopass :: construct => null()
    procedure(friction_check), pointer, nopass :: check => null()
  end type friction_law_entry_t

  !> The friction laws a run knows, in the order the messages list them.
  type :: friction_registry_t
    type(friction_law_entry_t), allocatable :: laws(:)
  contains
    procedure :: init => registry_init
    procedure :: free => registry_free
    procedure :: register => registry_register
    procedure :: find => registry_find
    procedure :: names => registry_names
    procedure :: size => registry_size
  end type friction_registry_t

  !> Set one deck parameter by name, as a real or as a choice (text).
  interface set_friction_parameter
    module procedure set_friction_real, set_friction_text
  end interface set_friction_parameter

contains

  !> The law `def` describes (a law of `registry`, by default the built-in ones); a definition
  !> with any problem (friction_def_problems) is an input error that lists them all, separated
  !> by "; ".
  subroutine create_friction_law(def, law, err, registry)
    type(friction_def_t), intent(in) :: def
    class(friction_law_t), allocatable, intent(out) :: law
    type(error_t), allocatable, intent(out) :: err
    type(friction_registry_t), intent(in), optional :: registry
    type(friction_registry_t) :: laws
    type(string_t), allocatable :: problems(:)
    integer :: k
    laws = registry_or_builtin(registry)
    problems = friction_def_problems(def, laws)
    if (size(problems) > 0) then
      call input_error(err, join_strings(problems, '; '))
      return
    end if
    k = laws%find(def%law)
    call laws%laws(k)%construct(def, law)
    law%explicit_rate = explicit_rate_of(def, laws%laws(k))
    law%relative_velocity = .false.
    if (allocated(def%velocity)) law%relative_velocity = def%velocity == 'RELATIVE'
  end subroutine create_friction_law

  !> RATE UPDATE as given, else the law's default (`explicit_rate` of its entry): EXPLICIT for
  !> RATE DEPENDENT (no state: mu falls at once with the rate when a < b), IMPLICIT for the
  !> laws with a state (their direct effect a > 0 makes the implicit update stable and exact);
  !> no rate, no matter.
  pure logical function explicit_rate_of(def, entry) result(explicit)
    type(friction_def_t), intent(in) :: def
    type(friction_law_entry_t), intent(in) :: entry
    if (allocated(def%rate_update)) then
      explicit = def%rate_update == 'EXPLICIT'
    else
      explicit = entry%explicit_rate
    end if
  end function explicit_rate_of

  !> The built-in laws, one entry each: adding a law is its module and one entry here.
  function builtin_friction_registry() result(registry)
    type(friction_registry_t) :: registry
    registry%laws = [ &
      friction_law_entry('COULOMB', 'MU0', '', .false., new_coulomb), &
      friction_law_entry('STATIC KINETIC', 'MU0, MUK, DECAY', '', .false., new_static_kinetic), &
      friction_law_entry('SLIP WEAKENING', 'MU0, MUK, DC', '', .false., new_slip_weakening), &
      friction_law_entry('RATE DEPENDENT', 'MU0, A, B, V0, VC, REGULARISATION', &
                         'RATE UPDATE, VELOCITY', .true., new_rate_dependent), &
      friction_law_entry('RATE STATE', 'MU0, A, B, DC, V0, VC, STATE LAW', &
                         'THETA0, VINIT, RATE UPDATE, VELOCITY', .false., new_rate_state, &
                         check_initial_state), &
      friction_law_entry('RATE STATE ARCSINH', 'MU0, A, B, DC, V0, STATE LAW', &
                         'THETA0, VINIT, RATE UPDATE, VELOCITY', .false., new_rate_state_arcsinh, &
                         check_initial_state)]
  end function builtin_friction_registry

  !> A registry entry: law `name`, its required and optional parameters as comma-separated
  !> lists of catalogue names ('' for none), its default RATE UPDATE (`explicit_rate`), its
  !> constructor and optionally its own check.
  function friction_law_entry(name, required, optional, explicit_rate, construct, check) &
      result(entry)
    character(len=*), intent(in) :: name, required, optional
    logical, intent(in) :: explicit_rate
    procedure(friction_constructor) :: construct
    procedure(friction_check), optional :: check
    type(friction_law_entry_t) :: entry
    entry%name = name
    entry%required = list_of(required)
    entry%optional = list_of(optional)
    entry%explicit_rate = explicit_rate
    entry%construct => construct
    if (present(check)) entry%check => check
  end function friction_law_entry

  !> The built-in laws.
  subroutine registry_init(this)
    class(friction_registry_t), intent(inout) :: this
    type(friction_registry_t) :: builtin
    call this%free()
    builtin = builtin_friction_registry()
    call move_alloc(builtin%laws, this%laws)
  end subroutine registry_init

  !> Forget every law.
  subroutine registry_free(this)
    class(friction_registry_t), intent(inout) :: this
    if (allocated(this%laws)) deallocate (this%laws)
  end subroutine registry_free

  !> Add law `entry`. An internal error if it has no name or constructor, if its name is
  !> already registered, or if it names a parameter the catalogue does not have.
  subroutine registry_register(this, entry, err)
    class(friction_registry_t), intent(inout) :: this
    type(friction_law_entry_t), intent(in) :: entry
    type(error_t), allocatable, intent(out) :: err
    type(string_t), allocatable :: parameters(:)
    integer :: i
    if (.not. allocated(this%laws)) allocate (this%laws(0))
    if (.not. allocated(entry%name) .or. .not. associated(entry%construct)) then
      call fatal_error(err, 'friction registry: a law needs a name and a constructor')
      return
    end if
    if (this%find(entry%name) /= 0) then
      call fatal_error(err, 'friction registry: law ' // entry%name // ' is already registered')
      return
    end if
    parameters = [entry%required, entry%optional]
    do i = 1, size(parameters)
      if (.not. known_parameter(parameters(i)%s)) then
        call fatal_error(err, 'friction registry: law ' // entry%name // ' names parameter ' // &
          parameters(i)%s // ', which is not in the catalogue (friction_parameters)')
        return
      end if
    end do
    this%laws = [this%laws, entry]
  end subroutine registry_register

  !> Index of law `name` (exact, upper case), 0 if none.
  pure integer function registry_find(this, name) result(index)
    class(friction_registry_t), intent(in) :: this
    character(len=*), intent(in) :: name
    index = name_index(this%names(), name)
  end function registry_find

  !> The law names in registry order.
  pure function registry_names(this) result(names)
    class(friction_registry_t), intent(in) :: this
    type(string_t), allocatable :: names(:)
    integer :: i
    allocate (names(this%size()))
    do i = 1, size(names)
      names(i)%s = this%laws(i)%name
    end do
  end function registry_names

  !> Number of laws.
  pure integer function registry_size(this) result(n)
    class(friction_registry_t), intent(in) :: this
    n = 0
    if (allocated(this%laws)) n = size(this%laws)
  end function registry_size

  !> `registry` if present, else the built-in laws.
  function registry_or_builtin(registry) result(laws)
    type(friction_registry_t), intent(in), optional :: registry
    type(friction_registry_t) :: laws
    if (present(registry)) then
      laws = registry
    else
      laws = builtin_friction_registry()
    end if
  end function registry_or_builtin

  subroutine new_coulomb(def, law)
    type(friction_def_t), intent(in) :: def
    class(friction_law_t), allocatable, intent(out) :: law
    allocate (law, source=coulomb_t(mu0=def%mu0))
  end subroutine new_coulomb

  subroutine new_static_kinetic(def, law)
    type(friction_def_t), intent(in) :: def
    class(friction_law_t), allocatable, intent(out) :: law
    allocate (law, source=static_kinetic_t(mu0=def%mu0, mu_kinetic=def%mu_kinetic, &
                                           decay=def%decay))
  end subroutine new_static_kinetic

  subroutine new_slip_weakening(def, law)
    type(friction_def_t), intent(in) :: def
    class(friction_law_t), allocatable, intent(out) :: law
    allocate (law, source=slip_weakening_t(mu0=def%mu0, mu_kinetic=def%mu_kinetic, dc=def%dc))
  end subroutine new_slip_weakening

  subroutine new_rate_dependent(def, law)
    type(friction_def_t), intent(in) :: def
    class(friction_law_t), allocatable, intent(out) :: law
    allocate (law, source=rate_dependent_t(mu0=def%mu0, a=def%a, b=def%b, v0=def%v0, &
      cutoff_rate=def%cutoff_rate, regularisation=merge(REGULARISATION_FLOOR, &
      REGULARISATION_LINEAR, def%regularisation == 'FLOOR')))
  end subroutine new_rate_dependent

  subroutine new_rate_state(def, law)
    type(friction_def_t), intent(in) :: def
    class(friction_law_t), allocatable, intent(out) :: law
    allocate (law, source=rate_state_t(mu0=def%mu0, a=def%a, b=def%b, dc=def%dc, &
      v0=def%v0, theta0=initial_theta(def), state_law=state_law_of(def), &
      cutoff_rate=def%cutoff_rate))
  end subroutine new_rate_state

  subroutine new_rate_state_arcsinh(def, law)
    type(friction_def_t), intent(in) :: def
    class(friction_law_t), allocatable, intent(out) :: law
    allocate (law, source=rate_state_arcsinh_t(mu0=def%mu0, a=def%a, b=def%b, dc=def%dc, &
      v0=def%v0, theta0=initial_theta(def), state_law=state_law_of(def)))
  end subroutine new_rate_state_arcsinh

  !> The initial state theta0 of a Dieterich-Ruina law: THETA0, or DC/VINIT.
  pure real(dp) function initial_theta(def) result(theta0)
    type(friction_def_t), intent(in) :: def
    theta0 = def%initial_state
    if (.not. given(theta0)) theta0 = def%dc / def%initial_rate
  end function initial_theta

  !> The Dieterich-Ruina laws need exactly one of THETA0 and VINIT.
  pure subroutine check_initial_state(def, problems)
    type(friction_def_t), intent(in) :: def
    type(string_t), allocatable, intent(inout) :: problems(:)
    if (given(def%initial_state) .and. given(def%initial_rate)) then
      problems = [problems, string_t('law ' // def%law // ': give the initial state either ' // &
        'as THETA0 or as VINIT, not both')]
    else if (.not. (given(def%initial_state) .or. given(def%initial_rate))) then
      problems = [problems, string_t('law ' // def%law // ': missing parameter THETA0 or ' // &
        'VINIT (' // describe('THETA0') // '; or ' // describe('VINIT') // ')')]
    end if
  end subroutine check_initial_state

  !> Every problem of `def`: unknown law (of `registry`, by default the built-in laws); a
  !> parameter the law does not take; a missing one; what the law's own check finds (THETA0
  !> and VINIT both or neither for the Dieterich-Ruina laws); a value out of range or not among
  !> the choices. Each message names the parameter and says what is valid.
  function friction_def_problems(def, registry) result(problems)
    type(friction_def_t), intent(in) :: def
    type(friction_registry_t), intent(in), optional :: registry
    type(string_t), allocatable :: problems(:)
    type(friction_registry_t) :: laws
    type(friction_parameter_t), allocatable :: catalogue(:)
    character(len=:), allocatable :: law
    integer :: i, k
    allocate (problems(0))
    laws = registry_or_builtin(registry)
    law = ''
    if (allocated(def%law)) law = def%law
    k = laws%find(law)
    if (k == 0) then
      problems = [string_t('unknown friction law "' // law // '"; expected one of ' // &
                           join_strings(laws%names(), ', '))]
      return
    end if
    associate (entry => laws%laws(k))
      catalogue = friction_parameters()
      do i = 1, size(catalogue)
        associate (name => catalogue(i)%name)
          if (is_given(def, name) .and. .not. takes_parameter(entry, name)) then
            problems = [problems, string_t('parameter ' // name // ' does not apply to law ' // &
              law // '; expected one of ' // parameter_names_of(entry))]
          end if
        end associate
      end do
      do i = 1, size(entry%required)
        if (.not. is_given(def, entry%required(i)%s)) problems = [problems, string_t('law ' // &
          law // ': missing parameter ' // entry%required(i)%s // ' (' // &
          describe(entry%required(i)%s) // ')')]
      end do
      if (associated(entry%check)) call entry%check(def, problems)
      call check_ranges(def, entry, problems)
    end associate
  end function friction_def_problems

  !> Out-of-range values and invalid choices of the parameters `law` takes, appended to
  !> `problems` (parameters the law does not take are reported by the caller).
  pure subroutine check_ranges(def, entry, problems)
    type(friction_def_t), intent(in) :: def
    type(friction_law_entry_t), intent(in) :: entry
    type(string_t), allocatable, intent(inout) :: problems(:)
    if (applies('MU0')) then
      if (def%mu0 < 0.0_dp) call out_of_range(problems, 'MU0', def%mu0, 'MU0 >= 0')
    end if
    if (applies('MUK')) then
      if (def%mu_kinetic < 0.0_dp .or. (given(def%mu0) .and. def%mu_kinetic > def%mu0)) &
        call out_of_range(problems, 'MUK', def%mu_kinetic, '0 <= MUK <= MU0 (MU0 = ' // &
                          str(def%mu0) // ')')
    end if
    if (applies('DECAY')) then
      if (def%decay <= 0.0_dp) &
        call out_of_range(problems, 'DECAY', def%decay, 'DECAY > 0 [time/length]')
    end if
    if (applies('DC')) then
      if (def%dc <= 0.0_dp) call out_of_range(problems, 'DC', def%dc, 'DC > 0 [length]')
    end if
    if (applies('A')) then
      if (entry%name == 'RATE STATE ARCSINH' .and. def%a <= 0.0_dp) then
        call out_of_range(problems, 'A', def%a, 'A > 0 (the arcsinh form divides by A)')
      else if (def%a < 0.0_dp) then
        call out_of_range(problems, 'A', def%a, 'A >= 0')
      end if
    end if
    if (applies('B')) then
      if (def%b < 0.0_dp) call out_of_range(problems, 'B', def%b, 'B >= 0')
    end if
    if (applies('V0')) then
      if (def%v0 <= 0.0_dp) call out_of_range(problems, 'V0', def%v0, 'V0 > 0 [length/time]')
    end if
    if (applies('VC')) then
      if (def%cutoff_rate <= 0.0_dp) &
        call out_of_range(problems, 'VC', def%cutoff_rate, 'VC > 0 [length/time]')
    end if
    if (applies('THETA0')) then
      if (def%initial_state <= 0.0_dp) &
        call out_of_range(problems, 'THETA0', def%initial_state, 'THETA0 > 0 [time]')
    end if
    if (applies('VINIT')) then
      if (def%initial_rate <= 0.0_dp) &
        call out_of_range(problems, 'VINIT', def%initial_rate, 'VINIT > 0 [length/time]')
    end if
    if (applies('STATE LAW')) then
      if (.not. in_list(def%state_law, STATE_LAW_NAMES)) problems = [problems, string_t( &
        'STATE LAW = "' // def%state_law // '" is not valid; expected one of ' // STATE_LAW_NAMES)]
    end if
    if (applies('REGULARISATION')) then
      if (.not. in_list(def%regularisation, REGULARISATION_NAMES)) problems = [problems, &
        string_t('REGULARISATION = "' // def%regularisation // '" is not valid; ' // &
        'expected one of ' // REGULARISATION_NAMES)]
    end if
    if (applies('RATE UPDATE')) then
      if (.not. in_list(def%rate_update, RATE_UPDATE_NAMES)) problems = [problems, &
        string_t('RATE UPDATE = "' // def%rate_update // '" is not valid; ' // &
        'expected one of ' // RATE_UPDATE_NAMES)]
    end if
    if (applies('VELOCITY')) then
      if (.not. in_list(def%velocity, VELOCITY_NAMES)) problems = [problems, &
        string_t('VELOCITY = "' // def%velocity // '" is not valid; ' // &
        'expected one of ' // VELOCITY_NAMES)]
    end if
  contains
    pure logical function applies(name)
      character(len=*), intent(in) :: name
      applies = is_given(def, name) .and. takes_parameter(entry, name)
    end function applies
  end subroutine check_ranges

  !> Append "NAME = value is out of range; expected <valid>" to `problems`.
  pure subroutine out_of_range(problems, name, value, valid)
    type(string_t), allocatable, intent(inout) :: problems(:)
    character(len=*), intent(in) :: name, valid
    real(dp), intent(in) :: value
    problems = [problems, string_t(name // ' = ' // str(value) // ' is out of range; ' // &
                                   'expected ' // valid)]
  end subroutine out_of_range

  !> Store the real parameter `name` (upper case deck name) in `def`. Unknown names, choice
  !> parameters and repeated parameters are input errors. Ranges are checked later
  !> (friction_def_problems), once the law is known.
  subroutine set_friction_real(def, name, value, err)
    type(friction_def_t), intent(inout) :: def
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: value
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: key
    key = to_upper(trim(name))
    if (.not. known_parameter(key)) then
      call unknown_parameter(key, err)
      return
    end if
    if (is_given(def, key)) then
      call input_error(err, 'repeated parameter ' // key)
      return
    end if
    select case (key)
    case ('MU0')
      def%mu0 = value
    case ('MUK')
      def%mu_kinetic = value
    case ('DECAY')
      def%decay = value
    case ('DC')
      def%dc = value
    case ('A')
      def%a = value
    case ('B')
      def%b = value
    case ('V0')
      def%v0 = value
    case ('VC')
      def%cutoff_rate = value
    case ('THETA0')
      def%initial_state = value
    case ('VINIT')
      def%initial_rate = value
    case default
      call input_error(err, 'parameter ' // key // ' expects one of ' // &
                       choices_text(key) // ', not a number')
    end select
  end subroutine set_friction_real

  !> Store the choice parameter `name` (STATE LAW, REGULARISATION, RATE UPDATE, VELOCITY) as
  !> `value`,
  !> upper-cased;
  !> the value is checked against the choices later (friction_def_problems).
  subroutine set_friction_text(def, name, value, err)
    type(friction_def_t), intent(inout) :: def
    character(len=*), intent(in) :: name, value
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: key
    key = to_upper(trim(name))
    if (.not. known_parameter(key)) then
      call unknown_parameter(key, err)
      return
    end if
    if (is_given(def, key)) then
      call input_error(err, 'repeated parameter ' // key)
      return
    end if
    select case (key)
    case ('STATE LAW')
      def%state_law = to_upper(trim(value))
    case ('REGULARISATION')
      def%regularisation = to_upper(trim(value))
    case ('RATE UPDATE')
      def%rate_update = to_upper(trim(value))
    case ('VELOCITY')
      def%velocity = to_upper(trim(value))
    case default
      call input_error(err, 'parameter ' // key // ' expects a number, not "' // value // '"')
    end select
  end subroutine set_friction_text

  subroutine unknown_parameter(key, err)
    character(len=*), intent(in) :: key
    type(error_t), allocatable, intent(out) :: err
    call input_error(err, 'unknown friction parameter "' // key // '"; expected one of ' // &
                     all_parameter_names())
  end subroutine unknown_parameter

  !> The catalogue of *FRICTION parameters, in the order the messages list them.
  pure function friction_parameters() result(catalogue)
    type(friction_parameter_t), allocatable :: catalogue(:)
    catalogue = [ &
      parameter_entry('MU0', '', 'friction coefficient: Coulomb mu; static coefficient ' // &
        '(STATIC KINETIC, SLIP WEAKENING); steady-state friction at V0 (rate laws); >= 0'), &
      parameter_entry('MUK', '', 'kinetic (residual) friction coefficient, 0 <= MUK <= MU0'), &
      parameter_entry('DECAY', 'time/length', 'exponential decay coefficient of mu with ' // &
        'slip rate, > 0'), &
      parameter_entry('DC', 'length', 'slip-weakening distance (SLIP WEAKENING) or ' // &
        'characteristic slip of the state evolution (RATE STATE laws), > 0'), &
      parameter_entry('A', '', 'direct-effect parameter a, >= 0 (> 0 for RATE STATE ARCSINH)'), &
      parameter_entry('B', '', 'evolution-effect parameter b, >= 0'), &
      parameter_entry('V0', 'length/time', 'reference slip rate, > 0'), &
      parameter_entry('VC', 'length/time', 'cut-off slip rate below which the law is ' // &
        'regularised, > 0'), &
      parameter_entry('REGULARISATION', '', 'mu below VC: FLOOR (held at mu_ss(VC)) or ' // &
        'LINEAR (linear tail, continuous slope)', REGULARISATION_NAMES), &
      parameter_entry('STATE LAW', '', 'state evolution: AGEING (Dieterich) or SLIP (Ruina)', &
        STATE_LAW_NAMES), &
      parameter_entry('RATE UPDATE', '', 'slip rate of an increment''s friction: EXPLICIT ' // &
        '(the previous increment''s, known at its start; default for RATE DEPENDENT) or ' // &
        'IMPLICIT (its own, solved in the return mapping; default for the RATE STATE laws)', &
        RATE_UPDATE_NAMES), &
      parameter_entry('VELOCITY', '', 'the velocity V the rate law is evaluated at: SLIP (the ' // &
        'slip rate, the plastic part, 0 in stick; default) or RELATIVE (the norm of the ' // &
        'total relative tangential velocity of the contact, elastic stick part + slip: the ' // &
        'literal reading of Xing et al. 2003, eq. 3)', VELOCITY_NAMES), &
      parameter_entry('THETA0', 'time', 'initial state theta, > 0'), &
      parameter_entry('VINIT', 'length/time', 'initial slip rate; the initial state is ' // &
        'steady state at it, theta0 = DC/VINIT; > 0') ]
  end function friction_parameters

  !> The law names of `registry` (by default the built-in laws), for the keyword table's
  !> choices and the messages.
  function friction_laws(registry) result(names)
    type(friction_registry_t), intent(in), optional :: registry
    type(string_t), allocatable :: names(:)
    type(friction_registry_t) :: laws
    laws = registry_or_builtin(registry)
    names = laws%names()
  end function friction_laws

  !> The parameters `law` requires (empty for an unknown law). The Dieterich-Ruina laws also
  !> need exactly one of their optional THETA0, VINIT.
  function friction_required_parameters(law, registry) result(names)
    character(len=*), intent(in) :: law
    type(friction_registry_t), intent(in), optional :: registry
    type(string_t), allocatable :: names(:)
    type(friction_registry_t) :: laws
    integer :: k
    laws = registry_or_builtin(registry)
    k = laws%find(law)
    if (k == 0) then
      allocate (names(0))
    else
      names = laws%laws(k)%required
    end if
  end function friction_required_parameters

  !> The optional parameters of `law`: THETA0 and VINIT for the Dieterich-Ruina laws (exactly
  !> one of them must be given), RATE UPDATE and VELOCITY for every rate law; none for the others.
  function friction_optional_parameters(law, registry) result(names)
    character(len=*), intent(in) :: law
    type(friction_registry_t), intent(in), optional :: registry
    type(string_t), allocatable :: names(:)
    type(friction_registry_t) :: laws
    integer :: k
    laws = registry_or_builtin(registry)
    k = laws%find(law)
    if (k == 0) then
      allocate (names(0))
    else
      names = laws%laws(k)%optional
    end if
  end function friction_optional_parameters

  !> All parameters of `law` as text, "MU0, MUK, DECAY" ('' for an unknown law).
  function friction_parameter_names(law, registry) result(text)
    character(len=*), intent(in) :: law
    type(friction_registry_t), intent(in), optional :: registry
    character(len=:), allocatable :: text
    type(friction_registry_t) :: laws
    integer :: k
    laws = registry_or_builtin(registry)
    k = laws%find(law)
    text = ''
    if (k /= 0) text = parameter_names_of(laws%laws(k))
  end function friction_parameter_names

  !> The parameters of a law entry as text, required then optional.
  pure function parameter_names_of(entry) result(text)
    type(friction_law_entry_t), intent(in) :: entry
    character(len=:), allocatable :: text
    text = join_strings([entry%required, entry%optional], ', ')
  end function parameter_names_of

  pure function parameter_entry(name, unit, description, choices) result(entry)
    character(len=*), intent(in) :: name, unit, description
    character(len=*), intent(in), optional :: choices
    type(friction_parameter_t) :: entry
    entry%name = name
    entry%unit = unit
    entry%description = description
    if (present(choices)) then
      entry%choices = list_of(choices)
    else
      allocate (entry%choices(0))
    end if
  end function parameter_entry

  !> Every parameter name of the catalogue as text.
  pure function all_parameter_names() result(text)
    character(len=:), allocatable :: text
    type(friction_parameter_t), allocatable :: catalogue(:)
    integer :: i
    catalogue = friction_parameters()
    text = catalogue(1)%name
    do i = 2, size(catalogue)
      text = text // ', ' // catalogue(i)%name
    end do
  end function all_parameter_names

  !> "description [unit]" of parameter `name`.
  pure function describe(name) result(text)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: text
    type(friction_parameter_t), allocatable :: catalogue(:)
    integer :: i
    catalogue = friction_parameters()
    text = ''
    do i = 1, size(catalogue)
      if (catalogue(i)%name /= name) cycle
      text = catalogue(i)%description
      if (len(catalogue(i)%unit) > 0) text = text // ' [' // catalogue(i)%unit // ']'
    end do
  end function describe

  !> The valid values of choice parameter `name` as text.
  pure function choices_text(name) result(text)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: text
    type(friction_parameter_t), allocatable :: catalogue(:)
    integer :: i
    catalogue = friction_parameters()
    text = ''
    do i = 1, size(catalogue)
      if (catalogue(i)%name == name) text = join_strings(catalogue(i)%choices, ', ')
    end do
  end function choices_text

  pure logical function known_parameter(name)
    character(len=*), intent(in) :: name
    known_parameter = in_list(name, all_parameter_names())
  end function known_parameter

  !> Whether law `entry` takes parameter `name` (required or optional).
  pure logical function takes_parameter(entry, name)
    type(friction_law_entry_t), intent(in) :: entry
    character(len=*), intent(in) :: name
    takes_parameter = in_list(name, parameter_names_of(entry))
  end function takes_parameter

  !> Whether the deck gave parameter `name` (a known name) in `def`.
  pure logical function is_given(def, name)
    type(friction_def_t), intent(in) :: def
    character(len=*), intent(in) :: name
    select case (name)
    case ('MU0')
      is_given = given(def%mu0)
    case ('MUK')
      is_given = given(def%mu_kinetic)
    case ('DECAY')
      is_given = given(def%decay)
    case ('DC')
      is_given = given(def%dc)
    case ('A')
      is_given = given(def%a)
    case ('B')
      is_given = given(def%b)
    case ('V0')
      is_given = given(def%v0)
    case ('VC')
      is_given = given(def%cutoff_rate)
    case ('THETA0')
      is_given = given(def%initial_state)
    case ('VINIT')
      is_given = given(def%initial_rate)
    case ('STATE LAW')
      is_given = allocated(def%state_law)
    case ('REGULARISATION')
      is_given = allocated(def%regularisation)
    case ('RATE UPDATE')
      is_given = allocated(def%rate_update)
    case ('VELOCITY')
      is_given = allocated(def%velocity)
    case default
      is_given = .false.
    end select
  end function is_given

  pure logical function given(value)
    real(dp), intent(in) :: value
    given = value /= FRICTION_UNSET
  end function given

  pure integer function state_law_of(def) result(state_law)
    type(friction_def_t), intent(in) :: def
    state_law = merge(STATE_LAW_SLIP, STATE_LAW_AGEING, def%state_law == 'SLIP')
  end function state_law_of

  !> Whether `item` is one of the comma-separated `list`.
  pure logical function in_list(item, list)
    character(len=*), intent(in) :: item, list
    type(string_t), allocatable :: items(:)
    integer :: i
    items = list_of(list)
    in_list = .false.
    do i = 1, size(items)
      if (items(i)%s == item) in_list = .true.
    end do
  end function in_list

  !> The items of a comma-separated list (none for a blank text).
  pure function list_of(text) result(items)
    character(len=*), intent(in) :: text
    type(string_t), allocatable :: items(:)
    if (len_trim(text) == 0) then
      allocate (items(0))
      return
    end if
    call split_fields(text, items)
  end function list_of

end module fcs_friction_factory
