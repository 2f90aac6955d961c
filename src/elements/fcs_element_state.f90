!> The element and material state: Cauchy stress, accumulated strain and the materials'
!> internal variables at every integration point of every element, the run state the element
!> loops (fcs_element_loops) update. Arrays are sized by the largest rule of the model's kinds
!> (max_points): an element with fewer points leaves the rest zero, and an all-C3D8 model has
!> (6, 8, n_elements), as before the element interface. It saves and loads itself (records
!> stress, strain and material_state of a group of the archive).
module fcs_element_state
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_archive, only: archive_t
  implicit none
  private
  public :: element_state_t

  type :: element_state_t
    !> stress(:, q, e) and strain(:, q, e) at point q of element e, Voigt order 11, 22, 33, 12,
    !> 13, 23; strains with engineering shear.
    real(dp), allocatable :: stress(:, :, :)
    real(dp), allocatable :: strain(:, :, :)
    !> Material internal variables (n_state, max_points, n_elements); n_state may be 0.
    real(dp), allocatable :: material_state(:, :, :)
  contains
    procedure :: init => element_state_init
    procedure :: save => element_state_save
    procedure :: load => element_state_load
  end type element_state_t

contains

  !> Zero stresses, strains and internal variables.
  subroutine element_state_init(this, max_points, n_elements, n_material_state)
    class(element_state_t), intent(inout) :: this
    integer, intent(in) :: max_points, n_elements, n_material_state
    if (allocated(this%stress)) deallocate (this%stress, this%strain, this%material_state)
    allocate (this%stress(6, max_points, n_elements), this%strain(6, max_points, n_elements))
    this%stress = 0.0_dp
    this%strain = 0.0_dp
    allocate (this%material_state(n_material_state, max_points, n_elements))
    this%material_state = 0.0_dp
  end subroutine element_state_init

  !> Write the fields as records `stress`, `strain` and (when there are internal variables)
  !> `material_state` of group `group` (which the caller has created).
  subroutine element_state_save(this, archive, group, err)
    class(element_state_t), intent(in) :: this
    class(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: group
    type(error_t), allocatable, intent(out) :: err
    call archive%put(group // '/stress', this%stress, err)
    if (.not. allocated(err)) call archive%put(group // '/strain', this%strain, err)
    if (.not. allocated(err) .and. size(this%material_state, 1) > 0) &
      call archive%put(group // '/material_state', this%material_state, err)
  end subroutine element_state_save

  !> Read what `save` wrote into fields set up for the same model (`init`).
  subroutine element_state_load(this, archive, group, err)
    class(element_state_t), intent(inout) :: this
    class(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: group
    type(error_t), allocatable, intent(out) :: err
    call archive%get(group // '/stress', this%stress, err)
    if (.not. allocated(err)) call archive%get(group // '/strain', this%strain, err)
    if (.not. allocated(err) .and. size(this%material_state, 1) > 0) &
      call archive%get(group // '/material_state', this%material_state, err)
  end subroutine element_state_load

end module fcs_element_state
