!> The finite element mesh: nodes, elements of any kind (mixed), node and element sets,
!> surfaces.
!>
!> Nodes and elements carry the user's ids; everything else refers to them by index (1..n).
!> Each element has a kind, an index into the mesh's `kinds`: what the mesh knows of an element
!> kind - its name, its number of nodes and the local nodes of its faces S1..Sn - is data the
!> element layer gives it (fcs_element_loops, `mesh_kinds`); the mesh does not interpolate.
!> `connectivity` has as many rows as the largest element, shorter elements padded with 0.
!> `face_nodes(e, f)` returns the nodes of face f of element e, corners first, ordered so that
!> the right-hand rule gives the outward normal.
module fcs_mesh
  use fcs_kinds, only: dp
  use fcs_int_map, only: int_map_t
  use fcs_sort, only: unique_sorted
  implicit none
  private
  public :: mesh_t, mesh_kind_t, named_set_t, surface_t
  public :: SURFACE_FACES, SURFACE_NODES, merge_sorted_unique, MESH_MAX_FACES, MESH_MAX_FACE_NODES

  !> Surface kinds.
  integer, parameter :: SURFACE_FACES = 1, SURFACE_NODES = 2
  !> Most faces of an element kind and most nodes of a face.
  integer, parameter :: MESH_MAX_FACES = 6, MESH_MAX_FACE_NODES = 8

  !> What the mesh knows of an element kind (given by the element layer).
  type :: mesh_kind_t
    character(len=:), allocatable :: name
    integer :: n_nodes = 0
    !> gmsh MSH element type read as this kind (0: none), and gmsh_order(a): the position in
    !> gmsh's node list of the kind's node a (CalculiX order).
    integer :: gmsh_type = 0
    integer, allocatable :: gmsh_order(:)
    integer :: n_faces = 0
    !> face_size(f) nodes of face f: face_local(1:face_size(f), f), corners first, outward.
    integer :: face_size(MESH_MAX_FACES) = 0
    integer :: face_local(MESH_MAX_FACE_NODES, MESH_MAX_FACES) = 0
  end type mesh_kind_t

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
    !> The kind of each element (index into `kinds`), and the kinds.
    integer, allocatable :: element_kind(:)
    type(mesh_kind_t), allocatable :: kinds(:)
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
    procedure :: find_kind => mesh_find_kind
    procedure :: find_gmsh_kind => mesh_find_gmsh_kind
    procedure :: element_nodes => mesh_element_nodes
    procedure :: n_faces => mesh_n_faces
    procedure :: face_nodes => mesh_face_nodes
  end type mesh_t

