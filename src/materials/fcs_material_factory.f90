!> Creates material objects by name.
module fcs_material_factory
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error
  use fcs_material, only: material_t
  use fcs_hypoelastic, only: hypoelastic_t
  implicit none
  private
  public :: create_material, MATERIAL_NAMES

  !> Valid material model names.
  character(len=*), parameter :: MATERIAL_NAMES = 'HYPOELASTIC'

contains

  !> A material model `name` with Young's modulus `e` and Poisson's ratio `nu`.
  subroutine create_material(name, e, nu, material, err)
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: e, nu
    class(material_t), allocatable, intent(out) :: material
    type(error_t), allocatable, intent(out) :: err
    select case (name)
    case ('HYPOELASTIC')
      allocate (hypoelastic_t :: material)
    case default
      call input_error(err, 'unknown material model "' // name // '"; expected one of ' // MATERIAL_NAMES)
      return
    end select
    material%youngs_modulus = e
    material%poisson_ratio = nu
  end subroutine create_material

end module fcs_material_factory
