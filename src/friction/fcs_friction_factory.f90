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
module fcs_friction_factory
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error
  use fcs_strings, only: string_t, str, join_strings, to_upper, split_fields
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
  public :: FRICTION_LAW_NAMES, FRICTION_UNSET

  !> Valid law names.
  character(len=*), parameter :: FRICTION_LAW_NAMES = 'COULOMB, STATIC KINETIC, ' // &
    'SLIP WEAKENING, RATE DEPENDENT, RATE STATE, RATE STATE ARCSINH'

  !> The value of a real parameter the deck did not give.
  real(dp), parameter :: FRICTION_UNSET = -huge(1.0_dp)

  !> Valid values of the two choice parameters.
  character(len=*), parameter :: STATE_LAW_NAMES = 'AGEING, SLIP'
  character(len=*), parameter :: REGULARISATION_NAMES = 'FLOOR, LINEAR'
  character(len=*), parameter :: RATE_UPDATE_NAMES = 'EXPLICIT, IMPLICIT'

  !> A friction law as the deck defines it: its name and parameters in deck units. A real
  !> parameter the deck did not give is FRICTION_UNSET, a text one is unallocated. Deck names:
  !> MU0 mu0, MUK mu_kinetic, DECAY decay, DC dc, A a, B b, V0 v0, VC cutoff_rate,
  !> REGULARISATION regularisation, STATE LAW state_law, THETA0 initial_state,
  !> VINIT initial_rate.
  type :: friction_def_t
    !> Law name, upper case (FRICTION_LAW_NAMES).
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

  !> Set one deck parameter by name, as a real or as a choice (text).
  interface set_friction_parameter
    module procedure set_friction_real, set_friction_text
  end interface set_friction_parameter

