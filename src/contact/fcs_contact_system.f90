!> The contact system: every node-to-point contact pair of the model (Xing, Mora &
!> Makinouchi 2003, section 2), with what the stepper needs each increment:
!>   - `cliques`: slave node + master face nodes for the sparse pattern (the current face and
!>     its neighbours, so that sliding rarely changes the pattern);
!>   - `assemble`: contact forces R f and tangents K_f (eqs. 8-10) of every closed node;
!>   - `events`: the R-minimum fractions of the trial increment at which a node closes
!>     (gap reaches 0), opens (normal force reaches 0), starts to slip (F = 0, eq. 3) or
!>     leaves its master segment (a return to stick, when slip reverses or unloads, is
!>     handled at the start of the increment by `switch_states` and a re-solve, as elastic
!>     unloading in plasticity);
!>   - `update`: the return mapping of every closed node (eq. 5) on the new configuration,
!>     segment hand-over while sliding, search for the open nodes, state changes.
module fcs_contact_system
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error, input_error
  use fcs_model, only: model_t, contact_pair_def_t
  use fcs_mesh, only: mesh_t, hex8_face_nodes, SURFACE_FACES
  use fcs_contact_geometry, only: segment_point_t, segment_point, project_to_segment, &
                                  calculix_tangents
  use fcs_contact_search, only: face_grid_t, closest_face, edge_excess, edge_support, XI_TOLERANCE, &
                                EDGE_EXTENSION
  use fcs_contact_element, only: contact_linear_t, contact_linearise, contact_update, &
                                 contact_update_t, contact_node_t, contact_params_t, CONTACT_OPEN, &
                                 CONTACT_STICK, CONTACT_SLIP, CONTACT_TIED
  use fcs_contact_state, only: contact_state_t
  use fcs_contact_areas, only: slave_node_areas, surface_face_nodes
  use fcs_contact_ties, only: tie_set_t
  use fcs_friction_law, only: friction_law_t, friction_derivatives_t
  use fcs_friction_factory, only: create_friction_law, friction_def_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_rmin_events, only: rmin_collector_t, EVENT_CONTACT_CLOSE, EVENT_CONTACT_OPEN, &
                             EVENT_STICK_TO_SLIP, EVENT_SEGMENT_CHANGE, &
                             EVENT_NONE
  use fcs_sort, only: unique_sorted, argsort_integers
  use fcs_strings, only: str
  implicit none
  private
  public :: contact_system_t, contact_pair_t, pair_totals_t

  !> Gaps within this fraction of the mean master face size count as touching.
  real(dp), parameter :: GAP_TOLERANCE = 1.0e-8_dp
  !> Largest penetration allowed, as a fraction of the mean master face size.
  real(dp), parameter :: PENETRATION_LIMIT = 0.05_dp
  !> A node whose event (close, open, stick to slip) was taken in an increment gets the
  !> event's state when, on the solution of the increment, it has come within this fraction
  !> of the way to the event from where it started (the linearisation error of the event's
  !> fraction); otherwise the corrected solution has moved it away and its state is decided
  !> as for any node.
  real(dp), parameter :: EVENT_BAND = 1.0e-2_dp
  !> A stick node within this fraction of its cone (|f_t| >= (1 - STICK_BAND) mu f_n) that the
  !> increment loads slips at its start instead of at an event at a tiny fraction r: round-off
  !> fluctuations of the normal force no longer cost an increment each (a first slip moves
  !> earlier by at most the time the load takes to grow by this fraction).
  real(dp), parameter :: STICK_BAND = 1.0e-4_dp
  !> A node held on its face during equilibrium iterations stays on it up to this distance
  !> (natural coordinates) past a shared edge; farther, the search rule decides again.
  real(dp), parameter :: HOLD_LIMIT = 0.5_dp
  !> How a node is held through equilibrium iterations.
  integer, parameter :: HOLD_NONE = 0, HOLD_CLOSED = 1, HOLD_OPEN = 2
  !> Largest number of changes of a held state in one increment.
  integer, parameter :: MAX_HOLD_FLIPS = 2
  !> Contact points within this distance (natural coordinates) of a segment edge are on it.
  real(dp), parameter :: SEGMENT_EDGE_TOLERANCE = 1.0e-6_dp

  type :: contact_pair_t
    character(len=:), allocatable :: name
    logical :: tied = .false.
    real(dp) :: normal_stiffness = 0.0_dp
    real(dp) :: stick_stiffness = 0.0_dp
    !> Radiation damping eta [stress time/length] of the pair (0: none).
    real(dp) :: radiation_damping = 0.0_dp
    !> Mean master face size; search reach for open nodes; tie position tolerance.
    real(dp) :: face_size = 0.0_dp
    real(dp) :: reach = 0.0_dp
    real(dp) :: position_tolerance = 0.0_dp
    class(friction_law_t), allocatable :: law
    !> Master faces (4 global node indices each, outward) and the faces sharing a node with
    !> each face (itself included): neighbors(neighbor_ptr(f):neighbor_ptr(f+1)-1).
    integer, allocatable :: face_nodes(:, :)
    integer, allocatable :: neighbor_ptr(:), neighbors(:)
    !> free_edge(k, f): edge k of face f (k = 1..4: nodes 1-2, 2-3, 3-4, 4-1, i.e. the edges
    !> xi_2 = -1, xi_1 = 1, xi_2 = 1, xi_1 = -1) bounds the master surface (no other face
    !> of the pair shares it).
    logical, allocatable :: free_edge(:, :)
    type(face_grid_t) :: grid
    !> Slave entries of this pair in the contact state: first..last.
    integer :: first = 1
    integer :: last = 0
    !> Slave nodes of the surface left out of this (untied) pair because a tie holds them.
    integer :: n_held_by_tie = 0
  end type contact_pair_t

  !> Sums over a pair, for the log and histories.
  type :: pair_totals_t
    real(dp) :: normal_force = 0.0_dp
    real(dp) :: tangential_force(3) = 0.0_dp
    integer :: n_stick = 0
    integer :: n_slip = 0
    integer :: n_open = 0
    integer :: n_tied = 0
  end type pair_totals_t

  type :: contact_system_t
    type(contact_pair_t), allocatable :: pairs(:)
    !> For each slave entry: its node, pair, tributary area.
    integer, allocatable :: slave_node(:), slave_pair(:)
    real(dp), allocatable :: area(:)
    !> Face each slave's pattern clique was built around (0: none) and whether the pattern
    !> must be rebuilt before the next assembly.
    integer, allocatable :: pattern_face(:)
    logical :: pattern_dirty = .false.
    !> Each slave's earliest event in the last trial increment (fraction and kind).
    real(dp), allocatable :: event_r(:)
    integer, allocatable :: event_kind(:)
    !> How often each node's stick/slip tangent was switched in the current increment.
    integer, allocatable :: switches(:)
    !> During the equilibrium iterations of an increment each closed node keeps the master
    !> face its first application chose (0: none): Newton's method then sees a smooth
    !> contact geometry, not a node flipping between two faces at a (slightly) kinked edge.
    integer, allocatable :: held_face(:)
    !> ... and its open or closed state (HOLD_OPEN, HOLD_CLOSED; HOLD_NONE for tied nodes),
    !> and how often check_held changed that in the increment.
    integer, allocatable :: hold_status(:), flips(:)
    logical :: holding = .false.
    !> Face and natural coordinates of every node at the start of the increment being
    !> applied (recorded by `update`).
    integer, allocatable :: start_face(:)
    real(dp), allocatable :: start_xi(:, :)
    !> The next entry of the same node in another pair (0: none; see find_twins).
    integer, allocatable :: twin(:)
    !> Tied pairs, as segment-to-segment penalty ties (their slave nodes' entries, status
    !> TIED, only report the tie forces), and the reference coordinates their displacements
    !> are measured from.
    type(tie_set_t) :: ties
    real(dp), allocatable :: reference(:, :)
    !> Largest changes over the last increment at nodes slipping before and after it: of
    !> ln V, of mu and of ln(state); and the largest slip of the increment over the law's
    !> characteristic slip L at any slipping node (rate-and-state laws); and the node where
    !> each happened.
    real(dp) :: change(4) = 0.0_dp
    integer :: change_node(4) = 0
  contains
    procedure :: init => system_init
    procedure :: n_slaves => system_n_slaves
    procedure :: cliques => system_cliques
    procedure :: assemble => system_assemble
    procedure :: events => system_events
    procedure :: switch_states => system_switch_states
    procedure :: update => system_update
    procedure :: totals => system_totals
    procedure :: traction => system_traction
    procedure :: forces => system_forces
    procedure :: local_values => system_local_values
    procedure :: check_penetration => system_check_penetration
    procedure :: check_gaps => system_check_gaps
    procedure :: hold_states => system_hold_states
    procedure :: check_held => system_check_held
    procedure :: release_states => system_release_states
  end type contact_system_t

