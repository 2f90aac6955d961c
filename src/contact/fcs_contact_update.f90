!> The contact system's update of the contact states after an increment (fcs_contact_system,
!> which declares these procedures): the return mapping of every closed node (Xing, Mora &
!> Makinouchi 2003, eq. 5), segment hand-over, opening, search for open nodes, tied nodes, and
!> the holding of states through the equilibrium iterations.
submodule (fcs_contact_system) fcs_contact_update
  implicit none

contains

  !> Documented with its interface in fcs_contact_system.
  module procedure system_update
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
    this%start_state = cstate%friction_state
    allocate (tie_force(size(x)))
    tie_force = 0.0_dp
    call this%ties%forces(x - this%reference, tie_force)
    do s = 1, size(this%slave_node)
      was_slipping = cstate%status(s) == CONTACT_SLIP .and. cstate%slip_rate(s) > 0.0_dp
      old_rate = law_rate(this%pairs(this%slave_pair(s))%law, cstate, s)
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
  end procedure system_update

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
    associate (pair => this%pairs(this%slave_pair(s)))
      in_extension = any(pair%free_edge(:, cstate%face(s)) .and. &
                         edge_excess(cstate%xi(:, s), face_node_count(pair%face_nodes(:, cstate%face(s)))) > XI_TOLERANCE)
    end associate
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
        if (all(edge_excess(cstate%xi(:, t), face_node_count(this%pairs(this%slave_pair(t))% &
                                                             face_nodes(:, cstate%face(t)))) <= XI_TOLERANCE)) then
          twin_inside = .true.
          return
        end if
      end if
      t = this%twin(t)
    end do
  end function twin_inside

  !> The changes of slipping node s over the increment that matter to its friction law: ln V
  !> for rate-dependent laws (V the law's rate, law_rate: the slip rate, or the total relative
  !> tangential velocity with VELOCITY=RELATIVE), mu, and the law's own state measure.
  subroutine record_friction_changes(this, s, old_rate, old_mu, old_state, cstate)
    type(contact_system_t), intent(inout) :: this
    integer, intent(in) :: s
    real(dp), intent(in) :: old_rate, old_mu, old_state
    type(contact_state_t), intent(in) :: cstate
    real(dp) :: log_rate
    associate (law => this%pairs(this%slave_pair(s))%law)
      log_rate = 0.0_dp
      if (law%rate_dependent() .and. old_rate > 0.0_dp) &
        log_rate = abs(log(law_rate(law, cstate, s) / old_rate))
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
    real(dp) :: gap, f(3)
    real(dp), allocatable :: xm(:, :)
    logical :: converged
    associate (pair => this%pairs(this%slave_pair(s)), node => this%slave_node(s))
      xm = x(:, pair_face_nodes(pair, cstate%face(s)))
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
      xs = slave_position(this, s, x)
      old_face = cstate%face(s)
      p_old = segment_point(x(:, pair_face_nodes(pair, old_face)), cstate%xi(:, s))
      mode = hold_mode(this, s)
      face = 0
      if (mode == HOLD_CLOSED) call held_point(this, s, pair, x, xs, old_face, cstate%xi(:, s), face, p, gap)
      if (face == 0) call follow(pair, x, xs, old_face, cstate%xi(:, s), face, p, gap)
      if (mode == HOLD_OPEN .or. face == 0 .or. (mode == HOLD_NONE .and. separated(this, s, gap))) then
        call open_node(cstate, s, face, p, gap)
        return
      end if
      ! The opening event of the increment was taken: the node opens if its normal force
      ! has (up to the linearisation error) come down to zero; under the exponential law, if
      ! its gap has come up to c0.
      params = params_of(this, s, face, p%xi)
      if (mode == HOLD_NONE .and. kind == EVENT_CONTACT_OPEN) then
        if (exponential(this, s)) then
          if (law_reach(this, s) - gap <= EVENT_BAND * (law_reach(this, s) - cstate%gap(s))) then
            call open_node(cstate, s, face, p, gap)
            return
          end if
        else if (params%support * pair%normal_stiffness * this%area(s) * (-gap) <= &
                 EVENT_BAND * cstate%normal_force(s)) then
          call open_node(cstate, s, face, p, gap)
          return
        end if
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

  !> A closed node at gap `gap` has separated: its gap exceeds GAP_TOLERANCE times the
  !> master face size, or, under the exponential law, c0 (where the law stops acting).
  logical function separated(this, s, gap)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    real(dp), intent(in) :: gap
    if (exponential(this, s)) then
      separated = gap > law_reach(this, s)
    else
      separated = gap > GAP_TOLERANCE * this%pairs(this%slave_pair(s))%face_size
    end if
  end function separated

  !> An open node at gap `gap` (at `start_gap` at the start of the increment, whose closing
  !> event was taken when kind is EVENT_CONTACT_CLOSE) closes: it penetrates (by more than
  !> GAP_TOLERANCE times the master face size) or its closing event brought it within the
  !> event band of touching; under the exponential law the same with the clearance c0 in
  !> place of contact (g <= c0 closes).
  logical function closes(this, s, gap, start_gap, kind)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s, kind
    real(dp), intent(in) :: gap, start_gap
    real(dp) :: c0
    if (exponential(this, s)) then
      c0 = law_reach(this, s)
      closes = gap <= c0 .or. (kind == EVENT_CONTACT_CLOSE .and. gap - c0 <= EVENT_BAND * (start_gap - c0))
    else
      closes = gap < -GAP_TOLERANCE * this%pairs(this%slave_pair(s))%face_size .or. &
               (kind == EVENT_CONTACT_CLOSE .and. gap <= EVENT_BAND * start_gap)
    end if
  end function closes

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
    cstate%relative_rate(s) = u%relative_rate
    cstate%mu(s) = u%mu
    cstate%friction_state(s) = u%friction_state
  end subroutine store_update

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
    integer, allocatable :: nodes(:)
    face = 0
    held = this%held_face(s)
    if (held == 0) return
    nodes = pair_face_nodes(pair, held)
    start = segment_centre(size(nodes))
    if (held == face_old) start = xi_old
    call project_to_segment(x(:, nodes), xs, start, p, gap, converged)
    if (.not. converged) return
    excess = edge_excess(p%xi, size(nodes))
    if (any(excess > merge(EDGE_EXTENSION, HOLD_LIMIT, pair%free_edge(:, held)))) return
    if (abs(gap) > pair%reach) return
    face = held
  end subroutine held_point

  !> Documented with its interface in fcs_contact_system.
  module procedure system_hold_states
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
  end procedure system_hold_states

  !> Documented with its interface in fcs_contact_system.
  module procedure system_check_held
    type(contact_params_t) :: params
    integer :: s
    n_changed = 0
    if (.not. this%holding) return
    do s = 1, size(this%slave_node)
      if (this%flips(s) >= MAX_HOLD_FLIPS) cycle
      select case (this%hold_status(s))
      case (HOLD_CLOSED)
        if (exponential(this, s)) then
          if (cstate%gap(s) <= law_reach(this, s)) cycle
        else if (cstate%normal_force(s) >= -normal_force_floor(this, s)) then
          cycle
        end if
        this%hold_status(s) = HOLD_OPEN
        this%held_face(s) = 0
      case (HOLD_OPEN)
        if (cstate%face(s) == 0) cycle
        if (this%twin(s) /= 0) then
          if (twin_inside(this, s, cstate)) cycle
        end if
        if (exponential(this, s)) then
          if (cstate%gap(s) > law_reach(this, s)) cycle
        else if (cstate%gap(s) >= -GAP_TOLERANCE * this%pairs(this%slave_pair(s))%face_size) then
          cycle
        end if
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
  end procedure system_check_held

  !> Documented with its interface in fcs_contact_system.
  module procedure system_release_states
    integer :: s
    this%holding = .false.
    do s = 1, size(this%slave_node)
      if (cstate%status(s) /= CONTACT_STICK .and. cstate%status(s) /= CONTACT_SLIP) cycle
      if (cstate%normal_force(s) >= 0.0_dp) cycle
      cstate%normal_force(s) = 0.0_dp
      cstate%friction(:, s) = 0.0_dp
    end do
  end procedure system_release_states

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
      if (mode == HOLD_CLOSED) call held_point(this, s, pair, x, slave_position(this, s, x), start_face, &
                                               start_xi, face, p, gap)
      if (face == 0) call search(pair, x, slave_position(this, s, x), face, p, gap)
      call open_node(cstate, s, face, p, gap)
      if (face == 0 .or. mode == HOLD_OPEN) return
      if (mode == HOLD_CLOSED .or. closes(this, s, gap, start_gap, kind)) then
        p_start = p
        if (start_face == face) p_start = segment_point(x(:, pair_face_nodes(pair, face)), start_xi)
        node = node_of(cstate, s, CONTACT_STICK)
        node%bilateral = mode == HOLD_CLOSED
        u = contact_update(p, gap, p_start, node, params_of(this, s, face, p%xi), pair%law, 0.0_dp)
        if (u%status == CONTACT_STICK) u%status = closing_status(u%mu)
        call store_update(cstate, s, u)
      end if
    end associate
  end subroutine update_open

end submodule fcs_contact_update
