!> Model builder, contact keywords: *SURFACE INTERACTION, *SURFACE BEHAVIOR, *FRICTION,
!> *CONTACT PAIR, *TIE, *CHANGE FRICTION, *CHANGE SURFACE BEHAVIOR (with their CalculiX
!> meaning; method notes 1.2-1.3).
module fcs_build_contact
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t
  use fcs_deck_fields, only: param_upper, param_value, line_real, line_optional_real
  use fcs_diagnostics, only: diagnostics_t, source_loc_t
  use fcs_builder_state, only: builder_t
  use fcs_mesh, only: SURFACE_FACES, SURFACE_NODES
  use fcs_model, only: model_t, interaction_def_t, contact_pair_def_t, friction_change_t, &
                       behavior_change_t
  use fcs_strings, only: to_upper, str, parse_real, string_t
  use fcs_error, only: error_t
  use fcs_friction_factory, only: friction_def_t, friction_def_problems, set_friction_parameter, &
                                  friction_parameter_names
  use fcs_pressure_overclosure, only: pressure_overclosure_t, OVERCLOSURE_EXPONENTIAL
  implicit none
  private
  public :: handle_surface_interaction, handle_surface_behavior, handle_friction
  public :: handle_contact_pair, handle_tie, resolve_pair_interactions, handle_change_friction
  public :: handle_change_surface_behavior

