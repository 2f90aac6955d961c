!> Model builder, mesh keywords: *NODE, *ELEMENT, *NSET, *ELSET, *SURFACE, *MESH.
module fcs_build_mesh
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_deck_lexer, only: card_t, data_line_t
  use fcs_deck_fields, only: param_upper, param_value, has_flag, line_real, line_int, &
                             line_optional_real, resolve_nodes, resolve_elements, is_integer_text, &
                             element_records
  use fcs_diagnostics, only: diagnostics_t, format_location
  use fcs_mesh, only: mesh_t, SURFACE_FACES
  use fcs_gmsh_reader, only: read_gmsh
  use fcs_model_checks, only: check_mesh_file_orientation
  use fcs_model, only: model_t
  use fcs_strings, only: to_upper, str, dirname, join_path, parse_int
  implicit none
  private
  public :: handle_node, handle_element, handle_nset, handle_elset, handle_surface, handle_mesh

  !> Largest count of ids one GENERATE line may produce (guards against typos like 1, 1e9).
  integer, parameter :: MAX_GENERATED = 50000000

contains

  !> *NODE: id, x, y, z. Further fields are ignored, as CalculiX ignores them (one warning
  !> per card names the first such line and counts them).
  subroutine handle_node(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: i, id, n_added, c, n_long, first_long
    integer, allocatable :: added(:)
    real(dp) :: x(3)
    logical :: ok, duplicate
    allocate (added(card%n_lines))
    n_added = 0
    n_long = 0
    first_long = 0
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        if (size(line%fields) > 4) then
          n_long = n_long + 1
          if (first_long == 0) first_long = i
        end if
        if (.not. line_int(line, 1, id, 'node id', 'NODE', diag)) cycle
        if (id <= 0) then
          call diag%report(line%loc, '*NODE: node ids must be positive, not ' // str(id))
          cycle
        end if
        ok = .true.
        do c = 1, 3
          if (.not. line_optional_real(line, c + 1, x(c), 0.0_dp, 'coordinate ' // &
                                       achar(iachar('x') + c - 1), 'NODE', diag)) ok = .false.
        end do
        if (.not. ok) cycle
        call model%mesh%add_node(id, x, duplicate)
        if (duplicate) then
          call diag%report(line%loc, '*NODE: node ' // str(id) // ' is defined twice')
          cycle
        end if
        n_added = n_added + 1
        added(n_added) = model%mesh%n_nodes
      end associate
      if (diag%is_full()) return
    end do
    if (card%find_param('NSET') > 0) call model%mesh%add_to_node_set(param_upper(card, 'NSET'), &
                                                                      added(1:n_added))
    if (n_long > 0) call diag%warn(card%lines(first_long)%loc, '*NODE: ' // str(n_long) // &
      ' line(s) of this card have fields after id, x, y, z (the first is this one); they ' // &
      'are ignored, as CalculiX ignores them')
  end subroutine handle_node

  !> *ELEMENT, TYPE=kind: id, then the kind's node ids (CalculiX order); a record continues on
  !> the next line after a trailing comma (C3D20: 15 + 5 node ids, as CalculiX writes them).
  !> Ids beyond the kind's count are ignored with one warning per card, as CalculiX ignores
  !> them.
  subroutine handle_element(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer :: i, a, b, id, node_id, n_added, kind, n, n_long, first_long
    integer, allocatable :: nodes(:), added(:)
    type(data_line_t), allocatable :: records(:)
    character(len=:), allocatable :: type_name, needs
    logical :: ok, duplicate
    n_long = 0
    first_long = 0
    type_name = param_upper(card, 'TYPE')
    kind = model%mesh%find_kind(type_name)
    if (kind == 0) return ! the keyword table has refused the TYPE already
    n = model%mesh%kinds(kind)%n_nodes
    allocate (nodes(n))
    needs = '*ELEMENT: a ' // type_name // ' element needs its id and ' // str(n) // ' node ids; '
    records = element_records(card, n + 1)
    allocate (added(size(records)))
    n_added = 0
    do i = 1, size(records)
      associate (line => records(i))
        if (size(line%fields) < n + 1 .and. .not. line%continued) then
          call diag%report(line%loc, needs // 'found ' // str(size(line%fields)) // &
                           ' fields (a record continues on the next line only after a ' // &
                           'trailing comma)')
          cycle
        else if (size(line%fields) < n + 1) then
          call diag%report(line%loc, needs // 'found ' // str(size(line%fields)) // ' fields')
          cycle
        else if (size(line%fields) > n + 1) then
          ! CalculiX reads the first n node ids of a record and ignores the rest (elements.f):
          ! decks written with its 11-node expansion of C3D8I carry extra ids.
          n_long = n_long + 1
          if (n_long == 1) first_long = i
        end if
        if (.not. line_int(line, 1, id, 'element id', 'ELEMENT', diag)) cycle
        if (id <= 0) then
          call diag%report(line%loc, '*ELEMENT: element ids must be positive, not ' // str(id))
          cycle
        end if
        ok = .true.
        do a = 1, n
          if (.not. line_int(line, a + 1, node_id, 'node id', 'ELEMENT', diag)) then
            ok = .false.
            exit
          end if
          nodes(a) = model%mesh%node_index(node_id)
          if (nodes(a) == 0) then
            call diag%report(line%loc, '*ELEMENT: element ' // str(id) // ' refers to node ' // &
                             str(node_id) // ', which is not defined (define nodes before ' // &
                             'the elements that use them)')
            ok = .false.
            exit
          end if
        end do
        if (.not. ok) cycle
        do a = 1, n - 1
          do b = a + 1, n
            if (nodes(a) == nodes(b)) ok = .false.
          end do
        end do
        if (.not. ok) then
          call diag%report(line%loc, '*ELEMENT: element ' // str(id) // ' uses a node twice ' // &
                           '(degenerate (collapsed) elements are not supported; use the ' // &
                           'tetrahedron or wedge kind instead)')
          cycle
        end if
        call model%mesh%add_element(id, nodes, duplicate, kind)
        if (duplicate) then
          call diag%report(line%loc, '*ELEMENT: element ' // str(id) // ' is defined twice')
          cycle
        end if
        n_added = n_added + 1
        added(n_added) = model%mesh%n_elements
      end associate
      if (diag%is_full()) return
    end do
    if (card%find_param('ELSET') > 0) &
      call model%mesh%add_to_element_set(param_upper(card, 'ELSET'), added(1:n_added))
    if (n_long > 0) call diag%warn(records(first_long)%loc, '*ELEMENT: ' // str(n_long) // &
      ' record(s) of this card have more than the id and ' // str(n) // ' node ids of a ' // &
      type_name // ' (the first is this one); the ids after the ' // str(n) // &
      'th are ignored, as CalculiX ignores them')
  end subroutine handle_element

  !> *NSET: node ids, node set names, or GENERATE ranges.
  subroutine handle_nset(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable :: members(:)
    call collect_members(card, model%mesh, .true., diag, members)
    call model%mesh%add_to_node_set(param_upper(card, 'NSET'), members)
  end subroutine handle_nset

  !> *ELSET: element ids, element set names, or GENERATE ranges.
  subroutine handle_elset(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable :: members(:)
    call collect_members(card, model%mesh, .false., diag, members)
    call model%mesh%add_to_element_set(param_upper(card, 'ELSET'), members)
  end subroutine handle_elset

  !> Members of a *NSET or *ELSET card, as indices. Ids that name no node (element) are
  !> skipped with a warning per data line, as CalculiX skips them; an undefined set name is
  !> an error.
  subroutine collect_members(card, mesh, nodes, diag, members)
    type(card_t), intent(in) :: card
    type(mesh_t), intent(in) :: mesh
    logical, intent(in) :: nodes
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable, intent(out) :: members(:)
    integer, allocatable :: found(:)
    character(len=:), allocatable :: keyword
    integer :: i, f, id, k, undefined(5), n_undefined
    logical :: ok
    keyword = merge('NSET ', 'ELSET', nodes)
    keyword = trim(keyword)
    allocate (members(0))
    do i = 1, card%n_lines
      if (has_flag(card, 'GENERATE')) then
        call generate_range(card%lines(i), mesh, nodes, keyword, diag, found)
        members = [members, found]
        cycle
      end if
      n_undefined = 0
      do f = 1, size(card%lines(i)%fields)
        associate (text => card%lines(i)%fields(f)%s)
          if (len(text) == 0) cycle
          if (is_integer_text(text)) then
            call parse_int(text, id, ok)
            k = 0
            if (ok) k = merge(mesh%node_index(id), mesh%element_index(id), nodes)
            if (k == 0) then
              call note_undefined(id, undefined, n_undefined)
            else
              members = [members, k]
            end if
          else if (nodes) then
            call resolve_nodes(mesh, text, card%lines(i), keyword, diag, found)
            members = [members, found]
          else
            call resolve_elements(mesh, text, card%lines(i), keyword, diag, found)
            members = [members, found]
          end if
        end associate
      end do
      if (n_undefined > 0) call diag%warn(card%lines(i)%loc, '*' // keyword // ': ' // &
        trim(merge('node(s)   ', 'element(s)', nodes)) // ' ' // id_list(undefined, n_undefined) // &
        ' not defined; skipped, as CalculiX skips them')
      if (diag%is_full()) return
    end do
  end subroutine collect_members

  !> Remember an undefined id: the first five, and how many.
  pure subroutine note_undefined(id, first, n)
    integer, intent(in) :: id
    integer, intent(inout) :: first(:), n
    n = n + 1
    if (n <= size(first)) first(n) = id
  end subroutine note_undefined

  !> "3, 7, 12" from the first ids of `n`; "3, 7, 12, 15, 20, ... (9 in all)" beyond five.
  function id_list(first, n) result(text)
    integer, intent(in) :: first(:), n
    character(len=:), allocatable :: text
    integer :: i
    text = ''
    do i = 1, min(n, size(first))
      if (i > 1) text = text // ', '
      text = text // str(first(i))
    end do
    if (n > size(first)) text = text // ', ... (' // str(n) // ' in all)'
  end function id_list

  !> One GENERATE line: first, last[, increment]. Ids in the range that name no node
  !> (element) are skipped with a warning, as CalculiX skips them.
  subroutine generate_range(line, mesh, nodes, keyword, diag, found)
    use fcs_deck_lexer, only: data_line_t
    type(data_line_t), intent(in) :: line
    type(mesh_t), intent(in) :: mesh
    logical, intent(in) :: nodes
    character(len=*), intent(in) :: keyword
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable, intent(out) :: found(:)
    integer :: first, last, step, id, n, k, undefined(5), n_undefined
    allocate (found(0))
    if (size(line%fields) < 2 .or. size(line%fields) > 3) then
      call diag%report(line%loc, '*' // keyword // ', GENERATE: expected first, last[, increment]')
      return
    end if
    if (.not. line_int(line, 1, first, 'first id', keyword, diag)) return
    if (.not. line_int(line, 2, last, 'last id', keyword, diag)) return
    step = 1
    if (size(line%fields) == 3) then
      if (len(line%fields(3)%s) > 0) then
        if (.not. line_int(line, 3, step, 'increment', keyword, diag)) return
      end if
    end if
    if (step <= 0 .or. last < first) then
      call diag%report(line%loc, '*' // keyword // ', GENERATE: need first <= last and a ' // &
                       'positive increment')
      return
    end if
    if ((int(last, 8) - first) / step + 1 > MAX_GENERATED) then
      call diag%report(line%loc, '*' // keyword // ', GENERATE: range too long (more than ' // &
                       str(MAX_GENERATED) // ' ids)')
      return
    end if
    deallocate (found)
    allocate (found((last - first) / step + 1))
    n = 0
    n_undefined = 0
    do id = first, last, step
      if (nodes) then
        k = mesh%node_index(id)
      else
        k = mesh%element_index(id)
      end if
      if (k == 0) then
        call note_undefined(id, undefined, n_undefined)
        cycle
      end if
      n = n + 1
      found(n) = k
    end do
    found = found(1:n)
    if (n_undefined > 0) call diag%warn(line%loc, '*' // keyword // ', GENERATE: ' // &
      str(n_undefined) // ' id(s) of the range name no ' // &
      trim(merge('node   ', 'element', nodes)) // ' (' // id_list(undefined, n_undefined) // &
      '); skipped, as CalculiX skips them')
  end subroutine generate_range

  !> *SURFACE: element faces (element or set, S1..S6) or nodes (TYPE=NODE).
  subroutine handle_surface(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    character(len=:), allocatable :: name, label
    integer, allocatable :: found(:)
    integer :: i, face
    real(dp) :: weight
    name = param_upper(card, 'NAME')
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        if (param_upper(card, 'TYPE') == 'NODE') then
          if (size(line%fields) > 2) then
            call diag%report(line%loc, '*SURFACE, TYPE=NODE: expected node or node set[, weight]')
            cycle
          end if
          if (.not. line_optional_real(line, 2, weight, 1.0_dp, 'weight', 'SURFACE', diag)) cycle
          if (weight /= 1.0_dp) then
            call diag%report(line%loc, '*SURFACE, TYPE=NODE: node weights are not supported ' // &
                             '(leave the second field empty or 1)')
            cycle
          end if
          call resolve_nodes(model%mesh, line%fields(1)%s, line, 'SURFACE', diag, found)
          call model%mesh%add_nodes_to_surface(name, found)
        else
          if (size(line%fields) /= 2) then
            call diag%report(line%loc, '*SURFACE: expected element or element set, face ' // &
                             'label S1..S6')
            cycle
          end if
          label = to_upper(line%fields(2)%s)
          face = 0
          if (len(label) == 2) then
            if (label(1:1) == 'S') face = index('123456', label(2:2))
          end if
          if (face == 0) then
            call diag%report(line%loc, '*SURFACE: face label "' // line%fields(2)%s // &
                             '" is not one of S1 ... S6 (S1-S4 on tetrahedra, S1-S5 on wedges, ' // &
                             'S1-S6 on hexahedra)')
            cycle
          end if
          call resolve_elements(model%mesh, line%fields(1)%s, line, 'SURFACE', diag, found)
          if (.not. faces_exist(model, found, face, line, diag)) cycle
          call model%mesh%add_faces_to_surface(name, found, spread(face, 1, size(found)))
        end if
      end associate
    end do
  end subroutine handle_surface

  !> Every element of `elements` has a face `face` (a tetrahedron has S1-S4, a wedge S1-S5);
  !> otherwise an error naming the first that has not.
  logical function faces_exist(model, elements, face, line, diag) result(ok)
    type(model_t), intent(in) :: model
    integer, intent(in) :: elements(:), face
    type(data_line_t), intent(in) :: line
    type(diagnostics_t), intent(inout) :: diag
    integer :: i
    ok = .true.
    do i = 1, size(elements)
      if (face <= model%mesh%n_faces(elements(i))) cycle
      ok = .false.
      associate (kind => model%mesh%kinds(model%mesh%element_kind(elements(i))))
        call diag%report(line%loc, '*SURFACE: element ' // str(model%mesh%element_id(elements(i))) // &
          ' (' // kind%name // ') has faces S1-S' // str(kind%n_faces) // ', not S' // str(face))
      end associate
      return
    end do
  end function faces_exist

  !> *MESH, FILE=x.msh[, HEX8=kind][, HEX20=kind]: read a gmsh mesh into the model, its 8- and
  !> 20-node hexahedra as the kinds named (default C3D8 and C3D20: the first catalogue kind of
  !> their gmsh type; the other gmsh types have one kind each).
  subroutine handle_mesh(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(error_t), allocatable :: err
    character(len=:), allocatable :: path
    integer, allocatable :: lines(:), kinds(:)
    integer :: first
    call chosen_kinds(card, model, diag, kinds)
    if (.not. allocated(kinds)) return
    path = join_path(dirname(card%loc%file), param_value(card, 'FILE'))
    first = model%mesh%n_elements + 1
    call read_gmsh(path, model%mesh, err, lines, kinds)
    if (.not. allocated(err)) call check_mesh_file_orientation(path, model, first, lines, err)
    if (allocated(err)) call diag%report(card%loc, '*MESH: ' // err%message)
  end subroutine handle_mesh

  !> The mesh kinds *MESH's HEX8= and HEX20= name (unallocated if a name is not a kind: the
  !> keyword table has reported it).
  subroutine chosen_kinds(card, model, diag, kinds)
    type(card_t), intent(in) :: card
    type(model_t), intent(in) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable, intent(out) :: kinds(:)
    character(len=*), parameter :: NAMES(2) = ['HEX8 ', 'HEX20']
    character(len=:), allocatable :: type_name
    integer :: i, kind
    integer :: found(size(NAMES)), n
    n = 0
    do i = 1, size(NAMES)
      if (card%find_param(trim(NAMES(i))) == 0) cycle
      type_name = param_upper(card, trim(NAMES(i)))
      kind = model%mesh%find_kind(type_name)
      if (kind == 0) return ! the keyword table has refused the value already
      n = n + 1
      found(n) = kind
    end do
    kinds = found(1:n)
  end subroutine chosen_kinds

end module fcs_build_mesh
