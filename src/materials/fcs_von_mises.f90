!> von Mises (J2) plasticity with isotropic, kinematic or combined hardening, as `*PLASTIC`
!> (and `*CYCLIC HARDENING`) define it in CalculiX, on the hypoelastic law of fcs_hypoelastic:
!> the elastic part is C : D (eq. M1), the plastic strain rate follows the normality rule.
!> Per integration point (Simo & Hughes 1998, "Computational Inelasticity", section 3.3 and
!> Box 3.1, J2 plasticity with combined nonlinear hardening):
!>
!>     f = q(xi) - R(alpha),   xi = dev(sigma) - beta,   q(xi) = sqrt(3/2 xi : xi)       (V1)
!>     d eps_p = d lambda sqrt(3/2) N,   N = xi / |xi|,   d alpha = d lambda              (V2)
!>     d beta = sqrt(2/3) d B(alpha) N                                                 (V3)
!>
!> alpha is the equivalent plastic strain (PEEQ: sqrt(2/3 d eps_p : d eps_p) summed), R the
!> yield-surface radius (a uniaxial stress) and B the kinematic curve, both functions of alpha:
!>
!> * HARDENING=ISOTROPIC: R = the *PLASTIC curve, B constant (no back stress);
!> * HARDENING=KINEMATIC: R = the first stress of the *PLASTIC curve, B = the curve;
!> * HARDENING=COMBINED: R = the *CYCLIC HARDENING curve, B = the *PLASTIC curve,
!>
!> so that in monotonic uniaxial loading the stress follows the *PLASTIC curve in every case,
!> and the back stress in uniaxial terms sqrt(3/2) |beta| is B(alpha) - B(0).
!>
!> Internal variables (13): alpha, the plastic strain (6, engineering shear) and beta (6).
module fcs_von_mises
  use fcs_kinds, only: dp
  use fcs_material, only: material_t, YIELD_TOLERANCE, UNLOADING_COSINE
  use fcs_hardening_table, only: hardening_table_t, solve_flow_equation
  use fcs_voigt, only: deviator, stress_norm, stress_dot, deviatoric_projector, outer, &
                       rotate_stress_like, rotate_strain_like
  implicit none
  private
  public :: von_mises_t, N_STATE_VON_MISES, PEEQ, PLASTIC_STRAIN, BACK_STRESS

  !> Positions of the internal variables (public for fcs_simo_plasticity, which extends them).
  integer, parameter :: PEEQ = 1, PLASTIC_STRAIN = 2, BACK_STRESS = 8
  integer, parameter :: N_STATE_VON_MISES = 13

  type, extends(material_t) :: von_mises_t
    !> Radius R(alpha) and kinematic curve B(alpha) of (V1)-(V3).
    type(hardening_table_t) :: radius
    type(hardening_table_t) :: kinematic
    character(len=:), allocatable :: hardening
  contains
    procedure :: tangent => von_mises_tangent
    procedure :: update => von_mises_update
    procedure :: event_fraction => von_mises_event_fraction
    procedure :: n_state => von_mises_n_state
    procedure :: name => von_mises_name
    procedure :: rotate_state => von_mises_rotate_state
    procedure :: equivalent_plastic_strain => von_mises_peeq
    procedure :: plastic_strain => von_mises_plastic_strain
    procedure :: add_plastic_strain => von_mises_add_plastic_strain
    procedure :: back_stress => von_mises_back_stress
    procedure :: is_plastic => von_mises_is_plastic
    procedure :: unloads => von_mises_unloads
    procedure :: on_surface => von_mises_on_surface
  end type von_mises_t

