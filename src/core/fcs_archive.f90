!> A checksummed archive of named arrays: what each owner of run state writes to save itself
!> (`save(archive, err)`) and reads back to load itself (`load(archive, err)`), the pattern of
!> fpm's `serializable_t` (`dump`/`load`). A checkpoint is then "save every owner" and a
!> restart "load every owner"; no owner reads another's arrays (doc/architecture.md, "Run
!> state").
!>
!> The archive is abstract so that the owners (contact, elements, state, monitors) depend on
!> core only: the storage is a backend's business (`fcs_h5_archive` in io/ stores each record
!> as an HDF5 dataset). What this type adds to every backend:
!> - every record carries a checksum of its data (FNV-1a with xor-shift, `fcs_checksum`),
!>   written as its `checksum` attribute and verified when it is read back: a damaged record
!>   is an input error naming it ("<path>: checksum mismatch ...: the checkpoint is damaged");
!> - `total` runs over the checksums of every record in the order written or read, so that
!>   the file can carry a checksum over all of them (`fcs_checkpoint`);
!> - reading checks the shape against the one the loading owner expects.
!>
!> Paths are absolute (`/state/u`); `group` creates a group when writing and does nothing when
!> reading, so that save and load can share the code that names the records.
module fcs_archive
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error
  use fcs_checksum, only: checksum_t, checksum_text
  implicit none
  private
  public :: archive_t

  type, abstract :: archive_t
    !> Running checksum over the checksums of every record written or read, in order.
    type(checksum_t) :: total
  contains
    procedure, private :: put_real_1 => archive_put_real_1
    procedure, private :: put_real_2 => archive_put_real_2
    procedure, private :: put_real_3 => archive_put_real_3
    procedure, private :: put_int_1 => archive_put_int_1
    procedure, private :: get_real_1 => archive_get_real_1
    procedure, private :: get_real_2 => archive_get_real_2
    procedure, private :: get_real_3 => archive_get_real_3
    procedure, private :: get_int_1 => archive_get_int_1
    !> `put(path, values, err)`: real(dp) rank 1-3 or integer rank 1, with its checksum.
    generic :: put => put_real_1, put_real_2, put_real_3, put_int_1
    !> `get(path, values, err)` into an array of the shape the record must have.
    generic :: get => get_real_1, get_real_2, get_real_3, get_int_1
    procedure :: get_columns => archive_get_columns
    procedure :: put_flag => archive_put_flag
    procedure :: get_flag => archive_get_flag
    procedure :: verify => archive_verify
    !> Backend: storage of records and attributes.
    procedure(is_writing_interface), deferred :: is_writing
    procedure(exists_interface), deferred :: exists
    procedure(group_interface), deferred :: group
    procedure(columns_interface), deferred :: columns
    procedure(write_real_1_interface), deferred :: write_real_1
    procedure(write_real_2_interface), deferred :: write_real_2
    procedure(write_real_3_interface), deferred :: write_real_3
    procedure(write_int_1_interface), deferred :: write_int_1
    procedure(read_real_1_interface), deferred :: read_real_1
    procedure(read_real_2_interface), deferred :: read_real_2
    procedure(read_real_3_interface), deferred :: read_real_3
    procedure(read_int_1_interface), deferred :: read_int_1
    procedure(write_text_interface), deferred :: write_text
    procedure(read_text_interface), deferred :: read_text
    procedure(write_integer_interface), deferred :: write_integer
    procedure(read_integer_interface), deferred :: read_integer
  end type archive_t

  abstract interface
    !> True while saving, false while loading.
    logical function is_writing_interface(this)
      import :: archive_t
      class(archive_t), intent(in) :: this
    end function is_writing_interface

    !> Whether a record or group `path` exists.
    logical function exists_interface(this, path)
      import :: archive_t
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path
    end function exists_interface

    !> Create group `path` when writing (nothing when reading).
    subroutine group_interface(this, path, err)
      import :: archive_t, error_t
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      type(error_t), allocatable, intent(out) :: err
    end subroutine group_interface

    !> Number of columns (last dimension) of the rank-2 record `path`.
    subroutine columns_interface(this, path, n, err)
      import :: archive_t, error_t
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      integer, intent(out) :: n
      type(error_t), allocatable, intent(out) :: err
    end subroutine columns_interface

    subroutine write_real_1_interface(this, path, values, err)
      import :: archive_t, error_t, dp
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      real(dp), intent(in) :: values(:)
      type(error_t), allocatable, intent(out) :: err
    end subroutine write_real_1_interface

    subroutine write_real_2_interface(this, path, values, err)
      import :: archive_t, error_t, dp
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      real(dp), intent(in) :: values(:, :)
      type(error_t), allocatable, intent(out) :: err
    end subroutine write_real_2_interface

    subroutine write_real_3_interface(this, path, values, err)
      import :: archive_t, error_t, dp
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      real(dp), intent(in) :: values(:, :, :)
      type(error_t), allocatable, intent(out) :: err
    end subroutine write_real_3_interface

    subroutine write_int_1_interface(this, path, values, err)
      import :: archive_t, error_t
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      integer, intent(in) :: values(:)
      type(error_t), allocatable, intent(out) :: err
    end subroutine write_int_1_interface

    !> Read record `path`, which must have the shape `expected`.
    subroutine read_real_1_interface(this, path, expected, values, err)
      import :: archive_t, error_t, dp
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      integer, intent(in) :: expected(:)
      real(dp), allocatable, intent(out) :: values(:)
      type(error_t), allocatable, intent(out) :: err
    end subroutine read_real_1_interface

    subroutine read_real_2_interface(this, path, expected, values, err)
      import :: archive_t, error_t, dp
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      integer, intent(in) :: expected(:)
      real(dp), allocatable, intent(out) :: values(:, :)
      type(error_t), allocatable, intent(out) :: err
    end subroutine read_real_2_interface

    subroutine read_real_3_interface(this, path, expected, values, err)
      import :: archive_t, error_t, dp
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      integer, intent(in) :: expected(:)
      real(dp), allocatable, intent(out) :: values(:, :, :)
      type(error_t), allocatable, intent(out) :: err
    end subroutine read_real_3_interface

    subroutine read_int_1_interface(this, path, expected, values, err)
      import :: archive_t, error_t
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path
      integer, intent(in) :: expected(:)
      integer, allocatable, intent(out) :: values(:)
      type(error_t), allocatable, intent(out) :: err
    end subroutine read_int_1_interface

    !> Text attribute `key` of record or group `path`.
    subroutine write_text_interface(this, path, key, text, err)
      import :: archive_t, error_t
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path, key, text
      type(error_t), allocatable, intent(out) :: err
    end subroutine write_text_interface

    subroutine read_text_interface(this, path, key, text, err)
      import :: archive_t, error_t
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path, key
      character(len=:), allocatable, intent(out) :: text
      type(error_t), allocatable, intent(out) :: err
    end subroutine read_text_interface

    !> Integer attribute `key` of record or group `path`.
    subroutine write_integer_interface(this, path, key, value, err)
      import :: archive_t, error_t
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path, key
      integer, intent(in) :: value
      type(error_t), allocatable, intent(out) :: err
    end subroutine write_integer_interface

    subroutine read_integer_interface(this, path, key, value, err)
      import :: archive_t, error_t
      class(archive_t), intent(inout) :: this
      character(len=*), intent(in) :: path, key
      integer, intent(out) :: value
      type(error_t), allocatable, intent(out) :: err
    end subroutine read_integer_interface
  end interface

