!> Model builder, output keywords: *NODE PRINT, *EL PRINT, *NODE FILE, *EL FILE.
module fcs_build_output
  use fcs_deck_lexer, only: card_t
  use fcs_deck_fields, only: param_upper, param_value
  use fcs_diagnostics, only: diagnostics_t
  use fcs_builder_state, only: builder_t
  use fcs_build_step, only: find_time_points
  use fcs_model, only: model_t, output_request_t, OUTPUT_NODE_PRINT, OUTPUT_EL_PRINT, &
                       OUTPUT_NODE_FILE, OUTPUT_EL_FILE, OUTPUT_CONTACT_PRINT, OUTPUT_CONTACT_FILE, &
                       TOTALS_NO, TOTALS_YES, TOTALS_ONLY
  use fcs_strings, only: string_t, to_upper, parse_int, join_strings
  implicit none
  private
  public :: handle_output_request

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
      allowed = [string_t('U'), string_t('RF')]
      request%set = model%mesh%find_node_set(param_upper(card, 'NSET'))
      if (request%set == 0) call diag%report(card%loc, '*NODE PRINT: node set "' // &
                                             param_value(card, 'NSET') // '" is not defined')
    case ('EL PRINT')
      request%kind = OUTPUT_EL_PRINT
      allowed = [string_t('S'), string_t('E')]
      request%set = model%mesh%find_element_set(param_upper(card, 'ELSET'))
      if (request%set == 0) call diag%report(card%loc, '*EL PRINT: element set "' // &
                                             param_value(card, 'ELSET') // '" is not defined')
    case ('NODE FILE')
      request%kind = OUTPUT_NODE_FILE
      allowed = [string_t('U'), string_t('RF')]
    case ('CONTACT PRINT', 'CONTACT FILE')
      request%kind = merge(OUTPUT_CONTACT_PRINT, OUTPUT_CONTACT_FILE, card%keyword == 'CONTACT PRINT')
      allowed = [string_t('CDIS'), string_t('CSTR'), string_t('CDISP'), string_t('CSTRESS')]
    case default
      request%kind = OUTPUT_EL_FILE
      allowed = [string_t('S'), string_t('E')]
    end select
    call read_variables(card, allowed, diag, request%variables)
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
    if (.not. allocated(state%step%outputs)) allocate (state%step%outputs(0))
    state%step%outputs = [state%step%outputs, request]
  end subroutine handle_output_request

  !> The variable names on the data lines, each checked against `allowed`.
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

end module fcs_build_output
