!> A hyperelastic material (`*HYPERELASTIC`, `*HYPERFOAM`; fcs_hyperelastic, doc/theory.md
!> section 2.11). Its stress is a function of the deformation gradient: the element loops
!> take it from F under NLGEOM (update_hyperelastic, hyperelastic_tangents), as they take St
!> Venant-Kirchhoff. CalculiX turns NLGEOM on for these materials (its *HYPERELASTIC reader:
!> "nonlinear geometric effects are turned on"), and so does the model builder; the
!> small-strain procedures below (the linearisation at F = I: isotropic elasticity with the
!> initial moduli mu_0, K_0) serve the parts that want an elastic scale (C3D8R's hourglass
!> stiffness, the default contact penalties): they are the hypoelastic material's, with the
!> initial moduli as its constants, so hyperelastic_t extends hypoelastic_t.
module fcs_hyperelastic_material
  use fcs_kinds, only: dp
  use fcs_hypoelastic, only: hypoelastic_t
  use fcs_hyperelastic, only: hyperelastic_law_t, hyperelastic_initial_moduli
  implicit none
  private
  public :: hyperelastic_t, hyperelastic_from_law

  type, extends(hypoelastic_t) :: hyperelastic_t
    type(hyperelastic_law_t) :: law
  contains
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

  pure function hyperelastic_name(this) result(name)
    class(hyperelastic_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'hyperelastic'
  end function hyperelastic_name

end module fcs_hyperelastic_material
