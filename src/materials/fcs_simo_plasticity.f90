!> Multiplicative finite-strain von Mises plasticity, CalculiX 2.20's law for *ELASTIC with
!> *PLASTIC under NLGEOM (ccx 2.20 manual, section 6.8.8 and its incplas.f; Simo 1988, Comp.
!> Meth. Appl. Mech. Engng. 66, 199-219 and 68, 1-31; Simo & Hughes 1998, "Computational
!> Inelasticity", boxes 9.1 and 9.2). doc/theory.md 2.8 derives it. In the reference
!> configuration, with C = F^T F, J = det F, Cbar = J^-2/3 C:
!>
!>   state: C_p^-1 (inverse plastic right Cauchy-Green tensor, b_e = F C_p^-1 F^T), the
!>          reference back stress B (its push-forward F B F^T J^-2/3 the spatial one), PEEQ
!>   I_bar = tr(Cbar C_p^-1) / 3,   B_m = tr(Cbar B) / 3                              (P1)
!>   S_dev = G (J^-2/3 C_p^-1 - I_bar C^-1),   Xi = S_dev - (J^-2/3 B - B_m C^-1)         (P2)
!>   |Xi| = sqrt(tr(C Xi C Xi)),   q = sqrt(3/2) |Xi| / J   (the Kirchhoff deviator's norm)
!>   yield:  q <= R(alpha)   (J R on the Kirchhoff stress: R a Cauchy curve)           (P3)
!>   flow:   q - 3 m d_alpha / J = R(alpha) + (m / G) (B(alpha) - B(alpha_n)),
!>           m = G I_bar - B_m,  d_alpha = alpha - alpha_n = sqrt(2/3) d_gamma          (P4)
!>   S = K/2 (J^2 - 1) C^-1 + S_dev - 2 m d_gamma / |Xi| Xi                            (P5)
!>   C_p^-1 -= 2 m d_gamma / (G |Xi|) J^2/3 Xi,
!>   B += 2 m J d_gamma_B / (3 G |Xi|) J^2/3 Xi,  d_gamma_B = sqrt(3/2) (B(alpha) - B(alpha_n))
!>
!> with R and B(alpha) the radius and kinematic curves of fcs_von_mises (HARDENING=ISOTROPIC,
!> KINEMATIC, COMBINED read as there). The Cauchy stress is F S F^T / det F. Pushed forward,
!> (P1)-(P5) are box 9.1 with the stored energy W = K/2 ((J^2 - 1)/2 - ln J) + G/2 (tr bbar_e
!> - 3) and mu_bar = G I_bar, the back stress convected by the deformation (it lives in the
!> reference configuration, as C_p^-1 does). Temperature: ccx's mechanical deformation
!> gradient F_m = F - a I (calcmechstrain.f; a the thermal strain from the initial
!> temperature) takes F's place in (P1)-(P5), the printed stress is F S F^T / det F with the
!> total F, and the elastic constants are those at the point's temperature.
!>
!> Without NLGEOM (and for C3D8I, whose modes are not part of F) the law is the rate form of
!> fcs_von_mises, which this type extends; its state extends that of fcs_von_mises, whose
!> slots keep PEEQ, the Green-Lagrange plastic strain (C_p - I)/2 and the back stress in the
!> units of the Cauchy stress, so that the R-minimum events (yield, plastic-strain limit),
!> the unloading test and the output read it as for the rate form.
module fcs_simo_plasticity
  use fcs_kinds, only: dp
  use fcs_von_mises, only: von_mises_t, N_STATE_VON_MISES, PEEQ, PLASTIC_STRAIN, BACK_STRESS
  use fcs_hardening_table, only: solve_flow_equation
  use fcs_st_venant_kirchhoff, only: voigt_tensor, tensor_voigt, determinant_of, inverse_of
  implicit none
  private
  public :: simo_plasticity_t, simo_from_von_mises, N_STATE_SIMO

  !> Positions of the state beyond fcs_von_mises's: C_p^-1 - I and B (tensor components in
  !> Voigt order, no doubled shears; zero for the undeformed state), and rho - 1, rho the
  !> ratio of the mechanical Kirchhoff stress over J_m to the printed Cauchy stress (1 without
  !> temperatures; (J / J_m)^(1/3) with them, exact for an isotropic thermal stretch).
  integer, parameter :: INVERSE_PLASTIC = N_STATE_VON_MISES + 1
  integer, parameter :: REFERENCE_BACK = INVERSE_PLASTIC + 6
  integer, parameter :: STRESS_RATIO = REFERENCE_BACK + 6
  integer, parameter :: N_STATE_SIMO = STRESS_RATIO

  !> The strain of the difference quotients of the tangent (central: error O(h^2)).
  real(dp), parameter :: TANGENT_STRAIN = 1.0e-6_dp

  real(dp), parameter :: IDENTITY(3, 3) = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, &
                                                    0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [3, 3])

  type, extends(von_mises_t) :: simo_plasticity_t
  contains
    procedure :: n_state => simo_n_state
    procedure :: name => simo_name
    procedure :: update => simo_rate_update
    procedure :: tangent => simo_rate_tangent
    procedure :: event_fraction => simo_event_fraction
    procedure :: on_surface => simo_on_surface
    procedure :: unloads => simo_unloads
    procedure :: add_plastic_strain => simo_add_plastic_strain
    procedure :: finite_stress => simo_finite_stress
    procedure :: finite_tangent => simo_finite_tangent
    procedure :: thermal_stretch => simo_thermal_stretch
  end type simo_plasticity_t

