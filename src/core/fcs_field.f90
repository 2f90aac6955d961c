!> A result field as plain data: a name, where its values live and the values, so that the
!> writers of results (src/io/) receive fields and know nothing of the modules that compute
!> them (contact, elements, stepper).
module fcs_field
  use fcs_kinds, only: dp
  implicit none
  private
  public :: field_t, field, point_field, FIELD_NODES, FIELD_CELLS, FIELD_POINTS, FIELD_SURFACE, FIELD_LOCATION_NAMES

  !> Where a field's values live: at the mesh nodes (values(:, node)), per element (cells,
  !> values(:, element)), at the integration points (point_values(:, q, element)), or at the
  !> points of a named surface grid (values(:, point), e.g. the slave nodes of a contact pair).
  integer, parameter :: FIELD_NODES = 1, FIELD_CELLS = 2, FIELD_POINTS = 3, FIELD_SURFACE = 4
  character(len=18), parameter :: FIELD_LOCATION_NAMES(4) = [character(len=18) :: 'node', &
    'element', 'integration point', 'surface point']

  type :: field_t
    character(len=:), allocatable :: name
    integer :: location = FIELD_NODES
    !> The surface grid the values belong to (FIELD_SURFACE only).
    character(len=:), allocatable :: grid
    !> values(component, entity) for nodes, cells and surface points.
    real(dp), allocatable :: values(:, :)
    !> point_values(component, point, element) for integration points.
    real(dp), allocatable :: point_values(:, :, :)
  end type field_t

contains

  !> A field of values(component, entity) at `location` (a surface field names its grid).
  pure function field(name, location, values, grid) result(f)
    character(len=*), intent(in) :: name
    integer, intent(in) :: location
    real(dp), intent(in) :: values(:, :)
    character(len=*), intent(in), optional :: grid
    type(field_t) :: f
    f%name = name
    f%location = location
    f%values = values
    if (present(grid)) f%grid = grid
  end function field

  !> A field at the integration points: values(component, point, element).
  pure function point_field(name, values) result(f)
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: values(:, :, :)
    type(field_t) :: f
    f%name = name
    f%location = FIELD_POINTS
    f%point_values = values
  end function point_field

end module fcs_field