contains

  pure integer function system_n_slaves(this)
    class(contact_system_t), intent(in) :: this
    system_n_slaves = 0
    if (allocated(this%slave_node)) system_n_slaves = size(this%slave_node)
  end function system_n_slaves

  !> Set up every pair of the model on coordinates x and find the initial contact state.
  subroutine system_init(this, model, x, cstate, err)
    class(contact_system_t), intent(inout) :: this
    type(model_t), intent(in) :: model
    real(dp), intent(in) :: x(:, :)
    type(contact_state_t), intent(inout) :: cstate
    type(error_t), allocatable, intent(out) :: err
    integer :: k, n_total
    integer, allocatable :: slaves(:), slave_faces(:, :)
    real(dp), allocatable :: areas(:)
    logical, allocatable :: tied(:)
    allocate (this%pairs(size(model%contact_pairs)), this%slave_node(0), this%slave_pair(0), &
              this%area(0))
    do k = 1, size(model%contact_pairs)
      call setup_pair(this%pairs(k), model, model%contact_pairs(k), x, err)
      if (allocated(err)) return
    end do
    call tied_nodes(this, model, x, tied)
    this%reference = model%mesh%x
    do k = 1, size(model%contact_pairs)
      if (.not. this%pairs(k)%tied) cycle
      call surface_face_nodes(model%mesh, model%contact_pairs(k)%slave_surface, slave_faces)
      call this%ties%add(slave_faces, this%pairs(k)%face_nodes, x, this%pairs(k)%normal_stiffness, &
                         this%pairs(k)%position_tolerance)
    end do
    n_total = 0
    do k = 1, size(model%contact_pairs)
      call slave_nodes_of(model, model%contact_pairs(k), this%pairs(k), slaves)
      if (.not. this%pairs(k)%tied) then
        this%pairs(k)%n_held_by_tie = count(tied(slaves))
        slaves = pack(slaves, .not. tied(slaves))
      end if
      call slave_node_areas(model%mesh, model%contact_pairs(k)%slave_surface, slaves, areas, err)
      if (allocated(err)) then
        err%message = 'contact pair ' // model%contact_pairs(k)%name // ': ' // err%message
        return
      end if
      this%pairs(k)%first = n_total + 1
      this%pairs(k)%last = n_total + size(slaves)
      n_total = n_total + size(slaves)
      this%slave_node = [this%slave_node, slaves]
      this%slave_pair = [this%slave_pair, spread(k, 1, size(slaves))]
      this%area = [this%area, areas]
    end do
    call cstate%init(n_total)
    allocate (this%pattern_face(n_total), this%event_r(n_total), this%event_kind(n_total), &
              this%switches(n_total))
    this%switches = 0
    this%pattern_face = 0
    this%event_r = huge(1.0_dp)
    this%event_kind = EVENT_NONE
    call find_twins(this)
    call initial_state(this, x, cstate)
    this%pattern_face = cstate%face
  end subroutine system_init

  !> Faces, neighbours, penalties, friction law and search grid of one pair.
  subroutine setup_pair(pair, model, def, x, err)
    type(contact_pair_t), intent(inout) :: pair
    type(model_t), intent(in) :: model
    type(contact_pair_def_t), intent(in) :: def
    real(dp), intent(in) :: x(:, :)
    type(error_t), allocatable, intent(out) :: err
    type(friction_def_t) :: frictionless
    integer :: f, nf
    pair%name = def%name
    pair%tied = def%tied
    pair%normal_stiffness = def%normal_stiffness
    pair%stick_stiffness = def%stick_stiffness
    pair%position_tolerance = def%position_tolerance
    pair%radiation_damping = def%radiation_damping
    associate (surface => model%mesh%surfaces(def%master_surface))
      nf = size(surface%element)
      allocate (pair%face_nodes(4, nf))
      do f = 1, nf
        pair%face_nodes(:, f) = hex8_face_nodes(model%mesh, surface%element(f), surface%face(f))
      end do
    end associate
    pair%face_size = 0.0_dp
    do f = 1, nf
      pair%face_size = pair%face_size + 0.5_dp * (norm2(x(:, pair%face_nodes(3, f)) - &
        x(:, pair%face_nodes(1, f))) + norm2(x(:, pair%face_nodes(4, f)) - x(:, pair%face_nodes(2, f))))
    end do
    pair%face_size = pair%face_size / (sqrt(2.0_dp) * nf)
    pair%reach = pair%face_size
    call face_neighbours(pair, model%mesh%n_nodes)
    call free_edges(pair)
    call pair%grid%build(face_coordinates(pair, x), pair%reach)
    frictionless%law = 'COULOMB'
    frictionless%mu0 = 0.0_dp
    if (def%interaction > 0) then
      if (model%interactions(def%interaction)%has_friction) then
        call create_friction_law(model%interactions(def%interaction)%friction, pair%law, err)
        if (allocated(err)) return
      end if
    end if
    if (.not. allocated(pair%law)) call create_friction_law(frictionless, pair%law, err)
  end subroutine setup_pair

  !> Node coordinates of every master face of a pair, (3, 4, n_faces).
  pure function face_coordinates(pair, x) result(face_x)
    type(contact_pair_t), intent(in) :: pair
    real(dp), intent(in) :: x(:, :)
    real(dp) :: face_x(3, 4, size(pair%face_nodes, 2))
    integer :: f
    do f = 1, size(pair%face_nodes, 2)
      face_x(:, :, f) = x(:, pair%face_nodes(:, f))
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
      node_ptr(pair%face_nodes(:, f) + 1) = node_ptr(pair%face_nodes(:, f) + 1) + 1
    end do
    node_ptr(1) = 1
    do i = 1, n_nodes
      node_ptr(i + 1) = node_ptr(i + 1) + node_ptr(i)
    end do
    allocate (node_faces(node_ptr(n_nodes + 1) - 1))
    fill = node_ptr(1:n_nodes)
    do f = 1, nf
      do i = 1, 4
        node = pair%face_nodes(i, f)
        node_faces(fill(node)) = f
        fill(node) = fill(node) + 1
      end do
    end do
    allocate (pair%neighbor_ptr(nf + 1), pair%neighbors(0))
    pair%neighbor_ptr(1) = 1
    do f = 1, nf
      allocate (found(0))
      do i = 1, 4
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
  !> pair has both its nodes (faces sharing a node are the only candidates).
  pure subroutine free_edges(pair)
    type(contact_pair_t), intent(inout) :: pair
    integer :: f, k, j, other, a, b
    allocate (pair%free_edge(4, size(pair%face_nodes, 2)))
    pair%free_edge = .true.
    do f = 1, size(pair%face_nodes, 2)
      do k = 1, 4
        a = pair%face_nodes(k, f)
        b = pair%face_nodes(mod(k, 4) + 1, f)
        do j = pair%neighbor_ptr(f), pair%neighbor_ptr(f + 1) - 1
          other = pair%neighbors(j)
          if (other == f) cycle
          if (any(pair%face_nodes(:, other) == a) .and. any(pair%face_nodes(:, other) == b)) &
            pair%free_edge(k, f) = .false.
        end do
      end do
    end do
  end subroutine free_edges

  !> The nodes a tie holds: slave nodes of a tied pair within its position tolerance of its
  !> master surface (those `initial_state` ties). A node both tied and a slave of a contact
  !> pair (the end of a fault segment next to a tied segment) is left to the tie and taken
  !> out of the contact pair, as Abaqus does with such overconstraints: two penalty elements
  !> on one node, the tie's and a frictional one, would otherwise both act on it and the
  !> frictional one would record a slip the tie does not allow.
  subroutine tied_nodes(this, model, x, tied)
    type(contact_system_t), intent(in) :: this
    type(model_t), intent(in) :: model
    real(dp), intent(in) :: x(:, :)
    logical, allocatable, intent(out) :: tied(:)
    type(segment_point_t) :: p
    integer, allocatable :: slaves(:)
    integer :: k, i, face
    real(dp) :: gap
    allocate (tied(model%mesh%n_nodes))
    tied = .false.
    do k = 1, size(this%pairs)
      if (.not. this%pairs(k)%tied) cycle
      call slave_nodes_of(model, model%contact_pairs(k), this%pairs(k), slaves)
      do i = 1, size(slaves)
        call search(this%pairs(k), x, x(:, slaves(i)), face, p, gap)
        if (face /= 0) tied(slaves(i)) = tied(slaves(i)) .or. &
                                         abs(gap) <= this%pairs(k)%position_tolerance
      end do
    end do
  end subroutine tied_nodes

  !> Slave nodes of a pair: the slave surface's nodes, less those on the master surface.
  subroutine slave_nodes_of(model, def, pair, slaves)
    type(model_t), intent(in) :: model
    type(contact_pair_def_t), intent(in) :: def
    type(contact_pair_t), intent(in) :: pair
    integer, allocatable, intent(out) :: slaves(:)
    integer, allocatable :: all(:), master(:)
    logical, allocatable :: on_master(:)
    integer :: i
    all = model%mesh%surface_node_list(def%slave_surface)
    master = unique_sorted(reshape(pair%face_nodes, [size(pair%face_nodes)]))
    allocate (on_master(model%mesh%n_nodes))
    on_master = .false.
    on_master(master) = .true.
    slaves = pack(all, [(.not. on_master(all(i)), i = 1, size(all))])
  end subroutine slave_nodes_of

  !> Initial search: tied nodes within the position tolerance are tied at their initial gap;
  !> other nodes are closed (stick) if they already penetrate.
  subroutine initial_state(this, x, cstate)
    type(contact_system_t), intent(inout) :: this
    real(dp), intent(in) :: x(:, :)
    type(contact_state_t), intent(inout) :: cstate
    type(segment_point_t) :: p
    type(contact_update_t) :: u
    integer :: s, face
    real(dp) :: gap
    do s = 1, size(this%slave_node)
      associate (pair => this%pairs(this%slave_pair(s)))
        call search(pair, x, x(:, this%slave_node(s)), face, p, gap)
        cstate%face(s) = face
        cstate%status(s) = CONTACT_OPEN
        cstate%mu(s) = pair%law%mu(0.0_dp, 0.0_dp, pair%law%initial_state())
        cstate%friction_state(s) = pair%law%initial_state()
        if (face == 0) cycle
        cstate%xi(:, s) = p%xi
        cstate%gap(s) = gap
        if (pair%tied) then
          if (abs(gap) > pair%position_tolerance) then
            cstate%face(s) = 0
            cycle
          end if
          cstate%status(s) = CONTACT_TIED
          cstate%tied_gap(s) = gap
        else if (gap <= GAP_TOLERANCE * pair%face_size) then
          u = contact_update(p, gap, p, node_of(cstate, s, CONTACT_STICK), params_of(this, s, face, p%xi), &
                             pair%law, 0.0_dp)
          cstate%status(s) = closing_status(u%mu)
          cstate%normal_force(s) = u%normal_force
          cstate%mu(s) = u%mu
        end if
      end associate
    end do
  end subroutine initial_state

  !> The state a node closes in: stick, or slip on a frictionless interface (mu = 0), whose
  !> cone has no interior (a stick node there would reach the cone at once, an R-minimum
  !> event at r = 0 that costs one increment at the minimum size per closing node).
  pure integer function closing_status(mu) result(status)
    real(dp), intent(in) :: mu
    status = CONTACT_STICK
    if (mu <= 0.0_dp) status = CONTACT_SLIP
  end function closing_status

  !> The kernel's view of slave s (status as given).
  pure function node_of(cstate, s, status) result(node)
    type(contact_state_t), intent(in) :: cstate
    integer, intent(in) :: s, status
    type(contact_node_t) :: node
    node%status = status
    node%normal_force = cstate%normal_force(s)
    node%friction = cstate%friction(:, s)
    node%trial_norm = max(cstate%trial_norm(s), norm2(cstate%friction(:, s)))
    node%friction_state = cstate%friction_state(s)
    node%tied_gap = cstate%tied_gap(s)
    node%slip_rate = cstate%slip_rate(s)
  end function node_of

  !> The friction coefficient of slave s's cone in the coming increment: the one in use, or
  !> for a law with an explicit rate mu at the slip rate of the last increment (during the
  !> equilibrium iterations, the one of the increment's return mapping).
  real(dp) function cone_mu(this, s, cstate) result(mu)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    type(contact_state_t), intent(in) :: cstate
    associate (law => this%pairs(this%slave_pair(s))%law)
      ! During the equilibrium iterations of an increment the state is an iterate whose
      ! slip rate is the increment's own: its cone is the one its return mapping used.
      if (law%explicit_rate .and. .not. this%holding) then
        mu = law%mu(cstate%normal_force(s) / this%area(s), cstate%slip_rate(s), &
                    cstate%friction_state(s))
      else
        mu = cstate%mu(s)
      end if
    end associate
  end function cone_mu

  !> Area and penalties of slave s, and the support of its master segment `face` at natural
  !> point xi (1 when not given: tied nodes).
  pure function params_of(this, s, face, xi) result(params)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    integer, intent(in), optional :: face
    real(dp), intent(in), optional :: xi(2)
    type(contact_params_t) :: params
    params%area = this%area(s)
    params%normal_stiffness = this%pairs(this%slave_pair(s))%normal_stiffness
    params%stick_stiffness = this%pairs(this%slave_pair(s))%stick_stiffness
    params%damping = this%pairs(this%slave_pair(s))%radiation_damping
    if (present(face) .and. present(xi)) call edge_support(xi, &
      this%pairs(this%slave_pair(s))%free_edge(:, face), params%support, params%dsupport)
  end function params_of

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

  !> Cliques for the sparse pattern: each slave with a face, with the nodes of that face and
  !> of its neighbours. Appended to clique_ptr/clique_nodes. The faces are the current ones,
  !> or with `keep_centres` those of the last pattern (after a restart, so that the pattern,
  !> and with it every floating-point result, is the one of the interrupted run).
  !> Only the slaves marked in `owned` (all if absent) contribute cliques: each process
  !> holds the contact elements it assembles.
  subroutine system_cliques(this, cstate, clique_ptr, clique_nodes, keep_centres, owned)
    class(contact_system_t), intent(inout) :: this
    type(contact_state_t), intent(in) :: cstate
    integer, allocatable, intent(inout) :: clique_ptr(:), clique_nodes(:)
    logical, intent(in), optional :: keep_centres
    logical, intent(in), optional :: owned(:)
    integer, allocatable :: nodes(:)
    integer :: s, j, f
    logical :: keep
    keep = .false.
    if (present(keep_centres)) keep = keep_centres
    do s = 1, size(this%slave_node)
      if (.not. keep) this%pattern_face(s) = cstate%face(s)
      f = this%pattern_face(s)
      if (f == 0) cycle
      if (present(owned)) then
        if (.not. owned(s)) cycle
      end if
      associate (pair => this%pairs(this%slave_pair(s)))
        nodes = [this%slave_node(s)]
        do j = pair%neighbor_ptr(f), pair%neighbor_ptr(f + 1) - 1
          nodes = [nodes, pair%face_nodes(:, pair%neighbors(j))]
        end do
      end associate
      nodes = unique_sorted(nodes)
      clique_nodes = [clique_nodes, nodes]
      clique_ptr = [clique_ptr, clique_ptr(size(clique_ptr)) + size(nodes)]
    end do
    if (owns_ties(owned)) call this%ties%cliques(clique_ptr, clique_nodes)
    if (.not. keep) this%pattern_dirty = .false.
  end subroutine system_cliques

  !> The process that assembles the ties: the one that owns the first slave entry (rank 0),
  !> or every caller that passes no ownership.
  pure logical function owns_ties(owned)
    logical, intent(in), optional :: owned(:)
    owns_ties = .true.
    if (.not. present(owned)) return
    if (size(owned) > 0) owns_ties = owned(1)
  end function owns_ties

  !> Linearisation of closed node s on coordinates x; dt is the trial time increment the
  !> rate term of the friction law refers to.
  subroutine linearise(this, s, x, cstate, dt, lin)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    real(dp), intent(in) :: x(:, :), dt
    type(contact_state_t), intent(in) :: cstate
    type(contact_linear_t), intent(out) :: lin
    type(segment_point_t) :: p, p_start
    type(friction_derivatives_t) :: fr
    type(contact_node_t) :: node
    type(contact_params_t) :: params
    real(dp) :: x5(3, 5)
    integer :: start_face
    associate (pair => this%pairs(this%slave_pair(s)))
      x5(:, 1) = x(:, this%slave_node(s))
      x5(:, 2:5) = x(:, pair%face_nodes(:, cstate%face(s)))
      p = segment_point(x5(:, 2:5), cstate%xi(:, s))
      fr = pair%law%evaluate(cstate%normal_force(s) / this%area(s), cstate%slip_rate(s), &
                             cstate%friction_state(s))
      fr%mu = cone_mu(this, s, cstate)
      node = node_of(cstate, s, cstate%status(s))
      node%bilateral = hold_mode(this, s) == HOLD_CLOSED
      params = params_of(this, s, cstate%face(s), cstate%xi(:, s))
      ! An explicit rate is known at the start of the increment: no dmu/dV in the tangent (its
      ! rate term is then the radiation damping's alone, 0 without damping).
      if (pair%law%explicit_rate) fr%dmu_drate = 0.0_dp
      start_face = 0
      if (this%holding) start_face = this%start_face(s)
      if (start_face == 0) then
        call contact_linearise(x5, p, cstate%gap(s), node, params, fr, dt, lin)
      else
        ! An iterate of the equilibrium iterations: it has slipped since the start point.
        p_start = segment_point(x(:, pair%face_nodes(:, start_face)), this%start_xi(:, s))
        if (start_face == cstate%face(s)) then
          call contact_linearise(x5, p, cstate%gap(s), node, params, fr, dt, lin, &
                                 p%x - p_start%x, p_start%shape)
        else
          call contact_linearise(x5, p, cstate%gap(s), node, params, fr, dt, lin, &
                                 p%x - p_start%x)
        end if
      end if
    end associate
  end subroutine linearise

  !> The 5 nodes of slave s's contact element.
  pure function element_nodes(this, s, cstate) result(nodes)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    type(contact_state_t), intent(in) :: cstate
    integer :: nodes(5)
    nodes(1) = this%slave_node(s)
    nodes(2:5) = this%pairs(this%slave_pair(s))%face_nodes(:, cstate%face(s))
  end function element_nodes

  !> Add K_f of every closed node to `matrix` and its forces R f to f_contact (3*n_nodes).
  subroutine system_assemble(this, x, cstate, dt, matrix, f_contact, err, owned)
    class(contact_system_t), intent(inout) :: this
    real(dp), intent(in) :: x(:, :), dt
    type(contact_state_t), intent(in) :: cstate
    type(sparse_matrix_t), intent(inout) :: matrix
    real(dp), intent(inout) :: f_contact(:)
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: owned(:)
    type(contact_linear_t) :: lin
    integer :: s, a, nodes(5)
    logical :: missing
    if (owns_ties(owned)) then
      call this%ties%assemble(x - this%reference, matrix, f_contact, missing)
      if (missing) then
        call fatal_error(err, 'internal error: a tied face pair is not in the sparse pattern')
        return
      end if
    end if
    do s = 1, size(this%slave_node)
      if (cstate%status(s) == CONTACT_OPEN .or. cstate%status(s) == CONTACT_TIED) cycle
      if (present(owned)) then
        if (.not. owned(s)) cycle
      end if
      call linearise(this, s, x, cstate, dt, lin)
      nodes = element_nodes(this, s, cstate)
      call matrix%add_matrix(nodes, lin%stiffness, missing)
      if (missing) then
        call fatal_error(err, 'internal error: contact element of node ' // str(nodes(1)) // &
                         ' is not in the sparse pattern')
        return
      end if
      do a = 1, 5
        f_contact(3 * nodes(a) - 2:3 * nodes(a)) = f_contact(3 * nodes(a) - 2:3 * nodes(a)) + &
          lin%force(3 * a - 2:3 * a)
      end do
    end do
  end subroutine system_assemble

  !> Offer the R-minimum events of the trial increment to the collector. The trial path is
  !> du(r) = du_fixed + r du_scaled (the out-of-balance correction is applied in full, the
  !> load increment scaled by r); contact quantities are linear in du (their linearisation).
  subroutine system_events(this, x, cstate, du_fixed, du_scaled, collector)
    class(contact_system_t), intent(inout) :: this
    real(dp), intent(in) :: x(:, :), du_fixed(:), du_scaled(:)
    type(contact_state_t), intent(in) :: cstate
    type(rmin_collector_t), intent(inout) :: collector
    type(contact_linear_t) :: lin
    type(segment_point_t) :: p
    real(dp) :: due_fixed(15), due_scaled(15), g_start, g_end
    integer :: s, a, nodes(5)
    this%event_r = huge(1.0_dp)
    this%event_kind = EVENT_NONE
    ! The switch passes of this increment are over: the next increment's start afresh.
    this%switches = 0
    do s = 1, size(this%slave_node)
      if (cstate%face(s) == 0 .or. cstate%status(s) == CONTACT_TIED) cycle
      nodes = element_nodes(this, s, cstate)
      do a = 1, 5
        due_fixed(3 * a - 2:3 * a) = du_fixed(3 * nodes(a) - 2:3 * nodes(a))
        due_scaled(3 * a - 2:3 * a) = du_scaled(3 * nodes(a) - 2:3 * nodes(a))
      end do
      if (cstate%status(s) == CONTACT_OPEN) then
        p = segment_point(x(:, nodes(2:5)), cstate%xi(:, s))
        g_start = cstate%gap(s) + relative_normal(p, due_fixed)
        g_end = g_start + relative_normal(p, due_scaled)
        if (cstate%gap(s) > 0.0_dp .and. g_end < 0.0_dp) &
          call offer(this, collector, s, crossing(g_start, g_end), EVENT_CONTACT_CLOSE)
        cycle
      end if
      call linearise(this, s, x, cstate, 0.0_dp, lin)
      p = segment_point(x(:, nodes(2:5)), cstate%xi(:, s))
      call closed_node_events(this, s, p, cstate, lin, due_fixed, due_scaled, collector)
    end do
  end subroutine system_events

  !> n.(du_s - sum N_I du_I): the gap change for nodal increments due(15).
  pure real(dp) function relative_normal(p, due)
    type(segment_point_t), intent(in) :: p
    real(dp), intent(in) :: due(15)
    relative_normal = dot_product(p%normal, due(1:3) - matmul(reshape(due(4:15), [3, 4]), p%shape))
  end function relative_normal

  !> Fraction at which a quantity going linearly from v_start (r = 0) to v_end (r = 1)
  !> reaches zero (0 if it starts at or beyond zero).
  pure real(dp) function crossing(v_start, v_end) result(r)
    real(dp), intent(in) :: v_start, v_end
    if (v_start * v_end >= 0.0_dp .and. abs(v_start) <= abs(v_end)) then
      r = 0.0_dp
    else
      r = v_start / (v_start - v_end)
    end if
  end function crossing

  !> State changes at the very start of the trial increment (r = 0), handled as in
  !> elastic-plastic unloading (Yamada et al. 1968): a slipping node whose elastic (stick)
  !> predictor stays inside the Coulomb cone unloads, and a sticking node on the cone whose
  !> predictor leaves it at once slips; their tangents are switched and the caller solves the
  !> increment again. Each node switches at most 10 times per increment (no endless flip-flop).
  !> `n_switched` counts the switches made.
  subroutine system_switch_states(this, x, cstate, du, n_switched)
    class(contact_system_t), intent(inout) :: this
    real(dp), intent(in) :: x(:, :), du(:)
    type(contact_state_t), intent(inout) :: cstate
    integer, intent(out) :: n_switched
    type(contact_linear_t) :: lin
    type(segment_point_t) :: p
    real(dp) :: due(15), fn, dfn, ft(3), dft(3), mu, qa, qb, qc, tolerance
    integer :: s, a, nodes(5)
    logical :: on_cone
    n_switched = 0
    do s = 1, size(this%slave_node)
      if (cstate%status(s) /= CONTACT_STICK .and. cstate%status(s) /= CONTACT_SLIP) cycle
      if (this%switches(s) >= 10) cycle
      nodes = element_nodes(this, s, cstate)
      do a = 1, 5
        due(3 * a - 2:3 * a) = du(3 * nodes(a) - 2:3 * nodes(a))
      end do
      call linearise(this, s, x, cstate, 0.0_dp, lin)
      p = segment_point(x(:, nodes(2:5)), cstate%xi(:, s))
      fn = cstate%normal_force(s)
      dfn = dot_product(lin%dfn, due)
      ! A node closed at (numerically) zero normal force that the trial increment pulls into
      ! tension separates now: closed_node_events offers no opening event below the force
      ! floor, so its penalty spring would otherwise hold the bodies together in tension for
      ! the whole increment.
      if (fn <= normal_force_floor(this, s) .and. fn + dfn < 0.0_dp) then
        call open_node(cstate, s, cstate%face(s), p, cstate%gap(s))
        this%switches(s) = this%switches(s) + 1
        n_switched = n_switched + 1
        cycle
      end if
      ft = cstate%friction(1, s) * p%e(:, 1) + cstate%friction(2, s) * p%e(:, 2)
      if (norm2(ft) <= 0.0_dp) cycle
      mu = cone_mu(this, s, cstate)
      dft = matmul(lin%dft_stick, due)
      qa = dot_product(dft, dft) - mu**2 * dfn**2
      qb = 2.0_dp * (dot_product(ft, dft) - mu**2 * fn * dfn)
      qc = dot_product(ft, ft) - mu**2 * fn**2
      tolerance = cone_tolerance(fn, ft, dfn, dft, mu)
      ! A slip node counts as on the cone down to the event band (|f_t| >= (1 - EVENT_BAND)
      ! mu f_n): one that a small rise of its normal force has left a hair inside keeps
      ! slipping unless the increment unloads it (hysteresis: no slip->stick->slip chatter of
      ! nodes that sit on the cone while their normal force fluctuates, e.g. in a rigid
      ! rotation). A stick node must come within the much narrower STICK_BAND: otherwise its
      ! stick->slip change is an event at the crossing (closed_node_events), so first slips
      ! keep their times (a 1 % band moved the fault-bend run's first slip by 2 %).
      if (cstate%status(s) == CONTACT_SLIP) then
        on_cone = qc >= -max(tolerance, (1.0_dp - (1.0_dp - EVENT_BAND)**2) * (mu * fn)**2)
      else
        on_cone = qc >= -max(tolerance, (1.0_dp - (1.0_dp - STICK_BAND)**2) * (mu * fn)**2)
      end if
      if (cstate%status(s) == CONTACT_SLIP) then
        if (.not. on_cone .or. (qb < -tolerance .or. (abs(qb) <= tolerance .and. qa < 0.0_dp))) then
          cstate%status(s) = CONTACT_STICK
          this%switches(s) = this%switches(s) + 1
          n_switched = n_switched + 1
        end if
      else if (on_cone .and. (qb > tolerance .or. (abs(qb) <= tolerance .and. qa > 0.0_dp))) then
        cstate%status(s) = CONTACT_SLIP
        cstate%trial_norm(s) = norm2(ft)
        this%switches(s) = this%switches(s) + 1
        n_switched = n_switched + 1
      end if
    end do
  end subroutine system_switch_states

  !> The normal force of slave s below which it counts as zero: the penalty force of a
  !> penetration of GAP_TOLERANCE times the pair's mean master face size.
  pure real(dp) function normal_force_floor(this, s) result(floor)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    associate (pair => this%pairs(this%slave_pair(s)))
      floor = GAP_TOLERANCE * pair%normal_stiffness * this%area(s) * pair%face_size
    end associate
  end function normal_force_floor

  !> Opening, stick-to-slip (the quadratic F(r) = 0 of eq. 3), segment exit, along the
  !> path du_fixed + r du_scaled.
  subroutine closed_node_events(this, s, p, cstate, lin, due_fixed, due_scaled, collector)
    type(contact_system_t), intent(inout) :: this
    integer, intent(in) :: s
    type(segment_point_t), intent(in) :: p
    type(contact_state_t), intent(in) :: cstate
    type(contact_linear_t), intent(in) :: lin
    real(dp), intent(in) :: due_fixed(15), due_scaled(15)
    type(rmin_collector_t), intent(inout) :: collector
    real(dp) :: fn, dfn, ft(3), dft(3), mu, qa, qb, qc, xi_start(2), dxi(2), r, fn_floor, bound
    integer :: alpha, edge
    associate (pair => this%pairs(this%slave_pair(s)))
      fn = cstate%normal_force(s) + dot_product(lin%dfn, due_fixed)
      dfn = dot_product(lin%dfn, due_scaled)
      fn_floor = normal_force_floor(this, s)
      if (cstate%normal_force(s) > fn_floor .and. fn + dfn < 0.0_dp) &
        call offer(this, collector, s, crossing(fn, fn + dfn), EVENT_CONTACT_OPEN)
      ft = cstate%friction(1, s) * p%e(:, 1) + cstate%friction(2, s) * p%e(:, 2) + &
           matmul(lin%dft_stick, due_fixed)
      mu = cone_mu(this, s, cstate)
      if (cstate%status(s) == CONTACT_STICK) then
        dft = matmul(lin%dft_stick, due_scaled)
        qa = dot_product(dft, dft) - mu**2 * dfn**2
        qb = 2.0_dp * (dot_product(ft, dft) - mu**2 * fn * dfn)
        qc = dot_product(ft, ft) - mu**2 * fn**2
        r = cone_crossing(qa, qb, qc, cone_tolerance(fn, ft, dfn, dft, mu))
        if (r <= 1.0_dp) call offer(this, collector, s, r, EVENT_STICK_TO_SLIP)
      end if
      xi_start = cstate%xi(:, s) + matmul(lin%dxi, due_fixed)
      dxi = matmul(lin%dxi, due_scaled)
      do alpha = 1, 2
        ! Reaching a shared edge (hand-over to the next segment), or the end of the extension
        ! past a free edge (the node leaves the master surface). A node already on a shared
        ! edge (nodes on master nodes or edges) changes segment by the hand-over rule in the
        ! update; no event is needed.
        if (alpha == 1) then
          edge = merge(4, 2, xi_start(alpha) + dxi(alpha) < 0.0_dp)
        else
          edge = merge(1, 3, xi_start(alpha) + dxi(alpha) < 0.0_dp)
        end if
        bound = 1.0_dp
        if (pair%free_edge(edge, cstate%face(s))) bound = 1.0_dp + EDGE_EXTENSION
        if (abs(cstate%xi(alpha, s)) < bound - SEGMENT_EDGE_TOLERANCE .and. &
            abs(xi_start(alpha) + dxi(alpha)) > bound) &
          call offer(this, collector, s, crossing(abs(xi_start(alpha)) - bound, &
                     abs(xi_start(alpha) + dxi(alpha)) - bound), EVENT_SEGMENT_CHANGE)
      end do
    end associate
  end subroutine closed_node_events

  !> New contact state on the coordinates x after an increment of duration dt whose
  !> fraction of the trial increment was r: the return mapping of every closed node (eq. 5),
  !> segment hand-over, opening, and the search for open nodes. Events whose fractions were
  !> within r are applied even when round-off leaves the node a hair short of them. The
  !> events of the increment are kept, so that an equilibrium iteration applying the
  !> corrected increment again from its start decides the same events.
  subroutine system_update(this, x, cstate, dt, r)
    class(contact_system_t), intent(inout) :: this
    real(dp), intent(in) :: x(:, :), dt, r
    type(contact_state_t), intent(inout) :: cstate
    integer :: k, s, kind
    real(dp), allocatable :: tie_force(:)
    real(dp) :: old_rate, old_mu, old_state
    logical :: was_slipping
    do k = 1, size(this%pairs)
      if (this%pairs(k)%grid%needs_rebuild(this%pairs(k)%face_nodes, x)) &
        call this%pairs(k)%grid%build(face_coordinates(this%pairs(k), x), this%pairs(k)%reach)
    end do
    this%change = 0.0_dp
    this%change_node = 0
    ! Where every node starts the increment (each application of an increment starts from the
    ! same state): the equilibrium iterations linearise about the slip since then.
    this%start_face = cstate%face
    this%start_xi = cstate%xi
    allocate (tie_force(size(x)))
    tie_force = 0.0_dp
    call this%ties%forces(x - this%reference, tie_force)
    do s = 1, size(this%slave_node)
      was_slipping = cstate%status(s) == CONTACT_SLIP .and. cstate%slip_rate(s) > 0.0_dp
      old_rate = cstate%slip_rate(s)
      old_mu = cstate%mu(s)
      old_state = cstate%friction_state(s)
      kind = EVENT_NONE
      if (this%event_r(s) <= r * (1.0_dp + 1.0e-9_dp)) kind = this%event_kind(s)
      select case (cstate%status(s))
      case (CONTACT_TIED)
        call update_tied(this, s, x, cstate, tie_force)
      case (CONTACT_STICK, CONTACT_SLIP)
        call update_closed(this, s, x, cstate, dt, kind)
      case default
        call update_open(this, s, x, cstate, kind)
      end select
      if (cstate%face(s) /= 0) then
        if (.not. in_pattern(this, s, cstate%face(s))) this%pattern_dirty = .true.
      end if
      if (was_slipping .and. cstate%status(s) == CONTACT_SLIP .and. cstate%slip_rate(s) > 0.0_dp) &
        call record_friction_changes(this, s, old_rate, old_mu, old_state, cstate)
      if (cstate%status(s) == CONTACT_SLIP) call record_slip_increment(this, s, cstate%slip_rate(s) * dt)
    end do
    call leave_to_twins(this, cstate)
  end subroutine system_update

  !> A node that is a slave of several pairs (one slave surface against master bodies side by
  !> side) touches one master at a time: an entry whose contact point lies in the extension
  !> past a free edge of its master opens when another entry of the same node is closed
  !> strictly on its own master (the node has crossed the joint), so that the joint does not
  !> carry it twice.
  subroutine leave_to_twins(this, cstate)
    type(contact_system_t), intent(in) :: this
    type(contact_state_t), intent(inout) :: cstate
    type(segment_point_t) :: p
    integer :: s
    if (.not. allocated(this%twin)) return
    do s = 1, size(this%slave_node)
      if (this%twin(s) == 0) cycle
      if (.not. in_extension(this, s, cstate)) cycle
      if (.not. twin_inside(this, s, cstate)) cycle
      p%xi = cstate%xi(:, s)
      call open_node(cstate, s, cstate%face(s), p, cstate%gap(s))
    end do
  end subroutine leave_to_twins

  !> Closed entry s has its contact point past a free edge of its face (in the extension).
  pure logical function in_extension(this, s, cstate)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    type(contact_state_t), intent(in) :: cstate
    in_extension = .false.
    if (cstate%status(s) /= CONTACT_STICK .and. cstate%status(s) /= CONTACT_SLIP) return
    if (cstate%face(s) == 0) return
    in_extension = any(this%pairs(this%slave_pair(s))%free_edge(:, cstate%face(s)) .and. &
                       edge_excess(cstate%xi(:, s)) > XI_TOLERANCE)
  end function in_extension

  !> Another entry of slave s's node is closed strictly on its master face.
  pure logical function twin_inside(this, s, cstate)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    type(contact_state_t), intent(in) :: cstate
    integer :: t
    twin_inside = .false.
    t = this%twin(s)
    do while (t /= s .and. t /= 0)
      if ((cstate%status(t) == CONTACT_STICK .or. cstate%status(t) == CONTACT_SLIP) .and. &
          cstate%face(t) /= 0) then
        if (all(edge_excess(cstate%xi(:, t)) <= XI_TOLERANCE)) then
          twin_inside = .true.
          return
        end if
      end if
      t = this%twin(t)
    end do
  end function twin_inside

  !> twin(s): the next entry of the same node in another pair (a cycle through all of them),
  !> 0 for a node that is a slave of one pair only.
  subroutine find_twins(this)
    type(contact_system_t), intent(inout) :: this
    integer, allocatable :: order(:)
    integer :: i, j, first, n
    n = size(this%slave_node)
    allocate (this%twin(n))
    this%twin = 0
    order = argsort_integers(this%slave_node)
    i = 1
    do while (i <= n)
      first = i
      do while (i < n)
        if (this%slave_node(order(i + 1)) /= this%slave_node(order(first))) exit
        i = i + 1
      end do
      if (i > first) then
        do j = first, i - 1
          this%twin(order(j)) = order(j + 1)
        end do
        this%twin(order(i)) = order(first)
      end if
      i = i + 1
    end do
  end subroutine find_twins

  !> The changes of slipping node s over the increment that matter to its friction law: ln V
  !> for rate-dependent laws, mu, and the law's own state measure.
  subroutine record_friction_changes(this, s, old_rate, old_mu, old_state, cstate)
    type(contact_system_t), intent(inout) :: this
    integer, intent(in) :: s
    real(dp), intent(in) :: old_rate, old_mu, old_state
    type(contact_state_t), intent(in) :: cstate
    real(dp) :: log_rate
    associate (law => this%pairs(this%slave_pair(s))%law)
      log_rate = 0.0_dp
      if (law%rate_dependent()) log_rate = abs(log(cstate%slip_rate(s) / old_rate))
      call record_changes(this, s, [log_rate, abs(cstate%mu(s) - old_mu), &
                                    law%state_change(old_state, cstate%friction_state(s))])
    end associate
  end subroutine record_friction_changes

  !> The slip of slipping node s over the increment in units of the characteristic slip L of
  !> its law (rate-and-state laws; the R-minimum limit MAX SLIP INCREMENT: the next increment
  !> is at most xi L / V_max, Lapusta et al. 2000).
  subroutine record_slip_increment(this, s, slip)
    type(contact_system_t), intent(inout) :: this
    integer, intent(in) :: s
    real(dp), intent(in) :: slip
    real(dp) :: length
    length = this%pairs(this%slave_pair(s))%law%characteristic_slip()
    if (length <= 0.0_dp) return
    if (slip / length > this%change(4)) then
      this%change(4) = slip / length
      this%change_node(4) = this%slave_node(s)
    end if
  end subroutine record_slip_increment

  !> Keep the largest changes of ln V, mu, ln(state) and where they happened.
  subroutine record_changes(this, s, changes)
    type(contact_system_t), intent(inout) :: this
    integer, intent(in) :: s
    real(dp), intent(in) :: changes(3)
    integer :: i
    do i = 1, 3
      if (changes(i) > this%change(i)) then
        this%change(i) = changes(i)
        this%change_node(i) = this%slave_node(s)
      end if
    end do
  end subroutine record_changes

  !> True when face f is the face of slave s's pattern clique or one of its neighbours.
  logical function in_pattern(this, s, f)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s, f
    integer :: centre
    centre = this%pattern_face(s)
    in_pattern = .false.
    if (centre == 0) return
    associate (pair => this%pairs(this%slave_pair(s)))
      in_pattern = any(pair%neighbors(pair%neighbor_ptr(centre):pair%neighbor_ptr(centre + 1) - 1) == f)
    end associate
  end function in_pattern

  !> A tied node: where it is on its master face, and the force the tie puts on it
  !> (`tie_force`, 3 * n_nodes: the segment-to-segment tie's nodal forces), split into the
  !> normal force and the tangential components in the face's frame, for the outputs.
  subroutine update_tied(this, s, x, cstate, tie_force)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    real(dp), intent(in) :: x(:, :), tie_force(:)
    type(contact_state_t), intent(inout) :: cstate
    type(segment_point_t) :: p, p_old
    real(dp) :: xm(3, 4), gap, f(3)
    logical :: converged
    associate (pair => this%pairs(this%slave_pair(s)), node => this%slave_node(s))
      xm = x(:, pair%face_nodes(:, cstate%face(s)))
      call project_to_segment(xm, x(:, node), cstate%xi(:, s), p, gap, converged)
      if (.not. converged) p = segment_point(xm, cstate%xi(:, s))
      p_old = segment_point(xm, cstate%xi(:, s))
      f = tie_force(3 * node - 2:3 * node)
      cstate%xi(:, s) = p%xi
      cstate%gap(s) = gap
      cstate%normal_force(s) = dot_product(f, p%normal)
      cstate%friction(:, s) = matmul(f - cstate%normal_force(s) * p%normal, p%e)
      cstate%tangential_displacement(:, s) = cstate%tangential_displacement(:, s) + p%x - p_old%x
    end associate
  end subroutine update_tied

  !> A closed node: follow its contact point (hand-over to a neighbouring face by the search
  !> rule when it leaves its face), return-map the friction, open it if it separated.
  subroutine update_closed(this, s, x, cstate, dt, kind)
    type(contact_system_t), intent(inout) :: this
    integer, intent(in) :: s, kind
    real(dp), intent(in) :: x(:, :), dt
    type(contact_state_t), intent(inout) :: cstate
    type(segment_point_t) :: p, p_old
    type(contact_update_t) :: u
    type(contact_node_t) :: node
    type(contact_params_t) :: params
    real(dp) :: xs(3), gap, friction(2), force(3)
    integer :: face, old_face, mode
    associate (pair => this%pairs(this%slave_pair(s)))
      xs = x(:, this%slave_node(s))
      old_face = cstate%face(s)
      p_old = segment_point(x(:, pair%face_nodes(:, old_face)), cstate%xi(:, s))
      mode = hold_mode(this, s)
      face = 0
      if (mode == HOLD_CLOSED) call held_point(this, s, pair, x, xs, old_face, cstate%xi(:, s), face, p, gap)
      if (face == 0) call follow(pair, x, xs, old_face, cstate%xi(:, s), face, p, gap)
      if (mode == HOLD_OPEN .or. face == 0 .or. &
          (mode == HOLD_NONE .and. gap > GAP_TOLERANCE * pair%face_size)) then
        call open_node(cstate, s, face, p, gap)
        return
      end if
      ! The opening event of the increment was taken: the node opens if its normal force
      ! has (up to the linearisation error) come down to zero.
      params = params_of(this, s, face, p%xi)
      if (mode == HOLD_NONE .and. kind == EVENT_CONTACT_OPEN .and. &
          params%support * pair%normal_stiffness * this%area(s) * (-gap) <= EVENT_BAND * cstate%normal_force(s)) then
        call open_node(cstate, s, face, p, gap)
        return
      end if
      friction = cstate%friction(:, s)
      if (face /= old_face) then
        ! Hand-over: keep the friction force vector, expressed in the new face's frame.
        force = friction(1) * p_old%e(:, 1) + friction(2) * p_old%e(:, 2)
        friction = matmul(force, p%e)
        if (norm2(friction) > 0.0_dp) friction = friction * norm2(force) / norm2(friction)
      end if
      node = node_of(cstate, s, cstate%status(s))
      node%friction = friction
      node%bilateral = mode == HOLD_CLOSED
      u = contact_update(p, gap, p_old, node, params, pair%law, dt)
      ! A node whose stick-to-slip event was taken and whose trial force has reached the
      ! cone up to the linearisation error slips from now on, its force on the cone (the
      ! state its slip tangent describes); so does any node without friction.
      if (kind == EVENT_STICK_TO_SLIP .and. u%status == CONTACT_STICK .and. &
          u%trial_norm >= (1.0_dp - EVENT_BAND) * u%mu * u%normal_force .and. u%trial_norm > 0.0_dp) then
        u%status = CONTACT_SLIP
        u%friction = u%friction * (u%mu * u%normal_force / u%trial_norm)
      end if
      if (u%status == CONTACT_STICK) u%status = closing_status(u%mu)
      cstate%face(s) = face
      cstate%xi(:, s) = p%xi
      cstate%gap(s) = gap
      call store_update(cstate, s, u)
    end associate
  end subroutine update_closed

  !> The result of a return mapping of slave s into its state.
  pure subroutine store_update(cstate, s, u)
    type(contact_state_t), intent(inout) :: cstate
    integer, intent(in) :: s
    type(contact_update_t), intent(in) :: u
    cstate%status(s) = u%status
    cstate%normal_force(s) = u%normal_force
    cstate%friction(:, s) = u%friction
    cstate%trial_norm(s) = u%trial_norm
    cstate%slip(s) = cstate%slip(s) + u%plastic_slip
    cstate%work(s) = cstate%work(s) + norm2(u%friction) * u%plastic_slip
    cstate%tangential_displacement(:, s) = cstate%tangential_displacement(:, s) + u%slip_vector
    cstate%slip_rate(s) = u%slip_rate
    cstate%mu(s) = u%mu
    cstate%friction_state(s) = u%friction_state
  end subroutine store_update

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
    call project_to_segment(x(:, pair%face_nodes(:, face_old)), xs, xi_old, p, gap, converged)
    face = face_old
    if (converged) then
      excess = edge_excess(p%xi)
      if (all(excess <= XI_TOLERANCE)) return
    end if
    call pair%grid%candidates(xs, candidates)
    candidates = unique_sorted([candidates, pair%neighbors(pair%neighbor_ptr(face_old): &
                                                           pair%neighbor_ptr(face_old + 1) - 1)])
    call closest_face(pair%face_nodes, x, candidates, xs, pair%reach, face, p, gap, pair%free_edge, &
                      extend=.true.)
  end subroutine follow

  !> The contact point of slave s on the face held for it (face = 0: none held, or the node
  !> has moved more than HOLD_LIMIT past one of its shared edges, or past the extension of a
  !> free edge). xi_old on face_old is the start of the projection when it is that face.
  subroutine held_point(this, s, pair, x, xs, face_old, xi_old, face, p, gap)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s, face_old
    type(contact_pair_t), intent(in) :: pair
    real(dp), intent(in) :: x(:, :), xs(3), xi_old(2)
    integer, intent(out) :: face
    type(segment_point_t), intent(out) :: p
    real(dp), intent(out) :: gap
    real(dp) :: start(2), excess(4)
    logical :: converged
    integer :: held
    face = 0
    held = this%held_face(s)
    if (held == 0) return
    start = 0.0_dp
    if (held == face_old) start = xi_old
    call project_to_segment(x(:, pair%face_nodes(:, held)), xs, start, p, gap, converged)
    if (.not. converged) return
    excess = edge_excess(p%xi)
    if (any(excess > merge(EDGE_EXTENSION, HOLD_LIMIT, pair%free_edge(:, held)))) return
    if (abs(gap) > pair%reach) return
    face = held
  end subroutine held_point

  !> Hold every node in its open or closed state, and every closed node on its face,
  !> through the equilibrium iterations that follow (the contact states "held" while the
  !> forces are corrected; `check_held` then re-evaluates them on the corrected solution).
  subroutine system_hold_states(this, cstate)
    class(contact_system_t), intent(inout) :: this
    type(contact_state_t), intent(in) :: cstate
    logical, allocatable :: closed(:)
    closed = cstate%status == CONTACT_STICK .or. cstate%status == CONTACT_SLIP
    this%held_face = merge(cstate%face, 0, closed)
    this%hold_status = merge(HOLD_CLOSED, HOLD_OPEN, closed)
    where (cstate%status == CONTACT_TIED) this%hold_status = HOLD_NONE
    ! The entries of a node in several pairs are decided together by the twin rule
    ! (leave_to_twins) in every application, not held one by one.
    where (this%twin /= 0) this%hold_status = HOLD_NONE
    if (.not. allocated(this%flips)) allocate (this%flips(size(this%slave_node)))
    this%flips = 0
    this%holding = .true.
  end subroutine system_hold_states

  !> The held states against the corrected solution: a node held closed whose (bilateral)
  !> normal force turned tensile is to open, a node held open that penetrates a master face
  !> is to close. Each node changes at most MAX_HOLD_FLIPS times per increment (no endless
  !> flip-flop); `n_changed` counts the changes, after which the caller iterates again.
  subroutine system_check_held(this, cstate, n_changed)
    class(contact_system_t), intent(inout) :: this
    type(contact_state_t), intent(in) :: cstate
    integer, intent(out) :: n_changed
    type(contact_params_t) :: params
    integer :: s
    n_changed = 0
    if (.not. this%holding) return
    do s = 1, size(this%slave_node)
      if (this%flips(s) >= MAX_HOLD_FLIPS) cycle
      select case (this%hold_status(s))
      case (HOLD_CLOSED)
        if (cstate%normal_force(s) >= -normal_force_floor(this, s)) cycle
        this%hold_status(s) = HOLD_OPEN
        this%held_face(s) = 0
      case (HOLD_OPEN)
        if (cstate%face(s) == 0) cycle
        if (this%twin(s) /= 0) then
          if (twin_inside(this, s, cstate)) cycle
        end if
        if (cstate%gap(s) >= -GAP_TOLERANCE * this%pairs(this%slave_pair(s))%face_size) cycle
        params = params_of(this, s, cstate%face(s), cstate%xi(:, s))
        if (params%support <= 0.0_dp) cycle
        this%hold_status(s) = HOLD_CLOSED
        this%held_face(s) = cstate%face(s)
      case default
        cycle
      end select
      this%flips(s) = this%flips(s) + 1
      n_changed = n_changed + 1
    end do
  end subroutine system_check_held

  !> End of the equilibrium iterations: the nodes decide their states freely again; a
  !> closed node left with a tensile force below the force floor carries none.
  subroutine system_release_states(this, cstate)
    class(contact_system_t), intent(inout) :: this
    type(contact_state_t), intent(inout) :: cstate
    integer :: s
    this%holding = .false.
    do s = 1, size(this%slave_node)
      if (cstate%status(s) /= CONTACT_STICK .and. cstate%status(s) /= CONTACT_SLIP) cycle
      if (cstate%normal_force(s) >= 0.0_dp) cycle
      cstate%normal_force(s) = 0.0_dp
      cstate%friction(:, s) = 0.0_dp
    end do
  end subroutine system_release_states

  !> How slave s is held now: HOLD_NONE outside the equilibrium iterations.
  pure integer function hold_mode(this, s) result(mode)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    mode = HOLD_NONE
    if (this%holding) mode = this%hold_status(s)
  end function hold_mode

  subroutine open_node(cstate, s, face, p, gap)
    type(contact_state_t), intent(inout) :: cstate
    integer, intent(in) :: s, face
    type(segment_point_t), intent(in) :: p
    real(dp), intent(in) :: gap
    cstate%status(s) = CONTACT_OPEN
    cstate%face(s) = face
    cstate%normal_force(s) = 0.0_dp
    cstate%friction(:, s) = 0.0_dp
    cstate%trial_norm(s) = 0.0_dp
    cstate%slip_rate(s) = 0.0_dp
    cstate%tangential_displacement(:, s) = 0.0_dp
    if (face == 0) return
    cstate%xi(:, s) = p%xi
    cstate%gap(s) = gap
  end subroutine open_node

  !> An open node: search; it closes if it penetrates or its closing event was taken. A
  !> node that closes measures its tangential motion from its projection at the start of the
  !> increment (on the same face), so that its stick force follows the stick tangent it
  !> gets (the R-minimum closing event makes that motion small: the node touches at the end
  !> of the increment).
  subroutine update_open(this, s, x, cstate, kind)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s, kind
    real(dp), intent(in) :: x(:, :)
    type(contact_state_t), intent(inout) :: cstate
    type(segment_point_t) :: p, p_start
    type(contact_update_t) :: u
    real(dp) :: gap
    integer :: face, start_face, mode
    real(dp) :: start_xi(2), start_gap
    type(contact_node_t) :: node
    associate (pair => this%pairs(this%slave_pair(s)))
      start_face = cstate%face(s)
      start_xi = cstate%xi(:, s)
      start_gap = cstate%gap(s)
      mode = hold_mode(this, s)
      face = 0
      if (mode == HOLD_CLOSED) call held_point(this, s, pair, x, x(:, this%slave_node(s)), start_face, &
                                               start_xi, face, p, gap)
      if (face == 0) call search(pair, x, x(:, this%slave_node(s)), face, p, gap)
      call open_node(cstate, s, face, p, gap)
      if (face == 0 .or. mode == HOLD_OPEN) return
      if (mode == HOLD_CLOSED .or. gap < -GAP_TOLERANCE * pair%face_size .or. &
          (kind == EVENT_CONTACT_CLOSE .and. gap <= EVENT_BAND * start_gap)) then
        p_start = p
        if (start_face == face) p_start = segment_point(x(:, pair%face_nodes(:, face)), start_xi)
        node = node_of(cstate, s, CONTACT_STICK)
        node%bilateral = mode == HOLD_CLOSED
        u = contact_update(p, gap, p_start, node, params_of(this, s, face, p%xi), pair%law, 0.0_dp)
        if (u%status == CONTACT_STICK) u%status = closing_status(u%mu)
        call store_update(cstate, s, u)
      end if
    end associate
  end subroutine update_open

  !> Before an increment du is applied: no contact node may end up deeper in its master
  !> than PENETRATION_LIMIT times the mean master face size (gaps predicted linearly). A
  !> deeper penetration means the penalty E_n is far too small for the load, or a slave node
  !> went through a thin master body: the run must stop rather than go on with wrong forces.
  subroutine system_check_penetration(this, model_node_id, x, cstate, du, err)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: model_node_id(:)
    real(dp), intent(in) :: x(:, :), du(:)
    type(contact_state_t), intent(in) :: cstate
    type(error_t), allocatable, intent(out) :: err
    type(segment_point_t) :: p
    real(dp) :: due(15), gap
    integer :: s, a, nodes(5)
    do s = 1, size(this%slave_node)
      if (cstate%status(s) /= CONTACT_STICK .and. cstate%status(s) /= CONTACT_SLIP) cycle
      nodes = element_nodes(this, s, cstate)
      do a = 1, 5
        due(3 * a - 2:3 * a) = du(3 * nodes(a) - 2:3 * nodes(a))
      end do
      p = segment_point(x(:, nodes(2:5)), cstate%xi(:, s))
      gap = cstate%gap(s) + relative_normal(p, due)
      associate (pair => this%pairs(this%slave_pair(s)))
        if (-gap <= PENETRATION_LIMIT * pair%face_size) cycle
        call penetration_error(pair, model_node_id(nodes(1)), -gap, err)
        return
      end associate
    end do
  end subroutine system_check_penetration

  !> After an increment: no closed node may be deeper in its master than PENETRATION_LIMIT
  !> times the mean master face size (as `check_penetration` predicts before it).
  subroutine system_check_gaps(this, model_node_id, cstate, err)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: model_node_id(:)
    type(contact_state_t), intent(in) :: cstate
    type(error_t), allocatable, intent(out) :: err
    integer :: s
    do s = 1, size(this%slave_node)
      if (cstate%status(s) /= CONTACT_STICK .and. cstate%status(s) /= CONTACT_SLIP) cycle
      associate (pair => this%pairs(this%slave_pair(s)))
        if (-cstate%gap(s) <= PENETRATION_LIMIT * pair%face_size) cycle
        call penetration_error(pair, model_node_id(this%slave_node(s)), -cstate%gap(s), err)
        return
      end associate
    end do
  end subroutine system_check_gaps

  subroutine penetration_error(pair, node_id, depth, err)
    type(contact_pair_t), intent(in) :: pair
    integer, intent(in) :: node_id
    real(dp), intent(in) :: depth
    type(error_t), allocatable, intent(out) :: err
    call fatal_error(err, 'excessive penetration: slave node ' // str(node_id) // &
      ' of contact pair ' // pair%name // ' would end ' // str(depth) // ' deep in the master ' // &
      'surface (more than ' // str(nint(100 * PENETRATION_LIMIT)) // '% of its face size ' // &
      str(pair%face_size) // '): the normal penalty E_n = ' // str(pair%normal_stiffness) // &
      ' is too small for the contact pressure, or the node went through the master body')
  end subroutine penetration_error

  !> Values of slave s as CalculiX prints them (*CONTACT PRINT): relative displacement
  !> (normal = gap, then the accumulated tangential displacement on CalculiX's tangents t_1,
  !> t_2 of the master normal, calculix_tangents) and stresses (pressure, then the shear on
  !> t_1, t_2 with CalculiX's sign: that of the elastic slip, i.e. the shear the slave node
  !> exerts on the master, opposite to the traction on the slave).
  subroutine system_local_values(this, s, x, cstate, displacement, stress)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    real(dp), intent(in) :: x(:, :)
    type(contact_state_t), intent(in) :: cstate
    real(dp), intent(out) :: displacement(3), stress(3)
    real(dp) :: normal(3), pressure, shear(3), t(3, 2)
    displacement = 0.0_dp
    stress = 0.0_dp
    if (cstate%face(s) == 0) return
    call this%traction(s, x, cstate, normal, pressure, shear)
    t = calculix_tangents(normal)
    displacement = [cstate%gap(s), matmul(cstate%tangential_displacement(:, s), t)]
    if (cstate%status(s) == CONTACT_OPEN) return
    stress = [pressure, -matmul(shear, t)]
  end subroutine system_local_values

  !> Nodal contact forces R f of every closed node on coordinates x, added to f_contact.
  subroutine system_forces(this, x, cstate, f_contact)
    class(contact_system_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :)
    type(contact_state_t), intent(in) :: cstate
    real(dp), intent(inout) :: f_contact(:)
    real(dp) :: normal(3), pressure, shear(3), f(3)
    type(segment_point_t) :: p
    integer :: s, a, nodes(5)
    call this%ties%forces(x - this%reference, f_contact)
    do s = 1, size(this%slave_node)
      if (cstate%status(s) == CONTACT_OPEN .or. cstate%status(s) == CONTACT_TIED .or. &
          cstate%face(s) == 0) cycle
      call this%traction(s, x, cstate, normal, pressure, shear)
      f = (pressure * normal + shear) * this%area(s)
      nodes = element_nodes(this, s, cstate)
      p = segment_point(x(:, nodes(2:5)), cstate%xi(:, s))
      f_contact(3 * nodes(1) - 2:3 * nodes(1)) = f_contact(3 * nodes(1) - 2:3 * nodes(1)) + f
      do a = 2, 5
        f_contact(3 * nodes(a) - 2:3 * nodes(a)) = f_contact(3 * nodes(a) - 2:3 * nodes(a)) - &
          p%shape(a - 1) * f
      end do
    end do
  end subroutine system_forces

  !> Totals of pair k: normal and tangential forces, counts by state.
  function system_totals(this, k, x, cstate) result(t)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: k
    real(dp), intent(in) :: x(:, :)
    type(contact_state_t), intent(in) :: cstate
    type(pair_totals_t) :: t
    real(dp) :: traction(3), normal(3), pressure, shear(3)
    integer :: s
    do s = this%pairs(k)%first, this%pairs(k)%last
      select case (cstate%status(s))
      case (CONTACT_STICK)
        t%n_stick = t%n_stick + 1
      case (CONTACT_SLIP)
        t%n_slip = t%n_slip + 1
      case (CONTACT_TIED)
        t%n_tied = t%n_tied + 1
      case default
        t%n_open = t%n_open + 1
      end select
      call this%traction(s, x, cstate, normal, pressure, shear)
      traction = shear
      t%normal_force = t%normal_force + pressure * this%area(s)
      t%tangential_force = t%tangential_force + traction * this%area(s)
    end do
  end function system_totals

  !> Contact tractions of slave s: master normal, pressure f_n/A (positive in compression)
  !> and shear traction vector f_t/A on the slave node.
  subroutine system_traction(this, s, x, cstate, normal, pressure, shear)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    real(dp), intent(in) :: x(:, :)
    type(contact_state_t), intent(in) :: cstate
    real(dp), intent(out) :: normal(3), pressure, shear(3)
    type(segment_point_t) :: p
    normal = 0.0_dp
    pressure = 0.0_dp
    shear = 0.0_dp
    if (cstate%face(s) == 0) return
    p = segment_point(x(:, this%pairs(this%slave_pair(s))%face_nodes(:, cstate%face(s))), cstate%xi(:, s))
    normal = p%normal
    if (cstate%status(s) == CONTACT_OPEN) return
    pressure = cstate%normal_force(s) / this%area(s)
    shear = (cstate%friction(1, s) * p%e(:, 1) + cstate%friction(2, s) * p%e(:, 2)) / this%area(s)
  end subroutine system_traction

  !> Round-off level [force^2] of the cone function F(r) = |f_t + r df_t|^2 -
  !> mu^2 (f_n + r df_n)^2 and of its coefficients: 1e-10 of the square of the largest force
  !> involved, the increments included. A node closed at zero force (f_n and f_t zero up to
  !> round-off) is then judged by how its forces grow (the sign of a), not by the signs of
  !> round-off residues in b and c, which otherwise put a spurious root near r = 0.
  pure real(dp) function cone_tolerance(fn, ft, dfn, dft, mu) result(tolerance)
    real(dp), intent(in) :: fn, ft(3), dfn, dft(3), mu
    tolerance = 1.0e-10_dp * max(mu * abs(fn), norm2(ft), mu * abs(dfn), norm2(dft))**2
  end function cone_tolerance

  !> First r in [0, 1] where the friction force reaches the Coulomb cone,
  !> F(r) = |f_t + r df_t|^2 - mu^2 (f_n + r df_n)^2 = a r^2 + b r + c = 0 (eq. 3), for a
  !> stick node (c <= 0 inside the cone). A node on the cone (|c| <= tolerance) slips now if
  !> F grows (b > 0), otherwise only where F comes back to zero. > 1: no crossing.
  pure real(dp) function cone_crossing(a, b, c, tolerance) result(r)
    real(dp), intent(in) :: a, b, c, tolerance
    real(dp) :: disc, r1, r2, q
    r = 2.0_dp
    if (abs(c) <= tolerance .or. c > 0.0_dp) then
      if (b > tolerance .or. (abs(b) <= tolerance .and. a > 0.0_dp)) then
        r = 0.0_dp
      else if (a > 0.0_dp) then
        r = -b / a
      end if
      return
    end if
    if (abs(a) <= tiny(1.0_dp)) then
      if (b > 0.0_dp) r = -c / b
      return
    end if
    disc = b * b - 4.0_dp * a * c
    if (disc < 0.0_dp) return
    q = -0.5_dp * (b + sign(sqrt(disc), b))
    r1 = q / a
    r2 = huge(1.0_dp)
    if (q /= 0.0_dp) r2 = c / q
    if (r1 >= 0.0_dp) r = min(r, r1)
    if (r2 >= 0.0_dp) r = min(r, r2)
  end function cone_crossing

  subroutine offer(this, collector, s, r, kind)
    type(contact_system_t), intent(inout) :: this
    type(rmin_collector_t), intent(inout) :: collector
    integer, intent(in) :: s, kind
    real(dp), intent(in) :: r
    real(dp) :: rr
    rr = max(0.0_dp, r)
    if (rr > 1.0_dp) return
    call collector%offer(rr, kind, this%slave_node(s), s)
    if (rr < this%event_r(s)) then
      this%event_r(s) = rr
      this%event_kind(s) = kind
    end if
  end subroutine offer

end module fcs_contact_system
