!> Unit test of fcs_friction_factory: every law by name from deck-style parameters, the
!> parameter catalogue and per-law lists, and the negative cases: unknown law (message lists the
!> valid ones), unknown/repeated/mistyped parameter, parameter of another law, missing
!> parameter, THETA0/VINIT both or neither, and every out-of-range value (message names it).
!> The registry: a test-only law (TEST LINEAR RATE, fcs_test_friction_laws) registered at run
!> time is listed by the law names, the *FRICTION keyword parameters and the messages, is
!> built by create_friction_law from a definition, and passes the shared derivative checks.
program test_fcs_friction_factory
  use, intrinsic :: iso_fortran_env, only: error_unit
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, EXIT_INPUT
  use fcs_strings, only: string_t, split_fields
  use fcs_friction_law, only: friction_law_t
  use fcs_friction_factory, only: friction_def_t, friction_parameter_t, create_friction_law, &
    set_friction_parameter, friction_parameters, friction_laws, friction_required_parameters, &
    friction_optional_parameters, friction_parameter_names, friction_def_problems, &
    friction_registry_t, friction_law_entry_t
  use fcs_strings, only: join_strings
  use fcs_keywords, only: param_spec_t, friction_keyword_params, PARAM_CHOICE
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_friction_laws, only: test_linear_rate_entry, check_derivatives
  implicit none
  type(test_suite_t) :: suite

  suite%name = 'fcs_friction_factory'
  call check_catalogue(suite)
  call check_valid_laws(suite)
  call check_unknown_law(suite)
  call check_setters(suite)
  call check_applicability(suite)
  call check_out_of_range(suite)
  call check_rate_update(suite)
  call check_velocity(suite)
  call check_registered_law(suite)
  call suite%report()

