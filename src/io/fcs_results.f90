!> The results file of a job: `<job>.h5` holds the data, `<job>.xdmf` indexes them as a
!> Temporal collection of frames that ParaView's Xdmf reader opens.
!>
!> Layout of `<job>.h5` (h5py shapes; n nodes, ne elements, m points of a surface grid):
!>
!>     /                                   attributes format="fcs3d results", format_version=1,
!>                                         creator="fcs3d", tensor6_order="xx xy xz yy yz zz"
!>     /mesh/node_ids            (n)       int   user node ids
!>     /mesh/coordinates         (n, 3)    real  reference coordinates
!>     /mesh/element_ids         (ne)      int   user element ids
!>     /mesh/connectivity        (ne, 8)   int   0-based node indices, C3D8 = VTK/XDMF hexahedron;
!>                               (ne, r)   in a mesh with other kinds: r = the largest element's
!>                                         node count, shorter rows padded with -1, and then
!>     /mesh/topology            (L)       int   XDMF Mixed topology: per element its XDMF cell
!>                                         type code and 0-based node indices (fcs_xdmf)
!>     /surfaces/<grid>                    attributes kind="POINTS"|"QUADS", n_points=m
!>     /surfaces/<grid>/connectivity (c, k) int  0-based into the grid's own m points;
!>                                         POINTS: (c, 1), one vertex per cell; QUADS: (c, 4)
!>     /frames/NNNNNN                      6 digits, from 000001; attributes time, step,
!>                                         increment, complete (0 while written, 1 at end_frame)
!>     /frames/NNNNNN/coordinates (n, 3)   current coordinates (updated Lagrangian geometry)
!>     /frames/NNNNNN/nodal/<f>   (n) or (n, k)         nodal field, k = 3 or 6 components
!>     /frames/NNNNNN/cell/<f>    (ne) or (ne, k)       element (cell) field
!>     /frames/NNNNNN/integration_points/<f> (ne, q, k) q points per element; HDF5 only
!>     /frames/NNNNNN/surfaces/<grid>/coordinates (m, 3)
!>     /frames/NNNNNN/surfaces/<grid>/nodal/<f>  (m) or (m, k)
!>
!> Scalars (one component) are stored as 1-D datasets. Symmetric tensors (six components) are
!> passed in fcs3d's internal order xx, yy, zz, xy, xz, yz (CalculiX's) and STORED in XDMF's
!> Tensor6 order xx, xy, xz, yy, yz, zz (the order VTK's Xdmf reader expands into a 3x3 tensor)
!> -- for every six-component dataset of the file, integration points included. Vector and
!> tensor datasets carry a string attribute `components` ("x y z", "xx xy xz yy yz zz").
!>
!> A frame is listed in the XDMF once `end_frame` has marked it complete and flushed the file.
!> Frames without `write_coordinates` use the reference coordinates. Once a surface grid is
!> defined, every frame is a Spatial collection (ParaView: a multiblock with blocks "volume" and
!> one per surface grid written in that frame); without surface grids, frames are single grids. The XDMF is rewritten
!> atomically at every `end_frame`; each DataItem refers to "<job>.h5:/path" by the bare file
!> name, so the two files can be moved together. `open_append` reopens a file, deletes a trailing
!> incomplete frame (left by a crash or a `close` inside a frame), rebuilds the XDMF from the
!> file's contents, and continues the numbering.
!>
!> The file is opened without HDF5 file locking so that viewers can read it while a job runs;
!> a reader may still see a frame being written, which the XDMF does not list yet. (Two runs of
!> one job are kept apart by the job lock, fcs_job_lock.)
!>
!> Failures. Before each write the space it needs (the data plus a margin for HDF5's metadata)
!> is reserved on disk (`h5_file_t%reserve`), so a full disk is met before a frame is begun or
!> a dataset written, never half-way through the flush that completes a frame. Whatever fails
!> while the file is being written (a full disk where space cannot be reserved, exhausted
!> memory, an HDF5 error), the file is given up without a further flush (`h5_file_t%abandon`):
!> it keeps every frame completed before, readable by h5py and listed in the XDMF, and
!> `open_append` (a restart) deletes the frame that was being written.
module fcs_results
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, fatal_error, input_error
  use fcs_strings, only: str, string_t, basename, parse_int
  use fcs_hdf5, only: h5_file_t
  use fcs_xdmf, only: xdmf_series_t, xdmf_frame_t, xdmf_grid_t, xdmf_attribute_t, xdmf_data_t, &
    XDMF_HEXAHEDRON, XDMF_QUADRILATERAL, XDMF_POLYVERTEX, XDMF_MIXED, XDMF_NODE, XDMF_CELL, &
    XDMF_SCALAR, XDMF_VECTOR, XDMF_TENSOR6, XDMF_MATRIX
  use fcs_version, only: FCS3D_IDENTITY
  use fcs_memory, only: allocation_failed
  use fcs_field, only: field_t, FIELD_NODES, FIELD_CELLS, FIELD_POINTS, FIELD_SURFACE
  implicit none
  private
  public :: results_file_t, GRID_POINTS, GRID_QUADS
  public :: RESULTS_FORMAT, RESULTS_FORMAT_VERSION, TENSOR6_TO_XDMF

  !> Kinds of surface grid: a cloud of points (XDMF Polyvertex), or quadrilaterals.
  integer, parameter :: GRID_POINTS = 1, GRID_QUADS = 2
  !> Value of the root attribute `format`, and the layout version written.
  character(len=*), parameter :: RESULTS_FORMAT = 'fcs3d results'
  integer, parameter :: RESULTS_FORMAT_VERSION = 1
  !> Position, in fcs3d's internal order (xx, yy, zz, xy, xz, yz), of each component of XDMF's
  !> Tensor6 order (xx, xy, xz, yy, yz, zz): stored = internal(TENSOR6_TO_XDMF).
  integer, parameter :: TENSOR6_TO_XDMF(6) = [1, 4, 5, 2, 6, 3]
  character(len=*), parameter :: TENSOR6_COMPONENTS = 'xx xy xz yy yz zz'
  character(len=*), parameter :: VECTOR_COMPONENTS = 'x y z'
  !> Frame groups are numbered with this many digits.
  integer, parameter :: FRAME_DIGITS = 6
  integer, parameter :: MAX_FRAMES = 10**FRAME_DIGITS - 1
  !> Longest field or grid name.
  integer, parameter :: MAX_NAME_LENGTH = 64
  !> Space reserved for HDF5's metadata: per dataset written, and per frame begun or ended
  !> [bytes]; per frame already in the file (the /frames group's heap may double) [bytes].
  integer(i8), parameter :: DATASET_MARGIN = 16384_i8, FRAME_MARGIN = 262144_i8, &
    MARGIN_PER_FRAME = 32_i8
  !> Name of the volume grid in the XDMF (reserved: no surface grid may use it).
  character(len=*), parameter :: VOLUME_GRID = 'volume'
  character(len=*), parameter :: WRITING = 'writing results', OPENING = 'opening results'

  !> A surface grid drawn at every frame: its name, kind, point and cell counts.
  type :: surface_grid_t
    character(len=:), allocatable :: name
    integer :: kind = GRID_POINTS
    integer :: n_points = 0
    integer :: n_cells = 0
    integer :: nodes_per_cell = 1
  end type surface_grid_t

  !> An open results file. `create` or `open_append` start it, `close` ends it.
  type :: results_file_t
    type(h5_file_t) :: h5
    character(len=:), allocatable :: h5_path
    character(len=:), allocatable :: xdmf_path
    integer :: n_nodes = 0
    integer :: n_elements = 0
    !> Length of /mesh/topology (0: all elements are 8-node hexahedra, no such dataset).
    integer :: mixed_length = 0
    type(surface_grid_t), allocatable :: surfaces(:)
    integer :: n_surfaces = 0
    !> The complete frames, as listed in the XDMF.
    type(xdmf_series_t) :: series
    !> The frame being written (valid while `in_frame`).
    type(xdmf_frame_t) :: frame
    !> Number of the last frame begun.
    integer :: frame_number = 0
    logical :: in_frame = .false.
  contains
    procedure :: create => results_create
    procedure :: open_append => results_open_append
    procedure :: define_surface_grid => results_define_surface_grid
    procedure :: begin_frame => results_begin_frame
    procedure :: write_coordinates => results_write_coordinates
    procedure :: write_nodal => results_write_nodal
    procedure :: write_cell => results_write_cell
    procedure :: write_integration_points => results_write_integration_points
    procedure :: write_surface_coordinates => results_write_surface_coordinates
    procedure :: write_surface_field => results_write_surface_field
    procedure :: write_field => results_write_field
    procedure :: end_frame => results_end_frame
    procedure :: close => results_close
    procedure :: n_frames => results_n_frames
    procedure :: write_table => results_write_table
    procedure :: is_open => results_is_open
  end type results_file_t

contains

  ! ---------------------------------------------------------------------------------------------
  ! Opening and closing
  ! ---------------------------------------------------------------------------------------------

  !> Create `<path_stem>.h5` and `<path_stem>.xdmf` (replacing existing ones) with the mesh:
  !> `node_ids(n)`, reference coordinates `x_ref(3, n)`, `element_ids(ne)` and `connectivity(8, ne)`
  !> of 1-based node indices (columns of `x_ref`) in C3D8 order. A mesh of other kinds passes
  !> `cell_types(ne)`, each element's XDMF cell type (`xdmf_cell_type`), and `connectivity(r, ne)`
  !> in CalculiX order (= VTK's for these kinds), rows past an element's nodes 0.
  subroutine results_create(this, path_stem, node_ids, x_ref, element_ids, connectivity, err, &
                            cell_types)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path_stem
    integer, intent(in) :: node_ids(:)
    real(dp), intent(in) :: x_ref(:, :)
    integer, intent(in) :: element_ids(:)
    integer, intent(in) :: connectivity(:, :)
    type(error_t), allocatable, intent(out) :: err
    integer, intent(in), optional :: cell_types(:)
    integer, allocatable :: topology(:)
    call start(this, path_stem, 'creating results', err)
    if (allocated(err)) return
    if (present(cell_types)) then
      if (size(connectivity, 1) /= 8 .or. any(cell_types /= 9)) then
        call mixed_topology(this, connectivity, cell_types, topology, err)
        if (allocated(err)) return
      end if
    end if
    call check_mesh(this, node_ids, x_ref, element_ids, connectivity, err)
    if (allocated(err)) return
    call this%h5%create(this%h5_path, err, file_locking=.false.)
    if (allocated(err)) then
      call prefix(err, 'creating results')
      return
    end if
    call this%h5%reserve(FRAME_MARGIN + 8_i8 * (size(node_ids, kind=i8) + size(x_ref, kind=i8) + &
      size(element_ids, kind=i8) + size(connectivity, kind=i8)), err)
    if (.not. allocated(err)) call write_mesh(this, node_ids, x_ref, element_ids, connectivity, err)
    if (.not. allocated(err) .and. allocated(topology)) call this%h5%write_dataset('/mesh/topology', &
      topology, err)
    if (.not. allocated(err)) call this%h5%flush(err)
    if (allocated(err)) then
      call prefix(err, 'creating results')
    else
      call this%series%write(this%xdmf_path, err)
    end if
    if (allocated(err)) call abandon(this)
  end subroutine results_create

  !> Reopen `<path_stem>.h5` to add frames after its last complete one. A trailing incomplete
  !> frame is deleted; the XDMF is rebuilt from the file. With `keep_frames`, only that many
  !> frames are kept and later ones deleted (a restart from a checkpoint taken when the file
  !> had that many frames writes them again).
  subroutine results_open_append(this, path_stem, err, keep_frames)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path_stem
    type(error_t), allocatable, intent(out) :: err
    integer, intent(in), optional :: keep_frames
    integer :: limit
    limit = huge(1)
    if (present(keep_frames)) limit = keep_frames
    call start(this, path_stem, OPENING, err)
    if (allocated(err)) return
    call this%h5%open(this%h5_path, .true., err, file_locking=.false.)
    if (.not. allocated(err)) call this%h5%reserve(FRAME_MARGIN, err)
    if (.not. allocated(err)) call check_format(this, err)
    if (.not. allocated(err)) call load_mesh_sizes(this, err)
    if (.not. allocated(err)) call load_surfaces(this, err)
    if (.not. allocated(err)) call load_frames(this, limit, err)
    if (.not. allocated(err)) call this%h5%flush(err)
    if (allocated(err)) then
      call prefix(err, OPENING)
    else
      call this%series%write(this%xdmf_path, err)
    end if
    if (allocated(err)) call abandon(this)
  end subroutine results_open_append

  !> Close the file. A frame begun but not ended stays incomplete: it is not in the XDMF, and
  !> `open_append` deletes it.
  subroutine results_close(this, err)
    class(results_file_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    this%in_frame = .false.
    if (.not. this%h5%is_open()) return
    call this%h5%close(err)
    if (allocated(err)) call prefix(err, 'closing results')
  end subroutine results_close

  !> Store a table (history, event catalog) as /<group>/<name>: a dataset `values` of shape
  !> (rows, columns) in h5py's view, with the column names as the attribute `columns`
  !> (comma-separated). Replaces what was there; flushed.
  subroutine results_write_table(this, group, name, columns, values, err)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: group, name, columns
    real(dp), intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: path
    path = '/' // group // '/' // name
    call require(this, .false., 'write_table', err)
    if (allocated(err)) return
    call this%h5%reserve(data_bytes(size(values, kind=i8)), err)
    if (.not. allocated(err)) then
      if (.not. this%h5%exists(path)) call this%h5%create_group(path, err)
    end if
    if (.not. allocated(err)) call this%h5%write_dataset(path // '/values', values, err)
    if (.not. allocated(err)) call this%h5%write_attribute(path // '/values', 'columns', columns, err)
    if (.not. allocated(err)) call this%h5%flush(err)
    if (allocated(err)) then
      call prefix(err, 'writing table ' // path // ' of')
      call give_up(this)
    end if
  end subroutine results_write_table

  !> Number of complete frames.
  pure integer function results_n_frames(this)
    class(results_file_t), intent(in) :: this
    results_n_frames = this%series%n_frames
  end function results_n_frames

  !> True while the file is open.
  pure logical function results_is_open(this)
    class(results_file_t), intent(in) :: this
    results_is_open = this%h5%is_open()
  end function results_is_open

  !> Reset the object for the file pair `<path_stem>.h5/.xdmf`.
  subroutine start(this, path_stem, action, err)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path_stem, action
    type(error_t), allocatable, intent(out) :: err
    if (this%h5%is_open()) then
      call fatal_error(err, action // ' ' // path_stem // '.h5: this object still holds ' // &
        this%h5_path)
      return
    end if
    if (len(path_stem) == 0) then
      call fatal_error(err, action // ': empty file name')
      return
    end if
    this%h5_path = path_stem // '.h5'
    this%xdmf_path = path_stem // '.xdmf'
    this%n_nodes = 0
    this%n_elements = 0
    this%mixed_length = 0
    if (allocated(this%surfaces)) deallocate (this%surfaces)
    allocate (this%surfaces(4))
    this%n_surfaces = 0
    call this%series%init(basename(path_stem), basename(path_stem) // '.h5')
    this%frame_number = 0
    this%in_frame = .false.
  end subroutine start

  !> Close after a failed create/open, keeping the first error.
  subroutine abandon(this)
    class(results_file_t), intent(inout) :: this
    type(error_t), allocatable :: ignored
    call this%h5%close(ignored)
    this%in_frame = .false.
  end subroutine abandon

  !> A write failed: give the file up without flushing it (see the module header).
  subroutine give_up(this)
    class(results_file_t), intent(inout) :: this
    if (this%h5%is_open()) call this%h5%abandon()
    this%in_frame = .false.
  end subroutine give_up

  !> Bytes to reserve for a dataset of `n` reals (or integers) and its metadata.
  pure integer(i8) function data_bytes(n)
    integer(i8), intent(in) :: n
    data_bytes = 8_i8 * n + DATASET_MARGIN
  end function data_bytes

  ! ---------------------------------------------------------------------------------------------
  ! Mesh
  ! ---------------------------------------------------------------------------------------------

  !> Sizes and node indices of the mesh passed to `create`.
  subroutine check_mesh(this, node_ids, x_ref, element_ids, connectivity, err)
    class(results_file_t), intent(inout) :: this
    integer, intent(in) :: node_ids(:)
    real(dp), intent(in) :: x_ref(:, :)
    integer, intent(in) :: element_ids(:)
    integer, intent(in) :: connectivity(:, :)
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: problem
    problem = ''
    if (size(x_ref, 1) /= 3) then
      problem = 'x_ref has ' // str(size(x_ref, 1)) // ' rows, expected 3'
    else if (size(node_ids) /= size(x_ref, 2)) then
      problem = str(size(node_ids)) // ' node ids for ' // str(size(x_ref, 2)) // ' nodes'
    else if (size(connectivity, 1) /= 8 .and. this%mixed_length == 0) then
      problem = 'connectivity has ' // str(size(connectivity, 1)) // ' rows, expected 8'
    else if (size(element_ids) /= size(connectivity, 2)) then
      problem = str(size(element_ids)) // ' element ids for ' // str(size(connectivity, 2)) // &
        ' elements'
    else if (size(connectivity) > 0) then
      if (minval(connectivity) < merge(0, 1, this%mixed_length > 0) .or. &
          maxval(connectivity) > size(x_ref, 2)) problem = &
        'connectivity refers to node indices outside 1..' // str(size(x_ref, 2))
    end if
    if (len(problem) > 0) then
      call fatal_error(err, 'creating results ' // this%h5_path // ': ' // problem)
      return
    end if
    this%n_nodes = size(x_ref, 2)
    this%n_elements = size(connectivity, 2)
  end subroutine check_mesh

  !> The XDMF Mixed topology of a mesh: per element its cell type and its 0-based nodes (the
  !> nonzero rows of its connectivity column). Sets `mixed_length`.
  subroutine mixed_topology(this, connectivity, cell_types, topology, err)
    class(results_file_t), intent(inout) :: this
    integer, intent(in) :: connectivity(:, :), cell_types(:)
    integer, allocatable, intent(out) :: topology(:)
    type(error_t), allocatable, intent(out) :: err
    integer :: e, n, at
    if (size(cell_types) /= size(connectivity, 2) .or. any(cell_types <= 0)) then
      call fatal_error(err, 'creating results ' // this%h5_path // ': ' // &
        str(size(cell_types)) // ' cell types (all known) expected for ' // &
        str(size(connectivity, 2)) // ' elements')
      return
    end if
    allocate (topology(size(connectivity, 2) + count(connectivity > 0)))
    at = 0
    do e = 1, size(connectivity, 2)
      n = count(connectivity(:, e) > 0)
      topology(at + 1) = cell_types(e)
      topology(at + 2:at + 1 + n) = connectivity(1:n, e) - 1
      at = at + 1 + n
    end do
    this%mixed_length = size(topology)
  end subroutine mixed_topology

  !> Root attributes, /mesh, and the empty /frames and /surfaces groups.
  subroutine write_mesh(this, node_ids, x_ref, element_ids, connectivity, err)
    class(results_file_t), intent(inout) :: this
    integer, intent(in) :: node_ids(:)
    real(dp), intent(in) :: x_ref(:, :)
    integer, intent(in) :: element_ids(:)
    integer, intent(in) :: connectivity(:, :)
    type(error_t), allocatable, intent(out) :: err
    call this%h5%write_attribute('/', 'format', RESULTS_FORMAT, err)
    if (.not. allocated(err)) call this%h5%write_attribute('/', 'format_version', &
      RESULTS_FORMAT_VERSION, err)
    if (.not. allocated(err)) call this%h5%write_attribute('/', 'creator', FCS3D_IDENTITY, err)
    if (.not. allocated(err)) call this%h5%write_attribute('/', 'tensor6_order', &
      TENSOR6_COMPONENTS, err)
    if (.not. allocated(err)) call this%h5%write_dataset('/mesh/node_ids', node_ids, err)
    if (.not. allocated(err)) call this%h5%write_dataset('/mesh/coordinates', x_ref, err)
    if (.not. allocated(err)) call this%h5%write_dataset('/mesh/element_ids', element_ids, err)
    if (.not. allocated(err)) call this%h5%write_dataset('/mesh/connectivity', &
      connectivity - 1, err)
    if (.not. allocated(err)) call this%h5%create_group('/frames', err)
    if (.not. allocated(err)) call this%h5%create_group('/surfaces', err)
  end subroutine write_mesh

  !> The root attributes must say this is a results file of a supported version.
  subroutine check_format(this, err)
    class(results_file_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: format
    integer :: version
    call this%h5%read_attribute('/', 'format', format, err)
    if (allocated(err)) then
      call input_error(err, this%h5_path // ': not an fcs3d results file (no format attribute)')
      return
    end if
    if (format /= RESULTS_FORMAT) then
      call input_error(err, this%h5_path // ': not an fcs3d results file (format "' // &
        format // '")')
      return
    end if
    call this%h5%read_attribute('/', 'format_version', version, err)
    if (allocated(err)) return
    if (version /= RESULTS_FORMAT_VERSION) call input_error(err, this%h5_path // &
      ': results format version ' // str(version) // ' is not supported (this build reads ' // &
      str(RESULTS_FORMAT_VERSION) // ')')
  end subroutine check_format

  !> Node and element counts from the shapes of /mesh/coordinates and /mesh/connectivity.
  subroutine load_mesh_sizes(this, err)
    class(results_file_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    integer(i8), allocatable :: dims(:)
    call this%h5%dataset_shape('/mesh/coordinates', dims, err)
    if (allocated(err)) return
    if (size(dims) /= 2) then
      call input_error(err, this%h5_path // ': /mesh/coordinates is not a table')
      return
    end if
    this%n_nodes = int(dims(2))
    call this%h5%dataset_shape('/mesh/connectivity', dims, err)
    if (allocated(err)) return
    if (size(dims) /= 2) then
      call input_error(err, this%h5_path // ': /mesh/connectivity is not a table')
      return
    end if
    this%n_elements = int(dims(2))
    this%mixed_length = 0
    if (this%h5%exists('/mesh/topology')) then
      call this%h5%dataset_shape('/mesh/topology', dims, err)
      if (allocated(err)) return
      this%mixed_length = int(dims(1))
    end if
  end subroutine load_mesh_sizes

  ! ---------------------------------------------------------------------------------------------
  ! Surface grids
  ! ---------------------------------------------------------------------------------------------

  !> Define a grid drawn at every frame from now on. `kind` GRID_POINTS: `connectivity(1, m)`,
  !> one vertex per cell (usually 0..m-1); GRID_QUADS: `connectivity(4, c)`. Entries are 0-based
  !> indices into the grid's own points, whose number is `n_points` (default: m for POINTS,
  !> maxval(connectivity) + 1 for QUADS). Redefining a grid identically (after `open_append`)
  !> is accepted; differently, an error. Not allowed inside a frame.
  subroutine results_define_surface_grid(this, name, kind, connectivity, err, n_points)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer, intent(in) :: kind
    integer, intent(in) :: connectivity(:, :)
    type(error_t), allocatable, intent(out) :: err
    integer, intent(in), optional :: n_points
    type(surface_grid_t) :: grid
    character(len=:), allocatable :: path
    integer :: k
    call require(this, .false., 'defining surface grid ' // name, err)
    if (allocated(err)) return
    call new_surface_grid(this, name, kind, connectivity, grid, err, n_points)
    if (allocated(err)) return
    k = find_surface(this, name)
    if (k > 0) then
      call compare_surface_grid(this, this%surfaces(k), grid, connectivity, err)
      return
    end if
    path = '/surfaces/' // name
    call this%h5%write_dataset(path // '/connectivity', connectivity, err)
    if (.not. allocated(err)) call this%h5%write_attribute(path, 'kind', kind_name(kind), err)
    if (.not. allocated(err)) call this%h5%write_attribute(path, 'n_points', grid%n_points, err)
    if (allocated(err)) then
      call prefix(err, WRITING)
      return
    end if
    call add_surface(this, grid)
  end subroutine results_define_surface_grid

  !> Check a new surface grid's arguments and fill its description.
  subroutine new_surface_grid(this, name, kind, connectivity, grid, err, n_points)
    class(results_file_t), intent(in) :: this
    character(len=*), intent(in) :: name
    integer, intent(in) :: kind
    integer, intent(in) :: connectivity(:, :)
    type(surface_grid_t), intent(out) :: grid
    type(error_t), allocatable, intent(out) :: err
    integer, intent(in), optional :: n_points
    character(len=:), allocatable :: problem
    problem = name_problem(name)
    if (len(problem) == 0 .and. name == VOLUME_GRID) problem = 'the name "' // VOLUME_GRID // &
      '" is reserved for the volume mesh'
    if (len(problem) == 0 .and. kind /= GRID_POINTS .and. kind /= GRID_QUADS) problem = &
      'unknown kind ' // str(kind) // '; expected GRID_POINTS or GRID_QUADS'
    if (len(problem) > 0) then
      call fail(this, 'surface grid "' // name // '": ' // problem, err)
      return
    end if
    grid%name = name
    grid%kind = kind
    grid%nodes_per_cell = merge(1, 4, kind == GRID_POINTS)
    grid%n_cells = size(connectivity, 2)
    if (present(n_points)) then
      grid%n_points = n_points
    else if (kind == GRID_POINTS) then
      grid%n_points = size(connectivity, 2)
    else
      grid%n_points = 0
      if (size(connectivity) > 0) grid%n_points = maxval(connectivity) + 1
    end if
    if (size(connectivity, 1) /= grid%nodes_per_cell) then
      problem = 'connectivity has ' // str(size(connectivity, 1)) // ' rows, expected ' // &
        str(grid%nodes_per_cell)
    else if (size(connectivity) > 0) then
      if (minval(connectivity) < 0 .or. maxval(connectivity) >= grid%n_points) problem = &
        'connectivity refers to points outside 0..' // str(grid%n_points - 1)
    end if
    if (len(problem) > 0) call fail(this, 'surface grid "' // name // '": ' // problem, err)
  end subroutine new_surface_grid

  !> A grid defined again must match the stored definition.
  subroutine compare_surface_grid(this, old, new, connectivity, err)
    class(results_file_t), intent(inout) :: this
    type(surface_grid_t), intent(in) :: old, new
    integer, intent(in) :: connectivity(:, :)
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: stored(:, :)
    logical :: same
    same = old%kind == new%kind .and. old%n_points == new%n_points .and. &
      old%n_cells == new%n_cells
    if (same) then
      call this%h5%read_dataset('/surfaces/' // old%name // '/connectivity', stored, err)
      if (allocated(err)) then
        call prefix(err, WRITING)
        return
      end if
      same = all(shape(stored) == shape(connectivity))
      if (same) same = all(stored == connectivity)
    end if
    if (.not. same) call fail(this, 'surface grid "' // old%name // &
      '" is already defined differently', err)
  end subroutine compare_surface_grid

  !> Read the surface grid definitions under /surfaces.
  subroutine load_surfaces(this, err)
    class(results_file_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    type(string_t), allocatable :: names(:)
    type(surface_grid_t) :: grid
    character(len=:), allocatable :: kind, path
    integer(i8), allocatable :: dims(:)
    integer :: i
    if (.not. this%h5%exists('/surfaces')) return
    call this%h5%list_group('/surfaces', names, err)
    do i = 1, size(names)
      if (allocated(err)) return
      path = '/surfaces/' // names(i)%s
      grid%name = names(i)%s
      call this%h5%read_attribute(path, 'kind', kind, err)
      if (allocated(err)) return
      if (kind == kind_name(GRID_POINTS)) then
        grid%kind = GRID_POINTS
      else if (kind == kind_name(GRID_QUADS)) then
        grid%kind = GRID_QUADS
      else
        call input_error(err, this%h5_path // ': ' // path // ' has unknown kind "' // kind // '"')
        return
      end if
      call this%h5%read_attribute(path, 'n_points', grid%n_points, err)
      if (.not. allocated(err)) call this%h5%dataset_shape(path // '/connectivity', dims, err)
      if (allocated(err)) return
      if (size(dims) /= 2) then
        call input_error(err, this%h5_path // ': ' // path // '/connectivity is not a table')
        return
      end if
      grid%nodes_per_cell = int(dims(1))
      grid%n_cells = int(dims(2))
      call add_surface(this, grid)
    end do
  end subroutine load_surfaces

  !> Append a surface grid description.
  subroutine add_surface(this, grid)
    class(results_file_t), intent(inout) :: this
    type(surface_grid_t), intent(in) :: grid
    type(surface_grid_t), allocatable :: grown(:)
    if (this%n_surfaces == size(this%surfaces)) then
      allocate (grown(2 * size(this%surfaces)))
      grown(1:this%n_surfaces) = this%surfaces(1:this%n_surfaces)
      call move_alloc(grown, this%surfaces)
    end if
    this%n_surfaces = this%n_surfaces + 1
    this%surfaces(this%n_surfaces) = grid
    this%series%spatial_collections = .true.
  end subroutine add_surface

  !> Index of the surface grid `name`, 0 if none.
  pure integer function find_surface(this, name) result(k)
    class(results_file_t), intent(in) :: this
    character(len=*), intent(in) :: name
    do k = 1, this%n_surfaces
      if (this%surfaces(k)%name == name) return
    end do
    k = 0
  end function find_surface

  pure function kind_name(kind) result(name)
    integer, intent(in) :: kind
    character(len=:), allocatable :: name
    if (kind == GRID_POINTS) then
      name = 'POINTS'
    else
      name = 'QUADS'
    end if
  end function kind_name

  ! ---------------------------------------------------------------------------------------------
  ! Frames
  ! ---------------------------------------------------------------------------------------------

  !> Start frame number n_frames()+1 at `time` (model time units) for `step` and `increment`.
  subroutine results_begin_frame(this, time, step, increment, err)
    class(results_file_t), intent(inout) :: this
    real(dp), intent(in) :: time
    integer, intent(in) :: step, increment
    type(error_t), allocatable, intent(out) :: err
    integer :: number
    character(len=:), allocatable :: path
    call require(this, .false., 'begin_frame', err)
    if (allocated(err)) return
    number = this%frame_number + 1
    if (number > MAX_FRAMES) then
      call fail(this, 'more than ' // str(MAX_FRAMES) // ' frames', err)
      return
    end if
    path = frame_path(number)
    call this%h5%reserve(FRAME_MARGIN + MARGIN_PER_FRAME * number, err)
    if (.not. allocated(err)) call this%h5%create_group(path, err)
    if (.not. allocated(err)) call this%h5%write_attribute(path, 'time', time, err)
    if (.not. allocated(err)) call this%h5%write_attribute(path, 'step', step, err)
    if (.not. allocated(err)) call this%h5%write_attribute(path, 'increment', increment, err)
    if (.not. allocated(err)) call this%h5%write_attribute(path, 'complete', 0, err)
    if (allocated(err)) then
      call prefix(err, WRITING)
      call give_up(this)
      return
    end if
    this%frame_number = number
    call start_frame(this, number, time)
    this%in_frame = .true.
  end subroutine results_begin_frame

  !> Mark the frame complete, flush the HDF5 file and rewrite the XDMF.
  subroutine results_end_frame(this, err)
    class(results_file_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    call require(this, .true., 'end_frame', err)
    if (allocated(err)) return
    call this%h5%reserve(FRAME_MARGIN + MARGIN_PER_FRAME * this%frame_number, err)
    if (.not. allocated(err)) call this%h5%write_attribute(frame_path(this%frame_number), &
      'complete', 1, err)
    if (.not. allocated(err)) call this%h5%flush(err)
    if (allocated(err)) then
      call prefix(err, WRITING)
      call give_up(this)
      return
    end if
    this%in_frame = .false.
    call this%series%add_frame(this%frame)
    call this%series%write(this%xdmf_path, err)
  end subroutine results_end_frame

  !> Current coordinates `x(3, n_nodes)` of the volume mesh in this frame.
  subroutine results_write_coordinates(this, x, err)
    class(results_file_t), intent(inout) :: this
    real(dp), intent(in) :: x(:, :)
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: path
    call require(this, .true., 'write_coordinates', err)
    if (allocated(err)) return
    call check_columns(this, 'coordinates', x, 3, this%n_nodes, 'nodes', err)
    if (allocated(err)) return
    path = frame_path(this%frame_number) // '/coordinates'
    call this%h5%reserve(data_bytes(size(x, kind=i8)), err)
    if (.not. allocated(err)) call this%h5%write_dataset(path, x, err)
    if (allocated(err)) then
      call prefix(err, WRITING)
      call give_up(this)
      return
    end if
    this%frame%grids(1)%geometry = real_data(path, this%n_nodes, 3)
  end subroutine results_write_coordinates

  !> Nodal field `values(k, n_nodes)`, k = 1 (Scalar), 3 (Vector) or 6 (symmetric tensor in
  !> internal order xx yy zz xy xz yz; stored and shown as XDMF Tensor6).
  subroutine results_write_nodal(this, name, values, err)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    call write_volume_field(this, name, XDMF_NODE, values, err)
  end subroutine results_write_nodal

  !> Element (cell) field `values(k, n_elements)`, k = 1, 3 or 6 as for `write_nodal`.
  subroutine results_write_cell(this, name, values, err)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    call write_volume_field(this, name, XDMF_CELL, values, err)
  end subroutine results_write_cell

  !> Nodal or cell field of the volume mesh.
  subroutine write_volume_field(this, name, centre, values, err)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer, intent(in) :: centre
    real(dp), intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: path, what
    integer :: n
    call require(this, .true., trim(merge('write_nodal', 'write_cell ', centre == XDMF_NODE)), err)
    if (allocated(err)) return
    what = 'nodal field "' // name // '"'
    n = this%n_nodes
    path = frame_path(this%frame_number) // '/nodal/' // name
    if (centre == XDMF_CELL) then
      what = 'cell field "' // name // '"'
      n = this%n_elements
      path = frame_path(this%frame_number) // '/cell/' // name
    end if
    call check_field(this, what, name, centre, values, n, this%frame%grids(1), err)
    if (allocated(err)) return
    call write_field(this, path, values, err)
    if (allocated(err)) then
      call give_up(this)
      return
    end if
    call this%frame%grids(1)%add_attribute(field_attribute(name, centre, path, n, &
      size(values, 1)))
  end subroutine write_volume_field

  !> Integration-point field `values(k, q, n_elements)` (q points per element, any k; six
  !> components are a symmetric tensor, reordered as for `write_nodal`). HDF5 only.
  subroutine results_write_integration_points(this, name, values, err)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    real(dp), intent(in) :: values(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: path, problem
    call require(this, .true., 'write_integration_points', err)
    if (allocated(err)) return
    problem = name_problem(name)
    if (len(problem) == 0 .and. size(values, 3) /= this%n_elements) problem = 'values have ' // &
      str(size(values, 3)) // ' elements, expected ' // str(this%n_elements)
    if (len(problem) == 0 .and. size(values, 1) < 1) problem = 'no components'
    if (len(problem) > 0) then
      call fail(this, 'integration-point field "' // name // '": ' // problem, err)
      return
    end if
    path = frame_path(this%frame_number) // '/integration_points/' // name
    call this%h5%reserve(data_bytes(size(values, kind=i8)), err)
    if (allocated(err)) then
    else if (size(values, 1) == 6) then
      call write_tensor_field(this, path, values, err)
    else
      call this%h5%write_dataset(path, values, err)
    end if
    if (allocated(err)) then
      call prefix(err, WRITING)
      call give_up(this)
    end if
  end subroutine results_write_integration_points

  !> A tensor field at integration points, `values(6, q, ne)`, stored with its components in
  !> XDMF's order (a reordered copy, allocated with a check).
  subroutine write_tensor_field(this, path, values, err)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: stored(:, :, :)
    integer :: status, k
    allocate (stored(6, size(values, 2), size(values, 3)), stat=status)
    if (allocation_failed(status, 'writing ' // path // ' of ' // this%h5_path, &
                          8_i8 * size(values, kind=i8), err)) return
    do k = 1, size(values, 3)
      stored(:, :, k) = values(TENSOR6_TO_XDMF, :, k)
    end do
    call this%h5%write_dataset(path, stored, err)
    if (.not. allocated(err)) call this%h5%write_attribute(path, 'components', &
      TENSOR6_COMPONENTS, err)
  end subroutine write_tensor_field

  !> Current coordinates `x(3, m)` of surface grid `grid_name` in this frame.
  subroutine results_write_surface_coordinates(this, grid_name, x, err)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: grid_name
    real(dp), intent(in) :: x(:, :)
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: path
    integer :: k
    call require(this, .true., 'write_surface_coordinates', err)
    if (allocated(err)) return
    k = require_surface(this, grid_name, err)
    if (allocated(err)) return
    if (frame_grid(this%frame, grid_name) > 0) then
      call fail(this, 'coordinates of surface grid "' // grid_name // &
        '" already written in frame ' // str(this%frame_number), err)
      return
    end if
    call check_columns(this, 'coordinates of surface grid "' // grid_name // '"', x, 3, &
      this%surfaces(k)%n_points, 'points', err)
    if (allocated(err)) return
    path = frame_path(this%frame_number) // '/surfaces/' // grid_name // '/coordinates'
    call this%h5%reserve(data_bytes(size(x, kind=i8)), err)
    if (.not. allocated(err)) call this%h5%write_dataset(path, x, err)
    if (allocated(err)) then
      call prefix(err, WRITING)
      call give_up(this)
      return
    end if
    call record_surface_coordinates(this, k, path)
  end subroutine results_write_surface_coordinates

  !> Write field `f` of the current frame where it lives (fcs_field): nodal, cell,
  !> integration-point or surface-grid values.
  subroutine results_write_field(this, f, err)
    class(results_file_t), intent(inout) :: this
    type(field_t), intent(in) :: f
    type(error_t), allocatable, intent(out) :: err
    select case (f%location)
    case (FIELD_NODES)
      call this%write_nodal(f%name, f%values, err)
    case (FIELD_CELLS)
      call this%write_cell(f%name, f%values, err)
    case (FIELD_POINTS)
      call this%write_integration_points(f%name, f%point_values, err)
    case (FIELD_SURFACE)
      call this%write_surface_field(f%grid, f%name, f%values, err)
    case default
      call fail(this, 'field "' // f%name // '": unknown location', err)
    end select
  end subroutine results_write_field

  !> Nodal field `values(k, m)` on surface grid `grid_name` (k = 1, 3 or 6, as `write_nodal`);
  !> the grid's coordinates must have been written in this frame.
  subroutine results_write_surface_field(this, grid_name, field_name, values, err)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: grid_name, field_name
    real(dp), intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: path, what
    integer :: k, g
    call require(this, .true., 'write_surface_field', err)
    if (allocated(err)) return
    k = require_surface(this, grid_name, err)
    if (allocated(err)) return
    what = 'field "' // field_name // '" of surface grid "' // grid_name // '"'
    g = frame_grid(this%frame, grid_name)
    if (g == 0) then
      call fail(this, what // ': write the grid''s coordinates first in this frame', err)
      return
    end if
    call check_field(this, what, field_name, XDMF_NODE, values, this%surfaces(k)%n_points, &
      this%frame%grids(g), err)
    if (allocated(err)) return
    path = frame_path(this%frame_number) // '/surfaces/' // grid_name // '/nodal/' // field_name
    call write_field(this, path, values, err)
    if (allocated(err)) then
      call give_up(this)
      return
    end if
    call this%frame%grids(g)%add_attribute(field_attribute(field_name, XDMF_NODE, path, &
      this%surfaces(k)%n_points, size(values, 1)))
  end subroutine results_write_surface_field

  !> Write a nodal/cell field: one component as a 1-D dataset, six reordered to XDMF's order
  !> (scalars and tensors through a copy allocated with a check).
  subroutine write_field(this, path, values, err)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: stored(:, :)
    integer :: status
    call this%h5%reserve(data_bytes(size(values, kind=i8)), err)
    if (allocated(err)) then
      call prefix(err, WRITING)
      return
    end if
    if (size(values, 1) == 3) then
      call this%h5%write_dataset(path, values, err)
      if (.not. allocated(err)) call this%h5%write_attribute(path, 'components', &
        VECTOR_COMPONENTS, err)
      if (allocated(err)) call prefix(err, WRITING)
      return
    end if
    allocate (stored(size(values, 1), size(values, 2)), stat=status)
    if (allocation_failed(status, 'writing ' // path // ' of ' // this%h5_path, &
                          8_i8 * size(values, kind=i8), err)) return
    if (size(values, 1) == 1) then
      stored = values
      call this%h5%write_dataset(path, stored(1, :), err)
    else
      stored = values(TENSOR6_TO_XDMF, :)
      call this%h5%write_dataset(path, stored, err)
      if (.not. allocated(err)) call this%h5%write_attribute(path, 'components', &
        TENSOR6_COMPONENTS, err)
    end if
    if (allocated(err)) call prefix(err, WRITING)
  end subroutine write_field

  ! ---------------------------------------------------------------------------------------------
  ! Frame descriptions (for the XDMF), shared by writing and by open_append
  ! ---------------------------------------------------------------------------------------------

  !> Begin the description of frame `number`: the volume grid with the reference coordinates
  !> (replaced by write_coordinates) and the node and element ids as fields.
  subroutine start_frame(this, number, time)
    class(results_file_t), intent(inout) :: this
    integer, intent(in) :: number
    real(dp), intent(in) :: time
    type(xdmf_grid_t) :: volume
    this%frame = xdmf_frame_t()
    this%frame%name = 'frame ' // frame_label(number)
    this%frame%time = time
    volume%name = VOLUME_GRID
    volume%n_cells = this%n_elements
    if (this%mixed_length > 0) then
      volume%topology = XDMF_MIXED
      volume%connectivity = integer_data('/mesh/topology', this%mixed_length, 1)
    else
      volume%topology = XDMF_HEXAHEDRON
      volume%nodes_per_cell = 8
      volume%connectivity = integer_data('/mesh/connectivity', this%n_elements, 8, table=.true.)
    end if
    volume%geometry = real_data('/mesh/coordinates', this%n_nodes, 3)
    call volume%add_attribute(xdmf_attribute_t('node_id', XDMF_NODE, XDMF_SCALAR, &
      integer_data('/mesh/node_ids', this%n_nodes, 1)))
    call volume%add_attribute(xdmf_attribute_t('element_id', XDMF_CELL, XDMF_SCALAR, &
      integer_data('/mesh/element_ids', this%n_elements, 1)))
    call this%frame%add_grid(volume)
  end subroutine start_frame

  !> Add surface grid k, with the coordinates at `path`, to the frame description.
  subroutine record_surface_coordinates(this, k, path)
    class(results_file_t), intent(inout) :: this
    integer, intent(in) :: k
    character(len=*), intent(in) :: path
    type(xdmf_grid_t) :: grid
    associate (surface => this%surfaces(k))
      grid%name = surface%name
      grid%topology = merge(XDMF_POLYVERTEX, XDMF_QUADRILATERAL, surface%kind == GRID_POINTS)
      grid%n_cells = surface%n_cells
      grid%nodes_per_cell = surface%nodes_per_cell
      grid%connectivity = integer_data('/surfaces/' // surface%name // '/connectivity', &
        surface%n_cells, surface%nodes_per_cell, table=.true.)
      grid%geometry = real_data(path, surface%n_points, 3)
    end associate
    call this%frame%add_grid(grid)
  end subroutine record_surface_coordinates

  !> Describe a field dataset of `n` rows and `components` columns.
  function field_attribute(name, centre, path, n, components) result(attribute)
    character(len=*), intent(in) :: name, path
    integer, intent(in) :: centre, n, components
    type(xdmf_attribute_t) :: attribute
    attribute%name = name
    attribute%centre = centre
    select case (components)
    case (1)
      attribute%attribute_type = XDMF_SCALAR
    case (3)
      attribute%attribute_type = XDMF_VECTOR
    case (6)
      attribute%attribute_type = XDMF_TENSOR6
    case default
      attribute%attribute_type = XDMF_MATRIX
    end select
    attribute%data = real_data(path, n, components)
  end function field_attribute

  !> A real dataset of n rows and k columns (k = 1: a 1-D dataset unless `table`).
  function real_data(path, n, k, table) result(data)
    character(len=*), intent(in) :: path
    integer, intent(in) :: n, k
    logical, intent(in), optional :: table
    type(xdmf_data_t) :: data
    logical :: two_d
    two_d = k /= 1
    if (present(table)) two_d = two_d .or. table
    data%path = path
    if (.not. two_d) then
      data%dims = [int(n, i8)]
    else
      data%dims = [int(n, i8), int(k, i8)]
    end if
    data%is_integer = .false.
    data%precision = 8
  end function real_data

  !> An integer dataset of n rows and k columns (k = 1: a 1-D dataset unless `table`).
  function integer_data(path, n, k, table) result(data)
    character(len=*), intent(in) :: path
    integer, intent(in) :: n, k
    logical, intent(in), optional :: table
    type(xdmf_data_t) :: data
    data = real_data(path, n, k, table)
    data%is_integer = .true.
    data%precision = bit_size(0) / 8
  end function integer_data

  !> Index of grid `name` in the frame description, 0 if absent.
  pure integer function frame_grid(frame, name) result(g)
    type(xdmf_frame_t), intent(in) :: frame
    character(len=*), intent(in) :: name
    do g = 1, frame%n_grids
      if (frame%grids(g)%name == name) return
    end do
    g = 0
  end function frame_grid

  ! ---------------------------------------------------------------------------------------------
  ! open_append: reading the frames back
  ! ---------------------------------------------------------------------------------------------

  !> Describe every complete frame; delete the first incomplete frame and all after it.
  subroutine load_frames(this, limit, err)
    class(results_file_t), intent(inout) :: this
    integer, intent(in) :: limit
    type(error_t), allocatable, intent(out) :: err
    type(string_t), allocatable :: names(:)
    integer :: i, number, complete
    logical :: ok, keeping
    call this%h5%list_group('/frames', names, err)
    if (allocated(err)) return
    keeping = .true.
    do i = 1, size(names)
      call parse_int(names(i)%s, number, ok)
      if (.not. ok .or. number /= i .or. len(names(i)%s) /= FRAME_DIGITS) then
        call input_error(err, this%h5_path // ': unexpected group /frames/' // names(i)%s // &
          ' (expected /frames/' // frame_label(i) // ')')
        return
      end if
      complete = 0
      if (keeping) then
        if (this%h5%has_attribute(frame_path(i), 'complete')) then
          call this%h5%read_attribute(frame_path(i), 'complete', complete, err)
          if (allocated(err)) return
        end if
      end if
      keeping = keeping .and. complete == 1 .and. i <= limit
      if (keeping) then
        call load_frame(this, i, err)
        if (allocated(err)) return
        call this%series%add_frame(this%frame)
        this%frame_number = i
      else
        call this%h5%delete(frame_path(i), err)
        if (allocated(err)) return
      end if
    end do
  end subroutine load_frames

  !> Rebuild the description of complete frame `number` from the file.
  subroutine load_frame(this, number, err)
    class(results_file_t), intent(inout) :: this
    integer, intent(in) :: number
    type(error_t), allocatable, intent(out) :: err
    real(dp) :: time
    type(string_t), allocatable :: names(:)
    integer :: k, i
    character(len=:), allocatable :: path, grid_path
    path = frame_path(number)
    call this%h5%read_attribute(path, 'time', time, err)
    if (allocated(err)) return
    call start_frame(this, number, time)
    if (this%h5%exists(path // '/coordinates')) &
      this%frame%grids(1)%geometry = real_data(path // '/coordinates', this%n_nodes, 3)
    call load_fields(this, path // '/nodal', XDMF_NODE, this%n_nodes, 1, err)
    if (.not. allocated(err)) call load_fields(this, path // '/cell', XDMF_CELL, &
      this%n_elements, 1, err)
    if (allocated(err)) return
    if (.not. this%h5%exists(path // '/surfaces')) return
    call this%h5%list_group(path // '/surfaces', names, err)
    do i = 1, size(names)
      if (allocated(err)) return
      k = find_surface(this, names(i)%s)
      if (k == 0) then
        call input_error(err, this%h5_path // ': ' // path // '/surfaces/' // names(i)%s // &
          ' belongs to no grid defined under /surfaces')
        return
      end if
      grid_path = path // '/surfaces/' // names(i)%s
      if (.not. this%h5%exists(grid_path // '/coordinates')) cycle
      call record_surface_coordinates(this, k, grid_path // '/coordinates')
      call load_fields(this, grid_path // '/nodal', XDMF_NODE, this%surfaces(k)%n_points, &
        this%frame%n_grids, err)
    end do
  end subroutine load_frame

  !> Describe every dataset in group `path` (if it exists) as a field of grid `g`.
  subroutine load_fields(this, path, centre, n, g, err)
    class(results_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(in) :: centre, n, g
    type(error_t), allocatable, intent(out) :: err
    type(string_t), allocatable :: names(:)
    integer(i8), allocatable :: dims(:)
    integer :: i, components
    if (.not. this%h5%exists(path)) return
    call this%h5%list_group(path, names, err)
    do i = 1, size(names)
      if (allocated(err)) return
      call this%h5%dataset_shape(path // '/' // names(i)%s, dims, err)
      if (allocated(err)) return
      components = 1
      if (size(dims) == 2) components = int(dims(1))
      if (size(dims) < 1 .or. size(dims) > 2 .or. dims(size(dims)) /= n) then
        call input_error(err, this%h5_path // ': ' // path // '/' // names(i)%s // &
          ' does not have one row per ' // merge('node', 'cell', centre == XDMF_NODE))
        return
      end if
      call this%frame%grids(g)%add_attribute(field_attribute(names(i)%s, centre, &
        path // '/' // names(i)%s, n, components))
    end do
  end subroutine load_fields

  ! ---------------------------------------------------------------------------------------------
  ! Checks and small helpers
  ! ---------------------------------------------------------------------------------------------

  !> The file must be open, and inside a frame exactly when `inside_frame`.
  subroutine require(this, inside_frame, action, err)
    class(results_file_t), intent(in) :: this
    logical, intent(in) :: inside_frame
    character(len=*), intent(in) :: action
    type(error_t), allocatable, intent(out) :: err
    if (.not. this%h5%is_open()) then
      call fatal_error(err, WRITING // ': ' // action // ': the results file is not open')
    else if (inside_frame .and. .not. this%in_frame) then
      call fail(this, action // ': no frame begun (call begin_frame first)', err)
    else if (.not. inside_frame .and. this%in_frame) then
      call fail(this, action // ': frame ' // str(this%frame_number) // &
        ' is still open (call end_frame first)', err)
    end if
  end subroutine require

  !> Index of surface grid `name`; an error if it is not defined.
  integer function require_surface(this, name, err) result(k)
    class(results_file_t), intent(in) :: this
    character(len=*), intent(in) :: name
    type(error_t), allocatable, intent(out) :: err
    k = find_surface(this, name)
    if (k == 0) call fail(this, 'surface grid "' // name // '" is not defined', err)
  end function require_surface

  !> A field's name, component count and column count (`n` rows of the grid); a grid may not
  !> hold two fields of the same name and centre (node_id and element_id are taken).
  subroutine check_field(this, what, name, centre, values, n, grid, err)
    class(results_file_t), intent(in) :: this
    character(len=*), intent(in) :: what, name
    integer, intent(in) :: centre
    real(dp), intent(in) :: values(:, :)
    integer, intent(in) :: n
    type(xdmf_grid_t), intent(in) :: grid
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: problem
    integer :: i
    problem = name_problem(name)
    if (len(problem) == 0 .and. all(size(values, 1) /= [1, 3, 6])) problem = 'values have ' // &
      str(size(values, 1)) // ' components; expected 1 (scalar), 3 (vector) or 6 (tensor)'
    if (len(problem) == 0 .and. size(values, 2) /= n) problem = 'values have ' // &
      str(size(values, 2)) // ' columns, expected ' // str(n) // ' (one per ' // &
      merge('node', 'cell', centre == XDMF_NODE) // ')'
    do i = 1, grid%n_attributes
      if (len(problem) > 0) exit
      if (grid%attributes(i)%name == name .and. grid%attributes(i)%centre == centre) problem = &
        'a field of this name is already in frame ' // str(this%frame_number)
    end do
    if (len(problem) > 0) call fail(this, what // ': ' // problem, err)
  end subroutine check_field

  !> `values` must have `rows` rows and `n` columns.
  subroutine check_columns(this, what, values, rows, n, unit, err)
    class(results_file_t), intent(in) :: this
    character(len=*), intent(in) :: what
    real(dp), intent(in) :: values(:, :)
    integer, intent(in) :: rows, n
    character(len=*), intent(in) :: unit
    type(error_t), allocatable, intent(out) :: err
    if (size(values, 1) /= rows .or. size(values, 2) /= n) call fail(this, what // &
      ': shape (' // str(size(values, 1)) // ', ' // str(size(values, 2)) // '), expected (' // &
      str(rows) // ', ' // str(n) // ') for ' // str(n) // ' ' // unit, err)
  end subroutine check_columns

  !> Why `name` cannot name a field or grid (empty if it can): 1 to 64 characters among
  !> letters, digits, '_', '-', '.', not starting with '.'. The name becomes an HDF5 link name
  !> and an XML attribute value.
  pure function name_problem(name) result(problem)
    character(len=*), intent(in) :: name
    character(len=:), allocatable :: problem
    integer :: i
    problem = ''
    if (len(name) == 0 .or. len(name) > MAX_NAME_LENGTH) then
      problem = 'a name needs 1 to ' // str(MAX_NAME_LENGTH) // ' characters'
      return
    end if
    if (name(1:1) == '.') problem = 'a name may not start with "."'
    do i = 1, len(name)
      if (len(problem) > 0) return
      select case (name(i:i))
      case ('a':'z', 'A':'Z', '0':'9', '_', '-', '.')
      case default
        problem = 'invalid character "' // name(i:i) // '" in name "' // name // &
          '" (letters, digits, _ - . only)'
      end select
    end do
  end function name_problem

  !> An internal error "writing results <file>: <what>".
  subroutine fail(this, what, err)
    class(results_file_t), intent(in) :: this
    character(len=*), intent(in) :: what
    type(error_t), allocatable, intent(out) :: err
    call fatal_error(err, WRITING // ' ' // this%h5_path // ': ' // what)
  end subroutine fail

  !> Prefix an HDF5-layer message (which starts with the file path) with `action`.
  subroutine prefix(err, action)
    type(error_t), intent(inout) :: err
    character(len=*), intent(in) :: action
    err%message = action // ' ' // err%message
  end subroutine prefix

  !> "/frames/NNNNNN".
  pure function frame_path(number) result(path)
    integer, intent(in) :: number
    character(len=:), allocatable :: path
    path = '/frames/' // frame_label(number)
  end function frame_path

  !> The frame number with FRAME_DIGITS digits.
  pure function frame_label(number) result(label)
    integer, intent(in) :: number
    character(len=FRAME_DIGITS) :: label
    write (label, '(i6.6)') number
  end function frame_label

end module fcs_results