contains

  !> Empty mesh whose elements may be of the given kinds.
  subroutine mesh_init(this, kinds)
    class(mesh_t), intent(inout) :: this
    type(mesh_kind_t), intent(in) :: kinds(:)
    call this%free()
    this%kinds = kinds
    allocate (this%node_id(1024), this%x(3, 1024))
    allocate (this%element_id(1024), this%connectivity(0, 1024), this%element_kind(1024))
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
    if (allocated(this%element_kind)) deallocate (this%element_kind)
    if (allocated(this%kinds)) deallocate (this%kinds)
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

  !> Add element `id` of kind `kind` (index into `kinds`) with node indices `nodes` (as many
  !> as the kind has). `duplicate` is true if the id exists.
  subroutine mesh_add_element(this, id, nodes, duplicate, kind)
    class(mesh_t), intent(inout) :: this
    integer, intent(in) :: id
    integer, intent(in) :: nodes(:)
    logical, intent(out) :: duplicate
    integer, intent(in) :: kind
    integer, allocatable :: ids(:), conn(:, :), kinds(:)
    integer :: rows, capacity
    duplicate = this%element_map%get(id) /= 0
    if (duplicate) return
    rows = max(size(this%connectivity, 1), size(nodes))
    capacity = size(this%element_id)
    if (this%n_elements == capacity) capacity = 2 * capacity
    if (rows > size(this%connectivity, 1) .or. capacity > size(this%element_id)) then
      allocate (ids(capacity), conn(rows, capacity), kinds(capacity))
      conn = 0
      ids(1:this%n_elements) = this%element_id(1:this%n_elements)
      conn(1:size(this%connectivity, 1), 1:this%n_elements) = this%connectivity(:, 1:this%n_elements)
      kinds(1:this%n_elements) = this%element_kind(1:this%n_elements)
      call move_alloc(ids, this%element_id)
      call move_alloc(conn, this%connectivity)
      call move_alloc(kinds, this%element_kind)
    end if
    this%n_elements = this%n_elements + 1
    this%element_id(this%n_elements) = id
    this%connectivity(:, this%n_elements) = 0
    this%connectivity(1:size(nodes), this%n_elements) = nodes
    this%element_kind(this%n_elements) = kind
    call this%element_map%set(id, this%n_elements)
  end subroutine mesh_add_element

  !> Index of the kind called `name`, 0 if none.
  pure integer function mesh_find_kind(this, name) result(k)
    class(mesh_t), intent(in) :: this
    character(len=*), intent(in) :: name
    do k = 1, size(this%kinds)
      if (this%kinds(k)%name == name) return
    end do
    k = 0
  end function mesh_find_kind

  !> Index of the first kind read from gmsh element type `gmsh_type`, 0 if none.
  pure integer function mesh_find_gmsh_kind(this, gmsh_type) result(k)
    class(mesh_t), intent(in) :: this
    integer, intent(in) :: gmsh_type
    do k = 1, size(this%kinds)
      if (this%kinds(k)%gmsh_type == gmsh_type) return
    end do
    k = 0
  end function mesh_find_gmsh_kind

  !> Node indices of element e (as many as its kind has).
  pure function mesh_element_nodes(this, e) result(nodes)
    class(mesh_t), intent(in) :: this
    integer, intent(in) :: e
    integer, allocatable :: nodes(:)
    nodes = this%connectivity(1:this%kinds(this%element_kind(e))%n_nodes, e)
  end function mesh_element_nodes

  !> Number of faces of element e.
  pure integer function mesh_n_faces(this, e) result(n)
    class(mesh_t), intent(in) :: this
    integer, intent(in) :: e
    n = this%kinds(this%element_kind(e))%n_faces
  end function mesh_n_faces

  !> Global node indices of face f of element e, corners first, outward by the right-hand rule.
  pure function mesh_face_nodes(this, e, f) result(nodes)
    class(mesh_t), intent(in) :: this
    integer, intent(in) :: e, f
    integer, allocatable :: nodes(:)
    associate (kind => this%kinds(this%element_kind(e)))
      nodes = this%connectivity(kind%face_local(1:kind%face_size(f), f), e)
    end associate
  end function mesh_face_nodes

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

  !> Index of surface `name`, 0 if none. A name may be both a node-based and an element-face
  !> surface (CalculiX keeps the two apart: *SURFACE, TYPE=NODE and TYPE=ELEMENT of the same
  !> name); `prefer` (SURFACE_NODES or SURFACE_FACES) picks that one when both exist, else the
  !> first defined is returned.
  pure integer function mesh_find_surface(this, name, prefer) result(k)
    class(mesh_t), intent(in) :: this
    character(len=*), intent(in) :: name
    integer, intent(in), optional :: prefer
    integer :: first
    first = 0
    do k = 1, size(this%surfaces)
      if (this%surfaces(k)%name /= name) cycle
      if (.not. present(prefer)) return
      if (this%surfaces(k)%kind == prefer) return
      if (first == 0) first = k
    end do
    k = first
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

  !> Add element faces to the element-face surface `name` (created if needed; a node-based
  !> surface of the same name is another surface).
  subroutine mesh_add_faces_to_surface(this, name, elements, faces)
    class(mesh_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer, intent(in) :: elements(:), faces(:)
    integer :: k
    k = surface_slot(this, name, SURFACE_FACES)
    this%surfaces(k)%element = [this%surfaces(k)%element, elements]
    this%surfaces(k)%face = [this%surfaces(k)%face, faces]
  end subroutine mesh_add_faces_to_surface

  !> Add nodes to the node-based surface `name` (created if needed; an element-face surface of
  !> the same name is another surface).
  subroutine mesh_add_nodes_to_surface(this, name, nodes)
    class(mesh_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer, intent(in) :: nodes(:)
    integer :: k
    k = surface_slot(this, name, SURFACE_NODES)
    this%surfaces(k)%nodes = merge_sorted_unique(this%surfaces(k)%nodes, nodes)
  end subroutine mesh_add_nodes_to_surface

  integer function surface_slot(this, name, kind) result(k)
    class(mesh_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer, intent(in) :: kind
    type(surface_t), allocatable :: grown(:)
    k = this%find_surface(name, kind)
    if (k > 0) then
      if (this%surfaces(k)%kind == kind) return
    end if
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
    integer :: f, n, used
    if (this%surfaces(k)%kind == SURFACE_NODES) then
      nodes = this%surfaces(k)%nodes
      return
    end if
    n = size(this%surfaces(k)%element)
    allocate (all(MESH_MAX_FACE_NODES * n))
    used = 0
    do f = 1, n
      associate (face => this%face_nodes(this%surfaces(k)%element(f), this%surfaces(k)%face(f)))
        all(used + 1:used + size(face)) = face
        used = used + size(face)
      end associate
    end do
    allocate (nodes(0))
    nodes = merge_sorted_unique(nodes, all(1:used))
  end function mesh_surface_node_list

  !> Trim the growable arrays to their used size (connectivity to the rows of the largest
  !> element).
  subroutine mesh_compact(this)
    class(mesh_t), intent(inout) :: this
    integer :: rows
    rows = 0
    if (this%n_elements > 0) rows = maxval(this%kinds(this%element_kind(1:this%n_elements))%n_nodes)
    this%node_id = this%node_id(1:this%n_nodes)
    this%x = this%x(:, 1:this%n_nodes)
    this%element_id = this%element_id(1:this%n_elements)
    this%connectivity = this%connectivity(1:rows, 1:this%n_elements)
    this%element_kind = this%element_kind(1:this%n_elements)
  end subroutine mesh_compact

  !> Sorted union of a sorted unique list and arbitrary extra values.
  pure function merge_sorted_unique(sorted, extra) result(out)
    integer, intent(in) :: sorted(:), extra(:)
    integer, allocatable :: out(:)
    out = unique_sorted([sorted, extra])
  end function merge_sorted_unique

end module fcs_mesh
