!> The HDF5 backend of `archive_t` (fcs_archive): each record is a dataset of the file under
!> its path, with its checksum as the dataset's `checksum` attribute (written and verified by
!> `archive_t`); groups are HDF5 groups. Reading checks the class and shape of each dataset
!> (fcs_hdf5) before `archive_t` verifies its checksum.
module fcs_h5_archive
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t
  use fcs_archive, only: archive_t
  use fcs_hdf5, only: h5_file_t
  implicit none
  private
  public :: h5_archive_t

  type, extends(archive_t) :: h5_archive_t
    type(h5_file_t) :: h5
    !> The file's path, and whether the archive is being written (saved) or read (loaded).
    character(len=:), allocatable :: path
    logical :: writing = .false.
  contains
    procedure :: is_writing => h5_archive_is_writing
    procedure :: exists => h5_archive_exists
    procedure :: group => h5_archive_group
    procedure :: columns => h5_archive_columns
    procedure :: write_real_1 => h5_archive_write_real_1
    procedure :: write_real_2 => h5_archive_write_real_2
    procedure :: write_real_3 => h5_archive_write_real_3
    procedure :: write_int_1 => h5_archive_write_int_1
    procedure :: read_real_1 => h5_archive_read_real_1
    procedure :: read_real_2 => h5_archive_read_real_2
    procedure :: read_real_3 => h5_archive_read_real_3
    procedure :: read_int_1 => h5_archive_read_int_1
    procedure :: write_text => h5_archive_write_text
    procedure :: read_text => h5_archive_read_text
    procedure :: write_integer => h5_archive_write_integer
    procedure :: read_integer => h5_archive_read_integer
  end type h5_archive_t

contains

  logical function h5_archive_is_writing(this)
    class(h5_archive_t), intent(in) :: this
    h5_archive_is_writing = this%writing
  end function h5_archive_is_writing

  logical function h5_archive_exists(this, path)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    h5_archive_exists = this%h5%exists(path)
  end function h5_archive_exists

  subroutine h5_archive_group(this, path, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    if (this%writing) call this%h5%create_group(path, err)
  end subroutine h5_archive_group

  subroutine h5_archive_columns(this, path, n, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(out) :: n
    type(error_t), allocatable, intent(out) :: err
    integer(i8), allocatable :: dims(:)
    n = 0
    call this%h5%dataset_shape(path, dims, err)
    if (.not. allocated(err)) n = int(dims(size(dims)))
  end subroutine h5_archive_columns

  subroutine h5_archive_write_real_1(this, path, values, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    call this%h5%write_dataset(path, values, err)
  end subroutine h5_archive_write_real_1

  subroutine h5_archive_write_real_2(this, path, values, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    call this%h5%write_dataset(path, values, err)
  end subroutine h5_archive_write_real_2

  subroutine h5_archive_write_real_3(this, path, values, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    real(dp), intent(in) :: values(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    call this%h5%write_dataset(path, values, err)
  end subroutine h5_archive_write_real_3

  subroutine h5_archive_write_int_1(this, path, values, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(in) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    call this%h5%write_dataset(path, values, err)
  end subroutine h5_archive_write_int_1

  subroutine h5_archive_read_real_1(this, path, expected, values, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(in) :: expected(:)
    real(dp), allocatable, intent(out) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    call this%h5%read_dataset(path, values, err, expected)
  end subroutine h5_archive_read_real_1

  subroutine h5_archive_read_real_2(this, path, expected, values, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(in) :: expected(:)
    real(dp), allocatable, intent(out) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    call this%h5%read_dataset(path, values, err, expected)
  end subroutine h5_archive_read_real_2

  subroutine h5_archive_read_real_3(this, path, expected, values, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(in) :: expected(:)
    real(dp), allocatable, intent(out) :: values(:, :, :)
    type(error_t), allocatable, intent(out) :: err
    call this%h5%read_dataset(path, values, err, expected)
  end subroutine h5_archive_read_real_3

  subroutine h5_archive_read_int_1(this, path, expected, values, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    integer, intent(in) :: expected(:)
    integer, allocatable, intent(out) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    call this%h5%read_dataset(path, values, err, expected)
  end subroutine h5_archive_read_int_1

  subroutine h5_archive_write_text(this, path, key, text, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path, key, text
    type(error_t), allocatable, intent(out) :: err
    call this%h5%write_attribute(path, key, text, err)
  end subroutine h5_archive_write_text

  subroutine h5_archive_read_text(this, path, key, text, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path, key
    character(len=:), allocatable, intent(out) :: text
    type(error_t), allocatable, intent(out) :: err
    call this%h5%read_attribute(path, key, text, err)
  end subroutine h5_archive_read_text

  subroutine h5_archive_write_integer(this, path, key, value, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path, key
    integer, intent(in) :: value
    type(error_t), allocatable, intent(out) :: err
    call this%h5%write_attribute(path, key, value, err)
  end subroutine h5_archive_write_integer

  subroutine h5_archive_read_integer(this, path, key, value, err)
    class(h5_archive_t), intent(inout) :: this
    character(len=*), intent(in) :: path, key
    integer, intent(out) :: value
    type(error_t), allocatable, intent(out) :: err
    call this%h5%read_attribute(path, key, value, err)
  end subroutine h5_archive_read_integer

end module fcs_h5_archive
