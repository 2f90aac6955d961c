!> The slip-event catalog. On every contact pair, an event starts when the slip rate of some
!> slave node exceeds the threshold, and ends when no node of the pair exceeds it. For each
!> event: onset and end times, the nodes that took part, the peak slip rate, the largest and
!> mean slip of those nodes during the event, the mean drop of their shear traction, and the
!> hypocentre (the node that crossed the threshold first, the fastest if several did).
!>
!> The CSV is written through fcs_text_file: a row is added whole or not at all, and the
!> whole-file rewrite replaces the file atomically.
module fcs_event_catalog
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error
  use fcs_strings, only: string_t, str
  use fcs_text_file, only: text_file_t
  use fcs_archive, only: archive_t
  implicit none
  private
  public :: event_catalog_t, slip_event_t, pair_watch_t, EVENT_COLUMNS

  !> Columns of the catalog table (CSV and HDF5).
  character(len=*), parameter :: EVENT_COLUMNS = 'event,pair,onset,end,duration,nodes,' // &
    'peak_slip_rate,max_slip,mean_slip,stress_drop,hypocentre_node,x,y,z'

  type :: slip_event_t
    integer :: pair = 0
    real(dp) :: onset = 0.0_dp
    real(dp) :: finish = 0.0_dp
    integer :: n_nodes = 0
    real(dp) :: peak_rate = 0.0_dp
    real(dp) :: max_slip = 0.0_dp
    real(dp) :: mean_slip = 0.0_dp
    real(dp) :: stress_drop = 0.0_dp
    !> Node id of the hypocentre and its position at onset.
    integer :: hypocentre = 0
    real(dp) :: location(3) = 0.0_dp
  end type slip_event_t

  !> What is watched on one pair: the event under way, and the slip and shear traction of
  !> every slave node after the previous increment (the values just before an onset).
  type :: pair_watch_t
    logical :: active = .false.
    type(slip_event_t) :: event
    logical, allocatable :: involved(:)
    real(dp), allocatable :: slip_start(:), shear_start(:)
    real(dp), allocatable :: last_slip(:), last_shear(:)
  end type pair_watch_t

  type :: event_catalog_t
    real(dp) :: threshold = 0.0_dp
    real(dp) :: min_slip = 0.0_dp
    type(pair_watch_t), allocatable :: watch(:)
    type(slip_event_t), allocatable :: events(:)
    integer :: n_events = 0
    character(len=:), allocatable :: csv_path
    !> Whether this process writes the CSV (rank 0 of a parallel run).
    logical :: writes = .true.
  contains
    procedure :: init => catalog_init
    procedure :: update => catalog_update
    procedure :: table => catalog_table
    procedure :: rewrite_csv => catalog_rewrite_csv
    procedure :: save => catalog_save
    procedure :: load => catalog_load
  end type event_catalog_t

  !> Values per event and per watched node in the archive (this type's own layout, read
  !> back only by `load`): the slip_event_t fields in order, and the five per-node arrays of
  !> a pair_watch_t then its active flag and event.
  integer, parameter :: N_EVENT_VALUES = 12, N_WATCH_ARRAYS = 5

