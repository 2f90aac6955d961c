!> The model builder: reads a deck, checks every card against the keyword table, hands each
!> to its handler, and checks the finished model. All problems are collected and reported
!> together (up to a limit); a deck with errors yields no model.
!>
!> The deck's shape: the model definition (model cards and cards allowed anywhere), then the
!> steps (*STEP ... *END STEP). Between two steps only definitions that the following steps
!> may use are allowed (*AMPLITUDE, *TIME POINTS, *RESTART); a model card there would change
!> the model after steps ran on it, a *BOUNDARY there belongs to no step. Nothing may follow the
!> last *END STEP: such a card would be read and never used.
module fcs_model_builder
  use fcs_solver_factory, only: DEFAULT_LINEAR_SOLVER
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_deck_lexer, only: deck_t, card_t, param_t, read_deck
  use fcs_diagnostics, only: diagnostics_t
  use fcs_keywords, only: keyword_spec_t, param_spec_t, keyword_table, find_keyword, &
                          find_param_spec, same_name, PARAM_FLAG, PARAM_NAME, PARAM_REAL, &
                          PARAM_INTEGER, PARAM_CHOICE, PARAM_FILE, PARAM_IGNORED, CONTEXT_MODEL, &
                          CONTEXT_STEP
  use fcs_builder_state, only: builder_t
  use fcs_build_mesh, only: handle_node, handle_element, handle_nset, handle_elset, &
                            handle_surface, handle_mesh
  use fcs_build_hyperelastic, only: handle_hyperelastic, handle_hyperfoam, handle_deformation_plasticity
  use fcs_build_material, only: handle_material, handle_elastic, handle_hypoelastic, &
    handle_density, &
                                handle_solid_section, handle_solver, handle_restart, &
                                resolve_section_materials, handle_orientation, is_isotropic_elastic
  use fcs_build_plasticity, only: handle_plastic, handle_cyclic_hardening, handle_drucker_prager, &
                                  handle_drucker_prager_hardening
  use fcs_build_step, only: handle_step, handle_static, handle_end_step, handle_boundary, &
                            handle_cload, handle_dsload, handle_amplitude, handle_time_points, &
                            handle_rmin
  use fcs_build_thermal, only: handle_expansion, handle_elastic_table, handle_initial_conditions, &
                               handle_temperature, resolve_temperatures, given_fields, &
                               check_body_loads
  use fcs_build_output, only: handle_output_request, handle_history, handle_event_catalog
  use fcs_build_contact, only: handle_surface_interaction, handle_surface_behavior, &
                               handle_change_surface_behavior, &
                               handle_friction, handle_contact_pair, handle_tie, &
                               resolve_pair_interactions, handle_change_friction
  use fcs_build_constraints, only: handle_equation, handle_mpc, handle_rigid_body, &
                                   handle_transform, resolve_transforms
  use fcs_build_coupling, only: handle_coupling, handle_kinematic, handle_distributing
  use fcs_model, only: model_t, step_t
  use fcs_element_loops, only: mesh_kinds
  use fcs_model_checks, only: check_model
  use fcs_deck_hash, only: hash_deck
  use fcs_calculix_keywords, only: is_calculix_keyword
  use fcs_strings, only: string_t, to_upper, parse_int, parse_real, join_strings, str
  implicit none
  private
  public :: build_model, unsupported_keyword_reason

