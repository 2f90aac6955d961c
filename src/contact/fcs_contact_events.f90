!> The contact system's R-minimum events and stick/slip switches (fcs_contact_system, which
!> declares these procedures): the fractions of a trial increment at which nodes close, open,
!> start to slip or leave their segment (Xing, Mora & Makinouchi 2003, eq. 3), and the state
!> switches at the start of an increment.
submodule (fcs_contact_system) fcs_contact_events
  implicit none

contains

  !> Documented with its interface in fcs_contact_system.
  module procedure system_events
    type(contact_linear_t) :: lin
    type(segment_point_t) :: p
    real(dp) :: due_fixed(MAX_ELEMENT_DOFS), due_scaled(MAX_ELEMENT_DOFS), g_start, g_end
    integer :: s, n_dof
    integer, allocatable :: nodes(:)
    this%event_r = huge(1.0_dp)
    this%event_kind = EVENT_NONE
    ! The switch passes of this increment are over: the next increment's start afresh.
    this%switches = 0
    do s = 1, size(this%slave_node)
      if (cstate%face(s) == 0 .or. cstate%status(s) == CONTACT_TIED) cycle
      nodes = element_nodes(this, s, cstate)
      n_dof = 3 * size(nodes)
      call gather_increment(this, s, nodes, du_fixed, due_fixed(1:n_dof))
      call gather_increment(this, s, nodes, du_scaled, due_scaled(1:n_dof))
      if (cstate%status(s) == CONTACT_OPEN) then
        p = segment_point(x(:, nodes(2:)), cstate%xi(:, s))
        g_start = cstate%gap(s) + relative_normal(p, due_fixed(1:n_dof))
        g_end = g_start + relative_normal(p, due_scaled(1:n_dof))
        if (exponential(this, s)) then
          ! The exponential law acts from the clearance c0 on: the node closes there.
          if (cstate%gap(s) > law_reach(this, s) .and. g_end < law_reach(this, s)) &
            call offer(this, collector, s, crossing(g_start - law_reach(this, s), &
                       g_end - law_reach(this, s)), EVENT_CONTACT_CLOSE)
        else if (cstate%gap(s) > 0.0_dp .and. g_end < 0.0_dp) then
          call offer(this, collector, s, crossing(g_start, g_end), EVENT_CONTACT_CLOSE)
        end if
        cycle
      end if
      call linearise(this, s, x, cstate, 0.0_dp, lin)
      p = segment_point(x(:, nodes(2:)), cstate%xi(:, s))
      call closed_node_events(this, s, p, cstate, lin, due_fixed(1:n_dof), due_scaled(1:n_dof), &
                              collector, events)
    end do
  end procedure system_events

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

  !> Documented with its interface in fcs_contact_system.
  module procedure system_switch_states
    type(contact_linear_t) :: lin
    type(segment_point_t) :: p
    real(dp) :: due(MAX_ELEMENT_DOFS), fn, dfn, ft(3), dft(3), mu, qa, qb, qc, tolerance
    integer :: s, n_dof
    integer, allocatable :: nodes(:)
    logical :: on_cone
    n_switched = 0
    do s = 1, size(this%slave_node)
      if (cstate%status(s) /= CONTACT_STICK .and. cstate%status(s) /= CONTACT_SLIP) cycle
      if (this%switches(s) >= 10) cycle
      nodes = element_nodes(this, s, cstate)
      n_dof = 3 * size(nodes)
      call gather_increment(this, s, nodes, du, due(1:n_dof))
      call linearise(this, s, x, cstate, 0.0_dp, lin)
      p = segment_point(x(:, nodes(2:)), cstate%xi(:, s))
      fn = cstate%normal_force(s)
      dfn = dot_product(lin%dfn(1:n_dof), due(1:n_dof))
      ! A node closed at (numerically) zero normal force that the trial increment pulls into
      ! tension separates now: closed_node_events offers no opening event below the force
      ! floor, so its penalty spring would otherwise hold the bodies together in tension for
      ! the whole increment.
      if (.not. exponential(this, s) .and. fn <= normal_force_floor(this, s) .and. fn + dfn < 0.0_dp) then
        call open_node(cstate, s, cstate%face(s), p, cstate%gap(s))
        this%switches(s) = this%switches(s) + 1
        n_switched = n_switched + 1
        cycle
      end if
      ft = cstate%friction(1, s) * p%e(:, 1) + cstate%friction(2, s) * p%e(:, 2)
      if (norm2(ft) <= 0.0_dp) cycle
      mu = cone_mu(this, s, cstate)
      dft = matmul(lin%dft_stick(:, 1:n_dof), due(1:n_dof))
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
  end procedure system_switch_states

  !> Opening, stick-to-slip (the quadratic F(r) = 0 of eq. 3), segment exit, along the
  !> path du_fixed + r du_scaled, as `events` (CONTACT_EVENTS_*) asks: stick-to-slip and the
  !> hand-over to the next segment under ALL, opening and the exit from the master surface
  !> (the end of the extension past a free edge) under ALL and NORMAL.
  subroutine closed_node_events(this, s, p, cstate, lin, due_fixed, due_scaled, collector, &
                                events)
    type(contact_system_t), intent(inout) :: this
    integer, intent(in) :: s
    type(segment_point_t), intent(in) :: p
    type(contact_state_t), intent(in) :: cstate
    type(contact_linear_t), intent(in) :: lin
    real(dp), intent(in) :: due_fixed(:), due_scaled(:)
    type(rmin_collector_t), intent(inout) :: collector
    integer, intent(in) :: events
    real(dp) :: fn, dfn, ft(3), dft(3), mu, qa, qb, qc, xi_start(2), dxi(2), r, fn_floor, bound
    integer :: alpha, edge, n_dof
    n_dof = size(due_fixed)
    associate (pair => this%pairs(this%slave_pair(s)))
      fn = cstate%normal_force(s) + dot_product(lin%dfn(1:n_dof), due_fixed)
      dfn = dot_product(lin%dfn(1:n_dof), due_scaled)
      if (events == CONTACT_EVENTS_CLOSING) then
        continue
      else if (exponential(this, s)) then
        call exponential_opening(this, s, p, cstate, due_fixed, due_scaled, collector)
      else
        fn_floor = normal_force_floor(this, s)
        if (cstate%normal_force(s) > fn_floor .and. fn + dfn < 0.0_dp) &
          call offer(this, collector, s, crossing(fn, fn + dfn), EVENT_CONTACT_OPEN)
      end if
      ft = cstate%friction(1, s) * p%e(:, 1) + cstate%friction(2, s) * p%e(:, 2) + &
           matmul(lin%dft_stick(:, 1:n_dof), due_fixed)
      mu = cone_mu(this, s, cstate)
      if (cstate%status(s) == CONTACT_STICK .and. events == CONTACT_EVENTS_ALL) then
        dft = matmul(lin%dft_stick(:, 1:n_dof), due_scaled)
        qa = dot_product(dft, dft) - mu**2 * dfn**2
        qb = 2.0_dp * (dot_product(ft, dft) - mu**2 * fn * dfn)
        qc = dot_product(ft, ft) - mu**2 * fn**2
        r = cone_crossing(qa, qb, qc, cone_tolerance(fn, ft, dfn, dft, mu))
        if (r <= 1.0_dp) call offer(this, collector, s, r, EVENT_STICK_TO_SLIP)
      end if
      xi_start = cstate%xi(:, s) + matmul(lin%dxi(:, 1:n_dof), due_fixed)
      dxi = matmul(lin%dxi(:, 1:n_dof), due_scaled)
      if (is_triangle(p%n_nodes)) then
        call triangle_edge_events(this, s, cstate, xi_start, dxi, collector, events)
        return
      end if
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
        if (.not. edge_is_event(events, bound > 1.0_dp)) cycle
        if (abs(cstate%xi(alpha, s)) < bound - SEGMENT_EDGE_TOLERANCE .and. &
            abs(xi_start(alpha) + dxi(alpha)) > bound) &
          call offer(this, collector, s, crossing(abs(xi_start(alpha)) - bound, &
                     abs(xi_start(alpha) + dxi(alpha)) - bound), EVENT_SEGMENT_CHANGE)
      end do
    end associate
  end subroutine closed_node_events

  !> Opening of a closed node under the exponential law: its gap, linear along the path
  !> du_fixed + r du_scaled, reaches c0 (where the law stops acting; its normal force never
  !> reaches zero).
  subroutine exponential_opening(this, s, p, cstate, due_fixed, due_scaled, collector)
    type(contact_system_t), intent(inout) :: this
    integer, intent(in) :: s
    type(segment_point_t), intent(in) :: p
    type(contact_state_t), intent(in) :: cstate
    real(dp), intent(in) :: due_fixed(:), due_scaled(:)
    type(rmin_collector_t), intent(inout) :: collector
    real(dp) :: c0, g_start, g_end
    c0 = law_reach(this, s)
    g_start = cstate%gap(s) + relative_normal(p, due_fixed)
    g_end = g_start + relative_normal(p, due_scaled)
    if (cstate%gap(s) <= c0 .and. g_end > c0) &
      call offer(this, collector, s, crossing(g_start - c0, g_end - c0), EVENT_CONTACT_OPEN)
  end subroutine exponential_opening

  !> Segment events of a node on a triangular segment along xi_start + r dxi: reaching an
  !> edge (excess 0, the hand-over to the next segment) or the end of the extension past a
  !> free edge (excess EDGE_EXTENSION, the node leaves the master surface), from strictly
  !> before it (fcs_contact_search's edge excess, linear in xi); which of them are events,
  !> `events` says (edge_is_event).
  subroutine triangle_edge_events(this, s, cstate, xi_start, dxi, collector, events)
    type(contact_system_t), intent(inout) :: this
    integer, intent(in) :: s
    type(contact_state_t), intent(in) :: cstate
    real(dp), intent(in) :: xi_start(2), dxi(2)
    type(rmin_collector_t), intent(inout) :: collector
    integer, intent(in) :: events
    real(dp) :: now(4), start(4), finish(4), bound
    integer :: edge
    now = edge_excess(cstate%xi(:, s), 3)
    start = edge_excess(xi_start, 3)
    finish = edge_excess(xi_start + dxi, 3)
    do edge = 1, 3
      bound = 0.0_dp
      if (this%pairs(this%slave_pair(s))%free_edge(edge, cstate%face(s))) bound = EDGE_EXTENSION
      if (.not. edge_is_event(events, bound > 0.0_dp)) cycle
      if (now(edge) < bound - SEGMENT_EDGE_TOLERANCE .and. finish(edge) > bound) &
        call offer(this, collector, s, crossing(start(edge) - bound, finish(edge) - bound), &
                   EVENT_SEGMENT_CHANGE)
    end do
  end subroutine triangle_edge_events

  !> Is reaching an edge of the segment an event under `events` (CONTACT_EVENTS_*)? The end of
  !> the extension past a free edge (`free`: the node leaves the master surface) is under ALL
  !> and NORMAL, a shared edge (the hand-over to the next segment) under ALL only.
  pure logical function edge_is_event(events, free)
    integer, intent(in) :: events
    logical, intent(in) :: free
    if (free) then
      edge_is_event = events /= CONTACT_EVENTS_CLOSING
    else
      edge_is_event = events == CONTACT_EVENTS_ALL
    end if
  end function edge_is_event

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



end submodule fcs_contact_events