contains

  !> *SURFACE INTERACTION, NAME=.
  subroutine handle_surface_interaction(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(interaction_def_t) :: interaction
    integer :: k
    interaction%name = param_upper(card, 'NAME')
    interaction%loc = card%loc
    do k = 1, size(model%interactions)
      if (model%interactions(k)%name == interaction%name) then
        call diag%report(card%loc, '*SURFACE INTERACTION: ' // interaction%name // ' is defined twice')
        state%interaction = 0
        return
      end if
    end do
    model%interactions = [model%interactions, interaction]
    state%interaction = size(model%interactions)
  end subroutine handle_surface_interaction

  logical function has_interaction(card, state, diag) result(ok)
    type(card_t), intent(in) :: card
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    ok = state%interaction > 0
    if (.not. ok) call diag%report(card%loc, '*' // card%keyword // ' must follow a ' // &
                                   '*SURFACE INTERACTION line')
  end function has_interaction

  !> *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR|TIED: slope K[, sigma_inf[, c0]], as in
  !> CalculiX; EXPONENTIAL: c0, p0 (exponential_behavior); in a step, after *CHANGE SURFACE
  !> BEHAVIOR, the interaction's new behaviour (handle_step_behavior). fcs3d's penalty E_n is K: p = K max(-c, 0) (c the clearance, negative when
  !> penetrating) on every slave node that projects onto the master. CalculiX's node-to-face
  !> law smooths it, p = -K c (1/2 + arctan(-c/eps)/pi) with eps = pi sigma_inf / K: a tension
  !> tending to sigma_inf at large clearance, p = K (-c) - sigma_inf at large penetration (so
  !> its penetrations exceed fcs3d's by sigma_inf / K at the same pressure); c0 scales the
  !> clearance within which CalculiX makes contact elements. Both are read and ignored, with
  !> a warning.
  subroutine handle_surface_behavior(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    if (state%in_step) then
      call handle_step_behavior(card, model, state, diag)
      return
    end if
    if (.not. has_interaction(card, state, diag)) return
    call read_behavior(card, model%interactions(state%interaction), diag)
  end subroutine handle_surface_behavior

  !> The normal behaviour of a *SURFACE BEHAVIOR card into `interaction` (left as it was
  !> after an error).
  subroutine read_behavior(card, interaction, diag)
    type(card_t), intent(in) :: card
    type(interaction_def_t), intent(inout) :: interaction
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: slope, extra(2)
    integer :: i
    if (param_upper(card, 'PRESSURE-OVERCLOSURE') == 'EXPONENTIAL') then
      call exponential_behavior(card, interaction, diag)
      return
    end if
    associate (line => card%lines(1))
      if (card%n_lines /= 1 .or. size(line%fields) > 3) then
        call diag%report(line%loc, '*SURFACE BEHAVIOR: expected one line: slope K[, sigma_inf[, c0]]')
        return
      end if
      if (.not. line_real(line, 1, slope, 'slope', 'SURFACE BEHAVIOR', diag)) return
      if (slope <= 0.0_dp) then
        call diag%report(line%loc, '*SURFACE BEHAVIOR: the slope (penalty stiffness E_n) must be positive')
        return
      end if
      extra = 0.0_dp
      do i = 2, size(line%fields)
        if (.not. line_optional_real(line, i, extra(i - 1), 0.0_dp, trim(merge('sigma_inf', &
            'c0       ', i == 2)), 'SURFACE BEHAVIOR', diag)) return
      end do
      if (extra(1) /= 0.0_dp) call diag%warn(line%loc, '*SURFACE BEHAVIOR: sigma_inf = ' // &
        line%fields(2)%s // ' is ignored: CalculiX''s smoothed law carries a tension tending ' // &
        'to sigma_inf at large clearance and gives p = K overclosure - sigma_inf at large ' // &
        'overclosure; fcs3d''s penalty p = K max(overclosure, 0) carries no tension ' // &
        '(penetrations differ by sigma_inf / K)')
      if (extra(2) /= 0.0_dp) call diag%warn(line%loc, '*SURFACE BEHAVIOR: c0 = ' // &
        line%fields(3)%s // ' (CalculiX''s clearance, relative to the slave faces, within ' // &
        'which it makes contact elements) is ignored: every slave node that projects onto ' // &
        'the master is a contact candidate in fcs3d')
    end associate
    interaction%normal_stiffness = slope
    interaction%tied = param_upper(card, 'PRESSURE-OVERCLOSURE') == 'TIED'
    interaction%overclosure = pressure_overclosure_t()
  end subroutine read_behavior

  !> *CHANGE SURFACE BEHAVIOR, INTERACTION= (CalculiX's changesurfacebehaviors.f): the
  !> *SURFACE BEHAVIOR that follows it gives that interaction's new normal behaviour from this
  !> step on.
  subroutine handle_change_surface_behavior(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(in) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    state%changed_behavior = interaction_index(model, param_upper(card, 'INTERACTION'))
    if (state%changed_behavior == 0) then
      call diag%report(card%loc, '*CHANGE SURFACE BEHAVIOR: interaction "' // &
                       param_value(card, 'INTERACTION') // '" is not defined')
      return
    end if
    state%behavior_loc = card%loc
  end subroutine handle_change_surface_behavior

  !> *SURFACE BEHAVIOR in a step, after *CHANGE SURFACE BEHAVIOR: the new normal behaviour of
  !> its interaction. CalculiX takes any law; fcs3d changes LINEAR and EXPONENTIAL parameters
  !> and laws, and releases a tie (TIED to LINEAR or EXPONENTIAL); tying an untied interaction
  !> in a step is refused. The interaction's definition is the one of the model: what a step
  !> changes is kept in the step (behavior_change_t) and applied when the step starts.
  subroutine handle_step_behavior(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(in) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(interaction_def_t) :: changed
    type(behavior_change_t) :: change
    integer :: n_before
    if (state%changed_behavior == 0) then
      call diag%report(card%loc, '*SURFACE BEHAVIOR in a step must follow *CHANGE SURFACE ' // &
                       'BEHAVIOR, INTERACTION= (or move it before the first *STEP)')
      return
    end if
    change%interaction = state%changed_behavior
    change%loc = card%loc
    state%changed_behavior = 0
    changed = model%interactions(change%interaction)
    n_before = diag%count
    call read_behavior(card, changed, diag)
    if (diag%count > n_before) return
    if (changed%tied .and. .not. model%interactions(change%interaction)%tied) then
      call diag%report(card%loc, '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED in a step: ' // &
        'interaction ' // changed%name // ' is not tied; tying surfaces in a step is not ' // &
        'available (a tie can be released: TIED to LINEAR or EXPONENTIAL)')
      return
    end if
    if (changed%tied) then
      call diag%report(card%loc, '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=TIED in a step: ' // &
        'the tie of interaction ' // changed%name // ' cannot be changed (its penalty is ' // &
        'fixed when the tie is made); release it with LINEAR or EXPONENTIAL')
      return
    end if
    change%normal_stiffness = changed%normal_stiffness
    change%overclosure = changed%overclosure
    if (.not. allocated(state%step%behavior_changes)) allocate (state%step%behavior_changes(0))
    state%step%behavior_changes = [state%step%behavior_changes, change]
  end subroutine handle_step_behavior

  !> *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL: one line c0 [length], p0 [stress]
  !> (CalculiX's order and checks, surfacebehaviors.f: c0 > 0, p0 >= 0; p = p0 exp(-beta g),
  !> beta = ln(100)/c0: fcs_pressure_overclosure). CalculiX reads the first two fields of the
  !> line and no more: later fields are ignored with a warning; p0 = 0 (no pressure at all)
  !> is accepted with a warning.
  subroutine exponential_behavior(card, interaction, diag)
    type(card_t), intent(in) :: card
    type(interaction_def_t), intent(inout) :: interaction
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: c0, p0
    associate (line => card%lines(1))
      if (card%n_lines /= 1 .or. size(line%fields) < 2) then
        call diag%report(line%loc, '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL: ' // &
          'expected one line: c0 (the clearance where the pressure is 1 % of p0), p0 (the ' // &
          'pressure at zero clearance)')
        return
      end if
      if (.not. line_real(line, 1, c0, 'c0', 'SURFACE BEHAVIOR', diag)) return
      if (.not. line_real(line, 2, p0, 'p0', 'SURFACE BEHAVIOR', diag)) return
      if (.not. (c0 > 0.0_dp .and. c0 <= huge(c0))) then
        call diag%report(line%loc, '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL: c0 = ' // &
          line%fields(1)%s // ' must be positive (the clearance [length] at which the pressure ' // &
          'has fallen to 1 % of p0)')
        return
      end if
      if (.not. (p0 >= 0.0_dp .and. p0 <= huge(p0))) then
        call diag%report(line%loc, '*SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=EXPONENTIAL: p0 = ' // &
          line%fields(2)%s // ' must not be negative (the contact pressure [stress] at zero ' // &
          'clearance)')
        return
      end if
      if (p0 == 0.0_dp) call diag%warn(line%loc, '*SURFACE BEHAVIOR: p0 = 0: the interaction ' // &
        'carries no contact pressure (accepted, as CalculiX does)')
      if (size(line%fields) > 2) call diag%warn(line%loc, '*SURFACE BEHAVIOR, PRESSURE-' // &
        'OVERCLOSURE=EXPONENTIAL: the fields after c0, p0 are ignored (CalculiX reads two)')
    end associate
    interaction%overclosure = pressure_overclosure_t(OVERCLOSURE_EXPONENTIAL, c0, p0)
    interaction%tied = .false.
    interaction%normal_stiffness = 0.0_dp
  end subroutine exponential_behavior

  !> *FRICTION, LAW=...: the law and its parameters (keyword line), or for COULOMB the
  !> CalculiX data line mu[, stick slope]; the stick slope also as STICK SLOPE=. In a step,
  !> after *CHANGE FRICTION: the new Coulomb friction of that interaction (handle_step_friction).
  subroutine handle_friction(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(friction_def_t) :: def
    real(dp) :: stick, damping
    logical :: from_material
    if (state%in_step) then
      call handle_step_friction(card, state, diag)
      return
    end if
    if (.not. has_interaction(card, state, diag)) return
    if (model%interactions(state%interaction)%has_friction) then
      call diag%report(card%loc, '*FRICTION: interaction ' // model%interactions(state%interaction)%name // &
                       ' already has friction')
      return
    end if
    if (.not. radiation_damping(card, damping, from_material, diag)) return
    if (.not. read_friction(card, def, stick, diag)) return
    associate (interaction => model%interactions(state%interaction))
      interaction%has_friction = .true.
      interaction%friction = def
      interaction%stick_stiffness = stick
      interaction%radiation_damping = damping
      interaction%damping_from_material = from_material
    end associate
  end subroutine handle_friction

  !> The law, its parameters and the stick slope of a *FRICTION card; false after errors.
  logical function read_friction(card, def, stick, diag) result(ok)
    type(card_t), intent(in) :: card
    type(friction_def_t), intent(out) :: def
    real(dp), intent(out) :: stick
    type(diagnostics_t), intent(inout) :: diag
    type(string_t), allocatable :: problems(:)
    integer :: i
    ok = .false.
    def%law = param_upper(card, 'LAW')
    def%loc = card%loc
    stick = 0.0_dp
    if (.not. set_law_parameters(card, def, stick, diag)) return
    if (card%n_lines > 0) then
      if (.not. coulomb_data_line(card, def, stick, diag)) return
    end if
    problems = friction_def_problems(def)
    do i = 1, size(problems)
      call diag%report(card%loc, '*FRICTION, LAW=' // def%law // ': ' // problems(i)%s)
    end do
    ok = size(problems) == 0
  end function read_friction

  !> *CHANGE FRICTION, INTERACTION=: the next *FRICTION of this step changes that interaction.
  subroutine handle_change_friction(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(in) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    state%changed_interaction = interaction_index(model, param_upper(card, 'INTERACTION'))
    if (state%changed_interaction == 0) then
      call diag%report(card%loc, '*CHANGE FRICTION: interaction "' // &
                       param_value(card, 'INTERACTION') // '" is not defined')
      return
    end if
    if (model%interactions(state%changed_interaction)%tied) then
      call diag%report(card%loc, '*CHANGE FRICTION: interaction "' // &
                       param_value(card, 'INTERACTION') // '" is tied (PRESSURE-OVERCLOSURE=TIED)')
      state%changed_interaction = 0
      return
    end if
    if (model%interactions(state%changed_interaction)%has_friction) then
      if (model%interactions(state%changed_interaction)%friction%law /= 'COULOMB') then
        call diag%report(card%loc, '*CHANGE FRICTION: interaction "' // &
          param_value(card, 'INTERACTION') // '" has friction LAW=' // &
          model%interactions(state%changed_interaction)%friction%law // &
          '; only Coulomb friction can be changed between steps')
        state%changed_interaction = 0
        return
      end if
    end if
    state%change_loc = card%loc
  end subroutine handle_change_friction

  !> *FRICTION in a step: after *CHANGE FRICTION, the Coulomb friction (mu[, stick slope]) of
  !> its interaction from this step on.
  subroutine handle_step_friction(card, state, diag)
    type(card_t), intent(in) :: card
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(friction_change_t) :: change
    if (state%changed_interaction == 0) then
      call diag%report(card%loc, '*FRICTION in a step must follow *CHANGE FRICTION, ' // &
                       'INTERACTION= (or move it before the first *STEP)')
      return
    end if
    change%interaction = state%changed_interaction
    change%loc = card%loc
    state%changed_interaction = 0
    if (card%find_param('RADIATION DAMPING') > 0) then
      call diag%report(card%loc, '*FRICTION in a step: RADIATION DAMPING cannot be changed ' // &
                       'between steps (give it on the *FRICTION of the interaction)')
      return
    end if
    if (.not. read_friction(card, change%friction, change%stick_stiffness, diag)) return
    if (change%friction%law /= 'COULOMB') then
      call diag%report(card%loc, '*FRICTION: only Coulomb friction (mu[, stick slope]) can ' // &
                       'be changed between steps, not LAW=' // change%friction%law)
      return
    end if
    if (.not. allocated(state%step%friction_changes)) allocate (state%step%friction_changes(0))
    state%step%friction_changes = [state%step%friction_changes, change]
  end subroutine handle_step_friction

  !> RADIATION DAMPING= of *FRICTION: eta >= 0 [stress time/length], or MATERIAL (eta from the
  !> bodies on either side of each pair, resolved with the model: fcs_model_checks). Absent: 0.
  logical function radiation_damping(card, damping, from_material, diag) result(ok)
    type(card_t), intent(in) :: card
    real(dp), intent(out) :: damping
    logical, intent(out) :: from_material
    type(diagnostics_t), intent(inout) :: diag
    character(len=:), allocatable :: text
    logical :: is_number
    ok = .true.
    damping = 0.0_dp
    from_material = .false.
    if (card%find_param('RADIATION DAMPING') == 0) return
    text = param_upper(card, 'RADIATION DAMPING')
    if (text == 'MATERIAL') then
      from_material = .true.
      return
    end if
    call parse_real(text, damping, is_number)
    if (.not. is_number .or. .not. (damping >= 0.0_dp .and. damping <= huge(damping))) then
      call diag%report(card%loc, '*FRICTION: RADIATION DAMPING = "' // &
        param_value(card, 'RADIATION DAMPING') // '" is not valid; expected MATERIAL (eta = ' // &
        'G / (2 c_s) from the elastic bodies of each pair) or a number eta >= 0 [stress ' // &
        'time/length]')
      damping = 0.0_dp
      ok = .false.
    end if
  end function radiation_damping

  !> The law's parameters from the keyword line; STICK SLOPE into `stick`.
  logical function set_law_parameters(card, def, stick, diag) result(ok)
    type(card_t), intent(in) :: card
    type(friction_def_t), intent(inout) :: def
    real(dp), intent(inout) :: stick
    type(diagnostics_t), intent(inout) :: diag
    type(error_t), allocatable :: err
    real(dp) :: value
    logical :: is_number
    integer :: k
    ok = .true.
    do k = 1, size(card%params)
      associate (param => card%params(k))
        if (param%name == 'LAW' .or. param%name == 'RADIATION DAMPING') cycle
        if (param%name == 'STICK SLOPE') then
          call parse_real(param%value, stick, is_number)
          if (stick <= 0.0_dp) then
            call diag%report(card%loc, '*FRICTION: STICK SLOPE must be positive')
            ok = .false.
          end if
          cycle
        end if
        call parse_real(param%value, value, is_number)
        if (is_number) then
          call set_friction_parameter(def, param%name, value, err)
        else
          call set_friction_parameter(def, param%name, param%value, err)
        end if
        if (allocated(err)) then
          call diag%report(card%loc, '*FRICTION: ' // err%message)
          ok = .false.
        end if
      end associate
    end do
  end function set_law_parameters

  !> The CalculiX data line mu[, stick slope], for COULOMB only.
  logical function coulomb_data_line(card, def, stick, diag) result(ok)
    type(card_t), intent(in) :: card
    type(friction_def_t), intent(inout) :: def
    real(dp), intent(inout) :: stick
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: mu, slope
    ok = .false.
    associate (line => card%lines(1))
      if (def%law /= 'COULOMB') then
        call diag%report(line%loc, '*FRICTION, LAW=' // def%law // ' takes its parameters on the ' // &
                         'keyword line (' // friction_parameter_names(def%law) // &
                         '; STICK SLOPE=), not on a data line')
        return
      end if
      if (card%n_lines /= 1 .or. size(line%fields) > 2) then
        call diag%report(line%loc, '*FRICTION: expected one line: mu[, stick slope]')
        return
      end if
      if (card%find_param('MU0') > 0) then
        call diag%report(line%loc, '*FRICTION: mu is given twice (MU0= and the data line)')
        return
      end if
      if (.not. line_real(line, 1, mu, 'friction coefficient', 'FRICTION', diag)) return
      if (.not. line_optional_real(line, 2, slope, 0.0_dp, 'stick slope', 'FRICTION', diag)) return
      if (size(line%fields) == 2) then
        if (slope <= 0.0_dp) then
          call diag%report(line%loc, '*FRICTION: the stick slope E_t must be positive')
          return
        end if
        if (stick > 0.0_dp) then
          call diag%report(line%loc, '*FRICTION: the stick slope is given twice (STICK SLOPE= ' // &
                           'and the data line)')
          return
        end if
        stick = slope
      end if
      def%mu0 = mu
    end associate
    ok = .true.
  end function coulomb_data_line

  !> *CONTACT PAIR, INTERACTION=: slave surface, master surface.
  subroutine handle_contact_pair(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(contact_pair_def_t) :: pair
    integer :: i
    pair%loc = card%loc
    pair%interaction_name = param_upper(card, 'INTERACTION')
    pair%surface_to_surface = param_upper(card, 'TYPE') == 'SURFACE TO SURFACE'
    if (card%find_param('SMALL SLIDING') > 0) call diag%warn(card%loc, '*CONTACT PAIR: SMALL ' // &
      'SLIDING is accepted as finite sliding: fcs3d finds each slave node''s master face once ' // &
      'per increment, as CalculiX does with SMALL SLIDING, and follows the node over the ' // &
      'master surface from increment to increment')
    if (card%find_param('ADJUST') > 0) then
      if (.not. adjust_parameter(card, model, diag, pair)) return
    end if
    do i = 1, card%n_lines
      if (.not. pair_surfaces(card, i, model, diag, pair)) cycle
      if (pair%surface_to_surface) then
        if (.not. face_slave(card, i, model, diag, pair)) cycle
      end if
      pair%name = param_upper(card, 'NAME')
      if (len(pair%name) == 0) pair%name = model%mesh%surfaces(pair%slave_surface)%name // '-' // &
                                           model%mesh%surfaces(pair%master_surface)%name
      if (card%n_lines > 1 .and. card%find_param('NAME') > 0) pair%name = pair%name // '-' // str(i)
      call add_pair(model, pair, card%lines(i)%loc, diag)
    end do
  end subroutine handle_contact_pair

  !> *CONTACT PAIR, ADJUST=: a clearance (a number >= 0) or a node set (its name), as
  !> CalculiX reads it; the move itself is fcs_contact_adjust's, after the model is built.
  logical function adjust_parameter(card, model, diag, pair) result(ok)
    type(card_t), intent(in) :: card
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(contact_pair_def_t), intent(inout) :: pair
    character(len=:), allocatable :: text
    real(dp) :: value
    text = param_value(card, 'ADJUST')
    pair%adjust_set = model%mesh%find_node_set(to_upper(text))
    ok = pair%adjust_set > 0
    if (ok) return
    call parse_real(text, value, ok)
    if (ok) then
      ok = value >= 0.0_dp
      if (ok) then
        pair%adjust_distance = value
      else
        call diag%report(card%loc, '*CONTACT PAIR: ADJUST=' // text // ' is negative; ' // &
          'expected a clearance >= 0 (slave nodes at most that far from the master are ' // &
          'moved onto it) or a node set')
      end if
    else if (len(text) > 0 .and. verify(text(1:1), '0123456789+-.') == 0) then
      call diag%report(card%loc, '*CONTACT PAIR: ADJUST=' // text // ' is not a number; ' // &
        'expected a clearance >= 0 or the name of a node set')
    else
      call diag%report(card%loc, '*CONTACT PAIR: ADJUST=' // text // ': no node set of ' // &
        'that name (define it with *NSET before the pair), nor a number (a clearance >= 0)')
    end if
  end function adjust_parameter

  !> The slave surface of a TYPE=SURFACE TO SURFACE pair (data line i): its element-face
  !> definition (integration points need faces); a node-based one is refused.
  logical function face_slave(card, i, model, diag, pair) result(ok)
    type(card_t), intent(in) :: card
    integer, intent(in) :: i
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(contact_pair_def_t), intent(inout) :: pair
    integer :: k
    k = model%mesh%find_surface(to_upper(card%lines(i)%fields(1)%s), SURFACE_FACES)
    ok = model%mesh%surfaces(k)%kind == SURFACE_FACES
    if (ok) then
      pair%slave_surface = k
    else
      call diag%report(card%lines(i)%loc, '*CONTACT PAIR, TYPE=SURFACE TO SURFACE: slave ' // &
        'surface "' // card%lines(i)%fields(1)%s // '" is node based; a surface-to-surface ' // &
        'pair integrates over the slave faces: define it by element faces (*SURFACE, ' // &
        'TYPE=ELEMENT) or use TYPE=NODE TO SURFACE')
    end if
  end function face_slave

  !> After the last card: the interaction of every *CONTACT PAIR, by name (a *SURFACE
  !> INTERACTION may follow the pair that names it, as CalculiX allows), and whether it ties.
  subroutine resolve_pair_interactions(model, diag)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: p, k
    do p = 1, size(model%contact_pairs)
      associate (pair => model%contact_pairs(p))
        if (.not. allocated(pair%interaction_name)) cycle
        pair%interaction = 0
        do k = 1, size(model%interactions)
          if (model%interactions(k)%name == pair%interaction_name) pair%interaction = k
        end do
        if (pair%interaction == 0) then
          call diag%report(pair%loc, '*CONTACT PAIR: interaction "' // pair%interaction_name // &
                           '" is not defined (define it with *SURFACE INTERACTION)')
          cycle
        end if
        pair%tied = model%interactions(pair%interaction)%tied
      end associate
    end do
  end subroutine resolve_pair_interactions

  !> *TIE, NAME=: slave surface, master surface.
  subroutine handle_tie(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(contact_pair_def_t) :: pair
    logical :: ok
    integer :: i
    pair%loc = card%loc
    pair%tied = .true.
    pair%interaction = 0
    if (card%find_param('POSITION TOLERANCE') > 0) then
      call parse_real(param_value(card, 'POSITION TOLERANCE'), pair%position_tolerance, ok)
      if (pair%position_tolerance <= 0.0_dp) then
        call diag%report(card%loc, '*TIE: POSITION TOLERANCE must be positive')
        return
      end if
    end if
    do i = 1, card%n_lines
      if (.not. pair_surfaces(card, i, model, diag, pair)) cycle
      pair%name = param_upper(card, 'NAME')
      if (card%n_lines > 1) pair%name = pair%name // '-' // str(i)
      call add_pair(model, pair, card%lines(i)%loc, diag)
    end do
  end subroutine handle_tie

  !> The slave and master surfaces of data line i.
  logical function pair_surfaces(card, i, model, diag, pair) result(ok)
    type(card_t), intent(in) :: card
    integer, intent(in) :: i
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(contact_pair_def_t), intent(inout) :: pair
    ok = .false.
    associate (line => card%lines(i))
      if (size(line%fields) /= 2) then
        call diag%report(line%loc, '*' // card%keyword // ': expected slave surface, master surface')
        return
      end if
      ! A name defined both ways (CalculiX's metalforming deck): the slave its nodes, the
      ! master its faces, as CalculiX takes them.
      pair%slave_surface = model%mesh%find_surface(to_upper(line%fields(1)%s), SURFACE_NODES)
      pair%master_surface = model%mesh%find_surface(to_upper(line%fields(2)%s), SURFACE_FACES)
      if (pair%slave_surface == 0) then
        call diag%report(line%loc, '*' // card%keyword // ': slave surface "' // line%fields(1)%s // &
                         '" is not defined')
        return
      end if
      if (pair%master_surface == 0) then
        call diag%report(line%loc, '*' // card%keyword // ': master surface "' // line%fields(2)%s // &
                         '" is not defined')
        return
      end if
      if (model%mesh%surfaces(pair%master_surface)%kind /= SURFACE_FACES) then
        call diag%report(line%loc, '*' // card%keyword // ': master surface "' // line%fields(2)%s // &
                         '" must be element-face based (the master segments are element faces)')
        return
      end if
      if (pair%slave_surface == pair%master_surface) then
        call diag%report(line%loc, '*' // card%keyword // ': a surface cannot be in contact with ' // &
                         'itself (self-contact is not supported)')
        return
      end if
    end associate
    ok = .true.
  end function pair_surfaces

  subroutine add_pair(model, pair, loc, diag)
    type(model_t), intent(inout) :: model
    type(contact_pair_def_t), intent(in) :: pair
    type(source_loc_t), intent(in) :: loc
    type(diagnostics_t), intent(inout) :: diag
    integer :: k
    do k = 1, size(model%contact_pairs)
      if (model%contact_pairs(k)%name == pair%name) then
        call diag%report(loc, 'contact pair ' // pair%name // ' is defined twice')
        return
      end if
    end do
    model%contact_pairs = [model%contact_pairs, pair]
  end subroutine add_pair

  !> Index of the *SURFACE INTERACTION named name (upper case) in model%interactions, 0 if none
  !> (the last one of that name, as the handlers found it before).
  pure integer function interaction_index(model, name) result(found)
    type(model_t), intent(in) :: model
    character(len=*), intent(in) :: name
    integer :: k
    found = 0
    do k = 1, size(model%interactions)
      if (model%interactions(k)%name == name) found = k
    end do
  end function interaction_index

end module fcs_build_contact