contains

  !> Read the deck at `path` and build `model`. On any input error, `err` holds all messages.
  subroutine build_model(path, model, deck, err)
    character(len=*), intent(in) :: path
    type(model_t), intent(out) :: model
    type(deck_t), intent(out) :: deck
    type(error_t), allocatable, intent(out) :: err
    type(diagnostics_t) :: diag
    type(builder_t) :: state
    type(keyword_spec_t), allocatable :: table(:)
    integer :: i, k, last_step_end
    call read_deck(path, deck, diag)
    if (diag%has_errors()) then
      call diag%to_error(err)
      return
    end if
    call init_model(model, path, err)
    if (allocated(err)) return
    allocate (state%steps(0))
    call state%boundary%clear()
    call state%loads%clear()
    call state%pressures%clear()
    call state%body_loads%clear()
    table = keyword_table()
    call canonical_spellings(deck, table)
    last_step_end = end_of_last_step(deck)
    do i = 1, deck%n_cards
      if (i > last_step_end) then
        call report_after_last_step(deck%cards(i), deck%cards(last_step_end), diag)
        if (diag%is_full()) exit
        cycle
      end if
      k = find_keyword(table, deck%cards(i)%keyword)
      if (.not. valid_card(deck%cards(i), table, k, state, diag)) then
        call keep_step_structure(deck%cards(i), state)
        cycle
      end if
      call dispatch(deck%cards(i), model, state, diag)
      if (diag%is_full()) exit
    end do
    if (state%in_step .and. .not. diag%is_full()) then
      call diag%report(state%step%loc, '*STEP: the step is not closed (add *END STEP at the end)')
    end if
    model%steps = state%steps
    if (.not. diag%is_full()) call resolve_temperatures(model, state, diag)
    if (.not. diag%is_full()) call resolve_section_materials(model, diag)
    if (.not. diag%is_full()) call resolve_pair_interactions(model, diag)
    if (.not. diag%is_full()) call resolve_transforms(model, diag)
    if (.not. diag%has_errors()) call check_model(model, diag, deck)
    if (.not. diag%has_errors()) call check_body_loads(model, diag)
    model%warnings = diag%warning_list()
    if (diag%has_errors()) then
      call diag%to_error(err)
      return
    end if
    call hash_deck(deck, model)
  end subroutine build_model

  !> Spell every keyword as the keyword table (or the list of refused CalculiX keywords) does:
  !> CalculiX ignores blanks in keywords, so that *ENDSTEP is *END STEP and *SOLIDSECTION is
  !> *SOLID SECTION.
  subroutine canonical_spellings(deck, table)
    type(deck_t), intent(inout) :: deck
    type(keyword_spec_t), intent(in) :: table(:)
    integer :: i, k
    do i = 1, deck%n_cards
      k = find_keyword(table, deck%cards(i)%keyword)
      if (k > 0) deck%cards(i)%keyword = table(k)%name
    end do
  end subroutine canonical_spellings

  !> Index of the last *END STEP card when no *STEP follows it; past the last card otherwise.
  pure integer function end_of_last_step(deck) result(last)
    type(deck_t), intent(in) :: deck
    integer :: i
    last = deck%n_cards + 1
    do i = deck%n_cards, 1, -1
      if (deck%cards(i)%keyword == 'STEP') return
      if (deck%cards(i)%keyword == 'END STEP') then
        last = i
        return
      end if
    end do
  end function end_of_last_step

  !> A card after the last *END STEP.
  subroutine report_after_last_step(card, end_step, diag)
    type(card_t), intent(in) :: card, end_step
    type(diagnostics_t), intent(inout) :: diag
    call diag%report(card%loc, '*' // card%keyword // ' comes after the last *END STEP (' // &
      end_step%loc%file // ':' // str(end_step%loc%line) // ') and would never be used: ' // &
      'move it into a step, or before the first *STEP if it belongs to the model definition')
  end subroutine report_after_last_step

  !> A card between two steps that may not stand there (see the module header).
  subroutine report_between_steps(card, spec, state, diag)
    type(card_t), intent(in) :: card
    type(keyword_spec_t), intent(in) :: spec
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    character(len=:), allocatable :: first_step
    first_step = state%steps(1)%loc%file // ':' // str(state%steps(1)%loc%line)
    if (spec%context == CONTEXT_MODEL) then
      call diag%report(card%loc, '*' // card%keyword // ' belongs to the model definition, ' // &
        'which ends at the first *STEP (' // first_step // '); it cannot change the model ' // &
        'between steps: move it before the first *STEP')
    else
      call diag%report(card%loc, '*' // card%keyword // ' between two steps belongs to ' // &
        'neither: put it inside the step it is meant for (after that step''s *STEP line)')
    end if
  end subroutine report_between_steps

  !> Cards that may stand between two steps: definitions the following steps may use.
  pure logical function allowed_between_steps(keyword)
    character(len=*), intent(in) :: keyword
    allowed_between_steps = any(keyword == [character(len=11) :: 'STEP', 'AMPLITUDE', &
      'TIME POINTS', 'RESTART'])
  end function allowed_between_steps

  subroutine init_model(model, path, err)
    type(model_t), intent(inout) :: model
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    model%title = ''
    model%deck_path = path
    model%solver_name = DEFAULT_LINEAR_SOLVER
    call model%element_kinds%init(err)
    if (allocated(err)) return
    call model%mesh%init(mesh_kinds(model%element_kinds))
    allocate (model%materials(0), model%sections(0), model%amplitudes(0), &
              model%time_points(0), model%steps(0), model%interactions(0), model%equations(0), &
              model%rotation_nodes(0), model%nonlinear_constraints(0), model%transforms(0), &
              model%orientations(0), model%contact_pairs(0), &
              model%histories(0), model%warnings(0))
  end subroutine init_model

  !> After a card with errors: still open or close its step, or mark the step's procedure as
  !> given, so that one bad *STEP, *STATIC or *END STEP line is reported once instead of
  !> making every later step keyword an error too ("can only appear inside a step").
  subroutine keep_step_structure(card, state)
    type(card_t), intent(in) :: card
    type(builder_t), intent(inout) :: state
    type(step_t) :: fresh
    select case (card%keyword)
    case ('STEP')
      if (state%in_step) return
      state%step = fresh
      state%step%loc = card%loc
      state%step%name = 'Step-' // str(size(state%steps) + 1)
      state%step%period = -1.0_dp
      state%in_step = .true.
    case ('STATIC')
      if (state%in_step) then
        state%step%period = 1.0_dp
        state%step%has_procedure = .true.
      end if
    case ('END STEP')
      state%in_step = .false.
    end select
  end subroutine keep_step_structure

  !> Hand a validated card to its handler.
  subroutine dispatch(card, model, state, diag)
    type(card_t), intent(inout) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    select case (card%keyword)
    case ('HEADING')
      if (card%n_lines > 0 .and. len(model%title) == 0) &
        model%title = join_strings(card%lines(1)%fields, ', ')
    case ('NODE')
      call handle_node(card, model, diag)
    case ('ELEMENT')
      call handle_element(card, model, diag)
    case ('NSET')
      call handle_nset(card, model, diag)
    case ('ELSET')
      call handle_elset(card, model, diag)
    case ('SURFACE')
      call handle_surface(card, model, diag)
    case ('MESH')
      call handle_mesh(card, model, diag)
    case ('SOLVER')
      call handle_solver(card, model, diag)
    case ('RESTART')
      call handle_restart(card, model, diag)
    case ('MATERIAL')
      call handle_material(card, model, state, diag)
    case ('ELASTIC')
      if (is_isotropic_elastic(card) .and. is_elastic_table(card)) then
        call handle_elastic_table(card, model, state, diag)
      else
        call handle_elastic(card, model, state, diag)
      end if
    case ('HYPOELASTIC')
      call handle_hypoelastic(card, model, state, diag)
    case ('HYPERELASTIC')
      call handle_hyperelastic(card, model, state, diag)
    case ('HYPERFOAM')
      call handle_hyperfoam(card, model, state, diag)
    case ('DEFORMATION PLASTICITY')
      call handle_deformation_plasticity(card, model, state, diag)
    case ('EXPANSION')
      call handle_expansion(card, model, state, diag)
    case ('INITIAL CONDITIONS')
      call handle_initial_conditions(card, model, state, diag)
    case ('TEMPERATURE')
      call handle_temperature(card, model, state, diag)
    case ('DENSITY')
      call handle_density(card, model, state, diag)
    case ('PLASTIC')
      call handle_plastic(card, model, state, diag)
    case ('CYCLIC HARDENING')
      call handle_cyclic_hardening(card, model, state, diag)
    case ('DRUCKER PRAGER')
      call handle_drucker_prager(card, model, state, diag)
    case ('DRUCKER PRAGER HARDENING')
      call handle_drucker_prager_hardening(card, model, state, diag)
    case ('SOLID SECTION')
      call handle_solid_section(card, model, diag)
    case ('ORIENTATION')
      call handle_orientation(card, model, diag)
    case ('SURFACE INTERACTION')
      call handle_surface_interaction(card, model, state, diag)
    case ('SURFACE BEHAVIOR')
      call handle_surface_behavior(card, model, state, diag)
    case ('FRICTION')
      call handle_friction(card, model, state, diag)
    case ('CHANGE FRICTION')
      call handle_change_friction(card, model, state, diag)
    case ('CHANGE SURFACE BEHAVIOR')
      call handle_change_surface_behavior(card, model, state, diag)
    case ('CONTACT PAIR')
      call handle_contact_pair(card, model, diag)
    case ('TIE')
      call handle_tie(card, model, diag)
    case ('EQUATION')
      call handle_equation(card, model, diag)
    case ('MPC')
      call handle_mpc(card, model, diag)
    case ('RIGID BODY')
      call handle_rigid_body(card, model, diag)
    case ('COUPLING')
      call handle_coupling(card, model, state, diag)
    case ('KINEMATIC')
      call handle_kinematic(card, model, state, diag)
    case ('DISTRIBUTING')
      call handle_distributing(card, model, state, diag)
    case ('TRANSFORM')
      call handle_transform(card, model, diag)
    case ('AMPLITUDE')
      call handle_amplitude(card, model, diag)
    case ('TIME POINTS')
      call handle_time_points(card, model, diag)
    case ('STEP')
      call handle_step(card, state, diag)
    case ('STATIC')
      call handle_static(card, state, diag)
    case ('RMIN')
      call handle_rmin(card, state, diag)
    case ('CONTROLS')
      call diag%warn(card%loc, '*CONTROLS is ignored: it tunes CalculiX''s Newton iterations ' // &
        'and increments; fcs3d''s follow its R-minimum step control (*RMIN sets its limits)')
    case ('END STEP')
      call handle_end_step(card, state, diag)
    case ('BOUNDARY')
      call handle_boundary(card, model, state, diag)
    case ('CLOAD')
      call handle_cload(card, model, state, diag)
    case ('DSLOAD', 'DLOAD')
      call handle_dsload(card, model, state, diag)
    case ('HISTORY')
      call handle_history(card, model, diag)
    case ('EVENT CATALOG')
      call handle_event_catalog(card, model, diag)
    case ('NODE PRINT', 'EL PRINT', 'NODE FILE', 'EL FILE', 'CONTACT PRINT', 'CONTACT FILE')
      call handle_output_request(card, model, state, diag)
    case default
      call diag%report(card%loc, '*' // card%keyword // ': internal error: no handler ' // &
                       '(the keyword table and the builder disagree)')
    end select
    select case (card%keyword)
    case ('MATERIAL', 'ELASTIC', 'HYPOELASTIC', 'HYPERELASTIC', 'HYPERFOAM', 'DENSITY', 'PLASTIC', 'CYCLIC HARDENING', &
          'DRUCKER PRAGER', 'DRUCKER PRAGER HARDENING', 'EXPANSION', 'DEFORMATION PLASTICITY')
    case default
      state%material = 0
    end select
    if (card%keyword /= 'SURFACE INTERACTION' .and. card%keyword /= 'SURFACE BEHAVIOR' .and. &
        card%keyword /= 'FRICTION') state%interaction = 0
    if (state%changed_behavior > 0 .and. card%keyword /= 'CHANGE SURFACE BEHAVIOR') then
      call diag%report(state%behavior_loc, '*CHANGE SURFACE BEHAVIOR must be followed directly ' // &
                       'by the *SURFACE BEHAVIOR card of the new behaviour')
      state%changed_behavior = 0
    end if
    if (state%coupling_ref > 0 .and. card%keyword /= 'COUPLING') then
      call diag%report(state%coupling_loc, '*COUPLING must be followed directly by *KINEMATIC ' // &
                       'or *DISTRIBUTING (the kind of coupling and its degrees of freedom)')
      state%coupling_ref = 0
    end if
  end subroutine dispatch

  !> Check a card against its specification: known keyword, right context, known and
  !> well-formed parameters, required ones present, data lines as expected. Defaults of
  !> absent parameters are added to the card (so the echo shows them).
  logical function valid_card(card, table, k, state, diag) result(ok)
    type(card_t), intent(inout) :: card
    type(keyword_spec_t), intent(in) :: table(:)
    integer, intent(in) :: k
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    integer :: n_before
    n_before = diag%count
    if (k == 0) then
      if (passed_over_as_calculix(card%keyword, table)) then
        call diag%warn(card%loc, 'unknown keyword *' // card%keyword // ' ignored with its ' // &
                       'data lines, as CalculiX ignores a card it cannot interpret (neither ' // &
                       'CalculiX nor fcs3d knows it)')
      else
        call diag%report(card%loc, unknown_keyword_message(card%keyword, table))
      end if
      ok = .false.
      return
    end if
    associate (spec => table(k))
      if (.not. state%in_step .and. size(state%steps) > 0 .and. &
          .not. allowed_between_steps(card%keyword)) then
        call report_between_steps(card, spec, state, diag)
      else if (spec%context == CONTEXT_MODEL .and. state%in_step) then
        if (card%keyword == 'STEP') then
          call diag%report(card%loc, '*STEP: the previous step "' // state%step%name // &
                           '" is not closed (add *END STEP before the next *STEP)')
        else
          call diag%report(card%loc, '*' // card%keyword // ' belongs to the model definition ' // &
                           'and cannot appear inside a step (move it before the first *STEP)')
        end if
      else if (spec%context == CONTEXT_STEP .and. .not. state%in_step) then
        call diag%report(card%loc, '*' // card%keyword // ' can only appear inside a step ' // &
                         '(between *STEP and *END STEP)')
      end if
      call check_params(card, spec, diag)
      if (len(spec%data) == 0 .and. card%n_lines > 0) then
        call diag%report(card%lines(1)%loc, '*' // card%keyword // ' takes no data lines ' // &
                         '(is a "*" missing at the start of the next keyword line?)')
      else if (spec%data_required .and. card%n_lines == 0 .and. .not. removes_all(card)) then
        call diag%report(card%loc, '*' // card%keyword // ': missing data lines: ' // spec%data)
      end if
    end associate
    ok = diag%count == n_before
  end function valid_card

  !> True for a card with OP=NEW (*BOUNDARY, *CLOAD, *DSLOAD): without data lines it removes
  !> every earlier condition of its kind, as in CalculiX.
  pure logical function removes_all(card)
    type(card_t), intent(in) :: card
    integer :: k
    k = card%find_param('OP')
    removes_all = .false.
    if (k > 0) removes_all = card%params(k)%value == 'NEW'
  end function removes_all

  !> Check each given parameter and add defaults of the absent ones.
  subroutine check_params(card, spec, diag)
    type(card_t), intent(inout) :: card
    type(keyword_spec_t), intent(in) :: spec
    type(diagnostics_t), intent(inout) :: diag
    integer :: i, j
    type(param_t) :: extra
    do i = 1, size(card%params)
      if (len(card%params(i)%name) == 0) cycle
      j = find_param_spec(spec, card%params(i)%name)
      if (j == 0) then
        call diag%report(card%loc, '*' // card%keyword // ': unknown parameter "' // &
                         card%params(i)%name // '"; ' // expected_params(spec))
        cycle
      end if
      card%params(i)%name = spec%params(j)%name
      if (spec%params(j)%kind == PARAM_IGNORED) then
        call diag%warn(card%loc, '*' // card%keyword // ': ' // card%params(i)%name // ' is ' // &
                       spec%params(j)%description)
        cycle
      end if
      call check_param_value(card, card%params(i), spec%params(j), diag)
    end do
    do j = 1, size(spec%params)
      if (card%find_param(spec%params(j)%name) > 0) cycle
      if (spec%params(j)%required) then
        call diag%report(card%loc, '*' // card%keyword // ': missing required parameter ' // &
                         spec%params(j)%name // '= (' // spec%params(j)%description // ')')
      else if (len(spec%params(j)%default) > 0) then
        extra%name = spec%params(j)%name
        extra%value = spec%params(j)%default
        extra%has_value = .true.
        card%params = [card%params, extra]
      end if
    end do
  end subroutine check_params

  !> Check one parameter's value against its kind; normalise choices to upper case.
  subroutine check_param_value(card, param, spec, diag)
    type(card_t), intent(in) :: card
    type(param_t), intent(inout) :: param
    type(param_spec_t), intent(in) :: spec
    type(diagnostics_t), intent(inout) :: diag
    character(len=:), allocatable :: prefix
    integer :: i, int_value
    real(dp) :: real_value
    logical :: ok
    prefix = '*' // card%keyword // ': ' // param%name
    if (spec%kind == PARAM_FLAG) then
      if (param%has_value) call diag%report(card%loc, prefix // ' is a flag and takes no value')
      return
    end if
    if (.not. param%has_value .and. spec%kind == PARAM_CHOICE .and. len(spec%flag_value) > 0) then
      param%value = spec%flag_value
      param%has_value = .true.
    end if
    if (.not. param%has_value .or. len(param%value) == 0) then
      call diag%report(card%loc, prefix // ' needs a value (' // param%name // '=...)')
      return
    end if
    select case (spec%kind)
    case (PARAM_CHOICE)
      param%value = to_upper(param%value)
      do i = 1, size(spec%choices)
        if (same_name(spec%choices(i)%s, param%value)) then
          param%value = spec%choices(i)%s
          return
        end if
      end do
      call diag%report(card%loc, prefix // '=' // param%value // ' is not valid; expected ' // &
                       join_strings(spec%choices, ', ') // '. ' // spec%description)
    case (PARAM_INTEGER)
      call parse_int(param%value, int_value, ok)
      if (.not. ok) call diag%report(card%loc, prefix // ' must be a whole number, not "' // &
                                     param%value // '"')
    case (PARAM_REAL)
      call parse_real(param%value, real_value, ok)
      if (.not. ok) call diag%report(card%loc, prefix // ' must be a number, not "' // &
                                     param%value // '"')
    case default
    end select
  end subroutine check_param_value

  function expected_params(spec) result(text)
    type(keyword_spec_t), intent(in) :: spec
    character(len=:), allocatable :: text
    integer :: j
    if (size(spec%params) == 0) then
      text = '*' // spec%name // ' takes no parameters'
      return
    end if
    text = 'expected one of '
    do j = 1, size(spec%params)
      if (j > 1) text = text // ', '
      text = text // spec%params(j)%name
    end do
  end function expected_params

  !> Whether an unknown card is passed over with a warning, as CalculiX passes over it: no
  !> CalculiX keyword begins its name (fcs_calculix_keywords), it is no Abaqus keyword that
  !> fcs3d refuses with a reason, and it is no near miss of a keyword fcs3d knows (a typo).
  logical function passed_over_as_calculix(keyword, table) result(pass)
    character(len=*), intent(in) :: keyword
    type(keyword_spec_t), intent(in) :: table(:)
    pass = .not. is_calculix_keyword(keyword)
    if (pass) pass = len(unsupported_keyword_reason(keyword)) == 0
    if (pass) pass = closest_keyword(keyword, table) == 0
  end function passed_over_as_calculix

  !> The keyword of `table` nearest to `keyword` when it is a plausible misspelling of it
  !> (edit distance at most max(2, a third of its length)), else 0.
  integer function closest_keyword(keyword, table) result(best)
    character(len=*), intent(in) :: keyword
    type(keyword_spec_t), intent(in) :: table(:)
    integer :: k, d, best_distance
    best = 0
    best_distance = huge(1)
    do k = 1, size(table)
      d = edit_distance(keyword, table(k)%name)
      if (d < best_distance) then
        best_distance = d
        best = k
      end if
    end do
    if (best_distance > max(2, len(keyword) / 3)) best = 0
  end function closest_keyword

  !> Message for an unknown keyword: a known CalculiX keyword we do not support says why;
  !> otherwise the closest known keyword is suggested.
  function unknown_keyword_message(keyword, table) result(text)
    character(len=*), intent(in) :: keyword
    type(keyword_spec_t), intent(in) :: table(:)
    character(len=:), allocatable :: text
    character(len=:), allocatable :: reason
    integer :: best
    reason = unsupported_keyword_reason(keyword)
    if (len(reason) > 0) then
      text = '*' // keyword // ' is not supported by fcs3d: ' // reason
      return
    end if
    text = 'unknown keyword *' // keyword
    best = closest_keyword(keyword, table)
    if (best > 0) then
      text = text // ' (did you mean *' // table(best)%name // '?)'
    else
      text = text // ' (fcs3d --list-keywords lists the keywords it knows)'
    end if
  end function unknown_keyword_message

  !> Why a keyword of CalculiX/Abaqus is refused ('' when it is simply unknown). Names are
  !> compared as CalculiX compares them (`same_name`: *RIGIDBODY is *RIGID BODY).
  function unsupported_keyword_reason(keyword) result(reason)
    character(len=*), intent(in) :: keyword
    character(len=:), allocatable :: reason
    if (is_one_of(keyword, [character(len=34) :: 'DYNAMIC', 'MODAL DYNAMIC', 'FREQUENCY', &
        'BUCKLE', 'HEAT TRANSFER', 'VISCO', 'COUPLED TEMPERATURE-DISPLACEMENT', &
        'UNCOUPLED TEMPERATURE-DISPLACEMENT', 'STEADY STATE DYNAMICS', 'GREEN', 'SENSITIVITY', &
        'COMPLEX FREQUENCY', 'ELECTROMAGNETICS'])) then
      reason = 'fcs3d solves quasi-static problems with its static-explicit stepper only (*STATIC)'
    else if (is_one_of(keyword, [character(len=34) :: 'SHELL SECTION', 'BEAM SECTION', &
             'MEMBRANE SECTION', 'SPRING', 'DASHPOT', 'MASS', 'USER ELEMENT', 'GAP'])) then
      reason = 'fcs3d has 3D solid elements only (C3D4, C3D6, C3D8, C3D8R, C3D8I, C3D10, ' // &
               'C3D15, C3D20, C3D20R)'
    else if (is_one_of(keyword, [character(len=34) :: &
             'CYCLIC SYMMETRY MODEL'])) then
      reason = 'constraints other than *BOUNDARY, *EQUATION, *MPC (PLANE, STRAIGHT, MEANROT), ' // &
               '*RIGID BODY, *COUPLING and *TRANSFORM are not available yet'
    else if (is_one_of(keyword, [character(len=34) :: &
             'CONDUCTIVITY', 'SPECIFIC HEAT', 'CREEP', &
             'USER MATERIAL', 'RATE DEPENDENT', 'CAP PLASTICITY', &
             'MOHR COULOMB', 'DRUCKER PRAGER CREEP'])) then
      reason = 'materials are linear elastic (*ELASTIC: isotropic, or anisotropic and elastic ' // &
               'only; St Venant-Kirchhoff under NLGEOM), hypoelastic (*HYPOELASTIC), ' // &
               'hyperelastic (*HYPERELASTIC, *HYPERFOAM), Ramberg-Osgood (*DEFORMATION ' // &
               'PLASTICITY), with ' // &
               'von Mises (*PLASTIC) or linear Drucker-Prager (*DRUCKER PRAGER) ' // &
               'plasticity'
    else if (is_one_of(keyword, [character(len=34) :: 'CFLUX', 'DFLUX', 'FILM', 'RADIATE'])) then
      reason = 'this load or initial condition is not available yet'
    else if (is_one_of(keyword, [character(len=34) :: 'CHANGE CONTACT TYPE'])) then
      reason = 'changing a contact interaction between steps is not available yet, except ' // &
               'its Coulomb friction (*CHANGE FRICTION) and normal behaviour (*CHANGE SURFACE BEHAVIOR)'
    else if (is_one_of(keyword, [character(len=34) :: 'PART', 'END PART', 'INSTANCE', &
             'END INSTANCE', 'ASSEMBLY', 'END ASSEMBLY'])) then
      reason = 'Abaqus parts and assemblies are not read (CalculiX does not read them either): ' // &
               'write the nodes and elements of the model as plain *NODE and *ELEMENT cards'
    else if (is_one_of(keyword, [character(len=34) :: 'GEOSTATIC', 'SOILS', 'DIRECT CYCLIC', &
             'MASS DIFFUSION', 'STEADY STATE TRANSPORT', 'ANNEAL', 'COUPLED THERMAL-ELECTRICAL', &
             'STATIC RIKS'])) then
      reason = 'this Abaqus procedure is not available; fcs3d solves quasi-static problems ' // &
               'with *STATIC (geostatic initial stress: *INITIAL CONDITIONS, TYPE=STRESS, GEOSTATIC)'
    else if (is_one_of(keyword, [character(len=34) :: 'PREDEFINED FIELD', 'FIELD', &
             'PERMEABILITY', 'POROUS ELASTIC', 'CONNECTOR SECTION', 'CONNECTOR BEHAVIOR', &
             'CONTACT', 'CONTACT INCLUSIONS', 'CONTACT PROPERTY ASSIGNMENT', 'SURFACE SMOOTHING', &
             'KINEMATIC COUPLING', 'CONTACT CONTROLS', 'CONTROLS'])) then
      reason = 'this Abaqus keyword is not available in fcs3d'
    else if (is_one_of(keyword, [character(len=34) :: 'NODE OUTPUT', 'ELEMENT OUTPUT', &
             'OUTPUT', 'CONTACT OUTPUT', 'SECTION PRINT', 'FACE PRINT'])) then
      reason = 'use *NODE PRINT / *EL PRINT (text) or *NODE FILE / *EL FILE (results file)'
    else
      reason = ''
    end if
  end function unsupported_keyword_reason

  !> Whether an *ELASTIC card is a temperature table (several lines, or a temperature field).
  logical function is_elastic_table(card) result(table)
    type(card_t), intent(in) :: card
    table = card%n_lines > 1
    if (card%n_lines == 1) table = given_fields(card%lines(1)) > 2
  end function is_elastic_table

  !> True when `keyword` is one of `names` (compared as `same_name`).
  pure logical function is_one_of(keyword, names)
    character(len=*), intent(in) :: keyword, names(:)
    integer :: i
    is_one_of = .false.
    do i = 1, size(names)
      if (same_name(keyword, trim(names(i)))) is_one_of = .true.
    end do
  end function is_one_of

  !> Levenshtein distance between two short strings.
  pure integer function edit_distance(a, b) result(d)
    character(len=*), intent(in) :: a, b
    integer :: row(0:len(b)), previous, tmp, i, j
    row = [(j, j = 0, len(b))]
    do i = 1, len(a)
      previous = row(0)
      row(0) = i
      do j = 1, len(b)
        tmp = row(j)
        row(j) = min(row(j) + 1, row(j - 1) + 1, previous + merge(0, 1, a(i:i) == b(j:j)))
        previous = tmp
      end do
    end do
    d = row(len(b))
  end function edit_distance

end module fcs_model_builder
