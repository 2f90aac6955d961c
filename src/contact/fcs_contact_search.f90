!> Contact search: a bucket grid over the master faces of a pair (global search: no all-pairs
!> loops) and the local search that projects a slave node onto candidate faces (Newton in
!> natural coordinates, fcs_contact_geometry) with a rule at edges and kinks:
!>   - if the projection falls inside one or more candidate faces (|xi| <= 1 + XI_TOLERANCE),
!>     the face with the smallest |gap| wins (at a concave kink, the closer surface);
!>   - otherwise (a convex kink, or beyond the surface edge) the contact point is the nearest
!>     point of the nearest face's boundary (xi clamped to [-1, 1]), with that face's normal
!>     at the clamped point; the gap is measured along it.
!> The same rule decides the hand-over from one segment to the next as a contact point
!> slides (fcs_contact_system).
module fcs_contact_search
  use fcs_kinds, only: dp
  use fcs_contact_geometry, only: segment_point_t, segment_point, project_to_segment
  implicit none
  private
  public :: face_grid_t, closest_face, XI_TOLERANCE

  !> A projection this far outside [-1, 1] in natural coordinates still counts as inside.
  real(dp), parameter :: XI_TOLERANCE = 1.0e-6_dp
  !> Largest number of grid cells (the cell size grows if needed).
  integer, parameter :: MAX_CELLS = 4000000

  !> Uniform bucket grid: faces registered in every cell their bounding box (inflated by
  !> `margin`) overlaps; cell c holds faces(cell_ptr(c):cell_ptr(c+1)-1).
  type :: face_grid_t
    real(dp) :: origin(3) = 0.0_dp
    real(dp) :: cell_size = 1.0_dp
    real(dp) :: margin = 0.0_dp
    integer :: dims(3) = 1
    integer, allocatable :: cell_ptr(:), faces(:)
    !> Coordinates of the face nodes (3, 4, n_faces) when the grid was built: to know when to
    !> rebuild, and to rebuild the same grid after a restart.
    real(dp), allocatable :: built_x(:, :, :)
  contains
    procedure :: build => grid_build
    procedure :: candidates => grid_candidates
    procedure :: needs_rebuild => grid_needs_rebuild
  end type face_grid_t

