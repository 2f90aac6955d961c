!> Model builder, step keywords: *STEP, *STATIC, *END STEP, *BOUNDARY, *CLOAD, *DSLOAD, *DLOAD,
!> *AMPLITUDE, *TIME POINTS.
!>
!> Conditions follow the Abaqus/CalculiX rules: *BOUNDARY in the model definition holds in
!> every step; in a step, OP=MOD (default) adds to or changes the conditions of the previous
!> step and OP=NEW first removes all of them. The same holds for *CLOAD and for the face
!> pressures of *DSLOAD and *DLOAD (one list, as in CalculiX). Within one scope (the model data, or one step) a degree of freedom takes one condition: two
!> different ones (say a node in both a fixed set and a prescribed set) are an error naming
!> both lines, where CalculiX would silently keep the later.
module fcs_build_step
  use fcs_kinds, only: dp
  use fcs_rmin_events, only: contact_events_level
  use fcs_deck_lexer, only: card_t, data_line_t
  use fcs_deck_fields, only: param_upper, param_value, has_flag, line_real, line_int, &
                             line_optional_real, resolve_nodes, resolve_elements, is_integer_text
  use fcs_diagnostics, only: diagnostics_t, source_loc_t
  use fcs_builder_state, only: builder_t
  use fcs_mesh, only: SURFACE_FACES
  use fcs_model, only: model_t, step_t, dof_condition_t, face_load_t, amplitude_t, &
                       time_points_t, BC_DISPLACEMENT, BC_VELOCITY, BC_FIXED, body_load_t, &
                       BODY_GRAV, BODY_CENTRIF
  use fcs_strings, only: to_upper, str, parse_int, parse_real
  implicit none
  private
  public :: handle_step, handle_static, handle_end_step, handle_boundary, handle_cload
  public :: handle_dsload, handle_amplitude, handle_time_points, find_amplitude, find_time_points
  public :: handle_rmin, amplitude_param

  !> Clashing conditions named per card; the rest are counted in one message.
  integer, parameter :: MAX_CLASHES_NAMED = 5