contains

  !> The law `def` describes; a definition with any problem (friction_def_problems) is an
  !> input error that lists them all, separated by "; ".
  subroutine create_friction_law(def, law, err)
    type(friction_def_t), intent(in) :: def
    class(friction_law_t), allocatable, intent(out) :: law
    type(error_t), allocatable, intent(out) :: err
    type(string_t), allocatable :: problems(:)
    real(dp) :: theta0
    problems = friction_def_problems(def)
    if (size(problems) > 0) then
      call input_error(err, join_strings(problems, '; '))
      return
    end if
    select case (def%law)
    case ('COULOMB')
      allocate (law, source=coulomb_t(mu0=def%mu0))
    case ('STATIC KINETIC')
      allocate (law, source=static_kinetic_t(mu0=def%mu0, mu_kinetic=def%mu_kinetic, &
                                             decay=def%decay))
    case ('SLIP WEAKENING')
      allocate (law, source=slip_weakening_t(mu0=def%mu0, mu_kinetic=def%mu_kinetic, dc=def%dc))
    case ('RATE DEPENDENT')
      allocate (law, source=rate_dependent_t(mu0=def%mu0, a=def%a, b=def%b, v0=def%v0, &
        cutoff_rate=def%cutoff_rate, regularisation=merge(REGULARISATION_FLOOR, &
        REGULARISATION_LINEAR, def%regularisation == 'FLOOR')))
    case ('RATE STATE', 'RATE STATE ARCSINH')
      theta0 = def%initial_state
      if (.not. given(theta0)) theta0 = def%dc / def%initial_rate
      if (def%law == 'RATE STATE') then
        allocate (law, source=rate_state_t(mu0=def%mu0, a=def%a, b=def%b, dc=def%dc, &
          v0=def%v0, theta0=theta0, state_law=state_law_of(def), cutoff_rate=def%cutoff_rate))
      else
        allocate (law, source=rate_state_arcsinh_t(mu0=def%mu0, a=def%a, b=def%b, dc=def%dc, &
          v0=def%v0, theta0=theta0, state_law=state_law_of(def)))
      end if
    end select
    law%explicit_rate = explicit_rate_of(def)
  end subroutine create_friction_law

  !> RATE UPDATE as given, else the law's default: EXPLICIT for RATE DEPENDENT (no state: mu
  !> falls at once with the rate when a < b), IMPLICIT for the laws with a state (their direct
  !> effect a > 0 makes the implicit update stable and exact); no rate, no matter.
  pure logical function explicit_rate_of(def) result(explicit)
    type(friction_def_t), intent(in) :: def
    if (allocated(def%rate_update)) then
      explicit = def%rate_update == 'EXPLICIT'
    else
      explicit = def%law == 'RATE DEPENDENT'
    end if
  end function explicit_rate_of

  !> Every problem of `def`: unknown law; a parameter the law does not take; a missing one;
  !> THETA0 and VINIT both or neither (Dieterich-Ruina laws); a value out of range or not
  !> among the choices. Each message names the parameter and says what is valid.
  pure function friction_def_problems(def) result(problems)
    type(friction_def_t), intent(in) :: def
    type(string_t), allocatable :: problems(:)
    type(friction_parameter_t), allocatable :: catalogue(:)
    type(string_t), allocatable :: required(:)
    character(len=:), allocatable :: law
    integer :: i
    allocate (problems(0))
    law = ''
    if (allocated(def%law)) law = def%law
    if (.not. is_friction_law(law)) then
      problems = [string_t('unknown friction law "' // law // '"; expected one of ' // &
                           FRICTION_LAW_NAMES)]
      return
    end if
    catalogue = friction_parameters()
    required = friction_required_parameters(law)
    do i = 1, size(catalogue)
      associate (name => catalogue(i)%name)
        if (is_given(def, name) .and. .not. takes_parameter(law, name)) then
          problems = [problems, string_t('parameter ' // name // ' does not apply to law ' // &
            law // '; expected one of ' // friction_parameter_names(law))]
        end if
      end associate
    end do
    do i = 1, size(required)
      if (.not. is_given(def, required(i)%s)) problems = [problems, string_t('law ' // law // &
        ': missing parameter ' // required(i)%s // ' (' // describe(required(i)%s) // ')')]
    end do
    if (law == 'RATE STATE' .or. law == 'RATE STATE ARCSINH') then
      if (given(def%initial_state) .and. given(def%initial_rate)) then
        problems = [problems, string_t('law ' // law // ': give the initial state either ' // &
          'as THETA0 or as VINIT, not both')]
      else if (.not. (given(def%initial_state) .or. given(def%initial_rate))) then
        problems = [problems, string_t('law ' // law // ': missing parameter THETA0 or ' // &
          'VINIT (' // describe('THETA0') // '; or ' // describe('VINIT') // ')')]
      end if
    end if
    call check_ranges(def, law, problems)
  end function friction_def_problems

  !> Out-of-range values and invalid choices of the parameters `law` takes, appended to
  !> `problems` (parameters the law does not take are reported by the caller).
  pure subroutine check_ranges(def, law, problems)
    type(friction_def_t), intent(in) :: def
    character(len=*), intent(in) :: law
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
      if (law == 'RATE STATE ARCSINH' .and. def%a <= 0.0_dp) then
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
  contains
    pure logical function applies(name)
      character(len=*), intent(in) :: name
      applies = is_given(def, name) .and. takes_parameter(law, name)
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

  !> Store the choice parameter `name` (STATE LAW, REGULARISATION, RATE UPDATE) as `value`,
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
      parameter_entry('THETA0', 'time', 'initial state theta, > 0'), &
      parameter_entry('VINIT', 'length/time', 'initial slip rate; the initial state is ' // &
        'steady state at it, theta0 = DC/VINIT; > 0') ]
  end function friction_parameters

  !> The valid law names, for the keyword table's choices.
  pure function friction_laws() result(names)
    type(string_t), allocatable :: names(:)
    names = list_of(FRICTION_LAW_NAMES)
  end function friction_laws

  !> The parameters `law` requires (empty for an unknown law). The Dieterich-Ruina laws also
  !> need exactly one of their optional THETA0, VINIT.
  pure function friction_required_parameters(law) result(names)
    character(len=*), intent(in) :: law
    type(string_t), allocatable :: names(:)
    select case (law)
    case ('COULOMB')
      names = list_of('MU0')
    case ('STATIC KINETIC')
      names = list_of('MU0, MUK, DECAY')
    case ('SLIP WEAKENING')
      names = list_of('MU0, MUK, DC')
    case ('RATE DEPENDENT')
      names = list_of('MU0, A, B, V0, VC, REGULARISATION')
    case ('RATE STATE')
      names = list_of('MU0, A, B, DC, V0, VC, STATE LAW')
    case ('RATE STATE ARCSINH')
      names = list_of('MU0, A, B, DC, V0, STATE LAW')
    case default
      allocate (names(0))
    end select
  end function friction_required_parameters

  !> The optional parameters of `law`: THETA0 and VINIT for the Dieterich-Ruina laws (exactly
  !> one of them must be given) and RATE UPDATE for every rate law; none for the others.
  pure function friction_optional_parameters(law) result(names)
    character(len=*), intent(in) :: law
    type(string_t), allocatable :: names(:)
    select case (law)
    case ('RATE STATE', 'RATE STATE ARCSINH')
      names = list_of('THETA0, VINIT, RATE UPDATE')
    case ('RATE DEPENDENT')
      names = list_of('RATE UPDATE')
    case default
      allocate (names(0))
    end select
  end function friction_optional_parameters

  !> All parameters of `law` as text, "MU0, MUK, DECAY" ('' for an unknown law).
  pure function friction_parameter_names(law) result(text)
    character(len=*), intent(in) :: law
    character(len=:), allocatable :: text
    text = join_strings([friction_required_parameters(law), &
                         friction_optional_parameters(law)], ', ')
  end function friction_parameter_names

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

  pure logical function is_friction_law(name)
    character(len=*), intent(in) :: name
    is_friction_law = in_list(name, FRICTION_LAW_NAMES)
  end function is_friction_law

  !> Whether `law` takes parameter `name` (required or optional).
  pure logical function takes_parameter(law, name)
    character(len=*), intent(in) :: law, name
    takes_parameter = in_list(name, friction_parameter_names(law))
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

  !> The items of a comma-separated list.
  pure function list_of(text) result(items)
    character(len=*), intent(in) :: text
    type(string_t), allocatable :: items(:)
    call split_fields(text, items)
  end function list_of

end module fcs_friction_factory
