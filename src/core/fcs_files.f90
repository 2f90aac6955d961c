!> File-system operations that Fortran lacks: atomic rename, removal, fsync, truncation, the
!> kind of a path (regular file, directory, FIFO, device), free space, space reservation, and
!> the C library's `errno` with its text.
!>
!> Thin wrappers over the C library (POSIX `rename`, `unlink`, `fsync`, `truncate`,
!> `posix_fallocate`, `statvfs`, `access`; Linux `statx`; `fopen`/`fileno`/`fclose` to obtain a
!> descriptor, because `open(2)` is variadic and cannot be declared portably with `bind(c)`).
!> Each failure becomes an `error_t` whose message names the path(s) and carries the C
!> library's own text from `strerror(errno)` (glibc and musl export errno through
!> `__errno_location`); a full disk or an exceeded quota is named as such (`failure_text`).
!>
!> `statx` is used instead of `stat` because its structure has one layout on every Linux
!> architecture (linux/stat.h), where `struct stat` differs between them.
!>
!> The usual pattern for replacing a file atomically (used for the XDMF index of the results,
!> the CSV files, the checkpoints): write `name.tmp`, `sync_file('name.tmp')`,
!> `rename_file('name.tmp', 'name')`, then `sync_file(dirname('name'))` so that the rename
!> itself survives a crash.
module fcs_files
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_ptr, c_size_t, c_null_char, &
    c_associated, c_f_pointer, c_long, c_int16_t, c_int32_t, c_int64_t
  use fcs_kinds, only: i8
  use fcs_error, only: error_t, fatal_error
  implicit none
  private
  public :: rename_file, remove_file, sync_file, directory_exists, make_directory
  public :: truncate_file, file_size, file_kind, file_kind_name, is_readable, free_space
  public :: reserve_space, current_errno, clear_errno, errno_text, failure_text, is_disk_full_errno
  public :: file_identity, descriptor_identity
  public :: FILE_MISSING, FILE_REGULAR, FILE_DIRECTORY, FILE_FIFO, FILE_CHARACTER_DEVICE, &
    FILE_BLOCK_DEVICE, FILE_SOCKET, FILE_OTHER
  public :: ERRNO_NO_SPACE, ERRNO_QUOTA

  !> What a path names (`file_kind`).
  integer, parameter :: FILE_MISSING = 0, FILE_REGULAR = 1, FILE_DIRECTORY = 2, FILE_FIFO = 3, &
    FILE_CHARACTER_DEVICE = 4, FILE_BLOCK_DEVICE = 5, FILE_SOCKET = 6, FILE_OTHER = 7
  !> errno values of a full file system and of an exceeded quota (Linux asm-generic/errno.h).
  integer, parameter :: ERRNO_NO_SPACE = 28, ERRNO_QUOTA = 122

  !> statx(2) arguments (linux/fcntl.h, linux/stat.h): relative to the working directory,
  !> following symbolic links; the type and size are wanted.
  integer(c_int), parameter :: AT_FDCWD = -100_c_int
  integer(c_int32_t), parameter :: STATX_TYPE_AND_SIZE = int(z'201', c_int32_t)
  !> statx(2) on a descriptor (empty path), and the inode wanted.
  integer(c_int), parameter :: AT_EMPTY_PATH = int(z'1000', c_int)
  integer(c_int32_t), parameter :: STATX_TYPE_INODE = int(z'101', c_int32_t)
  !> File type bits of st_mode (sys/stat.h).
  integer, parameter :: S_IFMT = int(o'170000'), S_IFREG = int(o'100000'), &
    S_IFDIR = int(o'040000'), S_IFIFO = int(o'010000'), S_IFCHR = int(o'020000'), &
    S_IFBLK = int(o'060000'), S_IFSOCK = int(o'140000')
  !> access(2): read permission.
  integer(c_int), parameter :: R_OK = 4_c_int

  !> struct statx (linux/stat.h): 256 bytes, the same layout on every architecture.
  type, bind(c) :: statx_t
    integer(c_int32_t) :: mask = 0, block_size = 0
    integer(c_int64_t) :: attributes = 0
    integer(c_int32_t) :: links = 0, uid = 0, gid = 0
    integer(c_int16_t) :: mode = 0, spare0 = 0
    integer(c_int64_t) :: inode = 0, size = 0, blocks = 0, attributes_mask = 0
    integer(c_int64_t) :: times(8) = 0
    integer(c_int32_t) :: devices(4) = 0
    integer(c_int64_t) :: spare(14) = 0
  end type statx_t

  !> struct statvfs of glibc on 64-bit Linux: eleven 64-bit fields and six ints.
  type, bind(c) :: statvfs_t
    integer(c_long) :: block_size = 0, fragment_size = 0, blocks = 0, blocks_free = 0, &
      blocks_available = 0, files = 0, files_free = 0, files_available = 0, fsid = 0, &
      flags = 0, name_max = 0
    integer(c_int) :: spare(6) = 0
  end type statvfs_t

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

    !> posix_fallocate(3): returns the error number (not errno), 0 on success.
    function c_posix_fallocate(descriptor, offset, length) bind(c, name='posix_fallocate') &
        result(status)
      import :: c_int, c_long
      integer(c_int), value :: descriptor
      integer(c_long), value :: offset, length
      integer(c_int) :: status
    end function c_posix_fallocate

    function c_statx(directory, path, flags, mask, buffer) bind(c, name='statx') result(status)
      import :: c_int, c_char, c_int32_t, statx_t
      integer(c_int), value :: directory
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: flags
      integer(c_int32_t), value :: mask
      type(statx_t), intent(out) :: buffer
      integer(c_int) :: status
    end function c_statx

    function c_statvfs(path, buffer) bind(c, name='statvfs') result(status)
      import :: c_int, c_char, statvfs_t
      character(kind=c_char), intent(in) :: path(*)
      type(statvfs_t), intent(out) :: buffer
      integer(c_int) :: status
    end function c_statvfs

    function c_access(path, mode) bind(c, name='access') result(status)
      import :: c_int, c_char
      character(kind=c_char), intent(in) :: path(*)
      integer(c_int), value :: mode
      integer(c_int) :: status
    end function c_access

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
      reason = failure_text()
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
    type(statx_t) :: info
    file_size = -1
    if (len(path) == 0) return
    if (c_statx(AT_FDCWD, path // c_null_char, 0_c_int, STATX_TYPE_AND_SIZE, info) /= 0) return
    file_size = info%size
  end function file_size

  !> What `path` names: FILE_MISSING (also when it cannot be examined), FILE_REGULAR,
  !> FILE_DIRECTORY, FILE_FIFO, FILE_CHARACTER_DEVICE, FILE_BLOCK_DEVICE, FILE_SOCKET or
  !> FILE_OTHER. Symbolic links are followed.
  integer function file_kind(path) result(kind)
    character(len=*), intent(in) :: path
    type(statx_t) :: info
    integer :: mode
    kind = FILE_MISSING
    if (len(path) == 0) return
    if (c_statx(AT_FDCWD, path // c_null_char, 0_c_int, STATX_TYPE_AND_SIZE, info) /= 0) return
    mode = iand(int(info%mode), int(z'FFFF'))
    select case (iand(mode, S_IFMT))
    case (S_IFREG)
      kind = FILE_REGULAR
    case (S_IFDIR)
      kind = FILE_DIRECTORY
    case (S_IFIFO)
      kind = FILE_FIFO
    case (S_IFCHR)
      kind = FILE_CHARACTER_DEVICE
    case (S_IFBLK)
      kind = FILE_BLOCK_DEVICE
    case (S_IFSOCK)
      kind = FILE_SOCKET
    case default
      kind = FILE_OTHER
    end select
  end function file_kind

  !> Device and inode of the file `path` names (0 when it cannot be examined): two paths or
  !> descriptors with the same identity are the same file.
  function file_identity(path) result(identity)
    character(len=*), intent(in) :: path
    integer(i8) :: identity(3)
    type(statx_t) :: info
    identity = 0
    if (c_statx(AT_FDCWD, path // c_null_char, 0_c_int, STATX_TYPE_INODE, info) /= 0) return
    identity = [int(info%devices(3), i8), int(info%devices(4), i8), int(info%inode, i8)]
  end function file_identity

  !> Device and inode of the open file `descriptor` (see `file_identity`).
  function descriptor_identity(descriptor) result(identity)
    integer(c_int), intent(in) :: descriptor
    integer(i8) :: identity(3)
    type(statx_t) :: info
    identity = 0
    if (c_statx(descriptor, c_null_char, AT_EMPTY_PATH, STATX_TYPE_INODE, info) /= 0) return
    identity = [int(info%devices(3), i8), int(info%devices(4), i8), int(info%inode, i8)]
  end function descriptor_identity

  !> "a directory", "a FIFO (named pipe)", ... for messages.
  pure function file_kind_name(kind) result(name)
    integer, intent(in) :: kind
    character(len=:), allocatable :: name
    select case (kind)
    case (FILE_MISSING)
      name = 'missing'
    case (FILE_REGULAR)
      name = 'a regular file'
    case (FILE_DIRECTORY)
      name = 'a directory'
    case (FILE_FIFO)
      name = 'a FIFO (named pipe)'
    case (FILE_CHARACTER_DEVICE)
      name = 'a character device'
    case (FILE_BLOCK_DEVICE)
      name = 'a block device'
    case (FILE_SOCKET)
      name = 'a socket'
    case default
      name = 'not a regular file'
    end select
  end function file_kind_name

  !> True when this process may read `path` (access(2) with R_OK).
  logical function is_readable(path)
    character(len=*), intent(in) :: path
    is_readable = c_access(path // c_null_char, R_OK) == 0
  end function is_readable

  !> Bytes available to this user on the file system holding `path` (statvfs f_bavail x
  !> f_frsize); -1 when it cannot be asked.
  integer(i8) function free_space(path)
    character(len=*), intent(in) :: path
    type(statvfs_t) :: info
    character(len=:), allocatable :: where
    where = path
    if (len(where) == 0) where = '.'
    free_space = -1
    if (c_statvfs(where // c_null_char, info) /= 0) return
    free_space = int(info%blocks_available, i8) * int(info%fragment_size, i8)
  end function free_space

  !> Make sure that bytes `offset` .. `offset + length - 1` of the existing file `path` are
  !> allocated on disk (posix_fallocate: the file grows to at least `offset + length`), so that
  !> later writes there cannot fail for want of space. A full disk is an error that says so;
  !> `supported` is false when the file system cannot reserve space (the caller then goes on
  !> without the guarantee).
  subroutine reserve_space(path, offset, length, supported, err)
    character(len=*), intent(in) :: path
    integer(i8), intent(in) :: offset, length
    logical, intent(out) :: supported
    type(error_t), allocatable, intent(out) :: err
    type(c_ptr) :: stream
    integer(c_int) :: status, close_status
    character(len=:), allocatable :: reason
    supported = .true.
    if (length <= 0) return
    stream = c_fopen(path // c_null_char, 'r+' // c_null_char)
    if (.not. c_associated(stream)) then
      reason = failure_text()
      call fatal_error(err, 'reserving space in ' // path // ': ' // reason)
      return
    end if
    status = c_posix_fallocate(c_fileno(stream), int(offset, c_long), int(length, c_long))
    close_status = c_fclose(stream)
    if (status == 0) return
    if (is_disk_full_errno(int(status))) then
      call fatal_error(err, path // ': ' // failure_text(int(status)) // ' (' // &
        bytes_text(length) // ' more were needed)')
    else
      supported = .false.
    end if
  end subroutine reserve_space

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
      reason = failure_text()
      failure = 'fsync of ' // path // ': ' // reason
    end if
    status = c_fclose(stream)
    if (status /= 0 .and. len(failure) == 0) then
      reason = failure_text()
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
      directory_exists = .true.
    else
      directory_exists = file_kind(path) == FILE_DIRECTORY
    end if
  end function directory_exists

  !> The C library's errno now.
  integer function current_errno()
    integer(c_int), pointer :: errno
    call c_f_pointer(c_errno_location(), errno)
    current_errno = int(errno)
  end function current_errno

  !> Set errno to 0, so that a later failure can tell whether it set it.
  subroutine clear_errno()
    integer(c_int), pointer :: errno
    call c_f_pointer(c_errno_location(), errno)
    errno = 0
  end subroutine clear_errno

  !> True for the errno values of a full file system or an exceeded disk quota.
  pure logical function is_disk_full_errno(code)
    integer, intent(in) :: code
    is_disk_full_errno = code == ERRNO_NO_SPACE .or. code == ERRNO_QUOTA
  end function is_disk_full_errno

  !> The C library's text for `code` (default: the current errno), e.g. "No such file or
  !> directory".
  function errno_text(code) result(text)
    integer, intent(in), optional :: code
    character(len=:), allocatable :: text
    type(c_ptr) :: message
    character(kind=c_char), pointer :: chars(:)
    integer :: i, length, value
    if (present(code)) then
      value = code
    else
      value = current_errno()
    end if
    message = c_strerror(int(value, c_int))
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

  !> The reason of a failed file operation for a message: "the disk is full (No space left on
  !> device)", "the disk quota is exceeded (...)", or the C library's text for the errno.
  function failure_text(code) result(text)
    integer, intent(in), optional :: code
    character(len=:), allocatable :: text
    integer :: value
    if (present(code)) then
      value = code
    else
      value = current_errno()
    end if
    select case (value)
    case (ERRNO_NO_SPACE)
      text = 'the disk is full (' // errno_text(value) // ')'
    case (ERRNO_QUOTA)
      text = 'the disk quota is exceeded (' // errno_text(value) // ')'
    case default
      text = errno_text(value)
    end select
  end function failure_text

  !> "12.3 MiB", "4 KiB", "17 bytes".
  function bytes_text(bytes) result(text)
    integer(i8), intent(in) :: bytes
    character(len=:), allocatable :: text
    character(len=32) :: buffer
    if (bytes >= 1048576_i8) then
      write (buffer, '(f0.1,a)') real(bytes) / 1048576.0, ' MiB'
    else if (bytes >= 1024_i8) then
      write (buffer, '(i0,a)') (bytes + 1023_i8) / 1024_i8, ' KiB'
    else
      write (buffer, '(i0,a)') bytes, ' bytes'
    end if
    text = trim(buffer)
  end function bytes_text

end module fcs_files
