!> A history table: rows of samples (first column the time) kept in memory, appended to a CSV
!> file as they come (flushed, so a crash loses nothing written), and stored in the results
!> file by the caller. The CSV is (re)written whole by `rewrite_csv`, which the caller calls
!> once the run is known to go ahead: for a new run, and after a restart (rows from the
!> checkpoint) only once the checkpoint was accepted, so that a refused restart leaves the
!> CSV of the earlier run as it was.
module fcs_history
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error
  use fcs_strings, only: string_t, join_strings
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
    integer :: unit, stat
    character(len=256) :: msg
    if (this%n_rows == size(this%rows, 2)) then
      allocate (grown(size(this%rows, 1), 2 * size(this%rows, 2)))
      grown(:, 1:this%n_rows) = this%rows(:, 1:this%n_rows)
      call move_alloc(grown, this%rows)
    end if
    this%n_rows = this%n_rows + 1
    this%rows(:, this%n_rows) = values
    if (.not. this%writes) return
    open (newunit=unit, file=this%csv_path, action='write', position='append', iostat=stat, iomsg=msg)
    if (stat /= 0) then
      call fatal_error(err, 'writing history ' // this%csv_path // ': ' // trim(msg))
      return
    end if
    call write_row(unit, values)
    close (unit)
  end subroutine table_append

  !> Write the whole CSV: header and every row.
  subroutine table_rewrite_csv(this, err)
    class(history_table_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    integer :: unit, stat, i
    character(len=256) :: msg
    if (.not. this%writes) return
    open (newunit=unit, file=this%csv_path, action='write', status='replace', iostat=stat, iomsg=msg)
    if (stat /= 0) then
      call fatal_error(err, 'writing history ' // this%csv_path // ': ' // trim(msg))
      return
    end if
    write (unit, '(a)') join_strings(this%columns, ',')
    do i = 1, this%n_rows
      call write_row(unit, this%rows(:, i))
    end do
    close (unit)
  end subroutine table_rewrite_csv

  subroutine write_row(unit, values)
    integer, intent(in) :: unit
    real(dp), intent(in) :: values(:)
    character(len=32) :: cell
    integer :: j
    do j = 1, size(values)
      write (cell, '(es24.16)') values(j)
      if (j < size(values)) then
        write (unit, '(a)', advance='no') trim(adjustl(cell)) // ','
      else
        write (unit, '(a)') trim(adjustl(cell))
      end if
    end do
  end subroutine write_row

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

end module fcs_history
