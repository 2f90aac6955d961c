!> Thin, checked helpers over the HDF5 Fortran API (library module `hdf5`, HDF5 1.10).
!>
!> An `h5_file_t` holds one open file: its id, the path used in messages, and a link-creation
!> property list that creates intermediate groups. Objects are addressed by absolute paths
!> ("/frames/000003/nodal/displacement"); groups and datasets are opened and closed inside each
!> call, so the file id is the only id that outlives a call. Every HDF5 status is checked; a
!> failure becomes an `error_t` whose message starts with the file path and names the call and
!> the object, e.g. "run.h5: H5Dwrite of /frames/000003/nodal/displacement failed".
!>
!> Array order. A Fortran array `a(n1, n2)` is written with the Fortran API's dimensions
!> (n1, n2); HDF5 stores them reversed, so h5py/numpy (C order) see shape (n2, n1) with the same
!> bytes: `x(3, n_nodes)` appears as an (n_nodes, 3) table whose rows are nodes. Reading reverses
!> again, and `dataset_shape` returns Fortran order (the reverse of h5py's `.shape`).
!>
!> Stored types: reals as IEEE 64-bit little endian, default integers as 32-bit little endian
!> (64-bit if the default integer is), strings as fixed-length, NUL-padded ASCII (h5py returns
!> `bytes`). Writing to a path that already exists replaces the dataset or attribute (HDF5 does
!> not reclaim the old space; `h5repack` does).
!>
!> Full disks. A failed call whose errno says the disk is full (or the quota exceeded) or
!> memory ran out says so first ("run.h5: the disk is full (No space left on device): H5Dwrite
!> of ... failed"). Writers that must never be caught half-way by a full disk call `reserve`
!> before they write: the space is allocated on disk beforehand (posix_fallocate), so the
!> writes that follow, and the flush of the metadata they create, cannot fail for want of space;
!> the unused rest is cut off at `close`. A file whose writing failed is given up with
!> `abandon`: its id is dropped without a flush, so the file stays as its last successful flush
!> left it (HDF5's own clean-up at exit, which would flush it, is switched off with
!> H5dont_atexit).
!>
!> Library state. `h5_library_open` is idempotent: it calls `h5open_f` only when the Fortran
!> predefined types are not valid ids, and always switches off HDF5's automatic printing of its
!> error stack (the messages here replace it). `h5_library_close` calls `h5close_f` only when
!> no HDF5 object of any file is open, so HDF5's own table of open ids is the reference count and
!> independent users (results file, restart file) may open and close in any order. Files open
!> and close the library themselves; code that only uses `h5_file_t` never calls either.
module fcs_hdf5
  use hdf5, only: hid_t, hsize_t, size_t, h5open_f, h5close_f, h5eset_auto_f, &
    h5iis_valid_f, h5iget_type_f, H5I_GROUP_F, &
    h5fcreate_f, h5fopen_f, h5fclose_f, h5fflush_f, h5fget_obj_count_f, &
    H5F_ACC_TRUNC_F, H5F_ACC_RDWR_F, H5F_ACC_RDONLY_F, H5F_SCOPE_GLOBAL_F, H5F_OBJ_ALL_F, &
    h5pcreate_f, h5pclose_f, h5pset_create_inter_group_f, h5pset_file_locking_f, &
    H5P_FILE_ACCESS_F, H5P_LINK_CREATE_F, &
    h5gcreate_f, h5gopen_f, h5gclose_f, h5gget_info_f, &
    h5lexists_f, h5ldelete_f, h5lget_name_by_idx_f, H5_INDEX_NAME_F, H5_ITER_INC_F, &
    h5oopen_f, h5oclose_f, &
    h5screate_f, h5screate_simple_f, h5sclose_f, h5sget_simple_extent_ndims_f, &
    h5sget_simple_extent_dims_f, H5S_SCALAR_F, &
    h5dcreate_f, h5dopen_f, h5dclose_f, h5dwrite_f, h5dread_f, h5dget_type_f, h5dget_space_f, &
    h5acreate_by_name_f, h5aopen_by_name_f, h5aexists_by_name_f, h5adelete_by_name_f, &
    h5aclose_f, h5awrite_f, h5aread_f, h5aget_type_f, h5aget_space_f, &
    h5tcopy_f, h5tset_size_f, h5tset_strpad_f, h5tget_size_f, h5tget_class_f, h5tclose_f, &
    h5tis_variable_str_f, H5T_FORTRAN_S1, H5T_STR_NULLPAD_F, H5T_FLOAT_F, H5T_INTEGER_F, &
    H5T_STRING_F, H5T_IEEE_F64LE, H5T_STD_I32LE, H5T_STD_I64LE, H5T_NATIVE_DOUBLE, &
    h5kind_to_type, H5_REAL_KIND, H5_INTEGER_KIND, h5fget_filesize_f, h5dont_atexit_f
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, fatal_error, input_error
  use fcs_strings, only: str, string_t, dirname
  use fcs_files, only: directory_exists, current_errno, clear_errno, failure_text, &
    is_disk_full_errno, reserve_space, free_space, truncate_file, file_size
  use fcs_memory, only: memory_error, ERRNO_NO_MEMORY
  implicit none
  private
  public :: h5_file_t, h5_library_open, h5_library_close

  !> Longest link name `list_group` accepts.
  integer, parameter :: MAX_LINK_NAME = 1024
  !> Smallest space reservation [bytes] (fewer posix_fallocate calls for small writes).
  integer(i8), parameter :: MIN_RESERVATION = 65536_i8

  !> One open HDF5 file. `create` and `open` are the constructors, `close` the destructor.
  type :: h5_file_t
    !> File id, -1 when closed.
    integer(hid_t) :: id = -1
    !> Link-creation property list (creates intermediate groups), -1 when closed.
    integer(hid_t) :: link_creation = -1
    !> Path of the file as given to `create`/`open`, used in every message.
    character(len=:), allocatable :: path
    !> True when opened for writing.
    logical :: writable = .false.
    !> End of the space reserved on disk (`reserve`), 0 when nothing is reserved now; whether
    !> anything was reserved since the file was opened (the rest is cut off at `close`).
    integer(i8) :: reserved_end = 0
    logical :: reserved = .false.
  contains
    procedure :: create => h5_file_create
    procedure :: open => h5_file_open
    procedure :: close => h5_file_close
    procedure :: flush => h5_file_flush
    procedure :: reserve => h5_file_reserve
    procedure :: abandon => h5_file_abandon
    procedure :: is_open => h5_file_is_open
    procedure :: exists => h5_file_exists
    procedure :: is_group => h5_file_is_group
    procedure :: create_group => h5_file_create_group
    procedure :: delete => h5_file_delete
    procedure :: list_group => h5_file_list_group
    procedure :: dataset_shape => h5_file_dataset_shape
    procedure :: has_attribute => h5_file_has_attribute
    procedure, private :: write_real_1 => h5_file_write_real_1
    procedure, private :: write_real_2 => h5_file_write_real_2
    procedure, private :: write_real_3 => h5_file_write_real_3
    procedure, private :: write_int_1 => h5_file_write_int_1
    procedure, private :: write_int_2 => h5_file_write_int_2
    procedure, private :: write_string => h5_file_write_string
    procedure, private :: read_real_1 => h5_file_read_real_1
    procedure, private :: read_real_2 => h5_file_read_real_2
    procedure, private :: read_real_3 => h5_file_read_real_3
    procedure, private :: read_int_1 => h5_file_read_int_1
    procedure, private :: read_int_2 => h5_file_read_int_2
    procedure, private :: read_string => h5_file_read_string
    procedure, private :: write_attribute_real => h5_file_write_attribute_real
    procedure, private :: write_attribute_int => h5_file_write_attribute_int
    procedure, private :: write_attribute_string => h5_file_write_attribute_string
    procedure, private :: read_attribute_real => h5_file_read_attribute_real
    procedure, private :: read_attribute_int => h5_file_read_attribute_int
    procedure, private :: read_attribute_string => h5_file_read_attribute_string
    !> `write_dataset(path, values, err)`: real(dp) rank 1-3, integer rank 1-2, or a string.
    generic :: write_dataset => write_real_1, write_real_2, write_real_3, write_int_1, &
      write_int_2, write_string
    !> `read_dataset(path, values, err [, expected_shape])` into an allocatable of the same
    !> type and rank (strings: `read_dataset(path, text, err)`).
    generic :: read_dataset => read_real_1, read_real_2, read_real_3, read_int_1, read_int_2, &
      read_string
    !> `write_attribute(object_path, name, value, err)`: scalar real(dp), integer or string.
    generic :: write_attribute => write_attribute_real, write_attribute_int, &
      write_attribute_string
    !> `read_attribute(object_path, name, value, err)`.
    generic :: read_attribute => read_attribute_real, read_attribute_int, read_attribute_string
    procedure, private :: fail => h5_file_fail
    procedure, private :: require_open => h5_file_require_open
    procedure, private :: create_dataset => h5_file_create_dataset
    procedure, private :: finish_dataset => h5_file_finish_dataset
    procedure, private :: open_dataset => h5_file_open_dataset
    procedure, private :: create_attribute => h5_file_create_attribute
    procedure, private :: finish_attribute => h5_file_finish_attribute
    procedure, private :: open_attribute => h5_file_open_attribute
  end type h5_file_t

contains

  ! ---------------------------------------------------------------------------------------------
  ! Library
  ! ---------------------------------------------------------------------------------------------

  !> Initialise the HDF5 Fortran library if it is not yet (idempotent), and switch off HDF5's
  !> automatic printing of its error stack.
  subroutine h5_library_open(err)
    type(error_t), allocatable, intent(out) :: err
    integer :: status
    ! Before the first HDF5 call: no flush of files left open at exit (see `abandon`). Later
    ! calls fail harmlessly.
    call h5dont_atexit_f(status)
    if (.not. library_is_open()) then
      call h5open_f(status)
      if (status < 0) then
        call fatal_error(err, 'HDF5 library: h5open_f failed')
        return
      end if
    end if
    call h5eset_auto_f(0, status)
    if (status < 0) call fatal_error(err, 'HDF5 library: H5Eset_auto failed')
  end subroutine h5_library_open

  !> Close the HDF5 Fortran library if it is open and no object of any file is open any more.
  subroutine h5_library_close(err)
    type(error_t), allocatable, intent(out) :: err
    integer(size_t) :: n_open
    integer :: status
    if (.not. library_is_open()) return
    call h5fget_obj_count_f(int(H5F_OBJ_ALL_F, hid_t), H5F_OBJ_ALL_F, n_open, status)
    if (status < 0) then
      call fatal_error(err, 'HDF5 library: H5Fget_obj_count failed')
      return
    end if
    if (n_open > 0) return
    call h5close_f(status)
    if (status < 0) call fatal_error(err, 'HDF5 library: h5close_f failed')
  end subroutine h5_library_close

  !> True when the Fortran library's predefined types are valid ids (h5open_f has run).
  logical function library_is_open()
    integer :: status
    call h5iis_valid_f(H5T_NATIVE_DOUBLE, library_is_open, status)
    if (status < 0) library_is_open = .false.
  end function library_is_open

  !> Close the library after a failed create/open, keeping the first error.
  subroutine release_library()
    type(error_t), allocatable :: ignored
    call h5_library_close(ignored)
  end subroutine release_library

  ! ---------------------------------------------------------------------------------------------
  ! Files
  ! ---------------------------------------------------------------------------------------------

  !> Create (or truncate) the file `path` for writing. `file_locking=.false.` disables HDF5's
  !> file locks so that viewers can open the file while it is being written (default: HDF5's).
  subroutine h5_file_create(this, path, err, file_locking)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: file_locking
    integer(hid_t) :: access
    integer :: status, close_status, code
    call prepare_open(this, path, file_locking, access, err)
    if (allocated(err)) return
    call clear_errno()
    call h5fcreate_f(path, H5F_ACC_TRUNC_F, this%id, status, access_prp=access)
    code = current_errno()
    call h5pclose_f(access, close_status)
    if (status < 0 .or. close_status < 0) then
      call abandon_open(this)
      call fatal_error(err, path // ': H5Fcreate failed' // location_hint(path, code))
      return
    end if
    this%writable = .true.
    call finish_open(this, err)
  end subroutine h5_file_create

  !> Open the existing file `path`, for reading and writing when `writable`.
  subroutine h5_file_open(this, path, writable, err, file_locking)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    logical, intent(in) :: writable
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: file_locking
    integer(hid_t) :: access
    integer :: status, close_status, mode, code
    logical :: found
    inquire (file=path, exist=found)
    if (.not. found) then
      call input_error(err, path // ': file not found')
      return
    end if
    call prepare_open(this, path, file_locking, access, err)
    if (allocated(err)) return
    mode = H5F_ACC_RDONLY_F
    if (writable) mode = H5F_ACC_RDWR_F
    call clear_errno()
    call h5fopen_f(path, mode, this%id, status, access_prp=access)
    code = current_errno()
    call h5pclose_f(access, close_status)
    if (status < 0 .or. close_status < 0) then
      call abandon_open(this)
      if (code /= 0) then
        call fatal_error(err, path // ': H5Fopen failed: ' // failure_text(code))
      else
        call fatal_error(err, path // ': H5Fopen failed (not an HDF5 file, or locked by ' // &
          'another process)')
      end if
      return
    end if
    this%writable = writable
    call finish_open(this, err)
  end subroutine h5_file_open

  !> Common start of create/open: the object must be closed; open the library; build the
  !> file-access property list.
  subroutine prepare_open(this, path, file_locking, access, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    logical, intent(in), optional :: file_locking
    integer(hid_t), intent(out) :: access
    type(error_t), allocatable, intent(out) :: err
    integer :: status, close_status
    access = -1
    if (this%is_open()) then
      call fatal_error(err, path // ': cannot open, this object still holds ' // this%path)
      return
    end if
    this%path = path
    this%writable = .false.
    call h5_library_open(err)
    if (allocated(err)) return
    call h5pcreate_f(H5P_FILE_ACCESS_F, access, status)
    if (status < 0) then
      call release_library()
      call fatal_error(err, path // ': H5Pcreate of the file-access list failed')
      return
    end if
    if (.not. present(file_locking)) return
    call h5pset_file_locking_f(access, file_locking, .true., status)
    if (status < 0) then
      call h5pclose_f(access, close_status)
      call release_library()
      call fatal_error(err, path // ': H5Pset_file_locking failed')
    end if
  end subroutine prepare_open

  !> Common end of create/open: the link-creation list that creates intermediate groups.
  subroutine finish_open(this, err)
    class(h5_file_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    integer :: status
    type(error_t), allocatable :: ignored
    call h5pcreate_f(H5P_LINK_CREATE_F, this%link_creation, status)
    if (status >= 0) call h5pset_create_inter_group_f(this%link_creation, 1, status)
    if (status < 0) then
      call fatal_error(err, this%path // ': H5Pcreate of the link-creation list failed')
      call this%close(ignored)
    end if
  end subroutine finish_open

  !> Forget a failed create/open.
  subroutine abandon_open(this)
    class(h5_file_t), intent(inout) :: this
    this%id = -1
    this%link_creation = -1
    call release_library()
  end subroutine abandon_open

  !> Why a file could not be created: a missing directory, or what errno `code` says (a full
  !> disk named as such); a guess when errno says nothing.
  function location_hint(path, code) result(hint)
    character(len=*), intent(in) :: path
    integer, intent(in) :: code
    character(len=:), allocatable :: hint
    if (.not. directory_exists(dirname(path))) then
      hint = ' (directory ' // dirname(path) // ' does not exist)'
    else if (code /= 0) then
      hint = ': ' // failure_text(code)
    else
      hint = ' (no permission to write in ' // dirname(path) // ', disk full, or the file ' // &
        'is open elsewhere?)'
    end if
  end function location_hint

  !> Close the file (no-op when not open), then the library if nothing else is open. Space
  !> reserved beyond the file's end is given back.
  subroutine h5_file_close(this, err)
    class(h5_file_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    integer :: status, list_status
    integer(hsize_t) :: used
    logical :: trim_file
    if (.not. this%is_open()) return
    list_status = 0
    trim_file = .false.
    if (this%reserved) then
      call h5fget_filesize_f(this%id, used, status)
      trim_file = status >= 0
    end if
    if (this%link_creation >= 0) call h5pclose_f(this%link_creation, list_status)
    call clear_errno()
    call h5fclose_f(this%id, status)
    this%id = -1
    this%link_creation = -1
    this%writable = .false.
    this%reserved_end = 0
    this%reserved = .false.
    if (status < 0) then
      call release_library()
      call this%fail('H5Fclose failed', err)
      return
    end if
    if (trim_file) then
      if (file_size(this%path) > int(used, i8)) call truncate_file(this%path, int(used, i8), err)
      if (allocated(err)) return
    end if
    if (list_status < 0) then
      call release_library()
      call fatal_error(err, this%path // ': H5Pclose of the link-creation list failed')
      return
    end if
    call h5_library_close(err)
  end subroutine h5_file_close

  !> Write everything buffered for this file to disk (H5Fflush, global scope).
  subroutine h5_file_flush(this, err)
    class(h5_file_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    integer :: status
    call this%require_open('flush', err)
    if (allocated(err)) return
    call h5fflush_f(this%id, H5F_SCOPE_GLOBAL_F, status)
    ! HDF5 may cut the file back to its allocated end while flushing: reserve again next time.
    this%reserved_end = 0
    if (status < 0) call this%fail('H5Fflush failed', err)
  end subroutine h5_file_flush

  !> Make sure that the next `bytes` bytes the file grows by are allocated on disk, so that the
  !> writes and the flush that follow cannot fail on a full disk. A disk too full for them is
  !> an error now, before anything is written. Where the file system cannot reserve space, the
  !> free space is checked instead (no guarantee: another process may take it meanwhile).
  subroutine h5_file_reserve(this, bytes, err)
    class(h5_file_t), intent(inout) :: this
    integer(i8), intent(in) :: bytes
    type(error_t), allocatable, intent(out) :: err
    integer(hsize_t) :: used
    integer(i8) :: length, available
    integer :: status
    logical :: supported
    call this%require_open('reserving space', err, write=.true.)
    if (allocated(err)) return
    call h5fget_filesize_f(this%id, used, status)
    if (status < 0) then
      call this%fail('H5Fget_filesize failed', err)
      return
    end if
    if (int(used, i8) + bytes <= this%reserved_end) return
    length = max(bytes, MIN_RESERVATION)
    call reserve_space(this%path, int(used, i8), length, supported, err)
    if (allocated(err)) return
    this%reserved = .true.
    if (supported) then
      this%reserved_end = int(used, i8) + length
      return
    end if
    available = free_space(dirname(this%path))
    if (available >= 0 .and. available < bytes) call fatal_error(err, this%path // &
      ': the disk is full: ' // str(bytes) // ' bytes are needed, ' // str(available) // ' are free')
  end subroutine h5_file_reserve

  !> Give the file up after a failed write: the id is dropped without a flush or close, so the
  !> file on disk stays as the last successful flush left it (a flush now could write half of
  !> what failed). The library stays open; nothing flushes the file at exit (H5dont_atexit).
  subroutine h5_file_abandon(this)
    class(h5_file_t), intent(inout) :: this
    this%id = -1
    this%link_creation = -1
    this%writable = .false.
    this%reserved_end = 0
    this%reserved = .false.
  end subroutine h5_file_abandon

  !> True when the object holds an open file.
  pure logical function h5_file_is_open(this)
    class(h5_file_t), intent(in) :: this
    h5_file_is_open = this%id >= 0
  end function h5_file_is_open

  ! ---------------------------------------------------------------------------------------------
  ! Links and groups
  ! ---------------------------------------------------------------------------------------------

  !> True when `path` names an existing object. Each component is tested in turn (H5Lexists
  !> fails on a missing intermediate group); a failing query counts as absent.
  logical function h5_file_exists(this, path)
    class(h5_file_t), intent(in) :: this
    character(len=*), intent(in) :: path
    integer :: k, status
    logical :: found
    h5_file_exists = .false.
    if (.not. this%is_open() .or. len(path) == 0) return
    if (path == '/') then
      h5_file_exists = .true.
      return
    end if
    do k = 2, len(path) + 1
      if (k <= len(path)) then
        if (path(k:k) /= '/') cycle
      end if
      if (path(k - 1:k - 1) == '/') cycle
      call h5lexists_f(this%id, path(1:k - 1), found, status)
      if (status < 0 .or. .not. found) return
    end do
    h5_file_exists = .true.
  end function h5_file_exists

  !> True when `path` names an existing group (the root "/" included).
  logical function h5_file_is_group(this, path)
    class(h5_file_t), intent(in) :: this
    character(len=*), intent(in) :: path
    integer(hid_t) :: object
    integer :: status, object_type
    h5_file_is_group = .false.
    if (.not. this%exists(path)) return
    call h5oopen_f(this%id, path, object, status)
    if (status < 0) return
    call h5iget_type_f(object, object_type, status)
    h5_file_is_group = status >= 0 .and. object_type == H5I_GROUP_F
    call h5oclose_f(object, status)
  end function h5_file_is_group

  !> Create the group `path` and any missing intermediate groups; an existing group is fine.
  subroutine h5_file_create_group(this, path, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: group
    integer :: status
    call this%require_open('creating group ' // path, err, write=.true.)
    if (allocated(err)) return
    if (this%exists(path)) then
      if (.not. this%is_group(path)) call this%fail(path // ' exists and is not a group', err)
      return
    end if
    call h5gcreate_f(this%id, path, group, status, lcpl_id=this%link_creation)
    if (status < 0) then
      call this%fail('H5Gcreate of ' // path // ' failed', err)
      return
    end if
    call h5gclose_f(group, status)
    if (status < 0) call this%fail('H5Gclose of ' // path // ' failed', err)
  end subroutine h5_file_create_group

  !> Remove the link `path` (a dataset or a whole group). The space is not reclaimed.
  subroutine h5_file_delete(this, path, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    integer :: status
    call this%require_open('deleting ' // path, err, write=.true.)
    if (allocated(err)) return
    call h5ldelete_f(this%id, path, status)
    if (status < 0) call this%fail('H5Ldelete of ' // path // ' failed', err)
  end subroutine h5_file_delete

  !> Names of the links in group `path`, in increasing name order.
  subroutine h5_file_list_group(this, path, names, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    type(string_t), allocatable, intent(out) :: names(:)
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: group
    integer :: status, close_status, storage_type, n_links, max_order, i
    integer(size_t) :: name_length
    character(len=MAX_LINK_NAME) :: buffer
    allocate (names(0))
    call this%require_open('listing ' // path, err)
    if (allocated(err)) return
    if (.not. this%is_group(path)) then
      call this%fail('group ' // path // ' not found', err)
      return
    end if
    call h5gopen_f(this%id, path, group, status)
    if (status < 0) then
      call this%fail('H5Gopen of ' // path // ' failed', err)
      return
    end if
    call h5gget_info_f(group, storage_type, n_links, max_order, status)
    call h5gclose_f(group, close_status)
    if (status < 0 .or. close_status < 0) then
      call this%fail('H5Gget_info of ' // path // ' failed', err)
      return
    end if
    deallocate (names)
    allocate (names(n_links))
    do i = 1, n_links
      call h5lget_name_by_idx_f(this%id, path, H5_INDEX_NAME_F, H5_ITER_INC_F, &
        int(i - 1, hsize_t), buffer, status, size=name_length)
      if (status < 0 .or. name_length > len(buffer)) then
        call this%fail('H5Lget_name_by_idx in ' // path // ' failed (link ' // str(i) // ')', err)
        return
      end if
      names(i)%s = buffer(1:int(name_length))
    end do
  end subroutine h5_file_list_group

  ! ---------------------------------------------------------------------------------------------
  ! Datasets: write
  ! ---------------------------------------------------------------------------------------------

  !> Write a real(dp) vector as a 1-D dataset.
  subroutine h5_file_write_real_1(this, path, values, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: dataset
    integer(hsize_t) :: dims(1)
    integer :: status
    dims = int(shape(values), hsize_t)
    call this%create_dataset(path, H5T_IEEE_F64LE, dims, dataset, err)
    if (allocated(err)) return
    status = 0
    if (size(values) > 0) call h5dwrite_f(dataset, real_memory_type(), values, dims, status)
    call this%finish_dataset('H5Dwrite', path, dataset, status, err)
  end subroutine h5_file_write_real_1

  !> Write a real(dp) matrix a(n1, n2); h5py sees shape (n2, n1).
  subroutine h5_file_write_real_2(this, path, values, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: dataset
    integer(hsize_t) :: dims(2)
    integer :: status
    dims = int(shape(values), hsize_t)
    call this%create_dataset(path, H5T_IEEE_F64LE, dims, dataset, err)
    if (allocated(err)) return
    status = 0
    if (size(values) > 0) call h5dwrite_f(dataset, real_memory_type(), values, dims, status)
    call this%finish_dataset('H5Dwrite', path, dataset, status, err)
  end subroutine h5_file_write_real_2

  !> Write a real(dp) array a(n1, n2, n3); h5py sees shape (n3, n2, n1).
  subroutine h5_file_write_real_3(this, path, values, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: dataset
    integer(hsize_t) :: dims(3)
    integer :: status
    dims = int(shape(values), hsize_t)
    call this%create_dataset(path, H5T_IEEE_F64LE, dims, dataset, err)
    if (allocated(err)) return
    status = 0
    if (size(values) > 0) call h5dwrite_f(dataset, real_memory_type(), values, dims, status)
    call this%finish_dataset('H5Dwrite', path, dataset, status, err)
  end subroutine h5_file_write_real_3

  !> Write a default-integer vector as a 1-D dataset.
  subroutine h5_file_write_int_1(this, path, values, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(in) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: dataset
    integer(hsize_t) :: dims(1)
    integer :: status
    dims = int(shape(values), hsize_t)
    call this%create_dataset(path, integer_file_type(), dims, dataset, err)
    if (allocated(err)) return
    status = 0
    if (size(values) > 0) call h5dwrite_f(dataset, integer_memory_type(), values, dims, status)
    call this%finish_dataset('H5Dwrite', path, dataset, status, err)
  end subroutine h5_file_write_int_1

  !> Write a default-integer matrix a(n1, n2); h5py sees shape (n2, n1).
  subroutine h5_file_write_int_2(this, path, values, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: dataset
    integer(hsize_t) :: dims(2)
    integer :: status
    dims = int(shape(values), hsize_t)
    call this%create_dataset(path, integer_file_type(), dims, dataset, err)
    if (allocated(err)) return
    status = 0
    if (size(values) > 0) call h5dwrite_f(dataset, integer_memory_type(), values, dims, status)
    call this%finish_dataset('H5Dwrite', path, dataset, status, err)
  end subroutine h5_file_write_int_2

  !> Write a scalar string dataset (fixed length, NUL padded).
  subroutine h5_file_write_string(this, path, text, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    character(len=*), intent(in) :: text
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: dataset, string_type
    integer(hsize_t) :: dims(0)
    integer :: status, close_status
    call make_string_type(len(text), string_type, status)
    if (status < 0) then
      call this%fail('creating a string type for ' // path // ' failed', err)
      return
    end if
    call this%create_dataset(path, string_type, dims, dataset, err)
    if (.not. allocated(err)) then
      call h5dwrite_f(dataset, string_type, padded(text), dims, status)
      call this%finish_dataset('H5Dwrite', path, dataset, status, err)
    end if
    call h5tclose_f(string_type, close_status)
    if (close_status < 0 .and. .not. allocated(err)) then
      call this%fail('H5Tclose of the string type of ' // path // ' failed', err)
    end if
  end subroutine h5_file_write_string

  !> Create the dataset `path` (replacing an existing one; intermediate groups are created) with
  !> the given file type and Fortran-order dimensions (none: scalar).
  subroutine h5_file_create_dataset(this, path, file_type, dims, dataset, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer(hid_t), intent(in) :: file_type
    integer(hsize_t), intent(in) :: dims(:)
    integer(hid_t), intent(out) :: dataset
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: space
    integer :: status, close_status
    dataset = -1
    call this%require_open('writing ' // path, err, write=.true.)
    if (allocated(err)) return
    if (this%exists(path)) then
      call h5ldelete_f(this%id, path, status)
      if (status < 0) then
        call this%fail('H5Ldelete of the previous ' // path // ' failed', err)
        return
      end if
    end if
    if (size(dims) == 0) then
      call h5screate_f(H5S_SCALAR_F, space, status)
    else
      call h5screate_simple_f(size(dims), dims, space, status)
    end if
    if (status < 0) then
      call this%fail('H5Screate for ' // path // ' failed', err)
      return
    end if
    call h5dcreate_f(this%id, path, file_type, space, dataset, status, &
      lcpl_id=this%link_creation)
    call h5sclose_f(space, close_status)
    if (status < 0) then
      dataset = -1
      call this%fail('H5Dcreate of ' // path // ' failed', err)
    else if (close_status < 0) then
      call h5dclose_f(dataset, status)
      dataset = -1
      call this%fail('H5Sclose for ' // path // ' failed', err)
    end if
  end subroutine h5_file_create_dataset

  !> After H5Dwrite/H5Dread returned `status`: close the dataset and report the first failure.
  subroutine h5_file_finish_dataset(this, operation, path, dataset, status, err)
    class(h5_file_t), intent(in) :: this
    character(len=*), intent(in) :: operation, path
    integer(hid_t), intent(in) :: dataset
    integer, intent(in) :: status
    type(error_t), allocatable, intent(out) :: err
    integer :: close_status
    call h5dclose_f(dataset, close_status)
    if (status < 0) then
      call this%fail(operation // ' of ' // path // ' failed', err)
    else if (close_status < 0) then
      call this%fail('H5Dclose of ' // path // ' failed', err)
    end if
  end subroutine h5_file_finish_dataset

  ! ---------------------------------------------------------------------------------------------
  ! Datasets: read
  ! ---------------------------------------------------------------------------------------------

  !> Read a 1-D real dataset; with `expected_shape`, a different shape is an error.
  subroutine h5_file_read_real_1(this, path, values, err, expected_shape)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), allocatable, intent(out) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    integer, intent(in), optional :: expected_shape(:)
    integer(hid_t) :: dataset
    integer(hsize_t) :: dims(1)
    integer :: status
    call this%open_dataset(path, H5T_FLOAT_F, dataset, dims, err, expected_shape)
    if (allocated(err)) return
    allocate (values(dims(1)))
    status = 0
    if (size(values) > 0) call h5dread_f(dataset, real_memory_type(), values, dims, status)
    call this%finish_dataset('H5Dread', path, dataset, status, err)
  end subroutine h5_file_read_real_1

  !> Read a 2-D real dataset (Fortran shape: the reverse of h5py's).
  subroutine h5_file_read_real_2(this, path, values, err, expected_shape)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), allocatable, intent(out) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    integer, intent(in), optional :: expected_shape(:)
    integer(hid_t) :: dataset
    integer(hsize_t) :: dims(2)
    integer :: status
    call this%open_dataset(path, H5T_FLOAT_F, dataset, dims, err, expected_shape)
    if (allocated(err)) return
    allocate (values(dims(1), dims(2)))
    status = 0
    if (size(values) > 0) call h5dread_f(dataset, real_memory_type(), values, dims, status)
    call this%finish_dataset('H5Dread', path, dataset, status, err)
  end subroutine h5_file_read_real_2

  !> Read a 3-D real dataset (Fortran shape: the reverse of h5py's).
  subroutine h5_file_read_real_3(this, path, values, err, expected_shape)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), allocatable, intent(out) :: values(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    integer, intent(in), optional :: expected_shape(:)
    integer(hid_t) :: dataset
    integer(hsize_t) :: dims(3)
    integer :: status
    call this%open_dataset(path, H5T_FLOAT_F, dataset, dims, err, expected_shape)
    if (allocated(err)) return
    allocate (values(dims(1), dims(2), dims(3)))
    status = 0
    if (size(values) > 0) call h5dread_f(dataset, real_memory_type(), values, dims, status)
    call this%finish_dataset('H5Dread', path, dataset, status, err)
  end subroutine h5_file_read_real_3

  !> Read a 1-D integer dataset.
  subroutine h5_file_read_int_1(this, path, values, err, expected_shape)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, allocatable, intent(out) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    integer, intent(in), optional :: expected_shape(:)
    integer(hid_t) :: dataset
    integer(hsize_t) :: dims(1)
    integer :: status
    call this%open_dataset(path, H5T_INTEGER_F, dataset, dims, err, expected_shape)
    if (allocated(err)) return
    allocate (values(dims(1)))
    status = 0
    if (size(values) > 0) call h5dread_f(dataset, integer_memory_type(), values, dims, status)
    call this%finish_dataset('H5Dread', path, dataset, status, err)
  end subroutine h5_file_read_int_1

  !> Read a 2-D integer dataset (Fortran shape: the reverse of h5py's).
  subroutine h5_file_read_int_2(this, path, values, err, expected_shape)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, allocatable, intent(out) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    integer, intent(in), optional :: expected_shape(:)
    integer(hid_t) :: dataset
    integer(hsize_t) :: dims(2)
    integer :: status
    call this%open_dataset(path, H5T_INTEGER_F, dataset, dims, err, expected_shape)
    if (allocated(err)) return
    allocate (values(dims(1), dims(2)))
    status = 0
    if (size(values) > 0) call h5dread_f(dataset, integer_memory_type(), values, dims, status)
    call this%finish_dataset('H5Dread', path, dataset, status, err)
  end subroutine h5_file_read_int_2

  !> Read a scalar fixed-length string dataset; trailing NULs are removed.
  subroutine h5_file_read_string(this, path, text, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    character(len=:), allocatable, intent(out) :: text
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: dataset, stored_type, memory_type
    integer(hsize_t) :: dims(0)
    integer :: status, close_status, length
    character(len=:), allocatable :: what, buffer
    text = ''
    call this%open_dataset(path, H5T_STRING_F, dataset, dims, err)
    if (allocated(err)) return
    call h5dget_type_f(dataset, stored_type, status)
    what = 'H5Dget_type'
    if (status >= 0) call string_memory_type(stored_type, length, memory_type, what)
    if (len(what) == 0) then
      allocate (character(len=max(length, 1)) :: buffer)
      call h5dread_f(dataset, memory_type, buffer, dims, status)
      call h5tclose_f(memory_type, close_status)
      if (close_status < 0) what = 'H5Tclose of the string type'
      if (status < 0) what = 'H5Dread'
      text = unpadded(buffer)
    end if
    status = 0
    if (len(what) > 0) status = -1
    call this%finish_dataset(what, path, dataset, status, err)
  end subroutine h5_file_read_string

  !> Open dataset `path` and check its type class and rank (size(dims)), and its Fortran-order
  !> shape against `expected_shape` if present. On success `dataset` is open and `dims` holds
  !> the shape; on failure nothing is left open.
  subroutine h5_file_open_dataset(this, path, expected_class, dataset, dims, err, expected_shape)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(in) :: expected_class
    integer(hid_t), intent(out) :: dataset
    integer(hsize_t), intent(out) :: dims(:)
    type(error_t), allocatable, intent(out) :: err
    integer, intent(in), optional :: expected_shape(:)
    integer(hsize_t), allocatable :: actual(:)
    integer :: status, type_class
    character(len=:), allocatable :: what
    dataset = -1
    dims = 0
    call this%require_open('reading ' // path, err)
    if (allocated(err)) return
    if (.not. this%exists(path)) then
      call input_error(err, this%path // ': dataset ' // path // ' not found')
      return
    end if
    call h5dopen_f(this%id, path, dataset, status)
    if (status < 0) then
      dataset = -1
      call this%fail('H5Dopen of ' // path // ' failed', err)
      return
    end if
    call dataset_layout(dataset, type_class, actual, what)
    if (len(what) > 0) then
      what = what // ' of ' // path // ' failed'
    else if (type_class /= expected_class) then
      what = path // ' holds ' // class_name(type_class) // ' values, expected ' // &
        class_name(expected_class)
    else if (size(actual) /= size(dims)) then
      what = path // ' has rank ' // str(size(actual)) // ', expected ' // str(size(dims))
    else if (present(expected_shape)) then
      if (any(actual /= int(expected_shape, hsize_t))) what = path // ' has shape ' // &
        shape_text(actual) // ', expected ' // shape_text(int(expected_shape, hsize_t))
    end if
    if (len(what) == 0) then
      dims = actual
      return
    end if
    call h5dclose_f(dataset, status)
    dataset = -1
    call input_error(err, this%path // ': ' // what)
  end subroutine h5_file_open_dataset

  !> Fortran-order shape of dataset `path` (the reverse of h5py's `.shape`; empty for a scalar).
  subroutine h5_file_dataset_shape(this, path, dims, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer(i8), allocatable, intent(out) :: dims(:)
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: dataset
    integer(hsize_t), allocatable :: actual(:)
    integer :: status, type_class
    character(len=:), allocatable :: what
    allocate (dims(0))
    call this%require_open('reading ' // path, err)
    if (allocated(err)) return
    if (.not. this%exists(path)) then
      call input_error(err, this%path // ': dataset ' // path // ' not found')
      return
    end if
    call h5dopen_f(this%id, path, dataset, status)
    if (status < 0) then
      call this%fail('H5Dopen of ' // path // ' failed', err)
      return
    end if
    call dataset_layout(dataset, type_class, actual, what)
    call h5dclose_f(dataset, status)
    if (len(what) > 0) then
      call this%fail(what // ' of ' // path // ' failed', err)
    else if (status < 0) then
      call this%fail('H5Dclose of ' // path // ' failed', err)
    else
      dims = int(actual, i8)
    end if
  end subroutine h5_file_dataset_shape

  !> Type class and Fortran-order dimensions of an open dataset; `what` names the failing call
  !> (empty on success).
  subroutine dataset_layout(dataset, type_class, dims, what)
    integer(hid_t), intent(in) :: dataset
    integer, intent(out) :: type_class
    integer(hsize_t), allocatable, intent(out) :: dims(:)
    character(len=:), allocatable, intent(out) :: what
    integer(hid_t) :: stored_type, space
    integer(hsize_t), allocatable :: max_dims(:)
    integer :: status, close_status
    type_class = -1
    allocate (dims(0))
    what = 'H5Dget_type'
    call h5dget_type_f(dataset, stored_type, status)
    if (status < 0) return
    what = 'H5Tget_class'
    call h5tget_class_f(stored_type, type_class, status)
    call h5tclose_f(stored_type, close_status)
    if (status < 0 .or. close_status < 0) return
    what = 'H5Dget_space'
    call h5dget_space_f(dataset, space, status)
    if (status < 0) return
    call space_dims(space, dims, max_dims, what)
  end subroutine dataset_layout

  !> Dimensions of a dataspace, which is closed afterwards; `what` is empty on success.
  subroutine space_dims(space, dims, max_dims, what)
    integer(hid_t), intent(in) :: space
    integer(hsize_t), allocatable, intent(out) :: dims(:), max_dims(:)
    character(len=:), allocatable, intent(inout) :: what
    integer :: status, rank, close_status
    what = 'H5Sget_simple_extent_ndims'
    call h5sget_simple_extent_ndims_f(space, rank, status)
    if (status >= 0) then
      allocate (dims(rank), max_dims(rank))
      what = 'H5Sget_simple_extent_dims'
      if (rank > 0) call h5sget_simple_extent_dims_f(space, dims, max_dims, status)
    end if
    call h5sclose_f(space, close_status)
    if (status >= 0 .and. close_status >= 0) what = ''
    if (.not. allocated(dims)) allocate (dims(0), max_dims(0))
  end subroutine space_dims

  ! ---------------------------------------------------------------------------------------------
  ! Attributes
  ! ---------------------------------------------------------------------------------------------

  !> True when object `object_path` has attribute `name` (a failing query counts as absent).
  logical function h5_file_has_attribute(this, object_path, name)
    class(h5_file_t), intent(in) :: this
    character(len=*), intent(in) :: object_path, name
    integer :: status
    h5_file_has_attribute = .false.
    if (.not. this%exists(object_path)) return
    call h5aexists_by_name_f(this%id, object_path, name, h5_file_has_attribute, status)
    if (status < 0) h5_file_has_attribute = .false.
  end function h5_file_has_attribute

  !> Write (or replace) the scalar real attribute `name` of object `object_path`.
  subroutine h5_file_write_attribute_real(this, object_path, name, value, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: object_path, name
    real(dp), intent(in) :: value
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: attribute
    integer(hsize_t), parameter :: dims(1) = 1
    integer :: status
    call this%create_attribute(object_path, name, H5T_IEEE_F64LE, attribute, err)
    if (allocated(err)) return
    call h5awrite_f(attribute, real_memory_type(), value, dims, status)
    call this%finish_attribute('H5Awrite', object_path, name, attribute, status, err)
  end subroutine h5_file_write_attribute_real

  !> Write (or replace) the scalar integer attribute `name` of object `object_path`.
  subroutine h5_file_write_attribute_int(this, object_path, name, value, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: object_path, name
    integer, intent(in) :: value
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: attribute
    integer(hsize_t), parameter :: dims(1) = 1
    integer :: status
    call this%create_attribute(object_path, name, integer_file_type(), attribute, err)
    if (allocated(err)) return
    call h5awrite_f(attribute, integer_memory_type(), value, dims, status)
    call this%finish_attribute('H5Awrite', object_path, name, attribute, status, err)
  end subroutine h5_file_write_attribute_int

  !> Write (or replace) the string attribute `name` of object `object_path`.
  subroutine h5_file_write_attribute_string(this, object_path, name, value, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: object_path, name
    character(len=*), intent(in) :: value
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: attribute, string_type
    integer(hsize_t), parameter :: dims(1) = 1
    integer :: status, close_status
    call make_string_type(len(value), string_type, status)
    if (status < 0) then
      call this%fail('creating a string type for attribute ' // name // ' failed', err)
      return
    end if
    call this%create_attribute(object_path, name, string_type, attribute, err)
    if (.not. allocated(err)) then
      call h5awrite_f(attribute, string_type, padded(value), dims, status)
      call this%finish_attribute('H5Awrite', object_path, name, attribute, status, err)
    end if
    call h5tclose_f(string_type, close_status)
    if (close_status < 0 .and. .not. allocated(err)) then
      call this%fail('H5Tclose of the type of attribute ' // name // ' failed', err)
    end if
  end subroutine h5_file_write_attribute_string

  !> Read the scalar real attribute `name` of object `object_path`.
  subroutine h5_file_read_attribute_real(this, object_path, name, value, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: object_path, name
    real(dp), intent(out) :: value
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: attribute
    integer(hsize_t), parameter :: dims(1) = 1
    integer :: status
    value = 0.0_dp
    call this%open_attribute(object_path, name, H5T_FLOAT_F, attribute, err)
    if (allocated(err)) return
    call h5aread_f(attribute, real_memory_type(), value, dims, status)
    call this%finish_attribute('H5Aread', object_path, name, attribute, status, err)
  end subroutine h5_file_read_attribute_real

  !> Read the scalar integer attribute `name` of object `object_path`.
  subroutine h5_file_read_attribute_int(this, object_path, name, value, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: object_path, name
    integer, intent(out) :: value
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: attribute
    integer(hsize_t), parameter :: dims(1) = 1
    integer :: status
    value = 0
    call this%open_attribute(object_path, name, H5T_INTEGER_F, attribute, err)
    if (allocated(err)) return
    call h5aread_f(attribute, integer_memory_type(), value, dims, status)
    call this%finish_attribute('H5Aread', object_path, name, attribute, status, err)
  end subroutine h5_file_read_attribute_int

  !> Read the fixed-length string attribute `name` of object `object_path`.
  subroutine h5_file_read_attribute_string(this, object_path, name, value, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: object_path, name
    character(len=:), allocatable, intent(out) :: value
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: attribute, stored_type, memory_type
    integer(hsize_t), parameter :: dims(1) = 1
    integer :: status, close_status, length
    character(len=:), allocatable :: what, buffer
    value = ''
    call this%open_attribute(object_path, name, H5T_STRING_F, attribute, err)
    if (allocated(err)) return
    call h5aget_type_f(attribute, stored_type, status)
    what = 'H5Aget_type'
    if (status >= 0) call string_memory_type(stored_type, length, memory_type, what)
    if (len(what) == 0) then
      allocate (character(len=max(length, 1)) :: buffer)
      call h5aread_f(attribute, memory_type, buffer, dims, status)
      call h5tclose_f(memory_type, close_status)
      if (close_status < 0) what = 'H5Tclose of the string type'
      if (status < 0) what = 'H5Aread'
      value = unpadded(buffer)
    end if
    status = 0
    if (len(what) > 0) status = -1
    call this%finish_attribute(what, object_path, name, attribute, status, err)
  end subroutine h5_file_read_attribute_string

  !> Create attribute `name` (scalar, of `file_type`) on `object_path`, replacing an old one.
  subroutine h5_file_create_attribute(this, object_path, name, file_type, attribute, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: object_path, name
    integer(hid_t), intent(in) :: file_type
    integer(hid_t), intent(out) :: attribute
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: space
    integer :: status, close_status
    attribute = -1
    call this%require_open('writing attribute ' // name // ' of ' // object_path, err, &
      write=.true.)
    if (allocated(err)) return
    if (.not. this%exists(object_path)) then
      call this%fail('attribute ' // name // ': object ' // object_path // ' not found', err)
      return
    end if
    if (this%has_attribute(object_path, name)) then
      call h5adelete_by_name_f(this%id, object_path, name, status)
      if (status < 0) then
        call this%fail('H5Adelete of ' // object_path // ' attribute ' // name // ' failed', err)
        return
      end if
    end if
    call h5screate_f(H5S_SCALAR_F, space, status)
    if (status < 0) then
      call this%fail('H5Screate for attribute ' // name // ' failed', err)
      return
    end if
    call h5acreate_by_name_f(this%id, object_path, name, file_type, space, attribute, status)
    call h5sclose_f(space, close_status)
    if (status < 0 .or. close_status < 0) then
      if (status >= 0) call h5aclose_f(attribute, close_status)
      attribute = -1
      call this%fail('H5Acreate of ' // object_path // ' attribute ' // name // ' failed', err)
    end if
  end subroutine h5_file_create_attribute

  !> Open attribute `name` of `object_path` and check its type class and that it is scalar.
  subroutine h5_file_open_attribute(this, object_path, name, expected_class, attribute, err)
    class(h5_file_t), intent(inout) :: this
    character(len=*), intent(in) :: object_path, name
    integer, intent(in) :: expected_class
    integer(hid_t), intent(out) :: attribute
    type(error_t), allocatable, intent(out) :: err
    integer(hid_t) :: stored_type, space
    integer(hsize_t), allocatable :: dims(:), max_dims(:)
    integer :: status, type_class, close_status
    character(len=:), allocatable :: what
    attribute = -1
    call this%require_open('reading attribute ' // name // ' of ' // object_path, err)
    if (allocated(err)) return
    if (.not. this%has_attribute(object_path, name)) then
      call input_error(err, this%path // ': ' // object_path // ' has no attribute ' // name)
      return
    end if
    call h5aopen_by_name_f(this%id, object_path, name, attribute, status)
    if (status < 0) then
      attribute = -1
      call this%fail('H5Aopen of ' // object_path // ' attribute ' // name // ' failed', err)
      return
    end if
    type_class = -1
    what = 'H5Aget_type'
    call h5aget_type_f(attribute, stored_type, status)
    if (status >= 0) then
      what = 'H5Tget_class'
      call h5tget_class_f(stored_type, type_class, status)
      call h5tclose_f(stored_type, close_status)
      if (status >= 0 .and. close_status >= 0) then
        what = 'H5Aget_space'
        call h5aget_space_f(attribute, space, status)
        if (status >= 0) call space_dims(space, dims, max_dims, what)
      end if
    end if
    if (len(what) > 0) then
      what = what // ' of ' // object_path // ' attribute ' // name // ' failed'
    else if (type_class /= expected_class) then
      what = object_path // ' attribute ' // name // ' holds ' // class_name(type_class) // &
        ' values, expected ' // class_name(expected_class)
    else if (product(dims) /= 1) then
      what = object_path // ' attribute ' // name // ' is not a scalar'
    end if
    if (len(what) == 0) return
    call h5aclose_f(attribute, status)
    attribute = -1
    call input_error(err, this%path // ': ' // what)
  end subroutine h5_file_open_attribute

  !> After H5Awrite/H5Aread returned `status`: close the attribute, report the first failure.
  subroutine h5_file_finish_attribute(this, operation, object_path, name, attribute, status, err)
    class(h5_file_t), intent(in) :: this
    character(len=*), intent(in) :: operation, object_path, name
    integer(hid_t), intent(in) :: attribute
    integer, intent(in) :: status
    type(error_t), allocatable, intent(out) :: err
    integer :: close_status
    call h5aclose_f(attribute, close_status)
    if (status < 0) then
      call this%fail(operation // ' of ' // object_path // ' attribute ' // name // ' failed', &
        err)
    else if (close_status < 0) then
      call this%fail('H5Aclose of ' // object_path // ' attribute ' // name // ' failed', err)
    end if
  end subroutine h5_file_finish_attribute

  ! ---------------------------------------------------------------------------------------------
  ! Small helpers
  ! ---------------------------------------------------------------------------------------------

  !> An internal error "<file>: <what>", which first names a full disk or exhausted memory when
  !> the failed call left that errno.
  subroutine h5_file_fail(this, what, err)
    class(h5_file_t), intent(in) :: this
    character(len=*), intent(in) :: what
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: path
    integer :: code
    code = current_errno()
    path = 'HDF5 file'
    if (allocated(this%path)) path = this%path
    if (is_disk_full_errno(code)) then
      call fatal_error(err, path // ': ' // failure_text(code) // ': ' // what)
    else if (code == ERRNO_NO_MEMORY) then
      call memory_error(err, 'using ' // path // ' (' // what // ')', 0_i8)
    else
      call fatal_error(err, path // ': ' // what)
    end if
  end subroutine h5_file_fail

  !> Error unless the file is open (and writable when `write`).
  subroutine h5_file_require_open(this, action, err, write)
    class(h5_file_t), intent(in) :: this
    character(len=*), intent(in) :: action
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: write
    call clear_errno()
    if (.not. this%is_open()) then
      call this%fail(action // ': the file is not open', err)
      return
    end if
    if (present(write)) then
      if (write .and. .not. this%writable) call this%fail(action // ': the file is read-only', err)
    end if
  end subroutine h5_file_require_open

  !> HDF5 memory type of real(dp).
  integer(hid_t) function real_memory_type()
    real_memory_type = h5kind_to_type(dp, H5_REAL_KIND)
  end function real_memory_type

  !> HDF5 memory type of the default integer.
  integer(hid_t) function integer_memory_type()
    integer_memory_type = h5kind_to_type(kind(0), H5_INTEGER_KIND)
  end function integer_memory_type

  !> Stored type of default integers: little-endian, of the default integer's width.
  integer(hid_t) function integer_file_type()
    if (bit_size(0) == 32) then
      integer_file_type = H5T_STD_I32LE
    else
      integer_file_type = H5T_STD_I64LE
    end if
  end function integer_file_type

  !> A fixed-length, NUL-padded string type of `length` characters (at least one).
  subroutine make_string_type(length, string_type, status)
    integer, intent(in) :: length
    integer(hid_t), intent(out) :: string_type
    integer, intent(out) :: status
    integer :: close_status
    call h5tcopy_f(H5T_FORTRAN_S1, string_type, status)
    if (status < 0) return
    call h5tset_size_f(string_type, int(max(length, 1), size_t), status)
    if (status >= 0) call h5tset_strpad_f(string_type, H5T_STR_NULLPAD_F, status)
    if (status < 0) call h5tclose_f(string_type, close_status)
  end subroutine make_string_type

  !> Length of a fixed-length string type; `what` names the problem (empty when fine).
  subroutine fixed_string_length(string_type, length, what)
    integer(hid_t), intent(in) :: string_type
    integer, intent(out) :: length
    character(len=:), allocatable, intent(inout) :: what
    logical :: variable
    integer(size_t) :: size_bytes
    integer :: status
    length = 0
    call h5tis_variable_str_f(string_type, variable, status)
    if (status < 0) then
      what = 'H5Tis_variable_str'
      return
    end if
    if (variable) then
      what = 'reading (variable-length strings are not supported)'
      return
    end if
    call h5tget_size_f(string_type, size_bytes, status)
    if (status < 0) then
      what = 'H5Tget_size'
      return
    end if
    length = int(size_bytes)
    what = ''
  end subroutine fixed_string_length

  !> Given the stored type of a string object (closed here), its length and a memory type of
  !> that length (to be closed by the caller); `what` names a failure (empty on success).
  subroutine string_memory_type(stored_type, length, memory_type, what)
    integer(hid_t), intent(in) :: stored_type
    integer, intent(out) :: length
    integer(hid_t), intent(out) :: memory_type
    character(len=:), allocatable, intent(inout) :: what
    integer :: status
    memory_type = -1
    call fixed_string_length(stored_type, length, what)
    call h5tclose_f(stored_type, status)
    if (len(what) > 0) return
    if (status < 0) then
      what = 'H5Tclose of the stored string type'
      return
    end if
    call make_string_type(length, memory_type, status)
    if (status < 0) what = 'creating a string type'
  end subroutine string_memory_type

  !> `text`, or a single NUL for the empty string (HDF5 string types have length >= 1).
  pure function padded(text) result(out)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: out
    if (len(text) == 0) then
      out = achar(0)
    else
      out = text
    end if
  end function padded

  !> `text` without its trailing NUL padding.
  pure function unpadded(text) result(out)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: out
    integer :: last
    last = len(text)
    do while (last > 0)
      if (text(last:last) /= achar(0)) exit
      last = last - 1
    end do
    out = text(1:last)
  end function unpadded

  !> Name of an HDF5 type class, for messages.
  function class_name(type_class) result(name)
    integer, intent(in) :: type_class
    character(len=:), allocatable :: name
    if (type_class == H5T_FLOAT_F) then
      name = 'floating-point'
    else if (type_class == H5T_INTEGER_F) then
      name = 'integer'
    else if (type_class == H5T_STRING_F) then
      name = 'string'
    else
      name = 'other (class ' // str(type_class) // ')'
    end if
  end function class_name

  !> "(n1, n2, ...)" in Fortran order.
  function shape_text(dims) result(text)
    integer(hsize_t), intent(in) :: dims(:)
    character(len=:), allocatable :: text
    integer :: i
    text = '('
    do i = 1, size(dims)
      if (i > 1) text = text // ', '
      text = text // str(int(dims(i), i8))
    end do
    text = text // ')'
  end function shape_text

end module fcs_hdf5
