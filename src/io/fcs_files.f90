!> File-system operations that Fortran lacks: atomic rename, removal, fsync, directory test.
!>
!> Thin wrappers over the C library (POSIX `rename`, `unlink`, `fsync`; `fopen`/`fileno`/`fclose`
!> to obtain a descriptor, because `open(2)` is variadic and cannot be declared portably with
!> `bind(c)`). Each failure becomes an `error_t` whose message names the path(s) and carries the
!> C library's own text from `strerror(errno)` (glibc and musl export errno through
!> `__errno_location`).
!>
!> The usual pattern for replacing a file atomically (used for the XDMF index of the results):
!> write `name.tmp`, `sync_file('name.tmp')`, `rename_file('name.tmp', 'name')`, then
!> `sync_file(dirname('name'))` so that the rename itself survives a crash.
module fcs_files
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_ptr, c_size_t, c_null_char, &
    c_associated, c_f_pointer, c_long
  use fcs_error, only: error_t, fatal_error
  implicit none
  private
  public :: rename_file, remove_file, sync_file, directory_exists, make_directory
  public :: truncate_file, file_size

  interface
    function c_rename(old_path, new_path) bind(c, name='rename') result(status)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: old_path(*), new_path(*)
      integer(c_int) :: status
    end function c_rename

    !> truncate(2); off_t is a C long on the 64-bit Linux targets fcs3d is built for.
    function c_truncate(path, length) bind(c, name='truncate') result(status)
      import :: c_char, c_int, c_long
      character(kind=c_char), intent(in) :: path(*)
      integer(c_long), value :: length
      integer(c_int) :: status
    end function c_truncate

    function c_unlink(path) bind(c, name='unlink') result(status)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int) :: status
    end function c_unlink

    function c_mkdir(path, mode) bind(c, name='mkdir') result(status)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: mode
      integer(c_int) :: status
    end function c_mkdir

    function c_fopen(path, mode) bind(c, name='fopen') result(stream)
      import :: c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*), mode(*)
      type(c_ptr) :: stream
    end function c_fopen

    function c_fileno(stream) bind(c, name='fileno') result(descriptor)
      import :: c_ptr, c_int
      type(c_ptr), value :: stream
      integer(c_int) :: descriptor
    end function c_fileno

    function c_fsync(descriptor) bind(c, name='fsync') result(status)
      import :: c_int
      integer(c_int), value :: descriptor
      integer(c_int) :: status
    end function c_fsync

    function c_fclose(stream) bind(c, name='fclose') result(status)
      import :: c_ptr, c_int
      type(c_ptr), value :: stream
      integer(c_int) :: status
    end function c_fclose

    function c_errno_location() bind(c, name='__errno_location') result(location)
      import :: c_ptr
      type(c_ptr) :: location
    end function c_errno_location

    function c_strerror(code) bind(c, name='strerror') result(text)
      import :: c_int, c_ptr
      integer(c_int), value :: code
      type(c_ptr) :: text
    end function c_strerror

    function c_strlen(text) bind(c, name='strlen') result(length)
      import :: c_ptr, c_size_t
      type(c_ptr), value :: text
      integer(c_size_t) :: length
    end function c_strlen
  end interface

contains

  !> Rename `old_path` to `new_path` (POSIX rename: atomic, replaces an existing `new_path` on the
  !> same file system).
  subroutine rename_file(old_path, new_path, err)
    character(len=*), intent(in) :: old_path, new_path
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: reason
    if (c_rename(old_path // c_null_char, new_path // c_null_char) /= 0) then
      reason = errno_text()
      call fatal_error(err, 'renaming ' // old_path // ' to ' // new_path // ': ' // reason)
    end if
  end subroutine rename_file

  !> Remove the file `path`. A file that does not exist is not an error unless `must_exist`.
  subroutine remove_file(path, err, must_exist)
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: must_exist
    logical :: exists, required
    character(len=:), allocatable :: reason
    required = .false.
    if (present(must_exist)) required = must_exist
    inquire (file=path, exist=exists)
    if (.not. exists .and. .not. required) return
    if (c_unlink(path // c_null_char) /= 0) then
      reason = errno_text()
      call fatal_error(err, 'removing ' // path // ': ' // reason)
    end if
  end subroutine remove_file

  !> Cut the file `path` to `length` bytes (the text outputs of a restarted run continue from
  !> the checkpoint, so what a killed run wrote after it is removed).
  subroutine truncate_file(path, length, err)
    character(len=*), intent(in) :: path
    integer(kind=8), intent(in) :: length
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: reason
    if (c_truncate(path // c_null_char, int(length, c_long)) /= 0) then
      reason = errno_text()
      call fatal_error(err, 'truncating ' // path // ': ' // reason)
    end if
  end subroutine truncate_file

  !> Size of file `path` in bytes (-1 if it does not exist).
  integer(kind=8) function file_size(path)
    character(len=*), intent(in) :: path
    logical :: exists
    inquire (file=path, exist=exists, size=file_size)
    if (.not. exists) file_size = -1
  end function file_size

  !> Flush the file or directory `path` to stable storage (fsync). For a directory this makes
  !> a preceding rename inside it durable.
  subroutine sync_file(path, err)
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    type(c_ptr) :: stream
    integer(c_int) :: status
    character(len=:), allocatable :: failure, reason
    stream = c_fopen(path // c_null_char, 'r' // c_null_char)
    if (.not. c_associated(stream)) then
      reason = errno_text()
      call fatal_error(err, 'opening ' // path // ' to synchronise it: ' // reason)
      return
    end if
    failure = ''
    if (c_fsync(c_fileno(stream)) /= 0) then
      reason = errno_text()
      failure = 'fsync of ' // path // ': ' // reason
    end if
    status = c_fclose(stream)
    if (status /= 0 .and. len(failure) == 0) then
      reason = errno_text()
      failure = 'closing ' // path // ': ' // reason
    end if
    if (len(failure) > 0) call fatal_error(err, failure)
  end subroutine sync_file

  !> Create the directory `path` (permissions 0777 less the umask); an existing directory is
  !> fine. The parent must exist.
  subroutine make_directory(path, err)
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    integer(c_int), parameter :: MODE_RWX_ALL = int(o'777', c_int)
    character(len=:), allocatable :: reason
    if (directory_exists(path)) return
    if (c_mkdir(path // c_null_char, MODE_RWX_ALL) /= 0) then
      reason = errno_text()
      call fatal_error(err, 'creating directory ' // path // ': ' // reason)
    end if
  end subroutine make_directory

  !> True when `path` names an existing directory.
  logical function directory_exists(path)
    character(len=*), intent(in) :: path
    if (len(path) == 0) then
      inquire (file='./.', exist=directory_exists)
    else
      inquire (file=path // '/.', exist=directory_exists)
    end if
  end function directory_exists

  !> The C library's text for the current errno ("No such file or directory").
  function errno_text() result(text)
    character(len=:), allocatable :: text
    integer(c_int), pointer :: errno
    type(c_ptr) :: message
    character(kind=c_char), pointer :: chars(:)
    integer :: i, length
    call c_f_pointer(c_errno_location(), errno)
    message = c_strerror(errno)
    if (.not. c_associated(message)) then
      text = 'unknown error'
      return
    end if
    length = int(c_strlen(message))
    call c_f_pointer(message, chars, [length])
    allocate (character(len=length) :: text)
    do i = 1, length
      text(i:i) = chars(i)
    end do
  end function errno_text

end module fcs_files
