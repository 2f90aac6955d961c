!> The finite element mesh: nodes, 8-node hexahedra, node and element sets, surfaces.
!>
!> Nodes and elements carry the user's ids; everything else refers to them by index (1..n).
!> Face numbering of the hexahedron follows Abaqus/CalculiX (S1..S6); `hex8_face_nodes`
!> returns a face's nodes ordered so that the right-hand rule gives the outward normal.
module fcs_mesh
  use fcs_kinds, only: dp
  use fcs_int_map, only: int_map_t
  use fcs_sort, only: unique_sorted
  implicit none
  private
  public :: mesh_t, named_set_t, surface_t, hex8_face_nodes, hex8_face_local, HEX8_FACE_LOCAL_NODES
  public :: SURFACE_FACES, SURFACE_NODES, merge_sorted_unique

  !> Surface kinds.
  integer, parameter :: SURFACE_FACES = 1, SURFACE_NODES = 2

  !> Local node numbers of faces S1..S6 (columns), ordered so that the right-hand rule gives the
  !> outward normal. The node sets are those of the Abaqus/CalculiX C3D8 faces
  !> (S1: 1-2-3-4, S2: 5-8-7-6, S3: 1-5-6-2, S4: 2-6-7-3, S5: 3-7-8-4, S6: 4-8-5-1).
  integer, parameter :: HEX8_FACE_LOCAL_NODES(4, 6) = reshape([ &
    1, 4, 3, 2, &
    5, 6, 7, 8, &
    1, 2, 6, 5, &
    2, 3, 7, 6, &
    3, 4, 8, 7, &
    4, 1, 5, 8], [4, 6])

  !> A named set of node or element indices, sorted and unique.
  type :: named_set_t
    character(len=:), allocatable :: name
    integer, allocatable :: members(:)
  end type named_set_t

  !> A named surface: element faces (element index, face 1..6) or, node based, a node list.
  type :: surface_t
    character(len=:), allocatable :: name
    integer :: kind = SURFACE_FACES
    integer, allocatable :: element(:)
    integer, allocatable :: face(:)
    integer, allocatable :: nodes(:)
  end type surface_t

  !> The mesh. Coordinates are the reference (initial) ones, in the deck's length unit.
  type :: mesh_t
    integer :: n_nodes = 0
    integer, allocatable :: node_id(:)
    real(dp), allocatable :: x(:, :)
    integer :: n_elements = 0
    integer, allocatable :: element_id(:)
    integer, allocatable :: connectivity(:, :)
    type(named_set_t), allocatable :: node_sets(:)
    type(named_set_t), allocatable :: element_sets(:)
    type(surface_t), allocatable :: surfaces(:)
    type(int_map_t) :: node_map
    type(int_map_t) :: element_map
  contains
    procedure :: init => mesh_init
    procedure :: free => mesh_free
    procedure :: add_node => mesh_add_node
    procedure :: add_element => mesh_add_element
    procedure :: node_index => mesh_node_index
    procedure :: element_index => mesh_element_index
    procedure :: find_node_set => mesh_find_node_set
    procedure :: find_element_set => mesh_find_element_set
    procedure :: find_surface => mesh_find_surface
    procedure :: add_to_node_set => mesh_add_to_node_set
    procedure :: add_to_element_set => mesh_add_to_element_set
    procedure :: add_faces_to_surface => mesh_add_faces_to_surface
    procedure :: add_nodes_to_surface => mesh_add_nodes_to_surface
    procedure :: surface_node_list => mesh_surface_node_list
    procedure :: compact => mesh_compact
  end type mesh_t

