!> Contact search: a bucket grid over the master faces of a pair (global search: no all-pairs
!> loops) and the local search that projects a slave node onto candidate faces (Newton in
!> natural coordinates, fcs_contact_geometry) with a rule at edges and kinks:
!>   - if the projection falls inside one or more candidate faces (every edge excess <=
!>     XI_TOLERANCE), the face with the smallest |gap| wins (at a concave kink, the closer
!>     surface);
!>   - otherwise (a convex kink, or beyond the surface edge) the contact point is the nearest
!>     point of the nearest face's boundary (xi clamped to the natural domain), with that
!>     face's normal at the clamped point; the gap is measured along it.
!> Faces may have 3, 4, 6 or 8 nodes (face_nodes(:, f) padded with 0 past its n_nodes). The
!> edge excess of a point is measured in units of half the natural span of the face, so that
!> the tolerances mean the same on triangles (span 1) as on quadrilaterals (span 2).
!> The same rule decides the hand-over from one segment to the next as a contact point
!> slides (fcs_contact_system).
module fcs_contact_search
  use fcs_kinds, only: dp
  use fcs_contact_geometry, only: segment_point_t, segment_point, project_to_segment, &
                                  segment_centre, segment_clamp, is_triangle
  implicit none
  private
  public :: face_grid_t, closest_face, edge_excess, edge_support, XI_TOLERANCE, EDGE_EXTENSION
  public :: face_node_count

  !> A projection this far outside [-1, 1] in natural coordinates still counts as inside.
  real(dp), parameter :: XI_TOLERANCE = 1.0e-6_dp
  !> How far (natural coordinates, of the span 2 of a face) a master surface extends past
  !> its free edges: a slave node flush with the edge of the master body, or pushed a hair
  !> past it by the lateral (Poisson) expansion of the bodies, keeps its contact; one that
  !> slides farther off loses it.
  real(dp), parameter :: EDGE_EXTENSION = 1.0e-1_dp
  !> The edge point of a face is a fallback contact point (a convex kink) only for a
  !> projection at most this far (natural coordinates) past its shared edges: a point
  !> farther out belongs to the neighbouring face, or is off the surface.
  real(dp), parameter :: CLAMP_LIMIT = 0.5_dp
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
    !> Coordinates of the face nodes (3, nodes per face, n_faces) when the grid was built: to know when to
    !> rebuild, and to rebuild the same grid after a restart.
    real(dp), allocatable :: built_x(:, :, :)
  contains
    procedure :: build => grid_build
    procedure :: candidates => grid_candidates
    procedure :: needs_rebuild => grid_needs_rebuild
  end type face_grid_t

