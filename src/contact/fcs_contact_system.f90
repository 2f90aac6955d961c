!> The contact system: every node-to-point contact pair of the model (Xing, Mora &
!> Makinouchi 2003, section 2), with what the stepper needs each increment:
!>   - `cliques`: slave node + master face nodes for the sparse pattern (the current face and
!>     its neighbours, so that sliding rarely changes the pattern);
!>   - `assemble`: contact forces R f and tangents K_f (eqs. 8-10) of every closed node;
!>   - `events`: the R-minimum fractions of the trial increment at which a node closes
!>     (gap reaches 0; c0 under the exponential law), opens (normal force reaches 0; gap
!>     reaches c0 under the exponential law, doc/theory.md 4.11), starts to slip (F = 0, eq. 3) or
!>     leaves its master segment (a return to stick, when slip reverses or unloads, is
!>     handled at the start of the increment by `switch_states` and a re-solve, as elastic
!>     unloading in plasticity);
!>   - `update`: the return mapping of every closed node (eq. 5) on the new configuration,
!>     segment hand-over while sliding, search for the open nodes, state changes.
module fcs_contact_system
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error, input_error
  use fcs_mesh, only: mesh_t
  use fcs_contact_geometry, only: segment_point_t, segment_point, project_to_segment, &
                                  calculix_tangents, is_triangle, segment_centre
  use fcs_contact_search, only: edge_excess, edge_support, XI_TOLERANCE, EDGE_EXTENSION, face_node_count
  use fcs_contact_pair, only: contact_pair_def_t, contact_pair_t, pair_setup, face_coordinates, &
                              search, follow, pair_face_nodes
  use fcs_contact_element, only: contact_linear_t, contact_linearise, contact_update, &
                                 contact_update_t, contact_node_t, contact_params_t, CONTACT_OPEN, &
                                 MAX_ELEMENT_DOFS, &
                                 CONTACT_STICK, CONTACT_SLIP, CONTACT_TIED
  use fcs_contact_state, only: contact_state_t
  use fcs_contact_areas, only: slave_node_areas, surface_face_nodes
  use fcs_contact_ties, only: tie_set_t
  use fcs_contact_points, only: slave_points_t, slave_face_points
  use fcs_friction_law, only: friction_law_t, friction_derivatives_t
  use fcs_friction_factory, only: friction_def_t, create_friction_law
  use fcs_sparse, only: sparse_matrix_t
  use fcs_rmin_events, only: rmin_collector_t, EVENT_CONTACT_CLOSE, EVENT_CONTACT_OPEN, &
                             EVENT_STICK_TO_SLIP, EVENT_SEGMENT_CHANGE, &
                             EVENT_NONE, CONTACT_EVENTS_ALL, CONTACT_EVENTS_CLOSING
  use fcs_sort, only: unique_sorted, argsort_integers
  use fcs_strings, only: str
  use fcs_diagnostics, only: format_location
  use fcs_archive, only: archive_t
  use fcs_field, only: field_t, field, FIELD_SURFACE
  use fcs_pressure_overclosure, only: pressure_overclosure_t
  implicit none
  private
  public :: contact_system_t, contact_pair_def_t, pair_totals_t

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

  !> Sums over a pair, for the log and histories: total normal and tangential forces, counts
  !> by state, mean and largest accumulated slip, largest slip rate, and the mean pressure and
  !> shear traction magnitude of the closed (not open) nodes.
  type :: pair_totals_t
    real(dp) :: normal_force = 0.0_dp
    real(dp) :: tangential_force(3) = 0.0_dp
    integer :: n_stick = 0
    integer :: n_slip = 0
    integer :: n_open = 0
    integer :: n_tied = 0
    real(dp) :: slip_mean = 0.0_dp
    real(dp) :: slip_max = 0.0_dp
    real(dp) :: rate_max = 0.0_dp
    real(dp) :: pressure_mean = 0.0_dp
    real(dp) :: shear_mean = 0.0_dp
  end type pair_totals_t

  !> The contact system. Its components are private: the rest of the code asks it (pairs,
  !> slave nodes, output fields, totals, events) and hands it the contact states to update,
  !> so that another discretisation can be put behind the same procedures.
  type :: contact_system_t
    private
    type(contact_pair_t), allocatable :: pairs(:)
    !> For each slave entry: its node, pair, tributary area.
    integer, allocatable :: slave_node(:), slave_pair(:)
    real(dp), allocatable :: area(:)
    !> The slave point of each entry: x_s = sum_a point_weight(a) x(point_nodes(a)) over
    !> a = point_ptr(s) .. point_ptr(s + 1) - 1. An entry of a node-to-surface pair is its
    !> node (weight 1); one of a surface-to-surface pair an integration point of a slave face
    !> (its nodes and their shape functions there; fcs_contact_points, doc/theory.md 4.10),
    !> whose slave_node is the face node nearest to it.
    integer, allocatable :: point_ptr(:), point_nodes(:)
    real(dp), allocatable :: point_weight(:)
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
    !> ... and its friction state (the state a law read with VELOCITY=RELATIVE and an implicit
    !> rate evolves from, for the state's part of dmu/dV in the tangent).
    real(dp), allocatable :: start_state(:)
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
    procedure :: save => system_save
    procedure :: load => system_load
    procedure :: n_pairs => system_n_pairs
    procedure :: pair_name => system_pair_name
    procedure :: pair_is_tied => system_pair_is_tied
    procedure :: set_pair_friction => system_set_pair_friction
    procedure :: set_pair_behavior => system_set_pair_behavior
    procedure :: pair_slave_nodes => system_pair_slave_nodes
    procedure :: pair_positions => system_pair_positions
    procedure :: held_by_tie => system_held_by_tie
    procedure :: needs_pattern => system_needs_pattern
    procedure :: friction_changes => system_friction_changes
    procedure :: pair_fields => system_pair_fields
    procedure :: pair_slip => system_pair_slip
    procedure :: frictional_work => system_frictional_work
    procedure :: print_values => system_print_values
  end type contact_system_t

  interface
    !> Offer the R-minimum events of the trial increment to the collector. The trial path is
    !> du(r) = du_fixed + r du_scaled (the out-of-balance correction is applied in full, the
    !> load increment scaled by r); contact quantities are linear in du (their linearisation).
    !> `events` (*RMIN, CONTACT EVENTS; CONTACT_EVENTS_* of fcs_rmin_events) says which changes
    !> are offered: under NORMAL a sticking node reaching the cone and a node reaching a shared
    !> edge of its segment are no events, under CLOSING an opening node and a node leaving the
    !> master surface are not either: the equilibrium iterations decide those states.
    module subroutine system_events(this, x, cstate, du_fixed, du_scaled, collector, events)
      class(contact_system_t), intent(inout) :: this
      real(dp), intent(in) :: x(:, :), du_fixed(:), du_scaled(:)
      type(contact_state_t), intent(in) :: cstate
      type(rmin_collector_t), intent(inout) :: collector
      integer, intent(in) :: events
    end subroutine system_events

    !> State changes at the very start of the trial increment (r = 0), handled as in
    !> elastic-plastic unloading (Yamada et al. 1968): a slipping node whose elastic (stick)
    !> predictor stays inside the Coulomb cone unloads, and a sticking node on the cone whose
    !> predictor leaves it at once slips; their tangents are switched and the caller solves the
    !> increment again. Each node switches at most 10 times per increment (no endless flip-flop).
    !> `n_switched` counts the switches made.
    module subroutine system_switch_states(this, x, cstate, du, n_switched)
      class(contact_system_t), intent(inout) :: this
      real(dp), intent(in) :: x(:, :), du(:)
      type(contact_state_t), intent(inout) :: cstate
      integer, intent(out) :: n_switched
    end subroutine system_switch_states

    !> New contact state on the coordinates x after an increment of duration dt whose
    !> fraction of the trial increment was r: the return mapping of every closed node (eq. 5),
    !> segment hand-over, opening, and the search for open nodes. Events whose fractions were
    !> within r are applied even when round-off leaves the node a hair short of them. The
    !> events of the increment are kept, so that an equilibrium iteration applying the
    !> corrected increment again from its start decides the same events.
    module subroutine system_update(this, x, cstate, dt, r)
      class(contact_system_t), intent(inout) :: this
      real(dp), intent(in) :: x(:, :), dt, r
      type(contact_state_t), intent(inout) :: cstate
    end subroutine system_update

    !> Hold every node in its open or closed state, and every closed node on its face,
    !> through the equilibrium iterations that follow (the contact states "held" while the
    !> forces are corrected; `check_held` then re-evaluates them on the corrected solution).
    module subroutine system_hold_states(this, cstate)
      class(contact_system_t), intent(inout) :: this
      type(contact_state_t), intent(in) :: cstate
    end subroutine system_hold_states

    !> The held states against the corrected solution: a node held closed whose (bilateral)
    !> normal force turned tensile is to open, a node held open that penetrates a master face
    !> is to close. Each node changes at most MAX_HOLD_FLIPS times per increment (no endless
    !> flip-flop); `n_changed` counts the changes, after which the caller iterates again.
    module subroutine system_check_held(this, cstate, n_changed)
      class(contact_system_t), intent(inout) :: this
      type(contact_state_t), intent(in) :: cstate
      integer, intent(out) :: n_changed
    end subroutine system_check_held

    !> End of the equilibrium iterations: the nodes decide their states freely again; a
    !> closed node left with a tensile force below the force floor carries none.
    module subroutine system_release_states(this, cstate)
      class(contact_system_t), intent(inout) :: this
      type(contact_state_t), intent(inout) :: cstate
    end subroutine system_release_states

    !> The state a node closes in: stick, or slip on a frictionless interface (mu = 0), whose
    !> cone has no interior (a stick node there would reach the cone at once, an R-minimum
    !> event at r = 0 that costs one increment at the minimum size per closing node).
    pure module function closing_status(mu) result(status)
      real(dp), intent(in) :: mu
      integer :: status
    end function closing_status

    !> The kernel's view of slave s (status as given).
    pure module function node_of(cstate, s, status) result(node)
      type(contact_state_t), intent(in) :: cstate
      integer, intent(in) :: s, status
      type(contact_node_t) :: node
    end function node_of

    !> The rate V at which slave s's law is evaluated: the slip rate of the last increment, or
    !> for a law read with VELOCITY=RELATIVE its total relative tangential velocity.
    pure module function law_rate(law, cstate, s) result(rate)
      class(friction_law_t), intent(in) :: law
      type(contact_state_t), intent(in) :: cstate
      integer, intent(in) :: s
      real(dp) :: rate
    end function law_rate

    !> The friction coefficient of slave s's cone in the coming increment: the one in use, or
    !> for a law with an explicit rate mu at the rate of the last increment (law_rate; during
    !> the equilibrium iterations, the one of the increment's return mapping).
    module function cone_mu(this, s, cstate) result(mu)
      type(contact_system_t), intent(in) :: this
      integer, intent(in) :: s
      type(contact_state_t), intent(in) :: cstate
      real(dp) :: mu
    end function cone_mu

    !> Area and penalties of slave s, and the support of its master segment `face` at natural
    !> point xi (1 when not given: tied nodes).
    pure module function params_of(this, s, face, xi) result(params)
      type(contact_system_t), intent(in) :: this
      integer, intent(in) :: s
      integer, intent(in), optional :: face
      real(dp), intent(in), optional :: xi(2)
      type(contact_params_t) :: params
    end function params_of

    !> Linearisation of closed node s on coordinates x; dt is the trial time increment the
    !> rate term of the friction law refers to.
    module subroutine linearise(this, s, x, cstate, dt, lin)
      type(contact_system_t), intent(in) :: this
      integer, intent(in) :: s
      real(dp), intent(in) :: x(:, :), dt
      type(contact_state_t), intent(in) :: cstate
      type(contact_linear_t), intent(out) :: lin
    end subroutine linearise

    !> The 1 + gamma nodes of slave s's contact element: the slave, then its segment's.
    pure module function element_nodes(this, s, cstate) result(nodes)
      class(contact_system_t), intent(in) :: this
      integer, intent(in) :: s
      type(contact_state_t), intent(in) :: cstate
      integer, allocatable :: nodes(:)
    end function element_nodes

    !> Position of slave s's point on coordinates x (its node's for a node-to-surface pair).
    pure module function slave_position(this, s, x) result(xs)
      type(contact_system_t), intent(in) :: this
      integer, intent(in) :: s
      real(dp), intent(in) :: x(:, :)
      real(dp) :: xs(3)
    end function slave_position

    !> The increments due(1:3 size(nodes)) of slave s's contact element (nodes: element_nodes)
    !> from the nodal increments du: its slave point's (interpolated on a slave face for a
    !> surface-to-surface pair), then its master nodes'.
    pure module subroutine gather_increment(this, s, nodes, du, due)
      type(contact_system_t), intent(in) :: this
      integer, intent(in) :: s, nodes(:)
      real(dp), intent(in) :: du(:)
      real(dp), intent(out) :: due(:)
    end subroutine gather_increment

    !> The contact element of slave s on the mesh's nodes: `all_nodes` (its slave point's
    !> nodes, then the master nodes), the stiffness T^T K_f T and the forces T^T R f, T the
    !> interpolation of the slave point's displacement from its nodes' (identity for a node).
    pure module subroutine expand_element(this, s, nodes, lin, all_nodes, stiffness, force)
      type(contact_system_t), intent(in) :: this
      integer, intent(in) :: s, nodes(:)
      type(contact_linear_t), intent(in) :: lin
      integer, allocatable, intent(out) :: all_nodes(:)
      real(dp), allocatable, intent(out) :: stiffness(:, :), force(:)
    end subroutine expand_element

    !> n.(du_s - sum N_I du_I): the gap change for nodal increments due(3 (1 + gamma)).
    pure module function relative_normal(p, due) result(change)
      type(segment_point_t), intent(in) :: p
      real(dp), intent(in) :: due(:)
      real(dp) :: change
    end function relative_normal

    !> How slave s is held now: HOLD_NONE outside the equilibrium iterations.
    pure module function hold_mode(this, s) result(mode)
      type(contact_system_t), intent(in) :: this
      integer, intent(in) :: s
      integer :: mode
    end function hold_mode

    !> The normal force of slave s below which it counts as zero: the penalty force of a
    !> penetration of GAP_TOLERANCE times the pair's mean master face size.
    pure module function normal_force_floor(this, s) result(floor)
      type(contact_system_t), intent(in) :: this
      integer, intent(in) :: s
      real(dp) :: floor
    end function normal_force_floor

    !> Slave s's pair has the exponential pressure-overclosure law (fcs_pressure_overclosure):
    !> it carries force at positive clearance up to c0, and opens and closes by its gap
    !> crossing c0 instead of by its normal force reaching zero.
    pure module function exponential(this, s) result(yes)
      type(contact_system_t), intent(in) :: this
      integer, intent(in) :: s
      logical :: yes
    end function exponential

    !> Clearance c0 up to which slave s's law acts (exponential law only).
    pure module function law_reach(this, s) result(reach)
      type(contact_system_t), intent(in) :: this
      integer, intent(in) :: s
      real(dp) :: reach
    end function law_reach

    !> Open slave s: no forces, on `face` (0: none in reach) at point p with gap `gap`.
    module subroutine open_node(cstate, s, face, p, gap)
      type(contact_state_t), intent(inout) :: cstate
      integer, intent(in) :: s, face
      type(segment_point_t), intent(in) :: p
      real(dp), intent(in) :: gap
    end subroutine open_node
  end interface

