!> Heap policy of the process: memory the program frees stays in it for the next allocation.
!>
!> The linear solvers allocate and free their factor workspace at every factorisation
!> (UMFPACK's Numeric object, MUMPS's S array), hundreds of times in a run. glibc serves blocks
!> above M_MMAP_THRESHOLD (at most 32 MiB) with mmap and gives them back with munmap, so each
!> factorisation touched its workspace afresh: 1.1e7 minor page faults and 18 s of system time
!> in a 137 s run of the 19k-DOF contact benchmark (doc/performance.md). With mmap off
!> (M_MMAP_MAX = 0) and trimming off (M_TRIM_THRESHOLD = -1: a trim threshold of 1 GiB still
!> gave 3.3e7 page faults and 380 s of system time in 600 s on the 102k-DOF benchmark, whose
!> factor workspace exceeds it), large blocks come from the heap and stay there: 8e4 page
!> faults, 119 s. The price: memory the process frees is not returned to the system until it
!> ends (peak resident memory +13 % on that run).
!> Parameters: glibc's malloc.h (M_TRIM_THRESHOLD = -1, M_MMAP_MAX = -4) and mallopt(3).
module fcs_heap_policy
  use, intrinsic :: iso_c_binding, only: c_int
  use fcs_error, only: error_t, fatal_error
  implicit none
  private
  public :: keep_freed_memory

  integer(c_int), parameter :: M_TRIM_THRESHOLD = -1_c_int, M_MMAP_MAX = -4_c_int
  !> The trim threshold that turns trimming off (mallopt(3)).
  integer(c_int), parameter :: NO_TRIMMING = -1_c_int

  interface
    function c_mallopt(param, value) bind(c, name='mallopt') result(ok)
      import :: c_int
      integer(c_int), value :: param, value
      integer(c_int) :: ok
    end function c_mallopt
  end interface

contains

  !> Turns mmap off for heap blocks and trimming off (mallopt returns 1 on success).
  subroutine keep_freed_memory(err)
    type(error_t), allocatable, intent(out) :: err
    if (c_mallopt(M_MMAP_MAX, 0_c_int) /= 1_c_int) then
      call fatal_error(err, 'mallopt(M_MMAP_MAX, 0) failed')
      return
    end if
    if (c_mallopt(M_TRIM_THRESHOLD, NO_TRIMMING) /= 1_c_int) &
      call fatal_error(err, 'mallopt(M_TRIM_THRESHOLD) failed')
  end subroutine keep_freed_memory

end module fcs_heap_policy