contains

  subroutine archive_put_real_1(this, path, values, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    call this%write_real_1(path, values, err)
    if (.not. allocated(err)) call sign_real(this, path, values, err)
  end subroutine archive_put_real_1

  subroutine archive_put_real_2(this, path, values, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    call this%write_real_2(path, values, err)
    if (.not. allocated(err)) call sign_real(this, path, reshape(values, [size(values)]), err)
  end subroutine archive_put_real_2

  subroutine archive_put_real_3(this, path, values, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    call this%write_real_3(path, values, err)
    if (.not. allocated(err)) call sign_real(this, path, reshape(values, [size(values)]), err)
  end subroutine archive_put_real_3

  subroutine archive_put_int_1(this, path, values, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(in) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    type(checksum_t) :: c
    call this%write_int_1(path, values, err)
    if (allocated(err)) return
    call c%add_int(values)
    call this%total%add_text(checksum_text(c%value))
    call this%write_text(path, 'checksum', checksum_text(c%value), err)
  end subroutine archive_put_int_1

  !> The checksum attribute of a real record, also added to the running total.
  subroutine sign_real(this, path, flat, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: flat(:)
    type(error_t), allocatable, intent(out) :: err
    type(checksum_t) :: c
    call c%add_real(flat)
    call this%total%add_text(checksum_text(c%value))
    call this%write_text(path, 'checksum', checksum_text(c%value), err)
  end subroutine sign_real

  subroutine archive_get_real_1(this, path, values, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(inout) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: stored(:)
    call this%read_real_1(path, shape(values), stored, err)
    if (.not. allocated(err)) call verify_real(this, path, stored, err)
    if (.not. allocated(err)) values = stored
  end subroutine archive_get_real_1

  subroutine archive_get_real_2(this, path, values, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(inout) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: stored(:, :)
    call this%read_real_2(path, shape(values), stored, err)
    if (.not. allocated(err)) call verify_real(this, path, reshape(stored, [size(stored)]), err)
    if (.not. allocated(err)) values = stored
  end subroutine archive_get_real_2

  subroutine archive_get_real_3(this, path, values, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(inout) :: values(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: stored(:, :, :)
    call this%read_real_3(path, shape(values), stored, err)
    if (.not. allocated(err)) call verify_real(this, path, reshape(stored, [size(stored)]), err)
    if (.not. allocated(err)) values = stored
  end subroutine archive_get_real_3

  subroutine archive_get_int_1(this, path, values, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(inout) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: stored(:)
    type(checksum_t) :: c
    call this%read_int_1(path, shape(values), stored, err)
    if (allocated(err)) then
      err%message = path // ': ' // err%message
      err%exit_code = 2
      return
    end if
    call c%add_int(stored)
    call this%verify(path, c, err)
    if (.not. allocated(err)) values = stored
  end subroutine archive_get_int_1

  !> A rank-2 record of `n_rows` rows and any number of columns (a table that grows, such as
  !> the rows of a history), into `values`.
  subroutine archive_get_columns(this, path, n_rows, values, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(in) :: n_rows
    real(dp), allocatable, intent(out) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    integer :: n
    call this%columns(path, n, err)
    if (allocated(err)) return
    allocate (values(n_rows, n))
    call this%get(path, values, err)
  end subroutine archive_get_columns

  !> A logical as the integer attribute `key` of group `path` (not checksummed: a flag).
  subroutine archive_put_flag(this, path, key, flag, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path, key
    logical, intent(in) :: flag
    type(error_t), allocatable, intent(out) :: err
    call this%write_integer(path, key, merge(1, 0, flag), err)
  end subroutine archive_put_flag

  subroutine archive_get_flag(this, path, key, flag, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path, key
    logical, intent(out) :: flag
    type(error_t), allocatable, intent(out) :: err
    integer :: value
    call this%read_integer(path, key, value, err)
    flag = value /= 0
  end subroutine archive_get_flag

  subroutine verify_real(this, path, flat, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: flat(:)
    type(error_t), allocatable, intent(out) :: err
    type(checksum_t) :: c
    call c%add_real(flat)
    call this%verify(path, c, err)
  end subroutine verify_real

  !> Compare the checksum `c` of the data read from `path` with its stored checksum, and add
  !> the stored one to the running total.
  subroutine archive_verify(this, path, c, err)
    class(archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    type(checksum_t), intent(in) :: c
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: stored
    call this%read_text(path, 'checksum', stored, err)
    if (allocated(err)) return
    if (stored /= checksum_text(c%value)) then
      call input_error(err, path // ': checksum mismatch (stored ' // stored // ', data ' // &
                       checksum_text(c%value) // '): the checkpoint is damaged')
      return
    end if
    call this%total%add_text(stored)
  end subroutine archive_verify

end module fcs_archive
