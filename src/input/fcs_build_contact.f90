!> Model builder, contact keywords: *SURFACE INTERACTION, *SURFACE BEHAVIOR, *FRICTION,
!> *CONTACT PAIR, *TIE (with their CalculiX meaning; method notes 1.2-1.3).
module fcs_build_contact
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t
  use fcs_deck_fields, only: param_upper, param_value, line_real, line_optional_real
  use fcs_diagnostics, only: diagnostics_t, source_loc_t
  use fcs_builder_state, only: builder_t
  use fcs_mesh, only: SURFACE_FACES
  use fcs_model, only: model_t, interaction_def_t, contact_pair_def_t
  use fcs_strings, only: to_upper, str, parse_real, string_t
  use fcs_error, only: error_t
  use fcs_friction_factory, only: friction_def_t, friction_def_problems, set_friction_parameter, &
                                  friction_parameter_names
  implicit none
  private
  public :: handle_surface_interaction, handle_surface_behavior, handle_friction
  public :: handle_contact_pair, handle_tie

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

  !> *SURFACE BEHAVIOR, PRESSURE-OVERCLOSURE=LINEAR|TIED: slope E_n.
  subroutine handle_surface_behavior(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: slope, extra
    integer :: i
    if (.not. has_interaction(card, state, diag)) return
    associate (line => card%lines(1))
      if (card%n_lines /= 1 .or. size(line%fields) > 3) then
        call diag%report(line%loc, '*SURFACE BEHAVIOR: expected one line: slope[, sigma_inf, c0]')
        return
      end if
      if (.not. line_real(line, 1, slope, 'slope', 'SURFACE BEHAVIOR', diag)) return
      if (slope <= 0.0_dp) then
        call diag%report(line%loc, '*SURFACE BEHAVIOR: the slope (penalty stiffness E_n) must be positive')
        return
      end if
      do i = 2, size(line%fields)
        if (.not. line_optional_real(line, i, extra, 0.0_dp, 'value', 'SURFACE BEHAVIOR', diag)) return
        if (extra /= 0.0_dp) then
          call diag%report(line%loc, '*SURFACE BEHAVIOR: sigma_inf and c0 (CalculiX''s tension ' // &
                           'at large clearance) are not used by fcs3d; leave them 0 or absent')
          return
        end if
      end do
    end associate
    associate (interaction => model%interactions(state%interaction))
      interaction%normal_stiffness = slope
      interaction%tied = param_upper(card, 'PRESSURE-OVERCLOSURE') == 'TIED'
    end associate
  end subroutine handle_surface_behavior

  !> *FRICTION, LAW=...: the law and its parameters (keyword line), or for COULOMB the
  !> CalculiX data line mu[, stick slope]; the stick slope also as STICK SLOPE=.
  subroutine handle_friction(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(friction_def_t) :: def
    type(string_t), allocatable :: problems(:)
    real(dp) :: stick, damping
    logical :: from_material
    integer :: i
    if (.not. has_interaction(card, state, diag)) return
    if (model%interactions(state%interaction)%has_friction) then
      call diag%report(card%loc, '*FRICTION: interaction ' // model%interactions(state%interaction)%name // &
                       ' already has friction')
      return
    end if
    def%law = param_upper(card, 'LAW')
    def%loc = card%loc
    stick = 0.0_dp
    if (.not. radiation_damping(card, damping, from_material, diag)) return
    if (.not. set_law_parameters(card, def, stick, diag)) return
    if (card%n_lines > 0) then
      if (.not. coulomb_data_line(card, def, stick, diag)) return
    end if
    problems = friction_def_problems(def)
    do i = 1, size(problems)
      call diag%report(card%loc, '*FRICTION, LAW=' // def%law // ': ' // problems(i)%s)
    end do
    if (size(problems) > 0) return
    associate (interaction => model%interactions(state%interaction))
      interaction%has_friction = .true.
      interaction%friction = def
      interaction%stick_stiffness = stick
      interaction%radiation_damping = damping
      interaction%damping_from_material = from_material
    end associate
  end subroutine handle_friction

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
    integer :: k, i
    pair%loc = card%loc
    do k = 1, size(model%interactions)
      if (model%interactions(k)%name == param_upper(card, 'INTERACTION')) pair%interaction = k
    end do
    if (pair%interaction == 0) then
      call diag%report(card%loc, '*CONTACT PAIR: interaction "' // param_value(card, 'INTERACTION') // &
                       '" is not defined (define it with *SURFACE INTERACTION first)')
      return
    end if
    do i = 1, card%n_lines
      if (.not. pair_surfaces(card, i, model, diag, pair)) cycle
      pair%name = param_upper(card, 'NAME')
      if (len(pair%name) == 0) pair%name = model%mesh%surfaces(pair%slave_surface)%name // '-' // &
                                           model%mesh%surfaces(pair%master_surface)%name
      if (card%n_lines > 1 .and. card%find_param('NAME') > 0) pair%name = pair%name // '-' // str(i)
      pair%tied = model%interactions(pair%interaction)%tied
      call add_pair(model, pair, card%lines(i)%loc, diag)
    end do
  end subroutine handle_contact_pair

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
      pair%slave_surface = model%mesh%find_surface(to_upper(line%fields(1)%s))
      pair%master_surface = model%mesh%find_surface(to_upper(line%fields(2)%s))
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

end module fcs_build_contact
