!> Wall-clock timing of run phases and peak-memory reading.
module fcs_timer
  use fcs_kinds, only: dp, i8
  use fcs_strings, only: string_t
  implicit none
  private
  public :: wall_time, phase_timer_t, peak_memory_mib

  !> Accumulated wall time per named phase (assembly, factorisation, solve, output, ...).
  type :: phase_timer_t
    type(string_t), allocatable :: names(:)
    real(dp), allocatable :: seconds(:)
    real(dp), allocatable :: started(:)
  contains
    procedure :: start => phase_timer_start
    procedure :: stop => phase_timer_stop
    procedure :: total => phase_timer_total
  end type phase_timer_t

contains

  !> Seconds since an arbitrary origin, from the monotonic system clock.
  real(dp) function wall_time()
    integer(i8) :: count, rate
    call system_clock(count, rate)
    wall_time = real(count, dp) / real(rate, dp)
  end function wall_time

  integer function phase_index(this, name)
    class(phase_timer_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    type(string_t), allocatable :: names(:)
    real(dp), allocatable :: seconds(:), started(:)
    integer :: i, n
    if (.not. allocated(this%names)) then
      allocate (this%names(0), this%seconds(0), this%started(0))
    end if
    do i = 1, size(this%names)
      if (this%names(i)%s == name) then
        phase_index = i
        return
      end if
    end do
    n = size(this%names)
    allocate (names(n + 1), seconds(n + 1), started(n + 1))
    names(1:n) = this%names
    seconds(1:n) = this%seconds
    started(1:n) = this%started
    names(n + 1)%s = name
    seconds(n + 1) = 0.0_dp
    started(n + 1) = -1.0_dp
    call move_alloc(names, this%names)
    call move_alloc(seconds, this%seconds)
    call move_alloc(started, this%started)
    phase_index = n + 1
  end function phase_index

  subroutine phase_timer_start(this, name)
    class(phase_timer_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer :: i
    i = phase_index(this, name)
    this%started(i) = wall_time()
  end subroutine phase_timer_start

  subroutine phase_timer_stop(this, name)
    class(phase_timer_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer :: i
    i = phase_index(this, name)
    if (this%started(i) >= 0.0_dp) this%seconds(i) = this%seconds(i) + wall_time() - this%started(i)
    this%started(i) = -1.0_dp
  end subroutine phase_timer_stop

  !> Total seconds spent in phase `name` (0 if never started).
  real(dp) function phase_timer_total(this, name)
    class(phase_timer_t), intent(inout) :: this
    character(len=*), intent(in) :: name
    integer :: i
    ! The index first: phase_index may reallocate the arrays.
    i = phase_index(this, name)
    phase_timer_total = this%seconds(i)
  end function phase_timer_total

  !> Peak resident memory of this process in MiB (VmHWM from /proc/self/status; 0 if unknown).
  real(dp) function peak_memory_mib()
    integer :: unit, stat, kib
    character(len=256) :: line
    peak_memory_mib = 0.0_dp
    open (newunit=unit, file='/proc/self/status', action='read', status='old', iostat=stat)
    if (stat /= 0) return
    do
      read (unit, '(a)', iostat=stat) line
      if (stat /= 0) exit
      if (line(1:6) == 'VmHWM:') then
        read (line(7:), *, iostat=stat) kib
        if (stat == 0) peak_memory_mib = real(kib, dp) / 1024.0_dp
        exit
      end if
    end do
    close (unit)
  end function peak_memory_mib

end module fcs_timer
