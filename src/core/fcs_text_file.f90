!> Text output files whose every write, flush and close is checked: the `.dat` tables, the log,
!> the history and event CSVs, the XDMF index, the echo.
!>
!> Why C stdio and not Fortran units: gfortran 12's run-time library drops the error of a failed
!> write(2) on a formatted or stream unit (measured: 10 MB written to a file system with 250 KB
!> free, or to /dev/full, and WRITE, FLUSH and CLOSE all return iostat 0 while the system call
!> returns ENOSPC). `fwrite`/`fflush`/`fclose` report it.
!>
!> Records and commits. Callers write a group of lines that belongs together (a table block, a
!> CSV row, a log line) and then `commit`: the data are flushed and the file size at that moment
!> becomes the last good size. When a write, flush or close fails, the object closes the file and
!> cuts it back to the last good size, so the file ends with complete records whatever the moment
!> of the failure, and the error names the file and the reason ("the disk is full ..."). A file
!> opened `atomic` is written under `<path>.tmp` and renamed over `<path>` at `close` (after an
!> fsync, and an fsync of the directory), so readers see the old or the new file, never a mix.
module fcs_text_file
  use, intrinsic :: iso_c_binding, only: c_char, c_int, c_ptr, c_size_t, c_null_char, &
    c_null_ptr, c_associated
  use fcs_kinds, only: i8
  use fcs_error, only: error_t, fatal_error
  use fcs_files, only: failure_text, rename_file, remove_file, sync_file, truncate_file, file_size
  use fcs_strings, only: dirname
  implicit none
  private
  public :: text_file_t

  !> One text file open for writing.
  type :: text_file_t
    type(c_ptr) :: stream = c_null_ptr
    !> The file's name, and the name it is written under (`<path>.tmp` when atomic).
    character(len=:), allocatable :: path
    character(len=:), allocatable :: writing_path
    logical :: atomic = .false.
    !> Size of the file after the last commit, and bytes written since then.
    integer(i8) :: committed = 0
    integer(i8) :: pending = 0
  contains
    procedure :: open => text_open
    procedure :: write => text_write
    procedure :: commit => text_commit
    procedure :: close => text_close
    procedure :: abandon => text_abandon
    procedure :: is_open => text_is_open
    procedure :: size => text_size
  end type text_file_t

  interface
    function c_fopen(path, mode) bind(c, name='fopen') result(stream)
      import :: c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*), mode(*)
      type(c_ptr) :: stream
    end function c_fopen

    function c_fwrite(buffer, size, count, stream) bind(c, name='fwrite') result(written)
      import :: c_char, c_size_t, c_ptr
      character(kind=c_char), intent(in) :: buffer(*)
      integer(c_size_t), value :: size, count
      type(c_ptr), value :: stream
      integer(c_size_t) :: written
    end function c_fwrite

    function c_fflush(stream) bind(c, name='fflush') result(status)
      import :: c_ptr, c_int
      type(c_ptr), value :: stream
      integer(c_int) :: status
    end function c_fflush

    function c_fclose(stream) bind(c, name='fclose') result(status)
      import :: c_ptr, c_int
      type(c_ptr), value :: stream
      integer(c_int) :: status
    end function c_fclose
  end interface

