!> The node-to-point contact element (Xing & Makinouchi 2000, 2002; Xing, Mora & Makinouchi
!> 2003, eqs. 2-9): a slave node s against the point c at natural coordinates xi of a master
!> segment of gamma = 3, 4, 6 or 8 nodes (fcs_contact_geometry). Degrees of freedom: u_s,
!> u_1..u_gamma (3 (1 + gamma), at most MAX_ELEMENT_DOFS = 27), assembly vector
!> R = [1, -N_1, ..., -N_gamma] (eq. 8) with the segment's own shape functions.
!>
!> Forces on the slave node: f = f_n n + f_t, with the penalty normal force f_n = E_n A (-g)
!> (g = n.(x_s - x_c) < 0 in penetration, A the slave node's tributary area), or with the
!> exponential pressure-overclosure law f_n = A p0 exp(-beta g) (fcs_pressure_overclosure), and the
!> frictional force f_t = f_m e_m kept by its components f_m in the local Cartesian frame
!> e_m of the master segment (the paper's e_i). Friction is treated like plasticity:
!> stick f_m = -E_t A u~_m^e (eq. 4; the force on the slave opposes its motion relative to
!> the master), slip on the cone |f_t| = mu f_n (eqs. 3, 5), return mapping
!> f^tr = f_old - E_t A du~ (eq. 5), f = mu f_n f^tr/|f^tr| when outside.
!>
!> Radiation damping (the quasi-dynamic approximation of Rice 1993, eq. 5; Rice & Ben-Zion
!> 1996): a slipping node resists with its frictional strength plus eta A V, eta = G/(2 c_s)
!> for one elastic material (fcs_model_checks), A its area and V its slip rate, so that the
!> friction stress it can hold, tau = f - eta V in Rice's notation, is the strength f less the
!> stress the radiated shear waves would carry away. It enters the return mapping (a viscous
!> spring eta A / dt in parallel with the rate term) and the rate term of the tangent.
!>
!> `contact_linearise` gives the derivatives of every contact quantity with respect to the
!> 3 (1 + gamma) nodal displacements on the current configuration: the gap, the natural coordinates of
!> the contact point (delta xi = A^-1 [a.du~ + g n.delta a], A = m - g h: the metric and
!> curvature terms), the normal, the frame, the forces, and the tangent K_f = -dF/du
!> (eqs. 6-9): the linearised friction law of eq. (6) (stick: E_t; slip: the projection
!> (I - eta eta) with factor mu f_n E_t/|f^tr|, the eta mu df_n coupling and the d mu terms)
!> plus the geometric terms from the rotation of n and e_m with the master surface and the
!> motion of the contact point along it (the H and C-bar terms of eq. 9). The unit tests
!> check K_f against finite differences of `contact_update`.
module fcs_contact_element
  use fcs_kinds, only: dp
  use fcs_contact_geometry, only: segment_point_t, segment_point, cross3, MAX_SEGMENT_NODES
  use fcs_friction_law, only: friction_law_t, friction_derivatives_t
  use fcs_pressure_overclosure, only: pressure_overclosure_t
  implicit none
  private
  public :: contact_linear_t, contact_linearise, contact_update, contact_update_t
  public :: contact_node_t, contact_params_t, MAX_ELEMENT_DOFS
  public :: CONTACT_OPEN, CONTACT_STICK, CONTACT_SLIP, CONTACT_TIED, contact_status_name

  !> Most degrees of freedom of a contact element: the slave and an 8-node segment.
  integer, parameter :: MAX_ELEMENT_DOFS = 3 * (1 + MAX_SEGMENT_NODES)
  !> Contact states of a slave node.
  integer, parameter :: CONTACT_OPEN = 0, CONTACT_STICK = 1, CONTACT_SLIP = 2, CONTACT_TIED = 3
  !> Tangent of a slipping node on a frictionless interface (no tangential stiffness).
  integer, parameter :: TANGENT_FREE = -1
  !> The rate-weakening part of the slip tangent is limited to -MAX_WEAKENING E_t A (the
  !> tangent only; the update is exact), so that one increment's tangent stays invertible.
  real(dp), parameter :: MAX_WEAKENING = 0.5_dp
  !> Iterations allowed for the implicit rate-dependent return mapping.
  integer, parameter :: RETURN_MAX_ITERATIONS = 200
  !> Smallest plastic slip, as a fraction of |f^tr|/E_t A, from which the return mapping
  !> searches the first root of its equation (2^-50: below the round-off of the slip).
  real(dp), parameter :: SCAN_START = 2.0_dp**(-50)

  !> The penalties and the tributary area of one slave node.
  type :: contact_params_t
    real(dp) :: area = 0.0_dp
    !> E_n, E_t [stress/length].
    real(dp) :: normal_stiffness = 0.0_dp
    real(dp) :: stick_stiffness = 0.0_dp
    !> Support of the master segment at the contact point (1 on the segment, falling to 0
    !> across the extension past a free edge of the master surface) and its derivative with
    !> respect to the natural coordinates: the normal force is support * E_n A max(0, -g).
    real(dp) :: support = 1.0_dp
    real(dp) :: dsupport(2) = 0.0_dp
    !> Radiation damping eta [stress time/length] (0: none): a slipping node resists with
    !> mu f_n + eta A V.
    real(dp) :: damping = 0.0_dp
    !> The pressure-overclosure law: LINEAR (the penalty E_n above) or EXPONENTIAL
    !> (f_n = support A p(g), p = p0 exp(-beta g); fcs_pressure_overclosure).
    type(pressure_overclosure_t) :: overclosure
    !> The friction law reads V as the total relative tangential velocity (VELOCITY=RELATIVE,
    !> friction_law_t%relative_velocity) instead of the slip rate: the rate term of the slip
    !> tangent then acts on the total relative motion, not in series with E_t A.
    logical :: relative_velocity = .false.
  end type contact_params_t

  !> The state of one slave node at the start of an increment.
  type :: contact_node_t
    integer :: status = CONTACT_OPEN
    real(dp) :: normal_force = 0.0_dp
    real(dp) :: friction(2) = 0.0_dp
    !> |f^tr| of the last return mapping (for the slip tangent).
    real(dp) :: trial_norm = 0.0_dp
    real(dp) :: friction_state = 0.0_dp
    real(dp) :: tied_gap = 0.0_dp
    !> Slip rate of the previous increment (0 after stick): the rate of an explicit law.
    real(dp) :: slip_rate = 0.0_dp
    !> Norm of the total relative tangential velocity of the previous increment (elastic +
    !> slip) [length/time]: the rate of an explicit law read with VELOCITY=RELATIVE.
    real(dp) :: relative_rate = 0.0_dp
    !> Held closed through equilibrium iterations: bilateral normal spring.
    logical :: bilateral = .false.
  end type contact_node_t

  !> Derivatives of the contact quantities with respect to the n_dof = 3 (1 + gamma) nodal
  !> displacements (entries past n_dof are zero).
  type :: contact_linear_t
    integer :: n_dof = 15
    real(dp) :: dgap(MAX_ELEMENT_DOFS) = 0.0_dp
    real(dp) :: dxi(2, MAX_ELEMENT_DOFS) = 0.0_dp
    !> Tangential relative motion (slip vector) a_alpha dxi^alpha.
    real(dp) :: dslip(3, MAX_ELEMENT_DOFS) = 0.0_dp
    real(dp) :: dfn(MAX_ELEMENT_DOFS) = 0.0_dp
    !> Tangential force change under stick (also for slip nodes: the elastic predictor).
    real(dp) :: dft_stick(3, MAX_ELEMENT_DOFS) = 0.0_dp
    !> Total force change under the node's current state.
    real(dp) :: df(3, MAX_ELEMENT_DOFS) = 0.0_dp
    !> Nodal forces R f and tangent stiffness -dF/du.
    real(dp) :: force(MAX_ELEMENT_DOFS) = 0.0_dp
    real(dp) :: stiffness(MAX_ELEMENT_DOFS, MAX_ELEMENT_DOFS) = 0.0_dp
  end type contact_linear_t

  !> Result of updating one contact node over an increment.
  type :: contact_update_t
    integer :: status = CONTACT_OPEN
    real(dp) :: normal_force = 0.0_dp
    real(dp) :: friction(2) = 0.0_dp
    !> Tangential relative motion of the increment (vector) and its irreversible part.
    real(dp) :: slip_vector(3) = 0.0_dp
    real(dp) :: plastic_slip = 0.0_dp
    real(dp) :: trial_norm = 0.0_dp
    !> Friction coefficient, slip rate and friction state at the end of the increment.
    real(dp) :: mu = 0.0_dp
    real(dp) :: slip_rate = 0.0_dp
    real(dp) :: friction_state = 0.0_dp
    !> Norm of the total relative tangential velocity over the increment, |(ds . e_m) e_m| / dt
    !> (elastic + slip) [length/time]; 0 for dt = 0.
    real(dp) :: relative_rate = 0.0_dp
  end type contact_update_t

contains

  !> Linearisation of a closed (stick, slip or tied) contact node at the current state.
  !> x5(3, 1 + gamma): slave then the gamma master nodes; p: the contact point; gap: current gap; node:
  !> its state (normal force, friction components, status, |f^tr|); params: area, E_n, E_t;
  !> fr: mu and its derivatives at the current state (dmu/dV = 0 for a law with an explicit
  !> rate); dt: the time increment the rate term of eq. (6) refers to (0: no rate term).
  !>
  !> Slip (eqs. 5-6): along the slip direction eta the force is F = f_n mu(V) + eta_r A V
  !> (eta_r the radiation damping), V = dlambda/dt with dlambda the plastic slip, so with
  !> k_v = (f_n dmu/dV + eta_r A) / dt the consistent response is
  !> dF = E_t A / (E_t A + k_v) [ (mu + f_n dmu/dp / A) df_n - k_v eta.ds ]
  !> (a spring E_t A in series with the rate term; k_v = 0 gives the rate-independent cone);
  !> across eta the stiffness is F E_t A / |f^tr| (I - eta eta). The rate term is
  !> linearised about the node's last slip rate V_old (node%slip_rate): a slip V_old dt keeps
  !> F, so the force of a slipping node is the predictor F - E_t A k_v/(E_t A + k_v)
  !> V_old dt along eta.
  !>
  !> Within the equilibrium iterations of an increment the node's state is an iterate that has
  !> already slipped by `slip` (the tangential relative motion since the start of the
  !> increment, from the point at natural coordinates with shape functions `shape_start` on
  !> the same face) on the increment: the trial force f_start - E_t A (slip . e_m) e_m then
  !> also changes through the master nodes' motion at the start point and through the turn of
  !> the frame e_m under the accumulated slip (both vanish at the start of an increment).
  pure subroutine contact_linearise(x5, p, gap, node, params, fr, dt, lin, slip, shape_start)
    real(dp), intent(in) :: x5(:, :), gap, dt
    type(segment_point_t), intent(in) :: p
    type(contact_node_t), intent(in) :: node
    type(contact_params_t), intent(in) :: params
    type(friction_derivatives_t), intent(in) :: fr
    type(contact_linear_t), intent(out) :: lin
    real(dp), intent(in), optional :: slip(3), shape_start(:)
    real(dp) :: dn(3, MAX_ELEMENT_DOFS), de(3, MAX_ELEMENT_DOFS, 2), eta(2), eta_vec(3), ft_vec(3), f(3)
    real(dp) :: k_t, k_v, series, mu_eff, penetration, dtrial(3, MAX_ELEMENT_DOFS), strength, factor
    real(dp) :: predictor
    lin%n_dof = 3 * size(x5, 2)
    call contact_kinematics(p, gap, lin, dn, de)
    dtrial = trial_slip_derivative(p, lin%dslip, de, slip, shape_start)
    k_t = params%stick_stiffness * params%area
    if (params%overclosure%is_exponential()) then
      ! f_n = support A p(g): df_n = A (support p'(g) dg + p(g) dsupport/dxi . dxi).
      lin%dfn = params%area * (params%support * params%overclosure%slope(gap) * lin%dgap + &
                params%overclosure%pressure(gap) * &
                (params%dsupport(1) * lin%dxi(1, :) + params%dsupport(2) * lin%dxi(2, :)))
    else
      penetration = max(0.0_dp, -gap)
      if (node%bilateral) penetration = -gap
      lin%dfn = -params%normal_stiffness * params%area * (params%support * lin%dgap - penetration * &
                (params%dsupport(1) * lin%dxi(1, :) + params%dsupport(2) * lin%dxi(2, :)))
    end if
    ! A bilateral node in tension carries no friction: its normal force only.
    if (node%normal_force < 0.0_dp) then
      lin%df = outer(p%normal, lin%dfn) + node%normal_force * dn
      call assemble_element(p, node%normal_force * p%normal, lin)
      return
    end if
    ft_vec = node%friction(1) * p%e(:, 1) + node%friction(2) * p%e(:, 2)
    lin%dft_stick = node%friction(1) * de(:, :, 1) + node%friction(2) * de(:, :, 2) - k_t * dtrial
    ! A slipping node on a cone of zero radius (mu = 0, or no normal force) carries no
    ! tangential force and has no tangential stiffness. A slipping node with friction but without a friction force
    ! yet (it slipped on first touch, f_n = 0) has no slip direction: it gets the stick
    ! tangent until it carries a force.
    select case (tangent_kind(node, fr%mu))
    case (TANGENT_FREE)
      lin%df = 0.0_dp
    case (CONTACT_SLIP)
      eta = node%friction / norm2(node%friction)
      eta_vec = eta(1) * p%e(:, 1) + eta(2) * p%e(:, 2)
      ! The returned force F = mu f_n + eta_r A V_old; F / |f^tr| <= 1 on the cone; held there
      ! when the cone has moved since (explicit rates, a new normal force).
      strength = fr%mu * node%normal_force + params%damping * params%area * node%slip_rate
      factor = min(1.0_dp, strength / max(node%trial_norm, norm2(node%friction)))
      mu_eff = fr%mu + node%normal_force * fr%dmu_dpressure / params%area
      if (params%relative_velocity) then
        call relative_rate_tangent(p, node, params, fr, dt, k_t, eta_vec, mu_eff, dtrial, slip, &
                                   lin, predictor)
      else
        k_v = 0.0_dp
        if (dt > 0.0_dp) k_v = max((node%normal_force * fr%dmu_drate + params%damping * params%area) / dt, &
                                   -MAX_WEAKENING * k_t)
        series = k_t / (k_t + k_v)
        lin%df = outer(eta_vec, series * (mu_eff * lin%dfn - k_v * matmul(eta_vec, dtrial)))
        predictor = series * k_v * node%slip_rate * dt
      end if
      lin%df = lin%df - factor * k_t * matmul(identity3() - outer3(p%normal, p%normal) &
                                              - outer3(eta_vec, eta_vec), dtrial) &
               + strength * (eta(1) * de(:, :, 1) + eta(2) * de(:, :, 2))
      ! Linearised about V_old, not V = 0: the friction predicted for a slip s of the
      ! increment is f_n mu(V_old) + k_v (s - V_old dt) (in series with E_t A). Without the
      ! V_old dt term, steady sliding keeps an out-of-balance force f_n V dmu/dV (in series)
      ! between the body and the contact, which the next increment applies in full.
      ft_vec = ft_vec - predictor * eta_vec
    case default
      lin%df = lin%dft_stick
    end select
    lin%df = lin%df + outer(p%normal, lin%dfn) + node%normal_force * dn
    f = node%normal_force * p%normal + ft_vec
    call assemble_element(p, f, lin)
  end subroutine contact_linearise

  !> The part along the slip direction eta of the slip tangent of a node whose law reads V as
  !> the total relative tangential velocity (VELOCITY=RELATIVE; Xing et al. 2003, eqs. 3, 6:
  !> the d mu / d u~dot_eq term). The returned force along eta is
  !> F = [E_t A mu(V) f_n + k_d |f^tr|] / (E_t A + k_d), k_d = eta_r A / dt, with
  !> V = |s_t| / dt the relative tangential motion s_t of the increment over dt, so
  !> dF = E_t A / (E_t A + k_d) [mu_eff df_n + k_r t.ds_t - k_d eta.ds_t], k_r = f_n dmu/dV / dt,
  !> t the direction of s_t (the iterate's own when `slip` is given, else -eta: a slipping
  !> slave moves against its friction force). Unlike the slip-rate reading, the rate term is not
  !> in series with E_t A: mu follows the total motion, elastic part included. k_r is limited to
  !> -MAX_WEAKENING E_t A (tangent only). `predictor`: at the start of an increment, the change
  !> of F the linearisation expects for a repeat of the previous increment's motion,
  !> E_t A / (E_t A + k_d) (k_r V_rel,old + k_d V_old) dt (V_rel,old = node%relative_rate,
  !> V_old = node%slip_rate), so that such a repeat keeps F, as in the slip-rate form; 0 at an
  !> iterate (`slip` given), which is linearised about its own motion.
  pure subroutine relative_rate_tangent(p, node, params, fr, dt, k_t, eta_vec, mu_eff, dtrial, &
                                        slip, lin, predictor)
    type(segment_point_t), intent(in) :: p
    type(contact_node_t), intent(in) :: node
    type(contact_params_t), intent(in) :: params
    type(friction_derivatives_t), intent(in) :: fr
    real(dp), intent(in) :: dt, k_t, eta_vec(3), mu_eff, dtrial(3, MAX_ELEMENT_DOFS)
    real(dp), intent(in), optional :: slip(3)
    type(contact_linear_t), intent(inout) :: lin
    real(dp), intent(out) :: predictor
    real(dp) :: k_r, k_d, series, direction(3), tangential(3)
    k_r = 0.0_dp
    k_d = 0.0_dp
    if (dt > 0.0_dp) then
      k_r = max(node%normal_force * fr%dmu_drate / dt, -MAX_WEAKENING * k_t)
      k_d = params%damping * params%area / dt
    end if
    series = k_t / (k_t + k_d)
    direction = -eta_vec
    predictor = series * (k_r * node%relative_rate + k_d * node%slip_rate) * dt
    if (present(slip)) then
      tangential = slip - dot_product(slip, p%normal) * p%normal
      if (norm2(tangential) > 0.0_dp) direction = tangential / norm2(tangential)
      predictor = 0.0_dp
    end if
    lin%df = outer(eta_vec, series * (mu_eff * lin%dfn + k_r * matmul(direction, dtrial) &
                                      - k_d * matmul(eta_vec, dtrial)))
  end subroutine relative_rate_tangent

  !> Derivative of the slip term sum_m (s . e_m) e_m of the trial force with respect to the
  !> nodal displacements: P_t ds + sum_m e_m (s . de_m), with ds = a_alpha dxi^alpha
  !> (`dslip`) plus, for an accumulated slip s from a start point with shape functions
  !> `shape_start` on the same face, sum_I (N_I - N_I,start) du_I. Without s: dslip.
  pure function trial_slip_derivative(p, dslip, de, slip, shape_start) result(g)
    type(segment_point_t), intent(in) :: p
    real(dp), intent(in) :: dslip(3, MAX_ELEMENT_DOFS), de(3, MAX_ELEMENT_DOFS, 2)
    real(dp), intent(in), optional :: slip(3), shape_start(:)
    real(dp) :: g(3, MAX_ELEMENT_DOFS)
    real(dp) :: ds(3, MAX_ELEMENT_DOFS), tangent_projector(3, 3)
    integer :: i, m
    g = dslip
    if (.not. present(slip)) return
    ds = dslip
    if (present(shape_start)) then
      do i = 1, p%n_nodes
        do m = 1, 3
          ds(m, 3 * i + m) = ds(m, 3 * i + m) + (p%shape(i) - shape_start(i))
        end do
      end do
    end if
    tangent_projector = identity3() - outer3(p%normal, p%normal)
    g = matmul(tangent_projector, ds)
    do m = 1, 2
      g = g + outer(p%e(:, m), matmul(slip, de(:, :, m)))
    end do
  end function trial_slip_derivative

  !> Nodal forces F = R f of the force f on the slave and the tangent K = -dF/du from
  !> lin%df and lin%dxi (eq. 8); dF_I = -N_I df - (dN_I/dxi . dxi) f on master node I.
  pure subroutine assemble_element(p, f, lin)
    type(segment_point_t), intent(in) :: p
    real(dp), intent(in) :: f(3)
    type(contact_linear_t), intent(inout) :: lin
    integer :: i
    lin%force(1:3) = f
    lin%stiffness(1:3, :) = -lin%df
    do i = 1, p%n_nodes
      lin%force(3 * i + 1:3 * i + 3) = -p%shape(i) * f
      lin%stiffness(3 * i + 1:3 * i + 3, :) = p%shape(i) * lin%df + &
        outer(f, p%dshape(1, i) * lin%dxi(1, :) + p%dshape(2, i) * lin%dxi(2, :))
    end do
  end subroutine assemble_element

  !> Which tangential tangent a closed node gets: TANGENT_FREE (slipping on a cone of zero
  !> radius, mu = 0 or no normal force (a node at the end of the extension past a free edge):
  !> no tangential force or stiffness), CONTACT_SLIP (slipping with a friction force,
  !> eq. 6) or CONTACT_STICK (sticking or tied, eq. 4; also a slipping node with friction
  !> but no friction force yet, whose slip direction is unknown).
  pure integer function tangent_kind(node, mu) result(kind)
    type(contact_node_t), intent(in) :: node
    real(dp), intent(in) :: mu
    kind = CONTACT_STICK
    if (node%status /= CONTACT_SLIP) return
    if (mu <= 0.0_dp .or. node%normal_force <= 0.0_dp) then
      kind = TANGENT_FREE
    else if (norm2(node%friction) > 0.0_dp) then
      kind = CONTACT_SLIP
    end if
  end function tangent_kind

  !> Derivatives of the contact point's geometry: the gap, the natural coordinates of the
  !> contact point (A dxi = a.du~ + g n.delta a, A = m - g h, h_12 = n.x_,12: the metric and
  !> curvature terms of eq. 9), the slip vector a_alpha dxi^alpha, the normal
  !> (delta n = -a^alpha (n.delta a_alpha)) and the frame (e1 = a1/|a1|, e2 = n x e1), with
  !> delta a_alpha = sum dN_I/dxi_alpha du_I + x_,ab dxi^b at the moving point.
  pure subroutine contact_kinematics(p, gap, lin, dn, de)
    type(segment_point_t), intent(in) :: p
    real(dp), intent(in) :: gap
    type(contact_linear_t), intent(inout) :: lin
    real(dp), intent(out) :: dn(3, MAX_ELEMENT_DOFS), de(3, MAX_ELEMENT_DOFS, 2)
    real(dp) :: dut(3, MAX_ELEMENT_DOFS), da(3, MAX_ELEMENT_DOFS, 2), dat(3, MAX_ELEMENT_DOFS, 2)
    real(dp) :: rhs(2, MAX_ELEMENT_DOFS), amat(2, 2), det, h12, proj(3, 3)
    integer :: i, alpha
    dut = 0.0_dp
    da = 0.0_dp
    do i = 1, 3
      dut(i, i) = 1.0_dp
    end do
    do alpha = 1, 2
      do i = 1, p%n_nodes
        call put_diag(da(:, :, alpha), i + 1, p%dshape(alpha, i))
      end do
    end do
    do i = 1, p%n_nodes
      call put_diag(dut, i + 1, -p%shape(i))
    end do
    h12 = dot_product(p%normal, p%twist)
    amat = p%metric
    amat(1, 2) = amat(1, 2) - gap * h12
    amat(2, 1) = amat(1, 2)
    if (p%n_nodes /= 4) then
      amat(1, 1) = amat(1, 1) - gap * dot_product(p%normal, p%second(:, 1))
      amat(2, 2) = amat(2, 2) - gap * dot_product(p%normal, p%second(:, 2))
    end if
    det = amat(1, 1) * amat(2, 2) - amat(1, 2) * amat(2, 1)
    do alpha = 1, 2
      rhs(alpha, :) = matmul(p%a(:, alpha), dut) + gap * matmul(p%normal, da(:, :, alpha))
    end do
    lin%dxi(1, :) = (amat(2, 2) * rhs(1, :) - amat(1, 2) * rhs(2, :)) / det
    lin%dxi(2, :) = (amat(1, 1) * rhs(2, :) - amat(2, 1) * rhs(1, :)) / det
    dat(:, :, 1) = da(:, :, 1) + outer(p%twist, lin%dxi(2, :))
    dat(:, :, 2) = da(:, :, 2) + outer(p%twist, lin%dxi(1, :))
    if (p%n_nodes /= 4) then
      dat(:, :, 1) = dat(:, :, 1) + outer(p%second(:, 1), lin%dxi(1, :))
      dat(:, :, 2) = dat(:, :, 2) + outer(p%second(:, 2), lin%dxi(2, :))
    end if
    dn = -outer(p%dual(:, 1), matmul(p%normal, dat(:, :, 1))) &
         - outer(p%dual(:, 2), matmul(p%normal, dat(:, :, 2)))
    proj = identity3() - outer3(p%e(:, 1), p%e(:, 1))
    de(:, :, 1) = matmul(proj, dat(:, :, 1)) / norm2(p%a(:, 1))
    de(:, :, 2) = -matmul(skew(p%e(:, 1)), dn) + matmul(skew(p%normal), de(:, :, 1))
    lin%dgap = matmul(p%normal, dut)
    lin%dslip = outer(p%a(:, 1), lin%dxi(1, :)) + outer(p%a(:, 2), lin%dxi(2, :))
  end subroutine contact_kinematics

  !> Return mapping of one closed contact node over an increment of duration dt (eq. 5):
  !> new contact point `p_new` (already projected) with gap `gap_new`, the old point
  !> `p_old_on_new` evaluated on the new master coordinates (the slip vector is their
  !> difference), the node's old state, the friction law. The elastic trial
  !> f^tr = f_old - E_t A ds is inside the cone |f| <= mu(p, 0, phi) f_n (stick) or is
  !> returned to it: the plastic slip dlambda solves
  !>   |f^tr| - E_t A dlambda = f_n mu(p, dlambda/dt, phi(dlambda)) + eta_r A dlambda/dt
  !> (rate and state evaluated at the end of the increment, the state evolved over it at
  !> the constant slip rate dlambda/dt, eta_r the radiation damping).
  !> Tied nodes keep a bilateral normal spring about their tied gap and never slip. Whether
  !> a node with zero normal force is open is decided by the caller (fcs_contact_system).
  pure function contact_update(p_new, gap_new, p_old_on_new, node, params, law, dt) result(out)
    type(segment_point_t), intent(in) :: p_new, p_old_on_new
    real(dp), intent(in) :: gap_new, dt
    type(contact_node_t), intent(in) :: node
    type(contact_params_t), intent(in) :: params
    class(friction_law_t), intent(in) :: law
    type(contact_update_t) :: out
    real(dp) :: trial(2), k_t, signed_force
    k_t = params%stick_stiffness * params%area
    out%slip_vector = p_new%x - p_old_on_new%x
    ! The frictional force on the slave opposes its motion relative to the master (eq. 4).
    trial = node%friction - k_t * matmul(out%slip_vector, p_new%e)
    out%trial_norm = norm2(trial)
    if (dt > 0.0_dp) out%relative_rate = norm2(matmul(out%slip_vector, p_new%e)) / dt
    out%friction_state = node%friction_state
    if (node%status == CONTACT_TIED) then
      out%status = CONTACT_TIED
      out%normal_force = -params%normal_stiffness * params%area * (gap_new - node%tied_gap)
      out%friction = trial
      return
    end if
    ! A node held closed through equilibrium iterations has a bilateral normal spring (its
    ! force may turn tensile, which the iterations then undo by opening it); the cone only
    ! ever sees a compressive force.
    if (params%overclosure%is_exponential()) then
      ! Exponential pressure-overclosure: compressive at any clearance the node is closed at.
      signed_force = params%support * params%area * params%overclosure%pressure(gap_new)
    else
      signed_force = params%support * params%normal_stiffness * params%area * (-gap_new)
    end if
    out%normal_force = max(0.0_dp, signed_force)
    call friction_return(out, trial, k_t, params%area, params%damping, law, node, dt)
    if (node%bilateral) out%normal_force = signed_force
  end function contact_update

  !> The friction part of the return mapping of a closed node with normal force
  !> out%normal_force (compressive): stick inside the cone of the static friction
  !> mu(p, 0, phi), else the plastic slip of eq. (5) (explicit or implicit rate), resisted by
  !> the radiation damping eta_r A V (damping = eta_r [stress time/length]; Rice 1993).
  pure subroutine friction_return(out, trial, k_t, area, damping, law, node, dt)
    type(contact_update_t), intent(inout) :: out
    real(dp), intent(in) :: trial(2), k_t, area, damping, dt
    class(friction_law_t), intent(in) :: law
    type(contact_node_t), intent(in) :: node
    real(dp) :: pressure, mu_static, state_static, k_damping
    pressure = out%normal_force / area
    ! The damping force eta_r A dlambda/dt of a slip dlambda over dt: a viscous spring.
    k_damping = 0.0_dp
    if (dt > 0.0_dp) k_damping = damping * area / dt
    if (law%relative_velocity) then
      call relative_return(out, trial, pressure, k_t, k_damping, law, node, dt)
      return
    end if
    if (law%explicit_rate) then
      call explicit_return(out, trial, pressure, k_t, k_damping, law, node, dt)
      return
    end if
    state_static = law%evolve_state(node%friction_state, 0.0_dp, max(dt, 0.0_dp))
    mu_static = law%mu(pressure, 0.0_dp, state_static)
    if (out%trial_norm <= mu_static * out%normal_force) then
      out%status = CONTACT_STICK
      out%friction = trial
      out%mu = mu_static
      out%friction_state = state_static
      return
    end if
    out%status = CONTACT_SLIP
    call return_to_cone(out%trial_norm, out%normal_force, pressure, k_t, k_damping, law, &
                        node%friction_state, dt, out%plastic_slip, out%mu, out%friction_state)
    out%friction = (out%mu * out%normal_force + k_damping * out%plastic_slip) * trial / out%trial_norm
    if (dt > 0.0_dp) out%slip_rate = out%plastic_slip / dt
  end subroutine friction_return

  !> The return mapping of a law with an explicit rate: the cone is mu_e = mu(p, V_prev,
  !> phi_old), V_prev the slip rate of the previous increment (0 after stick), so that the
  !> plastic slip is (|f^tr| - mu_e f_n) / (E_t A + k_damping) as for Coulomb friction
  !> (k_damping = eta_r A / dt, the radiation damping over the increment). The state evolves
  !> over the increment at the new rate. `mu` is mu_e for a slipping node (the force is
  !> mu_e f_n + eta_r A V) and the static mu(p, 0, phi) for a sticking one (the cone of its
  !> next increment).
  pure subroutine explicit_return(out, trial, pressure, k_t, k_damping, law, node, dt)
    type(contact_update_t), intent(inout) :: out
    real(dp), intent(in) :: trial(2), pressure, k_t, k_damping, dt
    class(friction_law_t), intent(in) :: law
    type(contact_node_t), intent(in) :: node
    real(dp) :: mu_e
    mu_e = law%mu(pressure, node%slip_rate, node%friction_state)
    if (out%trial_norm <= mu_e * out%normal_force) then
      out%status = CONTACT_STICK
      out%friction = trial
      out%friction_state = law%evolve_state(node%friction_state, 0.0_dp, max(dt, 0.0_dp))
      out%mu = law%mu(pressure, 0.0_dp, out%friction_state)
      return
    end if
    out%status = CONTACT_SLIP
    out%plastic_slip = (out%trial_norm - mu_e * out%normal_force) / (k_t + k_damping)
    out%mu = mu_e
    out%friction = (mu_e * out%normal_force + k_damping * out%plastic_slip) * trial / out%trial_norm
    if (dt > 0.0_dp) out%slip_rate = out%plastic_slip / dt
    out%friction_state = law%evolve_state(node%friction_state, out%slip_rate, max(dt, 0.0_dp))
  end subroutine explicit_return

  !> The return mapping of a law read with VELOCITY=RELATIVE, the literal reading of Xing et
  !> al. (2003, eq. 3): mu = mu(f_n, u~dot_eq, phi) with u~dot_eq = sqrt(u~dot_m u~dot_m) the
  !> norm of the total relative tangential velocity (elastic + plastic), here the increment's
  !> relative tangential motion over dt, out%relative_rate = |(ds . e_m) e_m| / dt. That
  !> motion is known from the kinematics before the split into stick and slip
  !> (f^tr = f_old - E_t A ds), so the cone mu_c = mu(p, V, phi) is known and the plastic slip
  !> follows as for Coulomb friction, (|f^tr| - mu_c f_n) / (E_t A + k_damping). V is the
  !> increment's own relative rate (IMPLICIT; the state evolved over the increment at it) or
  !> the previous increment's (EXPLICIT: node%relative_rate with the state at the start). The
  !> state evolves over the increment at the increment's relative rate; out%mu is mu_c for a
  !> slipping node and mu at the increment's relative rate and new state for a sticking one
  !> (the cone of its next increment under EXPLICIT).
  pure subroutine relative_return(out, trial, pressure, k_t, k_damping, law, node, dt)
    type(contact_update_t), intent(inout) :: out
    real(dp), intent(in) :: trial(2), pressure, k_t, k_damping, dt
    class(friction_law_t), intent(in) :: law
    type(contact_node_t), intent(in) :: node
    real(dp) :: mu_c
    out%friction_state = law%evolve_state(node%friction_state, out%relative_rate, max(dt, 0.0_dp))
    if (law%explicit_rate) then
      mu_c = law%mu(pressure, node%relative_rate, node%friction_state)
    else
      mu_c = law%mu(pressure, out%relative_rate, out%friction_state)
    end if
    if (out%trial_norm <= mu_c * out%normal_force) then
      out%status = CONTACT_STICK
      out%friction = trial
      out%mu = law%mu(pressure, out%relative_rate, out%friction_state)
      return
    end if
    out%status = CONTACT_SLIP
    out%plastic_slip = (out%trial_norm - mu_c * out%normal_force) / (k_t + k_damping)
    out%mu = mu_c
    out%friction = (mu_c * out%normal_force + k_damping * out%plastic_slip) * trial / out%trial_norm
    if (dt > 0.0_dp) out%slip_rate = out%plastic_slip / dt
  end subroutine relative_return

  !> Plastic slip of a slipping node: the smallest root in (0, |f^tr|/k_t] of
  !> g(l) = |f^tr| - (k_t + k_damping) l - f_n mu(p, l/dt, phi(l)) (k_damping = eta_r A / dt,
  !> the radiation damping), by the Illinois variant of regula falsi (g(0) > 0 > g(|f^tr|/k_t)
  !> bracket a root; no derivatives of the state update are needed). With dt = 0 the rate is
  !> taken as zero. g may have three roots (rate-and-state:
  !> the direct effect raises mu with l, the state evolution then lowers it); the smallest is
  !> the one the slip reaches continuously as the trial force grows from the cone, so it is
  !> bracketed first by marching up from a negligible slip in factors of 2.
  pure subroutine return_to_cone(trial_norm, fn, pressure, k_t, k_damping, law, state_old, dt, &
                                 slip, mu, state)
    real(dp), intent(in) :: trial_norm, fn, pressure, k_t, k_damping, state_old, dt
    class(friction_law_t), intent(in) :: law
    real(dp), intent(out) :: slip, mu, state
    real(dp) :: lo, hi, g_lo, g_hi, x, g
    integer :: iteration, side
    lo = 0.0_dp
    hi = trial_norm / k_t
    g_lo = residual(lo)
    g_hi = residual(hi)
    if (dt > 0.0_dp .and. g_lo > 0.0_dp .and. g_hi < 0.0_dp) then
      x = hi * SCAN_START
      do while (x < hi)
        g = residual(x)
        if (g <= 0.0_dp) then
          hi = x
          g_hi = g
          exit
        end if
        lo = x
        g_lo = g
        x = 2.0_dp * x
      end do
    end if
    side = 0
    x = hi
    do iteration = 1, RETURN_MAX_ITERATIONS
      if (g_hi >= 0.0_dp .or. g_lo <= 0.0_dp) exit
      x = (lo * g_hi - hi * g_lo) / (g_hi - g_lo)
      g = residual(x)
      if (abs(g) <= 1.0e-13_dp * trial_norm .or. hi - lo <= 1.0e-15_dp * hi) exit
      if (g > 0.0_dp) then
        lo = x
        g_lo = g
        if (side == 1) g_hi = 0.5_dp * g_hi
        side = 1
      else
        hi = x
        g_hi = g
        if (side == -1) g_lo = 0.5_dp * g_lo
        side = -1
      end if
    end do
    slip = x
    call evaluate(slip, mu, state)
  contains
    pure real(dp) function residual(l)
      real(dp), intent(in) :: l
      real(dp) :: m, st
      call evaluate(l, m, st)
      residual = trial_norm - (k_t + k_damping) * l - fn * m
    end function residual
    pure subroutine evaluate(l, m, st)
      real(dp), intent(in) :: l
      real(dp), intent(out) :: m, st
      real(dp) :: rate
      rate = 0.0_dp
      if (dt > 0.0_dp) rate = l / dt
      st = law%evolve_state(state_old, rate, max(dt, 0.0_dp))
      if (law%n_state() == 0 .and. dt <= 0.0_dp) st = state_old
      m = law%mu(pressure, rate, st)
    end subroutine evaluate
  end subroutine return_to_cone

  pure function contact_status_name(status) result(name)
    integer, intent(in) :: status
    character(len=:), allocatable :: name
    select case (status)
    case (CONTACT_STICK)
      name = 'stick'
    case (CONTACT_SLIP)
      name = 'slip'
    case (CONTACT_TIED)
      name = 'tied'
    case default
      name = 'open'
    end select
  end function contact_status_name

  pure subroutine put_diag(m, block, value)
    real(dp), intent(inout) :: m(:, :)
    integer, intent(in) :: block
    real(dp), intent(in) :: value
    integer :: i
    do i = 1, 3
      m(i, 3 * (block - 1) + i) = value
    end do
  end subroutine put_diag

  pure function outer(a, b) result(m)
    real(dp), intent(in) :: a(3), b(:)
    real(dp) :: m(3, size(b))
    integer :: i
    do i = 1, 3
      m(i, :) = a(i) * b
    end do
  end function outer

  pure function outer3(a, b) result(m)
    real(dp), intent(in) :: a(3), b(3)
    real(dp) :: m(3, 3)
    integer :: i
    do i = 1, 3
      m(i, :) = a(i) * b
    end do
  end function outer3

  pure function identity3() result(m)
    real(dp) :: m(3, 3)
    m = 0.0_dp
    m(1, 1) = 1.0_dp
    m(2, 2) = 1.0_dp
    m(3, 3) = 1.0_dp
  end function identity3

  pure function skew(a) result(s)
    real(dp), intent(in) :: a(3)
    real(dp) :: s(3, 3)
    s = reshape([0.0_dp, a(3), -a(2), -a(3), 0.0_dp, a(1), a(2), -a(1), 0.0_dp], [3, 3])
  end function skew

end module fcs_contact_element