contains

  !> Watch `size(pair_sizes)` pairs with the given numbers of slave nodes. The CSV is not
  !> written yet (rewrite_csv, once the run is known to go ahead).
  subroutine catalog_init(this, threshold, min_slip, pair_sizes, csv_path, err, writes)
    class(event_catalog_t), intent(inout) :: this
    real(dp), intent(in) :: threshold, min_slip
    integer, intent(in) :: pair_sizes(:)
    character(len=*), intent(in) :: csv_path
    type(error_t), allocatable, intent(out) :: err
    logical, intent(in), optional :: writes
    integer :: k, n
    if (present(writes)) this%writes = writes
    this%threshold = threshold
    this%min_slip = min_slip
    this%csv_path = csv_path
    allocate (this%watch(size(pair_sizes)), this%events(16))
    this%n_events = 0
    do k = 1, size(pair_sizes)
      n = pair_sizes(k)
      allocate (this%watch(k)%involved(n), this%watch(k)%slip_start(n), this%watch(k)%shear_start(n), &
                this%watch(k)%last_slip(n), this%watch(k)%last_shear(n))
      this%watch(k)%involved = .false.
      this%watch(k)%slip_start = 0.0_dp
      this%watch(k)%shear_start = 0.0_dp
      this%watch(k)%last_slip = 0.0_dp
      this%watch(k)%last_shear = 0.0_dp
    end do
  end subroutine catalog_init

  !> After an increment from t_start to t_end: the slip rate, accumulated slip and shear
  !> traction of pair k's slave nodes, their node ids and positions. `ended` returns the
  !> index of an event that ended (and was kept) in this call, 0 otherwise.
  subroutine catalog_update(this, k, t_start, t_end, rate, slip, shear, node_ids, x, ended, err)
    class(event_catalog_t), intent(inout) :: this
    integer, intent(in) :: k
    real(dp), intent(in) :: t_start, t_end, rate(:), slip(:), shear(:), x(:, :)
    integer, intent(in) :: node_ids(:)
    integer, intent(out) :: ended
    type(error_t), allocatable, intent(out) :: err
    logical :: fast(size(rate))
    integer :: first
    ended = 0
    fast = rate > this%threshold
    associate (w => this%watch(k))
      if (.not. w%active .and. any(fast)) then
        first = maxloc(rate, 1)
        w%active = .true.
        w%event = slip_event_t(pair=k, onset=t_start, hypocentre=node_ids(first), &
                               location=x(:, first))
        w%involved = .false.
        w%slip_start = w%last_slip
        w%shear_start = w%last_shear
      end if
      if (w%active) then
        w%involved = w%involved .or. fast
        w%event%peak_rate = max(w%event%peak_rate, maxval(rate))
        if (.not. any(fast)) then
          w%event%finish = t_start
          call close_event(this, k, slip, shear, ended, err)
        end if
      end if
      w%last_slip = slip
      w%last_shear = shear
    end associate
    if (t_end < t_start) ended = 0
  end subroutine catalog_update

  !> Finish the event of pair k: slip and stress drop of the nodes that took part.
  subroutine close_event(this, k, slip, shear, ended, err)
    type(event_catalog_t), intent(inout) :: this
    integer, intent(in) :: k
    real(dp), intent(in) :: slip(:), shear(:)
    integer, intent(out) :: ended
    type(error_t), allocatable, intent(out) :: err
    type(slip_event_t), allocatable :: grown(:)
    real(dp), allocatable :: event_slip(:)
    ended = 0
    associate (w => this%watch(k), e => this%watch(k)%event)
      w%active = .false.
      e%n_nodes = count(w%involved)
      if (e%n_nodes == 0) return
      event_slip = pack(slip - w%slip_start, w%involved)
      e%max_slip = maxval(event_slip)
      e%mean_slip = sum(event_slip) / e%n_nodes
      e%stress_drop = sum(pack(w%shear_start - shear, w%involved)) / e%n_nodes
      if (e%max_slip < this%min_slip) return
      if (this%n_events == size(this%events)) then
        allocate (grown(2 * size(this%events)))
        grown(1:this%n_events) = this%events(1:this%n_events)
        call move_alloc(grown, this%events)
      end if
      this%n_events = this%n_events + 1
      this%events(this%n_events) = e
      ended = this%n_events
    end associate
    call append_csv(this, ended, err)
  end subroutine close_event

  !> The catalog as a table (n_columns, n_events), columns as EVENT_COLUMNS.
  pure function catalog_table(this) result(table)
    class(event_catalog_t), intent(in) :: this
    real(dp), allocatable :: table(:, :)
    integer :: i
    allocate (table(14, this%n_events))
    do i = 1, this%n_events
      table(:, i) = event_row(this%events(i), i)
    end do
  end function catalog_table

  pure function event_row(e, i) result(row)
    type(slip_event_t), intent(in) :: e
    integer, intent(in) :: i
    real(dp) :: row(14)
    row = [real(i, dp), real(e%pair, dp), e%onset, e%finish, e%finish - e%onset, &
           real(e%n_nodes, dp), e%peak_rate, e%max_slip, e%mean_slip, e%stress_drop, &
           real(e%hypocentre, dp), e%location]
  end function event_row

  subroutine append_csv(this, i, err)
    type(event_catalog_t), intent(in) :: this
    integer, intent(in) :: i
    type(error_t), allocatable, intent(out) :: err
    type(text_file_t) :: file
    if (.not. this%writes) return
    call file%open(this%csv_path, err, append=.true.)
    if (.not. allocated(err)) call file%write(event_text(this%events(i), i), err)
    if (.not. allocated(err)) call file%close(err)
    if (allocated(err)) err%message = 'event catalog: ' // err%message
  end subroutine append_csv

  !> Event `i` as a CSV row.
  function event_text(e, i) result(text)
    type(slip_event_t), intent(in) :: e
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    character(len=512) :: buffer
    write (buffer, '(i0,a,i0,3(a,es16.9),a,i0,4(a,es16.9),a,i0,3(a,es16.9))') i, ',', e%pair, ',', &
      e%onset, ',', e%finish, ',', e%finish - e%onset, ',', e%n_nodes, ',', e%peak_rate, ',', &
      e%max_slip, ',', e%mean_slip, ',', e%stress_drop, ',', e%hypocentre, ',', e%location(1), ',', &
      e%location(2), ',', e%location(3)
    text = trim(buffer)
  end function event_text

  !> The whole CSV from the events in memory (new run, or after a restart).
  subroutine catalog_rewrite_csv(this, err)
    class(event_catalog_t), intent(inout) :: this
    type(error_t), allocatable, intent(out) :: err
    type(text_file_t) :: file
    integer :: i
    if (.not. this%writes) return
    call file%open(this%csv_path, err, atomic=.true.)
    if (.not. allocated(err)) call file%write(EVENT_COLUMNS, err)
    do i = 1, this%n_events
      if (allocated(err)) exit
      call file%write(event_text(this%events(i), i), err)
    end do
    if (.not. allocated(err)) call file%close(err)
    if (allocated(err)) then
      call file%abandon()
      err%message = 'event catalog: ' // err%message
    end if
  end subroutine catalog_rewrite_csv

  !> Write the events so far and the watch of every pair into group `group` of `archive`
  !> (records `events` and `watch_<k>`); nothing when the catalog is off.
  subroutine catalog_save(this, archive, group, err)
    class(event_catalog_t), intent(in) :: this
    class(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: group
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: table(:, :)
    integer :: i, k
    if (.not. allocated(this%watch)) return
    allocate (table(N_EVENT_VALUES, this%n_events))
    do i = 1, this%n_events
      table(:, i) = event_values(this%events(i))
    end do
    call archive%put(group // '/events', table, err)
    do k = 1, size(this%watch)
      if (allocated(err)) return
      call archive%put(group // '/watch_' // str(k), watch_values(this%watch(k)), err)
    end do
  end subroutine catalog_save

  !> Read what `save` wrote into a catalog set up for the same pairs (`init`).
  subroutine catalog_load(this, archive, group, err)
    class(event_catalog_t), intent(inout) :: this
    class(archive_t), intent(inout) :: archive
    character(len=*), intent(in) :: group
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: rows(:, :), table(:, :)
    integer :: i, k, n
    if (.not. allocated(this%watch)) return
    if (.not. archive%exists(group // '/events')) then
      call input_error(err, 'the checkpoint has no event catalog (was *EVENT CATALOG added?)')
      return
    end if
    call archive%get_columns(group // '/events', N_EVENT_VALUES, rows, err)
    if (allocated(err)) return
    n = size(rows, 2)
    deallocate (this%events)
    allocate (this%events(max(16, n)))
    do i = 1, n
      this%events(i) = values_event(rows(:, i))
    end do
    this%n_events = n
    do k = 1, size(this%watch)
      allocate (table(N_WATCH_ARRAYS * size(this%watch(k)%involved) + 1 + N_EVENT_VALUES, 1))
      call archive%get(group // '/watch_' // str(k), table, err)
      if (allocated(err)) return
      call set_watch(this%watch(k), table(:, 1))
      deallocate (table)
    end do
  end subroutine catalog_load

  pure function event_values(e) result(v)
    type(slip_event_t), intent(in) :: e
    real(dp) :: v(N_EVENT_VALUES)
    v = [real(e%pair, dp), e%onset, e%finish, real(e%n_nodes, dp), e%peak_rate, e%max_slip, &
         e%mean_slip, e%stress_drop, real(e%hypocentre, dp), e%location]
  end function event_values

  pure function values_event(v) result(e)
    real(dp), intent(in) :: v(N_EVENT_VALUES)
    type(slip_event_t) :: e
    e = slip_event_t(nint(v(1)), v(2), v(3), nint(v(4)), v(5), v(6), v(7), v(8), nint(v(9)), v(10:12))
  end function values_event

  !> A watch as one column: per-node involved flags, slip and shear at onset, last slip and
  !> shear (5 n values), then the active flag and the event under way (13).
  pure function watch_values(w) result(table)
    type(pair_watch_t), intent(in) :: w
    real(dp), allocatable :: table(:, :)
    table = reshape([merge(1.0_dp, 0.0_dp, w%involved), w%slip_start, w%shear_start, &
                     w%last_slip, w%last_shear, merge(1.0_dp, 0.0_dp, w%active), &
                     event_values(w%event)], [N_WATCH_ARRAYS * size(w%involved) + 1 + N_EVENT_VALUES, 1])
  end function watch_values

  pure subroutine set_watch(w, flat)
    type(pair_watch_t), intent(inout) :: w
    real(dp), intent(in) :: flat(:)
    integer :: n
    n = size(w%involved)
    w%involved = flat(1:n) > 0.5_dp
    w%slip_start = flat(n + 1:2 * n)
    w%shear_start = flat(2 * n + 1:3 * n)
    w%last_slip = flat(3 * n + 1:4 * n)
    w%last_shear = flat(4 * n + 1:5 * n)
    w%active = flat(5 * n + 1) > 0.5_dp
    w%event = values_event(flat(5 * n + 2:5 * n + 13))
  end subroutine set_watch

end module fcs_event_catalog
