!> Reader of gmsh MSH 4.1 mesh files, text or binary, into `mesh_t`.
!>
!> Format: gmsh reference manual, section "MSH file format" (version 4.1),
!> https://gmsh.info/doc/texinfo/gmsh.html#MSH-file-format . Sections read: $MeshFormat,
!> $PhysicalNames, $Entities (the physical tags of each entity), $Nodes and $Elements (entity
!> blocks in any order, node tags possibly sparse, parametric coordinates skipped). Other
!> sections ($Periodic, $NodeData, $Comments, ...) are skipped; $PartitionedEntities is an error.
!> Binary files must be little-endian with 8-byte `size_t` (what gmsh writes on x86 and ARM).
!>
!> What becomes what:
!> - The 3D elements of the kinds fcs3d has become mesh elements with their gmsh tag as id:
!>   4-node tetrahedra (gmsh type 4), 8-node hexahedra (5), 6-node prisms (6), 10-node
!>   tetrahedra (11), 20-node hexahedra (17) and 15-node prisms (18), mixed in any way. Each
!>   becomes the mesh kind read from its gmsh type (`find_gmsh_kind`: the first catalogue kind
!>   of that type, C3D4, C3D8, C3D6, C3D10, C3D20, C3D15) unless the caller names another kind
!>   of the same gmsh type (`kinds`: C3D20R for type 17, say). The connectivity is permuted from
!>   gmsh's node order to CalculiX's with the kind's `gmsh_order` (gmsh manual, section "Node
!>   ordering", https://gmsh.info/doc/texinfo/gmsh.html#Node-ordering : the corners of all
!>   three shapes are in CalculiX's order, the mid-side nodes follow gmsh's edge lists; see
!>   fcs_tetrahedra, fcs_wedges, fcs_hexahedra). Node tags become node ids; only nodes used by
!>   what is read (elements, faces and node groups below) are added.
!> - If the file has physical volumes, only the elements of physical volumes are used (gmsh
!>   convention); otherwise every 3D element in the file is used. What gmsh saves (checked with
!>   gmsh 4.8.4): without any physical group, all elements; with physical groups, only the
!>   elements of physical groups, unless Mesh.SaveAll = 1 (gmsh -save_all). So once a .geo file
!>   defines physical surfaces, its meshed volumes must be in a physical volume too (or the
!>   mesh saved with Mesh.SaveAll = 1), else the file holds no elements to read.
!> - Physical groups become named sets. The name is the upper-cased physical name (blanks kept),
!>   or, for an unnamed group, <POINT|CURVE|SURFACE|VOLUME>_<tag>, e.g. "SURFACE_3".
!>   A volume group gives an element set of its elements and a node set of their nodes; a
!>   surface group gives an element-face surface and a node set of the nodes of its faces; a
!>   curve or point group gives a node set. Groups without elements give no set. Sets that
!>   already exist in the mesh under the same name are extended (the mesh convention for
!>   repeated definitions).
!> - 3-node triangles (type 2), 6-node triangles (9), 4-node quadrangles (3) and 8-node
!>   quadrangles (16) of surface groups are not elements: each is matched by its corner nodes
!>   to the element face S1..Sn with the same corners (fcs_face_match), giving (element, face);
!>   the mid-side nodes of a second-order face must be those of the element face. A face
!>   shared by two elements takes the face of the element out of which the surface element's
!>   own normal (right-hand rule) points.
!> - Points (15) and lines (1, and 3-node lines, 8) outside physical groups are ignored, and so
!>   is any other element type outside physical groups unless it is three-dimensional.
!>   Complete second-order elements (9-node quadrangles 10, 27-node hexahedra 12, 18-node
!>   prisms 13) are an error advising Mesh.SecondOrderIncomplete = 1 (gmsh then writes the
!>   8-, 20- and 15-node serendipity elements CalculiX has); pyramids, higher orders and any
!>   other type in a physical group, or three-dimensional, are an error.
!>
!> The Jacobians of the elements read are the caller's to check (fcs_model_checks,
!> `check_mesh_file_orientation`), with the line of each element in the file that `read_gmsh`
!> returns.
!>
!> Errors are input errors: "path:line: message" for text files, "path: $Section (byte N):
!> message" for binary ones, "path: message" for what concerns the whole file.
module fcs_gmsh_reader
  use, intrinsic :: iso_fortran_env, only: int32
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, input_error
  use fcs_strings, only: str, to_upper
  use fcs_int_map, only: int_map_t
  use fcs_mesh, only: mesh_t, MESH_MAX_FACE_NODES
  use fcs_face_match, only: match_faces, face_corner_count
  use fcs_gmsh_stream, only: msh_stream_t, is_finite_bits
  implicit none
  private
  public :: read_gmsh

  !> gmsh element types handled by name (manual, "MSH file format", elementType).
  integer, parameter :: GMSH_LINE = 1, GMSH_TRIANGLE = 2, GMSH_QUAD = 3, GMSH_LINE3 = 8, &
    GMSH_TRIANGLE6 = 9, GMSH_QUAD9 = 10, GMSH_HEXAHEDRON27 = 12, GMSH_PRISM18 = 13, &
    GMSH_POINT = 15, GMSH_QUAD8 = 16
  !> The 3D types read as elements (tetrahedra, hexahedra, prisms of first and second order)
  !> and the 2D types read as their faces.
  integer, parameter :: SOLID_TYPES(6) = [4, 5, 6, 11, 17, 18]
  integer, parameter :: FACE_TYPES(4) = [GMSH_TRIANGLE, GMSH_QUAD, GMSH_TRIANGLE6, GMSH_QUAD8]
  !> Most nodes of a solid and of a face read.
  integer, parameter :: MAX_SOLID_NODES = 20, MAX_FACE_NODES = 8
  !> Nodes and dimension of gmsh element types 1..31 (same source).
  integer, parameter :: TYPE_NODES(31) = [2, 3, 4, 4, 8, 6, 5, 3, 6, 9, 10, 27, 18, 14, 1, 8, &
    20, 15, 13, 9, 10, 12, 15, 15, 21, 4, 5, 6, 20, 35, 56]
  integer, parameter :: TYPE_DIMENSION(31) = [1, 2, 2, 3, 3, 3, 3, 1, 2, 2, 3, 3, 3, 3, 0, 2, &
    3, 3, 3, 2, 2, 2, 2, 2, 2, 1, 1, 1, 3, 3, 3]
  !> What is done with an element block.
  integer, parameter :: BLOCK_SKIP = 0, BLOCK_SOLIDS = 1, BLOCK_FACES = 2, BLOCK_NODES = 3
  !> Largest tag that fits a mesh id.
  integer(i8), parameter :: MAX_TAG = int(huge(1), i8)
  !> Elements per read in a binary element block (bounds the temporary buffer).
  integer, parameter :: BINARY_BATCH = 65536
  !> Fewest bytes a node, an entity and a block header take in text and binary files, used to
  !> reject announced counts that the file cannot hold before allocating for them.
  integer, parameter :: TEXT_NODE_BYTES = 8, BINARY_NODE_BYTES = 32
  integer, parameter :: TEXT_RECORD_BYTES = 8, BINARY_BLOCK_BYTES = 20, BINARY_ENTITY_BYTES = 36
  character(len=7), parameter :: DIMENSION_NAME(0:3) = [character(len=7) :: 'POINT', 'CURVE', &
    'SURFACE', 'VOLUME']
  character(len=*), parameter :: KINDS_READ = 'fcs3d reads 4- and 10-node tetrahedra, 6- and &
    &15-node prisms and 8- and 20-node hexahedra (C3D4, C3D10, C3D6, C3D15, C3D8, C3D20), with &
    &3-, 6-node triangles and 4-, 8-node quadrangles as their faces'
  character(len=*), parameter :: ORDER_ADVICE = 'For second order, mesh with &
    &Mesh.ElementOrder = 2 and Mesh.SecondOrderIncomplete = 1 (gmsh -order 2 -setnumber &
    &Mesh.SecondOrderIncomplete 1): gmsh then writes the 8-node quadrangles, 20-node hexahedra &
    &and 15-node prisms CalculiX has.'

  !> A physical group: dimension, tag and the name of the sets it gives.
  type :: physical_group_t
    integer :: dim = 0
    integer :: tag = 0
    logical :: named = .false.
    character(len=:), allocatable :: name
  end type physical_group_t

  !> A geometrical entity and the physical groups (indices) it belongs to.
  type :: entity_t
    integer :: dim = 0
    integer :: tag = 0
    integer, allocatable :: groups(:)
  end type entity_t

  !> Elements kept from the file: tags, gmsh types, nodes (file node numbers 1..n_nodes, gmsh
  !> order, padded with 0 to `width`), the line each was read from (0 in binary files), and the
  !> blocks (entity, first, last) they came in. Nodes of points and lines are kept one per
  !> record (width 1).
  type :: element_store_t
    integer :: width = 0
    integer :: n = 0
    integer, allocatable :: tag(:)
    integer, allocatable :: gmsh_type(:)
    integer, allocatable :: nodes(:, :)
    integer, allocatable :: line(:)
    integer :: n_blocks = 0
    integer, allocatable :: block_entity(:), block_first(:), block_last(:)
  end type element_store_t

  !> Node tag -> file node number: a dense array over [min_tag, max_tag] when the tags are
  !> nearly contiguous, a hash map otherwise.
  type :: node_lookup_t
    logical :: use_map = .false.
    integer :: min_tag = 0
    integer, allocatable :: dense(:)
    type(int_map_t) :: map
  end type node_lookup_t

  !> Everything read from the file before it is added to the mesh.
  type :: msh_content_t
    type(physical_group_t), allocatable :: groups(:)
    integer :: n_groups = 0
    type(entity_t), allocatable :: entities(:)
    integer :: n_entities = 0
    type(int_map_t) :: entity_map(0:3)
    logical :: seen_entities = .false.
    logical :: seen_nodes = .false.
    logical :: seen_elements = .false.
    integer :: n_nodes = 0
    integer, allocatable :: node_tag(:)
    real(dp), allocatable :: node_x(:, :)
    type(node_lookup_t) :: lookup
    type(element_store_t) :: solids
    type(element_store_t) :: faces
    type(element_store_t) :: loose_nodes
  end type msh_content_t

  !> Where each face of a surface group lies: element (mesh index) and face S1..Sn.
  type :: face_matches_t
    integer, allocatable :: element(:)
    integer, allocatable :: face(:)
  end type face_matches_t

