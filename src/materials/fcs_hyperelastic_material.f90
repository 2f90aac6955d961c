!> A hyperelastic material (`*HYPERELASTIC`, `*HYPERFOAM`; fcs_hyperelastic, doc/theory.md
!> section 2.11). Its stress is a function of the deformation gradient: the element loops
!> take it from F under NLGEOM (update_hyperelastic, hyperelastic_tangents), as they take St
!> Venant-Kirchhoff. CalculiX turns NLGEOM on for these materials (its *HYPERELASTIC reader:
!> "nonlinear geometric effects are turned on"), and so does the model builder; the
!> small-strain procedures below (the linearisation at F = I: isotropic elasticity with the
!> initial moduli mu_0, K_0) serve the parts that want an elastic scale (C3D8R's hourglass
!> stiffness, the default contact penalties).
module fcs_hyperelastic_material
  use fcs_kinds, only: dp
  use fcs_material, only: material_t
  use fcs_hyperelastic, only: hyperelastic_law_t, hyperelastic_initial_moduli
  implicit none
  private
  public :: hyperelastic_t, hyperelastic_from_law

  type, extends(material_t) :: hyperelastic_t
    type(hyperelastic_law_t) :: law
  contains
    procedure :: tangent => hyperelastic_small_tangent
    procedure :: update => hyperelastic_small_update
    procedure :: event_fraction => hyperelastic_event_fraction
    procedure :: n_state => hyperelastic_n_state
    procedure :: name => hyperelastic_name
  end type hyperelastic_t

contains

  !> The material of `law`, with the Young's modulus and Poisson's ratio of its initial moduli:
  !> E = 9 K mu / (3 K + mu), nu = (3 K - 2 mu) / (2 (3 K + mu)).
  function hyperelastic_from_law(law) result(material)
    type(hyperelastic_law_t), intent(in) :: law
    type(hyperelastic_t) :: material
    real(dp) :: mu0, k0
    material%law = law
    call hyperelastic_initial_moduli(law, mu0, k0)
    material%youngs_modulus = 9.0_dp * k0 * mu0 / (3.0_dp * k0 + mu0)
    material%poisson_ratio = (3.0_dp * k0 - 2.0_dp * mu0) / (2.0_dp * (3.0_dp * k0 + mu0))
  end function hyperelastic_from_law

  pure function hyperelastic_small_tangent(this, stress, state) result(c)
    class(hyperelastic_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:)
    real(dp) :: c(6, 6)
    c = this%elastic_matrix()
  end function hyperelastic_small_tangent

  !> The linearisation at F = I (used only where the total form does not apply).
  pure subroutine hyperelastic_small_update(this, stress, strain_increment, state, consistent_tangent)
    class(hyperelastic_t), intent(in) :: this
    real(dp), intent(inout) :: stress(6)
    real(dp), intent(in) :: strain_increment(6)
    real(dp), intent(inout) :: state(:)
    real(dp), intent(out), optional :: consistent_tangent(6, 6)
    stress = stress + matmul(this%elastic_matrix(), strain_increment)
    if (present(consistent_tangent)) consistent_tangent = this%elastic_matrix()
  end subroutine hyperelastic_small_update

  !> No discrete states: never limits the increment.
  pure real(dp) function hyperelastic_event_fraction(this, stress, stress_increment, state)
    class(hyperelastic_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), stress_increment(6), state(:)
    hyperelastic_event_fraction = huge(1.0_dp)
  end function hyperelastic_event_fraction

  pure integer function hyperelastic_n_state(this)
    class(hyperelastic_t), intent(in) :: this
    hyperelastic_n_state = 0
  end function hyperelastic_n_state

  pure function hyperelastic_name(this) result(name)
    class(hyperelastic_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'hyperelastic'
  end function hyperelastic_name

end module fcs_hyperelastic_material