contains

  !> Start-of-increment tangent: on the yield surface, the elastoplastic tangent of continued
  !> loading (Simo & Hughes 1998, eq. 3.3.13 with (V1)-(V3); the consistent tangent of Box 3.2
  !> for a vanishing increment):
  !>     C_ep = C - 6 G^2 / (3 G + R' + B') N x N                                          (V4)
  !> with R', B' the slopes of the curves ahead of alpha; elsewhere C.
  pure function von_mises_tangent(this, stress, state) result(c)
    class(von_mises_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:)
    real(dp) :: c(6, 6)
    real(dp) :: xi(6), g, hardening
    c = this%elastic_matrix()
    if (.not. this%on_surface(stress, state)) return
    xi = deviator(stress) - state(BACK_STRESS:BACK_STRESS + 5)
    g = this%shear_modulus()
    hardening = this%radius%slope(state(PEEQ)) + this%kinematic%slope(state(PEEQ))
    xi = xi / stress_norm(xi)
    c = c - 6.0_dp * g**2 / (3.0_dp * g + hardening) * outer(xi, xi)
  end function von_mises_tangent

  !> Radial return (Simo & Hughes 1998, Box 3.1): elastic trial sigma_tr = sigma + C de,
  !> xi_tr = dev(sigma_tr) - beta, q_tr = sqrt(3/2) |xi_tr|. If q_tr <= R(alpha) the step is
  !> elastic. Otherwise the new alpha solves the consistency condition
  !>     q_tr - 3 G (alpha - alpha_n) = R(alpha) + B(alpha) - B(alpha_n)                  (V5)
  !> (exactly, segment by segment of the curves: solve_flow_equation), and with
  !> d lambda = alpha - alpha_n, N = xi_tr / |xi_tr| (unchanged by the return):
  !>     sigma = sigma_tr - sqrt(6) G d lambda N,   eps_p += d lambda sqrt(3/2) N,
  !>     beta += sqrt(2/3) (B(alpha) - B(alpha_n)) N.                                      (V6)
  !> The consistent tangent (Box 3.2, with A = 3 G + R' + B' on the segment of the root):
  !>     D = C - 6 G^2 / A N x N - 2 G (3 G d lambda / q_tr) (P - N x N)                   (V7)
  !> P the deviatoric projector.
  pure subroutine von_mises_update(this, stress, strain_increment, state, consistent_tangent)
    class(von_mises_t), intent(in) :: this
    real(dp), intent(inout) :: stress(6)
    real(dp), intent(in) :: strain_increment(6)
    real(dp), intent(inout) :: state(:)
    real(dp), intent(out), optional :: consistent_tangent(6, 6)
    real(dp) :: xi(6), n(6), q_trial, alpha_n, alpha, g, hardening, d_lambda, kinematic_n
    real(dp) :: flow(6)
    logical :: ok
    stress = stress + matmul(this%elastic_matrix(), strain_increment)
    if (present(consistent_tangent)) consistent_tangent = this%elastic_matrix()
    alpha_n = state(PEEQ)
    xi = deviator(stress) - state(BACK_STRESS:BACK_STRESS + 5)
    q_trial = sqrt(1.5_dp) * stress_norm(xi)
    if (q_trial <= this%radius%value(alpha_n)) return
    g = this%shear_modulus()
    kinematic_n = this%kinematic%value(alpha_n)
    call solve_flow_equation(q_trial + kinematic_n, 3.0_dp * g, alpha_n, &
                             [this%radius, this%kinematic], [1.0_dp, 1.0_dp], alpha, hardening, ok)
    d_lambda = alpha - alpha_n
    n = xi / stress_norm(xi)
    stress = stress - sqrt(6.0_dp) * g * d_lambda * n
    flow = sqrt(1.5_dp) * d_lambda * n
    flow(4:6) = 2.0_dp * flow(4:6)
    state(PEEQ) = alpha
    state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5) = state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5) + flow
    state(BACK_STRESS:BACK_STRESS + 5) = state(BACK_STRESS:BACK_STRESS + 5) + &
      sqrt(2.0_dp / 3.0_dp) * (this%kinematic%value(alpha) - kinematic_n) * n
    if (present(consistent_tangent)) consistent_tangent = consistent_tangent - &
      6.0_dp * g**2 / (3.0_dp * g + hardening) * outer(n, n) - &
      2.0_dp * g * (3.0_dp * g * d_lambda / q_trial) * (deviatoric_projector() - outer(n, n))
  end subroutine von_mises_update

  !> First yield along sigma + r dsigma (R-minimum yield event): the root in r > 0 of
  !>     3/2 |xi + r ds|^2 = R(alpha)^2,   ds = dev(dsigma)                                (V8)
  !> a quadratic a r^2 + b r + c with c < 0 for a point inside the surface (one positive root,
  !> taken in the cancellation-free form). A point on the surface that keeps loading is
  !> plastic already and reports none; one that unloads (the increment's cosine with xi below
  !> -UNLOADING_COSINE: b < -2 UNLOADING_COSINE sqrt(a 3/2 xi : xi)) crosses the surface
  !> again at the far root -b/a + O(c) (reverse yield within the increment).
  pure real(dp) function von_mises_event_fraction(this, stress, stress_increment, state) result(r)
    class(von_mises_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), stress_increment(6), state(:)
    real(dp) :: xi(6), ds(6), radius, a, b, c, root
    r = huge(1.0_dp)
    xi = deviator(stress) - state(BACK_STRESS:BACK_STRESS + 5)
    ds = deviator(stress_increment)
    radius = this%radius%value(state(PEEQ))
    a = 1.5_dp * stress_dot(ds, ds)
    b = 3.0_dp * stress_dot(xi, ds)
    c = min(0.0_dp, 1.5_dp * stress_dot(xi, xi) - radius**2)
    if (.not. (a > 0.0_dp)) return
    if (this%on_surface(stress, state) .and. &
        b >= -2.0_dp * UNLOADING_COSINE * sqrt(a * 1.5_dp * stress_dot(xi, xi))) return
    root = sqrt(max(0.0_dp, b**2 - 4.0_dp * a * c))
    if (b >= 0.0_dp) then
      r = -2.0_dp * c / (b + root)
    else
      r = (root - b) / (2.0_dp * a)
    end if
  end function von_mises_event_fraction

  !> On the surface: q(xi) >= R(alpha) (1 - YIELD_TOLERANCE).
  pure logical function von_mises_on_surface(this, stress, state) result(on)
    class(von_mises_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:)
    on = sqrt(1.5_dp) * stress_norm(deviator(stress) - state(BACK_STRESS:BACK_STRESS + 5)) >= &
         this%radius%value(state(PEEQ)) * (1.0_dp - YIELD_TOLERANCE)
  end function von_mises_on_surface

  !> Elastic unloading from the surface: xi : ds < -UNLOADING_COSINE |xi| |ds| for the
  !> deviator ds of the elastic trial C de of a point on it.
  pure logical function von_mises_unloads(this, stress, state, strain_increment) result(unloads)
    class(von_mises_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:), strain_increment(6)
    real(dp) :: xi(6), rate(6)
    unloads = this%on_surface(stress, state)
    if (.not. unloads) return
    xi = deviator(stress) - state(BACK_STRESS:BACK_STRESS + 5)
    rate = deviator(matmul(this%elastic_matrix(), strain_increment))
    unloads = stress_dot(xi, rate) < -UNLOADING_COSINE * stress_norm(xi) * stress_norm(rate)
  end function von_mises_unloads

  !> Rotate the plastic strain and the back stress with the stress.
  pure subroutine von_mises_rotate_state(this, state, q)
    class(von_mises_t), intent(in) :: this
    real(dp), intent(inout) :: state(:)
    real(dp), intent(in) :: q(3, 3)
    state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5) = &
      rotate_strain_like(state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5), q)
    state(BACK_STRESS:BACK_STRESS + 5) = rotate_stress_like(state(BACK_STRESS:BACK_STRESS + 5), q)
  end subroutine von_mises_rotate_state

  pure real(dp) function von_mises_peeq(this, state) result(peeq_value)
    class(von_mises_t), intent(in) :: this
    real(dp), intent(in) :: state(:)
    peeq_value = state(PEEQ)
  end function von_mises_peeq

  pure function von_mises_plastic_strain(this, state) result(strain)
    class(von_mises_t), intent(in) :: this
    real(dp), intent(in) :: state(:)
    real(dp) :: strain(6)
    strain = state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5)
  end function von_mises_plastic_strain

  !> Add eps_0 to the plastic strain (the initial plastic strain; alpha and beta unchanged:
  !> CalculiX's initial plastic strain does not harden).
  pure subroutine von_mises_add_plastic_strain(this, state, strain)
    class(von_mises_t), intent(in) :: this
    real(dp), intent(inout) :: state(:)
    real(dp), intent(in) :: strain(6)
    state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5) = state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5) + strain
  end subroutine von_mises_add_plastic_strain

  pure function von_mises_back_stress(this, state) result(alpha)
    class(von_mises_t), intent(in) :: this
    real(dp), intent(in) :: state(:)
    real(dp) :: alpha(6)
    alpha = state(BACK_STRESS:BACK_STRESS + 5)
  end function von_mises_back_stress

  pure logical function von_mises_is_plastic(this)
    class(von_mises_t), intent(in) :: this
    von_mises_is_plastic = .true.
  end function von_mises_is_plastic

  pure integer function von_mises_n_state(this)
    class(von_mises_t), intent(in) :: this
    von_mises_n_state = N_STATE_VON_MISES
  end function von_mises_n_state

  pure function von_mises_name(this) result(name)
    class(von_mises_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'von Mises, ' // this%hardening // ' hardening'
  end function von_mises_name

end module fcs_von_mises