contains

  !> A valid definition of `law` given as a deck would: "NAME=value, ..." (values read as
  !> reals except STATE LAW and REGULARISATION).
  function deck_def(law, parameters) result(def)
    character(len=*), intent(in) :: law, parameters
    type(friction_def_t) :: def
    type(string_t), allocatable :: fields(:)
    type(error_t), allocatable :: err
    integer :: i, eq
    real(dp) :: value
    def%law = law
    call split_fields(parameters, fields)
    do i = 1, size(fields)
      eq = index(fields(i)%s, '=')
      associate (name => fields(i)%s(1:eq - 1), text => fields(i)%s(eq + 1:))
        if (name == 'STATE LAW' .or. name == 'REGULARISATION' .or. name == 'RATE UPDATE' .or. &
            name == 'VELOCITY') then
          call set_friction_parameter(def, name, text, err)
        else
          read (text, *) value
          call set_friction_parameter(def, name, value, err)
        end if
        if (allocated(err)) then
          write (error_unit, '(a)') 'deck_def: ' // err%message
          error stop 1
        end if
      end associate
    end do
  end function deck_def

  !> The valid parameters of each law, in the units of the fault-bend model (mm, s).
  function valid_parameters(law) result(text)
    character(len=*), intent(in) :: law
    character(len=:), allocatable :: text
    select case (law)
    case ('COULOMB')
      text = 'MU0=0.6'
    case ('STATIC KINETIC')
      text = 'MU0=0.6, MUK=0.4, DECAY=10'
    case ('SLIP WEAKENING')
      text = 'MU0=0.6, MUK=0.4, DC=0.01'
    case ('RATE DEPENDENT')
      text = 'MU0=0.6, A=0.01, B=0.025, V0=0.001, VC=1e-6, REGULARISATION=floor'
    case ('RATE STATE')
      text = 'MU0=0.6, A=0.01, B=0.015, DC=0.01, V0=0.001, VC=1e-9, STATE LAW=AGEING, VINIT=0.002'
    case default
      text = 'MU0=0.6, A=0.01, B=0.015, DC=0.01, V0=0.001, STATE LAW=SLIP, THETA0=3'
    end select
  end function valid_parameters

  !> RATE UPDATE: EXPLICIT by default for RATE DEPENDENT, IMPLICIT for the laws with state,
  !> either when given; an invalid value and a law without a rate are refused.
  subroutine check_rate_update(suite)
    type(test_suite_t), intent(inout) :: suite
    class(friction_law_t), allocatable :: law
    type(error_t), allocatable :: err
    type(friction_def_t) :: def
    call create_friction_law(deck_def('RATE DEPENDENT', valid_parameters('RATE DEPENDENT')), law, err)
    call suite%check(.not. allocated(err) .and. law%explicit_rate, 'RATE DEPENDENT: explicit by default')
    call create_friction_law(deck_def('RATE STATE', valid_parameters('RATE STATE')), law, err)
    call suite%check(.not. allocated(err) .and. .not. law%explicit_rate, &
                     'RATE STATE: implicit by default')
    call create_friction_law(deck_def('RATE DEPENDENT', valid_parameters('RATE DEPENDENT') // &
                                      ', RATE UPDATE=implicit'), law, err)
    call suite%check(.not. allocated(err) .and. .not. law%explicit_rate, 'RATE UPDATE=IMPLICIT given')
    call create_friction_law(deck_def('RATE STATE ARCSINH', valid_parameters('RATE STATE ARCSINH') &
                                      // ', RATE UPDATE=EXPLICIT'), law, err)
    call suite%check(.not. allocated(err) .and. law%explicit_rate, 'RATE UPDATE=EXPLICIT given')
    def = deck_def('RATE DEPENDENT', valid_parameters('RATE DEPENDENT') // ', RATE UPDATE=LATER')
    call create_friction_law(def, law, err)
    call suite%check(allocated(err), 'RATE UPDATE=LATER refused')
    if (allocated(err)) call suite%check(contains_text(err%message, 'EXPLICIT, IMPLICIT'), &
                                         'the message lists EXPLICIT, IMPLICIT')
    def = deck_def('COULOMB', 'MU0=0.6, RATE UPDATE=EXPLICIT')
    call create_friction_law(def, law, err)
    call suite%check(allocated(err), 'RATE UPDATE refused for COULOMB')
  end subroutine check_rate_update

  !> VELOCITY: SLIP (the slip rate) by default and when given, RELATIVE (the total relative
  !> tangential velocity, the literal reading of eq. 3) for every rate law, independent of
  !> RATE UPDATE; an invalid value and a law without a rate are refused with a message that
  !> names the valid choices / the law's parameters.
  subroutine check_velocity(suite)
    type(test_suite_t), intent(inout) :: suite
    class(friction_law_t), allocatable :: law
    type(error_t), allocatable :: err
    call create_friction_law(deck_def('RATE DEPENDENT', valid_parameters('RATE DEPENDENT')), law, err)
    call suite%check(.not. allocated(err) .and. .not. law%relative_velocity, &
                     'VELOCITY: SLIP by default')
    call create_friction_law(deck_def('RATE DEPENDENT', valid_parameters('RATE DEPENDENT') // &
                                      ', VELOCITY=slip'), law, err)
    call suite%check(.not. allocated(err) .and. .not. law%relative_velocity, 'VELOCITY=SLIP given')
    call create_friction_law(deck_def('RATE DEPENDENT', valid_parameters('RATE DEPENDENT') // &
                                      ', VELOCITY=RELATIVE'), law, err)
    call suite%check(.not. allocated(err) .and. law%relative_velocity .and. law%explicit_rate, &
                     'VELOCITY=RELATIVE on RATE DEPENDENT, RATE UPDATE still EXPLICIT')
    call create_friction_law(deck_def('RATE STATE', valid_parameters('RATE STATE') // &
                                      ', VELOCITY=RELATIVE'), law, err)
    call suite%check(.not. allocated(err) .and. law%relative_velocity .and. .not. law%explicit_rate, &
                     'VELOCITY=RELATIVE on RATE STATE, implicit')
    call create_friction_law(deck_def('RATE STATE ARCSINH', valid_parameters('RATE STATE ARCSINH') &
                                      // ', VELOCITY=RELATIVE'), law, err)
    call suite%check(.not. allocated(err) .and. law%relative_velocity, &
                     'VELOCITY=RELATIVE on RATE STATE ARCSINH')
    call create_friction_law(deck_def('RATE DEPENDENT', valid_parameters('RATE DEPENDENT') // &
                                      ', VELOCITY=ELASTIC'), law, err)
    call suite%check(allocated(err), 'VELOCITY=ELASTIC refused')
    if (allocated(err)) call suite%check(contains_text(err%message, &
      'VELOCITY = "ELASTIC" is not valid; expected one of SLIP, RELATIVE'), 'the message lists SLIP, RELATIVE')
    call create_friction_law(deck_def('COULOMB', 'MU0=0.6, VELOCITY=RELATIVE'), law, err)
    call suite%check(allocated(err), 'VELOCITY refused for COULOMB')
    if (allocated(err)) call suite%check(contains_text(err%message, &
      'parameter VELOCITY does not apply to law COULOMB'), 'the message names VELOCITY and COULOMB')
  end subroutine check_velocity

  !> The recipe "How to add a friction law" on a test-only law: registered at run time, the
  !> registry's names, parameter lists, messages and the *FRICTION keyword parameters include
  !> it; create_friction_law builds it from deck-style parameters with its default RATE
  !> UPDATE; its derivatives pass the shared finite-difference checks. A second registration
  !> of the name, and an entry naming a parameter outside the catalogue, are refused.
  subroutine check_registered_law(suite)
    type(test_suite_t), intent(inout) :: suite
    type(friction_registry_t) :: registry
    type(friction_def_t) :: def
    class(friction_law_t), allocatable :: law
    type(error_t), allocatable :: err
    type(param_spec_t), allocatable :: params(:)
    character(len=*), parameter :: NAME = 'TEST LINEAR RATE'
    integer :: i
    call registry%init()
    call suite%equal_int(size(registry%names()), size(friction_laws()), 'registry: the built-in laws')
    call registry%register(test_linear_rate_entry(), err)
    call suite%check(.not. allocated(err), 'registry: ' // NAME // ' registered')
    call suite%check(any_is(friction_laws(registry), NAME), 'registry: law names include it')
    call suite%check(.not. any_is(friction_laws(), NAME), 'registry: the built-in list does not')
    call suite%check(friction_parameter_names(NAME, registry) == 'MU0, A, V0, RATE UPDATE', &
                     'registry: its parameter list')
    params = friction_keyword_params(registry)
    call suite%check(params(1)%name == 'LAW' .and. params(1)%kind == PARAM_CHOICE, &
                     'keyword table: *FRICTION LAW= is a choice')
    call suite%check(any_is(params(1)%choices, NAME), 'keyword table: LAW= offers it')
    params = friction_keyword_params()
    call suite%check(.not. any_is(params(1)%choices, NAME), 'keyword table: built-in LAW= does not')
    def = deck_def(NAME, 'MU0=0.5, A=0.02, V0=0.001')
    call suite%equal_int(size(friction_def_problems(def, registry)), 0, 'registry: a valid definition')
    call suite%equal_int(size(friction_def_problems(def)), 1, 'built-in: an unknown law')
    call create_friction_law(def, law, err, registry)
    call suite%check(.not. allocated(err), 'create_friction_law builds ' // NAME)
    if (allocated(law)) then
      call suite%check(law%name() == NAME, 'its name()')
      call suite%check(law%explicit_rate, 'its default RATE UPDATE (EXPLICIT)')
      call suite%close_to(law%mu(1.0_dp, 0.002_dp, 0.0_dp), 0.54_dp, 1.0e-15_dp, &
                          'mu = MU0 + A V/V0')
      do i = 0, 2
        call check_derivatives(suite, law, 10.0_dp, 0.001_dp * i, 0.0_dp, 0.001_dp, 1.0_dp, NAME)
      end do
    end if
    call create_friction_law(deck_def(NAME, 'MU0=0.5, A=0.02, V0=0.001, RATE UPDATE=IMPLICIT'), &
                             law, err, registry)
    call suite%check(.not. allocated(err) .and. .not. law%explicit_rate, 'RATE UPDATE=IMPLICIT given')
    call create_friction_law(deck_def(NAME, 'MU0=0.5, A=0.02'), law, err, registry)
    call suite%check(allocated(err), 'missing V0 refused')
    if (allocated(err)) call suite%check(contains_text(err%message, 'law ' // NAME // &
      ': missing parameter V0'), 'missing V0: message names the law and the parameter')
    call create_friction_law(deck_def(NAME, 'MU0=0.5, A=0.02, V0=0.001, DC=1'), law, err, registry)
    call suite%check(allocated(err), 'DC refused')
    if (allocated(err)) call suite%check(contains_text(err%message, 'parameter DC does not ' // &
      'apply to law ' // NAME // '; expected one of MU0, A, V0, RATE UPDATE'), &
      'DC: message lists its parameters')
    def%law = 'NO SUCH LAW'
    call create_friction_law(def, law, err, registry)
    call suite%check(allocated(err), 'unknown law refused')
    if (allocated(err)) call suite%check(contains_text(err%message, 'RATE STATE ARCSINH, ' // NAME), &
                                         'unknown law: the message lists the registered law')
    call registry%register(test_linear_rate_entry(), err)
    call suite%check(allocated(err), 'a second ' // NAME // ' refused')
    block
      type(friction_law_entry_t) :: entry
      entry = test_linear_rate_entry()
      entry%name = 'TEST OTHER'
      entry%required = [string_t('MU0'), string_t('K')]
      call registry%register(entry, err)
      call suite%check(allocated(err), 'a parameter outside the catalogue refused')
    end block
  end subroutine check_registered_law

  logical function any_is(names, name)
    type(string_t), intent(in) :: names(:)
    character(len=*), intent(in) :: name
    integer :: i
    any_is = .false.
    do i = 1, size(names)
      if (names(i)%s == name) any_is = .true.
    end do
  end function any_is

  logical function contains_text(message, text)
    character(len=*), intent(in) :: message, text
    contains_text = index(message, text) > 0
  end function contains_text

  subroutine check_catalogue(suite)
    type(test_suite_t), intent(inout) :: suite
    type(friction_parameter_t), allocatable :: catalogue(:)
    type(string_t), allocatable :: laws(:)
    catalogue = friction_parameters()
    laws = friction_laws()
    call suite%equal_int(size(laws), 6, 'six laws')
    call suite%equal_int(size(catalogue), 14, 'fourteen parameters')
    call suite%check(friction_parameter_names('RATE STATE') == &
                     'MU0, A, B, DC, V0, VC, STATE LAW, THETA0, VINIT, RATE UPDATE, VELOCITY', &
                     'RATE STATE parameter list')
    call suite%check(friction_parameter_names('COULOMB') == 'MU0', 'COULOMB parameter list')
    call suite%check(friction_parameter_names('NONSENSE') == '', 'unknown law: no parameters')
    call suite%equal_int(size(friction_required_parameters('RATE DEPENDENT')), 6, &
                         'RATE DEPENDENT: six required parameters')
    call suite%equal_int(size(friction_optional_parameters('RATE STATE ARCSINH')), 4, &
                         'RATE STATE ARCSINH: THETA0, VINIT, RATE UPDATE, VELOCITY optional')
    call suite%equal_int(size(catalogue(9)%choices), 2, 'REGULARISATION has two choices')
    call suite%check(catalogue(10)%name == 'STATE LAW' .and. catalogue(10)%choices(1)%s == &
                     'AGEING', 'STATE LAW choices')
    call suite%check(catalogue(4)%unit == 'length', 'DC unit')
  end subroutine check_catalogue

  !> Each law by name: its name(), number of states, initial state, and a value of mu.
  subroutine check_valid_laws(suite)
    type(test_suite_t), intent(inout) :: suite
    type(string_t), allocatable :: laws(:)
    class(friction_law_t), allocatable :: law
    type(error_t), allocatable :: err
    type(friction_def_t) :: def
    integer :: i
    integer, parameter :: n_states(6) = [0, 0, 1, 0, 1, 1]
    ! Initial states: slip 0; theta0 = DC/VINIT = 5 s; THETA0 = 3 s.
    real(dp), parameter :: initial(6) = [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 5.0_dp, 3.0_dp]
    laws = friction_laws()
    do i = 1, size(laws)
      def = deck_def(laws(i)%s, valid_parameters(laws(i)%s))
      call suite%equal_int(size(friction_def_problems(def)), 0, laws(i)%s // ': no problems')
      call create_friction_law(def, law, err)
      call suite%check(.not. allocated(err), laws(i)%s // ': created')
      if (allocated(err)) cycle
      call suite%check(law%name() == laws(i)%s, laws(i)%s // ': name()')
      call suite%equal_int(law%n_state(), n_states(i), laws(i)%s // ': n_state()')
      ! theta0 = 0.01/0.002 in floating point: a couple of ulps.
      call suite%close_to(law%initial_state(), initial(i), 1.0e-15_dp, laws(i)%s // &
                          ': initial_state()', floor=1.0_dp)
    end do
    ! Spot values from the factory-built laws (closed forms; rounding only).
    def = deck_def('RATE DEPENDENT', valid_parameters('RATE DEPENDENT'))
    call create_friction_law(def, law, err)
    call suite%close_to(law%mu(10.0_dp, 0.0_dp, 0.0_dp), 0.6_dp - 0.015_dp * log(1.0e-3_dp), &
                        1.0e-14_dp, 'RATE DEPENDENT FLOOR from the factory: mu(0) = mu_ss(VC)')
    def%regularisation = 'LINEAR'
    call create_friction_law(def, law, err)
    call suite%close_to(law%mu(10.0_dp, 0.0_dp, 0.0_dp), 0.615_dp - 0.015_dp * log(1.0e-3_dp), &
                        1.0e-14_dp, 'RATE DEPENDENT LINEAR from the factory: mu(0)')
    def = deck_def('STATIC KINETIC', valid_parameters('STATIC KINETIC'))
    call create_friction_law(def, law, err)
    call suite%close_to(law%mu(10.0_dp, 0.1_dp, 0.0_dp), 0.4_dp + 0.2_dp * exp(-1.0_dp), &
                        1.0e-14_dp, 'STATIC KINETIC from the factory')
    ! The frictionless law the contact system builds: COULOMB with only MU0 = 0 set.
    def = friction_def_t()
    def%law = 'COULOMB'
    def%mu0 = 0.0_dp
    call create_friction_law(def, law, err)
    call suite%check(.not. allocated(err), 'frictionless COULOMB')
  end subroutine check_valid_laws

  subroutine check_unknown_law(suite)
    type(test_suite_t), intent(inout) :: suite
    type(friction_def_t) :: def
    class(friction_law_t), allocatable :: law
    type(error_t), allocatable :: err
    type(string_t), allocatable :: laws(:)
    integer :: i
    def%law = 'RATE AND STATE'
    call create_friction_law(def, law, err)
    call suite%check(allocated(err), 'unknown law rejected')
    if (.not. allocated(err)) return
    call suite%equal_int(err%exit_code, EXIT_INPUT, 'unknown law: input error')
    call suite%check(contains_text(err%message, '"RATE AND STATE"'), 'unknown law: named')
    call suite%check(contains_text(err%message, join_strings(friction_laws(), ', ')), &
                     'unknown law: lists valid')
    laws = friction_laws()
    do i = 1, size(laws)
      call suite%check(contains_text(err%message, laws(i)%s), 'unknown law: lists ' // laws(i)%s)
    end do
    def = friction_def_t()
    call create_friction_law(def, law, err)
    call suite%check(allocated(err), 'no law name rejected')
  end subroutine check_unknown_law

  subroutine check_setters(suite)
    type(test_suite_t), intent(inout) :: suite
    type(friction_def_t) :: def
    type(error_t), allocatable :: err
    def%law = 'RATE STATE'
    call set_friction_parameter(def, 'MUS', 0.6_dp, err)
    call suite%check(allocated(err), 'unknown parameter MUS rejected')
    if (allocated(err)) call suite%check(contains_text(err%message, '"MUS"') .and. &
      contains_text(err%message, 'expected one of MU0, MUK, DECAY, DC, A, B, V0, VC'), &
      'unknown parameter: named, valid ones listed: ' // err%message)
    call set_friction_parameter(def, 'dc', 0.01_dp, err)
    call suite%check(.not. allocated(err) .and. def%dc == 0.01_dp, 'lower-case name accepted')
    call set_friction_parameter(def, 'DC', 0.02_dp, err)
    call suite%check(allocated(err), 'repeated DC rejected')
    if (allocated(err)) call suite%check(contains_text(err%message, 'repeated parameter DC'), &
                                         'repeated: named')
    call set_friction_parameter(def, 'STATE LAW', 1.0_dp, err)
    call suite%check(allocated(err), 'number for STATE LAW rejected')
    if (allocated(err)) call suite%check(contains_text(err%message, 'AGEING, SLIP'), &
                                         'number for a choice: choices listed')
    call set_friction_parameter(def, 'A', 'big', err)
    call suite%check(allocated(err), 'text for A rejected')
    call set_friction_parameter(def, 'STATE LAW', 'slip', err)
    call suite%check(.not. allocated(err) .and. def%state_law == 'SLIP', 'choice upper-cased')
  end subroutine check_setters

  !> A parameter of another law, a missing one, THETA0/VINIT both or neither, bad choices.
  subroutine check_applicability(suite)
    type(test_suite_t), intent(inout) :: suite
    type(friction_def_t) :: def
    class(friction_law_t), allocatable :: law
    type(error_t), allocatable :: err
    def = deck_def('COULOMB', 'MU0=0.6, DECAY=3')
    call expect_error(suite, def, 'DECAY does not apply to law COULOMB; expected one of MU0', &
                      'DECAY for COULOMB')
    def = deck_def('RATE STATE', 'MU0=0.6, A=0.01, B=0.015, V0=0.001, VC=1e-9, STATE LAW=AGEING, ' // &
                   'THETA0=1')
    call expect_error(suite, def, 'missing parameter DC', 'RATE STATE without DC')
    def = deck_def('RATE STATE', valid_parameters('RATE STATE') // ', THETA0=1')
    call expect_error(suite, def, 'either as THETA0 or as VINIT, not both', 'THETA0 and VINIT')
    def = deck_def('RATE STATE ARCSINH', 'MU0=0.6, A=0.01, B=0.015, DC=0.01, V0=0.001, STATE LAW=SLIP')
    call expect_error(suite, def, 'missing parameter THETA0 or VINIT', 'neither THETA0 nor VINIT')
    def = deck_def('RATE STATE ARCSINH', valid_parameters('RATE STATE ARCSINH') // ', VC=1e-9')
    call expect_error(suite, def, 'VC does not apply to law RATE STATE ARCSINH', 'VC for ARCSINH')
    def = deck_def('RATE DEPENDENT', 'MU0=0.6, A=0.01, B=0.025, V0=0.001, VC=1e-6')
    call expect_error(suite, def, 'missing parameter REGULARISATION', 'RATE DEPENDENT without REGULARISATION')
    def = deck_def('RATE DEPENDENT', 'MU0=0.6, A=0.01, B=0.025, V0=0.001, VC=1e-6, REGULARISATION=CAP')
    call expect_error(suite, def, 'REGULARISATION = "CAP" is not valid; expected one of FLOOR, LINEAR', &
                      'bad REGULARISATION')
    def = deck_def('RATE STATE', 'MU0=0.6, A=0.01, B=0.015, DC=0.01, V0=0.001, VC=1e-9, ' // &
                   'STATE LAW=AGING, VINIT=1')
    call expect_error(suite, def, 'STATE LAW = "AGING" is not valid; expected one of AGEING, SLIP', &
                      'bad STATE LAW')
    ! Every problem is reported, not only the first.
    def = deck_def('SLIP WEAKENING', 'MU0=-1, DC=0')
    call suite%equal_int(size(friction_def_problems(def)), 3, 'three problems reported together')
    call create_friction_law(def, law, err)
    if (allocated(err)) call suite%check(contains_text(err%message, 'MU0 = -1') .and. &
      contains_text(err%message, 'missing parameter MUK') .and. contains_text(err%message, 'DC = 0'), &
      'all three in the message: ' // err%message)
  end subroutine check_applicability

  !> Each out-of-range parameter, one at a time, on an otherwise valid definition.
  subroutine check_out_of_range(suite)
    type(test_suite_t), intent(inout) :: suite
    call expect_error(suite, deck_def('COULOMB', 'MU0=-0.1'), 'MU0 = -0.1 is out of range; expected MU0 >= 0', &
                      'negative MU0')
    call expect_error(suite, deck_def('STATIC KINETIC', 'MU0=0.6, MUK=0.7, DECAY=10'), &
                      'MUK = 0.7 is out of range; expected 0 <= MUK <= MU0', 'MUK > MU0')
    call expect_error(suite, deck_def('STATIC KINETIC', 'MU0=0.6, MUK=-0.1, DECAY=10'), &
                      'MUK = -0.1 is out of range', 'negative MUK')
    call expect_error(suite, deck_def('STATIC KINETIC', 'MU0=0.6, MUK=0.4, DECAY=0'), &
                      'DECAY = 0 is out of range; expected DECAY > 0', 'zero DECAY')
    call expect_error(suite, deck_def('SLIP WEAKENING', 'MU0=0.6, MUK=0.7, DC=0.01'), &
                      'MUK = 0.7 is out of range', 'SLIP WEAKENING: MUK > MU0')
    call expect_error(suite, deck_def('SLIP WEAKENING', 'MU0=0.6, MUK=0.4, DC=-0.01'), &
                      'DC = -1E-02 is out of range; expected DC > 0 [length]', 'negative DC')
    call expect_error(suite, deck_def('RATE DEPENDENT', 'MU0=0.6, A=-0.01, B=0.025, V0=0.001, VC=1e-6, ' // &
                      'REGULARISATION=FLOOR'), 'A = -1E-02 is out of range; expected A >= 0', 'negative A')
    call expect_error(suite, deck_def('RATE DEPENDENT', 'MU0=0.6, A=0.01, B=-0.025, V0=0.001, VC=1e-6, ' // &
                      'REGULARISATION=FLOOR'), 'B = -2.5E-02 is out of range; expected B >= 0', 'negative B')
    call expect_error(suite, deck_def('RATE DEPENDENT', 'MU0=0.6, A=0.01, B=0.025, V0=0, VC=1e-6, ' // &
                      'REGULARISATION=FLOOR'), 'V0 = 0 is out of range; expected V0 > 0', 'zero V0')
    call expect_error(suite, deck_def('RATE DEPENDENT', 'MU0=0.6, A=0.01, B=0.025, V0=0.001, VC=0, ' // &
                      'REGULARISATION=LINEAR'), 'VC = 0 is out of range; expected VC > 0', 'zero VC')
    call expect_error(suite, deck_def('RATE STATE', 'MU0=0.6, A=0.01, B=0.015, DC=0, V0=0.001, VC=1e-9, ' // &
                      'STATE LAW=AGEING, VINIT=1'), 'DC = 0 is out of range', 'RATE STATE: zero DC')
    call expect_error(suite, deck_def('RATE STATE', 'MU0=0.6, A=0.01, B=0.015, DC=0.01, V0=0.001, VC=-1, ' // &
                      'STATE LAW=AGEING, VINIT=1'), 'VC = -1 is out of range', 'RATE STATE: negative VC')
    call expect_error(suite, deck_def('RATE STATE', 'MU0=0.6, A=0.01, B=0.015, DC=0.01, V0=0.001, VC=1e-9, ' // &
                      'STATE LAW=AGEING, THETA0=0'), 'THETA0 = 0 is out of range; expected THETA0 > 0', &
                      'zero THETA0')
    call expect_error(suite, deck_def('RATE STATE', 'MU0=0.6, A=0.01, B=0.015, DC=0.01, V0=0.001, VC=1e-9, ' // &
                      'STATE LAW=AGEING, VINIT=-1'), 'VINIT = -1 is out of range; expected VINIT > 0', &
                      'negative VINIT')
    call expect_error(suite, deck_def('RATE STATE ARCSINH', 'MU0=0.6, A=0, B=0.015, DC=0.01, V0=0.001, ' // &
                      'STATE LAW=AGEING, THETA0=1'), 'A = 0 is out of range; expected A > 0', &
                      'ARCSINH: zero A')
    call expect_error(suite, deck_def('RATE STATE ARCSINH', 'MU0=0.6, A=0.01, B=0.015, DC=0.01, V0=-1, ' // &
                      'STATE LAW=AGEING, THETA0=1'), 'V0 = -1 is out of range', 'ARCSINH: negative V0')
  end subroutine check_out_of_range

  !> create_friction_law must fail with an input error whose message contains `expected`.
  subroutine expect_error(suite, def, expected, what)
    type(test_suite_t), intent(inout) :: suite
    type(friction_def_t), intent(in) :: def
    character(len=*), intent(in) :: expected, what
    class(friction_law_t), allocatable :: law
    type(error_t), allocatable :: err
    call create_friction_law(def, law, err)
    call suite%check(allocated(err), what // ': rejected')
    if (.not. allocated(err)) return
    call suite%check(err%exit_code == EXIT_INPUT .and. contains_text(err%message, expected), &
                     what // ': message "' // err%message // '" should contain "' // expected // '"')
  end subroutine expect_error

end program test_fcs_friction_factory