contains

  !> *STEP: open a step.
  subroutine handle_step(card, state, diag)
    type(card_t), intent(inout) :: card
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(step_t) :: step
    integer :: increments
    logical :: ok
    state%step = step
    state%in_step = .true.
    state%step%loc = card%loc
    state%step%name = param_value(card, 'NAME')
    if (len(state%step%name) == 0) state%step%name = 'Step-' // str(size(state%steps) + 1)
    ! NLGEOM stays on in the following steps until NLGEOM=NO, as in CalculiX (steps.f) and
    ! Abaqus: a step without the parameter inherits the previous step's setting.
    if (card%find_param('NLGEOM') > 0) then
      state%step%nlgeom = param_upper(card, 'NLGEOM') == 'YES'
      state%step%nlgeom_refused = .not. state%step%nlgeom
    else if (size(state%steps) > 0) then
      state%step%nlgeom = state%steps(size(state%steps))%nlgeom
    else
      state%step%nlgeom = .false.
    end if
    call parse_int(param_value(card, 'INC'), increments, ok)
    if (increments <= 0) then
      call diag%report(card%loc, '*STEP: INC must be a positive number of increments')
    end if
    state%step%max_increments = increments
    state%step%period = -1.0_dp
    state%scope = size(state%steps) + 1
    state%boundary_renewed = .false.
    state%loads_renewed = .false.
    state%pressures_renewed = .false.
  end subroutine handle_step

  !> *STATIC: initial increment, period, minimum and maximum increments.
  subroutine handle_static(card, state, diag)
    type(card_t), intent(inout) :: card
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: v(4)
    logical :: ok, given(4)
    integer :: i
    v = [1.0_dp, 1.0_dp, -1.0_dp, -1.0_dp]
    given = .false.
    if (state%step%has_procedure) then
      call diag%report(card%loc, '*STATIC: the step already has a *STATIC (one per step)')
      return
    end if
    ! The step has a procedure even if its values are bad: no second error at *END STEP.
    state%step%has_procedure = .true.
    state%step%period = 1.0_dp
    state%step%direct = has_flag(card, 'DIRECT')
    if (card%find_param('SOLVER') > 0) call diag%warn(card%loc, '*STATIC: SOLVER=' // &
      param_value(card, 'SOLVER') // ' (CalculiX''s linear solver) is ignored: fcs3d''s ' // &
      'solver is chosen by *SOLVER or --solver (default UMFPACK)')
    if (card%n_lines > 1) then
      call diag%report(card%lines(2)%loc, '*STATIC: expected one data line')
      return
    end if
    if (card%n_lines == 1) then
      if (size(card%lines(1)%fields) > 4) then
        call diag%report(card%lines(1)%loc, '*STATIC: expected initial increment, period, ' // &
                         'minimum increment, maximum increment')
        return
      end if
      ok = .true.
      do i = 1, 4
        if (.not. line_optional_real(card%lines(1), i, v(i), v(i), static_field(i), 'STATIC', diag)) &
          ok = .false.
        if (i <= size(card%lines(1)%fields)) given(i) = len(card%lines(1)%fields(i)%s) > 0
        if (given(i) .and. ok .and. v(i) <= 0.0_dp) then
          call diag%report(card%lines(1)%loc, '*STATIC: the ' // static_field(i) // ' must be ' // &
            'positive, not ' // card%lines(1)%fields(i)%s // ' (leave the field empty for the default)')
          ok = .false.
        end if
      end do
      if (.not. ok) return
    end if
    if (.not. given(3)) v(3) = 1.0e-5_dp * v(2)
    if (.not. given(4)) v(4) = v(2)
    if (any(v <= 0.0_dp)) then
      call diag%report(static_loc(card), '*STATIC: the time increments and the period must be positive')
      return
    end if
    if (v(3) > v(4)) then
      call diag%report(static_loc(card), '*STATIC: the minimum increment exceeds the maximum increment')
      return
    end if
    v(1) = min(max(v(1), v(3)), v(4), v(2))
    state%step%initial_increment = v(1)
    state%step%period = v(2)
    state%step%min_increment = v(3)
    state%step%max_increment = v(4)
    ! DIRECT: fixed increments, never longer than the initial one.
    if (state%step%direct) state%step%max_increment = v(1)
  end subroutine handle_static

  pure function static_field(i) result(name)
    integer, intent(in) :: i
    character(len=:), allocatable :: name
    select case (i)
    case (1)
      name = 'initial time increment'
    case (2)
      name = 'time period'
    case (3)
      name = 'minimum time increment'
    case default
      name = 'maximum time increment'
    end select
  end function static_field

  function static_loc(card) result(loc)
    use fcs_diagnostics, only: source_loc_t
    type(card_t), intent(in) :: card
    type(source_loc_t) :: loc
    loc = card%loc
    if (card%n_lines > 0) loc = card%lines(1)%loc
  end function static_loc

  !> *RMIN: limits of the R-minimum step control for this step.
  subroutine handle_rmin(card, state, diag)
    type(card_t), intent(in) :: card
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: strain, rotation, tolerance, rate_change, mu_change, state_change, balance, plastic
    real(dp) :: slip_increment
    logical :: ok
    integer :: n_before, iterations
    if (state%step%has_rmin) then
      call diag%report(card%loc, '*RMIN: the step already has a *RMIN (one per step)')
      return
    end if
    state%step%has_rmin = .true.
    n_before = diag%count
    call parse_real(param_value(card, 'MAX STRAIN INCREMENT'), strain, ok)
    call parse_real(param_value(card, 'MAX ROTATION INCREMENT'), rotation, ok)
    call parse_real(param_value(card, 'EVENT TOLERANCE'), tolerance, ok)
    call parse_real(param_value(card, 'MAX PLASTIC STRAIN INCREMENT'), plastic, ok)
    call parse_real(param_value(card, 'MAX LOG RATE CHANGE'), rate_change, ok)
    call parse_real(param_value(card, 'MAX FRICTION CHANGE'), mu_change, ok)
    call parse_real(param_value(card, 'MAX STATE CHANGE'), state_change, ok)
    call parse_real(param_value(card, 'EQUILIBRIUM TOLERANCE'), balance, ok)
    call parse_int(param_value(card, 'MAX ITERATIONS'), iterations, ok)
    slip_increment = 0.0_dp
    if (card%find_param('MAX SLIP INCREMENT') > 0) then
      call parse_real(param_value(card, 'MAX SLIP INCREMENT'), slip_increment, ok)
      if (.not. (slip_increment > 0.0_dp .and. slip_increment <= 10.0_dp)) &
        call diag%report(card%loc, '*RMIN: MAX SLIP INCREMENT must lie in (0, 10] (a fraction of ' // &
                         'the characteristic slip L)')
    end if
    if (strain <= 0.0_dp .or. strain > 0.1_dp) &
      call diag%report(card%loc, '*RMIN: MAX STRAIN INCREMENT must lie in (0, 0.1]')
    if (rotation <= 0.0_dp .or. rotation > 10.0_dp) &
      call diag%report(card%loc, '*RMIN: MAX ROTATION INCREMENT must lie in (0, 10] degrees')
    if (tolerance < 0.0_dp .or. tolerance > 0.5_dp) &
      call diag%report(card%loc, '*RMIN: EVENT TOLERANCE must lie in [0, 0.5]')
    if (plastic <= 0.0_dp .or. plastic > 1.0_dp) &
      call diag%report(card%loc, '*RMIN: MAX PLASTIC STRAIN INCREMENT must lie in (0, 1]')
    if (rate_change <= 0.0_dp) call diag%report(card%loc, '*RMIN: MAX LOG RATE CHANGE must be positive')
    if (mu_change <= 0.0_dp) call diag%report(card%loc, '*RMIN: MAX FRICTION CHANGE must be positive')
    if (state_change <= 0.0_dp) call diag%report(card%loc, '*RMIN: MAX STATE CHANGE must be positive')
    if (balance <= 0.0_dp .or. balance > 1.0_dp) &
      call diag%report(card%loc, '*RMIN: EQUILIBRIUM TOLERANCE must lie in (0, 1]')
    if (iterations < 1 .or. iterations > 100) &
      call diag%report(card%loc, '*RMIN: MAX ITERATIONS must lie in [1, 100]')
    if (diag%count > n_before) return
    state%step%rmin%equilibrium_tolerance = balance
    state%step%rmin%max_iterations = iterations
    state%step%rmin%carry_unbalanced = param_upper(card, 'NO EQUILIBRIUM') == 'CARRY'
    state%step%rmin%contact_events = contact_events_level(param_upper(card, 'CONTACT EVENTS'))
    state%step%rmin%max_log_rate_change = rate_change
    state%step%rmin%max_friction_change = mu_change
    state%step%rmin%max_state_change = state_change
    state%step%rmin%max_slip_increment = slip_increment
    state%step%rmin%max_strain_increment = strain
    state%step%rmin%max_rotation_increment = rotation * acos(-1.0_dp) / 180.0_dp
    state%step%rmin%event_tolerance = tolerance
    state%step%rmin%max_plastic_strain_increment = plastic
  end subroutine handle_rmin

  !> *END STEP: close the step with the complete condition lists.
  subroutine handle_end_step(card, state, diag)
    type(card_t), intent(in) :: card
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    if (.not. state%step%has_procedure) then
      call diag%report(card%loc, '*END STEP: step "' // state%step%name // '" has no procedure ' // &
                       '(add *STATIC after *STEP)')
    end if
    state%step%boundary = state%boundary%to_array()
    state%step%loads = state%loads%to_array()
    state%step%pressures = state%pressures%to_array()
    if (.not. allocated(state%body_loads%items)) call state%body_loads%clear()
    state%step%body_loads = state%body_loads%items(1:state%body_loads%n)
    if (.not. allocated(state%step%outputs)) allocate (state%step%outputs(0))
    if (.not. allocated(state%step%friction_changes)) allocate (state%step%friction_changes(0))
    if (state%changed_interaction > 0) then
      call diag%report(state%change_loc, '*CHANGE FRICTION: no *FRICTION follows it in this step')
      state%changed_interaction = 0
    end if
    state%steps = [state%steps, state%step]
    state%in_step = .false.
  end subroutine handle_end_step

  !> *BOUNDARY: node or set, first dof, last dof, value.
  subroutine handle_boundary(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(dof_condition_t) :: c
    integer, allocatable :: nodes(:)
    integer :: i, j, first, last, dof, amplitude, origin, clash, n_clashes
    real(dp) :: value
    if (.not. amplitude_param(card, model, diag, amplitude)) return
    if (has_flag(card, 'FIXED') .and. .not. state%in_step) then
      call diag%report(card%loc, '*BOUNDARY, FIXED keeps the displacement at the start of a ' // &
                       'step: it belongs in a step (between *STEP and *END STEP)')
      return
    end if
    n_clashes = 0
    if (param_upper(card, 'OP') == 'NEW' .and. .not. (state%in_step .and. state%boundary_renewed)) then
      call state%boundary%clear()
      state%boundary_renewed = state%in_step
    end if
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        if (size(line%fields) < 2 .or. size(line%fields) > 4) then
          call diag%report(line%loc, '*BOUNDARY: expected node or node set, first dof[, last ' // &
                           'dof[, value]]')
          cycle
        end if
        if (.not. line_int(line, 2, first, 'first degree of freedom', 'BOUNDARY', diag)) cycle
        last = first
        if (size(line%fields) >= 3) then
          if (len(line%fields(3)%s) > 0) then
            if (.not. line_int(line, 3, last, 'last degree of freedom', 'BOUNDARY', diag)) cycle
          end if
        end if
        if (.not. line_optional_real(line, 4, value, 0.0_dp, 'value', 'BOUNDARY', diag)) cycle
        call resolve_nodes(model%mesh, line%fields(1)%s, line, 'BOUNDARY', diag, nodes)
        if (.not. valid_dofs(line, first, last, all_coupled(state, nodes), diag)) cycle
        c%kind = merge(BC_VELOCITY, BC_DISPLACEMENT, param_upper(card, 'TYPE') == 'VELOCITY')
        if (has_flag(card, 'FIXED')) then
          c%kind = BC_FIXED
          if (size(line%fields) >= 4) call diag%warn(line%loc, '*BOUNDARY, FIXED: the value ' // &
            'is ignored (the displacement at the start of the step is kept, as in CalculiX)')
          value = 0.0_dp
        end if
        c%value = value
        c%amplitude = amplitude
        origin = record_line(state, line%loc)
        do j = 1, size(nodes)
          do dof = first, last
            call coupled_dof(state, nodes(j), dof, c%node, c%dof)
            call state%boundary%put(c, state%scope, origin, clash)
            if (clash > 0) call report_clash(state, model, line%loc, 'BOUNDARY', c, clash, &
                                             n_clashes, diag)
          end do
        end do
      end associate
    end do
    call report_more_clashes(card%loc, 'BOUNDARY', n_clashes, diag)
  end subroutine handle_boundary

  !> Remember the data line `loc` that sets conditions; its index is their origin.
  integer function record_line(state, loc) result(origin)
    type(builder_t), intent(inout) :: state
    type(source_loc_t), intent(in) :: loc
    type(source_loc_t), allocatable :: grown(:)
    if (.not. allocated(state%condition_lines)) allocate (state%condition_lines(16))
    if (state%n_condition_lines == size(state%condition_lines)) then
      allocate (grown(2 * size(state%condition_lines)))
      grown(1:state%n_condition_lines) = state%condition_lines(1:state%n_condition_lines)
      call move_alloc(grown, state%condition_lines)
    end if
    state%n_condition_lines = state%n_condition_lines + 1
    origin = state%n_condition_lines
    state%condition_lines(origin) = loc
  end function record_line

  !> Report that `c` contradicts the condition set by line `clash` in the same scope (the
  !> first MAX_CLASHES_NAMED of a card; the rest are counted).
  subroutine report_clash(state, model, loc, keyword, c, clash, n_clashes, diag)
    type(builder_t), intent(in) :: state
    type(model_t), intent(in) :: model
    type(source_loc_t), intent(in) :: loc
    character(len=*), intent(in) :: keyword
    type(dof_condition_t), intent(in) :: c
    integer, intent(in) :: clash
    integer, intent(inout) :: n_clashes
    type(diagnostics_t), intent(inout) :: diag
    character(len=:), allocatable :: scope
    n_clashes = n_clashes + 1
    if (n_clashes > MAX_CLASHES_NAMED) return
    scope = 'the model data'
    if (state%in_step) scope = 'this step'
    associate (earlier => state%condition_lines(clash))
      call diag%report(loc, '*' // keyword // ': node ' // str(model%mesh%node_id(c%node)) // &
        ', degree of freedom ' // str(c%dof) // ' already has a different value in ' // scope // &
        ' (set at ' // earlier%file // ':' // str(earlier%line) // '); a degree of freedom ' // &
        'takes one value per step: take the node out of one of the sets, or give the values ' // &
        'in different steps')
    end associate
  end subroutine report_clash

  subroutine report_more_clashes(loc, keyword, n_clashes, diag)
    type(source_loc_t), intent(in) :: loc
    character(len=*), intent(in) :: keyword
    integer, intent(in) :: n_clashes
    type(diagnostics_t), intent(inout) :: diag
    if (n_clashes <= MAX_CLASHES_NAMED) return
    call diag%report(loc, '*' // keyword // ': ' // str(n_clashes - MAX_CLASHES_NAMED) // &
      ' more degrees of freedom with two different conditions in the same step')
  end subroutine report_more_clashes

  !> Degree of freedom `dof` of `node` as fcs3d holds it: 4-6 of the reference node of a
  !> *KINEMATIC coupling are 1-3 of its generated rotation node (fcs_build_coupling).
  subroutine coupled_dof(state, node, dof, held_node, held_dof)
    type(builder_t), intent(in) :: state
    integer, intent(in) :: node, dof
    integer, intent(out) :: held_node, held_dof
    held_node = node
    held_dof = dof
    if (dof <= 3) return
    held_node = state%coupling_rots(findloc(state%coupling_refs, node, 1))
    held_dof = dof - 3
  end subroutine coupled_dof

  !> True when every node is the reference node of a *KINEMATIC coupling (which has
  !> rotations 4-6).
  logical function all_coupled(state, nodes)
    type(builder_t), intent(in) :: state
    integer, intent(in) :: nodes(:)
    integer :: j
    all_coupled = .false.
    if (.not. allocated(state%coupling_refs) .or. size(nodes) == 0) return
    do j = 1, size(nodes)
      if (.not. any(state%coupling_refs == nodes(j))) return
    end do
    all_coupled = .true.
  end function all_coupled

  logical function valid_dofs(line, first, last, rotations, diag) result(ok)
    type(data_line_t), intent(in) :: line
    integer, intent(in) :: first, last
    !> The nodes have rotations 4-6 (reference nodes of *KINEMATIC couplings).
    logical, intent(in) :: rotations
    type(diagnostics_t), intent(inout) :: diag
    ok = first >= 1 .and. last <= merge(6, 3, rotations) .and. first <= last
    if (ok) return
    if (first >= 4 .and. first <= 6 .or. last >= 4 .and. last <= 6) then
      call diag%report(line%loc, '*BOUNDARY: degrees of freedom 4-6 are rotations, which solid ' // &
                       'elements do not have (only the reference node of a *COUPLING with ' // &
                       '*KINEMATIC has them); use 1, 2, 3 (x, y, z)')
    else
      call diag%report(line%loc, '*BOUNDARY: degrees of freedom must satisfy 1 <= first <= ' // &
                       'last <= 3 (x, y, z)')
    end if
  end function valid_dofs

  !> *CLOAD: node or set, dof, magnitude (applied to every node of a set).
  subroutine handle_cload(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(dof_condition_t) :: c
    integer, allocatable :: nodes(:)
    integer :: i, j, dof, amplitude, origin, clash, n_clashes
    real(dp) :: value
    if (.not. amplitude_param(card, model, diag, amplitude)) return
    n_clashes = 0
    if (param_upper(card, 'OP') == 'NEW' .and. .not. state%loads_renewed) then
      call state%loads%clear()
      state%loads_renewed = .true.
    end if
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        if (size(line%fields) /= 3) then
          call diag%report(line%loc, '*CLOAD: expected node or node set, dof, magnitude')
          cycle
        end if
        if (.not. line_int(line, 2, dof, 'degree of freedom', 'CLOAD', diag)) cycle
        if (.not. line_real(line, 3, value, 'magnitude', 'CLOAD', diag)) cycle
        call resolve_nodes(model%mesh, line%fields(1)%s, line, 'CLOAD', diag, nodes)
        if (dof < 1 .or. dof > merge(6, 3, all_coupled(state, nodes))) then
          call diag%report(line%loc, '*CLOAD: the degree of freedom must be 1, 2 or 3 (x, y, z; ' // &
            'moments 4-6 only at the reference node of a *COUPLING with *KINEMATIC)')
          cycle
        end if
        c%value = value
        c%amplitude = amplitude
        origin = record_line(state, line%loc)
        do j = 1, size(nodes)
          call coupled_dof(state, nodes(j), dof, c%node, c%dof)
          call state%loads%put(c, state%scope, origin, clash)
          if (clash > 0) call report_clash(state, model, line%loc, 'CLOAD', c, clash, &
                                           n_clashes, diag)
        end do
      end associate
    end do
    call report_more_clashes(card%loc, 'CLOAD', n_clashes, diag)
  end subroutine handle_cload

  !> *DSLOAD: surface, P, pressure, or element/set, P1..P6, pressure. *DLOAD: element/set,
  !> P1..P6, pressure (CalculiX's face numbering, as S1..S6). Both fill one list of face
  !> pressures, as in CalculiX, so OP=NEW of either removes the pressures of both.
  subroutine handle_dsload(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(face_load_t) :: f
    integer :: i, amplitude
    real(dp) :: value
    if (.not. amplitude_param(card, model, diag, amplitude)) return
    if (param_upper(card, 'OP') == 'NEW' .and. .not. state%pressures_renewed) then
      call state%pressures%clear()
      call state%body_loads%clear()
      state%pressures_renewed = .true.
    end if
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        if (card%keyword == 'DLOAD' .and. size(line%fields) >= 2) then
          if (is_body_label(line%fields(2)%s)) then
            call put_body_load(card, line, model, state, amplitude, diag)
            cycle
          end if
        end if
        if (size(line%fields) >= 2) then
          if (pressure_face(card, line%fields(2)%s) < 0) then
            call diag%report(line%loc, '*' // card%keyword // ': ' // &
                             load_label_message(card, to_upper(line%fields(2)%s)))
            cycle
          end if
        end if
        if (size(line%fields) /= 3) then
          call diag%report(line%loc, '*' // card%keyword // ': expected ' // &
                           trim(merge('surface, P, pressure        ', 'element or set, Pn, pressure', &
                                      card%keyword == 'DSLOAD')))
          cycle
        end if
        if (.not. line_real(line, 3, value, 'pressure', card%keyword, diag)) cycle
        f%pressure = value
        f%amplitude = amplitude
        if (pressure_face(card, line%fields(2)%s) == 0) then
          call put_surface_pressure(card, line, model, state, f, diag)
        else
          call put_element_pressure(card, line, model, state, f, diag)
        end if
      end associate
    end do
  end subroutine handle_dsload

  !> Whether a *DLOAD label is a body load fcs3d applies (GRAV, CENTRIF).
  pure logical function is_body_label(text)
    character(len=*), intent(in) :: text
    is_body_label = to_upper(text) == 'GRAV' .or. to_upper(text) == 'CENTRIF'
  end function is_body_label

  !> *DLOAD body loads, as CalculiX: element or set, GRAV, g, nx, ny, nz (the acceleration
  !> and its direction, normalised here), or element or set, CENTRIF, omega^2, x0, y0, z0,
  !> ax, ay, az (a point of the axis and its direction).
  subroutine put_body_load(card, line, model, state, amplitude, diag)
    type(card_t), intent(in) :: card
    type(data_line_t), intent(in) :: line
    type(model_t), intent(in) :: model
    type(builder_t), intent(inout) :: state
    integer, intent(in) :: amplitude
    type(diagnostics_t), intent(inout) :: diag
    type(body_load_t) :: b
    integer, allocatable :: elements(:)
    real(dp) :: values(7), length
    integer :: j, n_values, n
    n = size(line%fields)
    do while (n > 0)
      if (len(line%fields(n)%s) > 0) exit
      n = n - 1
    end do
    if (to_upper(line%fields(2)%s) == 'GRAV') then
      b%kind = BODY_GRAV
      n_values = 4
    else
      b%kind = BODY_CENTRIF
      n_values = 7
    end if
    if (n /= 2 + n_values) then
      if (b%kind == BODY_GRAV) then
        call diag%report(line%loc, '*DLOAD: expected element or set, GRAV, magnitude, ' // &
                         'direction x, y, z')
      else
        call diag%report(line%loc, '*DLOAD: expected element or set, CENTRIF, omega^2, a ' // &
                         'point of the axis x, y, z, the axis direction x, y, z')
      end if
      return
    end if
    do j = 1, n_values
      if (.not. line_real(line, 2 + j, values(j), 'value', card%keyword, diag)) return
    end do
    b%magnitude = values(1)
    b%vector(1:n_values - 1) = values(2:n_values)
    associate (direction => b%vector(merge(1, 4, b%kind == BODY_GRAV):merge(3, 6, b%kind == BODY_GRAV)))
      length = norm2(direction)
      if (.not. (length > 0.0_dp)) then
        call diag%report(line%loc, '*DLOAD: the ' // trim(merge('direction', 'axis     ', &
                         b%kind == BODY_GRAV)) // ' must not be zero')
        return
      end if
      direction = direction / length
    end associate
    b%amplitude = amplitude
    b%loc = line%loc
    call resolve_elements(model%mesh, line%fields(1)%s, line, card%keyword, diag, elements)
    do j = 1, size(elements)
      b%element = elements(j)
      call state%body_loads%put(b)
    end do
  end subroutine put_body_load

  !> A pressure on every face of an element-face surface (*DSLOAD, label P).
  subroutine put_surface_pressure(card, line, model, state, f, diag)
    type(card_t), intent(in) :: card
    type(data_line_t), intent(in) :: line
    type(model_t), intent(in) :: model
    type(builder_t), intent(inout) :: state
    type(face_load_t), intent(inout) :: f
    type(diagnostics_t), intent(inout) :: diag
    integer :: j, k
    k = model%mesh%find_surface(to_upper(line%fields(1)%s), SURFACE_FACES)
    if (k == 0) then
      call diag%report(line%loc, '*' // card%keyword // ': surface "' // line%fields(1)%s // &
                       '" is not defined')
      return
    end if
    if (model%mesh%surfaces(k)%kind /= SURFACE_FACES) then
      call diag%report(line%loc, '*' // card%keyword // ': surface "' // line%fields(1)%s // &
                       '" is node based; pressure needs an element-face surface')
      return
    end if
    do j = 1, size(model%mesh%surfaces(k)%element)
      f%element = model%mesh%surfaces(k)%element(j)
      f%face = model%mesh%surfaces(k)%face(j)
      call state%pressures%put(f)
    end do
  end subroutine put_surface_pressure

  !> A pressure on face n of an element or of every element of a set (label Pn).
  subroutine put_element_pressure(card, line, model, state, f, diag)
    type(card_t), intent(in) :: card
    type(data_line_t), intent(in) :: line
    type(model_t), intent(in) :: model
    type(builder_t), intent(inout) :: state
    type(face_load_t), intent(inout) :: f
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable :: elements(:)
    integer :: j
    f%face = pressure_face(card, line%fields(2)%s)
    call resolve_elements(model%mesh, line%fields(1)%s, line, card%keyword, diag, elements)
    do j = 1, size(elements)
      f%element = elements(j)
      call state%pressures%put(f)
    end do
  end subroutine put_element_pressure

  !> The face of a pressure label: n for Pn (n = 1..6), 0 for P (*DSLOAD: a surface), -1 for
  !> anything else.
  pure integer function pressure_face(card, text) result(face)
    type(card_t), intent(in) :: card
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: label
    label = to_upper(text)
    face = -1
    if (label == 'P' .and. card%keyword == 'DSLOAD') face = 0
    if (len(label) == 2) then
      if (label(1:1) == 'P' .and. index('123456', label(2:2)) > 0) face = index('123456', label(2:2))
    end if
  end function pressure_face

  !> Why a load label is refused: CalculiX's body loads and user-defined loads are not
  !> available yet; anything else is not a label.
  function load_label_message(card, label) result(text)
    type(card_t), intent(in) :: card
    character(len=*), intent(in) :: label
    character(len=:), allocatable :: text
    character(len=*), parameter :: expected = 'P1..P6 (pressure on face n of an element or ' // &
                                              'element set)'
    select case (label)
    case ('GRAV', 'CENTRIF')
      text = 'load label "' // label // '" (a body load) goes with *DLOAD and an element or ' // &
             'element set'
    case ('NEWTONGRAVITY', 'BX', 'BY', 'BZ', 'BXNU', 'BYNU', 'BZNU', 'EDNOR')
      text = 'load label "' // label // '" (a body load) is not available in fcs3d; ' // &
             'available: ' // expected // ', GRAV, CENTRIF'
    case default
      if (len(label) > 2) then
        if (label(1:1) == 'P' .and. index('123456', label(2:2)) > 0) then
          text = 'load label "' // label // '" (a non-uniform pressure of CalculiX: by user ' // &
                 'subroutine or from nodal values) is not available in fcs3d; available: ' // &
                 expected
          return
        end if
      end if
      text = 'load label "' // label // '" is not valid; expected ' // expected
      if (card%keyword == 'DSLOAD') text = text // ', or P with an element-face surface'
    end select
  end function load_label_message

  !> The AMPLITUDE= parameter resolved to an index (0 if absent). False if undefined.
  !> The amplitude of a load card (0: none). With TIME DELAY=d, a copy of the amplitude
  !> shifted by d (its times + d: a(t - d), constant beyond the ends as every amplitude) is
  !> added to the model once, named "<name> (TIME DELAY=d)", and is the card's amplitude.
  logical function amplitude_param(card, model, diag, amplitude) result(ok)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer, intent(out) :: amplitude
    real(dp) :: delay
    amplitude = 0
    ok = .true.
    if (card%find_param('AMPLITUDE') == 0) then
      if (card%find_param('TIME DELAY') > 0) call diag%report(card%loc, '*' // card%keyword // &
        ': TIME DELAY shifts an amplitude: give AMPLITUDE= too')
      ok = card%find_param('TIME DELAY') == 0
      return
    end if
    amplitude = find_amplitude(model, param_upper(card, 'AMPLITUDE'))
    ok = amplitude > 0
    if (.not. ok) then
      call diag%report(card%loc, '*' // card%keyword // ': amplitude "' // &
                       param_value(card, 'AMPLITUDE') // '" is not defined ' // &
                       '(define it with *AMPLITUDE before it is used)')
      return
    end if
    if (card%find_param('TIME DELAY') == 0) return
    if (model%amplitudes(amplitude)%quadratic) then
      call diag%report(card%loc, '*' // card%keyword // ': TIME DELAY cannot shift the user ' // &
                       'amplitude ' // model%amplitudes(amplitude)%name)
      ok = .false.
      return
    end if
    call parse_real(param_value(card, 'TIME DELAY'), delay, ok)
    if (.not. ok) return ! the keyword table has reported the value
    if (delay /= 0.0_dp) amplitude = delayed_amplitude(model, amplitude, delay)
  end function amplitude_param

  !> Index of amplitude k shifted by `delay` (added to the model the first time).
  integer function delayed_amplitude(model, k, delay) result(index)
    type(model_t), intent(inout) :: model
    integer, intent(in) :: k
    real(dp), intent(in) :: delay
    type(amplitude_t) :: shifted
    character(len=32) :: text
    write (text, '(g0)') delay
    shifted = model%amplitudes(k)
    shifted%name = model%amplitudes(k)%name // ' (TIME DELAY=' // trim(text) // ')'
    shifted%time = model%amplitudes(k)%time + delay
    index = find_amplitude(model, shifted%name)
    if (index > 0) return
    model%amplitudes = [model%amplitudes, shifted]
    index = size(model%amplitudes)
  end function delayed_amplitude

  pure integer function find_amplitude(model, name) result(k)
    type(model_t), intent(in) :: model
    character(len=*), intent(in) :: name
    do k = 1, size(model%amplitudes)
      if (model%amplitudes(k)%name == name) return
    end do
    k = 0
  end function find_amplitude

  pure integer function find_time_points(model, name) result(k)
    type(model_t), intent(in) :: model
    character(len=*), intent(in) :: name
    do k = 1, size(model%time_points)
      if (model%time_points(k)%name == name) return
    end do
    k = 0
  end function find_time_points

  !> *AMPLITUDE: pairs of time, value with increasing times.
  subroutine handle_amplitude(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(amplitude_t) :: a
    real(dp) :: t, v
    integer :: i, j, n
    logical :: ok
    a%name = param_upper(card, 'NAME')
    a%total_time = param_upper(card, 'TIME') == 'TOTAL TIME'
    if (find_amplitude(model, a%name) > 0) then
      call diag%report(card%loc, '*AMPLITUDE: amplitude ' // a%name // ' is defined twice')
      return
    end if
    allocate (a%time(0), a%value(0))
    if (has_flag(card, 'USER')) then
      call user_amplitude(card, a, diag, ok)
      if (ok) model%amplitudes = [model%amplitudes, a]
      return
    end if
    if (card%n_lines == 0) then
      call diag%report(card%loc, '*AMPLITUDE: missing data lines: pairs time, value')
      return
    end if
    ok = .true.
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        n = size(line%fields)
        if (mod(n, 2) /= 0) then
          call diag%report(line%loc, '*AMPLITUDE: expected pairs of time, value')
          ok = .false.
          cycle
        end if
        do j = 1, n, 2
          if (.not. line_real(line, j, t, 'time', 'AMPLITUDE', diag)) ok = .false.
          if (.not. line_real(line, j + 1, v, 'value', 'AMPLITUDE', diag)) ok = .false.
          if (.not. ok) exit
          if (size(a%time) > 0) then
            if (t <= a%time(size(a%time))) then
              call diag%report(line%loc, '*AMPLITUDE: times must increase (' // str(t) // &
                               ' follows ' // str(a%time(size(a%time))) // ')')
              ok = .false.
              exit
            end if
          end if
          a%time = [a%time, t]
          a%value = [a%value, v]
        end do
      end associate
    end do
    if (ok) model%amplitudes = [model%amplitudes, a]
  end subroutine handle_amplitude

  !> *AMPLITUDE, USER: CalculiX calls its subroutine uamplitude, of which it ships one
  !> amplitude, QUADRATIC, a(t) = t^2 (ccx src/uamplitude.f; any other name stops ccx with
  !> "unknown amplitude"). fcs3d loads no user code: QUADRATIC is built in, anything else is
  !> refused.
  subroutine user_amplitude(card, a, diag, ok)
    type(card_t), intent(in) :: card
    type(amplitude_t), intent(inout) :: a
    type(diagnostics_t), intent(inout) :: diag
    logical, intent(out) :: ok
    ok = a%name == 'QUADRATIC'
    if (.not. ok) then
      call diag%report(card%loc, '*AMPLITUDE, USER: user amplitude "' // a%name // '" needs ' // &
        'user code, which fcs3d does not load; only the amplitude CalculiX ships with its ' // &
        'uamplitude.f is built in: NAME=QUADRATIC, a(t) = t^2')
      return
    end if
    ok = card%n_lines == 0
    if (.not. ok) then
      call diag%report(card%lines(1)%loc, '*AMPLITUDE, USER: a user amplitude takes no data lines')
      return
    end if
    a%quadratic = .true.
  end subroutine user_amplitude

  !> *TIME POINTS: increasing times, or start, end, increment with GENERATE.
  subroutine handle_time_points(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(time_points_t) :: tp
    real(dp) :: t, start, finish, increment
    integer :: i, j, n
    tp%name = param_upper(card, 'NAME')
    tp%total_time = param_upper(card, 'TIME') == 'TOTAL TIME'
    if (find_time_points(model, tp%name) > 0) then
      call diag%report(card%loc, '*TIME POINTS: list ' // tp%name // ' is defined twice')
      return
    end if
    allocate (tp%times(0))
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        if (has_flag(card, 'GENERATE')) then
          if (size(line%fields) /= 3) then
            call diag%report(line%loc, '*TIME POINTS, GENERATE: expected start, end, increment')
            return
          end if
          if (.not. line_real(line, 1, start, 'start', 'TIME POINTS', diag)) return
          if (.not. line_real(line, 2, finish, 'end', 'TIME POINTS', diag)) return
          if (.not. line_real(line, 3, increment, 'increment', 'TIME POINTS', diag)) return
          if (increment <= 0.0_dp .or. finish < start .or. (finish - start) / increment > 1.0e7_dp) then
            call diag%report(line%loc, '*TIME POINTS, GENERATE: need start <= end and a ' // &
                             'positive increment giving at most 1e7 points')
            return
          end if
          n = int((finish - start) / increment * (1.0_dp + 1.0e-12_dp))
          tp%times = [tp%times, [(start + j * increment, j = 0, n)]]
        else
          do j = 1, size(line%fields)
            if (len(line%fields(j)%s) == 0) cycle
            if (.not. line_real(line, j, t, 'time', 'TIME POINTS', diag)) return
            tp%times = [tp%times, t]
          end do
        end if
      end associate
    end do
    do i = 2, size(tp%times)
      if (tp%times(i) <= tp%times(i - 1)) then
        call diag%report(card%loc, '*TIME POINTS: times must increase (' // str(tp%times(i)) // &
                         ' follows ' // str(tp%times(i - 1)) // ')')
        return
      end if
    end do
    model%time_points = [model%time_points, tp]
  end subroutine handle_time_points

end module fcs_build_step