contains

  !> Build the grid for faces with node coordinates face_x(3, nodes, nf) (a face with fewer
  !> nodes repeats its first node in the unused columns); faces are found for
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
      do a = 1, face_node_count(face_nodes(:, f))
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
  !> `free_edge(k, f)` (k = 1..4: the edges xi_2 = -1, xi_1 = 1, xi_2 = 1, xi_1 = -1 of a
  !> quadrilateral; k = 1..3: the edges t = 0, s + t = 1, s = 0 of a triangle) says
  !> which edges of a face bound the master surface (no other face of the surface shares
  !> them). Beyond such an edge the surface ends: a projection up to EDGE_EXTENSION past it
  !> still counts (on the face's continuation, as if inside), one farther past it gives no
  !> contact point on that face, not a point clamped to the edge. Across a shared edge (a
  !> convex kink) the clamped edge point is the fallback, as before. A projection strictly
  !> inside a face is preferred to one in an extension (two master bodies side by side).
  !> Without `extend` (or with extend false) the extensions do not count: an open node
  !> closes only strictly on the master surface, a closed one keeps its contact up to the end
  !> of the extension (no chatter of a node on the edge between open and closed).
  subroutine closest_face(face_nodes, x, candidates, xs, max_distance, face, point, gap, free_edge, &
                          extend)
    integer, intent(in) :: face_nodes(:, :)
    real(dp), intent(in) :: x(:, :)
    integer, intent(in) :: candidates(:)
    real(dp), intent(in) :: xs(3), max_distance
    integer, intent(out) :: face
    type(segment_point_t), intent(out) :: point
    real(dp), intent(out) :: gap
    logical, intent(in), optional :: free_edge(:, :)
    logical, intent(in), optional :: extend
    type(segment_point_t) :: p, clamped, extended_point, edge_point
    real(dp) :: g, best_inside, best_extended, best_edge, distance, excess(4)
    real(dp), allocatable :: xm(:, :)
    integer :: i, f, edge_face, extended_face, n
    logical :: converged, free(4), extended
    extended = .false.
    if (present(extend)) extended = extend
    face = 0
    gap = huge(1.0_dp)
    best_inside = huge(1.0_dp)
    best_extended = huge(1.0_dp)
    best_edge = huge(1.0_dp)
    edge_face = 0
    extended_face = 0
    do i = 1, size(candidates)
      f = candidates(i)
      n = face_node_count(face_nodes(:, f))
      xm = x(:, face_nodes(1:n, f))
      free = .false.
      if (present(free_edge)) free = free_edge(:, f)
      call project_to_segment(xm, xs, segment_centre(n), p, g, converged)
      excess = huge(1.0_dp)
      if (converged) excess = edge_excess(p%xi, n)
      if (all(excess <= XI_TOLERANCE)) then
        if (abs(g) < best_inside .and. abs(g) <= max_distance) then
          best_inside = abs(g)
          face = f
          point = p
          gap = g
        end if
      else if (converged .and. all(excess <= XI_TOLERANCE .or. (free .and. excess <= EDGE_EXTENSION))) then
        if (.not. extended) cycle
        if (abs(g) < best_extended .and. abs(g) <= max_distance) then
          best_extended = abs(g)
          extended_face = f
          extended_point = p
        end if
      else if (converged .and. all(excess <= merge(EDGE_EXTENSION, CLAMP_LIMIT, free))) then
        clamped = segment_point(xm, segment_clamp(p%xi, n))
        distance = norm2(xs - clamped%x)
        if (distance < best_edge .and. distance <= max_distance) then
          best_edge = distance
          edge_face = f
          edge_point = clamped
        end if
      end if
    end do
    if (face /= 0) return
    if (extended_face /= 0) then
      face = extended_face
      point = extended_point
    else if (edge_face /= 0) then
      face = edge_face
      point = edge_point
    else
      return
    end if
    gap = dot_product(xs - point%x, point%normal)
  end subroutine closest_face

  !> The support a master segment gives at natural point xi (Xing & Makinouchi's segments
  !> extended past the free edges of the master surface): 1 on the segment and past its
  !> shared edges, falling linearly to 0 across the extension EDGE_EXTENSION past a free
  !> edge, 0 beyond; the product of the two directions at a corner. `dw` is its derivative
  !> with respect to xi (n_nodes: of the face; on a triangle the product over its free edges
  !> of 1 - excess/EDGE_EXTENSION). The normal penalty force is scaled by it, so that a node sliding off
  !> the master surface loses its contact force continuously. (Linear, not a smooth step: a
  !> slope that vanished at the end of the ramp would let the linear prediction of the
  !> opening event halve the remaining distance at every increment.)
  pure subroutine edge_support(xi, free, w, dw, n_nodes)
    real(dp), intent(in) :: xi(2)
    logical, intent(in) :: free(4)
    real(dp), intent(out) :: w, dw(2)
    integer, intent(in) :: n_nodes
    real(dp) :: wa(2), dwa(2), t, side
    integer :: alpha, edge
    if (is_triangle(n_nodes)) then
      call triangle_support(xi, free, w, dw)
      return
    end if
    wa = 1.0_dp
    dwa = 0.0_dp
    do alpha = 1, 2
      side = sign(1.0_dp, xi(alpha))
      if (alpha == 1) then
        edge = merge(2, 4, side > 0.0_dp)
      else
        edge = merge(3, 1, side > 0.0_dp)
      end if
      if (.not. free(edge) .or. abs(xi(alpha)) <= 1.0_dp) cycle
      t = (abs(xi(alpha)) - 1.0_dp) / EDGE_EXTENSION
      if (t >= 1.0_dp) then
        wa(alpha) = 0.0_dp
      else
        wa(alpha) = 1.0_dp - t
        dwa(alpha) = -side / EDGE_EXTENSION
      end if
    end do
    w = wa(1) * wa(2)
    dw = [dwa(1) * wa(2), wa(1) * dwa(2)]
  end subroutine edge_support

  !> The support of a triangular segment: the product over its free edges k of
  !> 1 - e_k/EDGE_EXTENSION (e_k the edge excess, clipped to [0, 1] of the ramp).
  pure subroutine triangle_support(xi, free, w, dw)
    real(dp), intent(in) :: xi(2)
    logical, intent(in) :: free(4)
    real(dp), intent(out) :: w, dw(2)
    real(dp), parameter :: GRADIENT(2, 3) = reshape([0.0_dp, -2.0_dp, 2.0_dp, 2.0_dp, -2.0_dp, 0.0_dp], [2, 3])
    real(dp) :: excess(4), factor(3), dfactor(2, 3)
    integer :: k
    excess = edge_excess(xi, 3)
    factor = 1.0_dp
    dfactor = 0.0_dp
    do k = 1, 3
      if (.not. free(k) .or. excess(k) <= 0.0_dp) cycle
      if (excess(k) >= EDGE_EXTENSION) then
        factor(k) = 0.0_dp
      else
        factor(k) = 1.0_dp - excess(k) / EDGE_EXTENSION
        dfactor(:, k) = -GRADIENT(:, k) / EDGE_EXTENSION
      end if
    end do
    w = product(factor)
    dw = dfactor(:, 1) * factor(2) * factor(3) + factor(1) * dfactor(:, 2) * factor(3) + &
         factor(1) * factor(2) * dfactor(:, 3)
  end subroutine triangle_support

  !> How far natural point xi lies past each edge of a segment of n_nodes nodes; negative
  !> inside. Quadrilaterals (k = 1..4: xi_2 = -1, xi_1 = 1, xi_2 = 1, xi_1 = -1): the distance
  !> in natural coordinates. Triangles (k = 1..3: t = 0, s + t = 1, s = 0; k = 4 is no edge,
  !> -huge): twice the distance as a fraction of the height over the edge, so that an excess
  !> means the same fraction of the face's span as on a quadrilateral (span 2).
  pure function edge_excess(xi, n_nodes) result(excess)
    real(dp), intent(in) :: xi(2)
    integer, intent(in) :: n_nodes
    real(dp) :: excess(4)
    if (is_triangle(n_nodes)) then
      excess = [-2.0_dp * xi(2), 2.0_dp * (xi(1) + xi(2) - 1.0_dp), -2.0_dp * xi(1), -huge(1.0_dp)]
    else
      excess = [-1.0_dp - xi(2), xi(1) - 1.0_dp, xi(2) - 1.0_dp, -1.0_dp - xi(1)]
    end if
  end function edge_excess

  !> Number of nodes of a face in a padded face-node column (the entries before the first 0).
  pure integer function face_node_count(column) result(n)
    integer, intent(in) :: column(:)
    n = size(column)
    do while (n > 0)
      if (column(n) /= 0) exit
      n = n - 1
    end do
  end function face_node_count

end module fcs_contact_search
