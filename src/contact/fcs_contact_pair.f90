!> A contact pair as the contact system holds it: its definition from the deck (slave and
!> master surfaces, resolved penalties: `contact_pair_def_t`, part of the model), and what is
!> built from it on the mesh - the master faces (3, 4, 6 or 8 node indices each, outward:
!> element faces of any kind, corners first), the faces
!> sharing a node with each face, the free edges of the master surface, the search grid and
!> the friction law - with the pair-level geometry: global search of a point and following a
!> closed node's contact point from face to face (fcs_contact_search).
module fcs_contact_pair
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error
  use fcs_strings, only: str
  use fcs_diagnostics, only: source_loc_t
  use fcs_mesh, only: mesh_t
  use fcs_contact_geometry, only: segment_point_t, project_to_segment, is_triangle, cross3
  use fcs_contact_search, only: face_grid_t, closest_face, edge_excess, XI_TOLERANCE, face_node_count
  use fcs_friction_law, only: friction_law_t
  use fcs_friction_factory, only: create_friction_law, friction_def_t
  use fcs_sort, only: unique_sorted
  use fcs_pressure_overclosure, only: pressure_overclosure_t
  implicit none
  private
  public :: contact_pair_def_t, contact_pair_t, pair_setup, face_coordinates, search, follow
  public :: pair_face_nodes

  !> A node-to-point contact pair (*CONTACT PAIR) or a tied pair (*TIE).
  type :: contact_pair_def_t
    character(len=:), allocatable :: name
    !> Slave: a surface (element-face or node based); master: an element-face surface.
    integer :: slave_surface = 0
    integer :: master_surface = 0
    !> The *SURFACE INTERACTION, which may come after the pair (as CalculiX allows): its name
    !> is resolved after the last card.
    integer :: interaction = 0
    character(len=:), allocatable :: interaction_name
    logical :: tied = .false.
    !> TYPE=SURFACE TO SURFACE: the slave entries are integration points of the slave faces
    !> (doc/theory.md 4.10), not its nodes.
    logical :: surface_to_surface = .false.
    !> *TIE: slave nodes farther than this from the master are not tied (<= 0: default).
    real(dp) :: position_tolerance = 0.0_dp
    !> *CONTACT PAIR, ADJUST=: slave nodes with a signed gap up to adjust_distance [length]
    !> (< 0: none), or those of node set adjust_set (0: none), are moved onto the master
    !> before the analysis (fcs_contact_adjust).
    real(dp) :: adjust_distance = -1.0_dp
    integer :: adjust_set = 0
    !> Resolved penalties E_n, E_t [stress/length] and friction coefficient of this pair.
    real(dp) :: normal_stiffness = 0.0_dp
    real(dp) :: stick_stiffness = 0.0_dp
    !> Pressure-overclosure law (LINEAR: the penalty normal_stiffness; EXPONENTIAL: c0, p0).
    type(pressure_overclosure_t) :: overclosure
    !> Mean thickness h of the master elements and the modulus E the defaults come from.
    real(dp) :: master_thickness = 0.0_dp
    real(dp) :: master_modulus = 0.0_dp
    !> Resolved radiation damping eta [stress time/length] of this pair (0: none).
    real(dp) :: radiation_damping = 0.0_dp
    type(source_loc_t) :: loc
  end type contact_pair_def_t

  type :: contact_pair_t
    character(len=:), allocatable :: name
    logical :: tied = .false.
    !> Slave entries are integration points of the slave faces (TYPE=SURFACE TO SURFACE).
    logical :: surface_to_surface = .false.
    real(dp) :: normal_stiffness = 0.0_dp
    real(dp) :: stick_stiffness = 0.0_dp
    type(pressure_overclosure_t) :: overclosure
    !> Radiation damping eta [stress time/length] of the pair (0: none).
    real(dp) :: radiation_damping = 0.0_dp
    !> Mean master face size; search reach for open nodes; tie position tolerance.
    real(dp) :: face_size = 0.0_dp
    real(dp) :: reach = 0.0_dp
    real(dp) :: position_tolerance = 0.0_dp
    class(friction_law_t), allocatable :: law
    !> Master faces (global node indices, outward, corners first; a column holds the largest
    !> face of the pair and a smaller face is padded with 0: pair_face_nodes) and the faces
    !> sharing a node with each face (itself included):
    !> neighbors(neighbor_ptr(f):neighbor_ptr(f+1)-1).
    integer, allocatable :: face_nodes(:, :)
    integer, allocatable :: neighbor_ptr(:), neighbors(:)
    !> free_edge(k, f): edge k of face f (k = 1..4: corners 1-2, 2-3, 3-4, 4-1, i.e. the edges
    !> xi_2 = -1, xi_1 = 1, xi_2 = 1, xi_1 = -1; a triangle's edges 1-2, 2-3, 3-1 are
    !> t = 0, s + t = 1, s = 0 and its k = 4 is never free) bounds the master surface (no
    !> other face of the pair shares it).
    logical, allocatable :: free_edge(:, :)
    type(face_grid_t) :: grid
    !> Slave entries of this pair in the contact state: first..last.
    integer :: first = 1
    integer :: last = 0
    !> Slave nodes of the surface left out of this (untied) pair because a tie holds them.
    integer :: n_held_by_tie = 0
  end type contact_pair_t

