!> Model builder, output keywords: *NODE PRINT, *EL PRINT, *NODE FILE, *EL FILE.
module fcs_build_output
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t
  use fcs_deck_fields, only: param_upper, param_value
  use fcs_diagnostics, only: diagnostics_t
  use fcs_builder_state, only: builder_t
  use fcs_build_step, only: find_time_points
  use fcs_model, only: history_request_t, history_item_t, HISTORY_NSET_U, HISTORY_NSET_RF, &
                       HISTORY_CONTACT, HISTORY_ENERGY, HISTORY_RESIDUAL
  use fcs_model, only: model_t, output_request_t, OUTPUT_NODE_PRINT, OUTPUT_EL_PRINT, &
                       OUTPUT_NODE_FILE, OUTPUT_EL_FILE, OUTPUT_CONTACT_PRINT, OUTPUT_CONTACT_FILE, &
                       TOTALS_NO, TOTALS_YES, TOTALS_ONLY
  use fcs_strings, only: string_t, to_upper, parse_int, parse_real, join_strings
  use fcs_material_factory, only: PLASTICITY_NONE
  use fcs_hyperelastic, only: HYPER_NONE, hyper_law_text
  implicit none
  private
  public :: handle_output_request, handle_history, handle_event_catalog

contains

  !> Any of the four output keywords: check the set, the variables and the schedule.
  subroutine handle_output_request(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(in) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(output_request_t) :: request
    type(string_t), allocatable :: allowed(:)
    logical :: ok
    select case (card%keyword)
    case ('NODE PRINT')
      request%kind = OUTPUT_NODE_PRINT
      allowed = [string_t('U'), string_t('RF'), string_t('NT')]
      request%set = model%mesh%find_node_set(param_upper(card, 'NSET'))
      request%global = param_upper(card, 'GLOBAL') == 'YES'
      if (request%set == 0) call diag%report(card%loc, '*NODE PRINT: node set "' // &
                                             param_value(card, 'NSET') // '" is not defined')
    case ('EL PRINT')
      request%kind = OUTPUT_EL_PRINT
      request%global = param_upper(card, 'GLOBAL') == 'YES'
      allowed = [string_t('S'), string_t('E'), string_t('PEEQ'), string_t('PE'), &
                 string_t('ENER'), string_t('ELSE')]
      request%set = model%mesh%find_element_set(param_upper(card, 'ELSET'))
      if (request%set == 0) call diag%report(card%loc, '*EL PRINT: element set "' // &
                                             param_value(card, 'ELSET') // '" is not defined')
    case ('NODE FILE')
      request%kind = OUTPUT_NODE_FILE
      allowed = [string_t('U'), string_t('RF'), string_t('NT')]
    case ('CONTACT PRINT', 'CONTACT FILE')
      request%kind = merge(OUTPUT_CONTACT_PRINT, OUTPUT_CONTACT_FILE, card%keyword == 'CONTACT PRINT')
      allowed = [string_t('CDIS'), string_t('CSTR'), string_t('CDISP'), string_t('CSTRESS')]
      if (card%keyword == 'CONTACT PRINT' .and. any(model%contact_pairs%surface_to_surface)) then
        call diag%report(card%loc, '*CONTACT PRINT: not available with a TYPE=SURFACE TO ' // &
          'SURFACE contact pair (its slave entries are integration points of the slave faces, ' // &
          'not nodes, so there is no table by slave node; *CONTACT FILE writes their fields ' // &
          'at the points to the results file)')
        return
      end if
    case default
      request%kind = OUTPUT_EL_FILE
      allowed = [string_t('S'), string_t('E'), string_t('PEEQ'), string_t('PE')]
    end select
    call read_variables(card, allowed, diag, request%variables)
    call check_energy_request(card, model, request, diag)
    call parse_int(param_value(card, 'FREQUENCY'), request%frequency, ok)
    if (request%frequency < 0) call diag%report(card%loc, '*' // card%keyword // &
                                                ': FREQUENCY must not be negative')
    if (card%find_param('TIME POINTS') > 0) then
      request%time_points = find_time_points(model, param_upper(card, 'TIME POINTS'))
      if (request%time_points == 0) call diag%report(card%loc, '*' // card%keyword // &
          ': time points "' // param_value(card, 'TIME POINTS') // '" are not defined ' // &
          '(define them with *TIME POINTS before they are used)')
    end if
    select case (param_upper(card, 'TOTALS'))
    case ('YES')
      request%totals = TOTALS_YES
    case ('ONLY')
      request%totals = TOTALS_ONLY
    case default
      request%totals = TOTALS_NO
    end select
    call warn_output_params(card, diag)
    if (.not. allocated(state%step%outputs)) allocate (state%step%outputs(0))
    ! CDIS and CSTR have no totals: TOTALS=ONLY prints nothing, as in CalculiX.
    if (request%kind == OUTPUT_CONTACT_PRINT .and. request%totals == TOTALS_ONLY) return
    state%step%outputs = [state%step%outputs, request]
  end subroutine handle_output_request

  !> Warnings for output parameters that fcs3d accepts but that do not do here what they say:
  !> TOTALS of variables without totals, NSET of results frames (which hold every node),
  !> OUTPUT=2D (shell and beam output; fcs3d's solids are written in 3D).
  subroutine warn_output_params(card, diag)
    type(card_t), intent(in) :: card
    type(diagnostics_t), intent(inout) :: diag
    character(len=:), allocatable :: totals
    totals = param_upper(card, 'TOTALS')
    if (card%keyword == 'EL PRINT' .and. totals /= 'NO' .and. len(totals) > 0) &
      call diag%warn(card%loc, '*EL PRINT: TOTALS=' // totals // ': S, E and PE have no ' // &
        'totals (CalculiX sums whole-element variables such as ELSE and EVOL only, which ' // &
        'fcs3d does not compute); the tables are printed as without TOTALS, as CalculiX ' // &
        'prints them')
    if (card%keyword == 'CONTACT PRINT' .and. totals == 'YES') call diag%warn(card%loc, &
      '*CONTACT PRINT: TOTALS=YES: CDIS and CSTR have no totals (CalculiX sums contact ' // &
      'energies only); the tables are printed as without TOTALS, as CalculiX prints them')
    if (card%keyword == 'CONTACT PRINT' .and. totals == 'ONLY') call diag%warn(card%loc, &
      '*CONTACT PRINT: TOTALS=ONLY: CDIS and CSTR have no totals (CalculiX sums contact ' // &
      'energies only); this request prints nothing, as in CalculiX')
    if (card%find_param('NSET') > 0 .and. (card%keyword == 'NODE FILE' .or. &
        card%keyword == 'CONTACT FILE')) call diag%warn(card%loc, '*' // card%keyword // &
      ': NSET=' // param_value(card, 'NSET') // ' does not restrict the results: every ' // &
      'frame of <job>.h5 holds every node')
    if (param_upper(card, 'OUTPUT') == '2D') call diag%warn(card%loc, '*' // card%keyword // &
      ': OUTPUT=2D is for CalculiX''s expanded shell and beam elements; fcs3d''s solid ' // &
      'elements are written in 3D')
  end subroutine warn_output_params

  !> The variable names on the data lines, each checked against `allowed`.
  !> ENER and ELSE print the elastic energy 1/2 S:(E - E_th) (fcs_dat_output): with a plastic
  !> material that is not the internal energy CalculiX prints, so they are refused there; with a
  !> hyperelastic one (*HYPERELASTIC, *HYPERFOAM, *DEFORMATION PLASTICITY) it is not U either:
  !> refused too.
  subroutine check_energy_request(card, model, request, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(in) :: model
    type(output_request_t), intent(in) :: request
    type(diagnostics_t), intent(inout) :: diag
    integer :: v, k
    do v = 1, size(request%variables)
      if (request%variables(v)%s /= 'ENER' .and. request%variables(v)%s /= 'ELSE') cycle
      if (.not. allocated(model%materials)) return
      do k = 1, size(model%materials)
        if (model%materials(k)%plastic%model /= PLASTICITY_NONE) then
          call diag%report(card%loc, '*' // card%keyword // ': ' // request%variables(v)%s // &
            ' (internal energy) is available for elastic materials only (fcs3d prints 1/2 S:E); ' // &
            'material ' // model%materials(k)%name // ' is plastic')
          return
        end if
        if (model%materials(k)%hyperelastic%family /= HYPER_NONE) then
          call diag%report(card%loc, '*' // card%keyword // ': ' // request%variables(v)%s // &
            ' (internal energy) is not available for hyperelastic materials and *DEFORMATION ' // &
            'PLASTICITY (fcs3d prints 1/2 S:E, not the strain energy U); material ' // &
            model%materials(k)%name // ' is ' // hyper_law_text(model%materials(k)%hyperelastic%family))
          return
        end if
      end do
    end do
  end subroutine check_energy_request

  subroutine read_variables(card, allowed, diag, variables)
    type(card_t), intent(in) :: card
    type(string_t), intent(in) :: allowed(:)
    type(diagnostics_t), intent(inout) :: diag
    type(string_t), allocatable, intent(out) :: variables(:)
    integer :: i, f, k
    character(len=:), allocatable :: name
    logical :: known
    allocate (variables(0))
    do i = 1, card%n_lines
      do f = 1, size(card%lines(i)%fields)
        name = to_upper(card%lines(i)%fields(f)%s)
        if (len(name) == 0) cycle
        known = .false.
        do k = 1, size(allowed)
          if (allowed(k)%s == name) known = .true.
        end do
        if (.not. known) then
          call diag%report(card%lines(i)%loc, '*' // card%keyword // ': output variable "' // &
                           card%lines(i)%fields(f)%s // '" is not available; expected ' // &
                           join_strings(allowed, ', '))
          cycle
        end if
        if (name == 'CDISP') name = 'CDIS'
        if (name == 'CSTRESS') name = 'CSTR'
        variables = [variables, string_t(name)]
      end do
    end do
  end subroutine read_variables

  !> *HISTORY, NAME=: the quantities to sample.
  subroutine handle_history(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(history_request_t) :: history
    type(history_item_t) :: item
    character(len=:), allocatable :: what
    logical :: ok
    integer :: i, k
    history%name = param_upper(card, 'NAME')
    do k = 1, size(model%histories)
      if (model%histories(k)%name == history%name) then
        call diag%report(card%loc, '*HISTORY: history ' // history%name // ' is defined twice')
        return
      end if
    end do
    call parse_int(param_value(card, 'FREQUENCY'), history%frequency, ok)
    if (history%frequency < 0) call diag%report(card%loc, '*HISTORY: FREQUENCY must not be negative')
    if (card%find_param('TIME POINTS') > 0) then
      history%time_points = find_time_points(model, param_upper(card, 'TIME POINTS'))
      if (history%time_points == 0) call diag%report(card%loc, '*HISTORY: time points "' // &
        param_value(card, 'TIME POINTS') // '" are not defined (define them with *TIME POINTS first)')
    end if
    allocate (history%items(0))
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        what = to_upper(line%fields(1)%s)
        item%target = 0
        select case (what)
        case ('NSET')
          if (size(line%fields) /= 3) then
            call diag%report(line%loc, '*HISTORY: expected NSET, <node set>, U or RF')
            cycle
          end if
          item%target = model%mesh%find_node_set(to_upper(line%fields(2)%s))
          if (item%target == 0) then
            call diag%report(line%loc, '*HISTORY: node set "' // line%fields(2)%s // '" is not defined')
            cycle
          end if
          select case (to_upper(line%fields(3)%s))
          case ('U')
            item%kind = HISTORY_NSET_U
          case ('RF')
            item%kind = HISTORY_NSET_RF
          case default
            call diag%report(line%loc, '*HISTORY: node set quantity "' // line%fields(3)%s // &
                             '" is not available; expected U or RF')
            cycle
          end select
        case ('CONTACT')
          item%kind = HISTORY_CONTACT
          if (size(line%fields) == 2) item%target = find_pair(model, to_upper(line%fields(2)%s))
          if (item%target == 0) then
            call diag%report(line%loc, '*HISTORY: expected CONTACT, <contact pair or tie name> ' // &
                             '(a name given by NAME= on *CONTACT PAIR or *TIE, or slave-master)')
            cycle
          end if
        case ('ENERGY')
          item%kind = HISTORY_ENERGY
        case ('RESIDUAL')
          item%kind = HISTORY_RESIDUAL
        case default
          call diag%report(line%loc, '*HISTORY: unknown quantity "' // line%fields(1)%s // &
                           '"; expected NSET, CONTACT, ENERGY or RESIDUAL')
          cycle
        end select
        history%items = [history%items, item]
      end associate
    end do
    model%histories = [model%histories, history]
  end subroutine handle_history

  pure integer function find_pair(model, name) result(k)
    type(model_t), intent(in) :: model
    character(len=*), intent(in) :: name
    do k = 1, size(model%contact_pairs)
      if (model%contact_pairs(k)%name == name) return
    end do
    k = 0
  end function find_pair

  !> *EVENT CATALOG, SLIP RATE=, MIN SLIP=.
  subroutine handle_event_catalog(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    logical :: ok
    call parse_real(param_value(card, 'SLIP RATE'), model%event_threshold, ok)
    call parse_real(param_value(card, 'MIN SLIP'), model%event_min_slip, ok)
    if (model%event_threshold <= 0.0_dp) call diag%report(card%loc, '*EVENT CATALOG: SLIP RATE ' // &
                                                          'must be positive')
    if (model%event_min_slip < 0.0_dp) call diag%report(card%loc, '*EVENT CATALOG: MIN SLIP must ' // &
                                                        'not be negative')
  end subroutine handle_event_catalog

end module fcs_build_output