contains

  !> Read the gmsh MSH 4.1 file `path` (text or binary) into `mesh`, which must be initialised
  !> and may already hold nodes, elements and sets (ids must not clash with the file's tags).
  !> The whole file is read and checked before the mesh is touched, except for id clashes and
  !> faces on no element face: after such an error the mesh holds part of the file.
  subroutine read_gmsh(path, mesh, err, element_lines, kinds)
    character(len=*), intent(in) :: path
    type(mesh_t), intent(inout) :: mesh
    type(error_t), allocatable, intent(out) :: err
    !> For each element added (in mesh order), its line in the file (0 in a binary file).
    integer, allocatable, intent(out), optional :: element_lines(:)
    !> Mesh kinds (indices into mesh%kinds) that the elements of their gmsh types become,
    !> instead of the first kind of that type (C3D20R for 20-node hexahedra, say).
    integer, intent(in), optional :: kinds(:)
    type(msh_stream_t) :: stream
    type(msh_content_t) :: content
    call stream%open(path, err)
    if (allocated(err)) return
    call read_content(stream, content, err)
    call stream%close()
    if (allocated(err)) return
    if (present(kinds)) then
      call build_mesh(path, content, kinds, mesh, err)
    else
      call build_mesh(path, content, [integer ::], mesh, err)
    end if
    if (present(element_lines)) element_lines = content%solids%line(1:content%solids%n)
  end subroutine read_gmsh

  ! ------------------------------------------------------------------------------------------
  ! Sections
  ! ------------------------------------------------------------------------------------------

  !> Read the whole file into `content`, section by section.
  subroutine read_content(stream, content, err)
    type(msh_stream_t), intent(inout) :: stream
    type(msh_content_t), intent(inout) :: content
    type(error_t), allocatable, intent(out) :: err
    logical :: found
    character(len=:), allocatable :: name
    allocate (content%groups(8), content%entities(64))
    call init_store(content%solids, MAX_SOLID_NODES)
    call init_store(content%faces, MAX_FACE_NODES)
    call init_store(content%loose_nodes, 1)
    call read_mesh_format(stream, err)
    if (allocated(err)) return
    do
      call next_nonblank(stream, found)
      if (.not. found) exit
      name = stream%token(1)
      if (name(1:1) /= '$' .or. stream%n_tokens /= 1) then
        call stream%fail(err, 'expected a section header such as $Nodes, found "' // &
          clip(stream%line(1:stream%line_length)) // '"')
        return
      end if
      stream%section = name
      call read_section(stream, content, name, err)
      if (allocated(err)) return
      stream%section = ''
    end do
    if (.not. content%seen_nodes) then
      call input_error(err, stream%path // ': no $Nodes section: the file is truncated or holds no &
        &mesh (mesh with gmsh -3)')
    else if (.not. content%seen_elements) then
      call input_error(err, stream%path // ': no $Elements section: the file is truncated or holds no &
        &mesh (mesh with gmsh -3)')
    end if
  end subroutine read_content

  !> Read the section whose header `name` ("$Nodes") was just read, up to its end line.
  subroutine read_section(stream, content, name, err)
    type(msh_stream_t), intent(inout) :: stream
    type(msh_content_t), intent(inout) :: content
    character(len=*), intent(in) :: name
    type(error_t), allocatable, intent(out) :: err
    select case (name)
    case ('$PhysicalNames')
      call read_physical_names(stream, content, err)
    case ('$Entities')
      call read_entities(stream, content, err)
    case ('$Nodes')
      call read_nodes(stream, content, err)
    case ('$Elements')
      call read_elements(stream, content, err)
    case ('$PartitionedEntities')
      call stream%fail(err, 'partitioned .msh files are not supported; write the mesh &
        &unpartitioned (gmsh -part 0, Mesh.NbPartitions = 0)')
    case ('$MeshFormat')
      call stream%fail(err, 'repeated $MeshFormat section')
    case default
      if (len(name) >= 4) then
        if (name(1:4) == '$End') then
          call stream%fail(err, name // ' without a section to end')
          return
        end if
      end if
      call skip_section(stream, name(2:), err)
      return
    end select
    if (allocated(err)) return
    call expect_end(stream, name(2:), err)
  end subroutine read_section

  !> $MeshFormat: only version 4.1; binary files must be little-endian with 8-byte size_t.
  subroutine read_mesh_format(stream, err)
    type(msh_stream_t), intent(inout) :: stream
    type(error_t), allocatable, intent(out) :: err
    logical :: found, ok
    real(dp) :: version
    integer(i8) :: file_type, data_size
    integer :: one
    call next_nonblank(stream, found)
    if (.not. found) then
      call input_error(err, stream%path // ': the file is empty, not a gmsh mesh')
      return
    end if
    if (stream%token(1) == '$NOD' .or. stream%token(1) == '$NOE') then
      call stream%fail(err, 'MSH version 1 is not supported: save as MSH 4.1 (gmsh -format msh41)')
      return
    else if (stream%token(1) /= '$MeshFormat') then
      call stream%fail(err, 'not a gmsh mesh file: expected $MeshFormat, found "' // &
        clip(stream%line(1:stream%line_length)) // '"')
      return
    end if
    stream%section = '$MeshFormat'
    call stream%next_line(found)
    call stream%get_real(1, version, ok)
    if (ok) call stream%get_int(2, file_type, ok)
    if (ok) call stream%get_int(3, data_size, ok)
    if (.not. found .or. .not. ok .or. stream%n_tokens /= 3) then
      call stream%fail(err, 'expected "version file-type data-size" such as "4.1 0 8", found "' // &
        clip(stream%line(1:stream%line_length)) // '"')
      return
    end if
    if (abs(version - 4.1_dp) > 1.0e-9_dp) then
      call stream%fail(err, 'version ' // stream%token(1) // ' is not supported: save as MSH 4.1 &
        &(gmsh -format msh41)')
      return
    end if
    if (file_type /= 0 .and. file_type /= 1) then
      call stream%fail(err, 'file type ' // str(file_type) // ' is neither 0 (text) nor 1 (binary)')
      return
    end if
    if (file_type == 1) then
      stream%binary = .true.
      if (data_size /= 8) then
        call stream%fail(err, 'binary files with ' // str(data_size) // '-byte size_t are not &
          &supported (expected 8); write the file on a 64-bit machine or as text')
        return
      end if
      call stream%read_int32(one, ok)
      if (.not. ok) then
        call stream%fail(err, 'unexpected end of file in $MeshFormat')
      else if (one == 16777216) then
        call stream%fail(err, 'big-endian binary file: write it on a little-endian machine or as text')
      else if (one /= 1) then
        call stream%fail(err, 'corrupt binary header: expected the integer 1, found ' // str(one))
      end if
      if (allocated(err)) return
    end if
    call expect_end(stream, 'MeshFormat', err)
    stream%section = ''
  end subroutine read_mesh_format

  !> Skip section `name` (without "$") up to its "$End" line.
  subroutine skip_section(stream, name, err)
    type(msh_stream_t), intent(inout) :: stream
    character(len=*), intent(in) :: name
    type(error_t), allocatable, intent(out) :: err
    logical :: found
    do
      call stream%next_line(found)
      if (.not. found) then
        call stream%fail(err, 'unexpected end of file: $End' // name // ' is missing (the file is &
          &truncated)')
        return
      end if
      if (stream%n_tokens >= 1) then
        if (stream%token(1) == '$End' // name) return
      end if
    end do
  end subroutine skip_section

  !> Expect the line "$End<name>" (blank lines, such as the end of a binary line, are skipped).
  subroutine expect_end(stream, name, err)
    type(msh_stream_t), intent(inout) :: stream
    character(len=*), intent(in) :: name
    type(error_t), allocatable, intent(out) :: err
    logical :: found
    call next_nonblank(stream, found)
    if (.not. found) then
      call stream%fail(err, 'unexpected end of file: $End' // name // ' is missing (the file is &
          &truncated)')
    else if (stream%token(1) /= '$End' // name .or. stream%n_tokens /= 1) then
      call stream%fail(err, 'expected $End' // name // ', found "' // &
        clip(stream%line(1:stream%line_length)) // '" (the section holds more or other data &
        &than its header announces)')
    end if
  end subroutine expect_end

  !> Next line with at least one token; `found` is false at the end of the file.
  subroutine next_nonblank(stream, found)
    type(msh_stream_t), intent(inout) :: stream
    logical, intent(out) :: found
    do
      call stream%next_line(found)
      if (.not. found) return
      if (stream%n_tokens > 0) return
    end do
  end subroutine next_nonblank

  !> Next line, which must hold exactly `size(values)` integers (`what` describes them).
  subroutine read_int_line(stream, values, what, err)
    type(msh_stream_t), intent(inout) :: stream
    integer(i8), intent(out) :: values(:)
    character(len=*), intent(in) :: what
    type(error_t), allocatable, intent(out) :: err
    logical :: found, ok
    integer :: i
    values = 0
    call stream%next_line(found)
    ok = found .and. stream%n_tokens == size(values)
    do i = 1, size(values)
      if (ok) call stream%get_int(i, values(i), ok)
    end do
    if (.not. ok) call fail_line(stream, found, what, err)
  end subroutine read_int_line

  !> Error for a text line that does not hold `what` (or for the end of the file, if not `found`).
  subroutine fail_line(stream, found, what, err)
    type(msh_stream_t), intent(in) :: stream
    logical, intent(in) :: found
    character(len=*), intent(in) :: what
    type(error_t), allocatable, intent(out) :: err
    if (found) then
      call stream%fail(err, 'expected ' // what // ', found "' // clip(stream%line(1:stream%line_length)) // '"')
    else
      call stream%fail(err, 'unexpected end of file in ' // stream%section // ' (expected ' // what // &
        '): the file is truncated')
    end if
  end subroutine fail_line

  !> The next header record of `size(values)` integers, as a text line or, in binary files,
  !> `n_int` 4-byte integers followed by 8-byte sizes.
  subroutine read_header(stream, values, n_int, what, err)
    type(msh_stream_t), intent(inout) :: stream
    integer(i8), intent(out) :: values(:)
    integer, intent(in) :: n_int
    character(len=*), intent(in) :: what
    type(error_t), allocatable, intent(out) :: err
    integer(int32) :: ints(n_int)
    integer(i8) :: sizes(size(values) - n_int, 1)
    logical :: ok
    if (.not. stream%binary) then
      call read_int_line(stream, values, what, err)
      return
    end if
    call stream%read_int32_array(ints, ok)
    if (ok) call stream%read_size_array(sizes, ok)
    values = [int(ints, i8), sizes(:, 1)]
    if (.not. ok) call stream%fail(err, 'unexpected end of file (expected ' // what // ')')
  end subroutine read_header

  !> Check that `value` is a count in 0..huge and that `value * min_bytes` bytes remain.
  subroutine check_count(stream, value, min_bytes, what, err)
    type(msh_stream_t), intent(in) :: stream
    integer(i8), intent(in) :: value
    integer, intent(in) :: min_bytes
    character(len=*), intent(in) :: what
    type(error_t), allocatable, intent(out) :: err
    if (value < 0 .or. value > MAX_TAG) then
      call stream%fail(err, 'invalid number of ' // what // ': ' // str(value))
    else if (value > stream%remaining() / max(min_bytes, 1)) then
      call stream%fail(err, 'the file is truncated or corrupt: ' // str(value) // ' ' // what // &
        ' announced but only ' // str(stream%remaining()) // ' bytes remain')
    end if
  end subroutine check_count

  !> Check that a tag is a valid id (1..huge).
  subroutine check_tag(stream, value, what, err)
    type(msh_stream_t), intent(in) :: stream
    integer(i8), intent(in) :: value
    character(len=*), intent(in) :: what
    type(error_t), allocatable, intent(out) :: err
    if (value < 1 .or. value > MAX_TAG) call stream%fail(err, what // ' tag ' // str(value) // &
      ' is out of the supported range 1..' // str(MAX_TAG))
  end subroutine check_tag

  ! ------------------------------------------------------------------------------------------
  ! $PhysicalNames and $Entities
  ! ------------------------------------------------------------------------------------------

  !> $PhysicalNames (text even in binary files): dimension, tag, "name" per line.
  subroutine read_physical_names(stream, content, err)
    type(msh_stream_t), intent(inout) :: stream
    type(msh_content_t), intent(inout) :: content
    type(error_t), allocatable, intent(out) :: err
    integer(i8) :: count(1), dim, tag
    integer :: i, first, last, g
    logical :: found, ok
    call read_int_line(stream, count, 'the number of physical names', err)
    if (allocated(err)) return
    call check_count(stream, count(1), TEXT_RECORD_BYTES, 'physical names', err)
    if (allocated(err)) return
    do i = 1, int(count(1))
      call stream%next_line(found)
      if (.not. found) then
        call stream%fail(err, 'unexpected end of file in $PhysicalNames')
        return
      end if
      call stream%get_int(1, dim, ok)
      if (ok) call stream%get_int(2, tag, ok)
      first = index(stream%line(1:stream%line_length), '"')
      last = index(stream%line(1:stream%line_length), '"', back=.true.)
      if (.not. ok .or. dim < 0 .or. dim > 3 .or. abs(tag) > MAX_TAG .or. last <= first) then
        call stream%fail(err, 'expected: dimension (0 to 3) tag "name", found "' // &
          clip(stream%line(1:stream%line_length)) // '"')
        return
      end if
      call find_or_add_group(content, int(dim), int(tag), g)
      if (content%groups(g)%named) then
        call stream%fail(err, 'physical ' // group_label(content%groups(g)) // ' is named twice')
        return
      end if
      content%groups(g)%named = .true.
      if (len_trim(stream%line(first + 1:last - 1)) > 0) &
        content%groups(g)%name = to_upper(trim(adjustl(stream%line(first + 1:last - 1))))
    end do
  end subroutine read_physical_names

  !> $Entities: per point, curve, surface and volume, its tag and physical tags.
  subroutine read_entities(stream, content, err)
    type(msh_stream_t), intent(inout) :: stream
    type(msh_content_t), intent(inout) :: content
    type(error_t), allocatable, intent(out) :: err
    integer(i8) :: counts(4)
    integer :: dim, i, tag
    integer, allocatable :: physical(:)
    if (content%seen_entities .or. content%seen_elements) then
      call stream%fail(err, 'repeated $Entities section, or one after $Elements')
      return
    end if
    call read_header(stream, counts, 0, 'the numbers of points, curves, surfaces and volumes', err)
    if (allocated(err)) return
    do dim = 0, 3
      call check_count(stream, counts(dim + 1), merge(BINARY_ENTITY_BYTES, TEXT_RECORD_BYTES, &
        stream%binary), 'entities', err)
      if (allocated(err)) return
    end do
    do dim = 0, 3
      do i = 1, int(counts(dim + 1))
        if (stream%binary) then
          call read_entity_binary(stream, dim, tag, physical, err)
        else
          call read_entity_text(stream, dim, tag, physical, err)
        end if
        if (allocated(err)) return
        call add_entity(content, dim, tag, physical)
      end do
    end do
    content%seen_entities = .true.
  end subroutine read_entities

  !> One entity line: tag, 3 (points) or 6 (bounding box) reals, number of physical tags, the
  !> tags, then bounding entities (ignored).
  subroutine read_entity_text(stream, dim, tag, physical, err)
    type(msh_stream_t), intent(inout) :: stream
    integer, intent(in) :: dim
    integer, intent(out) :: tag
    integer, allocatable, intent(out) :: physical(:)
    type(error_t), allocatable, intent(out) :: err
    integer(i8) :: value, count
    integer :: first, j
    logical :: found, ok
    tag = 0
    allocate (physical(0))
    call stream%next_line(found)
    if (.not. found) then
      call stream%fail(err, 'unexpected end of file in $Entities')
      return
    end if
    first = merge(5, 8, dim == 0)
    call stream%get_int(1, value, ok)
    if (ok) call stream%get_int(first, count, ok)
    if (ok) ok = value >= 1 .and. value <= MAX_TAG .and. count >= 0 .and. &
      count <= stream%n_tokens - first
    if (.not. ok) then
      call stream%fail(err, 'expected the ' // trim(to_lower_word(dim)) // &
        ' tag, coordinates and physical tags, found "' // clip(stream%line(1:stream%line_length)) // '"')
      return
    end if
    tag = int(value)
    deallocate (physical)
    allocate (physical(count))
    do j = 1, int(count)
      call stream%get_int(first + j, value, ok)
      if (.not. ok .or. abs(value) > MAX_TAG) then
        call stream%fail(err, 'bad physical tag "' // stream%token(first + j) // '"')
        return
      end if
      physical(j) = int(value)
    end do
  end subroutine read_entity_text

  !> One binary entity: int tag, 3 or 6 doubles, size_t n, n ints (physical tags), and for
  !> curves, surfaces and volumes size_t m, m ints (bounding entities, skipped).
  subroutine read_entity_binary(stream, dim, tag, physical, err)
    type(msh_stream_t), intent(inout) :: stream
    integer, intent(in) :: dim
    integer, intent(out) :: tag
    integer, allocatable, intent(out) :: physical(:)
    type(error_t), allocatable, intent(out) :: err
    integer(i8) :: count, n_bounding
    integer(int32), allocatable :: buffer(:)
    logical :: ok
    allocate (physical(0))
    call stream%read_int32(tag, ok)
    if (ok) call stream%skip_bytes(merge(24_i8, 48_i8, dim == 0), ok)
    if (ok) call stream%read_size(count, ok)
    if (ok) ok = count <= stream%remaining() / 4
    if (ok) then
      allocate (buffer(count))
      call stream%read_int32_array(buffer, ok)
      physical = int(buffer)
    end if
    if (ok .and. dim > 0) then
      call stream%read_size(n_bounding, ok)
      if (ok) ok = n_bounding <= stream%remaining() / 4
      if (ok) call stream%skip_bytes(4_i8 * n_bounding, ok)
    end if
    if (.not. ok) call stream%fail(err, 'unexpected end of file or corrupt data in $Entities')
  end subroutine read_entity_binary

  !> Record entity (dim, tag) with physical tags `physical`.
  subroutine add_entity(content, dim, tag, physical)
    type(msh_content_t), intent(inout) :: content
    integer, intent(in) :: dim, tag
    integer, intent(in) :: physical(:)
    type(entity_t), allocatable :: grown(:)
    integer, allocatable :: groups(:)
    integer :: j, g
    allocate (groups(0))
    do j = 1, size(physical)
      call find_or_add_group(content, dim, physical(j), g)
      if (.not. any(groups == g)) groups = [groups, g]
    end do
    if (content%n_entities == size(content%entities)) then
      allocate (grown(2 * size(content%entities)))
      grown(1:content%n_entities) = content%entities(1:content%n_entities)
      call move_alloc(grown, content%entities)
    end if
    content%n_entities = content%n_entities + 1
    content%entities(content%n_entities)%dim = dim
    content%entities(content%n_entities)%tag = tag
    call move_alloc(groups, content%entities(content%n_entities)%groups)
    call content%entity_map(dim)%set(tag, content%n_entities)
  end subroutine add_entity

  !> Index `g` of physical group (dim, tag), created (with its default name) if new.
  subroutine find_or_add_group(content, dim, tag, g)
    type(msh_content_t), intent(inout) :: content
    integer, intent(in) :: dim, tag
    integer, intent(out) :: g
    type(physical_group_t), allocatable :: grown(:)
    do g = 1, content%n_groups
      if (content%groups(g)%dim == dim .and. content%groups(g)%tag == tag) return
    end do
    if (content%n_groups == size(content%groups)) then
      allocate (grown(2 * size(content%groups)))
      grown(1:content%n_groups) = content%groups(1:content%n_groups)
      call move_alloc(grown, content%groups)
    end if
    content%n_groups = content%n_groups + 1
    g = content%n_groups
    content%groups(g)%dim = dim
    content%groups(g)%tag = tag
    content%groups(g)%name = trim(DIMENSION_NAME(dim)) // '_' // str(tag)
  end subroutine find_or_add_group

  !> Index of entity (dim, tag), 0 if the file did not list it.
  integer function entity_index(content, dim, tag)
    type(msh_content_t), intent(in) :: content
    integer(i8), intent(in) :: dim, tag
    entity_index = 0
    if (dim < 0 .or. dim > 3 .or. abs(tag) > MAX_TAG) return
    entity_index = content%entity_map(dim)%get(int(tag))
  end function entity_index

  !> "surface 3 "FIXED"" or "surface 3" for an unnamed group, for messages.
  function group_label(group) result(label)
    type(physical_group_t), intent(in) :: group
    character(len=:), allocatable :: label
    label = trim(to_lower_word(group%dim)) // ' ' // str(group%tag)
    if (group%named) label = label // ' "' // group%name // '"'
  end function group_label

  !> "point", "curve", "surface" or "volume".
  pure function to_lower_word(dim) result(word)
    integer, intent(in) :: dim
    character(len=7) :: word
    integer :: i
    word = DIMENSION_NAME(dim)
    do i = 1, len_trim(word)
      word(i:i) = achar(iachar(word(i:i)) + 32)
    end do
  end function to_lower_word

  ! ------------------------------------------------------------------------------------------
  ! $Nodes
  ! ------------------------------------------------------------------------------------------

  !> $Nodes: header (blocks, nodes, min and max tag), then per entity block its tags and
  !> coordinates.
  subroutine read_nodes(stream, content, err)
    type(msh_stream_t), intent(inout) :: stream
    type(msh_content_t), intent(inout) :: content
    type(error_t), allocatable, intent(out) :: err
    integer(i8) :: header(4), block(4)
    integer :: b, count, n_coordinates
    if (content%seen_nodes) then
      call stream%fail(err, 'repeated $Nodes section (several meshes in one file are not supported)')
      return
    end if
    call read_header(stream, header, 0, 'the node header "blocks nodes min-tag max-tag"', err)
    if (.not. allocated(err)) call check_count(stream, header(1), merge(BINARY_BLOCK_BYTES, &
      TEXT_RECORD_BYTES, stream%binary), 'node blocks', err)
    if (.not. allocated(err)) call check_count(stream, header(2), merge(BINARY_NODE_BYTES, &
      TEXT_NODE_BYTES, stream%binary), 'nodes', err)
    if (allocated(err)) return
    content%n_nodes = int(header(2))
    allocate (content%node_tag(content%n_nodes), content%node_x(3, content%n_nodes))
    count = 0
    do b = 1, int(header(1))
      call read_header(stream, block, 3, 'the block header "dimension entity parametric nodes"', err)
      if (allocated(err)) return
      if (block(1) < 0 .or. block(1) > 3 .or. block(3) < 0 .or. block(3) > 1 .or. block(4) < 0 &
          .or. block(4) > content%n_nodes - count) then
        call stream%fail(err, 'bad node block header (dimension ' // str(block(1)) // ', parametric ' &
          // str(block(3)) // ', ' // str(block(4)) // ' nodes; the header announced ' // &
          str(content%n_nodes) // ' nodes in all)')
        return
      end if
      n_coordinates = 3 + int(block(1) * block(3))
      if (stream%binary) then
        call read_node_block_binary(stream, content, count, int(block(4)), n_coordinates, err)
      else
        call read_node_block_text(stream, content, count, int(block(4)), n_coordinates, err)
      end if
      if (allocated(err)) return
      count = count + int(block(4))
    end do
    if (count /= content%n_nodes) then
      call stream%fail(err, 'the $Nodes header announces ' // str(content%n_nodes) // &
        ' nodes but the blocks hold ' // str(count))
      return
    end if
    call build_node_lookup(stream, content, err)
    content%seen_nodes = .true.
  end subroutine read_nodes

  !> A text node block: `n` lines of one tag, then `n` lines of coordinates.
  subroutine read_node_block_text(stream, content, offset, n, n_coordinates, err)
    type(msh_stream_t), intent(inout) :: stream
    type(msh_content_t), intent(inout) :: content
    integer, intent(in) :: offset, n, n_coordinates
    type(error_t), allocatable, intent(out) :: err
    integer(i8) :: tag
    integer :: i, j
    logical :: found, ok
    do i = 1, n
      call stream%next_line(found)
      ok = found .and. stream%n_tokens == 1
      if (ok) call stream%get_int(1, tag, ok)
      if (.not. ok) then
        call fail_line(stream, found, 'a node tag', err)
        return
      end if
      call check_tag(stream, tag, 'node', err)
      if (allocated(err)) return
      content%node_tag(offset + i) = int(tag)
    end do
    do i = 1, n
      call stream%next_line(found)
      ok = found .and. stream%n_tokens == n_coordinates
      do j = 1, 3
        if (ok) call stream%get_real(j, content%node_x(j, offset + i), ok)
      end do
      if (.not. ok) then
        call fail_line(stream, found, str(n_coordinates) // ' coordinates of node ' // &
          str(content%node_tag(offset + i)), err)
        return
      end if
    end do
  end subroutine read_node_block_text

  !> A binary node block: `n` size_t tags, then `n` times `n_coordinates` doubles.
  subroutine read_node_block_binary(stream, content, offset, n, n_coordinates, err)
    type(msh_stream_t), intent(inout) :: stream
    type(msh_content_t), intent(inout) :: content
    integer, intent(in) :: offset, n, n_coordinates
    type(error_t), allocatable, intent(out) :: err
    integer(i8), allocatable :: tags(:, :)
    real(dp), allocatable :: coordinates(:, :)
    integer :: i
    logical :: ok
    if (8_i8 * n * (1 + n_coordinates) > stream%remaining()) then
      call stream%fail(err, 'the file is truncated: a block of ' // str(n) // ' nodes does not fit')
      return
    end if
    allocate (tags(1, n), coordinates(n_coordinates, n))
    call stream%read_size_array(tags, ok)
    if (ok) call stream%read_real_array(coordinates, ok)
    if (.not. ok) then
      call stream%fail(err, 'unexpected end of file in a node block')
      return
    end if
    do i = 1, n
      call check_tag(stream, tags(1, i), 'node', err)
      if (allocated(err)) return
      if (.not. all(is_finite_bits(coordinates(1:3, i)))) then
        call stream%fail(err, 'node ' // str(tags(1, i)) // ' has a coordinate that is not a finite number')
        return
      end if
      content%node_tag(offset + i) = int(tags(1, i))
      content%node_x(:, offset + i) = coordinates(1:3, i)
    end do
  end subroutine read_node_block_binary

  !> Build the node tag -> file node number lookup; a repeated tag is an error.
  subroutine build_node_lookup(stream, content, err)
    type(msh_stream_t), intent(in) :: stream
    type(msh_content_t), intent(inout) :: content
    type(error_t), allocatable, intent(out) :: err
    integer :: i, k, previous, max_tag
    associate (lookup => content%lookup, n => content%n_nodes)
      if (n == 0) then
        allocate (lookup%dense(0))
        return
      end if
      lookup%min_tag = minval(content%node_tag(1:n))
      max_tag = maxval(content%node_tag(1:n))
      lookup%use_map = int(max_tag, i8) - lookup%min_tag + 1 > 4_i8 * n + 1024
      if (lookup%use_map) then
        call lookup%map%init(n)
      else
        allocate (lookup%dense(max_tag - lookup%min_tag + 1))
        lookup%dense = 0
      end if
      do i = 1, n
        if (lookup%use_map) then
          call lookup%map%set(content%node_tag(i), i, previous)
        else
          k = content%node_tag(i) - lookup%min_tag + 1
          previous = lookup%dense(k)
          lookup%dense(k) = i
        end if
        if (previous /= 0) then
          call input_error(err, stream%path // ': $Nodes: node tag ' // str(content%node_tag(i)) // &
            ' appears twice')
          return
        end if
      end do
    end associate
  end subroutine build_node_lookup

  !> File node number of node `tag`, 0 if the file has no such node.
  pure integer function node_number(lookup, tag)
    type(node_lookup_t), intent(in) :: lookup
    integer(i8), intent(in) :: tag
    integer(i8) :: k
    node_number = 0
    if (lookup%use_map) then
      if (tag >= 1 .and. tag <= MAX_TAG) node_number = lookup%map%get(int(tag))
    else
      k = tag - lookup%min_tag + 1
      if (k >= 1 .and. k <= size(lookup%dense, kind=i8)) node_number = lookup%dense(k)
    end if
  end function node_number

  ! ------------------------------------------------------------------------------------------
  ! $Elements
  ! ------------------------------------------------------------------------------------------

  !> $Elements: header (blocks, elements, min and max tag), then entity blocks of one type.
  subroutine read_elements(stream, content, err)
    type(msh_stream_t), intent(inout) :: stream
    type(msh_content_t), intent(inout) :: content
    type(error_t), allocatable, intent(out) :: err
    integer(i8) :: header(4), block(4), total
    integer :: b, kind, entity, n_per
    logical :: volume_groups
    if (content%seen_elements .or. .not. content%seen_nodes) then
      call stream%fail(err, 'repeated $Elements section, or one before $Nodes')
      return
    end if
    call read_header(stream, header, 0, 'the element header "blocks elements min-tag max-tag"', err)
    if (.not. allocated(err)) call check_count(stream, header(1), merge(BINARY_BLOCK_BYTES, &
      TEXT_RECORD_BYTES, stream%binary), 'element blocks', err)
    if (allocated(err)) return
    volume_groups = .false.
    do b = 1, content%n_entities
      if (content%entities(b)%dim == 3) volume_groups = volume_groups .or. &
        size(content%entities(b)%groups) > 0
    end do
    total = 0
    do b = 1, int(header(1))
      call read_header(stream, block, 3, 'the block header "dimension entity type elements"', err)
      if (allocated(err)) return
      entity = entity_index(content, block(1), block(2))
      call classify_block(stream, content, block, entity, volume_groups, kind, err)
      if (allocated(err)) return
      n_per = 0
      if (block(3) >= 1 .and. block(3) <= size(TYPE_NODES)) n_per = TYPE_NODES(block(3))
      if (block(3) == 92) n_per = 64
      if (block(3) == 93) n_per = 125
      if (n_per == 0 .and. stream%binary) then
        call stream%fail(err, 'unknown element type ' // str(block(3)) // ': cannot skip it in a binary file')
        return
      end if
      call check_count(stream, block(4), merge(8, 2, stream%binary) * (1 + n_per), 'elements', err)
      if (allocated(err)) return
      call read_element_block(stream, content, kind, entity, int(block(3)), n_per, int(block(4)), err)
      if (allocated(err)) return
      total = total + block(4)
    end do
    if (total /= header(2)) then
      call stream%fail(err, 'the $Elements header announces ' // str(header(2)) // &
        ' elements but the blocks hold ' // str(total))
      return
    end if
    content%seen_elements = .true.
  end subroutine read_elements

  !> Decide what to do with an element block (dimension, entity tag, type, count): keep its
  !> solids, faces or nodes, skip it, or reject an unsupported element type.
  subroutine classify_block(stream, content, block, entity, volume_groups, kind, err)
    type(msh_stream_t), intent(in) :: stream
    type(msh_content_t), intent(in) :: content
    integer(i8), intent(in) :: block(4)
    integer, intent(in) :: entity
    logical, intent(in) :: volume_groups
    integer, intent(out) :: kind
    type(error_t), allocatable, intent(out) :: err
    logical :: grouped
    integer :: element_dimension
    character(len=:), allocatable :: where, advice
    grouped = .false.
    if (entity > 0) grouped = size(content%entities(entity)%groups) > 0
    kind = BLOCK_SKIP
    if (any(SOLID_TYPES == block(3))) then
      if (grouped .or. .not. volume_groups) kind = BLOCK_SOLIDS
      return
    else if (any(FACE_TYPES == block(3))) then
      if (grouped) kind = BLOCK_FACES
      return
    else if (block(3) == GMSH_LINE .or. block(3) == GMSH_LINE3 .or. block(3) == GMSH_POINT) then
      if (grouped) kind = BLOCK_NODES
      return
    end if
    element_dimension = int(block(1))
    if (block(3) >= 1 .and. block(3) <= size(TYPE_DIMENSION)) element_dimension = TYPE_DIMENSION(block(3))
    if (block(3) == 92 .or. block(3) == 93) element_dimension = 3
    if (.not. (grouped .or. element_dimension == 3 .or. block(1) == 3)) return
    where = trim(to_lower_word(int(max(0_i8, min(3_i8, block(1)))))) // ' ' // str(block(2))
    if (grouped) where = 'physical ' // group_label(content%groups(content%entities(entity)%groups(1)))
    select case (block(3))
    case (GMSH_QUAD9, GMSH_HEXAHEDRON27, GMSH_PRISM18)
      advice = 'complete second-order elements are not supported (CalculiX has none). ' // ORDER_ADVICE
    case (7, 14, 19)
      advice = 'fcs3d has no pyramid element (CalculiX has none); mesh the volume with &
        &tetrahedra only, or with hexahedra and prisms (Extrude, Transfinite, Recombine).'
    case default
      advice = KINDS_READ // '. ' // ORDER_ADVICE
    end select
    call stream%fail(err, type_name(block(3)) // ' elements (gmsh element type ' // str(block(3)) // &
      ') in ' // where // ': ' // advice)
  end subroutine classify_block

  !> Name of a gmsh element type, for messages.
  function type_name(element_type) result(name)
    integer(i8), intent(in) :: element_type
    character(len=:), allocatable :: name
    select case (element_type)
    case (1)
      name = '2-node line'
    case (2)
      name = '3-node triangle'
    case (3)
      name = '4-node quadrangle'
    case (4)
      name = '4-node tetrahedron'
    case (6)
      name = '6-node prism'
    case (7)
      name = '5-node pyramid'
    case (8)
      name = '3-node line (second order)'
    case (9)
      name = '6-node triangle (second order)'
    case (10)
      name = '9-node quadrangle (second order)'
    case (11)
      name = '10-node tetrahedron (second order)'
    case (12)
      name = '27-node hexahedron (second order)'
    case (13)
      name = '18-node prism (second order)'
    case (14)
      name = '14-node pyramid (second order)'
    case (16)
      name = '8-node quadrangle (second order)'
    case (17)
      name = '20-node hexahedron (second order)'
    case (18)
      name = '15-node prism (second order)'
    case (19)
      name = '13-node pyramid (second order)'
    case default
      name = 'Higher-order or unknown'
    end select
  end function type_name

  !> Read (or skip) the `n` elements of a block of `n_per`-node elements of gmsh type
  !> `element_type`.
  subroutine read_element_block(stream, content, kind, entity, element_type, n_per, n, err)
    type(msh_stream_t), intent(inout) :: stream
    type(msh_content_t), intent(inout) :: content
    integer, intent(in) :: kind, entity, element_type, n_per, n
    type(error_t), allocatable, intent(out) :: err
    integer :: i
    logical :: found
    select case (kind)
    case (BLOCK_SOLIDS)
      call read_block_into(stream, content%lookup, content%solids, entity, element_type, n_per, n, err)
    case (BLOCK_FACES)
      call read_block_into(stream, content%lookup, content%faces, entity, element_type, n_per, n, err)
    case (BLOCK_NODES)
      call read_block_into(stream, content%lookup, content%loose_nodes, entity, element_type, n_per, n, err)
    case default
      if (stream%binary) then
        call stream%skip_bytes(8_i8 * n * (1 + n_per), found)
        if (.not. found) call stream%fail(err, 'unexpected end of file in an element block')
      else
        do i = 1, n
          call stream%next_line(found)
          if (.not. found) then
            call stream%fail(err, 'unexpected end of file in an element block')
            return
          end if
        end do
      end if
    end select
  end subroutine read_element_block

  !> Read `n` elements of `n_per` nodes and gmsh type `element_type` into `store` (as one
  !> block of `entity`).
  subroutine read_block_into(stream, lookup, store, entity, element_type, n_per, n, err)
    type(msh_stream_t), intent(inout) :: stream
    type(node_lookup_t), intent(in) :: lookup
    type(element_store_t), intent(inout) :: store
    integer, intent(in) :: entity, element_type, n_per, n
    type(error_t), allocatable, intent(out) :: err
    integer(i8), allocatable :: records(:, :)
    integer :: done, m, e, j
    logical :: ok, found
    call store_begin_block(store, entity, n * merge(n_per, 1, store%width == 1))
    allocate (records(1 + n_per, min(n, merge(BINARY_BATCH, 1, stream%binary))))
    done = 0
    do while (done < n)
      m = min(size(records, 2), n - done)
      if (stream%binary) then
        call stream%read_size_array(records(:, 1:m), ok)
        if (.not. ok) then
          call stream%fail(err, 'unexpected end of file in an element block')
          return
        end if
      else
        call stream%next_line(found)
        ok = found .and. stream%n_tokens == 1 + n_per
        do j = 1, 1 + n_per
          if (ok) call stream%get_int(j, records(j, 1), ok)
        end do
        if (.not. ok) then
          call fail_line(stream, found, 'an element tag and its ' // str(n_per) // ' node tags', err)
          return
        end if
      end if
      do e = 1, m
        call store_element(stream, lookup, store, element_type, records(:, e), err)
        if (allocated(err)) return
      end do
      done = done + m
    end do
    store%block_last(store%n_blocks) = store%n
  end subroutine read_block_into

  !> Append one element (tag, node tags) of gmsh type `element_type` to `store`, translating
  !> node tags to file node numbers: one record, or one per node in a store of width 1.
  subroutine store_element(stream, lookup, store, element_type, record, err)
    type(msh_stream_t), intent(in) :: stream
    type(node_lookup_t), intent(in) :: lookup
    type(element_store_t), intent(inout) :: store
    integer, intent(in) :: element_type
    integer(i8), intent(in) :: record(:)
    type(error_t), allocatable, intent(out) :: err
    integer :: nodes(size(record) - 1), j, line
    call check_tag(stream, record(1), 'element', err)
    if (allocated(err)) return
    do j = 1, size(nodes)
      nodes(j) = node_number(lookup, record(1 + j))
      if (nodes(j) == 0) then
        call stream%fail(err, 'element ' // str(record(1)) // ' refers to node ' // str(record(1 + j)) // &
          ', which is not in $Nodes')
        return
      end if
    end do
    line = 0
    if (.not. stream%binary) line = stream%line_number
    if (store%width == 1) then
      do j = 1, size(nodes)
        call append_record(store, int(record(1)), element_type, nodes(j:j), line)
      end do
    else
      call append_record(store, int(record(1)), element_type, nodes, line)
    end if
  end subroutine store_element

  !> Append one record to `store` (room made by store_begin_block).
  subroutine append_record(store, tag, element_type, nodes, line)
    type(element_store_t), intent(inout) :: store
    integer, intent(in) :: tag, element_type, nodes(:), line
    store%n = store%n + 1
    store%tag(store%n) = tag
    store%gmsh_type(store%n) = element_type
    store%nodes(:, store%n) = 0
    store%nodes(1:size(nodes), store%n) = nodes
    store%line(store%n) = line
  end subroutine append_record

  !> Empty store of records of `width` nodes.
  subroutine init_store(store, width)
    type(element_store_t), intent(out) :: store
    integer, intent(in) :: width
    store%width = width
    allocate (store%tag(0), store%gmsh_type(0), store%nodes(width, 0), store%line(0))
    allocate (store%block_entity(8), store%block_first(8), store%block_last(8))
  end subroutine init_store

  !> Open a new block of `entity` in `store` with room for `extra` more records.
  subroutine store_begin_block(store, entity, extra)
    type(element_store_t), intent(inout) :: store
    integer, intent(in) :: entity, extra
    integer, allocatable :: grown(:), grown_nodes(:, :)
    integer :: capacity
    if (store%n + extra > size(store%tag)) then
      capacity = max(store%n + extra, 2 * size(store%tag))
      allocate (grown(capacity))
      grown(1:store%n) = store%tag(1:store%n)
      call move_alloc(grown, store%tag)
      allocate (grown(capacity))
      grown(1:store%n) = store%gmsh_type(1:store%n)
      call move_alloc(grown, store%gmsh_type)
      allocate (grown(capacity))
      grown(1:store%n) = store%line(1:store%n)
      call move_alloc(grown, store%line)
      allocate (grown_nodes(store%width, capacity))
      grown_nodes(:, 1:store%n) = store%nodes(:, 1:store%n)
      call move_alloc(grown_nodes, store%nodes)
    end if
    if (store%n_blocks == size(store%block_entity)) then
      store%block_entity = [store%block_entity, store%block_entity]
      store%block_first = [store%block_first, store%block_first]
      store%block_last = [store%block_last, store%block_last]
    end if
    store%n_blocks = store%n_blocks + 1
    store%block_entity(store%n_blocks) = entity
    store%block_first(store%n_blocks) = store%n + 1
    store%block_last(store%n_blocks) = store%n
  end subroutine store_begin_block

  ! ------------------------------------------------------------------------------------------
  ! Into the mesh
  ! ------------------------------------------------------------------------------------------

  !> Add the nodes, elements and physical groups read from `path` to `mesh`; `kinds` are the
  !> mesh kinds chosen for their gmsh types (see read_gmsh).
  subroutine build_mesh(path, content, kinds, mesh, err)
    character(len=*), intent(in) :: path
    type(msh_content_t), intent(in) :: content
    integer, intent(in) :: kinds(:)
    type(mesh_t), intent(inout) :: mesh
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: node_index(:), element_index(:), kind_of_type(:)
    type(face_matches_t) :: matches
    if (content%solids%n == 0) then
      call input_error(err, path // ': no 3D elements to read (' // KINDS_READ // '). gmsh saves &
        &only the elements of physical groups when there are any: put the meshed volumes in a &
        &Physical Volume, or save all elements (Mesh.SaveAll = 1, gmsh -save_all).')
      return
    end if
    call choose_kinds(path, content, kinds, mesh, kind_of_type, err)
    if (allocated(err)) return
    call add_nodes(path, content, mesh, node_index, err)
    if (allocated(err)) return
    call add_solids(path, content, mesh, kind_of_type, node_index, element_index, err)
    if (allocated(err)) return
    call match_surface_faces(path, content, mesh, node_index, element_index, matches, err)
    if (allocated(err)) return
    call add_groups(path, content, mesh, node_index, element_index, matches, err)
  end subroutine build_mesh

  !> The mesh kind of each gmsh type of the solids read (kind_of_type(type), 0 for types not
  !> read): the kind of `kinds` with that gmsh type, else the mesh's first kind of the type.
  subroutine choose_kinds(path, content, kinds, mesh, kind_of_type, err)
    character(len=*), intent(in) :: path
    type(msh_content_t), intent(in) :: content
    integer, intent(in) :: kinds(:)
    type(mesh_t), intent(in) :: mesh
    integer, allocatable, intent(out) :: kind_of_type(:)
    type(error_t), allocatable, intent(out) :: err
    integer :: t, k
    allocate (kind_of_type(maxval(SOLID_TYPES)))
    kind_of_type = 0
    do t = 1, size(kind_of_type)
      if (.not. any(content%solids%gmsh_type(1:content%solids%n) == t)) cycle
      kind_of_type(t) = mesh%find_gmsh_kind(t)
      do k = 1, size(kinds)
        if (mesh%kinds(kinds(k))%gmsh_type == t) kind_of_type(t) = kinds(k)
      end do
      if (kind_of_type(t) == 0) then
        call input_error(err, path // ': the mesh has no element kind for ' // &
          type_name(int(t, i8)) // ' elements (gmsh type ' // str(t) // ')')
        return
      end if
      if (.not. allocated(mesh%kinds(kind_of_type(t))%gmsh_order)) then
        call input_error(err, path // ': element kind ' // mesh%kinds(kind_of_type(t))%name // &
          ' has no gmsh node order')
        return
      end if
    end do
  end subroutine choose_kinds

  !> Add the nodes used by the kept elements, in file order; `node_index` maps file node
  !> numbers to mesh indices (0 for nodes not added).
  subroutine add_nodes(path, content, mesh, node_index, err)
    character(len=*), intent(in) :: path
    type(msh_content_t), intent(in) :: content
    type(mesh_t), intent(inout) :: mesh
    integer, allocatable, intent(out) :: node_index(:)
    type(error_t), allocatable, intent(out) :: err
    logical, allocatable :: used(:)
    logical :: duplicate
    integer :: i
    allocate (used(content%n_nodes), node_index(content%n_nodes))
    used = .false.
    node_index = 0
    call mark_nodes(content%solids, 1, content%solids%n, used)
    call mark_nodes(content%faces, 1, content%faces%n, used)
    call mark_nodes(content%loose_nodes, 1, content%loose_nodes%n, used)
    do i = 1, content%n_nodes
      if (.not. used(i)) cycle
      call mesh%add_node(content%node_tag(i), content%node_x(:, i), duplicate)
      if (duplicate) then
        call input_error(err, path // ': node ' // str(content%node_tag(i)) // ' already exists in &
          &the mesh (node ids of a mesh file must differ from those defined before it)')
        return
      end if
      node_index(i) = mesh%n_nodes
    end do
  end subroutine add_nodes

  !> Mark the nodes of records first..last of `store` (padding zeros skipped).
  subroutine mark_nodes(store, first, last, used)
    type(element_store_t), intent(in) :: store
    integer, intent(in) :: first, last
    logical, intent(inout) :: used(:)
    integer :: k, j
    do k = first, last
      do j = 1, store%width
        if (store%nodes(j, k) > 0) used(store%nodes(j, k)) = .true.
      end do
    end do
  end subroutine mark_nodes

  !> Add the solids, their nodes permuted from gmsh's order to CalculiX's; `element_index` maps
  !> their position in the file's list to mesh indices.
  subroutine add_solids(path, content, mesh, kind_of_type, node_index, element_index, err)
    character(len=*), intent(in) :: path
    type(msh_content_t), intent(in) :: content
    type(mesh_t), intent(inout) :: mesh
    integer, intent(in) :: kind_of_type(:), node_index(:)
    integer, allocatable, intent(out) :: element_index(:)
    type(error_t), allocatable, intent(out) :: err
    integer :: k, n_before, kind
    logical :: duplicate
    n_before = mesh%n_elements
    allocate (element_index(content%solids%n))
    do k = 1, content%solids%n
      kind = kind_of_type(content%solids%gmsh_type(k))
      associate (order => mesh%kinds(kind)%gmsh_order)
        call mesh%add_element(content%solids%tag(k), node_index(content%solids%nodes(order, k)), &
                              duplicate, kind)
      end associate
      if (duplicate) then
        if (mesh%element_index(content%solids%tag(k)) > n_before) then
          call input_error(err, path // ': element ' // str(content%solids%tag(k)) // &
            ' appears twice in $Elements')
        else
          call input_error(err, path // ': element ' // str(content%solids%tag(k)) // ' already &
            &exists in the mesh (element ids of a mesh file must differ from those defined before it)')
        end if
        return
      end if
      element_index(k) = mesh%n_elements
    end do
  end subroutine add_solids

  !> Match every kept surface element to the element face with the same corners; one on no
  !> face (or, in a non-conforming mesh, on more than two), or whose mid-side nodes are not
  !> those of the element face, is an error.
  subroutine match_surface_faces(path, content, mesh, node_index, element_index, matches, err)
    character(len=*), intent(in) :: path
    type(msh_content_t), intent(in) :: content
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: node_index(:), element_index(:)
    type(face_matches_t), intent(out) :: matches
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: corners(:, :), n_corners(:), counts(:), face_nodes(:), own(:)
    integer :: q, first, last, n_own
    associate (faces => content%faces)
      allocate (corners(4, faces%n), n_corners(faces%n))
      corners = 0
      do q = 1, faces%n
        n_corners(q) = face_corner_count(TYPE_NODES(faces%gmsh_type(q)))
        corners(1:n_corners(q), q) = node_index(faces%nodes(1:n_corners(q), q))
      end do
      first = 1
      last = 0
      if (size(element_index) > 0) then
        first = element_index(1)
        last = element_index(size(element_index))
      end if
      call match_faces(mesh, first, last, corners, n_corners, matches%element, matches%face, counts)
      do q = 1, faces%n
        if (counts(q) /= 1 .and. counts(q) /= 2) then
          call face_error(path, content, q, face_error_text(counts(q)), err)
          return
        end if
        n_own = TYPE_NODES(faces%gmsh_type(q))
        if (n_own == n_corners(q)) cycle
        face_nodes = mesh%face_nodes(matches%element(q), matches%face(q))
        own = node_index(faces%nodes(1:n_own, q))
        if (size(face_nodes) /= n_own .or. .not. same_members(face_nodes, own)) then
          call face_error(path, content, q, 'has the corners of face S' // str(matches%face(q)) // &
            ' of element ' // str(mesh%element_id(matches%element(q))) // ' (' // &
            mesh%kinds(mesh%element_kind(matches%element(q)))%name // ') but not its mid-side &
            &nodes: the mesh is not conforming (faces and volumes of different order?)', err)
          return
        end if
      end do
    end associate
  end subroutine match_surface_faces

  !> What is wrong with a surface element on `count` element faces (0, or more than 2).
  function face_error_text(count) result(text)
    integer, intent(in) :: count
    character(len=:), allocatable :: text
    if (count == 0) then
      text = 'matches no face of an element read from this file (a physical surface must lie &
        &on element faces; is the adjacent volume in a physical volume?)'
    else
      text = 'lies on ' // str(count) // ' element faces: the mesh is not conforming'
    end if
  end function face_error_text

  !> True if `a` and `b` hold the same values (each without repetitions).
  pure logical function same_members(a, b)
    integer, intent(in) :: a(:), b(:)
    integer :: j
    same_members = size(a) == size(b)
    if (.not. same_members) return
    do j = 1, size(a)
      if (.not. any(b == a(j))) same_members = .false.
    end do
  end function same_members

  !> Error `text` for surface element `q`, at its line of the file.
  subroutine face_error(path, content, q, text, err)
    character(len=*), intent(in) :: path
    type(msh_content_t), intent(in) :: content
    integer, intent(in) :: q
    character(len=*), intent(in) :: text
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: where, what
    integer :: b, j, entity
    where = path // ': $Elements'
    if (content%faces%line(q) > 0) where = path // ':' // str(content%faces%line(q))
    what = type_name(int(content%faces%gmsh_type(q), i8)) // ' ' // str(content%faces%tag(q)) // ' (nodes'
    do j = 1, TYPE_NODES(content%faces%gmsh_type(q))
      what = what // ' ' // str(content%node_tag(content%faces%nodes(j, q)))
    end do
    what = what // ')'
    do b = 1, content%faces%n_blocks
      if (q < content%faces%block_first(b) .or. q > content%faces%block_last(b)) cycle
      entity = content%faces%block_entity(b)
      if (entity > 0) what = what // ' of physical ' // &
        group_label(content%groups(content%entities(entity)%groups(1)))
    end do
    call input_error(err, where // ': ' // what // ' ' // text)
  end subroutine face_error

  !> Turn the physical groups into sets and surfaces (see the module comment).
  subroutine add_groups(path, content, mesh, node_index, element_index, matches, err)
    character(len=*), intent(in) :: path
    type(msh_content_t), intent(in) :: content
    type(mesh_t), intent(inout) :: mesh
    integer, intent(in) :: node_index(:), element_index(:)
    type(face_matches_t), intent(in) :: matches
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: members(:), elements(:), faces(:), nodes(:)
    logical, allocatable :: used(:)
    integer :: g, h, k, n
    allocate (used(content%n_nodes))
    do g = 1, content%n_groups
      do h = 1, g - 1
        if (content%groups(h)%name /= content%groups(g)%name) cycle
        call input_error(err, path // ': physical ' // group_label(content%groups(h)) // ' and physical ' &
          // group_label(content%groups(g)) // ' would both give sets named "' // content%groups(g)%name &
          // '"; give them different names')
        return
      end do
    end do
    do g = 1, content%n_groups
      associate (group => content%groups(g))
        used = .false.
        select case (group%dim)
        case (3)
          members = group_members(content, content%solids, g, used)
          if (size(members) == 0) cycle
          call mesh%add_to_element_set(group%name, element_index(members))
          call mesh%add_to_node_set(group%name, pack(node_index, used))
        case (2)
          members = group_members(content, content%faces, g, used)
          if (size(members) == 0) cycle
          elements = matches%element(members)
          faces = matches%face(members)
          call mesh%add_faces_to_surface(group%name, elements, faces)
          allocate (nodes(MESH_MAX_FACE_NODES * size(elements)))
          n = 0
          do k = 1, size(elements)
            associate (face_nodes => mesh%face_nodes(elements(k), faces(k)))
              nodes(n + 1:n + size(face_nodes)) = face_nodes
              n = n + size(face_nodes)
            end associate
          end do
          call mesh%add_to_node_set(group%name, nodes(1:n))
          deallocate (nodes)
        case default
          members = group_members(content, content%loose_nodes, g, used)
          if (size(members) == 0) cycle
          call mesh%add_to_node_set(group%name, pack(node_index, used))
        end select
      end associate
    end do
  end subroutine add_groups

  !> Records of `store` in blocks whose entity belongs to group `g`; their nodes are marked
  !> in `used`.
  function group_members(content, store, g, used) result(members)
    type(msh_content_t), intent(in) :: content
    type(element_store_t), intent(in) :: store
    integer, intent(in) :: g
    logical, intent(inout) :: used(:)
    integer, allocatable :: members(:)
    integer :: b, n, k
    allocate (members(store%n))
    n = 0
    do b = 1, store%n_blocks
      if (store%block_entity(b) == 0) cycle
      if (.not. any(content%entities(store%block_entity(b))%groups == g)) cycle
      do k = store%block_first(b), store%block_last(b)
        n = n + 1
        members(n) = k
      end do
      call mark_nodes(store, store%block_first(b), store%block_last(b), used)
    end do
    members = members(1:n)
  end function group_members

  !> Text shortened to 60 characters, with non-printable characters shown as "?", for messages.
  pure function clip(text) result(out)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: out
    integer :: i, n
    n = min(len(text), 60)
    allocate (character(len=n) :: out)
    do i = 1, n
      out(i:i) = text(i:i)
      if (iachar(text(i:i)) < 32 .or. iachar(text(i:i)) > 126) out(i:i) = '?'
    end do
    if (len(text) > 60) out = out // '...'
  end function clip

end module fcs_gmsh_reader
