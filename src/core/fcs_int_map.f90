!> A hash map from integer keys (user ids of nodes and elements) to integer values (indices),
!> with open addressing and linear probing. Grows automatically; keys may be any integer.
module fcs_int_map
  implicit none
  private
  public :: int_map_t

  integer, parameter :: EMPTY_SLOT = -huge(1)

  type :: int_map_t
    integer, allocatable :: keys(:)
    integer, allocatable :: values(:)
    integer :: count = 0
  contains
    procedure :: init => int_map_init
    procedure :: free => int_map_free
    procedure :: set => int_map_set
    procedure :: get => int_map_get
  end type int_map_t

contains

  !> Empty map sized for about `expected` keys.
  subroutine int_map_init(this, expected)
    class(int_map_t), intent(inout) :: this
    integer, intent(in) :: expected
    integer :: capacity
    call this%free()
    capacity = 64
    do while (capacity < 2 * max(expected, 1))
      capacity = capacity * 2
    end do
    allocate (this%keys(0:capacity - 1), this%values(0:capacity - 1))
    this%keys = EMPTY_SLOT
    this%values = 0
    this%count = 0
  end subroutine int_map_init

  subroutine int_map_free(this)
    class(int_map_t), intent(inout) :: this
    if (allocated(this%keys)) deallocate (this%keys)
    if (allocated(this%values)) deallocate (this%values)
    this%count = 0
  end subroutine int_map_free

  pure integer function slot_of(key, capacity) result(slot)
    integer, intent(in) :: key, capacity
    integer(kind=8) :: h
    h = int(key, 8) * 2654435761_8
    h = ieor(h, ishft(h, -16))
    slot = int(modulo(h, int(capacity, 8)))
  end function slot_of

  !> Insert or overwrite `key` -> `value`. `previous` returns the old value (0 if new).
  subroutine int_map_set(this, key, value, previous)
    class(int_map_t), intent(inout) :: this
    integer, intent(in) :: key, value
    integer, intent(out), optional :: previous
    integer :: old
    if (.not. allocated(this%keys)) call this%init(64)
    if (2 * (this%count + 1) > size(this%keys)) call grow(this)
    call insert(this, key, value, old)
    if (present(previous)) previous = old
  end subroutine int_map_set

  !> Insert or overwrite without growing (the table has a free slot); `previous` as in set.
  subroutine insert(this, key, value, previous)
    type(int_map_t), intent(inout) :: this
    integer, intent(in) :: key, value
    integer, intent(out) :: previous
    integer :: slot, capacity
    capacity = size(this%keys)
    slot = slot_of(key, capacity)
    do
      if (this%keys(slot) == EMPTY_SLOT) then
        this%keys(slot) = key
        this%values(slot) = value
        this%count = this%count + 1
        previous = 0
        return
      else if (this%keys(slot) == key) then
        previous = this%values(slot)
        this%values(slot) = value
        return
      end if
      slot = modulo(slot + 1, capacity)
    end do
  end subroutine insert

  !> Value stored for `key`, or 0 when absent.
  pure integer function int_map_get(this, key) result(value)
    class(int_map_t), intent(in) :: this
    integer, intent(in) :: key
    integer :: slot, capacity
    value = 0
    if (.not. allocated(this%keys)) return
    capacity = size(this%keys)
    slot = slot_of(key, capacity)
    do
      if (this%keys(slot) == EMPTY_SLOT) return
      if (this%keys(slot) == key) then
        value = this%values(slot)
        return
      end if
      slot = modulo(slot + 1, capacity)
    end do
  end function int_map_get

  subroutine grow(this)
    type(int_map_t), intent(inout) :: this
    integer, allocatable :: old_keys(:), old_values(:)
    integer :: i, previous
    call move_alloc(this%keys, old_keys)
    call move_alloc(this%values, old_values)
    call this%init(size(old_keys))
    do i = 0, size(old_keys) - 1
      if (old_keys(i) /= EMPTY_SLOT) call insert(this, old_keys(i), old_values(i), previous)
    end do
  end subroutine grow

end module fcs_int_map
