!> Sorting helpers: in-place heap sort and a stable index sort (merge sort).
module fcs_sort
  use fcs_kinds, only: dp
  implicit none
  private
  public :: sort_integers, argsort_integers, argsort_reals, unique_sorted

contains

  !> Sort integers in place (heap sort, O(n log n), no extra memory).
  pure subroutine sort_integers(a)
    integer, intent(inout) :: a(:)
    integer :: n, i, tmp
    n = size(a)
    do i = n / 2, 1, -1
      call sift_down(a, i, n)
    end do
    do i = n, 2, -1
      tmp = a(1)
      a(1) = a(i)
      a(i) = tmp
      call sift_down(a, 1, i - 1)
    end do
  end subroutine sort_integers

  pure subroutine sift_down(a, start, last)
    integer, intent(inout) :: a(:)
    integer, intent(in) :: start, last
    integer :: root, child, tmp
    root = start
    do while (2 * root <= last)
      child = 2 * root
      if (child < last) then
        if (a(child) < a(child + 1)) child = child + 1
      end if
      if (a(root) >= a(child)) return
      tmp = a(root)
      a(root) = a(child)
      a(child) = tmp
      root = child
    end do
  end subroutine sift_down

  !> Sorted copy without repeated values.
  pure function unique_sorted(values) result(out)
    integer, intent(in) :: values(:)
    integer, allocatable :: out(:)
    integer, allocatable :: all(:)
    integer :: i, n
    allocate (all(size(values)))
    all(:) = values
    call sort_integers(all)
    allocate (out(size(all)))
    n = 0
    do i = 1, size(all)
      if (n > 0) then
        if (out(n) == all(i)) cycle
      end if
      n = n + 1
      out(n) = all(i)
    end do
    out = out(1:n)
  end function unique_sorted

  !> Permutation that sorts `a` ascending, stable for equal keys.
  pure function argsort_integers(a) result(order)
    integer, intent(in) :: a(:)
    integer, allocatable :: order(:)
    integer, allocatable :: work(:)
    integer :: i, width, lo, mid, hi, n
    n = size(a)
    allocate (order(n), work(n))
    order = [(i, i = 1, n)]
    width = 1
    do while (width < n)
      lo = 1
      do while (lo <= n)
        mid = min(lo + width - 1, n)
        hi = min(lo + 2 * width - 1, n)
        if (mid < hi) call merge_int(a, order, work, lo, mid, hi)
        lo = lo + 2 * width
      end do
      width = 2 * width
    end do
  end function argsort_integers

  pure subroutine merge_int(a, order, work, lo, mid, hi)
    integer, intent(in) :: a(:)
    integer, intent(inout) :: order(:), work(:)
    integer, intent(in) :: lo, mid, hi
    integer :: i, j, k
    i = lo
    j = mid + 1
    k = lo
    do while (i <= mid .and. j <= hi)
      if (a(order(j)) < a(order(i))) then
        work(k) = order(j)
        j = j + 1
      else
        work(k) = order(i)
        i = i + 1
      end if
      k = k + 1
    end do
    work(k:k + mid - i) = order(i:mid)
    k = k + mid - i + 1
    work(k:k + hi - j) = order(j:hi)
    order(lo:hi) = work(lo:hi)
  end subroutine merge_int

  !> Permutation that sorts real values ascending, stable for equal keys.
  pure function argsort_reals(a) result(order)
    real(dp), intent(in) :: a(:)
    integer, allocatable :: order(:)
    integer, allocatable :: work(:)
    integer :: i, j, k, width, lo, mid, hi, n
    n = size(a)
    allocate (order(n), work(n))
    order = [(i, i = 1, n)]
    width = 1
    do while (width < n)
      lo = 1
      do while (lo <= n)
        mid = min(lo + width - 1, n)
        hi = min(lo + 2 * width - 1, n)
        if (mid < hi) then
          i = lo
          j = mid + 1
          k = lo
          do while (i <= mid .and. j <= hi)
            if (a(order(j)) < a(order(i))) then
              work(k) = order(j)
              j = j + 1
            else
              work(k) = order(i)
              i = i + 1
            end if
            k = k + 1
          end do
          work(k:k + mid - i) = order(i:mid)
          k = k + mid - i + 1
          work(k:k + hi - j) = order(j:hi)
          order(lo:hi) = work(lo:hi)
        end if
        lo = lo + 2 * width
      end do
      width = 2 * width
    end do
  end function argsort_reals

end module fcs_sort
