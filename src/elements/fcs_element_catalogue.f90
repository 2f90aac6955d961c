!> The catalogue of element kinds: the one source that the deck reader (*ELEMENT, TYPE=), the
!> gmsh reader, the keyword documentation and the messages read. Lookup is by CalculiX's type
!> name (case and surrounding blanks ignored); an unknown name is an input error listing the
!> valid names.
!>
!> Adding a kind (doc/architecture.md, "How to add an element kind"): write its definition
!> function (`kind_definition_t`: nodes, basis monomials, rule, faces, extrapolation,
!> formulation, gmsh order) in the module of its topology, add its name to
!> `ELEMENT_KIND_NAMES` and its case to `builtin_definition`. A kind can also be added at run
!> time with `add` (the unit test registers a test-only kind that way).
module fcs_element_catalogue
  use fcs_error, only: error_t, fatal_error, input_error
  use fcs_strings, only: to_upper
  use fcs_element_kind, only: element_kind_t, kind_definition_t, KERNEL_HEX8
  use fcs_hexahedra, only: c3d8_definition, c3d8r_definition, c3d8i_definition, &
    c3d20_definition, c3d20r_definition
  use fcs_tetrahedra, only: c3d4_definition, c3d10_definition
  use fcs_wedges, only: c3d6_definition, c3d15_definition
  implicit none
  private
  public :: element_catalogue_t, ELEMENT_KIND_NAMES, builtin_definition

  !> CalculiX names of the built-in kinds, in catalogue order (blank-padded: trim them).
  character(len=6), parameter :: ELEMENT_KIND_NAMES(9) = [character(len=6) :: &
    'C3D4', 'C3D6', 'C3D8', 'C3D8R', 'C3D8I', 'C3D10', 'C3D15', 'C3D20', 'C3D20R']

  !> The element kinds of a run, built once; element blocks refer to a kind by its index.
  type :: element_catalogue_t
    type(element_kind_t), allocatable :: kinds(:)
  contains
    procedure :: init => catalogue_init
    procedure :: free => catalogue_free
    procedure :: add => catalogue_add
    procedure :: size => catalogue_size
    procedure :: find => catalogue_find
    procedure :: lookup => catalogue_lookup
    procedure :: names => catalogue_names
    procedure :: find_gmsh => catalogue_find_gmsh
  end type element_catalogue_t