contains

  !> Open `path` for writing: replaced (default), appended to (`append`), or written under
  !> `<path>.tmp` and renamed into place at `close` (`atomic`).
  subroutine text_open(this, path, err, append, atomic)
    class(text_file_t), intent(inout) :: this
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: append, atomic
    character(len=1) :: mode
    character(len=:), allocatable :: reason
    call this%abandon()
    this%path = path
    this%atomic = .false.
    if (present(atomic)) this%atomic = atomic
    this%writing_path = path
    if (this%atomic) this%writing_path = path // '.tmp'
    mode = 'w'
    this%committed = 0
    if (present(append)) then
      if (append .and. .not. this%atomic) then
        mode = 'a'
        this%committed = max(0_i8, file_size(path))
      end if
    end if
    this%pending = 0
    this%stream = c_fopen(this%writing_path // c_null_char, mode // c_null_char)
    if (.not. c_associated(this%stream)) then
      reason = failure_text()
      call fatal_error(err, 'opening ' // this%writing_path // ' for writing: ' // reason)
    end if
  end subroutine text_open

  !> Write `line` and a line end.
  subroutine text_write(this, line, err)
    class(text_file_t), intent(inout) :: this
    character(len=*), intent(in) :: line
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: record
    if (.not. c_associated(this%stream)) then
      call fatal_error(err, 'writing ' // path_or_unknown(this) // ': the file is not open')
      return
    end if
    record = line // achar(10)
    if (c_fwrite(record, 1_c_size_t, int(len(record), c_size_t), this%stream) /= &
        int(len(record), c_size_t)) then
      call fail(this, 'writing', err)
      return
    end if
    this%pending = this%pending + len(record)
  end subroutine text_write

  !> Flush what was written since the last commit; the file's size becomes the last good size.
  subroutine text_commit(this, err)
    class(text_file_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    if (.not. c_associated(this%stream)) then
      call fatal_error(err, 'writing ' // path_or_unknown(this) // ': the file is not open')
      return
    end if
    if (c_fflush(this%stream) /= 0) then
      call fail(this, 'writing', err)
      return
    end if
    this%committed = this%committed + this%pending
    this%pending = 0
  end subroutine text_commit

  !> Commit and close; an atomic file is then synchronised and renamed into place.
  subroutine text_close(this, err)
    class(text_file_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    integer(c_int) :: status
    if (.not. c_associated(this%stream)) return
    call this%commit(err)
    if (allocated(err)) return
    status = c_fclose(this%stream)
    this%stream = c_null_ptr
    if (status /= 0) then
      call rollback(this, 'closing', err)
      return
    end if
    if (.not. this%atomic) return
    call sync_file(this%writing_path, err)
    if (.not. allocated(err)) call rename_file(this%writing_path, this%path, err)
    if (.not. allocated(err)) call sync_file(dirname(this%path), err)
    if (allocated(err)) call discard_temporary(this)
  end subroutine text_close

  !> Close without committing: what was written since the last commit is cut off (an atomic
  !> file's temporary is removed). Nothing to do when the file is not open.
  subroutine text_abandon(this)
    class(text_file_t), intent(inout) :: this
    integer(c_int) :: status
    type(error_t), allocatable :: ignored
    if (.not. c_associated(this%stream)) return
    status = c_fclose(this%stream)
    this%stream = c_null_ptr
    if (this%atomic) then
      call discard_temporary(this)
    else
      call truncate_file(this%writing_path, this%committed, ignored)
    end if
    this%pending = 0
  end subroutine text_abandon

  pure logical function text_is_open(this)
    class(text_file_t), intent(in) :: this
    text_is_open = c_associated(this%stream)
  end function text_is_open

  !> Size of the file at the last commit [bytes].
  pure integer(i8) function text_size(this)
    class(text_file_t), intent(in) :: this
    text_size = this%committed
  end function text_size

  !> A failed write or flush: the reason (errno) first, then close and cut back.
  subroutine fail(this, action, err)
    class(text_file_t), intent(inout) :: this
    character(len=*), intent(in) :: action
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: reason
    reason = failure_text()
    call fatal_error(err, action // ' ' // this%path // ': ' // reason)
    call this%abandon()
  end subroutine fail

  !> fclose failed (the last buffered data could not be written): cut back to the last commit.
  subroutine rollback(this, action, err)
    class(text_file_t), intent(inout) :: this
    character(len=*), intent(in) :: action
    type(error_t), allocatable, intent(out) :: err
    character(len=:), allocatable :: reason
    type(error_t), allocatable :: ignored
    reason = failure_text()
    call fatal_error(err, action // ' ' // this%path // ': ' // reason)
    if (this%atomic) then
      call discard_temporary(this)
    else
      call truncate_file(this%writing_path, this%committed, ignored)
    end if
  end subroutine rollback

  subroutine discard_temporary(this)
    class(text_file_t), intent(inout) :: this
    type(error_t), allocatable :: ignored
    call remove_file(this%writing_path, ignored)
  end subroutine discard_temporary

  function path_or_unknown(this) result(path)
    class(text_file_t), intent(in) :: this
    character(len=:), allocatable :: path
    if (allocated(this%path)) then
      path = this%path
    else
      path = '(no file)'
    end if
  end function path_or_unknown

end module fcs_text_file