contains

  !> The finite-strain law with the curves of `law`.
  pure function simo_from_von_mises(law) result(simo)
    type(von_mises_t), intent(in) :: law
    type(simo_plasticity_t) :: simo
    simo%von_mises_t = law
  end function simo_from_von_mises

  !> Cauchy stress `sigma` (Voigt) at the total deformation gradient f from the state at the
  !> start of the increment, which becomes the state at f: (P1)-(P5). `a`: the thermal strain
  !> (F_m = f - a I); `t`: the temperature of the elastic constants (ignored when they do not
  !> depend on it). With `continued_loading`, the return is the one linearised at alpha_n
  !> (the slopes of the curves ahead of it), taken even inside the surface: the elastoplastic
  !> response of a point on it, for the tangent.
  pure subroutine simo_finite_stress(this, f, a, t, state, sigma, continued_loading)
    class(simo_plasticity_t), intent(in) :: this
    real(dp), intent(in) :: f(3, 3), a, t
    real(dp), intent(inout) :: state(:)
    real(dp), intent(out) :: sigma(6)
    logical, intent(in), optional :: continued_loading
    real(dp) :: fm(3, 3), c(3, 3), c_inv(3, 3), cp_inv(3, 3), b_ref(3, 3), xi(3, 3), s(3, 3)
    real(dp) :: cx(3, 3), g, k, j, j23, i_bar, back_mean, norm, q_trial, alpha_n, d_alpha
    real(dp) :: d_kin, m, drop, alpha, slope
    logical :: linearised, ok
    integer :: i
    linearised = .false.
    if (present(continued_loading)) linearised = continued_loading
    call moduli(this, t, g, k)
    fm = f
    do i = 1, 3
      fm(i, i) = fm(i, i) - a
    end do
    c = matmul(transpose(fm), fm)
    j = determinant_of(fm)
    c_inv = inverse_of(c)
    j23 = j**(2.0_dp / 3.0_dp)
    cp_inv = IDENTITY + voigt_tensor(state(INVERSE_PLASTIC:INVERSE_PLASTIC + 5))
    b_ref = voigt_tensor(state(REFERENCE_BACK:REFERENCE_BACK + 5))
    i_bar = trace(matmul(c, cp_inv)) / (3.0_dp * j23)
    back_mean = trace(matmul(c, b_ref)) / (3.0_dp * j23)
    s = g * (cp_inv / j23 - i_bar * c_inv)
    xi = s - (b_ref / j23 - back_mean * c_inv)
    cx = matmul(c, xi)
    norm = sqrt(max(0.0_dp, sum(cx * transpose(cx))))
    q_trial = sqrt(1.5_dp) * norm / j
    alpha_n = state(PEEQ)
    if ((linearised .or. q_trial > this%radius%value(alpha_n)) .and. norm > 0.0_dp) then
      m = g * i_bar - back_mean
      if (linearised) then
        d_alpha = (q_trial - this%radius%value(alpha_n)) / (3.0_dp * m / j + &
                  this%radius%slope(alpha_n) + m / g * this%kinematic%slope(alpha_n))
        d_kin = this%kinematic%slope(alpha_n) * d_alpha
      else
        call solve_flow_equation(q_trial + m / g * this%kinematic%value(alpha_n), 3.0_dp * m / j, &
                                 alpha_n, [this%radius, this%kinematic], [1.0_dp, m / g], alpha, &
                                 slope, ok)
        d_alpha = alpha - alpha_n
        d_kin = this%kinematic%value(alpha) - this%kinematic%value(alpha_n)
      end if
      ! 2 m d_gamma / |Xi| with d_gamma = sqrt(3/2) d_alpha (P5).
      drop = 2.0_dp * m * sqrt(1.5_dp) * d_alpha / norm
      s = s - drop * xi
      cp_inv = cp_inv - drop / g * j23 * xi
      b_ref = b_ref + 2.0_dp * m * j * sqrt(1.5_dp) * d_kin / (3.0_dp * g * norm) * j23 * xi
      state(PEEQ) = alpha_n + d_alpha
      state(INVERSE_PLASTIC:INVERSE_PLASTIC + 5) = tensor_voigt(cp_inv - IDENTITY)
      state(REFERENCE_BACK:REFERENCE_BACK + 5) = tensor_voigt(b_ref)
      state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5) = engineering(0.5_dp * (inverse_of(cp_inv) - IDENTITY))
    end if
    s = s + 0.5_dp * k * (j**2 - 1.0_dp) * c_inv
    sigma = tensor_voigt(matmul(f, matmul(s, transpose(f)))) / determinant_of(f)
    ! The spatial back stress over J_m (deviatoric: F_m C^-1 F_m^T = I) and rho for the
    ! rate-form checks on the printed stress.
    back_mean = trace(matmul(c, b_ref)) / (3.0_dp * j23)
    state(BACK_STRESS:BACK_STRESS + 5) = &
      tensor_voigt(matmul(fm, matmul(b_ref / j23 - back_mean * c_inv, transpose(fm)))) / j
    state(STRESS_RATIO) = (determinant_of(f) / j)**(1.0_dp / 3.0_dp) - 1.0_dp
  end subroutine simo_finite_stress

  !> The tangent of simo_finite_stress in the rate form of the element loops, sigma^J = c : D
  !> (Jaumann rate of the Cauchy stress, D the rate of deformation): with l = D (no spin) the
  !> Jaumann rate is the material rate, so column b of c is the central difference quotient
  !> (sigma((I + h D_b) F) - sigma((I - h D_b) F)) / (2 h), D_b the unit rate of Voigt
  !> component b (engineering shear), from the current state. This is the spatial tangent of
  !> box 9.2 of Simo & Hughes (1998) (the Lie derivative of tau, L_v tau = c_tau : D) with
  !> sigma^J = (c_tau + D tau + tau D) : D / J - sigma tr D (doc/theory.md 2.10) evaluated to
  !> O(h^2): with `plastic`, of continued loading (the linearised return), else elastic.
  pure function simo_finite_tangent(this, f, a, t, state, plastic) result(c)
    class(simo_plasticity_t), intent(in) :: this
    real(dp), intent(in) :: f(3, 3), a, t, state(:)
    logical, intent(in) :: plastic
    real(dp) :: c(6, 6)
    real(dp) :: d(3, 3), trial(size(state)), plus(6), minus(6)
    integer, parameter :: VOIGT_I(6) = [1, 2, 3, 1, 1, 2], VOIGT_J(6) = [1, 2, 3, 2, 3, 3]
    integer :: b
    do b = 1, 6
      d = 0.0_dp
      d(VOIGT_I(b), VOIGT_J(b)) = merge(1.0_dp, 0.5_dp, b <= 3) * TANGENT_STRAIN
      d(VOIGT_J(b), VOIGT_I(b)) = d(VOIGT_I(b), VOIGT_J(b))
      trial = state
      call this%finite_stress(matmul(IDENTITY + d, f), a, t, trial, plus, plastic)
      trial = state
      call this%finite_stress(matmul(IDENTITY - d, f), a, t, trial, minus, plastic)
      c(:, b) = (plus - minus) / (2.0_dp * TANGENT_STRAIN)
    end do
  end function simo_finite_tangent

  !> The thermal strain a of the last finite_stress of a state, recovered from rho and the
  !> deformation gradient f there: a = det(f)^(1/3) (1 - 1/rho), exact for an isotropic
  !> stretch (the tangent's F_m where the temperatures of the start are not at hand).
  pure real(dp) function simo_thermal_stretch(this, f, state) result(a)
    class(simo_plasticity_t), intent(in) :: this
    real(dp), intent(in) :: f(3, 3), state(:)
    a = determinant_of(f)**(1.0_dp / 3.0_dp) * (1.0_dp - 1.0_dp / (1.0_dp + state(STRESS_RATIO)))
  end function simo_thermal_stretch

  !> G and K at temperature t.
  pure subroutine moduli(this, t, g, k)
    class(simo_plasticity_t), intent(in) :: this
    real(dp), intent(in) :: t
    real(dp), intent(out) :: g, k
    real(dp) :: e, nu
    e = this%youngs_modulus
    nu = this%poisson_ratio
    if (this%thermal%elastic_varies()) call this%thermal%elastic_at(t, e, nu)
    g = 0.5_dp * e / (1.0_dp + nu)
    k = e / (3.0_dp * (1.0_dp - 2.0_dp * nu))
  end subroutine moduli

  !> The rate form (fcs_von_mises) on rho sigma, the stress the yield function reads.
  pure subroutine simo_rate_update(this, stress, strain_increment, state, consistent_tangent)
    class(simo_plasticity_t), intent(in) :: this
    real(dp), intent(inout) :: stress(6)
    real(dp), intent(in) :: strain_increment(6)
    real(dp), intent(inout) :: state(:)
    real(dp), intent(out), optional :: consistent_tangent(6, 6)
    real(dp) :: rho
    rho = 1.0_dp + state(STRESS_RATIO)
    stress = rho * stress
    call this%von_mises_t%update(stress, strain_increment, state, consistent_tangent)
    stress = stress / rho
  end subroutine simo_rate_update

  pure function simo_rate_tangent(this, stress, state) result(c)
    class(simo_plasticity_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:)
    real(dp) :: c(6, 6)
    c = this%von_mises_t%tangent((1.0_dp + state(STRESS_RATIO)) * stress, state)
  end function simo_rate_tangent

  pure real(dp) function simo_event_fraction(this, stress, stress_increment, state) result(r)
    class(simo_plasticity_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), stress_increment(6), state(:)
    real(dp) :: rho
    rho = 1.0_dp + state(STRESS_RATIO)
    r = this%von_mises_t%event_fraction(rho * stress, rho * stress_increment, state)
  end function simo_event_fraction

  pure logical function simo_on_surface(this, stress, state) result(on)
    class(simo_plasticity_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:)
    on = this%von_mises_t%on_surface((1.0_dp + state(STRESS_RATIO)) * stress, state)
  end function simo_on_surface

  pure logical function simo_unloads(this, stress, state, strain_increment) result(unloads)
    class(simo_plasticity_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:), strain_increment(6)
    unloads = this%von_mises_t%unloads((1.0_dp + state(STRESS_RATIO)) * stress, state, &
                                       strain_increment)
  end function simo_unloads

  !> The initial plastic strain: added to the plastic strain as by fcs_von_mises, and C_p^-1
  !> = (I + 2 E_p)^-1, E_p the plastic strain taken as a Green-Lagrange strain.
  pure subroutine simo_add_plastic_strain(this, state, strain)
    class(simo_plasticity_t), intent(in) :: this
    real(dp), intent(inout) :: state(:)
    real(dp), intent(in) :: strain(6)
    real(dp) :: e_p(6)
    call this%von_mises_t%add_plastic_strain(state, strain)
    e_p = state(PLASTIC_STRAIN:PLASTIC_STRAIN + 5)
    e_p(4:6) = 0.5_dp * e_p(4:6)
    state(INVERSE_PLASTIC:INVERSE_PLASTIC + 5) = &
      tensor_voigt(inverse_of(IDENTITY + 2.0_dp * voigt_tensor(e_p)) - IDENTITY)
  end subroutine simo_add_plastic_strain

  pure integer function simo_n_state(this)
    class(simo_plasticity_t), intent(in) :: this
    simo_n_state = N_STATE_SIMO
  end function simo_n_state

  pure function simo_name(this) result(name)
    class(simo_plasticity_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'von Mises, ' // this%hardening // ' hardening (multiplicative under NLGEOM)'
  end function simo_name

  !> The Voigt vector with engineering shears of a symmetric strain tensor.
  pure function engineering(t) result(v)
    real(dp), intent(in) :: t(3, 3)
    real(dp) :: v(6)
    v = tensor_voigt(t)
    v(4:6) = 2.0_dp * v(4:6)
  end function engineering

  pure real(dp) function trace(t)
    real(dp), intent(in) :: t(3, 3)
    trace = t(1, 1) + t(2, 2) + t(3, 3)
  end function trace

end module fcs_simo_plasticity