contains

  pure integer function system_n_slaves(this)
    class(contact_system_t), intent(in) :: this
    system_n_slaves = 0
    if (allocated(this%slave_node)) system_n_slaves = size(this%slave_node)
  end function system_n_slaves

  !> Write the search and pattern bookkeeping that a restart needs to continue exactly into
  !> group /contact_system of `archive`: the face each slave's pattern clique was built
  !> around, whether the pattern is due for a rebuild, and the coordinates each pair's search
  !> grid was built on (the grid is rebuilt from them, as it was). Nothing without slaves.
  subroutine system_save(this, archive, err)
    class(contact_system_t), intent(in) :: this
    class(archive_t), intent(inout) :: archive
    type(error_t), allocatable, intent(out) :: err
    integer :: k
    if (this%n_slaves() == 0) return
    call archive%group('/contact_system', err)
    if (.not. allocated(err)) call archive%put('/contact_system/pattern_face', this%pattern_face, err)
    do k = 1, size(this%pairs)
      if (allocated(err)) return
      call archive%put('/contact_system/grid_' // str(k), this%pairs(k)%grid%built_x, err)
    end do
    if (.not. allocated(err)) call archive%put_flag('/contact_system', 'pattern_dirty', &
                                                    this%pattern_dirty, err)
  end subroutine system_save

  !> Read what `save` wrote into a system set up for the same model (`init`).
  subroutine system_load(this, archive, err)
    class(contact_system_t), intent(inout) :: this
    class(archive_t), intent(inout) :: archive
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: grid(:, :, :)
    integer :: k
    if (this%n_slaves() == 0) return
    call archive%get('/contact_system/pattern_face', this%pattern_face, err)
    do k = 1, size(this%pairs)
      if (allocated(err)) return
      allocate (grid, mold=this%pairs(k)%grid%built_x)
      call archive%get('/contact_system/grid_' // str(k), grid, err)
      if (.not. allocated(err)) call this%pairs(k)%grid%build(grid, this%pairs(k)%reach)
      deallocate (grid)
    end do
    if (.not. allocated(err)) call archive%get_flag('/contact_system', 'pattern_dirty', &
                                                    this%pattern_dirty, err)
  end subroutine system_load

  !> Set up the pairs `defs` on `mesh`, pair k with the friction law `frictions(k)`, on
  !> coordinates x, and find the initial contact state.
  subroutine system_init(this, defs, frictions, mesh, x, cstate, err)
    class(contact_system_t), intent(inout) :: this
    type(contact_pair_def_t), intent(in) :: defs(:)
    type(friction_def_t), intent(in) :: frictions(:)
    type(mesh_t), intent(in) :: mesh
    real(dp), intent(in) :: x(:, :)
    type(contact_state_t), intent(inout) :: cstate
    type(error_t), allocatable, intent(out) :: err
    integer :: k, n_total, i
    integer, allocatable :: slaves(:), slave_faces(:, :)
    real(dp), allocatable :: areas(:)
    logical, allocatable :: tied(:), carries(:)
    allocate (this%pairs(size(defs)), this%slave_node(0), this%slave_pair(0), this%area(0), &
              this%point_ptr(1), this%point_nodes(0), this%point_weight(0))
    this%point_ptr(1) = 1
    do k = 1, size(defs)
      call pair_setup(this%pairs(k), defs(k), frictions(k), mesh, x, err)
      if (allocated(err)) return
    end do
    call tied_nodes(this, defs, mesh, x, tied)
    this%reference = mesh%x
    do k = 1, size(defs)
      if (.not. this%pairs(k)%tied) cycle
      call surface_face_nodes(mesh, defs(k)%slave_surface, slave_faces, err)
      if (allocated(err)) return
      if (size(slave_faces, 1) /= 4 .or. size(this%pairs(k)%face_nodes, 1) /= 4 .or. &
          any(slave_faces == 0) .or. any(this%pairs(k)%face_nodes == 0)) then
        call input_error(err, format_location(defs(k)%loc, '*TIE ' // defs(k)%name // ': the ' // &
          'segment-to-segment tie integrates 4-node (bilinear quadrilateral) faces only; its ' // &
          'surfaces have triangular or quadratic faces (not supported yet: use C3D8 elements ' // &
          'next to the tied surfaces)'))
        return
      end if
      call this%ties%add(slave_faces, this%pairs(k)%face_nodes, x, this%pairs(k)%normal_stiffness, &
                         this%pairs(k)%position_tolerance, k)
    end do
    n_total = 0
    do k = 1, size(defs)
      if (this%pairs(k)%surface_to_surface .and. .not. this%pairs(k)%tied) then
        call add_face_points(this, k, defs(k), mesh, x, n_total, err)
        if (allocated(err)) return
        cycle
      end if
      call slave_nodes_of(mesh, defs(k), this%pairs(k), slaves)
      if (.not. this%pairs(k)%tied) then
        this%pairs(k)%n_held_by_tie = count(tied(slaves))
        slaves = pack(slaves, .not. tied(slaves))
      end if
      call slave_node_areas(mesh, defs(k)%slave_surface, slaves, areas, err, carries)
      if (allocated(err)) then
        err%message = 'contact pair ' // defs(k)%name // ': ' // err%message
        return
      end if
      ! Nodes whose consistent share of the slave surface is zero (corners of 6-node
      ! triangles) carry no contact force: no contact element (fcs_contact_areas).
      if (.not. all(carries)) then
        slaves = pack(slaves, carries)
        areas = pack(areas, carries)
      end if
      this%pairs(k)%first = n_total + 1
      this%pairs(k)%last = n_total + size(slaves)
      n_total = n_total + size(slaves)
      this%slave_node = [this%slave_node, slaves]
      this%slave_pair = [this%slave_pair, spread(k, 1, size(slaves))]
      this%area = [this%area, areas]
      this%point_ptr = [this%point_ptr, size(this%point_nodes) + [(i, i = 1, size(slaves))] + 1]
      this%point_nodes = [this%point_nodes, slaves]
      this%point_weight = [this%point_weight, spread(1.0_dp, 1, size(slaves))]
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

  !> The entries of surface-to-surface pair k (`def`): the integration points of its slave
  !> faces on coordinates x (fcs_contact_points), appended after the n_total entries so far.
  subroutine add_face_points(this, k, def, mesh, x, n_total, err)
    type(contact_system_t), intent(inout) :: this
    integer, intent(in) :: k
    type(contact_pair_def_t), intent(in) :: def
    type(mesh_t), intent(in) :: mesh
    real(dp), intent(in) :: x(:, :)
    integer, intent(inout) :: n_total
    type(error_t), allocatable, intent(out) :: err
    type(slave_points_t) :: points
    integer :: n
    call slave_face_points(mesh, def%slave_surface, this%pairs(k)%face_nodes, x, this%pairs(k)%reach, &
                           points, err)
    if (allocated(err)) then
      err%message = format_location(def%loc, '*CONTACT PAIR ' // def%name // ': ' // err%message)
      return
    end if
    n = size(points%node)
    this%pairs(k)%first = n_total + 1
    this%pairs(k)%last = n_total + n
    n_total = n_total + n
    this%slave_node = [this%slave_node, points%node]
    this%slave_pair = [this%slave_pair, spread(k, 1, n)]
    this%area = [this%area, points%area]
    this%point_ptr = [this%point_ptr, size(this%point_nodes) + points%ptr(2:)]
    this%point_nodes = [this%point_nodes, points%nodes]
    this%point_weight = [this%point_weight, points%weight]
  end subroutine add_face_points

  !> The nodes a tie holds: slave nodes of a tied pair within its position tolerance of its
  !> master surface (those `initial_state` ties). A node both tied and a slave of a contact
  !> pair (the end of a fault segment next to a tied segment) is left to the tie and taken
  !> out of the contact pair, as Abaqus does with such overconstraints: two penalty elements
  !> on one node, the tie's and a frictional one, would otherwise both act on it and the
  !> frictional one would record a slip the tie does not allow.
  subroutine tied_nodes(this, defs, mesh, x, tied)
    type(contact_system_t), intent(in) :: this
    type(contact_pair_def_t), intent(in) :: defs(:)
    type(mesh_t), intent(in) :: mesh
    real(dp), intent(in) :: x(:, :)
    logical, allocatable, intent(out) :: tied(:)
    type(segment_point_t) :: p
    integer, allocatable :: slaves(:)
    integer :: k, i, face
    real(dp) :: gap
    allocate (tied(mesh%n_nodes))
    tied = .false.
    do k = 1, size(this%pairs)
      if (.not. this%pairs(k)%tied) cycle
      call slave_nodes_of(mesh, defs(k), this%pairs(k), slaves)
      do i = 1, size(slaves)
        call search(this%pairs(k), x, x(:, slaves(i)), face, p, gap)
        if (face /= 0) tied(slaves(i)) = tied(slaves(i)) .or. &
                                         abs(gap) <= this%pairs(k)%position_tolerance
      end do
    end do
  end subroutine tied_nodes

  !> Slave nodes of a pair: the slave surface's nodes, less those on the master surface.
  subroutine slave_nodes_of(mesh, def, pair, slaves)
    type(mesh_t), intent(in) :: mesh
    type(contact_pair_def_t), intent(in) :: def
    type(contact_pair_t), intent(in) :: pair
    integer, allocatable, intent(out) :: slaves(:)
    integer, allocatable :: all(:), master(:)
    logical, allocatable :: on_master(:)
    integer :: i
    all = mesh%surface_node_list(def%slave_surface)
    master = unique_sorted(pack(pair%face_nodes, pair%face_nodes /= 0))
    allocate (on_master(mesh%n_nodes))
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
        call search(pair, x, slave_position(this, s, x), face, p, gap)
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
        else if (initially_closed(this, s, gap)) then
          u = contact_update(p, gap, p, node_of(cstate, s, CONTACT_STICK), params_of(this, s, face, p%xi), &
                             pair%law, 0.0_dp)
          cstate%status(s) = closing_status(u%mu)
          cstate%normal_force(s) = u%normal_force
          cstate%mu(s) = u%mu
        end if
      end associate
    end do
  end subroutine initial_state

  !> A node at gap `gap` at the start of the run is closed: it touches (within GAP_TOLERANCE
  !> of the master face size), or, under the exponential law, its clearance is at most c0.
  logical function initially_closed(this, s, gap)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    real(dp), intent(in) :: gap
    if (exponential(this, s)) then
      initially_closed = gap <= law_reach(this, s)
    else
      initially_closed = gap <= GAP_TOLERANCE * this%pairs(this%slave_pair(s))%face_size
    end if
  end function initially_closed





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
        nodes = this%point_nodes(this%point_ptr(s):this%point_ptr(s + 1) - 1)
        do j = pair%neighbor_ptr(f), pair%neighbor_ptr(f + 1) - 1
          nodes = [nodes, pair_face_nodes(pair, pair%neighbors(j))]
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
    integer :: s, a, n_dof
    integer, allocatable :: nodes(:), all_nodes(:)
    real(dp), allocatable :: stiffness(:, :), force(:)
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
      if (this%pairs(this%slave_pair(s))%surface_to_surface) then
        call expand_element(this, s, nodes, lin, all_nodes, stiffness, force)
        call matrix%add_matrix(all_nodes, stiffness, missing)
        if (missing) then
          call fatal_error(err, 'internal error: contact element of point ' // str(s) // &
                           ' is not in the sparse pattern')
          return
        end if
        do a = 1, size(all_nodes)
          f_contact(3 * all_nodes(a) - 2:3 * all_nodes(a)) = f_contact(3 * all_nodes(a) - 2:3 * all_nodes(a)) + &
            force(3 * a - 2:3 * a)
        end do
        cycle
      end if
      n_dof = 3 * size(nodes)
      call matrix%add_matrix(nodes, lin%stiffness(1:n_dof, 1:n_dof), missing)
      if (missing) then
        call fatal_error(err, 'internal error: contact element of node ' // str(nodes(1)) // &
                         ' is not in the sparse pattern')
        return
      end if
      do a = 1, size(nodes)
        f_contact(3 * nodes(a) - 2:3 * nodes(a)) = f_contact(3 * nodes(a) - 2:3 * nodes(a)) + &
          lin%force(3 * a - 2:3 * a)
      end do
    end do
  end subroutine system_assemble



  !> twin(s): the next entry of the same node in another pair (a cycle through all of them),
  !> 0 for a node that is a slave of one pair only.
  subroutine find_twins(this)
    type(contact_system_t), intent(inout) :: this
    integer, allocatable :: order(:), key(:)
    integer :: i, j, first, n
    n = size(this%slave_node)
    allocate (this%twin(n))
    this%twin = 0
    ! The points of surface-to-surface pairs have no twins: each its own negative key.
    key = this%slave_node
    do i = 1, n
      if (this%pairs(this%slave_pair(i))%surface_to_surface) key(i) = -i
    end do
    order = argsort_integers(key)
    i = 1
    do while (i <= n)
      first = i
      do while (i < n)
        if (key(order(i + 1)) /= key(order(first))) exit
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
    real(dp) :: due(MAX_ELEMENT_DOFS), gap
    integer :: s
    integer, allocatable :: nodes(:)
    do s = 1, size(this%slave_node)
      if (cstate%status(s) /= CONTACT_STICK .and. cstate%status(s) /= CONTACT_SLIP) cycle
      nodes = element_nodes(this, s, cstate)
      call gather_increment(this, s, nodes, du, due(1:3 * size(nodes)))
      p = segment_point(x(:, nodes(2:)), cstate%xi(:, s))
      gap = cstate%gap(s) + relative_normal(p, due(1:3 * size(nodes)))
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
    integer :: s, a, i
    integer, allocatable :: nodes(:)
    call this%ties%forces(x - this%reference, f_contact)
    do s = 1, size(this%slave_node)
      if (cstate%status(s) == CONTACT_OPEN .or. cstate%status(s) == CONTACT_TIED .or. &
          cstate%face(s) == 0) cycle
      call this%traction(s, x, cstate, normal, pressure, shear)
      f = (pressure * normal + shear) * this%area(s)
      nodes = element_nodes(this, s, cstate)
      p = segment_point(x(:, nodes(2:)), cstate%xi(:, s))
      if (this%pairs(this%slave_pair(s))%surface_to_surface) then
        do a = this%point_ptr(s), this%point_ptr(s + 1) - 1
          i = this%point_nodes(a)
          f_contact(3 * i - 2:3 * i) = f_contact(3 * i - 2:3 * i) + this%point_weight(a) * f
        end do
      else
        f_contact(3 * nodes(1) - 2:3 * nodes(1)) = f_contact(3 * nodes(1) - 2:3 * nodes(1)) + f
      end if
      do a = 2, size(nodes)
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
    real(dp) :: traction(3), normal(3), pressure, shear(3), sum_pressure, sum_shear
    integer :: s, first, last, n_closed
    first = this%pairs(k)%first
    last = this%pairs(k)%last
    sum_pressure = 0.0_dp
    sum_shear = 0.0_dp
    n_closed = 0
    do s = first, last
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
      if (cstate%status(s) == CONTACT_OPEN) cycle
      sum_pressure = sum_pressure + pressure
      sum_shear = sum_shear + norm2(shear)
      n_closed = n_closed + 1
    end do
    t%slip_mean = sum(cstate%slip(first:last)) / max(1, last - first + 1)
    t%slip_max = maxval(cstate%slip(first:last))
    t%rate_max = maxval(cstate%slip_rate(first:last))
    t%pressure_mean = sum_pressure / max(1, n_closed)
    t%shear_mean = sum_shear / max(1, n_closed)
  end function system_totals

  !> Number of contact pairs.
  pure integer function system_n_pairs(this) result(n)
    class(contact_system_t), intent(in) :: this
    n = 0
    if (allocated(this%pairs)) n = size(this%pairs)
  end function system_n_pairs

  !> Name of pair k (as in the deck).
  pure function system_pair_name(this, k) result(name)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: k
    character(len=:), allocatable :: name
    name = this%pairs(k)%name
  end function system_pair_name

  !> Whether pair k is tied (*TIE).
  pure logical function system_pair_is_tied(this, k) result(tied)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: k
    tied = this%pairs(k)%tied
  end function system_pair_is_tied

  !> *CHANGE FRICTION (CalculiX's meaning): pair k takes the friction law `friction` (and the
  !> stick slope `stick_stiffness` when positive) and its closed nodes are brought onto the new
  !> cone: a friction force beyond it is scaled back onto it and the node slips, the return
  !> mapping of the paper's friction-as-plasticity treatment (eqs. 2-6) applied to the stored
  !> force; a slipping node on the cone (within CHANGE_CONE_TOLERANCE) keeps slipping; any other
  !> closed node sticks; on a frictionless interface a closed node slips with f_t = 0.
  !> Idempotent, so a run resuming within a step applies it again without effect.
  subroutine system_set_pair_friction(this, k, friction, stick_stiffness, cstate, err)
    class(contact_system_t), intent(inout) :: this
    integer, intent(in) :: k
    type(friction_def_t), intent(in) :: friction
    real(dp), intent(in) :: stick_stiffness
    type(contact_state_t), intent(inout) :: cstate
    type(error_t), allocatable, intent(out) :: err
    real(dp), parameter :: CHANGE_CONE_TOLERANCE = 1.0e-9_dp
    real(dp) :: mu, limit, magnitude
    integer :: s
    associate (pair => this%pairs(k))
      if (allocated(pair%law)) deallocate (pair%law)
      call create_friction_law(friction, pair%law, err)
      if (allocated(err)) return
      if (stick_stiffness > 0.0_dp) pair%stick_stiffness = stick_stiffness
      mu = pair%law%mu(0.0_dp, 0.0_dp, pair%law%initial_state())
      do s = pair%first, pair%last
        if (cstate%status(s) /= CONTACT_STICK .and. cstate%status(s) /= CONTACT_SLIP) cycle
        cstate%mu(s) = mu
        limit = mu * max(cstate%normal_force(s), 0.0_dp)
        magnitude = norm2(cstate%friction(:, s))
        if (mu <= 0.0_dp .or. magnitude > limit * (1.0_dp + CHANGE_CONE_TOLERANCE)) then
          if (magnitude > 0.0_dp) cstate%friction(:, s) = cstate%friction(:, s) * (limit / magnitude)
          cstate%trial_norm(s) = max(magnitude, limit)
          cstate%status(s) = CONTACT_SLIP
        else if (cstate%status(s) /= CONTACT_SLIP .or. &
                 magnitude < limit * (1.0_dp - CHANGE_CONE_TOLERANCE)) then
          cstate%status(s) = CONTACT_STICK
        end if
      end do
    end associate
  end subroutine system_set_pair_friction

  !> *CHANGE SURFACE BEHAVIOR (CalculiX's meaning): pair k takes the normal behaviour of its
  !> interaction anew: the penalty `normal_stiffness` (when positive) and the pressure-
  !> overclosure law `overclosure`. A tied pair whose behaviour is no longer TIED is released:
  !> its tie stops coupling the surfaces (tie_set_t%release) and its slave entries (its slave
  !> nodes, also for a surface-to-surface pair) become ordinary contact nodes, open, which the
  !> next update searches and closes if they touch. Idempotent (a run resuming within a step
  !> applies it again without effect).
  subroutine system_set_pair_behavior(this, k, normal_stiffness, overclosure, cstate)
    class(contact_system_t), intent(inout) :: this
    integer, intent(in) :: k
    real(dp), intent(in) :: normal_stiffness
    type(pressure_overclosure_t), intent(in) :: overclosure
    type(contact_state_t), intent(inout) :: cstate
    type(segment_point_t) :: p
    integer :: s
    associate (pair => this%pairs(k))
      if (normal_stiffness > 0.0_dp) pair%normal_stiffness = normal_stiffness
      pair%overclosure = overclosure
      if (pair%overclosure%is_exponential()) pair%reach = max(pair%face_size, 2.0_dp * overclosure%c0)
      if (.not. pair%tied) return
      pair%tied = .false.
      call this%ties%release(k)
      do s = pair%first, pair%last
        if (cstate%status(s) /= CONTACT_TIED) cycle
        p%xi = cstate%xi(:, s)
        call open_node(cstate, s, cstate%face(s), p, cstate%gap(s))
        cstate%tied_gap(s) = 0.0_dp
      end do
    end associate
  end subroutine system_set_pair_behavior

  !> The node (index) of each slave entry of pair k, in the pair's order (the order of its
  !> output fields and of `pair_slip`).
  pure function system_pair_slave_nodes(this, k) result(nodes)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: k
    integer, allocatable :: nodes(:)
    nodes = this%slave_node(this%pairs(k)%first:this%pairs(k)%last)
  end function system_pair_slave_nodes

  !> Positions on coordinates x of the slave entries of pair k, in the pair's order: its slave
  !> nodes, or the integration points of a surface-to-surface pair.
  pure function system_pair_positions(this, k, x) result(positions)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: k
    real(dp), intent(in) :: x(:, :)
    real(dp), allocatable :: positions(:, :)
    integer :: s
    allocate (positions(3, this%pairs(k)%last - this%pairs(k)%first + 1))
    do s = this%pairs(k)%first, this%pairs(k)%last
      positions(:, s - this%pairs(k)%first + 1) = slave_position(this, s, x)
    end do
  end function system_pair_positions

  !> Slave nodes of the surface of pair k left out of it because a tie holds them.
  pure integer function system_held_by_tie(this, k) result(n)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: k
    n = this%pairs(k)%n_held_by_tie
  end function system_held_by_tie

  !> Whether the contact elements have moved out of the sparse pattern (`cliques` rebuilds it).
  pure logical function system_needs_pattern(this) result(dirty)
    class(contact_system_t), intent(in) :: this
    dirty = this%pattern_dirty
  end function system_needs_pattern

  !> The largest changes over the last increment at nodes slipping before and after it, of
  !> ln V, of mu and of the friction law's state measure, and the largest slip of a slipping
  !> node over its law's characteristic slip L (0: none), and the node of each.
  pure subroutine system_friction_changes(this, change, node)
    class(contact_system_t), intent(in) :: this
    real(dp), intent(out) :: change(4)
    integer, intent(out) :: node(4)
    change = this%change
    node = this%change_node
  end subroutine system_friction_changes

  !> The output fields of pair k on coordinates x, on the surface grid `grid` (its slave
  !> nodes in the pair's order): status (CONTACT_OPEN/STICK/SLIP/TIED), gap (0 without a
  !> master face in reach), pressure and shear traction magnitude, accumulated slip, slip rate,
  !> friction coefficient, the friction law's state variable (theta [time] of the
  !> rate-and-state laws, the accumulated slip [length] of SLIP WEAKENING, 0 for laws without
  !> state), and the shear traction vector.
  function system_pair_fields(this, k, x, cstate, grid) result(fields)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: k
    real(dp), intent(in) :: x(:, :)
    type(contact_state_t), intent(in) :: cstate
    character(len=*), intent(in) :: grid
    type(field_t), allocatable :: fields(:)
    character(len=*), parameter :: NAMES(8) = [character(len=15) :: 'status', 'gap', 'pressure', &
      'shear_magnitude', 'slip', 'slip_rate', 'mu', 'friction_state']
    real(dp), allocatable :: values(:, :), shear(:, :)
    real(dp) :: normal(3), pressure, traction(3)
    integer :: s, j, first, last
    first = this%pairs(k)%first
    last = this%pairs(k)%last
    allocate (values(8, last - first + 1), shear(3, last - first + 1))
    do s = first, last
      j = s - first + 1
      call this%traction(s, x, cstate, normal, pressure, traction)
      values(:, j) = [real(cstate%status(s), dp), cstate%gap(s), pressure, norm2(traction), &
                      cstate%slip(s), cstate%slip_rate(s), cstate%mu(s), cstate%friction_state(s)]
      if (cstate%face(s) == 0) values(2, j) = 0.0_dp
      shear(:, j) = traction
    end do
    allocate (fields(9))
    do j = 1, 8
      fields(j) = field(trim(NAMES(j)), FIELD_SURFACE, values(j:j, :), grid)
    end do
    fields(9) = field('shear', FIELD_SURFACE, shear, grid)
  end function system_pair_fields

  !> Slip rate, accumulated slip and shear traction magnitude of the slave entries of pair k
  !> (the event catalog's view).
  subroutine system_pair_slip(this, k, x, cstate, rate, slip, shear)
    class(contact_system_t), intent(in) :: this
    integer, intent(in) :: k
    real(dp), intent(in) :: x(:, :)
    type(contact_state_t), intent(in) :: cstate
    real(dp), allocatable, intent(out) :: rate(:), slip(:), shear(:)
    real(dp) :: normal(3), pressure, traction(3)
    integer :: s, first, last
    first = this%pairs(k)%first
    last = this%pairs(k)%last
    rate = cstate%slip_rate(first:last)
    slip = cstate%slip(first:last)
    allocate (shear(last - first + 1))
    do s = first, last
      call this%traction(s, x, cstate, normal, pressure, traction)
      shear(s - first + 1) = norm2(traction)
    end do
  end subroutine system_pair_slip

  !> Frictional work dissipated at all slave nodes so far [force x length].
  pure real(dp) function system_frictional_work(this, cstate) result(work)
    class(contact_system_t), intent(in) :: this
    type(contact_state_t), intent(in) :: cstate
    work = sum(cstate%work)
  end function system_frictional_work

  !> For every slave entry: its node, whether it is closed (not open), and its values in the
  !> local frame of its master face as CalculiX prints them (`local_values`: relative
  !> displacement and stresses).
  subroutine system_print_values(this, x, cstate, node, closed, displacement, stress)
    class(contact_system_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :)
    type(contact_state_t), intent(in) :: cstate
    integer, allocatable, intent(out) :: node(:)
    logical, allocatable, intent(out) :: closed(:)
    real(dp), allocatable, intent(out) :: displacement(:, :), stress(:, :)
    integer :: s
    if (.not. allocated(this%slave_node) .or. .not. allocated(cstate%status)) then
      ! No contact pair (a deck with *CONTACT PRINT and none, as CalculiX allows): no rows.
      allocate (node(0), closed(0), displacement(3, 0), stress(3, 0))
      return
    end if
    node = this%slave_node
    closed = cstate%status /= CONTACT_OPEN
    allocate (displacement(3, size(node)), stress(3, size(node)))
    displacement = 0.0_dp
    stress = 0.0_dp
    do s = 1, size(node)
      if (closed(s)) call this%local_values(s, x, cstate, displacement(:, s), stress(:, s))
    end do
  end subroutine system_print_values

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
    p = segment_point(x(:, pair_face_nodes(this%pairs(this%slave_pair(s)), cstate%face(s))), cstate%xi(:, s))
    normal = p%normal
    if (cstate%status(s) == CONTACT_OPEN) return
    pressure = cstate%normal_force(s) / this%area(s)
    shear = (cstate%friction(1, s) * p%e(:, 1) + cstate%friction(2, s) * p%e(:, 2)) / this%area(s)
  end subroutine system_traction

end module fcs_contact_system