contains

  !> Definition of built-in kind `name` (one of ELEMENT_KIND_NAMES); `found` false otherwise.
  subroutine builtin_definition(name, def, found)
    character(len=*), intent(in) :: name
    type(kind_definition_t), intent(out) :: def
    logical, intent(out) :: found
    found = .true.
    select case (to_upper(trim(adjustl(name))))
    case ('C3D4')
      def = c3d4_definition()
    case ('C3D6')
      def = c3d6_definition()
    case ('C3D8')
      def = c3d8_definition()
    case ('C3D8R')
      def = c3d8r_definition()
    case ('C3D8I')
      def = c3d8i_definition()
    case ('C3D10')
      def = c3d10_definition()
    case ('C3D15')
      def = c3d15_definition()
    case ('C3D20')
      def = c3d20_definition()
    case ('C3D20R')
      def = c3d20r_definition()
    case default
      found = .false.
    end select
  end subroutine builtin_definition

  !> Build every built-in kind. A failure is an internal error (a kind's data is wrong).
  subroutine catalogue_init(this, err)
    class(element_catalogue_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    type(kind_definition_t) :: def
    logical :: found
    integer :: k
    call this%free()
    allocate (this%kinds(0))
    do k = 1, size(ELEMENT_KIND_NAMES)
      call builtin_definition(ELEMENT_KIND_NAMES(k), def, found)
      if (.not. found) then
        call fatal_error(err, 'element catalogue: no definition of ' // trim(ELEMENT_KIND_NAMES(k)))
        return
      end if
      call this%add(def, err)
      if (allocated(err)) return
      ! C3D8 runs on the hand-written kernels of the 8-node hexahedron (the same floating-point
      ! operations as before the element interface); every other kind on the tables.
      if (trim(ELEMENT_KIND_NAMES(k)) == 'C3D8') this%kinds(size(this%kinds))%kernel = KERNEL_HEX8
    end do
  end subroutine catalogue_init

  !> Forget every kind.
  subroutine catalogue_free(this)
    class(element_catalogue_t), intent(inout) :: this
    if (allocated(this%kinds)) deallocate (this%kinds)
  end subroutine catalogue_free

  !> Build the kind of `def` and append it. A name already in the catalogue is refused.
  subroutine catalogue_add(this, def, err)
    class(element_catalogue_t), intent(inout) :: this
    type(kind_definition_t), intent(in) :: def
    type(error_t), allocatable, intent(out) :: err
    type(element_kind_t), allocatable :: grown(:)
    integer :: n
    if (.not. allocated(this%kinds)) allocate (this%kinds(0))
    if (.not. allocated(def%name)) then
      call fatal_error(err, 'element catalogue: a kind without a name')
      return
    end if
    if (this%find(def%name) /= 0) then
      call fatal_error(err, 'element catalogue: kind ' // def%name // ' is already defined')
      return
    end if
    n = size(this%kinds)
    allocate (grown(n + 1))
    grown(1:n) = this%kinds
    call grown(n + 1)%init(def, err)
    if (allocated(err)) return
    call move_alloc(grown, this%kinds)
  end subroutine catalogue_add

  !> Number of kinds.
  pure integer function catalogue_size(this) result(n)
    class(element_catalogue_t), intent(in) :: this
    n = 0
    if (allocated(this%kinds)) n = size(this%kinds)
  end function catalogue_size

  !> Index of the kind called `name` (case and surrounding blanks ignored), 0 if none.
  pure integer function catalogue_find(this, name) result(index)
    class(element_catalogue_t), intent(in) :: this
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: wanted
    wanted = to_upper(trim(adjustl(name)))
    do index = 1, this%size()
      if (to_upper(this%kinds(index)%name) == wanted) return
    end do
    index = 0
  end function catalogue_find

  !> Index of the kind called `name`, or an input error 'unknown element type "X"; expected
  !> one of C3D4, C3D6, ...' (the caller adds the deck location).
  subroutine catalogue_lookup(this, name, index, err)
    class(element_catalogue_t), intent(in) :: this
    character(len=*), intent(in) :: name
    integer, intent(out) :: index
    type(error_t), allocatable, intent(out) :: err
    index = this%find(name)
    if (index == 0) call input_error(err, 'unknown element type "' // trim(adjustl(name)) // &
                                     '"; expected one of ' // this%names())
  end subroutine catalogue_lookup

  !> The kinds' names separated by commas, in catalogue order.
  pure function catalogue_names(this) result(text)
    class(element_catalogue_t), intent(in) :: this
    character(len=:), allocatable :: text
    integer :: k
    text = ''
    do k = 1, this%size()
      if (k > 1) text = text // ', '
      text = text // this%kinds(k)%name
    end do
  end function catalogue_names

  !> Index of the first kind (in catalogue order) read from gmsh element type `gmsh_type`
  !> (4 -> C3D4, 5 -> C3D8, 6 -> C3D6, 11 -> C3D10, 17 -> C3D20, 18 -> C3D15), 0 if none. The
  !> other kinds of the same topology and node count share its `gmsh_order`.
  pure integer function catalogue_find_gmsh(this, gmsh_type) result(index)
    class(element_catalogue_t), intent(in) :: this
    integer, intent(in) :: gmsh_type
    do index = 1, this%size()
      if (this%kinds(index)%gmsh_type == gmsh_type) return
    end do
    index = 0
  end function catalogue_find_gmsh

end module fcs_element_catalogue
