!> Handlers of the constraint keywords: *EQUATION (linear equations between displacement
!> components), *MPC (PLANE, STRAIGHT, MEANROT) and *RIGID BODY, the last two linearised in
!> the initial configuration into linear equations and, for steps with NLGEOM, recorded as
!> nonlinear constraints owning those equations (model%nonlinear_constraints,
!> fcs_nonlinear_constraints). All equations are stored in model%equations as
!> fcs_linear_constraints' plain data. Their resolution (dependent degrees of freedom,
!> cascades) is checked when the model is finished (fcs_model_checks), their elimination
!> done by the stepper (doc/theory.md, 6.2, 6.2.1 and 6.2.3).
module fcs_build_constraints
  use fcs_kinds, only: dp
  use fcs_deck_lexer, only: card_t, data_line_t
  use fcs_diagnostics, only: diagnostics_t, source_loc_t
  use fcs_deck_fields, only: line_int, line_real, is_integer_text, param_value, resolve_nodes, &
                             resolve_elements
  use fcs_model, only: model_t, transform_def_t
  use fcs_linear_constraints, only: constraint_term_t, linear_equation_t
  use fcs_nonlinear_constraints, only: nonlinear_constraint_t, constraint_gradient, &
                                       CONSTRAINT_PLANE, CONSTRAINT_STRAIGHT, CONSTRAINT_RIGID, &
                                       CONSTRAINT_MEAN_ROTATION
  use fcs_strings, only: str, to_upper, parse_int
  implicit none
  private
  public :: handle_equation, handle_mpc, handle_rigid_body, handle_transform, resolve_transforms
  public :: rigid_equations, unique

  !> Terms per data line of *EQUATION, as CalculiX reads them (12 entries per line).
  integer, parameter :: MAX_TERMS_PER_LINE = 4