contains

  !> Faces, neighbours, penalties, friction law and search grid of one pair, defined by `def`
  !> on `mesh`, with the friction law `friction`, on coordinates x.
  subroutine pair_setup(pair, def, friction, mesh, x, err)
    type(contact_pair_t), intent(inout) :: pair
    type(contact_pair_def_t), intent(in) :: def
    type(friction_def_t), intent(in) :: friction
    type(mesh_t), intent(in) :: mesh
    real(dp), intent(in) :: x(:, :)
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: nodes(:)
    integer :: f, nf, width
    pair%name = def%name
    pair%tied = def%tied
    pair%surface_to_surface = def%surface_to_surface
    pair%normal_stiffness = def%normal_stiffness
    pair%stick_stiffness = def%stick_stiffness
    pair%overclosure = def%overclosure
    pair%position_tolerance = def%position_tolerance
    pair%radiation_damping = def%radiation_damping
    associate (surface => mesh%surfaces(def%master_surface))
      nf = size(surface%element)
      width = 0
      do f = 1, nf
        width = max(width, size(mesh%face_nodes(surface%element(f), surface%face(f))))
      end do
      allocate (pair%face_nodes(width, nf))
      pair%face_nodes = 0
      do f = 1, nf
        nodes = mesh%face_nodes(surface%element(f), surface%face(f))
        if (all(size(nodes) /= [3, 4, 6, 8])) then
          call input_error(err, 'contact pair ' // def%name // ': face S' // str(surface%face(f)) // &
            ' of element ' // str(mesh%element_id(surface%element(f))) // ' has ' // &
            str(size(nodes)) // ' nodes; master segments have 3, 4, 6 or 8 nodes')
          return
        end if
        pair%face_nodes(1:size(nodes), f) = nodes
      end do
    end associate
    pair%face_size = 0.0_dp
    do f = 1, nf
      pair%face_size = pair%face_size + face_length(x(:, pair_face_nodes(pair, f)))
    end do
    pair%face_size = pair%face_size / nf
    pair%reach = pair%face_size
    ! The exponential law acts up to the clearance c0: open nodes are found that far.
    if (pair%overclosure%is_exponential()) pair%reach = max(pair%face_size, 2.0_dp * pair%overclosure%c0)
    call face_neighbours(pair, mesh%n_nodes)
    call free_edges(pair)
    call pair%grid%build(face_coordinates(pair, x), pair%reach)
    call create_friction_law(friction, pair%law, err)
  end subroutine pair_setup

  !> The length of a face for the pair's mean face size: the mean diagonal over sqrt(2) of a
  !> quadrilateral (its side when square), sqrt(2 A) of a triangle of area A (its legs when
  !> right isosceles), from the corner nodes.
  pure real(dp) function face_length(xf) result(length)
    real(dp), intent(in) :: xf(:, :)
    if (is_triangle(size(xf, 2))) then
      length = sqrt(norm2(cross3(xf(:, 2) - xf(:, 1), xf(:, 3) - xf(:, 1))))
    else
      length = 0.5_dp * (norm2(xf(:, 3) - xf(:, 1)) + norm2(xf(:, 4) - xf(:, 2))) / sqrt(2.0_dp)
    end if
  end function face_length

  !> The node indices of master face f of a pair (3, 4, 6 or 8).
  pure function pair_face_nodes(pair, f) result(nodes)
    type(contact_pair_t), intent(in) :: pair
    integer, intent(in) :: f
    integer, allocatable :: nodes(:)
    nodes = pair%face_nodes(1:face_node_count(pair%face_nodes(:, f)), f)
  end function pair_face_nodes

  !> Node coordinates of every master face of a pair, (3, nodes per face, n_faces); a face with
  !> fewer nodes repeats its first node in the unused columns.
  pure function face_coordinates(pair, x) result(face_x)
    type(contact_pair_t), intent(in) :: pair
    real(dp), intent(in) :: x(:, :)
    real(dp) :: face_x(3, size(pair%face_nodes, 1), size(pair%face_nodes, 2))
    integer :: f, a
    do f = 1, size(pair%face_nodes, 2)
      do a = 1, size(pair%face_nodes, 1)
        if (pair%face_nodes(a, f) /= 0) then
          face_x(:, a, f) = x(:, pair%face_nodes(a, f))
        else
          face_x(:, a, f) = x(:, pair%face_nodes(1, f))
        end if
      end do
    end do
  end function face_coordinates

  !> For every face, the faces sharing at least one node with it (itself included).
  subroutine face_neighbours(pair, n_nodes)
    type(contact_pair_t), intent(inout) :: pair
    integer, intent(in) :: n_nodes
    integer, allocatable :: node_ptr(:), node_faces(:), fill(:), found(:)
    integer :: f, i, nf, node, j
    nf = size(pair%face_nodes, 2)
    allocate (node_ptr(n_nodes + 1))
    node_ptr = 0
    do f = 1, nf
      do i = 1, face_node_count(pair%face_nodes(:, f))
        node = pair%face_nodes(i, f)
        node_ptr(node + 1) = node_ptr(node + 1) + 1
      end do
    end do
    node_ptr(1) = 1
    do i = 1, n_nodes
      node_ptr(i + 1) = node_ptr(i + 1) + node_ptr(i)
    end do
    allocate (node_faces(node_ptr(n_nodes + 1) - 1))
    fill = node_ptr(1:n_nodes)
    do f = 1, nf
      do i = 1, face_node_count(pair%face_nodes(:, f))
        node = pair%face_nodes(i, f)
        node_faces(fill(node)) = f
        fill(node) = fill(node) + 1
      end do
    end do
    allocate (pair%neighbor_ptr(nf + 1), pair%neighbors(0))
    pair%neighbor_ptr(1) = 1
    do f = 1, nf
      allocate (found(0))
      do i = 1, face_node_count(pair%face_nodes(:, f))
        node = pair%face_nodes(i, f)
        found = [found, (node_faces(j), j = node_ptr(node), node_ptr(node + 1) - 1)]
      end do
      found = unique_sorted(found)
      pair%neighbors = [pair%neighbors, found]
      pair%neighbor_ptr(f + 1) = pair%neighbor_ptr(f) + size(found)
      deallocate (found)
    end do
  end subroutine face_neighbours

  !> Which face edges bound the master surface: an edge is free when no other face of the
  !> pair has both its corner nodes (faces sharing a node are the only candidates). The
  !> fourth edge of a triangle does not exist and is never free.
  pure subroutine free_edges(pair)
    type(contact_pair_t), intent(inout) :: pair
    integer :: f, k, j, other, a, b, corners
    allocate (pair%free_edge(4, size(pair%face_nodes, 2)))
    pair%free_edge = .true.
    do f = 1, size(pair%face_nodes, 2)
      corners = 4
      if (is_triangle(face_node_count(pair%face_nodes(:, f)))) then
        corners = 3
        pair%free_edge(4, f) = .false.
      end if
      do k = 1, corners
        a = pair%face_nodes(k, f)
        b = pair%face_nodes(mod(k, corners) + 1, f)
        do j = pair%neighbor_ptr(f), pair%neighbor_ptr(f + 1) - 1
          other = pair%neighbors(j)
          if (other == f) cycle
          if (any(pair%face_nodes(:, other) == a) .and. any(pair%face_nodes(:, other) == b)) &
            pair%free_edge(k, f) = .false.
        end do
      end do
    end do
  end subroutine free_edges

  !> Global search of one point: grid candidates, then the projection rule.
  subroutine search(pair, x, xs, face, point, gap)
    type(contact_pair_t), intent(in) :: pair
    real(dp), intent(in) :: x(:, :), xs(3)
    integer, intent(out) :: face
    type(segment_point_t), intent(out) :: point
    real(dp), intent(out) :: gap
    integer, allocatable :: candidates(:)
    call pair%grid%candidates(xs, candidates)
    call closest_face(pair%face_nodes, x, candidates, xs, pair%reach, face, point, gap, pair%free_edge, &
                      extend=.true.)
  end subroutine search

  !> Where a closed node's contact point is now: its face if the projection stays on it (or
  !> within the extension past a free edge), else the face chosen by the search rule among
  !> the faces sharing a node with it and those the search grid holds near the node (a
  !> neighbouring master body that shares no node with it); face = 0: nothing in reach, or
  !> the node has slid off the master surface.
  subroutine follow(pair, x, xs, face_old, xi_old, face, p, gap)
    type(contact_pair_t), intent(in) :: pair
    real(dp), intent(in) :: x(:, :), xs(3), xi_old(2)
    integer, intent(in) :: face_old
    integer, intent(out) :: face
    type(segment_point_t), intent(out) :: p
    real(dp), intent(out) :: gap
    integer, allocatable :: candidates(:)
    real(dp) :: excess(4)
    logical :: converged
    integer, allocatable :: nodes(:)
    nodes = pair_face_nodes(pair, face_old)
    call project_to_segment(x(:, nodes), xs, xi_old, p, gap, converged)
    face = face_old
    if (converged) then
      excess = edge_excess(p%xi, size(nodes))
      if (all(excess <= XI_TOLERANCE)) return
    end if
    call pair%grid%candidates(xs, candidates)
    candidates = unique_sorted([candidates, pair%neighbors(pair%neighbor_ptr(face_old): &
                                                           pair%neighbor_ptr(face_old + 1) - 1)])
    call closest_face(pair%face_nodes, x, candidates, xs, pair%reach, face, p, gap, pair%free_edge, &
                      extend=.true.)
  end subroutine follow

end module fcs_contact_pair
