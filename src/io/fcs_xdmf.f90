!> An XDMF 2 index of a time series whose heavy data live in one HDF5 file.
!>
!> The series is a Temporal collection of frames. A frame is written as a Spatial collection
!> that carries the <Time> and holds the frame's grids (the volume mesh plus surface grids) when
!> it has several grids or when `spatial_collections` is set; otherwise as its single grid
!> (GridType="Uniform") with the <Time>. Set `spatial_collections` whenever any frame may have
!> several grids: VTK's reader fixes its output type (multiblock or unstructured grid) from the
!> first frame, so all frames of a series must have the same form.
!> Every DataItem is Format="HDF" and refers to "<file>.h5:/path" with the file name relative to
!> the XDMF file, so the pair of files can be moved together. Dimensions are written slowest
!> first, as h5py reports them (the reverse of the Fortran shape).
!>
!> Reference: XDMF model and format, version 2 (xdmf.org, "XDMF Model and Format"); attribute
!> types Scalar, Vector, Tensor6 (symmetric, components xx xy xz yy yz zz, as VTK's Xdmf2 reader
!> expands them) and Matrix; topologies Hexahedron, Quadrilateral, Polyvertex and Mixed (a flat
!> list of cells, each its XDMF cell type code followed by its node indices: Tetrahedron 6,
!> Wedge 8, Hexahedron 9, Tetrahedron_10 38, Wedge_15 40, Hexahedron_20 48; the node order of
!> each is VTK's, which for these kinds is CalculiX's: corners, then the mid-side nodes edge by
!> edge in the same order).
!>
!> `xdmf_series_t%write` replaces the XDMF file atomically: it writes "<path>.tmp", fsyncs it,
!> renames it over "<path>" and fsyncs the directory, so a viewer never reads half a file
!> (fcs_text_file; every write checked, a failure leaves the previous index in place).
module fcs_xdmf
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t
  use fcs_strings, only: str, replace_all
  use fcs_text_file, only: text_file_t
  implicit none
  private
  public :: xdmf_series_t, xdmf_frame_t, xdmf_grid_t, xdmf_attribute_t, xdmf_data_t
  public :: XDMF_HEXAHEDRON, XDMF_QUADRILATERAL, XDMF_POLYVERTEX, XDMF_MIXED
  public :: xdmf_cell_type
  public :: XDMF_NODE, XDMF_CELL
  public :: XDMF_SCALAR, XDMF_VECTOR, XDMF_TENSOR6, XDMF_MATRIX

  !> Topologies (XDMF TopologyType).
  integer, parameter :: XDMF_HEXAHEDRON = 1, XDMF_QUADRILATERAL = 2, XDMF_POLYVERTEX = 3
  integer, parameter :: XDMF_MIXED = 4
  !> Attribute centres (XDMF Center).
  integer, parameter :: XDMF_NODE = 1, XDMF_CELL = 2
  !> Attribute types (XDMF AttributeType).
  integer, parameter :: XDMF_SCALAR = 1, XDMF_VECTOR = 2, XDMF_TENSOR6 = 3, XDMF_MATRIX = 4

  !> One heavy dataset: its path in the HDF5 file, its dimensions (slowest first) and type.
  type :: xdmf_data_t
    character(len=:), allocatable :: path
    integer(i8), allocatable :: dims(:)
    logical :: is_integer = .false.
    !> Bytes per value (4 or 8).
    integer :: precision = 8
  end type xdmf_data_t

  !> A named field on a grid.
  type :: xdmf_attribute_t
    character(len=:), allocatable :: name
    integer :: centre = XDMF_NODE
    integer :: attribute_type = XDMF_SCALAR
    type(xdmf_data_t) :: data
  end type xdmf_attribute_t

  !> An unstructured grid: topology, geometry (XYZ) and fields.
  type :: xdmf_grid_t
    character(len=:), allocatable :: name
    integer :: topology = XDMF_HEXAHEDRON
    !> Number of cells and nodes per cell.
    integer(i8) :: n_cells = 0
    integer :: nodes_per_cell = 8
    type(xdmf_data_t) :: connectivity
    type(xdmf_data_t) :: geometry
    type(xdmf_attribute_t), allocatable :: attributes(:)
    integer :: n_attributes = 0
  contains
    procedure :: add_attribute => grid_add_attribute
  end type xdmf_grid_t

  !> One time step: a name (used for the Spatial collection), its time and its grids.
  type :: xdmf_frame_t
    character(len=:), allocatable :: name
    real(dp) :: time = 0.0_dp
    type(xdmf_grid_t), allocatable :: grids(:)
    integer :: n_grids = 0
  contains
    procedure :: add_grid => frame_add_grid
  end type xdmf_frame_t

  !> The series: collection name, heavy-data file name (relative), frames.
  type :: xdmf_series_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: heavy_file
    type(xdmf_frame_t), allocatable :: frames(:)
    integer :: n_frames = 0
    !> Write every frame as a Spatial collection, even a frame with a single grid.
    logical :: spatial_collections = .false.
  contains
    procedure :: init => series_init
    procedure :: add_frame => series_add_frame
    procedure :: write => series_write
  end type xdmf_series_t

