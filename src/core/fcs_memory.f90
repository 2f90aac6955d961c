!> Running out of memory: the error fcs3d gives, the reserve that lets it give it, and the BLAS
!> set-up that keeps OpenBLAS from hanging.
!>
!> * `memory_error` makes the run's error "out of memory while <what> (needed about N MiB)"
!>   (exit status 1). Large arrays are allocated with `stat=` and turned into it
!>   (`allocation_failed`); library statuses that mean "no memory" (UMFPACK, MUMPS, HDF5's
!>   errno ENOMEM) too.
!> * The reserve: `prepare_memory` allocates and touches MEMORY_RESERVE_MIB of heap at the start;
!>   `memory_error` frees it, so that what runs after the failure (the message, closing the
!>   results file, the last good frame and checkpoint of the driver) finds memory again. With
!>   the heap policy of fcs_heap_policy freed blocks stay in the process, so the reserve is
!>   really there for the next allocations. Like the signal flag of fcs_signals, the reserve is
!>   process-wide state and therefore a module variable (doc/architecture.md).
!> * OpenBLAS (0.3.21, pthreads) allocates a 128 MiB work buffer for each thread: its worker
!>   threads at library load, the calling thread at its first BLAS call; when an allocation
!>   fails it retries for ever (blas_memory_alloc), and a worker stuck so also hangs the exit
!>   (fcs3d hung with `ulimit -v` of 100 to 300 MB). Hence:
!>   - `pin_blas_threads`, the first thing main does: unless the user chose a number of threads
!>     (OPENBLAS_NUM_THREADS, GOTO_NUM_THREADS, OMP_NUM_THREADS), fcs3d sets
!>     OPENBLAS_NUM_THREADS=1 and executes itself again, because OpenBLAS reads the variable
!>     only when it is loaded; with one thread OpenBLAS starts no worker (measured at start:
!>     58 to 189 MB of address space with the default two threads, depending on whether the
!>     worker has allocated its buffer yet; 50 MB with one). Under MPI (the launcher's variables
!>     are set) it calls openblas_set_num_threads(1) instead. One thread is also what `make run`
!>     chose for reproducible round-off (doc/performance.md);
!>   - `prepare_memory` checks that the address-space limit leaves room for the calling
!>     thread's buffer, then makes one tiny BLAS call so that the buffer is allocated at once,
!>     while memory is certainly there, and kept for the whole run.
!> * `ensure_memory` asks for a block of the size a phase will need and frees it at once: with
!>   the heap policy of fcs_heap_policy the block stays in the process, so the phase's own
!>   allocations find it, and a shortage is reported before the phase starts.
!> * The safety net for the allocations that cannot report back (an ALLOCATE without STAT=, an
!>   automatic reallocation, an array temporary; the Makefile's -fcheck=mem makes the last
!>   checked): gfortran's run-time library then prints "Error allocating N bytes" and calls
!>   exit. `prepare_memory` registers an exit handler that, unless main said the exit is its
!>   own (`mark_normal_exit`), adds "fcs3d: out of memory while <activity>" when errno is
!>   ENOMEM (the activity is what the driver said it was doing, `set_activity`), writes the
!>   same into the log, and ends the process with status 1 at once (the run-time library would
!>   give 2, "bad input", for its other errors; and no library clean-up runs, so the results
!>   file stays as its last flush left it). When the heap is exhausted to its last byte, the
!>   run-time library's own error report fails to allocate and recurses until the stack
!>   overflows (seen while reading a large deck under `ulimit -v`); a handler of SIGSEGV and
!>   SIGBUS on an alternate stack gives the same message and status 1 when errno says ENOMEM,
!>   and otherwise restores the previous handler (gfortran's backtrace) and lets the signal
!>   take its course. The structures are glibc's on 64-bit Linux (bits/sigaction.h, stack_t).
!>   Like the reserve, this is process-wide state.
module fcs_memory
  use, intrinsic :: iso_c_binding, only: c_int, c_long, c_char, c_ptr, c_funptr, c_null_ptr, &
    c_null_char, c_associated, c_f_procpointer, c_loc, c_funloc, c_f_pointer, c_signed_char, &
    c_size_t
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, fatal_error
  use fcs_strings, only: str
  implicit none
  private
  public :: pin_blas_threads, prepare_memory, memory_error, allocation_failed, &
    release_memory_reserve, address_space_left, ensure_memory, set_activity, set_failure_log, &
    mark_normal_exit, ERRNO_NO_MEMORY, MEMORY_RESERVE_MIB

  !> errno of a failed allocation (ENOMEM).
  integer, parameter :: ERRNO_NO_MEMORY = 12
  !> Heap held back for the work that follows an out-of-memory failure [MiB].
  integer, parameter :: MEMORY_RESERVE_MIB = 16
  !> Address space the first BLAS call needs besides what is mapped already [MiB] (OpenBLAS
  !> 0.3.21 maps a 128 MiB buffer, 129 MiB with its alignment; measured 147 MB with the
  !> reserve).
  integer, parameter :: BLAS_BUFFER_MIB = 130
  !> Environment variables by which the user sets the BLAS threads, and by which an MPI
  !> launcher shows itself (Open MPI, PMIx, MPICH's PMI).
  character(len=*), parameter :: THREAD_VARIABLES(3) = [character(len=20) :: &
    'OPENBLAS_NUM_THREADS', 'GOTO_NUM_THREADS', 'OMP_NUM_THREADS']
  character(len=*), parameter :: LAUNCHER_VARIABLES(3) = [character(len=20) :: &
    'OMPI_COMM_WORLD_SIZE', 'PMIX_RANK', 'PMI_RANK']
  !> Set (to 1) when fcs3d itself chose one BLAS thread, for the note in the log.
  character(len=*), parameter :: PINNED_MARK = 'FCS3D_PINNED_BLAS_THREADS'
  integer, parameter :: MAX_ARGUMENTS = 256
  !> getrlimit(2) resource number of the address-space limit (ulimit -v), and "no limit".
  integer(c_int), parameter :: RLIMIT_AS = 9_c_int
  integer(c_long), parameter :: RLIM_INFINITY = -1_c_long
  integer(i8), parameter :: MIB = 1048576_i8

  !> The reserve (see above): allocated by prepare_memory, freed by memory_error.
  real(dp), allocatable, save :: reserve(:)
  !> For the exit handler: what the run is doing and about how much memory that needs, the
  !> log to write to, and whether main ends the process itself.
  character(len=256), save :: activity = 'starting'
  integer(i8), save :: activity_bytes = 0
  character(len=1024), save :: failure_log = ''
  logical, save :: normal_exit = .false., handler_registered = .false.
  integer, parameter :: STDERR = 2
  !> SIGBUS and SIGSEGV; sigaction flags SA_ONSTACK and SA_RESETHAND (bits/sigaction.h).
  integer(c_int), parameter :: SIGBUS = 7_c_int, SIGSEGV = 11_c_int
  integer(c_int), parameter :: SA_ONSTACK = int(z'08000000', c_int), &
    SA_RESETHAND = int(z'80000000', c_int)
  !> The alternate stack of the signal handler [bytes].
  integer, parameter :: SIGNAL_STACK_BYTES = 65536

  !> struct sigaction of glibc on 64-bit Linux: handler, 1024-bit mask, flags, restorer.
  type, bind(c) :: sigaction_t
    type(c_funptr) :: handler
    integer(c_long) :: mask(16) = 0
    integer(c_int) :: flags = 0, padding = 0
    type(c_ptr) :: restorer = c_null_ptr
  end type sigaction_t
  !> stack_t: base, flags, size.
  type, bind(c) :: stack_t
    type(c_ptr) :: base = c_null_ptr
    integer(c_int) :: flags = 0, padding = 0
    integer(c_size_t) :: size = 0
  end type stack_t

  !> The handlers the signal handler replaced (restored for crashes that are not memory), and
  !> its stack.
  type(sigaction_t), save :: previous_action(2)
  integer(c_signed_char), save, target :: signal_stack(SIGNAL_STACK_BYTES)

  type, bind(c) :: rlimit_t
    integer(c_long) :: current = 0, maximum = 0
  end type rlimit_t

  abstract interface
    subroutine set_threads_interface(n) bind(c)
      import :: c_int
      integer(c_int), value :: n
    end subroutine set_threads_interface
  end interface

  interface
    function c_sigaction(signum, action, old_action) bind(c, name='sigaction') result(status)
      import :: c_int, sigaction_t
      integer(c_int), value :: signum
      type(sigaction_t), intent(in) :: action
      type(sigaction_t), intent(out) :: old_action
      integer(c_int) :: status
    end function c_sigaction
    function c_sigaltstack(stack, old_stack) bind(c, name='sigaltstack') result(status)
      import :: c_int, stack_t, c_ptr
      type(stack_t), intent(in) :: stack
      type(c_ptr), value :: old_stack
      integer(c_int) :: status
    end function c_sigaltstack
    function c_atexit(handler) bind(c, name='atexit') result(status)
      import :: c_funptr, c_int
      type(c_funptr), value :: handler
      integer(c_int) :: status
    end function c_atexit
    subroutine c_exit_now(status) bind(c, name='_exit')
      import :: c_int
      integer(c_int), value :: status
    end subroutine c_exit_now
    function c_write(descriptor, buffer, count) bind(c, name='write') result(written)
      import :: c_int, c_char, c_long
      integer(c_int), value :: descriptor
      character(kind=c_char), intent(in) :: buffer(*)
      integer(c_long), value :: count
      integer(c_long) :: written
    end function c_write
    function c_fopen(path, mode) bind(c, name='fopen') result(stream)
      import :: c_char, c_ptr
      character(kind=c_char), intent(in) :: path(*), mode(*)
      type(c_ptr) :: stream
    end function c_fopen
    function c_fputs(text, stream) bind(c, name='fputs') result(status)
      import :: c_char, c_ptr, c_int
      character(kind=c_char), intent(in) :: text(*)
      type(c_ptr), value :: stream
      integer(c_int) :: status
    end function c_fputs
    function c_fclose(stream) bind(c, name='fclose') result(status)
      import :: c_ptr, c_int
      type(c_ptr), value :: stream
      integer(c_int) :: status
    end function c_fclose
    function c_errno_location() bind(c, name='__errno_location') result(location)
      import :: c_ptr
      type(c_ptr) :: location
    end function c_errno_location
    function c_setenv(name, value, overwrite) bind(c, name='setenv') result(status)
      import :: c_char, c_int
      character(kind=c_char), intent(in) :: name(*), value(*)
      integer(c_int), value :: overwrite
      integer(c_int) :: status
    end function c_setenv
    function c_execv(path, arguments) bind(c, name='execv') result(status)
      import :: c_char, c_ptr, c_int
      character(kind=c_char), intent(in) :: path(*)
      type(c_ptr), intent(in) :: arguments(*)
      integer(c_int) :: status
    end function c_execv
    function c_getrlimit(resource, limit) bind(c, name='getrlimit') result(status)
      import :: c_int, rlimit_t
      integer(c_int), value :: resource
      type(rlimit_t), intent(out) :: limit
      integer(c_int) :: status
    end function c_getrlimit
    !> dlsym(RTLD_DEFAULT, name): RTLD_DEFAULT is the null handle.
    function c_dlsym(handle, name) bind(c, name='dlsym') result(address)
      import :: c_ptr, c_char, c_funptr
      type(c_ptr), value :: handle
      character(kind=c_char), intent(in) :: name(*)
      type(c_funptr) :: address
    end function c_dlsym
    !> BLAS: y = alpha A x + beta y, A symmetric (reference BLAS interface).
    subroutine dsymv(uplo, n, alpha, a, lda, x, incx, beta, y, incy)
      import :: dp
      character(len=1), intent(in) :: uplo
      integer, intent(in) :: n, lda, incx, incy
      real(dp), intent(in) :: alpha, beta, a(lda, *), x(*)
      real(dp), intent(inout) :: y(*)
    end subroutine dsymv
  end interface

contains

  !> One BLAS thread unless the user chose a number (see the module header): set
  !> OPENBLAS_NUM_THREADS=1 and execute this program again with the same arguments; under an
  !> MPI launcher, or if that fails, tell OpenBLAS directly. Call it first in main.
  subroutine pin_blas_threads()
    integer(c_int) :: status
    logical :: done
    if (any_set(THREAD_VARIABLES)) return
    if (.not. any_set(LAUNCHER_VARIABLES)) then
      status = c_setenv('OPENBLAS_NUM_THREADS' // c_null_char, '1' // c_null_char, 1_c_int)
      if (status == 0) status = c_setenv(PINNED_MARK // c_null_char, '1' // c_null_char, 1_c_int)
      if (status == 0) call execute_again()
    end if
    done = set_blas_threads(1)
  end subroutine pin_blas_threads

  !> execv("/proc/self/exe", the same arguments); returns only when that fails.
  subroutine execute_again()
    type :: argument_t
      character(kind=c_char, len=:), allocatable :: text
    end type argument_t
    type(argument_t), allocatable, target :: arguments(:)
    type(c_ptr) :: pointers(MAX_ARGUMENTS + 1)
    integer :: i, n, length
    integer(c_int) :: status
    n = command_argument_count()
    if (n + 1 > MAX_ARGUMENTS) return
    allocate (arguments(0:n))
    do i = 0, n
      call get_command_argument(i, length=length)
      allocate (character(kind=c_char, len=length + 1) :: arguments(i)%text)
      call get_command_argument(i, arguments(i)%text(1:length))
      arguments(i)%text(length + 1:length + 1) = c_null_char
      pointers(i + 1) = c_loc(arguments(i)%text(1:1))
    end do
    pointers(n + 2) = c_null_ptr
    status = c_execv('/proc/self/exe' // c_null_char, pointers)
  end subroutine execute_again

  !> True when one of the environment variables `names` is set and not empty.
  logical function any_set(names)
    character(len=*), intent(in) :: names(:)
    integer :: i, length, status
    any_set = .false.
    do i = 1, size(names)
      call get_environment_variable(trim(names(i)), length=length, status=status)
      if (status == 0 .and. length > 0) any_set = .true.
    end do
  end function any_set

  !> At the start of a run: room for the BLAS buffer under an address-space limit, the BLAS
  !> buffer itself, and the reserve. `note` says how the BLAS threads were chosen (for the log).
  subroutine prepare_memory(note, err)
    character(len=:), allocatable, intent(out) :: note
    type(error_t), allocatable, intent(out) :: err
    integer(i8) :: left
    note = ''
    if (any_set([PINNED_MARK])) note = 'OpenBLAS runs on one thread (OPENBLAS_NUM_THREADS=1 ' // &
      'set by fcs3d; set OPENBLAS_NUM_THREADS yourself for more)'
    left = address_space_left()
    if (left >= 0 .and. left < (BLAS_BUFFER_MIB + 2 * MEMORY_RESERVE_MIB) * MIB) then
      call fatal_error(err, 'out of memory while starting: the address-space limit ' // &
        '(ulimit -v) leaves only ' // str(left / MIB) // ' MiB (needed about ' // &
        str(BLAS_BUFFER_MIB + 2 * MEMORY_RESERVE_MIB) // ' MiB more to start)')
      return
    end if
    call touch_blas_buffer()
    call hold_reserve(err)
    if (handler_registered) return
    handler_registered = c_atexit(c_funloc(on_exit)) == 0
    call catch_crashes()
  end subroutine prepare_memory

  !> Install the SIGSEGV/SIGBUS handler on its own stack (see the module header).
  subroutine catch_crashes()
    type(stack_t) :: stack
    type(sigaction_t) :: action
    integer(c_int) :: status
    stack%base = c_loc(signal_stack)
    stack%size = int(SIGNAL_STACK_BYTES, c_size_t)
    if (c_sigaltstack(stack, c_null_ptr) /= 0) return
    action%handler = c_funloc(on_crash)
    action%flags = ior(SA_ONSTACK, SA_RESETHAND)
    status = c_sigaction(SIGSEGV, action, previous_action(1))
    status = c_sigaction(SIGBUS, action, previous_action(2))
  end subroutine catch_crashes

  !> SIGSEGV/SIGBUS: out of memory (errno ENOMEM) ends the run with the message and status 1;
  !> any other crash goes back to the handler that was there before, and the signal is raised
  !> again when the faulting instruction is retried.
  subroutine on_crash(signum) bind(c)
    integer(c_int), value :: signum
    integer(c_int), pointer :: errno
    type(sigaction_t) :: ignored
    integer(c_int) :: status
    call c_f_pointer(c_errno_location(), errno)
    if (errno == ERRNO_NO_MEMORY .and. .not. normal_exit) then
      normal_exit = .true.
      call report_failure('fcs3d: out of memory while ')
    end if
    if (signum == SIGSEGV) then
      status = c_sigaction(SIGSEGV, previous_action(1), ignored)
    else
      status = c_sigaction(SIGBUS, previous_action(2), ignored)
    end if
  end subroutine on_crash

  !> Say what the run is doing now (for the exit handler's message), and about how many bytes
  !> it needs (0: unknown).
  subroutine set_activity(what, bytes)
    character(len=*), intent(in) :: what
    integer(i8), intent(in), optional :: bytes
    activity = what
    activity_bytes = 0
    if (present(bytes)) activity_bytes = bytes
  end subroutine set_activity

  !> The log file the exit handler appends its message to ('' for none).
  subroutine set_failure_log(path)
    character(len=*), intent(in) :: path
    failure_log = path
  end subroutine set_failure_log

  !> Main ends the process itself (success or a reported error): the exit handler stays quiet.
  subroutine mark_normal_exit()
    normal_exit = .true.
  end subroutine mark_normal_exit

  !> Ask for `bytes` bytes and give them back at once (see the module header): an error
  !> "out of memory while <what>" if they are not there.
  subroutine ensure_memory(bytes, what, err)
    integer(i8), intent(in) :: bytes
    character(len=*), intent(in) :: what
    type(error_t), allocatable, intent(out) :: err
    integer(c_signed_char), allocatable :: block(:)
    integer :: status
    if (bytes <= 0) return
    allocate (block(bytes), stat=status)
    if (status /= 0) then
      call memory_error(err, what, bytes)
      return
    end if
    deallocate (block)
  end subroutine ensure_memory

  !> The exit handler (see the module header).
  subroutine on_exit() bind(c)
    integer(c_int), pointer :: errno
    if (normal_exit) return
    call c_f_pointer(c_errno_location(), errno)
    if (errno == ERRNO_NO_MEMORY) then
      call report_failure('fcs3d: out of memory while ')
    else
      call report_failure('fcs3d: stopped by the Fortran run-time library (message above) while ')
    end if
  end subroutine on_exit

  !> Write `opening` and the activity (with its memory figure) to standard error and the log,
  !> and end the process with status 1 at once. It runs in the exit and signal handlers when
  !> memory may be exhausted: nothing here allocates (a fixed buffer on the stack, system
  !> calls; the log is skipped if fopen finds no memory).
  subroutine report_failure(opening)
    character(len=*), intent(in) :: opening
    character(kind=c_char, len=1024) :: line
    character(kind=c_char, len=len(failure_log) + 1) :: path
    type(c_ptr) :: stream
    integer(c_int) :: status
    integer(c_long) :: written
    integer :: n
    n = 0
    call put(line, n, opening)
    call put(line, n, activity(1:len_trim(activity)))
    if (activity_bytes > 0) then
      call put(line, n, ' (needed about ')
      call put_integer(line, n, max(1_i8, (activity_bytes + MIB / 2) / MIB))
      call put(line, n, ' MiB)')
    end if
    call put(line, n, achar(10))
    written = c_write(STDERR, line, int(n, c_long))
    if (len_trim(failure_log) > 0) then
      line(n + 1:n + 1) = c_null_char
      path = failure_log
      path(len_trim(failure_log) + 1:len_trim(failure_log) + 1) = c_null_char
      stream = c_fopen(path, 'a' // c_null_char)
      if (c_associated(stream)) then
        status = c_fputs(line, stream)
        status = c_fputs('exit status 1 (run failure)' // achar(10) // c_null_char, stream)
        status = c_fclose(stream)
      end if
    end if
    call c_exit_now(1_c_int)
  end subroutine report_failure

  !> Append `text` to `line(1:n)` (cut at the buffer's end, one character kept for a NUL).
  subroutine put(line, n, text)
    character(len=*), intent(inout) :: line
    integer, intent(inout) :: n
    character(len=*), intent(in) :: text
    integer :: m
    m = min(len(text), len(line) - 1 - n)
    if (m <= 0) return
    line(n + 1:n + m) = text(1:m)
    n = n + m
  end subroutine put

  !> Append the decimal digits of `value` (>= 0) without any allocation.
  subroutine put_integer(line, n, value)
    character(len=*), intent(inout) :: line
    integer, intent(inout) :: n
    integer(i8), intent(in) :: value
    character(len=20) :: digits
    integer(i8) :: rest
    integer :: k
    rest = value
    k = len(digits) + 1
    do
      k = k - 1
      digits(k:k) = achar(iachar('0') + int(mod(rest, 10_i8)))
      rest = rest / 10_i8
      if (rest == 0 .or. k == 1) exit
    end do
    call put(line, n, digits(k:))
  end subroutine put_integer

  !> openblas_set_num_threads(n) when the BLAS library is OpenBLAS; false otherwise.
  logical function set_blas_threads(n) result(done)
    integer, intent(in) :: n
    type(c_funptr) :: address
    procedure(set_threads_interface), pointer :: set_threads
    address = c_dlsym(c_null_ptr, 'openblas_set_num_threads' // c_null_char)
    done = c_associated(address)
    if (.not. done) return
    call c_f_procpointer(address, set_threads)
    call set_threads(int(n, c_int))
  end function set_blas_threads

  !> One 1 x 1 symmetric product: OpenBLAS allocates its buffer for this thread now.
  subroutine touch_blas_buffer()
    real(dp) :: a(1, 1), x(1), y(1)
    a = 1.0_dp
    x = 1.0_dp
    y = 0.0_dp
    call dsymv('U', 1, 1.0_dp, a, 1, x, 1, 0.0_dp, y, 1)
  end subroutine touch_blas_buffer

  !> Allocate and touch the reserve.
  subroutine hold_reserve(err)
    type(error_t), allocatable, intent(out) :: err
    integer :: status
    if (allocated(reserve)) return
    allocate (reserve(MEMORY_RESERVE_MIB * MIB / 8), stat=status)
    if (status /= 0) then
      call fatal_error(err, 'out of memory while starting (needed about ' // &
        str(MEMORY_RESERVE_MIB) // ' MiB)')
      return
    end if
    reserve = 0.0_dp
  end subroutine hold_reserve

  !> Free the reserve (idempotent).
  subroutine release_memory_reserve()
    if (allocated(reserve)) deallocate (reserve)
  end subroutine release_memory_reserve

  !> Address space left under the limit of `ulimit -v` [bytes]; -1 when there is no limit.
  integer(i8) function address_space_left() result(left)
    type(rlimit_t) :: limit
    left = -1
    if (c_getrlimit(RLIMIT_AS, limit) /= 0) return
    if (limit%current == RLIM_INFINITY .or. limit%current < 0) return
    left = max(0_i8, int(limit%current, i8) - mapped_bytes())
  end function address_space_left

  !> Size of this process's address space [bytes] (/proc/self/statm, in pages of 4 KiB);
  !> 0 when it cannot be read.
  integer(i8) function mapped_bytes() result(bytes)
    integer :: unit, status
    integer(i8) :: pages
    bytes = 0
    open (newunit=unit, file='/proc/self/statm', action='read', status='old', iostat=status)
    if (status /= 0) return
    read (unit, *, iostat=status) pages
    if (status == 0) bytes = pages * 4096_i8
    close (unit, iostat=status)
  end function mapped_bytes

  !> The error "out of memory while <what> (needed about N MiB)" (exit status 1; without the
  !> figure when `bytes` is 0). Frees the reserve, so that the work after the failure has
  !> memory.
  subroutine memory_error(err, what, bytes)
    type(error_t), allocatable, intent(out) :: err
    character(len=*), intent(in) :: what
    integer(i8), intent(in) :: bytes
    call release_memory_reserve()
    if (bytes > 0) then
      call fatal_error(err, 'out of memory while ' // what // ' (needed about ' // &
        str(max(1_i8, (bytes + MIB / 2) / MIB)) // ' MiB)')
    else
      call fatal_error(err, 'out of memory while ' // what)
    end if
  end subroutine memory_error

  !> After `allocate (..., stat=status)`: true, with the memory error, when it failed.
  !> `bytes` is the size asked for.
  logical function allocation_failed(status, what, bytes, err) result(failed)
    integer, intent(in) :: status
    character(len=*), intent(in) :: what
    integer(i8), intent(in) :: bytes
    type(error_t), allocatable, intent(inout) :: err
    failed = status /= 0
    if (failed) call memory_error(err, what, bytes)
  end function allocation_failed

end module fcs_memory