contains

  !> Empty mesh.
  subroutine mesh_init(this)
    class(mesh_t), intent(inout) :: this
    call this%free()
    allocate (this%node_id(1024), this%x(3, 1024))
    allocate (this%element_id(1024), this%connectivity(8, 1024))
    allocate (this%node_sets(0), this%element_sets(0), this%surfaces(0))
    call this%node_map%init(1024)
    call this%element_map%init(1024)
  end subroutine mesh_init

  !> Release everything.
  subroutine mesh_free(this)
    class(mesh_t), intent(inout) :: this
    this%n_nodes = 0
    this%n_elements = 0
    if (allocated(this%node_id)) deallocate (this%node_id)
    if (allocated(this%x)) deallocate (this%x)
    if (allocated(this%element_id)) deallocate (this%element_id)
    if (allocated(this%connectivity)) deallocate (this%connectivity)
    if (allocated(this%node_sets)) deallocate (this%node_sets)
    if (allocated(this%element_sets)) deallocate (this%element_sets)
    if (allocated(this%surfaces)) deallocate (this%surfaces)
    call this%node_map%free()
    call this%element_map%free()
  end subroutine mesh_free

  !> Add node `id` at `x`. `duplicate` is true (and nothing changes) if the id exists.
  subroutine mesh_add_node(this, id, x, duplicate)
    class(mesh_t), intent(inout) :: this
    integer, intent(in) :: id
    real(dp), intent(in) :: x(3)
    logical, intent(out) :: duplicate
    integer, allocatable :: ids(:)
    real(dp), allocatable :: coords(:, :)
    duplicate = this%node_map%get(id) /= 0
    if (duplicate) return
    if (this%n_nodes == size(this%node_id)) then
      allocate (ids(2 * size(this%node_id)), coords(3, 2 * size(this%node_id)))
      ids(1:this%n_nodes) = this%node_id(1:this%n_nodes)
      coords(:, 1:this%n_nodes) = this%x(:, 1:this%n_nodes)
      call move_alloc(ids, this%node_id)
      call move_alloc(coords, this%x)
    end if
    this%n_nodes = this%n_nodes + 1
    this%node_id(this%n_nodes) = id
    this%x(:, this%n_nodes) = x
    call this%node_map%set(id, this%n_nodes)
  end subroutine mesh_add_node

  !> Add element `id` with node indices `nodes(8)`. `duplicate` is true if the id exists.
  subroutine mesh_add_element(this, id, nodes, duplicate)
    class(mesh_t), intent(inout) :: this
    integer, intent(in) :: id
    integer, intent(in) :: nodes(8)
    logical, intent(out) :: duplicate
    integer, allocatable :: ids(:), conn(:, :)
    duplicate = this%element_map%get(id) /= 0
    if (duplicate) return
    if (this%n_elements == size(this%element_id)) then
      allocate (ids(2 * size(this%element_id)), conn(8, 2 * size(this%element_id)))
      ids(1:this%n_elements) = this%element_id(1:this%n_elements)
      conn(:, 1:this%n_elements) = this%connectivity(:, 1:this%n_elements)
      call move_alloc(ids, this%element_id)
      call move_alloc(conn, this%connectivity)
    end if
    this%n_elements = this%n_elements + 1
    this%element_id(this%n_elements) = id
    this%connectivity(:, this%n_elements) = nodes
    call this%element_map%set(id, this%n_elements)
  end subroutine mesh_add_element

  !> Index of node `id`, 0 if undefined.
  pure integer function mesh_node_index(this, id)
    class(mesh_t), intent(in) :: this
    integer, intent(in) :: id
    mesh_node_index = this%node_map%get(id)
  end function mesh_node_index

  !> Index of element `id`, 0 if undefined.
  pure integer function mesh_element_index(this, id)
    class(mesh_t), intent(in) :: this
    integer, intent(in) :: id
    mesh_element_index = this%element_map%get(id)
  end function mesh_element_index

  !> Index of the node set called `name` (upper case), 0 if none.
  pure integer function mesh_find_node_set(this, name) result(k)
    class(mesh_t), intent(in) :: this
    character(len=*), intent(in) :: name
    do k = 1, size(this%node_sets)
      if (this%node_sets(k)%name == name) return
    end do
    k = 0
  end function mesh_find_node_set

  pure integer function mesh_find_element_set(this, name) result(k)
    class(mesh_t), intent(in) :: this
    character(len=*), intent(in) :: name
    do k = 1, size(this%element_sets)
      if (this%element_sets(k)%name == name) return
    end do
    k = 0
  end function mesh_find_element_set

  pure integer function mesh_find_surface(this, name) result(k)
    class(mesh_t), intent(in) :: this
    character(len=*), intent(in) :: name
    do k = 1, size(this%surfaces)
      if (this%surfaces(k)%name == name) return
    end do
    k = 0
  end function mesh_find_surface

  !> Add node indices to set `name`, creating it if needed (repeated definitions accumulate).
  subroutine mesh_add_to_node_set(this, name, members)
    class(mesh_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer, intent(in) :: members(:)
    call add_to_sets(this%node_sets, name, members)
  end subroutine mesh_add_to_node_set

  subroutine mesh_add_to_element_set(this, name, members)
    class(mesh_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer, intent(in) :: members(:)
    call add_to_sets(this%element_sets, name, members)
  end subroutine mesh_add_to_element_set

  subroutine add_to_sets(sets, name, members)
    type(named_set_t), allocatable, intent(inout) :: sets(:)
    character(len=*), intent(in) :: name
    integer, intent(in) :: members(:)
    type(named_set_t), allocatable :: grown(:)
    integer :: k
    do k = 1, size(sets)
      if (sets(k)%name == name) then
        sets(k)%members = merge_sorted_unique(sets(k)%members, members)
        return
      end if
    end do
    allocate (grown(size(sets) + 1))
    grown(1:size(sets)) = sets
    grown(size(grown))%name = name
    allocate (grown(size(grown))%members(0))
    grown(size(grown))%members = merge_sorted_unique(grown(size(grown))%members, members)
    call move_alloc(grown, sets)
  end subroutine add_to_sets

  !> Add element faces to surface `name` (element-face kind). `kind_clash` if the surface
  !> exists and is node based.
  subroutine mesh_add_faces_to_surface(this, name, elements, faces, kind_clash)
    class(mesh_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer, intent(in) :: elements(:), faces(:)
    logical, intent(out) :: kind_clash
    integer :: k
    k = surface_slot(this, name, SURFACE_FACES)
    kind_clash = this%surfaces(k)%kind /= SURFACE_FACES
    if (kind_clash) return
    this%surfaces(k)%element = [this%surfaces(k)%element, elements]
    this%surfaces(k)%face = [this%surfaces(k)%face, faces]
  end subroutine mesh_add_faces_to_surface

  !> Add nodes to a node-based surface `name`.
  subroutine mesh_add_nodes_to_surface(this, name, nodes, kind_clash)
    class(mesh_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer, intent(in) :: nodes(:)
    logical, intent(out) :: kind_clash
    integer :: k
    k = surface_slot(this, name, SURFACE_NODES)
    kind_clash = this%surfaces(k)%kind /= SURFACE_NODES
    if (kind_clash) return
    this%surfaces(k)%nodes = merge_sorted_unique(this%surfaces(k)%nodes, nodes)
  end subroutine mesh_add_nodes_to_surface

  integer function surface_slot(this, name, kind) result(k)
    class(mesh_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer, intent(in) :: kind
    type(surface_t), allocatable :: grown(:)
    k = this%find_surface(name)
    if (k > 0) return
    allocate (grown(size(this%surfaces) + 1))
    grown(1:size(this%surfaces)) = this%surfaces
    k = size(grown)
    grown(k)%name = name
    grown(k)%kind = kind
    allocate (grown(k)%element(0), grown(k)%face(0), grown(k)%nodes(0))
    call move_alloc(grown, this%surfaces)
  end function surface_slot

  !> All nodes of surface `k` (node list, or the nodes of its faces), sorted and unique.
  function mesh_surface_node_list(this, k) result(nodes)
    class(mesh_t), intent(in) :: this
    integer, intent(in) :: k
    integer, allocatable :: nodes(:)
    integer, allocatable :: all(:)
    integer :: f, n
    if (this%surfaces(k)%kind == SURFACE_NODES) then
      nodes = this%surfaces(k)%nodes
      return
    end if
    n = size(this%surfaces(k)%element)
    allocate (all(4 * n))
    do f = 1, n
      all(4 * f - 3:4 * f) = hex8_face_nodes(this, this%surfaces(k)%element(f), this%surfaces(k)%face(f))
    end do
    allocate (nodes(0))
    nodes = merge_sorted_unique(nodes, all)
  end function mesh_surface_node_list

  !> Trim the growable arrays to their used size.
  subroutine mesh_compact(this)
    class(mesh_t), intent(inout) :: this
    this%node_id = this%node_id(1:this%n_nodes)
    this%x = this%x(:, 1:this%n_nodes)
    this%element_id = this%element_id(1:this%n_elements)
    this%connectivity = this%connectivity(:, 1:this%n_elements)
  end subroutine mesh_compact

  !> Global node indices of face `face` (1..6) of element `element`, outward by right-hand rule.
  pure function hex8_face_nodes(mesh, element, face) result(nodes)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: element, face
    integer :: nodes(4)
    nodes = mesh%connectivity(HEX8_FACE_LOCAL_NODES(:, face), element)
  end function hex8_face_nodes

  !> Local node numbers (1..8) of face `face`.
  pure function hex8_face_local(face) result(local)
    integer, intent(in) :: face
    integer :: local(4)
    local = HEX8_FACE_LOCAL_NODES(:, face)
  end function hex8_face_local

  !> Sorted union of a sorted unique list and arbitrary extra values.
  pure function merge_sorted_unique(sorted, extra) result(out)
    integer, intent(in) :: sorted(:), extra(:)
    integer, allocatable :: out(:)
    out = unique_sorted([sorted, extra])
  end function merge_sorted_unique

end module fcs_mesh
