!> Handlers of *COUPLING and the card that must follow it, *KINEMATIC or *DISTRIBUTING
!> (ccx 2.20 manual, *COUPLING, *KINEMATIC, *DISTRIBUTING and the theory section "Kinematic
!> and Distributing Coupling"; learnt from ccx's couplings.f):
!>
!> * *KINEMATIC: the nodes of the surface follow, in the directions given (1-3), the rigid
!>   motion of the reference node. As in CalculiX, a rotation node is generated (the node
!>   after the largest number defined so far, at the reference node) whose three degrees of
!>   freedom are the rotation of the reference node, radians, and the rigid-body equations of
!>   *RIGID BODY are written for every surface node and direction (fcs_build_constraints,
!>   `rigid_equations`: linearised without NLGEOM, CalculiX's finite rotation (N3) with it).
!>   CalculiX connects the reference node's own rotational degrees of freedom 4-6 to the
!>   rotation node; fcs3d's nodes have three, so *BOUNDARY and *CLOAD on the rotation go to
!>   the generated node (its number is printed as a warning).
!> * *DISTRIBUTING: the translation of the reference node is the mean of the surface nodes'
!>   translations weighted by their nodal areas a_j = int N_j dA (CalculiX's weights):
!>       u_ref,i - sum_j (a_j / A) u_j,i = 0,   A = sum_j a_j,   i = 1, 2, 3         (C1)
!>   one linear equation per direction whose dependent term is the reference node's (ccx
!>   writes the same constraint through duplicated nodes and makes the surface nodes
!>   dependent; the solution is the same). A force F on the reference node is then spread
!>   as (a_j / A) F over the surface (T^T f, doc/theory.md (L2)). Rotations (4-6) are
!>   refused.
module fcs_build_coupling
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t, data_line_t
  use fcs_diagnostics, only: diagnostics_t
  use fcs_deck_fields, only: line_int, param_value
  use fcs_model, only: model_t
  use fcs_builder_state, only: builder_t
  use fcs_mesh, only: SURFACE_FACES
  use fcs_element_kernels, only: element_face_pressure
  use fcs_linear_constraints, only: constraint_term_t, linear_equation_t
  use fcs_build_constraints, only: rigid_equations, unique
  use fcs_strings, only: str, to_upper, parse_int
  implicit none
  private
  public :: handle_coupling, handle_kinematic, handle_distributing

contains

  !> *COUPLING, REF NODE=, SURFACE=, CONSTRAINT NAME= (ORIENTATION= refused): kept in the
  !> builder's state for the *KINEMATIC or *DISTRIBUTING card that must follow.
  subroutine handle_coupling(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(in) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    integer :: id, ref, surface
    logical :: ok
    state%coupling_ref = 0
    if (len(param_value(card, 'ORIENTATION')) > 0) then
      call diag%report(card%loc, '*COUPLING: ORIENTATION= (degrees of freedom in local axes) ' // &
        'is not available in fcs3d; the coupled directions are the global ones')
      return
    end if
    call parse_int(param_value(card, 'REF NODE'), id, ok)
    ref = 0
    if (ok) ref = model%mesh%node_index(id)
    if (ref == 0) then
      call diag%report(card%loc, '*COUPLING: REF NODE ' // param_value(card, 'REF NODE') // &
                       ' is not a defined node (define it by *NODE before the *COUPLING card)')
      return
    end if
    surface = model%mesh%find_surface(to_upper(param_value(card, 'SURFACE')), SURFACE_FACES)
    if (surface == 0) then
      call diag%report(card%loc, '*COUPLING: surface "' // param_value(card, 'SURFACE') // &
                       '" is not defined (define it by *SURFACE before the *COUPLING card)')
      return
    end if
    state%coupling_ref = ref
    state%coupling_surface = surface
    state%coupling_name = param_value(card, 'CONSTRAINT NAME')
    state%coupling_loc = card%loc
  end subroutine handle_coupling

  !> *KINEMATIC: data lines first[, last] direction (1..3): the rigid-body equations of the
  !> surface's nodes in those directions (module header).
  subroutine handle_kinematic(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable :: members(:)
    integer :: i, first, last, ref, rot, rot_id
    logical :: duplicate
    if (.not. follows_coupling(card, state, diag)) return
    ref = state%coupling_ref
    state%coupling_ref = 0
    members = surface_nodes(model, state%coupling_surface)
    members = pack(members, members /= ref)
    if (size(members) == 0) then
      call diag%report(card%loc, '*KINEMATIC: the surface of *COUPLING "' // &
                       state%coupling_name // '" holds no node besides the reference node')
      return
    end if
    ! The rotation node, as CalculiX generates it: the next node number, at the reference node.
    rot_id = maxval(model%mesh%node_id(1:model%mesh%n_nodes)) + 1
    call model%mesh%add_node(rot_id, model%mesh%x(:, ref), duplicate)
    rot = model%mesh%node_index(rot_id)
    model%rotation_nodes = [model%rotation_nodes, rot]
    if (.not. allocated(state%coupling_refs)) allocate (state%coupling_refs(0), state%coupling_rots(0))
    state%coupling_refs = [state%coupling_refs, ref]
    state%coupling_rots = [state%coupling_rots, rot]
    call diag%warn(card%loc, '*KINEMATIC: node ' // str(rot_id) // ' is generated as the ' // &
      'rotation node of *COUPLING "' // state%coupling_name // '" (its degrees of freedom 1-3 ' // &
      'are the rotation of reference node ' // str(model%mesh%node_id(ref)) // ', radians: ' // &
      'CalculiX''s degrees of freedom 4-6 of the reference node)')
    do i = 1, card%n_lines
      if (.not. dof_range(card%lines(i), 'KINEMATIC', 3, first, last, diag)) cycle
      call rigid_equations(model, members, ref, rot, first, last, card%lines(i)%loc, &
                           '*KINEMATIC')
    end do
  end subroutine handle_kinematic

  !> *DISTRIBUTING: data lines first[, last] (1..3; rotations 4-6 refused): the equations
  !> (C1), written once for the three directions (CalculiX couples all three translations
  !> whatever the lines say).
  subroutine handle_distributing(card, model, state, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(builder_t), intent(inout) :: state
    type(diagnostics_t), intent(inout) :: diag
    type(linear_equation_t) :: equation
    integer, allocatable :: nodes(:)
    real(dp), allocatable :: area(:)
    integer :: i, j, first, last, ref
    logical :: ok
    if (.not. follows_coupling(card, state, diag)) return
    ref = state%coupling_ref
    state%coupling_ref = 0
    ok = .true.
    do i = 1, card%n_lines
      if (.not. dof_range(card%lines(i), 'DISTRIBUTING', 6, first, last, diag)) then
        ok = .false.
        cycle
      end if
      if (last > 3) then
        call diag%report(card%lines(i)%loc, '*DISTRIBUTING: the rotational degrees of ' // &
          'freedom 4-6 (the mean rotation of the surface) are not available in fcs3d; the ' // &
          'translations 1-3 are')
        ok = .false.
      end if
    end do
    if (.not. ok) return
    if (model%mesh%surfaces(state%coupling_surface)%kind /= SURFACE_FACES) then
      call diag%report(card%loc, '*DISTRIBUTING: the surface of *COUPLING "' // &
        state%coupling_name // '" must be made of element faces (CalculiX refuses a nodal ' // &
        'surface too: the weights are the nodal areas)')
      return
    end if
    call nodal_areas(model, state%coupling_surface, nodes, area)
    if (any(nodes == ref)) then
      call diag%report(card%loc, '*DISTRIBUTING: the reference node of *COUPLING "' // &
                       state%coupling_name // '" lies on its own surface')
      return
    end if
    if (sum(area) <= 0.0_dp) then
      call diag%report(card%loc, '*DISTRIBUTING: the surface of *COUPLING "' // &
                       state%coupling_name // '" has no area')
      return
    end if
    do i = 1, 3
      equation%terms = [constraint_term_t(ref, i, 1.0_dp), &
                        (constraint_term_t(nodes(j), i, -area(j) / sum(area)), j = 1, size(nodes))]
      equation%loc = card%loc
      equation%origin = '*DISTRIBUTING'
      model%equations = [model%equations, equation]
    end do
  end subroutine handle_distributing

  !> True when a *COUPLING card stands right before `card` (else an input error).
  logical function follows_coupling(card, state, diag) result(ok)
    type(card_t), intent(in) :: card
    type(builder_t), intent(in) :: state
    type(diagnostics_t), intent(inout) :: diag
    ok = state%coupling_ref > 0
    if (.not. ok) call diag%report(card%loc, '*' // card%keyword // ' must follow directly ' // &
      'a valid *COUPLING card (REF NODE=, SURFACE=, CONSTRAINT NAME=)')
  end function follows_coupling

  !> first[, last] of a data line (last = first when absent), 1 <= first <= last <= highest.
  logical function dof_range(line, keyword, highest, first, last, diag) result(ok)
    type(data_line_t), intent(in) :: line
    character(len=*), intent(in) :: keyword
    integer, intent(in) :: highest
    integer, intent(out) :: first, last
    type(diagnostics_t), intent(inout) :: diag
    ok = .false.
    first = 0
    last = 0
    if (size(line%fields) < 1 .or. size(line%fields) > 2) then
      call diag%report(line%loc, '*' // keyword // ': expected the first degree of freedom ' // &
                       'and, optionally, the last one')
      return
    end if
    if (.not. line_int(line, 1, first, 'first degree of freedom', keyword, diag)) return
    last = first
    if (size(line%fields) == 2) then
      if (len(line%fields(2)%s) > 0) then
        if (.not. line_int(line, 2, last, 'last degree of freedom', keyword, diag)) return
      end if
    end if
    ok = first >= 1 .and. first <= last .and. last <= highest
    if (.not. ok) then
      if (highest == 3 .and. last >= 4 .and. last <= 6 .and. first >= 1 .and. first <= last) then
        call diag%report(line%loc, '*' // keyword // ': degrees of freedom ' // str(first) // &
          '-' // str(last) // ': the surface nodes of a kinematic coupling follow the ' // &
          'reference node in their translations 1-3 only (as in CalculiX)')
      else
        call diag%report(line%loc, '*' // keyword // ': degrees of freedom ' // str(first) // &
          '-' // str(last) // ' must satisfy 1 <= first <= last <= ' // str(highest))
      end if
    end if
  end function dof_range

  !> The nodes of a surface (faces: the nodes of its faces; nodal: its nodes), each once.
  function surface_nodes(model, surface) result(nodes)
    type(model_t), intent(in) :: model
    integer, intent(in) :: surface
    integer, allocatable :: nodes(:)
    integer :: k
    associate (s => model%mesh%surfaces(surface))
      if (s%kind /= SURFACE_FACES) then
        nodes = unique(s%nodes)
        return
      end if
      allocate (nodes(0))
      do k = 1, size(s%element)
        nodes = [nodes, model%mesh%face_nodes(s%element(k), s%face(k))]
      end do
      nodes = unique(nodes)
    end associate
  end function surface_nodes

  !> The nodes of a face surface and their nodal areas a_j = int N_j dA (C1): on every face,
  !> the nodal forces of a unit pull (the element's pressure rule, as CalculiX integrates
  !> them) projected on the face's mean unit normal (exact for a flat face; a quadratic face
  !> has negative corner areas, as in CalculiX).
  subroutine nodal_areas(model, surface, nodes, area)
    type(model_t), intent(in) :: model
    integer, intent(in) :: surface
    integer, allocatable, intent(out) :: nodes(:)
    real(dp), allocatable, intent(out) :: area(:)
    integer, allocatable :: face(:)
    real(dp), allocatable :: force(:)
    real(dp) :: normal(3)
    integer :: k, j, m, e, slot
    nodes = surface_nodes(model, surface)
    allocate (area(size(nodes)))
    area = 0.0_dp
    associate (s => model%mesh%surfaces(surface))
      do k = 1, size(s%element)
        e = s%element(k)
        face = model%mesh%face_nodes(e, s%face(k))
        m = size(face)
        allocate (force(3 * m))
        call element_face_pressure(model%element_kinds%kinds(model%mesh%element_kind(e)), &
                                   s%face(k), model%mesh%x(:, face), -1.0_dp, force)
        normal = 0.0_dp
        do j = 1, m
          normal = normal + force(3 * j - 2:3 * j)
        end do
        if (norm2(normal) > 0.0_dp) normal = normal / norm2(normal)
        do j = 1, m
          slot = findloc(nodes, face(j), 1)
          area(slot) = area(slot) + dot_product(force(3 * j - 2:3 * j), normal)
        end do
        deallocate (force)
      end do
    end associate
  end subroutine nodal_areas

end module fcs_build_coupling