contains

  !> Append a field to the grid (the array grows by doubling).
  subroutine grid_add_attribute(this, attribute)
    class(xdmf_grid_t), intent(inout) :: this
    type(xdmf_attribute_t), intent(in) :: attribute
    type(xdmf_attribute_t), allocatable :: grown(:)
    if (.not. allocated(this%attributes)) allocate (this%attributes(4))
    if (this%n_attributes == size(this%attributes)) then
      allocate (grown(2 * size(this%attributes)))
      grown(1:this%n_attributes) = this%attributes(1:this%n_attributes)
      call move_alloc(grown, this%attributes)
    end if
    this%n_attributes = this%n_attributes + 1
    this%attributes(this%n_attributes) = attribute
  end subroutine grid_add_attribute

  !> Append a grid to the frame.
  subroutine frame_add_grid(this, grid)
    class(xdmf_frame_t), intent(inout) :: this
    type(xdmf_grid_t), intent(in) :: grid
    type(xdmf_grid_t), allocatable :: grown(:)
    if (.not. allocated(this%grids)) allocate (this%grids(2))
    if (this%n_grids == size(this%grids)) then
      allocate (grown(2 * size(this%grids)))
      grown(1:this%n_grids) = this%grids(1:this%n_grids)
      call move_alloc(grown, this%grids)
    end if
    this%n_grids = this%n_grids + 1
    this%grids(this%n_grids) = grid
  end subroutine frame_add_grid

  !> Empty series named `name` whose DataItems refer to `heavy_file` (relative to the XDMF).
  subroutine series_init(this, name, heavy_file)
    class(xdmf_series_t), intent(inout) :: this
    character(len=*), intent(in) :: name, heavy_file
    this%name = name
    this%heavy_file = heavy_file
    if (allocated(this%frames)) deallocate (this%frames)
    allocate (this%frames(16))
    this%n_frames = 0
    this%spatial_collections = .false.
  end subroutine series_init

  !> Append a frame.
  subroutine series_add_frame(this, frame)
    class(xdmf_series_t), intent(inout) :: this
    type(xdmf_frame_t), intent(in) :: frame
    type(xdmf_frame_t), allocatable :: grown(:)
    if (.not. allocated(this%frames)) allocate (this%frames(16))
    if (this%n_frames == size(this%frames)) then
      allocate (grown(2 * size(this%frames)))
      grown(1:this%n_frames) = this%frames(1:this%n_frames)
      call move_alloc(grown, this%frames)
    end if
    this%n_frames = this%n_frames + 1
    this%frames(this%n_frames) = frame
  end subroutine series_add_frame

  !> Write the whole series to `path`, atomically (temporary file, fsync, rename).
  subroutine series_write(this, path, err)
    class(xdmf_series_t), intent(in) :: this
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    type(text_file_t) :: file
    call file%open(path, err, atomic=.true.)
    if (.not. allocated(err)) call write_document(this, file, err)
    if (.not. allocated(err)) call file%close(err)
    if (allocated(err)) call file%abandon()
  end subroutine series_write

  !> The XML document.
  subroutine write_document(series, file, err)
    type(xdmf_series_t), intent(in) :: series
    type(text_file_t), intent(inout) :: file
    type(error_t), allocatable, intent(out) :: err
    integer :: i
    call write_lines(file, [character(len=40) :: '<?xml version="1.0" ?>', &
      '<!DOCTYPE Xdmf SYSTEM "Xdmf.dtd" []>', '<Xdmf Version="2.0">', '  <Domain>'], err)
    if (.not. allocated(err)) call file%write('    <Grid Name="' // xml_text(series%name) // &
      '" GridType="Collection" CollectionType="Temporal">', err)
    do i = 1, series%n_frames
      if (allocated(err)) return
      call write_frame(series, series%frames(i), file, err)
    end do
    if (.not. allocated(err)) call write_lines(file, [character(len=12) :: '    </Grid>', &
      '  </Domain>', '</Xdmf>'], err)
  end subroutine write_document

  !> One frame: a single grid, or a Spatial collection of its grids, with the frame's time.
  subroutine write_frame(series, frame, file, err)
    type(xdmf_series_t), intent(in) :: series
    type(xdmf_frame_t), intent(in) :: frame
    type(text_file_t), intent(inout) :: file
    type(error_t), allocatable, intent(out) :: err
    character(len=*), parameter :: indent = '      '
    character(len=:), allocatable :: stamp
    integer :: i
    stamp = indent // '  <Time Value="' // real_text(frame%time) // '"/>'
    if (frame%n_grids == 1 .and. .not. series%spatial_collections) then
      call write_grid(series, frame%grids(1), indent, stamp, file, err)
      return
    end if
    call file%write(indent // '<Grid Name="' // xml_text(frame%name) // &
      '" GridType="Collection" CollectionType="Spatial">', err)
    if (.not. allocated(err)) call file%write(stamp, err)
    do i = 1, frame%n_grids
      if (allocated(err)) return
      call write_grid(series, frame%grids(i), indent // '  ', '', file, err)
    end do
    if (.not. allocated(err)) call file%write(indent // '</Grid>', err)
  end subroutine write_frame

  !> One Uniform grid; `stamp` (the <Time> line, or empty) follows the opening tag.
  subroutine write_grid(series, grid, indent, stamp, file, err)
    type(xdmf_series_t), intent(in) :: series
    type(xdmf_grid_t), intent(in) :: grid
    character(len=*), intent(in) :: indent, stamp
    type(text_file_t), intent(inout) :: file
    type(error_t), allocatable, intent(out) :: err
    integer :: i
    call file%write(indent // '<Grid Name="' // xml_text(grid%name) // '" GridType="Uniform">', err)
    if (.not. allocated(err) .and. len(stamp) > 0) call file%write(stamp, err)
    if (.not. allocated(err)) call file%write(indent // '  <Topology TopologyType="' // &
      topology_name(grid%topology) // '" NumberOfElements="' // str(grid%n_cells) // &
      nodes_per_element(grid) // '>', err)
    if (.not. allocated(err)) call file%write(data_item(series, grid%connectivity, &
      indent // '    '), err)
    if (.not. allocated(err)) call file%write(indent // '  </Topology>', err)
    if (.not. allocated(err)) call file%write(indent // '  <Geometry GeometryType="XYZ">', err)
    if (.not. allocated(err)) call file%write(data_item(series, grid%geometry, indent // '    '), err)
    if (.not. allocated(err)) call file%write(indent // '  </Geometry>', err)
    do i = 1, grid%n_attributes
      if (allocated(err)) return
      call file%write(indent // '  <Attribute Name="' // xml_text(grid%attributes(i)%name) // &
        '" AttributeType="' // attribute_type_name(grid%attributes(i)%attribute_type) // &
        '" Center="' // centre_name(grid%attributes(i)%centre) // '">', err)
      if (.not. allocated(err)) call file%write(data_item(series, grid%attributes(i)%data, &
        indent // '    '), err)
      if (.not. allocated(err)) call file%write(indent // '  </Attribute>', err)
    end do
    if (.not. allocated(err)) call file%write(indent // '</Grid>', err)
  end subroutine write_grid

  !> Write each of `lines` (trailing blanks removed).
  subroutine write_lines(file, lines, err)
    type(text_file_t), intent(inout) :: file
    character(len=*), intent(in) :: lines(:)
    type(error_t), allocatable, intent(out) :: err
    integer :: i
    do i = 1, size(lines)
      call file%write(trim(lines(i)), err)
      if (allocated(err)) return
    end do
  end subroutine write_lines

  !> A DataItem line referring to the heavy dataset.
  function data_item(series, data, indent) result(line)
    type(xdmf_series_t), intent(in) :: series
    type(xdmf_data_t), intent(in) :: data
    character(len=*), intent(in) :: indent
    character(len=:), allocatable :: line
    character(len=:), allocatable :: dims, number_type
    integer :: i
    dims = ''
    do i = 1, size(data%dims)
      if (i > 1) dims = dims // ' '
      dims = dims // str(data%dims(i))
    end do
    number_type = 'Float'
    if (data%is_integer) number_type = 'Int'
    line = indent // '<DataItem Dimensions="' // dims // '" NumberType="' // number_type // &
      '" Precision="' // str(data%precision) // '" Format="HDF">' // &
      xml_text(series%heavy_file) // ':' // xml_text(data%path) // '</DataItem>'
  end function data_item

  !> The NodesPerElement attribute of a grid's topology (none for Mixed).
  function nodes_per_element(grid) result(text)
    type(xdmf_grid_t), intent(in) :: grid
    character(len=:), allocatable :: text
    if (grid%topology == XDMF_MIXED) then
      text = '"'
    else
      text = '" NodesPerElement="' // str(grid%nodes_per_cell) // '"'
    end if
  end function nodes_per_element

  !> XDMF's cell type code (for Mixed topologies) of a solid with `n_faces` faces and `n_nodes`
  !> nodes (tetrahedra 4 faces, wedges 5, hexahedra 6; linear or quadratic serendipity), 0 if
  !> XDMF has none.
  pure integer function xdmf_cell_type(n_faces, n_nodes) result(code)
    integer, intent(in) :: n_faces, n_nodes
    select case (100 * n_faces + n_nodes)
    case (404)
      code = 6
    case (506)
      code = 8
    case (608)
      code = 9
    case (410)
      code = 38
    case (515)
      code = 40
    case (620)
      code = 48
    case default
      code = 0
    end select
  end function xdmf_cell_type

  pure function topology_name(topology) result(name)
    integer, intent(in) :: topology
    character(len=:), allocatable :: name
    select case (topology)
    case (XDMF_HEXAHEDRON)
      name = 'Hexahedron'
    case (XDMF_QUADRILATERAL)
      name = 'Quadrilateral'
    case (XDMF_POLYVERTEX)
      name = 'Polyvertex'
    case (XDMF_MIXED)
      name = 'Mixed'
    case default
      name = 'NoTopology'
    end select
  end function topology_name

  pure function attribute_type_name(attribute_type) result(name)
    integer, intent(in) :: attribute_type
    character(len=:), allocatable :: name
    select case (attribute_type)
    case (XDMF_VECTOR)
      name = 'Vector'
    case (XDMF_TENSOR6)
      name = 'Tensor6'
    case (XDMF_MATRIX)
      name = 'Matrix'
    case default
      name = 'Scalar'
    end select
  end function attribute_type_name

  pure function centre_name(centre) result(name)
    integer, intent(in) :: centre
    character(len=:), allocatable :: name
    if (centre == XDMF_CELL) then
      name = 'Cell'
    else
      name = 'Node'
    end if
  end function centre_name

  !> A real with 17 significant digits (round trip), no blanks.
  function real_text(value) result(text)
    real(dp), intent(in) :: value
    character(len=:), allocatable :: text
    character(len=32) :: buffer
    write (buffer, '(es24.16e3)') value
    text = trim(adjustl(buffer))
  end function real_text

  !> `text` with XML's special characters escaped.
  pure function xml_text(text) result(out)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: out
    out = replace_all(text, '&', '&amp;')
    out = replace_all(out, '<', '&lt;')
    out = replace_all(out, '>', '&gt;')
    out = replace_all(out, '"', '&quot;')
  end function xml_text

end module fcs_xdmf
