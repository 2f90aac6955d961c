!> The abstract material: the constitutive part of the rate formulation, sigma^J = C : D
!> (Xing, Mora & Makinouchi 2003, eq. 1), for one integration point. Nothing here knows the
!> element kind: every element kind calls the same procedures at each of its points.
!>
!> Stresses and strains are in Voigt order (11, 22, 33, 12, 13, 23) with engineering shear
!> strains (gamma_12 = 2 eps_12), the order CalculiX prints them in. The caller rotates the
!> stress objectively (Hughes & Winget 1980) and, for a material with internal variables, the
!> tensor-valued ones too (`rotate_state`), before `update` adds the constitutive part for the
!> strain increment. `update` is a pure function of its inputs: called again with the same
!> start stress, state and increment it gives the same result (equilibrium iterations may
!> recompute an increment from the saved start of the increment).
!>
!> Each material may keep internal variables per integration point (`n_state` of them; their
!> layout is the material's own: others ask for the equivalent plastic strain, the plastic
!> strain and the back stress through the accessors) and may report R-minimum events (first
!> yield, `event_fraction`).
module fcs_material
  use fcs_kinds, only: dp
  use fcs_thermal_properties, only: thermal_properties_t
  implicit none
  private
  public :: material_t, material_slot_t, isotropic_elastic_matrix, isotropic_compliance_matrix
  public :: YIELD_TOLERANCE, UNLOADING_COSINE

  !> A point whose yield function f lies within YIELD_TOLERANCE times the current yield
  !> stress of the surface counts as on it: its tangent is elastoplastic (unless the increment
  !> unloads it) and it reports no yield event. Radial return leaves f at round-off (1e-15
  !> relative) and an R-minimum yield event lands within about 1e-12 without NLGEOM. Under
  !> NLGEOM the event is predicted with the strain increment on the start configuration while
  !> the update takes it on the mid-increment one, so a point lands short by about half its
  !> strain increment, relative: up to 1e-3 with the default MAX STRAIN INCREMENT of 2e-3.
  !> Counted as on the surface, such a point takes the elastoplastic tangent in the next
  !> increment, instead of a second yield event a hair away, which the minimum increment
  !> would overshoot with the elastic tangent (measured: 3e-4 of the yield stress of
  !> out-of-balance in uniaxial stress, against 1e-5 with this tolerance).
  real(dp), parameter :: YIELD_TOLERANCE = 1.0e-3_dp

  !> A point on its yield surface unloads when the elastic trial of the increment points into
  !> the elastic domain by more than this cosine (with the normal of the surface): more than
  !> about 6 degrees inwards. Flowing points (contained plastic flow, perfect plasticity) have
  !> trials close to the tangent plane on either side; counted as unloading they would report
  !> a re-crossing of the surface a hair into every increment (the far root of the yield
  !> event, at a fraction proportional to the cosine) and stall the stepper. Between 0 and
  !> this cosine the point keeps the elastoplastic tangent; the return mapping decides the
  !> update in every case.
  real(dp), parameter :: UNLOADING_COSINE = 0.1_dp

  type, abstract :: material_t
    real(dp) :: youngs_modulus = 0.0_dp
    real(dp) :: poisson_ratio = 0.0_dp
    !> Under NLGEOM, St Venant-Kirchhoff (fcs_st_venant_kirchhoff: the stress a function of the
    !> deformation gradient, CalculiX's law for *ELASTIC) instead of the rate form of `update`
    !> (*HYPOELASTIC, and the elastic part of plasticity). The element loops choose the path.
    logical :: st_venant_kirchhoff = .false.
    !> Thermal expansion and temperature-dependent elastic constants (fcs_thermal_properties);
    !> empty for a material that temperature does not affect.
    type(thermal_properties_t) :: thermal
  contains
    procedure(tangent_interface), deferred :: tangent
    procedure(update_interface), deferred :: update
    procedure(event_interface), deferred :: event_fraction
    procedure(n_state_interface), deferred :: n_state
    procedure(name_interface), deferred :: name
    procedure :: elastic_matrix => material_elastic_matrix
    procedure :: shear_modulus => material_shear_modulus
    procedure :: bulk_modulus => material_bulk_modulus
    procedure :: rotate_state => material_rotate_state
    procedure :: equivalent_plastic_strain => material_equivalent_plastic_strain
    procedure :: plastic_strain => material_plastic_strain
    procedure :: add_plastic_strain => material_add_plastic_strain
    procedure :: back_stress => material_back_stress
    procedure :: is_plastic => material_is_plastic
    procedure :: is_anisotropic => material_is_anisotropic
    procedure :: plastic_strain_fraction => material_plastic_strain_fraction
    procedure :: point_events => material_point_events
    procedure :: unloads => material_unloads
    procedure :: on_surface => material_on_surface
    procedure :: thermal_strain_increment => material_thermal_strain_increment
    procedure :: elastic_matrix_at => material_elastic_matrix_at
    procedure :: rescale_stress => material_rescale_stress
    procedure :: at_temperature => material_at_temperature
  end type material_t

  !> One material object (of any law), e.g. one per *MATERIAL of a model.
  type :: material_slot_t
    class(material_t), allocatable :: m
  end type material_slot_t

  abstract interface
    !> Tangent modulus C (6x6, engineering strain to stress) for the current state of one
    !> integration point, at the start of an increment: the elastoplastic tangent of
    !> continued loading for a point on its yield surface (the consistent tangent of a
    !> vanishing increment), the elastic one otherwise.
    pure function tangent_interface(this, stress, state) result(c)
      import :: material_t, dp
      class(material_t), intent(in) :: this
      real(dp), intent(in) :: stress(6), state(:)
      real(dp) :: c(6, 6)
    end function tangent_interface

    !> Add the constitutive stress change for `strain_increment` to `stress` (already rotated
    !> to the end of the increment) and update the internal variables. With
    !> `consistent_tangent`, also d(stress)/d(strain_increment) of this update (the
    !> algorithmic tangent, for equilibrium iterations).
    pure subroutine update_interface(this, stress, strain_increment, state, consistent_tangent)
      import :: material_t, dp
      class(material_t), intent(in) :: this
      real(dp), intent(inout) :: stress(6)
      real(dp), intent(in) :: strain_increment(6)
      real(dp), intent(inout) :: state(:)
      real(dp), intent(out), optional :: consistent_tangent(6, 6)
    end subroutine update_interface

    !> Fraction r of a trial stress increment at which the state changes (first yield: the
    !> stress reaches the yield surface), or a value > 1 if it does not within the increment.
    pure real(dp) function event_interface(this, stress, stress_increment, state)
      import :: material_t, dp
      class(material_t), intent(in) :: this
      real(dp), intent(in) :: stress(6), stress_increment(6), state(:)
    end function event_interface

    !> Number of internal variables per integration point.
    pure integer function n_state_interface(this)
      import :: material_t
      class(material_t), intent(in) :: this
    end function n_state_interface

    pure function name_interface(this) result(name)
      import :: material_t
      class(material_t), intent(in) :: this
      character(len=:), allocatable :: name
    end function name_interface
  end interface

contains

  !> Isotropic elasticity matrix of this material.
  pure function material_elastic_matrix(this) result(c)
    class(material_t), intent(in) :: this
    real(dp) :: c(6, 6)
    c = isotropic_elastic_matrix(this%youngs_modulus, this%poisson_ratio)
  end function material_elastic_matrix

  !> G = E / (2 (1 + nu)).
  pure real(dp) function material_shear_modulus(this) result(g)
    class(material_t), intent(in) :: this
    g = 0.5_dp * this%youngs_modulus / (1.0_dp + this%poisson_ratio)
  end function material_shear_modulus

  !> K = E / (3 (1 - 2 nu)).
  pure real(dp) function material_bulk_modulus(this) result(k)
    class(material_t), intent(in) :: this
    k = this%youngs_modulus / (3.0_dp * (1.0_dp - 2.0_dp * this%poisson_ratio))
  end function material_bulk_modulus

  !> Rotate the tensor-valued internal variables objectively by the increment's rotation q
  !> (Hughes & Winget 1980). Materials without such variables keep the default (nothing).
  pure subroutine material_rotate_state(this, state, q)
    class(material_t), intent(in) :: this
    real(dp), intent(inout) :: state(:)
    real(dp), intent(in) :: q(3, 3)
  end subroutine material_rotate_state

  !> Equivalent plastic strain (PEEQ) of a state; 0 for a material without plasticity.
  pure real(dp) function material_equivalent_plastic_strain(this, state) result(peeq)
    class(material_t), intent(in) :: this
    real(dp), intent(in) :: state(:)
    peeq = 0.0_dp
  end function material_equivalent_plastic_strain

  !> Plastic strain tensor (Voigt, engineering shear) of a state; 0 without plasticity.
  pure function material_plastic_strain(this, state) result(strain)
    class(material_t), intent(in) :: this
    real(dp), intent(in) :: state(:)
    real(dp) :: strain(6)
    strain = 0.0_dp
  end function material_plastic_strain

  !> Add eps_0 (Voigt, engineering shear) to the plastic strain of a state: the initial plastic
  !> strain of *INITIAL CONDITIONS, TYPE=PLASTIC STRAIN. A material without a plastic strain
  !> keeps the default (nothing): for it eps_0 lives in the initial stress -C : eps_0 alone.
  pure subroutine material_add_plastic_strain(this, state, strain)
    class(material_t), intent(in) :: this
    real(dp), intent(inout) :: state(:)
    real(dp), intent(in) :: strain(6)
  end subroutine material_add_plastic_strain

  !> Back stress (centre of the yield surface, Voigt) of a state; 0 without kinematic
  !> hardening.
  pure function material_back_stress(this, state) result(alpha)
    class(material_t), intent(in) :: this
    real(dp), intent(in) :: state(:)
    real(dp) :: alpha(6)
    alpha = 0.0_dp
  end function material_back_stress

  !> Whether the material can yield (keeps a plastic state).
  pure logical function material_is_plastic(this)
    class(material_t), intent(in) :: this
    material_is_plastic = .false.
  end function material_is_plastic

  !> Whether the elastic stiffness has material axes (fcs_anisotropic_elastic): the element
  !> loops then turn strains and stresses into the axes of the element's *ORIENTATION.
  pure logical function material_is_anisotropic(this)
    class(material_t), intent(in) :: this
    material_is_anisotropic = .false.
  end function material_is_anisotropic

  !> The fraction r of a trial increment at which the equivalent plastic strain of this
  !> point grows by `limit` (the R-minimum limit MAX PLASTIC STRAIN INCREMENT), or a value
  !> > 1 if it grows less over the whole trial increment. The increment taken applies
  !> `strain_fixed` (the out-of-balance correction) in full and r times `strain_load`, from
  !> `stress` and `state`; `r_yield` is the point's yield fraction (> 1 if it does not yield
  !> or is plastic already). The growth is computed by the material's own update for r = 0
  !> and 1 and taken linear in r beyond the yield fraction, which is exact for proportional
  !> loading on one segment of a hardening curve and an estimate otherwise (the limit is a
  !> step control, not a tolerance).
  pure real(dp) function material_plastic_strain_fraction(this, stress, state, strain_fixed, &
                                                           strain_load, r_yield, limit) result(r)
    class(material_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:), strain_fixed(6), strain_load(6), r_yield, limit
    real(dp) :: trial_stress(6), trial_state(size(state)), start, growth_full, growth_fixed
    r = huge(1.0_dp)
    if (.not. this%is_plastic() .or. .not. (limit > 0.0_dp)) return
    start = this%equivalent_plastic_strain(state)
    trial_stress = stress
    trial_state = state
    call this%update(trial_stress, strain_fixed + strain_load, trial_state)
    growth_full = this%equivalent_plastic_strain(trial_state) - start
    if (growth_full <= limit) return
    if (r_yield >= 0.0_dp .and. r_yield < 1.0_dp) then
      r = r_yield + (1.0_dp - r_yield) * limit / growth_full
      return
    end if
    trial_stress = stress
    trial_state = state
    call this%update(trial_stress, strain_fixed, trial_state)
    growth_fixed = this%equivalent_plastic_strain(trial_state) - start
    ! The correction alone already exceeds the limit: scaling the load cannot help.
    if (growth_fixed >= limit) return
    r = (limit - growth_fixed) / (growth_full - growth_fixed)
  end function material_plastic_strain_fraction

  !> Whether a point on its yield surface leaves it inwards under the elastic trial of
  !> `strain_increment` (the trial's cosine with the normal of the surface below
  !> -UNLOADING_COSINE): elastic unloading, whose
  !> tangent is the elastic one (Yamada, Yoshimura & Sakurai 1968). False for a point inside
  !> the surface and for a material without plasticity (the default).
  pure logical function material_unloads(this, stress, state, strain_increment) result(unloads)
    class(material_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:), strain_increment(6)
    unloads = .false.
  end function material_unloads

  !> Whether the point lies on its yield surface (within YIELD_TOLERANCE): false for a
  !> material without plasticity (the default).
  pure logical function material_on_surface(this, stress, state) result(on)
    class(material_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:)
    on = .false.
  end function material_on_surface

  !> The R-minimum fractions of one integration point for a trial increment that applies
  !> `strain_fixed` (the out-of-balance correction) in full and r times `strain_load`, both
  !> linearised at the start of the increment with its tangent (the elastic one for a point
  !> that the increment unloads): `r_yield`, where the stress
  !> reaches the yield surface (event_fraction), and `r_plastic`, where the equivalent plastic
  !> strain has grown by `limit` (plastic_strain_fraction); values > 1 when they do not happen.
  pure subroutine material_point_events(this, stress, state, strain_fixed, strain_load, limit, &
                                        r_yield, r_plastic)
    class(material_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:), strain_fixed(6), strain_load(6), limit
    real(dp), intent(out) :: r_yield, r_plastic
    real(dp) :: tangent(6, 6)
    if (this%unloads(stress, state, strain_fixed + strain_load)) then
      ! Elastic unloading: where the elastic path reaches the surface again (reverse yield).
      tangent = this%elastic_matrix()
      r_yield = this%event_fraction(stress + matmul(tangent, strain_fixed), &
                                    matmul(tangent, strain_load), state)
    else if (this%on_surface(stress, state)) then
      ! Plastic loading: no event (the elastoplastic stress path stays on the surface).
      r_yield = huge(1.0_dp)
    else
      tangent = this%tangent(stress, state)
      r_yield = this%event_fraction(stress + matmul(tangent, strain_fixed), &
                                    matmul(tangent, strain_load), state)
    end if
    r_plastic = this%plastic_strain_fraction(stress, state, strain_fixed, strain_load, r_yield, limit)
  end subroutine material_point_events

  !> The thermal strain increment (Voigt, engineering shear) of a point whose temperature goes
  !> from t_start to t_end: [1, 1, 1, 0, 0, 0] (alpha(t_end) (t_end - T_Z) - alpha(t_start)
  !> (t_start - T_Z)), the secant form of CalculiX (fcs_thermal_properties); 0 without
  !> *EXPANSION.
  pure function material_thermal_strain_increment(this, t_start, t_end) result(increment)
    class(material_t), intent(in) :: this
    real(dp), intent(in) :: t_start, t_end
    real(dp) :: increment(6)
    increment = 0.0_dp
    if (.not. this%thermal%has_expansion()) return
    increment(1:3) = this%thermal%strain(t_end) - this%thermal%strain(t_start)
  end function material_thermal_strain_increment

  !> The elastic matrix at temperature t: C(E(t), nu(t)) for temperature-dependent constants,
  !> else the material's own.
  pure function material_elastic_matrix_at(this, t) result(c)
    class(material_t), intent(in) :: this
    real(dp), intent(in) :: t
    real(dp) :: c(6, 6)
    real(dp) :: e, nu
    if (this%thermal%elastic_varies()) then
      call this%thermal%elastic_at(t, e, nu)
      c = isotropic_elastic_matrix(e, nu)
    else
      c = this%elastic_matrix()
    end if
  end function material_elastic_matrix_at

  !> The stress of a point whose elastic constants change from their values at t_start to
  !> those at t_end with its elastic strain held: C(t_end) C(t_start)^-1 sigma. This is the
  !> term dC : C^-1 : sigma of the rate form sigma^J = C : (D - D_th) + dC/dT T' : C^-1 : sigma
  !> (doc/theory.md, section 2.5), integrated so that sigma = C(T) eps_el exactly, CalculiX's
  !> total form for small strains. Unchanged when the constants do not depend on temperature.
  pure function material_rescale_stress(this, stress, t_start, t_end) result(rescaled)
    class(material_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), t_start, t_end
    real(dp) :: rescaled(6)
    real(dp) :: e0, nu0, e1, nu1
    rescaled = stress
    if (.not. this%thermal%elastic_varies()) return
    call this%thermal%elastic_at(t_start, e0, nu0)
    call this%thermal%elastic_at(t_end, e1, nu1)
    if (e0 == e1 .and. nu0 == nu1) return
    rescaled = matmul(isotropic_elastic_matrix(e1, nu1), &
                      matmul(isotropic_compliance_matrix(e0, nu0), stress))
  end function material_rescale_stress

  !> A copy of this material with its elastic constants at temperature t (the material
  !> itself, copied, when they do not depend on temperature).
  subroutine material_at_temperature(this, t, copy)
    class(material_t), intent(in) :: this
    real(dp), intent(in) :: t
    class(material_t), allocatable, intent(out) :: copy
    allocate (copy, source=this)
    if (this%thermal%elastic_varies()) &
      call this%thermal%elastic_at(t, copy%youngs_modulus, copy%poisson_ratio)
  end subroutine material_at_temperature

  !> Isotropic compliance matrix (the inverse of isotropic_elastic_matrix): engineering
  !> strain from stress, Voigt order.
  pure function isotropic_compliance_matrix(e, nu) result(s)
    real(dp), intent(in) :: e, nu
    real(dp) :: s(6, 6)
    integer :: i
    s = 0.0_dp
    s(1:3, 1:3) = -nu / e
    do i = 1, 3
      s(i, i) = 1.0_dp / e
      s(i + 3, i + 3) = 2.0_dp * (1.0_dp + nu) / e
    end do
  end function isotropic_compliance_matrix

  !> Isotropic elasticity matrix in Voigt order (11,22,33,12,13,23), engineering shear.
  pure function isotropic_elastic_matrix(e, nu) result(c)
    real(dp), intent(in) :: e, nu
    real(dp) :: c(6, 6)
    real(dp) :: lambda, mu
    integer :: i
    lambda = e * nu / ((1.0_dp + nu) * (1.0_dp - 2.0_dp * nu))
    mu = 0.5_dp * e / (1.0_dp + nu)
    c = 0.0_dp
    c(1:3, 1:3) = lambda
    do i = 1, 3
      c(i, i) = lambda + 2.0_dp * mu
      c(i + 3, i + 3) = mu
    end do
  end function isotropic_elastic_matrix

end module fcs_material
