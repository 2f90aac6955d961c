!> Isotropic hypoelastic material: sigma^J = C : D with constant isotropic C (Xing, Mora &
!> Makinouchi 2003, eq. 1; the Jaumann rate is integrated objectively by the element).
module fcs_hypoelastic
  use fcs_kinds, only: dp
  use fcs_material, only: material_t
  implicit none
  private
  public :: hypoelastic_t

  type, extends(material_t) :: hypoelastic_t
  contains
    procedure :: tangent => hypoelastic_tangent
    procedure :: update => hypoelastic_update
    procedure :: event_fraction => hypoelastic_event_fraction
    procedure :: n_state => hypoelastic_n_state
    procedure :: name => hypoelastic_name
  end type hypoelastic_t

contains

  pure function hypoelastic_tangent(this, stress, state) result(c)
    class(hypoelastic_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:)
    real(dp) :: c(6, 6)
    c = this%elastic_matrix()
  end function hypoelastic_tangent

  !> sigma <- sigma + C : delta_epsilon (eq. M1); the consistent tangent is C.
  pure subroutine hypoelastic_update(this, stress, strain_increment, state, consistent_tangent)
    class(hypoelastic_t), intent(in) :: this
    real(dp), intent(inout) :: stress(6)
    real(dp), intent(in) :: strain_increment(6)
    real(dp), intent(inout) :: state(:)
    real(dp), intent(out), optional :: consistent_tangent(6, 6)
    stress = stress + matmul(this%elastic_matrix(), strain_increment)
    if (present(consistent_tangent)) consistent_tangent = this%elastic_matrix()
  end subroutine hypoelastic_update

  !> No discrete states: never limits the increment.
  pure real(dp) function hypoelastic_event_fraction(this, stress, stress_increment, state)
    class(hypoelastic_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), stress_increment(6), state(:)
    hypoelastic_event_fraction = huge(1.0_dp)
  end function hypoelastic_event_fraction

  pure integer function hypoelastic_n_state(this)
    class(hypoelastic_t), intent(in) :: this
    hypoelastic_n_state = 0
  end function hypoelastic_n_state

  pure function hypoelastic_name(this) result(name)
    class(hypoelastic_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = 'hypoelastic'
  end function hypoelastic_name

end module fcs_hypoelastic
