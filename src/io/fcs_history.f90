!> A history table: rows of samples (first column the time) kept in memory, appended to a CSV
!> file as they come (flushed, so a crash loses nothing written), and stored in the results
!> file by the caller. The CSV is (re)written whole by `rewrite_csv`, which the caller calls
!> once the run is known to go ahead: for a new run, and after a restart (rows from the
!> checkpoint) only once the checkpoint was accepted, so that a refused restart leaves the
!> CSV of the earlier run as it was.
!>
!> Writes are checked (fcs_text_file): a row that cannot be written whole is cut off again, so
!> the CSV always ends with complete rows; the whole-file rewrite replaces the file atomically.
module fcs_history
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error
  use fcs_strings, only: string_t, join_strings
  use fcs_text_file, only: text_file_t
  use fcs_archive, only: archive_t
  implicit none
  private
  public :: history_table_t

  type :: history_table_t
    character(len=:), allocatable :: name
    character(len=:), allocatable :: csv_path
    type(string_t), allocatable :: columns(:)
    real(dp), allocatable :: rows(:, :)
    integer :: n_rows = 0
    !> Whether this process writes the CSV (rank 0 of a parallel run; every process keeps
    !> the rows).
    logical :: writes = .true.
  contains
    procedure :: create => table_create
    procedure :: append => table_append
    procedure :: rewrite_csv => table_rewrite_csv
    procedure :: values => table_values
    procedure :: set_rows => table_set_rows
    procedure :: save => table_save
    procedure :: load => table_load
  end type history_table_t

contains

  !> A new, empty table for the CSV file `csv_path` (not written yet: see rewrite_csv).
  subroutine table_create(this, name, csv_path, columns, err, writes)
    class(history_table_t), intent(inout) :: this
    character(len=*), intent(in) :: name, csv_path
    type(string_t), intent(in) :: columns(:)
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: writes
    if (present(writes)) this%writes = writes
    this%name = name
    this%csv_path = csv_path
    this%columns = columns
    allocate (this%rows(size(columns), 64))
    this%n_rows = 0
  end subroutine table_create

  !> Add a row (memory and CSV).
  subroutine table_append(this, values, err)
    class(history_table_t), intent(inout) :: this
    real(dp), intent(in) :: values(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: grown(:, :)
    type(text_file_t) :: file
    if (this%n_rows == size(this%rows, 2)) then
      allocate (grown(size(this%rows, 1), 2 * size(this%rows, 2)))
      grown(:, 1:this%n_rows) = this%rows(:, 1:this%n_rows)
      call move_alloc(grown, this%rows)
    end if
    this%n_rows = this%n_rows + 1
    this%rows(:, this%n_rows) = values
    if (.not. this%writes) return
    call file%open(this%csv_path, err, append=.true.)
    if (.not. allocated(err)) call file%write(row_text(values), err)
    if (.not. allocated(err)) call file%close(err)
    if (allocated(err)) err%message = 'history ' // this%name // ': ' // err%message
  end subroutine table_append

  !> Write the whole CSV: header and every row.
  subroutine table_rewrite_csv(this, err)
    class(history_table_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    type(text_file_t) :: file
    integer :: i
    if (.not. this%writes) return
    call file%open(this%csv_path, err, atomic=.true.)
    if (.not. allocated(err)) call file%write(join_strings(this%columns, ','), err)
    do i = 1, this%n_rows
      if (allocated(err)) exit
      call file%write(row_text(this%rows(:, i)), err)
    end do
    if (.not. allocated(err)) call file%close(err)
    if (allocated(err)) then
      call file%abandon()
      err%message = 'history ' // this%name // ': ' // err%message
    end if
  end subroutine table_rewrite_csv

  !> One CSV row: every value with 17 significant digits.
  function row_text(values) result(row)
    real(dp), intent(in) :: values(:)
    character(len=:), allocatable :: row
    character(len=32) :: cell
    integer :: j
    row = ''
    do j = 1, size(values)
      write (cell, '(es24.16)') values(j)
      row = row // trim(adjustl(cell))
      if (j < size(values)) row = row // ','
    end do
  end function row_text

  !> The rows so far, (n_columns, n_rows).
  pure function table_values(this) result(values)
    class(history_table_t), intent(in) :: this
    real(dp), allocatable :: values(:, :)
    values = this%rows(:, 1:this%n_rows)
  end function table_values

  !> Replace the rows (restart; the CSV is rewritten by the caller, see rewrite_csv).
  subroutine table_set_rows(this, values, err)
    class(history_table_t), intent(inout) :: this
    real(dp), intent(in) :: values(:, :)
    type(error_t), allocatable, intent(out) :: err
    deallocate (this%rows)
    allocate (this%rows(size(values, 1), max(64, size(values, 2))))
    this%rows(:, 1:size(values, 2)) = values
    this%n_rows = size(values, 2)
  end subroutine table_set_rows

  !> Write the rows so far as the record `path` of `archive`.
  subroutine table_save(this, archive, path, err)
    class(history_table_t), intent(in) :: this
    class(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    call archive%put(path, this%values(), err)
  end subroutine table_save

  !> Replace the rows by the record `path` of `archive` (the CSV is rewritten by the caller);
  !> a checkpoint without it was written for a deck without this history.
  subroutine table_load(this, archive, path, err)
    class(history_table_t), intent(inout) :: this
    class(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: path
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: rows(:, :)
    if (.not. archive%exists(path)) then
      call input_error(err, 'the checkpoint has no history ' // this%name // ' (was *HISTORY added?)')
      return
    end if
    call archive%get_columns(path, size(this%columns), rows, err)
    if (.not. allocated(err)) call this%set_rows(rows, err)
  end subroutine table_load

end module fcs_history
