!> Reading values out of validated cards: parameters, numbers in data lines, and node or
!> element targets (an id or a set name). Every problem is reported to the diagnostics with
!> the data line's location.
module fcs_deck_fields
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t, data_line_t
  use fcs_diagnostics, only: diagnostics_t
  use fcs_mesh, only: mesh_t
  use fcs_strings, only: string_t, parse_real, parse_int, to_upper, str
  implicit none
  private
  public :: param_value, param_upper, has_flag, line_real, line_int, line_optional_real
  public :: resolve_nodes, resolve_elements, is_integer_text, element_records

contains

  !> Value of parameter `name` as written ('' if absent; validation has filled in defaults).
  pure function param_value(card, name) result(value)
    type(card_t), intent(in) :: card
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: value
    integer :: k
    k = card%find_param(name)
    value = ''
    if (k > 0) value = card%params(k)%value
  end function param_value

  !> Upper-case value of parameter `name` (names and choices are case-insensitive).
  pure function param_upper(card, name) result(value)
    type(card_t), intent(in) :: card
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: value
    value = to_upper(param_value(card, name))
  end function param_upper

  !> True when the flag parameter `name` is present.
  pure logical function has_flag(card, name)
    type(card_t), intent(in) :: card
    character(len=*), intent(in) :: name
    has_flag = card%find_param(name) > 0
  end function has_flag

  !> Field `i` of `line` as a real; `what` names it in the error message.
  logical function line_real(line, i, value, what, keyword, diag) result(ok)
    type(data_line_t), intent(in) :: line
    integer, intent(in) :: i
    real(dp), intent(out) :: value
    character(len=*), intent(in) :: what, keyword
    type(diagnostics_t), intent(inout) :: diag
    value = 0.0_dp
    ok = .false.
    if (i > size(line%fields)) then
      call diag%report(line%loc, '*' // keyword // ': missing ' // what // ' (field ' // str(i) // ')')
      return
    end if
    call parse_real(line%fields(i)%s, value, ok)
    if (.not. ok) call diag%report(line%loc, '*' // keyword // ': ' // what // ' must be a number, ' // &
                                   'not "' // line%fields(i)%s // '" (field ' // str(i) // ')')
  end function line_real

  !> Field `i` as a real if present and not empty; otherwise `default`.
  logical function line_optional_real(line, i, value, default, what, keyword, diag) result(ok)
    type(data_line_t), intent(in) :: line
    integer, intent(in) :: i
    real(dp), intent(out) :: value
    real(dp), intent(in) :: default
    character(len=*), intent(in) :: what, keyword
    type(diagnostics_t), intent(inout) :: diag
    value = default
    ok = .true.
    if (i > size(line%fields)) return
    if (len(line%fields(i)%s) == 0) return
    ok = line_real(line, i, value, what, keyword, diag)
  end function line_optional_real

  !> Field `i` of `line` as an integer.
  logical function line_int(line, i, value, what, keyword, diag) result(ok)
    type(data_line_t), intent(in) :: line
    integer, intent(in) :: i
    integer, intent(out) :: value
    character(len=*), intent(in) :: what, keyword
    type(diagnostics_t), intent(inout) :: diag
    value = 0
    ok = .false.
    if (i > size(line%fields)) then
      call diag%report(line%loc, '*' // keyword // ': missing ' // what // ' (field ' // str(i) // ')')
      return
    end if
    call parse_int(line%fields(i)%s, value, ok)
    if (.not. ok) call diag%report(line%loc, '*' // keyword // ': ' // what // ' must be a whole ' // &
                                   'number, not "' // line%fields(i)%s // '" (field ' // str(i) // ')')
  end function line_int

  !> The records of an *ELEMENT card whose records have `n_fields` fields (the id and the node
  !> ids): each data line, joined with the lines that follow while it ends with a comma and
  !> its record is unfinished (fewer than `n_fields` fields), as a 20-node element is written
  !> on two lines. A complete line's trailing comma only ends it, as in CalculiX. A record
  !> keeps the first line's location and the joined text; one that stays unfinished or grows
  !> too long is left for the caller to report (by its field count).
  function element_records(card, n_fields) result(records)
    type(card_t), intent(in) :: card
    integer, intent(in) :: n_fields
    type(data_line_t), allocatable :: records(:)
    integer :: i, n
    allocate (records(card%n_lines))
    n = 0
    i = 0
    do while (i < card%n_lines)
      i = i + 1
      n = n + 1
      records(n) = card%lines(i)
      do while (records(n)%continued .and. size(records(n)%fields) < n_fields .and. &
                i < card%n_lines)
        i = i + 1
        records(n)%fields = [records(n)%fields, card%lines(i)%fields]
        records(n)%loc%text = records(n)%loc%text // ' ' // card%lines(i)%loc%text
        records(n)%continued = card%lines(i)%continued
      end do
    end do
    records = records(1:n)
  end function element_records

  !> True when `text` looks like an integer id (digits with an optional sign).
  pure logical function is_integer_text(text)
    character(len=*), intent(in) :: text
    integer :: i, start
    is_integer_text = .false.
    if (len(text) == 0) return
    start = 1
    if (text(1:1) == '-' .or. text(1:1) == '+') start = 2
    if (start > len(text)) return
    do i = start, len(text)
      if (text(i:i) < '0' .or. text(i:i) > '9') return
    end do
    is_integer_text = .true.
  end function is_integer_text

  !> Node indices named by `text`: a node id or a node set name. Reports undefined ones.
  subroutine resolve_nodes(mesh, text, line, keyword, diag, nodes)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: text, keyword
    type(data_line_t), intent(in) :: line
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable, intent(out) :: nodes(:)
    integer :: id, k
    logical :: ok
    allocate (nodes(0))
    if (len(text) == 0) then
      call diag%report(line%loc, '*' // keyword // ': missing node or node set')
    else if (is_integer_text(text)) then
      call parse_int(text, id, ok)
      k = 0
      if (ok) k = mesh%node_index(id)
      if (k == 0) then
        call diag%report(line%loc, '*' // keyword // ': node ' // text // ' is not defined')
      else
        nodes = [k]
      end if
    else
      k = mesh%find_node_set(to_upper(text))
      if (k == 0) then
        call diag%report(line%loc, '*' // keyword // ': node set "' // text // '" is not defined' // &
                         defined_names_hint(mesh, .true.))
      else
        nodes = mesh%node_sets(k)%members
      end if
    end if
  end subroutine resolve_nodes

  !> Element indices named by `text`: an element id or an element set name.
  subroutine resolve_elements(mesh, text, line, keyword, diag, elements)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: text, keyword
    type(data_line_t), intent(in) :: line
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable, intent(out) :: elements(:)
    integer :: id, k
    logical :: ok
    allocate (elements(0))
    if (len(text) == 0) then
      call diag%report(line%loc, '*' // keyword // ': missing element or element set')
    else if (is_integer_text(text)) then
      call parse_int(text, id, ok)
      k = 0
      if (ok) k = mesh%element_index(id)
      if (k == 0) then
        call diag%report(line%loc, '*' // keyword // ': element ' // text // ' is not defined')
      else
        elements = [k]
      end if
    else
      k = mesh%find_element_set(to_upper(text))
      if (k == 0) then
        call diag%report(line%loc, '*' // keyword // ': element set "' // text // &
                         '" is not defined' // defined_names_hint(mesh, .false.))
      else
        elements = mesh%element_sets(k)%members
      end if
    end if
  end subroutine resolve_elements

  !> "; defined: A, B, C" listing up to 8 set names, or '' when there are none.
  function defined_names_hint(mesh, node_sets) result(text)
    type(mesh_t), intent(in) :: mesh
    logical, intent(in) :: node_sets
    character(len=:), allocatable :: text
    integer :: i, n
    text = ''
    if (node_sets) then
      n = size(mesh%node_sets)
    else
      n = size(mesh%element_sets)
    end if
    if (n == 0) return
    text = '; defined sets: '
    do i = 1, min(n, 8)
      if (i > 1) text = text // ', '
      if (node_sets) then
        text = text // mesh%node_sets(i)%name
      else
        text = text // mesh%element_sets(i)%name
      end if
    end do
    if (n > 8) text = text // ', ...'
  end function defined_names_hint

end module fcs_deck_fields