contains

  !> *EQUATION: per equation a line with the number of terms N, then the N terms (node,
  !> direction, coefficient), at most four per line (ccx manual, *EQUATION). The first term's
  !> degree of freedom is the dependent one (eliminated).
  subroutine handle_equation(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(linear_equation_t) :: equation
    integer :: i, n_terms, n_read, n_errors
    logical :: ok
    i = 1
    do while (i <= card%n_lines)
      associate (line => card%lines(i))
        if (size(line%fields) /= 1) then
          call diag%report(line%loc, '*EQUATION: expected the number of terms of the next ' // &
            'equation alone on its line (then node, direction, coefficient for each term, at ' // &
            'most four terms per line)')
          return
        end if
        if (.not. line_int(line, 1, n_terms, 'number of terms', 'EQUATION', diag)) return
        if (n_terms < 1) then
          call diag%report(line%loc, '*EQUATION: the number of terms must be at least 1, not ' // &
                           str(n_terms))
          return
        end if
      end associate
      allocate (equation%terms(n_terms))
      n_read = 0
      n_errors = diag%count
      i = i + 1
      do while (n_read < n_terms)
        if (i > card%n_lines) then
          call diag%report(card%lines(card%n_lines)%loc, '*EQUATION: the equation announces ' // &
            str(n_terms) // ' terms, ' // str(n_read) // ' follow')
          return
        end if
        if (n_read == 0) equation%loc = card%lines(i)%loc
        call read_terms(card%lines(i), model, n_terms, equation%terms, n_read, ok, diag)
        if (.not. ok) return
        i = i + 1
      end do
      if (diag%count > n_errors) then
        deallocate (equation%terms)
        cycle
      end if
      if (equation%terms(1)%coefficient == 0.0_dp) then
        call diag%report(equation%loc, '*EQUATION: the coefficient of the first term (the ' // &
          'dependent degree of freedom) must not be zero')
      else
        equation%origin = '*EQUATION'
        model%equations = [model%equations, equation]
      end if
      deallocate (equation%terms)
    end do
  end subroutine handle_equation

  !> The terms of one data line (node, direction, coefficient, ...) into terms(n_read+1:).
  !> `ok` is false when the line's shape is wrong (the rest of the card cannot be read).
  subroutine read_terms(line, model, n_terms, terms, n_read, ok, diag)
    type(data_line_t), intent(in) :: line
    type(model_t), intent(in) :: model
    integer, intent(in) :: n_terms
    type(constraint_term_t), intent(inout) :: terms(:)
    integer, intent(inout) :: n_read
    logical, intent(out) :: ok
    type(diagnostics_t), intent(inout) :: diag
    integer :: n_fields, k, id, node, dof
    real(dp) :: coefficient
    n_fields = size(line%fields)
    ok = .false.
    if (n_fields == 0 .or. mod(n_fields, 3) /= 0 .or. n_fields > 3 * MAX_TERMS_PER_LINE) then
      call diag%report(line%loc, '*EQUATION: expected node, direction, coefficient for each ' // &
        'term, at most four terms per line (' // str(n_fields) // ' fields)')
      return
    end if
    if (n_read + n_fields / 3 > n_terms) then
      call diag%report(line%loc, '*EQUATION: more terms than the ' // str(n_terms) // &
                       ' the equation announces')
      return
    end if
    ok = .true.
    do k = 1, n_fields / 3
      n_read = n_read + 1
      if (.not. is_integer_text(line%fields(3 * k - 2)%s)) then
        call diag%report(line%loc, '*EQUATION: term ' // str(n_read) // ': expected a node ' // &
          'number, not "' // line%fields(3 * k - 2)%s // '" (a node set is not a term of ' // &
          '*EQUATION, in CalculiX 2.20 either)')
        cycle
      end if
      if (.not. line_int(line, 3 * k - 2, id, 'node', 'EQUATION', diag)) cycle
      node = model%mesh%node_index(id)
      if (node == 0) then
        call diag%report(line%loc, '*EQUATION: term ' // str(n_read) // ': node ' // str(id) // &
                         ' is not defined')
        cycle
      end if
      if (.not. line_int(line, 3 * k - 1, dof, 'direction', 'EQUATION', diag)) cycle
      if (dof < 1 .or. dof > 3) then
        call diag%report(line%loc, '*EQUATION: term ' // str(n_read) // ': direction ' // &
          str(dof) // ' is not a displacement component of a solid node (1, 2 or 3)')
        cycle
      end if
      if (.not. line_real(line, 3 * k, coefficient, 'coefficient', 'EQUATION', diag)) cycle
      terms(n_read) = constraint_term_t(node, dof, coefficient)
    end do
  end subroutine read_terms

  !> *MPC: a name, then the nodes (first line: up to 15 after the name; further lines up to 16;
  !> zero entries discarded; a node set stands for its nodes), as CalculiX reads it (ccx
  !> manual, *MPC). PLANE (the nodes after
  !> the first three stay in the plane of the first three) and STRAIGHT (the nodes after the
  !> first two stay on their line) are linearised in the initial configuration (doc/theory.md
  !> 6.2.1) and nonlinear in steps with NLGEOM (6.2.3); CalculiX turns NLGEOM on for them:
  !> fcs3d keeps each step's NLGEOM (a warning says so). MEANROT: `mean_rotation_equation`.
  subroutine handle_mpc(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable :: nodes(:), members(:)
    character(len=:), allocatable :: kind
    integer :: i, j, id, node
    logical :: ok, from_set
    from_set = .false.
    kind = to_upper(card%lines(1)%fields(1)%s)
    if (kind /= 'PLANE' .and. kind /= 'STRAIGHT' .and. kind /= 'MEANROT') then
      call diag%report(card%lines(1)%loc, '*MPC: "' // card%lines(1)%fields(1)%s // '" is not ' // &
        'available; expected PLANE, STRAIGHT or MEANROT (BEAM, DIST and user MPCs are not ' // &
        'implemented in fcs3d)')
      return
    end if
    allocate (nodes(0))
    do i = 1, card%n_lines
      associate (line => card%lines(i))
        if (size(line%fields) > 16) then
          call diag%report(line%loc, '*MPC: at most 16 entries per line (' // &
                           str(size(line%fields)) // ')')
          return
        end if
        do j = merge(2, 1, i == 1), size(line%fields)
          if (len(line%fields(j)%s) == 0) cycle
          if (.not. is_integer_text(line%fields(j)%s)) then
            ! A node set, as CalculiX accepts: its nodes in the set's order.
            call resolve_nodes(model%mesh, line%fields(j)%s, line, 'MPC', diag, members)
            if (size(members) == 0) return
            nodes = [nodes, members]
            from_set = from_set .or. size(nodes) == size(members)
            cycle
          end if
          call parse_int(line%fields(j)%s, id, ok)
          if (.not. ok) then
            call diag%report(line%loc, '*MPC: expected a node number or a node set, not "' // &
                             line%fields(j)%s // '" (field ' // str(j) // ')')
            return
          end if
          if (id == 0) cycle
          node = model%mesh%node_index(id)
          if (node == 0) then
            call diag%report(line%loc, '*MPC: node ' // str(id) // ' is not defined')
            return
          end if
          nodes = [nodes, node]
        end do
      end associate
    end do
    if (kind == 'MEANROT') then
      call mean_rotation_equation(card, model, nodes, diag)
      return
    end if
    call diag%warn(card%loc, '*MPC ' // kind // ': CalculiX turns NLGEOM on for it; fcs3d ' // &
      'keeps each step''s NLGEOM: nonlinear in steps with NLGEOM, linearised in the initial ' // &
      'configuration in the others (exact for small rotations of the ' // &
      merge('plane', 'line ', kind == 'PLANE') // ')')
    ! fcs3d's node sets are sorted, not in the order of the deck, which CalculiX takes the
    ! defining nodes from: when the list starts with a set, the defining nodes are chosen
    ! from the geometry instead (the first node, the one farthest from it, and for PLANE the
    ! one farthest from their line): the same plane or line when the nodes lie in one.
    if (from_set .and. size(nodes) >= 3) call choose_defining(model, nodes, merge(3, 2, kind == 'PLANE'))
    if (kind == 'PLANE') then
      call plane_equations(card, model, nodes, diag)
    else
      call straight_equations(card, model, nodes, diag)
    end if
  end subroutine handle_mpc

  !> Move to the front of `nodes` n_defining well-spread nodes: nodes(1), the node farthest
  !> from it, and (n_defining = 3) the node farthest from the line through those two.
  subroutine choose_defining(model, nodes, n_defining)
    type(model_t), intent(in) :: model
    integer, intent(inout) :: nodes(:)
    integer, intent(in) :: n_defining
    real(dp) :: d(size(nodes)), e(3)
    integer :: k, best
    do k = 1, size(nodes)
      d(k) = norm2(model%mesh%x(:, nodes(k)) - model%mesh%x(:, nodes(1)))
    end do
    best = maxloc(d, 1)
    call swap(nodes, 2, best)
    if (n_defining < 3) return
    e = model%mesh%x(:, nodes(2)) - model%mesh%x(:, nodes(1))
    do k = 1, size(nodes)
      d(k) = norm2(cross(model%mesh%x(:, nodes(k)) - model%mesh%x(:, nodes(1)), e))
    end do
    best = maxloc(d, 1)
    call swap(nodes, 3, best)
  contains
    subroutine swap(list, i, j)
      integer, intent(inout) :: list(:)
      integer, intent(in) :: i, j
      integer :: kept
      kept = list(i)
      list(i) = list(j)
      list(j) = kept
    end subroutine swap
  end subroutine choose_defining

  !> PLANE, linearised: with r = x_p - x_a, e1 = x_b - x_a, e2 = x_c - x_a, n = e1 x e2, the
  !> change of (x_p - x_a) . n is
  !>   n . (u_p - u_a) + (e2 x r) . (u_b - u_a) + (r x e1) . (u_c - u_a) = 0
  !> (doc/theory.md (L3)); the dependent term is chosen by `add_equation`.
  subroutine plane_equations(card, model, nodes, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    integer, intent(in) :: nodes(:)
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: e1(3), e2(3), n(3), r(3), cb(3), cc(3), ca(3)
    integer :: k, p
    if (size(nodes) < 4) then
      call diag%report(card%lines(1)%loc, '*MPC PLANE: expected the three nodes defining the ' // &
                       'plane and at least one node to keep in it')
      return
    end if
    e1 = model%mesh%x(:, nodes(2)) - model%mesh%x(:, nodes(1))
    e2 = model%mesh%x(:, nodes(3)) - model%mesh%x(:, nodes(1))
    n = cross(e1, e2)
    if (norm2(n) <= 1.0e-10_dp * norm2(e1) * norm2(e2)) then
      call diag%report(card%lines(1)%loc, '*MPC PLANE: the first three nodes lie on a line and ' // &
                       'define no plane')
      return
    end if
    do k = 4, size(nodes)
      p = nodes(k)
      r = model%mesh%x(:, p) - model%mesh%x(:, nodes(1))
      cb = cross(e2, r)
      cc = cross(r, e1)
      ca = -(n + cb + cc)
      call add_equation(model, card, '*MPC PLANE', [p, nodes(1), nodes(2), nodes(3)], &
                        reshape([n, ca, cb, cc], [3, 4]), spread(spread(.true., 1, 3), 2, 4), &
                        diag, CONSTRAINT_PLANE)
    end do
  end subroutine plane_equations

  !> STRAIGHT, linearised: with e = x_b - x_a and s = (x_p - x_a) . e / |e|^2, the motion of p
  !> across the line, v = u_p - (1 - s) u_a - s u_b, has no component normal to e:
  !>   v_i e_j - v_j e_i = 0   for the two i /= j,  j the direction of the largest |e_j|
  !> (doc/theory.md (L4)); the dependent term (u_p,i when free) is chosen by `add_equation`.
  subroutine straight_equations(card, model, nodes, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    integer, intent(in) :: nodes(:)
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: e(3), s, c(3, 3), weight(3)
    logical :: kept(3, 3)
    integer :: k, p, i, j
    if (size(nodes) < 3) then
      call diag%report(card%lines(1)%loc, '*MPC STRAIGHT: expected the two nodes defining the ' // &
                       'line and at least one node to keep on it')
      return
    end if
    e = model%mesh%x(:, nodes(2)) - model%mesh%x(:, nodes(1))
    if (norm2(e) <= 0.0_dp) then
      call diag%report(card%lines(1)%loc, '*MPC STRAIGHT: the first two nodes coincide and ' // &
                       'define no line')
      return
    end if
    j = maxloc(abs(e), 1)
    do k = 3, size(nodes)
      p = nodes(k)
      s = dot_product(model%mesh%x(:, p) - model%mesh%x(:, nodes(1)), e) / dot_product(e, e)
      weight = [1.0_dp, -(1.0_dp - s), -s]
      do i = 1, 3
        if (i == j) cycle
        ! Columns: the coefficients of nodes p, a, b.
        c = 0.0_dp
        c(i, :) = weight * e(j)
        c(j, :) = -weight * e(i)
        kept = .false.
        kept([i, j], :) = .true.
        call add_equation(model, card, '*MPC STRAIGHT', [p, nodes(1), nodes(2)], c, kept, diag, &
                          CONSTRAINT_STRAIGHT, i, j)
      end do
    end do
  end subroutine straight_equations

  !> One equation sum_a coefficients(:, a) . u_{nodes(a)} = 0; a term with a zero coefficient
  !> is left out unless `kept` (the terms of a nonlinear constraint, whose coefficients change
  !> with the geometry). Its dependent term is the component of u_{nodes(1)} with the largest
  !> |coefficient| that is not already dependent in an earlier equation, else the largest
  !> such term of the other nodes (as CalculiX picks the dependent term of its nonlinear MPCs
  !> among the free ones); when every term is dependent already, the equation is redundant:
  !> an input error. With `kind`, the equation is the linearisation of that nonlinear
  !> constraint (fcs_nonlinear_constraints; `direction`, `along` its STRAIGHT directions).
  subroutine add_equation(model, card, origin, nodes, coefficients, kept, diag, kind, direction, along)
    type(model_t), intent(inout) :: model
    type(card_t), intent(in) :: card
    character(len=*), intent(in) :: origin
    integer, intent(in) :: nodes(:)
    real(dp), intent(in) :: coefficients(:, :)
    logical, intent(in) :: kept(:, :)
    type(diagnostics_t), intent(inout) :: diag
    integer, intent(in) :: kind
    integer, intent(in), optional :: direction, along
    type(linear_equation_t) :: equation
    type(nonlinear_constraint_t) :: constraint
    real(dp) :: best
    integer :: a, d, first_node, first_dof
    first_node = 0
    do a = 1, size(nodes)
      best = 0.0_dp
      do d = 1, 3
        if (abs(coefficients(d, a)) <= best) cycle
        if (is_dependent(model, nodes(a), d)) cycle
        best = abs(coefficients(d, a))
        first_node = a
        first_dof = d
      end do
      if (first_node > 0) exit
    end do
    if (first_node == 0) then
      call diag%report(card%lines(1)%loc, origin // ': the constraint on node ' // &
        str(model%mesh%node_id(nodes(1))) // ' is redundant: each of its degrees of freedom is ' // &
        'already the dependent term of another constraint (a node in two *MPCs that say the ' // &
        'same?)')
      return
    end if
    equation%terms = [constraint_term_t(nodes(first_node), first_dof, &
                                        coefficients(first_dof, first_node))]
    do a = 1, size(nodes)
      do d = 1, 3
        if (a == first_node .and. d == first_dof) cycle
        if (coefficients(d, a) == 0.0_dp .and. .not. kept(d, a)) cycle
        equation%terms = [equation%terms, constraint_term_t(nodes(a), d, coefficients(d, a))]
      end do
    end do
    equation%loc = card%lines(1)%loc
    equation%origin = origin
    if (kind == CONSTRAINT_MEAN_ROTATION) then
      ! RF at the angle node is the moment the constraint transmits (CalculiX prints it).
      equation%transmits = .true.
      equation%first_transmitting = size(equation%terms)
    end if
    model%equations = [model%equations, equation]
    constraint%kind = kind
    constraint%nodes = nodes
    constraint%equation = size(model%equations)
    if (present(direction)) constraint%direction = direction
    if (present(along)) constraint%along = along
    if (kind == CONSTRAINT_MEAN_ROTATION) constraint%vector = model%mesh%x(:, nodes(size(nodes))) / &
                                                            norm2(model%mesh%x(:, nodes(size(nodes))))
    model%nonlinear_constraints = [model%nonlinear_constraints, constraint]
  end subroutine add_equation

  !> MEANROT: the member nodes, each listed three times (once per direction), then the angle
  !> node m, whose coordinates are the axis and whose first displacement is the mean rotation
  !> about it, radians (ccx manual, *MPC; umpc_mean_rot.f): (N4) of fcs_nonlinear_constraints,
  !> linearised at the initial configuration for steps without NLGEOM (CalculiX does not turn
  !> NLGEOM on for it).
  subroutine mean_rotation_equation(card, model, nodes, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    integer, intent(in) :: nodes(:)
    type(diagnostics_t), intent(inout) :: diag
    type(nonlinear_constraint_t) :: probe
    integer, allocatable :: members(:)
    real(dp), allocatable :: u(:, :), gradient(:, :)
    logical, allocatable :: kept(:, :)
    real(dp) :: g
    integer :: k, n, angle_node
    n = (size(nodes) - 1) / 3
    if (size(nodes) < 7 .or. mod(size(nodes) - 1, 3) /= 0) then
      call diag%report(card%lines(1)%loc, '*MPC MEANROT: expected each member node three ' // &
        'times (once per direction), at least two members, then the node whose coordinates ' // &
        'give the axis and whose first degree of freedom is the angle (' // str(size(nodes)) // &
        ' nodes)')
      return
    end if
    members = [(nodes(3 * k - 2), k = 1, n)]
    do k = 1, n
      if (nodes(3 * k - 1) /= members(k) .or. nodes(3 * k) /= members(k)) then
        call diag%report(card%lines(1)%loc, '*MPC MEANROT: member ' // str(k) // ' (node ' // &
          str(model%mesh%node_id(members(k))) // ') must be listed three times in a row, once ' // &
          'per direction, as CalculiX requires')
        return
      end if
    end do
    angle_node = nodes(size(nodes))
    if (any(members == angle_node)) then
      call diag%report(card%lines(1)%loc, '*MPC MEANROT: the last node (' // &
        str(model%mesh%node_id(angle_node)) // ', the axis and angle) may not be a member')
      return
    end if
    if (norm2(model%mesh%x(:, angle_node)) <= 0.0_dp) then
      call diag%report(card%lines(1)%loc, '*MPC MEANROT: the coordinates of the last node (' // &
        str(model%mesh%node_id(angle_node)) // ') are the rotation axis and must not be zero')
      return
    end if
    probe%kind = CONSTRAINT_MEAN_ROTATION
    probe%nodes = [members, angle_node]
    probe%vector = model%mesh%x(:, angle_node) / norm2(model%mesh%x(:, angle_node))
    allocate (u(3, model%mesh%n_nodes))
    u = 0.0_dp
    call constraint_gradient(probe, model%mesh%x, u, g, gradient)
    if (count(any(gradient(:, 1:n) /= 0.0_dp, dim=1)) < 1) then
      call diag%report(card%lines(1)%loc, '*MPC MEANROT: every member lies on the axis ' // &
        'through their centroid: no rotation about it can be measured')
      return
    end if
    allocate (kept(3, n + 1))
    kept = .true.
    kept(2:3, n + 1) = .false.
    call add_equation(model, card, '*MPC MEANROT', probe%nodes, gradient, kept, diag, &
                      CONSTRAINT_MEAN_ROTATION)
  end subroutine mean_rotation_equation

  !> True when (node, direction) is the dependent term of an equation of the model so far.
  logical function is_dependent(model, node, direction)
    type(model_t), intent(in) :: model
    integer, intent(in) :: node, direction
    integer :: k
    is_dependent = .false.
    do k = 1, size(model%equations)
      if (model%equations(k)%terms(1)%node == node .and. &
          model%equations(k)%terms(1)%dof == direction) then
        is_dependent = .true.
        return
      end if
    end do
  end function is_dependent

  !> *RIGID BODY, NSET= or ELSET=, REF NODE=, ROT NODE=: the nodes of the set move with the
  !> reference node and the rotation of the rotation node (whose three degrees of freedom
  !> are rotations, radians), linearised in the initial configuration (CalculiX's RIGID MPCs
  !> are nonlinear): for each node p, r = x_p - x_ref, and each direction i
  !>   u_p,i - u_ref,i - (theta x r)_i = 0                                       (doc/theory.md (L5))
  !> with u_p,i dependent. Both nodes must be given (CalculiX generates missing ones).
  subroutine handle_rigid_body(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    integer, allocatable :: members(:), elements(:)
    integer :: ref, rot, k
    if (len(param_value(card, 'NSET')) > 0 .eqv. len(param_value(card, 'ELSET')) > 0) then
      call diag%report(card%loc, '*RIGID BODY: give either NSET= or ELSET= (the nodes of the body)')
      return
    end if
    if (.not. given_node(card, model, 'REF NODE', ref, diag)) return
    if (.not. given_node(card, model, 'ROT NODE', rot, diag)) return
    if (ref == rot) then
      call diag%report(card%loc, '*RIGID BODY: REF NODE and ROT NODE must be different nodes')
      return
    end if
    if (len(param_value(card, 'NSET')) > 0) then
      call resolve_nodes(model%mesh, param_value(card, 'NSET'), card_line(card), 'RIGID BODY', &
                         diag, members)
    else
      call resolve_elements(model%mesh, param_value(card, 'ELSET'), card_line(card), 'RIGID BODY', &
                            diag, elements)
      allocate (members(0))
      do k = 1, size(elements)
        members = [members, model%mesh%element_nodes(elements(k))]
      end do
      members = unique(members)
    end if
    members = pack(members, members /= ref .and. members /= rot)
    if (size(members) == 0) then
      call diag%report(card%loc, '*RIGID BODY: the set holds no node besides REF NODE and ROT NODE')
      return
    end if
    if (is_rotation_node(model, ref)) then
      call diag%report(card%loc, '*RIGID BODY: REF NODE ' // str(model%mesh%node_id(ref)) // &
                       ' is the ROT NODE of another rigid body')
      return
    end if
    model%rotation_nodes = [model%rotation_nodes, rot]
    call rigid_equations(model, members, ref, rot, 1, 3, card%loc, '*RIGID BODY')
  end subroutine handle_rigid_body

  !> The rigid-body equations (doc/theory.md (L5)) of the nodes `members` in directions
  !> first..last, about reference node `ref` with the rotation held by the three degrees of
  !> freedom of `rot`; each also a nonlinear constraint (N3) for steps with NLGEOM. Used by
  !> *RIGID BODY (directions 1-3) and *COUPLING with *KINEMATIC (the directions given).
  subroutine rigid_equations(model, members, ref, rot, first, last, loc, origin)
    type(model_t), intent(inout) :: model
    integer, intent(in) :: members(:), ref, rot, first, last
    type(source_loc_t), intent(in) :: loc
    character(len=*), intent(in) :: origin
    type(linear_equation_t) :: equation
    real(dp) :: r(3)
    integer :: k, p, i, i1, i2
    do k = 1, size(members)
      p = members(k)
      r = model%mesh%x(:, p) - model%mesh%x(:, ref)
      do i = first, last
        i1 = mod(i, 3) + 1
        i2 = mod(i + 1, 3) + 1
        ! (theta x r)_i = theta_i1 r_i2 - theta_i2 r_i1; theta_i's term, zero here, is that
        ! of the nonlinear constraint (N3) under NLGEOM.
        equation%terms = [constraint_term_t(p, i, 1.0_dp), constraint_term_t(ref, i, -1.0_dp), &
                          constraint_term_t(rot, i1, -r(i2)), constraint_term_t(rot, i2, r(i1)), &
                          constraint_term_t(rot, i, 0.0_dp)]
        equation%loc = loc
        equation%origin = origin
        equation%transmits = .true.
        model%equations = [model%equations, equation]
        model%nonlinear_constraints = [model%nonlinear_constraints, nonlinear_constraint_t( &
          CONSTRAINT_RIGID, size(model%equations), [p, ref, rot], i, 0, r)]
      end do
    end do
  end subroutine rigid_equations

  !> *TRANSFORM, NSET=, TYPE=R|C: one data line with the points a and b (ccx manual,
  !> *TRANSFORM); the axes are worked out per node after the last card (`resolve_transforms`).
  subroutine handle_transform(card, model, diag)
    type(card_t), intent(in) :: card
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    type(transform_def_t) :: t
    integer :: k
    if (card%n_lines /= 1) then
      call diag%report(card%loc, '*TRANSFORM: expected one data line (a_x, a_y, a_z, b_x, b_y, b_z)')
      return
    end if
    associate (line => card%lines(1))
      if (size(line%fields) /= 6) then
        call diag%report(line%loc, '*TRANSFORM: expected six coordinates a_x, a_y, a_z, b_x, ' // &
                         'b_y, b_z (' // str(size(line%fields)) // ' fields)')
        return
      end if
      do k = 1, 3
        if (.not. line_real(line, k, t%a(k), 'coordinate of a', 'TRANSFORM', diag)) return
        if (.not. line_real(line, k + 3, t%b(k), 'coordinate of b', 'TRANSFORM', diag)) return
      end do
      t%loc = line%loc
    end associate
    t%node_set = model%mesh%find_node_set(to_upper(param_value(card, 'NSET')))
    if (t%node_set == 0) then
      call diag%report(card%loc, '*TRANSFORM: node set "' // param_value(card, 'NSET') // &
                       '" is not defined')
      return
    end if
    t%cylindrical = to_upper(param_value(card, 'TYPE')) == 'C'
    if (.not. t%cylindrical) then
      if (norm2(t%a) <= 0.0_dp .or. norm2(cross(t%a, t%b)) <= 1.0e-10_dp * norm2(t%a) * norm2(t%b)) then
        call diag%report(t%loc, '*TRANSFORM, TYPE=R: a must be a point off the origin and b a ' // &
                         'point off the line through the origin and a')
        return
      end if
    else if (norm2(t%b - t%a) <= 0.0_dp) then
      call diag%report(t%loc, '*TRANSFORM, TYPE=C: the two points of the axis coincide')
      return
    end if
    model%transforms = [model%transforms, t]
  end subroutine handle_transform

  !> Local axes of every node of a *TRANSFORM's set (a later card overrides an earlier one for
  !> a node in both, as in CalculiX): TYPE=R: e_x = a / |a|, e_z = a x b / |a x b|,
  !> e_y = e_z x e_x; TYPE=C: e_z = (b - a) / |b - a|, e_x the unit normal from the axis to
  !> the node (radial), e_y = e_z x e_x (tangential). A node on the axis of a cylindrical
  !> system has no radial direction: an input error.
  subroutine resolve_transforms(model, diag)
    type(model_t), intent(inout) :: model
    type(diagnostics_t), intent(inout) :: diag
    real(dp) :: ex(3), ey(3), ez(3), r(3)
    integer :: k, j, node
    allocate (model%node_frame(3, 3, model%mesh%n_nodes), model%transformed(model%mesh%n_nodes))
    model%node_frame = 0.0_dp
    model%transformed = .false.
    do k = 1, size(model%transforms)
      associate (t => model%transforms(k), members => model%mesh%node_sets(model%transforms(k)%node_set)%members)
        do j = 1, size(members)
          node = members(j)
          if (t%cylindrical) then
            ez = (t%b - t%a) / norm2(t%b - t%a)
            r = model%mesh%x(:, node) - t%a
            r = r - dot_product(r, ez) * ez
            if (norm2(r) <= 1.0e-10_dp * max(norm2(t%b - t%a), norm2(model%mesh%x(:, node) - t%a))) then
              call diag%report(t%loc, '*TRANSFORM, TYPE=C: node ' // str(model%mesh%node_id(node)) // &
                               ' lies on the axis, where the radial direction is undefined')
              return
            end if
            ex = r / norm2(r)
          else
            ex = t%a / norm2(t%a)
            ez = cross(t%a, t%b)
            ez = ez / norm2(ez)
          end if
          ey = cross(ez, ex)
          model%node_frame(:, 1, node) = ex
          model%node_frame(:, 2, node) = ey
          model%node_frame(:, 3, node) = ez
          model%transformed(node) = .true.
        end do
      end associate
    end do
  end subroutine resolve_transforms

  !> The node named by parameter `name` (required).
  logical function given_node(card, model, name, node, diag) result(ok)
    type(card_t), intent(in) :: card
    type(model_t), intent(in) :: model
    character(len=*), intent(in) :: name
    integer, intent(out) :: node
    type(diagnostics_t), intent(inout) :: diag
    integer :: id
    node = 0
    call parse_int(param_value(card, name), id, ok)
    if (.not. ok) then
      call diag%report(card%loc, '*RIGID BODY: ' // name // '= must be a node number (fcs3d ' // &
        'does not generate the node when it is missing, as CalculiX does: define it by *NODE)')
      return
    end if
    node = model%mesh%node_index(id)
    ok = node > 0
    if (.not. ok) call diag%report(card%loc, '*RIGID BODY: ' // name // ' ' // str(id) // &
                                   ' is not defined')
  end function given_node

  logical function is_rotation_node(model, node)
    type(model_t), intent(in) :: model
    integer, intent(in) :: node
    is_rotation_node = any(model%rotation_nodes == node)
  end function is_rotation_node

  !> The keyword line as a data line (for resolve_nodes' messages).
  function card_line(card) result(line)
    type(card_t), intent(in) :: card
    type(data_line_t) :: line
    line%loc = card%loc
    allocate (line%fields(0))
  end function card_line

  pure function unique(values) result(out)
    integer, intent(in) :: values(:)
    integer, allocatable :: out(:)
    integer :: k
    allocate (out(0))
    do k = 1, size(values)
      if (.not. any(out == values(k))) out = [out, values(k)]
    end do
  end function unique

  pure function cross(a, b) result(c)
    real(dp), intent(in) :: a(3), b(3)
    real(dp) :: c(3)
    c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
  end function cross

end module fcs_build_constraints