contains

  !> Build the grid for faces with node coordinates face_x(3, 4, nf); faces are found for
  !> points within `margin` of their bounding box.
  subroutine grid_build(this, face_x, margin)
    class(face_grid_t), intent(inout) :: this
    real(dp), intent(in) :: face_x(:, :, :)
    real(dp), intent(in) :: margin
    real(dp) :: lo(3), hi(3), box_lo(3, size(face_x, 3)), box_hi(3, size(face_x, 3))
    integer :: f, nf, i, j, k, c, ilo(3), ihi(3)
    integer, allocatable :: count(:), fill(:)
    nf = size(face_x, 3)
    this%margin = margin
    this%cell_size = tiny(1.0_dp)
    do f = 1, nf
      box_lo(:, f) = minval(face_x(:, :, f), dim=2) - margin
      box_hi(:, f) = maxval(face_x(:, :, f), dim=2) + margin
      this%cell_size = max(this%cell_size, maxval(box_hi(:, f) - box_lo(:, f)))
    end do
    lo = minval(box_lo, dim=2)
    hi = maxval(box_hi, dim=2)
    this%origin = lo
    do
      this%dims = max(1, ceiling((hi - lo) / this%cell_size))
      if (product(int(this%dims, 8)) <= MAX_CELLS) exit
      this%cell_size = 2.0_dp * this%cell_size
    end do
    allocate (count(product(this%dims)))
    count = 0
    do f = 1, nf
      call cell_range(this, box_lo(:, f), box_hi(:, f), ilo, ihi)
      do k = ilo(3), ihi(3)
        do j = ilo(2), ihi(2)
          do i = ilo(1), ihi(1)
            c = cell_index(this, [i, j, k])
            count(c) = count(c) + 1
          end do
        end do
      end do
    end do
    if (allocated(this%cell_ptr)) deallocate (this%cell_ptr, this%faces)
    allocate (this%cell_ptr(size(count) + 1))
    this%cell_ptr(1) = 1
    do c = 1, size(count)
      this%cell_ptr(c + 1) = this%cell_ptr(c) + count(c)
    end do
    allocate (this%faces(this%cell_ptr(size(count) + 1) - 1))
    fill = this%cell_ptr(1:size(count))
    do f = 1, nf
      call cell_range(this, box_lo(:, f), box_hi(:, f), ilo, ihi)
      do k = ilo(3), ihi(3)
        do j = ilo(2), ihi(2)
          do i = ilo(1), ihi(1)
            c = cell_index(this, [i, j, k])
            this%faces(fill(c)) = f
            fill(c) = fill(c) + 1
          end do
        end do
      end do
    end do
    this%built_x = face_x
  end subroutine grid_build

  !> True when some face node has moved more than half the margin since the grid was built.
  logical function grid_needs_rebuild(this, face_nodes, x)
    class(face_grid_t), intent(in) :: this
    integer, intent(in) :: face_nodes(:, :)
    real(dp), intent(in) :: x(:, :)
    integer :: f, a
    grid_needs_rebuild = .true.
    if (.not. allocated(this%built_x)) return
    do f = 1, size(face_nodes, 2)
      do a = 1, 4
        if (norm2(x(:, face_nodes(a, f)) - this%built_x(:, a, f)) > 0.5_dp * this%margin) return
      end do
    end do
    grid_needs_rebuild = .false.
  end function grid_needs_rebuild

  subroutine cell_range(grid, lo, hi, ilo, ihi)
    type(face_grid_t), intent(in) :: grid
    real(dp), intent(in) :: lo(3), hi(3)
    integer, intent(out) :: ilo(3), ihi(3)
    ilo = min(max(floor((lo - grid%origin) / grid%cell_size) + 1, 1), grid%dims)
    ihi = min(max(floor((hi - grid%origin) / grid%cell_size) + 1, 1), grid%dims)
  end subroutine cell_range

  pure integer function cell_index(grid, ijk)
    type(face_grid_t), intent(in) :: grid
    integer, intent(in) :: ijk(3)
    cell_index = ijk(1) + grid%dims(1) * ((ijk(2) - 1) + grid%dims(2) * (ijk(3) - 1))
  end function cell_index

  !> Faces whose inflated boxes contain point p (empty if p is outside the grid).
  subroutine grid_candidates(this, p, faces)
    class(face_grid_t), intent(in) :: this
    real(dp), intent(in) :: p(3)
    integer, allocatable, intent(out) :: faces(:)
    integer :: ijk(3), c
    ijk = floor((p - this%origin) / this%cell_size) + 1
    if (any(ijk < 1) .or. any(ijk > this%dims)) then
      allocate (faces(0))
      return
    end if
    c = cell_index(this, ijk)
    faces = this%faces(this%cell_ptr(c):this%cell_ptr(c + 1) - 1)
  end subroutine grid_candidates

  !> The contact point of slave position xs among candidate faces (rule in the module
  !> header). face = 0 when no candidate face projects within `max_distance`.
  subroutine closest_face(face_nodes, x, candidates, xs, max_distance, face, point, gap)
    integer, intent(in) :: face_nodes(:, :)
    real(dp), intent(in) :: x(:, :)
    integer, intent(in) :: candidates(:)
    real(dp), intent(in) :: xs(3), max_distance
    integer, intent(out) :: face
    type(segment_point_t), intent(out) :: point
    real(dp), intent(out) :: gap
    type(segment_point_t) :: p, clamped
    real(dp) :: g, xm(3, 4), best_inside, best_edge, distance, outside
    integer :: i, f, edge_face
    logical :: converged
    type(segment_point_t) :: edge_point
    face = 0
    gap = huge(1.0_dp)
    best_inside = huge(1.0_dp)
    best_edge = huge(1.0_dp)
    edge_face = 0
    do i = 1, size(candidates)
      f = candidates(i)
      xm = x(:, face_nodes(:, f))
      call project_to_segment(xm, xs, [0.0_dp, 0.0_dp], p, g, converged)
      outside = huge(1.0_dp)
      if (converged) outside = maxval(abs(p%xi)) - 1.0_dp
      if (outside <= XI_TOLERANCE) then
        if (abs(g) < best_inside .and. abs(g) <= max_distance) then
          best_inside = abs(g)
          face = f
          point = p
          gap = g
        end if
      else
        if (converged) then
          clamped = segment_point(xm, max(-1.0_dp, min(1.0_dp, p%xi)))
        else
          clamped = segment_point(xm, [0.0_dp, 0.0_dp])
        end if
        distance = norm2(xs - clamped%x)
        if (distance < best_edge .and. distance <= max_distance) then
          best_edge = distance
          edge_face = f
          edge_point = clamped
        end if
      end if
    end do
    if (face /= 0 .or. edge_face == 0) return
    face = edge_face
    point = edge_point
    gap = dot_product(xs - point%x, point%normal)
  end subroutine closest_face

end module fcs_contact_search
