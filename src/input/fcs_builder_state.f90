!> The model builder's working state while it walks through the cards: the current material,
!> the step being built, and the running lists of boundary conditions and loads that carry
!> over from step to step (Abaqus/CalculiX OP=MOD / OP=NEW semantics).
module fcs_builder_state
  use fcs_kinds, only: dp
  use fcs_diagnostics, only: source_loc_t
  use fcs_int_map, only: int_map_t
  use fcs_model, only: step_t, dof_condition_t, face_load_t, body_load_t
  implicit none
  private
  public :: builder_t, condition_list_t, pressure_list_t, body_load_list_t

  !> Conditions on degrees of freedom, at most one per (node, dof): a new one replaces the old.
  !> Each remembers the scope (model data or a step) and the data line that set it, so that
  !> two different conditions on one degree of freedom in the same scope can be reported.
  type :: condition_list_t
    type(dof_condition_t), allocatable :: items(:)
    integer, allocatable :: scope(:)
    integer, allocatable :: origin(:)
    integer :: n = 0
    type(int_map_t) :: slot
  contains
    procedure :: clear => condition_list_clear
    procedure :: put => condition_list_put
    procedure :: to_array => condition_list_to_array
  end type condition_list_t

  !> Face pressures, at most one per (element, face).
  type :: pressure_list_t
    type(face_load_t), allocatable :: items(:)
    integer :: n = 0
    type(int_map_t) :: slot
  contains
    procedure :: clear => pressure_list_clear
    procedure :: put => pressure_list_put
    procedure :: to_array => pressure_list_to_array
  end type pressure_list_t

  !> Body loads, at most one per (element, kind): a new one replaces the old.
  type :: body_load_list_t
    type(body_load_t), allocatable :: items(:)
    integer :: n = 0
    type(int_map_t) :: slot
  contains
    procedure :: clear => body_load_list_clear
    procedure :: put => body_load_list_put
  end type body_load_list_t

  type :: builder_t
    !> Material that *ELASTIC and *DENSITY apply to (0: none yet).
    integer :: material = 0
    !> Interaction that *SURFACE BEHAVIOR and *FRICTION apply to (0: none yet).
    integer :: interaction = 0
    !> Interaction of the step's *CHANGE FRICTION that awaits its *FRICTION (0: none).
    integer :: changed_interaction = 0
    type(source_loc_t) :: change_loc
    !> Interaction a *CHANGE SURFACE BEHAVIOR of this step named, for the *SURFACE BEHAVIOR
    !> that must follow it (0: none pending), and where it was.
    integer :: changed_behavior = 0
    type(source_loc_t) :: behavior_loc
    !> The *COUPLING that awaits its *KINEMATIC or *DISTRIBUTING (coupling_ref = 0: none):
    !> its reference node and surface (indices), its name and line.
    integer :: coupling_ref = 0
    integer :: coupling_surface = 0
    character(len=:), allocatable :: coupling_name
    type(source_loc_t) :: coupling_loc
    !> The reference nodes of the *KINEMATIC couplings so far and their generated rotation
    !> nodes: *BOUNDARY and *CLOAD on degrees of freedom 4-6 of such a reference node go to
    !> degrees of freedom 1-3 of its rotation node (CalculiX's rotations of the reference node).
    integer, allocatable :: coupling_refs(:), coupling_rots(:)
    logical :: in_step = .false.
    !> 0 for the model data, k while step k is read: conditions of one scope must agree.
    integer :: scope = 0
    !> Data lines that set conditions (`origin` of condition_list_t indexes them).
    type(source_loc_t), allocatable :: condition_lines(:)
    integer :: n_condition_lines = 0
    type(step_t) :: step
    !> Whether this step already applied OP=NEW to each list (only the first NEW clears).
    logical :: boundary_renewed = .false.
    logical :: loads_renewed = .false.
    logical :: pressures_renewed = .false.
    type(condition_list_t) :: boundary
    type(condition_list_t) :: loads
    type(pressure_list_t) :: pressures
    type(body_load_list_t) :: body_loads
    type(step_t), allocatable :: steps(:)
    !> *INITIAL CONDITIONS, TYPE=TEMPERATURE as read: node indices and values (later lines
    !> win), resolved into model%initial_temperature after the last card.
    integer, allocatable :: initial_temperature_node(:)
    real(dp), allocatable :: initial_temperature_value(:)
  end type builder_t

contains

  subroutine body_load_list_clear(this)
    class(body_load_list_t), intent(inout) :: this
    this%n = 0
    if (.not. allocated(this%items)) allocate (this%items(16))
    call this%slot%init(16)
  end subroutine body_load_list_clear

  !> Add `b`, replacing the body load of the same kind on the same element.
  subroutine body_load_list_put(this, b)
    class(body_load_list_t), intent(inout) :: this
    type(body_load_t), intent(in) :: b
    type(body_load_t), allocatable :: grown(:)
    integer :: key, k
    if (.not. allocated(this%items)) call this%clear()
    key = 2 * (b%element - 1) + b%kind
    k = this%slot%get(key)
    if (k == 0) then
      if (this%n == size(this%items)) then
        allocate (grown(2 * size(this%items)))
        grown(1:this%n) = this%items(1:this%n)
        call move_alloc(grown, this%items)
      end if
      this%n = this%n + 1
      k = this%n
      call this%slot%set(key, k)
    end if
    this%items(k) = b
  end subroutine body_load_list_put

  subroutine condition_list_clear(this)
    class(condition_list_t), intent(inout) :: this
    this%n = 0
    if (.not. allocated(this%items)) allocate (this%items(64), this%scope(64), this%origin(64))
    call this%slot%init(64)
  end subroutine condition_list_clear

  !> Add `c` (set in `scope` by data line `origin`), replacing an existing condition on the
  !> same (node, dof). `clash` is the origin of a different condition that the same scope
  !> already gave this degree of freedom (0: none).
  subroutine condition_list_put(this, c, scope, origin, clash)
    class(condition_list_t), intent(inout) :: this
    type(dof_condition_t), intent(in) :: c
    integer, intent(in) :: scope, origin
    integer, intent(out) :: clash
    integer :: key, k
    clash = 0
    if (.not. allocated(this%items)) call this%clear()
    key = 3 * (c%node - 1) + c%dof
    k = this%slot%get(key)
    if (k > 0) then
      if (this%scope(k) == scope .and. .not. same_condition(this%items(k), c)) clash = this%origin(k)
    else
      if (this%n == size(this%items)) call grow(this)
      this%n = this%n + 1
      k = this%n
      call this%slot%set(key, k)
    end if
    this%items(k) = c
    this%scope(k) = scope
    this%origin(k) = origin
  end subroutine condition_list_put

  subroutine grow(this)
    class(condition_list_t), intent(inout) :: this
    type(dof_condition_t), allocatable :: grown(:)
    integer, allocatable :: grown_int(:)
    integer :: capacity
    capacity = 2 * size(this%items)
    allocate (grown(capacity))
    grown(1:this%n) = this%items(1:this%n)
    call move_alloc(grown, this%items)
    allocate (grown_int(capacity))
    grown_int(1:this%n) = this%scope(1:this%n)
    call move_alloc(grown_int, this%scope)
    allocate (grown_int(capacity))
    grown_int(1:this%n) = this%origin(1:this%n)
    call move_alloc(grown_int, this%origin)
  end subroutine grow

  pure logical function same_condition(a, b)
    type(dof_condition_t), intent(in) :: a, b
    same_condition = a%kind == b%kind .and. a%value == b%value .and. a%amplitude == b%amplitude
  end function same_condition

  function condition_list_to_array(this) result(out)
    class(condition_list_t), intent(in) :: this
    type(dof_condition_t), allocatable :: out(:)
    if (allocated(this%items)) then
      out = this%items(1:this%n)
    else
      allocate (out(0))
    end if
  end function condition_list_to_array

  subroutine pressure_list_clear(this)
    class(pressure_list_t), intent(inout) :: this
    this%n = 0
    if (.not. allocated(this%items)) allocate (this%items(64))
    call this%slot%init(64)
  end subroutine pressure_list_clear

  !> Add `f`, replacing an existing pressure on the same face.
  subroutine pressure_list_put(this, f)
    class(pressure_list_t), intent(inout) :: this
    type(face_load_t), intent(in) :: f
    type(face_load_t), allocatable :: grown(:)
    integer :: key, k
    if (.not. allocated(this%items)) call this%clear()
    key = 6 * (f%element - 1) + f%face
    k = this%slot%get(key)
    if (k > 0) then
      this%items(k) = f
      return
    end if
    if (this%n == size(this%items)) then
      allocate (grown(2 * size(this%items)))
      grown(1:this%n) = this%items(1:this%n)
      call move_alloc(grown, this%items)
    end if
    this%n = this%n + 1
    this%items(this%n) = f
    call this%slot%set(key, this%n)
  end subroutine pressure_list_put

  function pressure_list_to_array(this) result(out)
    class(pressure_list_t), intent(in) :: this
    type(face_load_t), allocatable :: out(:)
    if (allocated(this%items)) then
      out = this%items(1:this%n)
    else
      allocate (out(0))
    end if
  end function pressure_list_to_array

end module fcs_builder_state
