!> Linear Drucker-Prager plasticity in Abaqus's form (Abaqus Analysis User's Guide,
!> "Extended Drucker-Prager models", linear criterion with flow stress ratio K = 1), on the
!> hypoelastic law of fcs_hypoelastic. With p = -tr(sigma)/3 (pressure, positive in
!> compression), q = sqrt(3/2 s : s) and the friction and dilation angles beta, psi:
!>
!>     F = q - p tan(beta) - d(eps_bar) <= 0                    (yield surface)           (D1)
!>     G = q - p tan(psi)                                       (flow potential)          (D2)
!>     d eps_p = d lambda dG/dsigma = d lambda (sqrt(3/2) N + tan(psi)/3 I),  N = s/|s|   (D3)
!>     d eps_bar = c d lambda                                                             (D4)
!>
!> The cohesion d follows the *DRUCKER PRAGER HARDENING curve sigma_h(eps_bar) by its TYPE,
!> and c makes eps_bar the plastic strain of that test (Abaqus's definitions for K = 1):
!> COMPRESSION d = (1 - tan(beta)/3) sigma_c, c = 1 - tan(psi)/3 (|eps_p,11| in uniaxial
!> compression); TENSION d = (1 + tan(beta)/3) sigma_t, c = 1 + tan(psi)/3; SHEAR
!> d = sqrt(3) tau, c = 1 (gamma_p / sqrt(3) in pure shear). psi = beta is associated flow;
!> psi /= beta makes the tangent unsymmetric.
!>
!> Internal variables (7): eps_bar (PEEQ) and the plastic strain (6, engineering shear).
module fcs_drucker_prager
  use fcs_kinds, only: dp
  use fcs_material, only: material_t, YIELD_TOLERANCE, UNLOADING_COSINE
  use fcs_hardening_table, only: hardening_table_t, solve_flow_equation
  use fcs_voigt, only: VOIGT_IDENTITY, deviator, stress_norm, stress_dot, trace, &
                       deviatoric_projector, outer, rotate_strain_like
  implicit none
  private
  public :: drucker_prager_t, N_STATE_DRUCKER_PRAGER

  integer, parameter :: PEEQ = 1, PLASTIC_STRAIN = 2
  integer, parameter :: N_STATE_DRUCKER_PRAGER = 7

  type, extends(material_t) :: drucker_prager_t
    real(dp) :: tan_friction = 0.0_dp
    real(dp) :: tan_dilation = 0.0_dp
    !> The hardening curve sigma_h(eps_bar); d = cohesion_factor * sigma_h.
    type(hardening_table_t) :: hardening
    real(dp) :: cohesion_factor = 1.0_dp
    !> c of (D4).
    real(dp) :: rate_factor = 1.0_dp
    character(len=:), allocatable :: hardening_type
  contains
    procedure :: tangent => drucker_prager_tangent
    procedure :: update => drucker_prager_update
    procedure :: event_fraction => drucker_prager_event_fraction
    procedure :: n_state => drucker_prager_n_state
    procedure :: name => drucker_prager_name
    procedure :: rotate_state => drucker_prager_rotate_state
    procedure :: equivalent_plastic_strain => drucker_prager_peeq
    procedure :: plastic_strain => drucker_prager_plastic_strain
    procedure :: is_plastic => drucker_prager_is_plastic
    procedure :: cohesion => drucker_prager_cohesion
    procedure :: unloads => drucker_prager_unloads
    procedure :: on_surface => drucker_prager_on_surface
    procedure :: loading_cosine => drucker_prager_loading_cosine
  end type drucker_prager_t

contains

  !> d(eps_bar).
  pure real(dp) function drucker_prager_cohesion(this, eps_bar) result(d)
    class(drucker_prager_t), intent(in) :: this
    real(dp), intent(in) :: eps_bar
    d = this%cohesion_factor * this%hardening%value(eps_bar)
  end function drucker_prager_cohesion

  !> Start-of-increment tangent: on the smooth part of the cone, the elastoplastic tangent of
  !> continued loading (the consistent tangent (D7) for a vanishing increment),
  !>     C_ep = C - (sqrt(6) G N + K tan(psi) I) x (sqrt(6) G N + K tan(beta) I) / A,
  !>     A = 3 G + K tan(beta) tan(psi) + c d'                                            (D5)
  !> unsymmetric unless psi = beta; C inside the cone and at the apex (a corner, where the
  !> return mapping alone decides).
  pure function drucker_prager_tangent(this, stress, state) result(c)
    class(drucker_prager_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:)
    real(dp) :: c(6, 6)
    real(dp) :: s(6), g, k, a
    c = this%elastic_matrix()
    if (.not. this%on_surface(stress, state)) return
    s = deviator(stress)
    g = this%shear_modulus()
    k = this%bulk_modulus()
    s = s / stress_norm(s)
    a = 3.0_dp * g + k * this%tan_friction * this%tan_dilation + &
        this%rate_factor * this%cohesion_factor * this%hardening%slope(state(PEEQ))
    c = c - outer(sqrt(6.0_dp) * g * s + k * this%tan_dilation * VOIGT_IDENTITY, &
                  sqrt(6.0_dp) * g * s + k * this%tan_friction * VOIGT_IDENTITY) / a
  end function drucker_prager_tangent

  !> Return mapping (de Souza Neto, Peric & Owen 2008, "Computational Methods for
  !> Plasticity", section 8.3.3 and Box 8.9, in the variables of (D1)-(D4)). Elastic trial
  !> sigma_tr = sigma + C de with q_tr, p_tr, N = s_tr/|s_tr|. If F(sigma_tr) <= 0: elastic.
  !> Smooth cone: q = q_tr - 3 G dl, p = p_tr + K tan(psi) dl, and eps_bar = eps_n + c dl
  !> solves
  !>     q_tr - tan(beta) p_tr - (3 G + K tan(beta) tan(psi)) (eps_bar - eps_n) / c = d(eps_bar)  (D6)
  !> (exactly, segment by segment); sigma = sigma_tr - dl (sqrt(6) G N + K tan(psi) I).
  !> Consistent tangent (A of (D5) on the segment of the root):
  !>     D = C - 2 G (3 G dl / q_tr) (P - N x N)
  !>           - (sqrt(6) G N + K tan(psi) I) x (sqrt(6) G N + K tan(beta) I) / A         (D7)
  !> If the smooth solution has q < 0 the stress returns to the apex q = 0: with the plastic
  !> volume change v, p = p_tr + K v, eps_bar = eps_n + c v / tan(psi) and
  !>     -tan(beta) p_tr - K tan(beta) tan(psi) (eps_bar - eps_n) / c = d(eps_bar),
  !>     D = K c d' / (K tan(beta) tan(psi) + c d') I x I.                                 (D8)
  !> With psi = 0 the flow rule allows no plastic volume change and no stress beyond the
  !> apex satisfies it: the stress is then put on the apex (p = -d / tan(beta)), with
  !> dl = q_tr / (3 G) (a tension cut-off).
  pure subroutine drucker_prager_update(this, stress, strain_increment, state, consistent_tangent)
    class(drucker_prager_t), intent(in) :: this
    real(dp), intent(inout) :: stress(6)
    real(dp), intent(in) :: strain_increment(6)
    real(dp), intent(inout) :: state(:)
    real(dp), intent(out), optional :: consistent_tangent(6, 6)
    real(dp) :: s(6), n(6), q_trial, p_trial, eps_n, eps_bar, g, k, b, slope, d_lambda
    real(dp) :: flow(6), a, apex_start
    logical :: ok
    stress = stress + matmul(this%elastic_matrix(), strain_increment)
    if (present(consistent_tangent)) consistent_tangent = this%elastic_matrix()
    eps_n = state(PEEQ)
    s = deviator(stress)
    q_trial = sqrt(1.5_dp) * stress_norm(s)
    p_trial = -trace(stress) / 3.0_dp
    if (q_trial - this%tan_friction * p_trial <= this%cohesion(eps_n)) return
    g = this%shear_modulus()
    k = this%bulk_modulus()
    b = (3.0_dp * g + k * this%tan_friction * this%tan_dilation) / this%rate_factor
    call solve_flow_equation(q_trial - this%tan_friction * p_trial, b, eps_n, [this%hardening], &
                             [this%cohesion_factor], eps_bar, slope, ok)
    d_lambda = (eps_bar - eps_n) / this%rate_factor
    if (q_trial - 3.0_dp * g * d_lambda >= 0.0_dp .and. q_trial > 0.0_dp) then
      n = s / stress_norm(s)
      stress = stress - d_lambda * (sqrt(6.0_dp) * g * n + k * this%tan_dilation * VOIGT_IDENTITY)
      flow = d_lambda * (sqrt(1.5_dp) * n + this%tan_dilation / 3.0_dp * VOIGT_IDENTITY)
      if (present(consistent_tangent)) then
        a = this%rate_factor * (b + slope)
        consistent_tangent = consistent_tangent - &
          2.0_dp * g * (3.0_dp * g * d_lambda / q_trial) * (deviatoric_projector() - outer(n, n)) - &
          outer(sqrt(6.0_dp) * g * n + k * this%tan_dilation * VOIGT_IDENTITY, &
                sqrt(6.0_dp) * g * n + k * this%tan_friction * VOIGT_IDENTITY) / a
      end if
    else
      ! The apex. The smooth solution passes q = 0 at dl = q_tr / (3 G): the apex solution
      ! lies beyond it.
      apex_start = eps_n + this%rate_factor * q_trial / (3.0_dp * g)
      if (this%tan_dilation > 0.0_dp) then
        b = k * this%tan_friction * this%tan_dilation / this%rate_factor
        call solve_flow_equation(-this%tan_friction * p_trial - b * (apex_start - eps_n), b, &
                                 apex_start, [this%hardening], [this%cohesion_factor], eps_bar, &
                                 slope, ok)
        if (present(consistent_tangent)) consistent_tangent = k * this%rate_factor * slope / &
          (k * this%tan_friction * this%tan_dilation + this%rate_factor * slope) * &
          outer(VOIGT_IDENTITY, VOIGT_IDENTITY)
      else
        eps_bar = apex_start
        slope = this%cohesion_factor * this%hardening%slope(eps_bar)
        if (present(consistent_tangent)) consistent_tangent = slope * this%rate_factor * &
          sqrt(6.0_dp) / (3.0_dp * this%tan_friction) * outer(VOIGT_IDENTITY, s / stress_norm(s))
      end if
      ! sigma = -p I with p on the apex; the plastic strain is C^-1 (sigma_tr - sigma).
      stress = this%cohesion(eps_bar) / this%tan_friction * VOIGT_IDENTITY
      flow = s / (2.0_dp * g) + (-this%cohesion(eps_bar) / this%tan_friction - p_trial) / &
             (3.0_dp * k) * VOIGT_IDENTITY
    end if
    flow(4:6) = 2.0_dp * flow(4:6)
    state(PEEQ) = eps_bar
    state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5) = state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5) + flow
  end subroutine drucker_prager_update

  !> First yield along sigma + r dsigma (R-minimum yield event). With h(r) = tan(beta) p(r) + d
  !> the surface is q(r) = h(r) >= 0; squared,
  !>     phi(r) = 3/2 |s + r ds|^2 - h(r)^2 = a r^2 + b r + c = 0,                          (D9)
  !> c < 0 inside the cone. Leaving the cone continuously, the path meets q = h with h >= 0
  !> first, so the yield fraction is the smallest positive root of phi with h >= 0; when phi
  !> has no such root the path can only leave through the apex, where h(r) = 0. A point on the
  !> cone that keeps loading reports none; one that unloads (cosine with the normal below
  !> -UNLOADING_COSINE) leaves the root at 0 out and reports where it reaches the cone again.
  pure real(dp) function drucker_prager_event_fraction(this, stress, stress_increment, state) &
      result(r)
    class(drucker_prager_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), stress_increment(6), state(:)
    real(dp) :: s(6), ds(6), p, dp_, d, h, dh, a, b, c, disc, roots(3)
    integer :: i
    logical :: on_cone
    r = huge(1.0_dp)
    s = deviator(stress)
    ds = deviator(stress_increment)
    p = -trace(stress) / 3.0_dp
    dp_ = -trace(stress_increment) / 3.0_dp
    d = this%cohesion(state(PEEQ))
    h = this%tan_friction * p + d
    dh = this%tan_friction * dp_
    ! At the apex (a corner of a convex cone) a straight path stays outside or goes inside
    ! for good: no event.
    if (sqrt(1.5_dp) * stress_norm(s) - h >= -YIELD_TOLERANCE * d .and. &
        sqrt(1.5_dp) * stress_norm(s) <= YIELD_TOLERANCE * d) return
    on_cone = this%on_surface(stress, state)
    if (on_cone) then
      if (this%loading_cosine(stress, stress_increment) >= -UNLOADING_COSINE) return
    end if
    a = 1.5_dp * stress_dot(ds, ds) - dh**2
    b = 3.0_dp * stress_dot(s, ds) - 2.0_dp * h * dh
    c = 1.5_dp * stress_dot(s, s) - h**2
    roots = huge(1.0_dp)
    if (abs(a) > 0.0_dp) then
      disc = b**2 - 4.0_dp * a * c
      if (disc >= 0.0_dp) then
        if (b >= 0.0_dp) then
          roots(1) = (-b - sqrt(disc)) / (2.0_dp * a)
          if (abs(roots(1)) > 0.0_dp) roots(2) = c / (a * roots(1))
        else
          roots(1) = (-b + sqrt(disc)) / (2.0_dp * a)
          if (abs(roots(1)) > 0.0_dp) roots(2) = c / (a * roots(1))
        end if
      end if
    else if (abs(b) > 0.0_dp) then
      roots(1) = -c / b
    end if
    if (on_cone) then
      ! Leave out the root at (about) 0, where the path leaves the cone.
      if (abs(roots(2)) < abs(roots(1))) then
        roots(2) = huge(1.0_dp)
      else
        roots(1) = roots(2)
        roots(2) = huge(1.0_dp)
      end if
    end if
    if (dh < 0.0_dp) roots(3) = -h / dh
    do i = 1, 3
      ! Only positive roots below the best so far (huge(1.0_dp) marks no root: r starts there,
      ! and p + roots(i) * dp_ would overflow on it).
      if (.not. (roots(i) > 0.0_dp .and. roots(i) < r)) cycle
      if (this%tan_friction * (p + roots(i) * dp_) + d < -YIELD_TOLERANCE * d) cycle
      r = min(r, roots(i))
    end do
  end function drucker_prager_event_fraction

  !> On the smooth part of the cone: F >= -YIELD_TOLERANCE d and q > YIELD_TOLERANCE d (the
  !> apex is a corner: its tangent is elastic and its events are those of a point inside).
  pure logical function drucker_prager_on_surface(this, stress, state) result(on)
    class(drucker_prager_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:)
    real(dp) :: q, d
    q = sqrt(1.5_dp) * stress_norm(deviator(stress))
    d = this%cohesion(state(PEEQ))
    on = q + this%tan_friction * trace(stress) / 3.0_dp - d >= -YIELD_TOLERANCE * d .and. &
         q > YIELD_TOLERANCE * d
  end function drucker_prager_on_surface

  !> Cosine of a stress rate with the normal dF/dsigma = sqrt(3/2) N + tan(beta)/3 I of the
  !> cone (0 for a vanishing rate).
  pure real(dp) function drucker_prager_loading_cosine(this, stress, rate) result(cosine)
    class(drucker_prager_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), rate(6)
    real(dp) :: s(6), normal(6), size
    s = deviator(stress)
    normal = sqrt(1.5_dp) * s / stress_norm(s) + this%tan_friction / 3.0_dp * VOIGT_IDENTITY
    size = stress_norm(normal) * stress_norm(rate)
    cosine = 0.0_dp
    if (size > 0.0_dp) cosine = stress_dot(normal, rate) / size
  end function drucker_prager_loading_cosine

  !> Elastic unloading from the smooth part of the cone: the elastic trial C de of the
  !> increment has a cosine below -UNLOADING_COSINE with the cone's normal.
  pure logical function drucker_prager_unloads(this, stress, state, strain_increment) result(unloads)
    class(drucker_prager_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:), strain_increment(6)
    unloads = this%on_surface(stress, state)
    if (unloads) unloads = this%loading_cosine(stress, matmul(this%elastic_matrix(), strain_increment)) &
                           < -UNLOADING_COSINE
  end function drucker_prager_unloads

  !> Rotate the plastic strain with the stress.
  pure subroutine drucker_prager_rotate_state(this, state, q)
    class(drucker_prager_t), intent(in) :: this
    real(dp), intent(inout) :: state(:)
    real(dp), intent(in) :: q(3, 3)
    state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5) = &
      rotate_strain_like(state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5), q)
  end subroutine drucker_prager_rotate_state

  pure real(dp) function drucker_prager_peeq(this, state) result(peeq_value)
    class(drucker_prager_t), intent(in) :: this
    real(dp), intent(in) :: state(:)
    peeq_value = state(PEEQ)
  end function drucker_prager_peeq

  pure function drucker_prager_plastic_strain(this, state) result(strain)
    class(drucker_prager_t), intent(in) :: this
    real(dp), intent(in) :: state(:)
    real(dp) :: strain(6)
    strain = state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5)
  end function drucker_prager_plastic_strain

  pure logical function drucker_prager_is_plastic(this)
    class(drucker_prager_t), intent(in) :: this
    drucker_prager_is_plastic = .true.
  end function drucker_prager_is_plastic

  pure integer function drucker_prager_n_state(this)
    class(drucker_prager_t), intent(in) :: this
    drucker_prager_n_state = N_STATE_DRUCKER_PRAGER
  end function drucker_prager_n_state

  pure function drucker_prager_name(this) result(name)
    class(drucker_prager_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'Drucker-Prager (linear, hardening in ' // this%hardening_type // ')'
  end function drucker_prager_name

end module fcs_drucker_prager
