!> The node-to-point contact element (Xing & Makinouchi 2000, 2002; Xing, Mora & Makinouchi
!> 2003, eqs. 2-9): a slave node s against the point c at natural coordinates xi of a 4-node
!> master segment. Degrees of freedom: u_s, u_1..u_4 (15), assembly vector
!> R = [1, -N_1, -N_2, -N_3, -N_4] (eq. 8).
!>
!> Forces on the slave node: f = f_n n + f_t, with the penalty normal force f_n = E_n A (-g)
!> (g = n.(x_s - x_c) < 0 in penetration, A the slave node's tributary area) and the
!> frictional force f_t = f_m e_m kept by its components f_m in the local Cartesian frame
!> e_m of the master segment (the paper's e_i). Friction is treated like plasticity:
!> stick f_m = -E_t A u~_m^e (eq. 4; the force on the slave opposes its motion relative to
!> the master), slip on the cone |f_t| = mu f_n (eqs. 3, 5), return mapping
!> f^tr = f_old - E_t A du~ (eq. 5), f = mu f_n f^tr/|f^tr| when outside.
!>
!> `contact_linearise` gives the derivatives of every contact quantity with respect to the
!> 15 nodal displacements on the current configuration: the gap, the natural coordinates of
!> the contact point (delta xi = A^-1 [a.du~ + g n.delta a], A = m - g h: the metric and
!> curvature terms), the normal, the frame, the forces, and the tangent K_f = -dF/du
!> (eqs. 6-9): the linearised friction law of eq. (6) (stick: E_t; slip: the projection
!> (I - eta eta) with factor mu f_n E_t/|f^tr|, the eta mu df_n coupling and the d mu terms)
!> plus the geometric terms from the rotation of n and e_m with the master surface and the
!> motion of the contact point along it (the H and C-bar terms of eq. 9). The unit tests
!> check K_f against finite differences of `contact_update`.
module fcs_contact_element
  use fcs_kinds, only: dp
  use fcs_contact_geometry, only: segment_point_t, segment_point, cross3
  use fcs_friction_law, only: friction_derivatives_t
  implicit none
  private
  public :: contact_linear_t, contact_linearise, contact_update, contact_update_t
  public :: CONTACT_OPEN, CONTACT_STICK, CONTACT_SLIP, CONTACT_TIED, contact_status_name

  !> Contact states of a slave node.
  integer, parameter :: CONTACT_OPEN = 0, CONTACT_STICK = 1, CONTACT_SLIP = 2, CONTACT_TIED = 3

  !> Derivatives of the contact quantities with respect to the 15 nodal displacements.
  type :: contact_linear_t
    real(dp) :: dgap(15) = 0.0_dp
    real(dp) :: dxi(2, 15) = 0.0_dp
    !> Tangential relative motion (slip vector) a_alpha dxi^alpha.
    real(dp) :: dslip(3, 15) = 0.0_dp
    real(dp) :: dfn(15) = 0.0_dp
    !> Tangential force change under stick (also for slip nodes: the elastic predictor).
    real(dp) :: dft_stick(3, 15) = 0.0_dp
    !> Total force change under the node's current state.
    real(dp) :: df(3, 15) = 0.0_dp
    !> Nodal forces R f and tangent stiffness -dF/du.
    real(dp) :: force(15) = 0.0_dp
    real(dp) :: stiffness(15, 15) = 0.0_dp
  end type contact_linear_t

  !> Result of updating one contact node over an increment.
  type :: contact_update_t
    integer :: status = CONTACT_OPEN
    real(dp) :: xi(2) = 0.0_dp
    real(dp) :: gap = 0.0_dp
    real(dp) :: normal_force = 0.0_dp
    real(dp) :: friction(2) = 0.0_dp
    !> Tangential relative motion of the increment (vector) and its irreversible part.
    real(dp) :: slip_vector(3) = 0.0_dp
    real(dp) :: plastic_slip = 0.0_dp
    real(dp) :: mu = 0.0_dp
  end type contact_update_t

contains

  !> Linearisation of a closed (stick, slip or tied) contact node at the current state.
  !> xs, xm: slave and master coordinates; p: the contact point; gap: current gap;
  !> fn: normal force; ft(2): friction components; status; area; en, et: penalties
  !> [stress/length]; fr: mu and its derivatives at the current state; trial_norm: |f^tr|
  !> for slip (>= mu fn); rate_factor: d(slip rate)/d(slip) = 1/dt (0: no rate term).
  pure subroutine contact_linearise(xs, xm, p, gap, fn, ft, status, area, en, et, fr, trial_norm, &
                                    rate_factor, lin)
    real(dp), intent(in) :: xs(3), xm(3, 4), gap, fn, ft(2), area, en, et, trial_norm, rate_factor
    type(segment_point_t), intent(in) :: p
    integer, intent(in) :: status
    type(friction_derivatives_t), intent(in) :: fr
    type(contact_linear_t), intent(out) :: lin
    real(dp) :: dut(3, 15), da(3, 15, 2), dat(3, 15, 2), dn(3, 15), de(3, 15, 2), rhs(2, 15)
    real(dp) :: amat(2, 2), det, h12, eta(2), eta_vec(3), ft_vec(3), f(3), factor, proj(3, 3)
    real(dp) :: dmu(15)
    integer :: i, alpha
    ! du~ = du_s - sum N_I du_I and delta a_alpha at fixed xi.
    dut = 0.0_dp
    da = 0.0_dp
    do i = 1, 3
      dut(i, i) = 1.0_dp
    end do
    do alpha = 1, 2
      do i = 1, 4
        call put_diag(da(:, :, alpha), i + 1, p%dshape(alpha, i))
      end do
    end do
    do i = 1, 4
      call put_diag(dut, i + 1, -p%shape(i))
    end do
    ! Contact point: A dxi = a.du~ + g n.delta a, A = m - g h (h_12 = n.x_,12).
    h12 = dot_product(p%normal, p%twist)
    amat = p%metric
    amat(1, 2) = amat(1, 2) - gap * h12
    amat(2, 1) = amat(1, 2)
    det = amat(1, 1) * amat(2, 2) - amat(1, 2) * amat(2, 1)
    do alpha = 1, 2
      rhs(alpha, :) = matmul(p%a(:, alpha), dut) + gap * matmul(p%normal, da(:, :, alpha))
    end do
    lin%dxi(1, :) = (amat(2, 2) * rhs(1, :) - amat(1, 2) * rhs(2, :)) / det
    lin%dxi(2, :) = (amat(1, 1) * rhs(2, :) - amat(2, 1) * rhs(1, :)) / det
    ! Total change of the base vectors at the moving point: delta a_alpha + x_,ab dxi^b.
    dat(:, :, 1) = da(:, :, 1) + outer(p%twist, lin%dxi(2, :))
    dat(:, :, 2) = da(:, :, 2) + outer(p%twist, lin%dxi(1, :))
    ! Normal: delta n = -a^alpha (n.delta a_alpha); frame: e1 = a1/|a1|, e2 = n x e1.
    dn = -outer(p%dual(:, 1), matmul(p%normal, dat(:, :, 1))) &
         - outer(p%dual(:, 2), matmul(p%normal, dat(:, :, 2)))
    proj = identity3() - outer3(p%e(:, 1), p%e(:, 1))
    de(:, :, 1) = matmul(proj, dat(:, :, 1)) / norm2(p%a(:, 1))
    de(:, :, 2) = -matmul(skew(p%e(:, 1)), dn) + matmul(skew(p%normal), de(:, :, 1))
    lin%dgap = matmul(p%normal, dut)
    lin%dslip = outer(p%a(:, 1), lin%dxi(1, :)) + outer(p%a(:, 2), lin%dxi(2, :))
    lin%dfn = -en * area * lin%dgap
    ft_vec = ft(1) * p%e(:, 1) + ft(2) * p%e(:, 2)
    lin%dft_stick = ft(1) * de(:, :, 1) + ft(2) * de(:, :, 2) - et * area * lin%dslip
    select case (status)
    case (CONTACT_SLIP)
      eta = ft / max(norm2(ft), tiny(1.0_dp))
      eta_vec = eta(1) * p%e(:, 1) + eta(2) * p%e(:, 2)
      factor = fr%mu * fn / max(trial_norm, tiny(1.0_dp))
      ! Slip rate V = |slip| / dt with the slip opposite to the force direction eta.
      dmu = fr%dmu_dpressure * lin%dfn / area - fr%dmu_drate * rate_factor * matmul(eta_vec, lin%dslip)
      lin%df = outer(eta_vec, fr%mu * lin%dfn + fn * dmu) &
               - factor * et * area * matmul(identity3() - outer3(p%normal, p%normal) &
                                             - outer3(eta_vec, eta_vec), lin%dslip) &
               + fr%mu * fn * (eta(1) * de(:, :, 1) + eta(2) * de(:, :, 2))
    case default
      lin%df = lin%dft_stick
    end select
    lin%df = lin%df + outer(p%normal, lin%dfn) + fn * dn
    ! Nodal forces F = R f and K = -dF/du; dF_I = -N_I df - (dN_I/dxi . dxi) f.
    f = fn * p%normal + ft_vec
    lin%force(1:3) = f
    lin%stiffness(1:3, :) = -lin%df
    do i = 1, 4
      lin%force(3 * i + 1:3 * i + 3) = -p%shape(i) * f
      lin%stiffness(3 * i + 1:3 * i + 3, :) = p%shape(i) * lin%df + &
        outer(f, p%dshape(1, i) * lin%dxi(1, :) + p%dshape(2, i) * lin%dxi(2, :))
    end do
  end subroutine contact_linearise

  !> Return mapping of one closed contact node over an increment (eq. 5): new contact point
  !> `p_new` (already projected), the old point `p_old` evaluated on the new master
  !> coordinates (for the slip vector), the old friction components `ft_old`, and mu.
  !> Tied nodes keep a bilateral normal spring about `tied_gap` and never slip. Whether a
  !> node with zero normal force is open is decided by the caller (fcs_contact_system).
  pure function contact_update(p_new, gap_new, p_old_on_new, ft_old, status_old, area, en, et, mu, &
                               tied_gap) result(out)
    type(segment_point_t), intent(in) :: p_new, p_old_on_new
    real(dp), intent(in) :: gap_new, ft_old(2), area, en, et, mu, tied_gap
    integer, intent(in) :: status_old
    type(contact_update_t) :: out
    real(dp) :: trial(2), norm_trial
    out%xi = p_new%xi
    out%gap = gap_new
    out%slip_vector = p_new%x - p_old_on_new%x
    out%mu = mu
    ! The frictional force on the slave opposes its motion relative to the master (eq. 4).
    trial = ft_old - et * area * matmul(out%slip_vector, p_new%e)
    if (status_old == CONTACT_TIED) then
      out%status = CONTACT_TIED
      out%normal_force = -en * area * (gap_new - tied_gap)
      out%friction = trial
      return
    end if
    out%normal_force = en * area * max(0.0_dp, -gap_new)
    norm_trial = norm2(trial)
    if (norm_trial <= mu * out%normal_force) then
      out%status = CONTACT_STICK
      out%friction = trial
    else
      out%status = CONTACT_SLIP
      out%friction = mu * out%normal_force * trial / norm_trial
      out%plastic_slip = (norm_trial - mu * out%normal_force) / (et * area)
    end if
  end function contact_update

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
    real(dp), intent(inout) :: m(3, 15)
    integer, intent(in) :: block
    real(dp), intent(in) :: value
    integer :: i
    do i = 1, 3
      m(i, 3 * (block - 1) + i) = value
    end do
  end subroutine put_diag

  pure function outer(a, b) result(m)
    real(dp), intent(in) :: a(3), b(15)
    real(dp) :: m(3, 15)
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
