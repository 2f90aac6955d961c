!> A material used only by the tests: TEST LINEAR ELASTIC, sigma <- sigma + C : delta_epsilon
!> with the isotropic C of its E and nu, written here as a new model would be, with its
!> registry entry (`test_elastic_entry`), so that a test can add it to the material registry
!> the way a new material is added (doc/architecture.md, "How to add a material").
module fcs_test_materials
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_material, only: material_t, isotropic_elastic_matrix
  use fcs_material_factory, only: plastic_def_t, material_entry_t
  implicit none
  private
  public :: test_elastic_t, test_elastic_entry, TEST_ELASTIC_NAME

  character(len=*), parameter :: TEST_ELASTIC_NAME = 'TEST LINEAR ELASTIC'

  type, extends(material_t) :: test_elastic_t
  contains
    procedure :: tangent => test_elastic_tangent
    procedure :: update => test_elastic_update
    procedure :: event_fraction => test_elastic_event_fraction
    procedure :: n_state => test_elastic_n_state
    procedure :: name => test_elastic_name_of
  end type test_elastic_t

contains

  !> The registry entry: name TEST LINEAR ELASTIC, constructor new_test_elastic.
  function test_elastic_entry() result(entry)
    type(material_entry_t) :: entry
    entry%name = TEST_ELASTIC_NAME
    entry%construct => new_test_elastic
  end function test_elastic_entry

  subroutine new_test_elastic(plastic, material, err)
    type(plastic_def_t), intent(in) :: plastic
    class(material_t), allocatable, intent(out) :: material
    type(error_t), allocatable, intent(out) :: err
    allocate (test_elastic_t :: material)
  end subroutine new_test_elastic

  pure function test_elastic_tangent(this, stress, state) result(c)
    class(test_elastic_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), state(:)
    real(dp) :: c(6, 6)
    c = isotropic_elastic_matrix(this%youngs_modulus, this%poisson_ratio)
  end function test_elastic_tangent

  pure subroutine test_elastic_update(this, stress, strain_increment, state, consistent_tangent)
    class(test_elastic_t), intent(in) :: this
    real(dp), intent(inout) :: stress(6)
    real(dp), intent(in) :: strain_increment(6)
    real(dp), intent(inout) :: state(:)
    real(dp), intent(out), optional :: consistent_tangent(6, 6)
    stress = stress + matmul(this%tangent(stress, state), strain_increment)
    if (present(consistent_tangent)) consistent_tangent = this%tangent(stress, state)
  end subroutine test_elastic_update

  pure real(dp) function test_elastic_event_fraction(this, stress, stress_increment, state)
    class(test_elastic_t), intent(in) :: this
    real(dp), intent(in) :: stress(6), stress_increment(6), state(:)
    test_elastic_event_fraction = huge(1.0_dp)
  end function test_elastic_event_fraction

  pure integer function test_elastic_n_state(this)
    class(test_elastic_t), intent(in) :: this
    test_elastic_n_state = 0
  end function test_elastic_n_state

  pure function test_elastic_name_of(this) result(name)
    class(test_elastic_t), intent(in) :: this
    character(len=:), allocatable :: name
    name = TEST_ELASTIC_NAME
  end function test_elastic_name_of

end module fcs_test_materials
