!> The contact system's view of one slave node (fcs_contact_system, which declares these
!> procedures; the events and the update use them as the system does): its contact element
!> (node_of, params_of, element_nodes), the friction coefficient of its cone, its
!> linearisation, how it is held, when it closes and opens, its gap change.
submodule (fcs_contact_system) fcs_contact_nodes
  implicit none

contains

  !> Documented with its interface in fcs_contact_system.
  module procedure closing_status
    status = CONTACT_STICK
    if (mu <= 0.0_dp) status = CONTACT_SLIP
  end procedure closing_status

  !> Documented with its interface in fcs_contact_system.
  module procedure node_of
    node%status = status
    node%normal_force = cstate%normal_force(s)
    node%friction = cstate%friction(:, s)
    node%trial_norm = max(cstate%trial_norm(s), norm2(cstate%friction(:, s)))
    node%friction_state = cstate%friction_state(s)
    node%tied_gap = cstate%tied_gap(s)
    node%slip_rate = cstate%slip_rate(s)
    node%relative_rate = cstate%relative_rate(s)
  end procedure node_of

  !> Documented with its interface in fcs_contact_system.
  module procedure cone_mu
    associate (law => this%pairs(this%slave_pair(s))%law)
      ! During the equilibrium iterations of an increment the state is an iterate whose
      ! slip rate is the increment's own: its cone is the one its return mapping used.
      if (law%explicit_rate .and. .not. this%holding) then
        mu = law%mu(cstate%normal_force(s) / this%area(s), law_rate(law, cstate, s), &
                    cstate%friction_state(s))
      else
        mu = cstate%mu(s)
      end if
    end associate
  end procedure cone_mu

  !> Documented with its interface in fcs_contact_system.
  module procedure law_rate
    if (law%relative_velocity) then
      rate = cstate%relative_rate(s)
    else
      rate = cstate%slip_rate(s)
    end if
  end procedure law_rate

  !> Documented with its interface in fcs_contact_system.
  module procedure params_of
    params%area = this%area(s)
    params%normal_stiffness = this%pairs(this%slave_pair(s))%normal_stiffness
    params%stick_stiffness = this%pairs(this%slave_pair(s))%stick_stiffness
    params%damping = this%pairs(this%slave_pair(s))%radiation_damping
    params%overclosure = this%pairs(this%slave_pair(s))%overclosure
    params%relative_velocity = this%pairs(this%slave_pair(s))%law%relative_velocity
    if (present(face) .and. present(xi)) call edge_support(xi, &
      this%pairs(this%slave_pair(s))%free_edge(:, face), params%support, params%dsupport, &
      face_node_count(this%pairs(this%slave_pair(s))%face_nodes(:, face)))
  end procedure params_of

  !> Documented with its interface in fcs_contact_system.
  module procedure linearise
    type(segment_point_t) :: p, p_start
    type(friction_derivatives_t) :: fr
    type(contact_node_t) :: node
    type(contact_params_t) :: params
    real(dp), allocatable :: x5(:, :)
    integer :: start_face
    integer, allocatable :: nodes(:)
    associate (pair => this%pairs(this%slave_pair(s)))
      nodes = element_nodes(this, s, cstate)
      x5 = x(:, nodes)
      if (pair%surface_to_surface) x5(:, 1) = slave_position(this, s, x)
      p = segment_point(x5(:, 2:), cstate%xi(:, s))
      fr = pair%law%evaluate(cstate%normal_force(s) / this%area(s), &
                             law_rate(pair%law, cstate, s), cstate%friction_state(s))
      fr%mu = cone_mu(this, s, cstate)
      node = node_of(cstate, s, cstate%status(s))
      node%bilateral = hold_mode(this, s) == HOLD_CLOSED
      params = params_of(this, s, cstate%face(s), cstate%xi(:, s))
      ! An explicit rate is known at the start of the increment: no dmu/dV in the tangent (its
      ! rate term is then the radiation damping's alone, 0 without damping).
      if (pair%law%explicit_rate) then
        fr%dmu_drate = 0.0_dp
      else if (pair%law%relative_velocity) then
        fr%dmu_drate = relative_rate_derivative(this, s, cstate, fr, dt)
      end if
      start_face = 0
      if (this%holding) start_face = this%start_face(s)
      if (start_face == 0) then
        call contact_linearise(x5, p, cstate%gap(s), node, params, fr, dt, lin)
      else
        ! An iterate of the equilibrium iterations: it has slipped since the start point.
        p_start = segment_point(x(:, pair_face_nodes(pair, start_face)), this%start_xi(:, s))
        if (start_face == cstate%face(s)) then
          call contact_linearise(x5, p, cstate%gap(s), node, params, fr, dt, lin, &
                                 p%x - p_start%x, p_start%shape(1:p_start%n_nodes))
        else
          call contact_linearise(x5, p, cstate%gap(s), node, params, fr, dt, lin, &
                                 p%x - p_start%x)
        end if
      end if
    end associate
  end procedure linearise

  !> dmu/dV of slave s for the tangent of a law read with VELOCITY=RELATIVE and an implicit
  !> rate: mu = mu(V, phi(V)) with phi(V) the state evolved over dt at V from the state at the
  !> start of the increment (relative_return), so dmu/dV = d_mu/d_V + d_mu/d_phi d_phi/d_V;
  !> d_phi/d_V by central differences of the law's exact state update (relative step 1e-6).
  !> Without it the tangent of a slipping node has the direct effect A/V alone, while the
  !> update weakens as (A - B)/V once the state follows the rate within the increment.
  function relative_rate_derivative(this, s, cstate, fr, dt) result(dmu_drate)
    type(contact_system_t), intent(in) :: this
    integer, intent(in) :: s
    type(contact_state_t), intent(in) :: cstate
    type(friction_derivatives_t), intent(in) :: fr
    real(dp), intent(in) :: dt
    real(dp) :: dmu_drate
    real(dp), parameter :: STEP = 1.0e-6_dp
    real(dp) :: rate, state, dstate
    dmu_drate = fr%dmu_drate
    associate (law => this%pairs(this%slave_pair(s))%law)
      rate = cstate%relative_rate(s)
      if (law%n_state() == 0 .or. dt <= 0.0_dp .or. rate <= 0.0_dp) return
      state = cstate%friction_state(s)
      if (this%holding .and. allocated(this%start_state)) state = this%start_state(s)
      dstate = (law%evolve_state(state, rate * (1.0_dp + STEP), dt) - &
                law%evolve_state(state, rate * (1.0_dp - STEP), dt)) / (2.0_dp * STEP * rate)
      dmu_drate = dmu_drate + fr%dmu_dstate * dstate
    end associate
  end function relative_rate_derivative

  !> Documented with its interface in fcs_contact_system.
  module procedure element_nodes
    nodes = [this%slave_node(s), pair_face_nodes(this%pairs(this%slave_pair(s)), cstate%face(s))]
  end procedure element_nodes

  !> Documented with its interface in fcs_contact_system.
  module procedure slave_position
    integer :: a
    if (.not. this%pairs(this%slave_pair(s))%surface_to_surface) then
      xs = x(:, this%slave_node(s))
      return
    end if
    xs = 0.0_dp
    do a = this%point_ptr(s), this%point_ptr(s + 1) - 1
      xs = xs + this%point_weight(a) * x(:, this%point_nodes(a))
    end do
  end procedure slave_position

  !> Documented with its interface in fcs_contact_system.
  module procedure gather_increment
    integer :: a, i
    do a = 1, size(nodes)
      due(3 * a - 2:3 * a) = du(3 * nodes(a) - 2:3 * nodes(a))
    end do
    if (.not. this%pairs(this%slave_pair(s))%surface_to_surface) return
    due(1:3) = 0.0_dp
    do a = this%point_ptr(s), this%point_ptr(s + 1) - 1
      i = this%point_nodes(a)
      due(1:3) = due(1:3) + this%point_weight(a) * du(3 * i - 2:3 * i)
    end do
  end procedure gather_increment

  !> Documented with its interface in fcs_contact_system.
  module procedure expand_element
    real(dp), allocatable :: t(:, :)
    integer :: a, n_point, n_kernel, j
    n_point = this%point_ptr(s + 1) - this%point_ptr(s)
    n_kernel = 3 * size(nodes)
    all_nodes = [this%point_nodes(this%point_ptr(s):this%point_ptr(s + 1) - 1), nodes(2:)]
    allocate (t(n_kernel, 3 * size(all_nodes)))
    t = 0.0_dp
    do a = 1, n_point
      do j = 1, 3
        t(j, 3 * (a - 1) + j) = this%point_weight(this%point_ptr(s) + a - 1)
      end do
    end do
    do j = 4, n_kernel
      t(j, 3 * n_point + j - 3) = 1.0_dp
    end do
    force = matmul(lin%force(1:n_kernel), t)
    stiffness = matmul(transpose(t), matmul(lin%stiffness(1:n_kernel, 1:n_kernel), t))
  end procedure expand_element

  !> Documented with its interface in fcs_contact_system.
  module procedure relative_normal
    change = dot_product(p%normal, due(1:3) - matmul(reshape(due(4:3 + 3 * p%n_nodes), [3, p%n_nodes]), &
                                                     p%shape(1:p%n_nodes)))
  end procedure relative_normal

  !> Documented with its interface in fcs_contact_system.
  module procedure hold_mode
    mode = HOLD_NONE
    if (this%holding) mode = this%hold_status(s)
  end procedure hold_mode

  !> Documented with its interface in fcs_contact_system.
  module procedure normal_force_floor
    associate (pair => this%pairs(this%slave_pair(s)))
      floor = GAP_TOLERANCE * pair%normal_stiffness * this%area(s) * pair%face_size
    end associate
  end procedure normal_force_floor

  !> Documented with its interface in fcs_contact_system.
  module procedure exponential
    yes = this%pairs(this%slave_pair(s))%overclosure%is_exponential()
  end procedure exponential

  !> Documented with its interface in fcs_contact_system.
  module procedure law_reach
    reach = this%pairs(this%slave_pair(s))%overclosure%reach()
  end procedure law_reach

  module procedure open_node
    cstate%status(s) = CONTACT_OPEN
    cstate%face(s) = face
    cstate%normal_force(s) = 0.0_dp
    cstate%friction(:, s) = 0.0_dp
    cstate%trial_norm(s) = 0.0_dp
    cstate%slip_rate(s) = 0.0_dp
    cstate%relative_rate(s) = 0.0_dp
    cstate%tangential_displacement(:, s) = 0.0_dp
    if (face == 0) return
    cstate%xi(:, s) = p%xi
    cstate%gap(s) = gap
  end procedure open_node

end submodule fcs_contact_nodes
