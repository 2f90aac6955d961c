!> Segment-to-segment (mortar) integration for a penalty tie between two non-matching surface
!> meshes. The tie energy is (k/2) int_{Gamma_s} |u_s(x) - u_m(P(x))|^2 dA over the slave
!> surface, P(x) the closest-point projection onto the master surface. For a slave face S and
!> a master face M it needs, over the overlap S cap P^-1(M),
!>   D_ab = int N^S_a N^S_b dA,   M_ab = int N^S_a N^M_b(P(x)) dA,   E_ab = int N^M_a N^M_b dA,
!> and the pair's tie stiffness is k [D, -M; -M^T, E] (x the 3 x 3 identity).
!> The overlap is integrated segment-wise (Puso & Laursen 2004, "A mortar segment-to-segment
!> contact method for large deformation solid mechanics", CMAME 193, 601-629, section 4;
!> Puso 2004, "A 3D mortar method for solid mechanics", IJNME 59, 315-336, section 3):
!>   1. both faces are projected along n_0 onto the slave face's mid-plane (through its centre
!>      x_s(0), normal n_0 = the slave normal at xi = 0); a bilinear face projects onto the
!>      bilinear map of its projected corners, so the projected faces are the polygons of
!>      their projected corners;
!>   2. the master polygon is clipped against the slave polygon (Sutherland & Hodgman 1974,
!>      "Reentrant polygon clipping", CACM 17(1), 32-42), both convex;
!>   3. the clip polygon is split into triangles (a fan from its vertex centroid), each
!>      integrated by default with the 7-point degree-5 rule (Dunavant 1985, "High degree
!>      efficient symmetrical Gaussian quadrature rules for the triangle", IJNME 21,
!>      1129-1148, table of degree 5; the rule is Radon's, with closed-form points from
!>      sqrt(15)), or with a conical product rule of a higher degree (options%degree);
!>   4. each plane point y is mapped to the slave natural coordinates by inverting the
!>      projected bilinear map (Newton), giving the slave surface point x_s above y, then to
!>      the master by project_to_segment (closest point); the weight is the rule's weight
!>      times the triangle's area times the plane-to-surface area factor
!>      |a_1 x a_2| / |(a_1 x a_2) . n_0| of the slave face at that point.
!> On flat parallel faces the master point is the point below y and the polygons are the
!> exact overlap; N^S N^M is then of degree 4 in the plane coordinates when both faces are
!> parallelograms, so D, M, E are exact to round-off. For general (non-parallelogram) quads
!> the inverse bilinear map is not polynomial and the integrals carry a quadrature error that
!> falls exponentially with the degree (unit test: 1.4e-6 relative at degree 5 on quads
!> distorted by a quarter cell, round-off at degree 24). The patch-test identity
!> sum_b D_ab u_s,b = sum_b M_ab u_m,b for linear u holds at every quadrature point (both
!> interpolations reproduce u), so it is exact whatever the shapes and the degree.
!> Faces: 4-node bilinear quads. The public interface takes the node count from the array
!> shape and the result is sized by MORTAR_FACE_NODES_MAX, so that other face kinds (3, 6,
!> 8 nodes) need only their shape functions (bilinear_shape, newton_plane), corner lists and a
!> closest-point projection here.
module fcs_tie_mortar
  use fcs_kinds, only: dp
  use fcs_contact_geometry, only: segment_point_t, segment_point, project_to_segment
  implicit none
  private
  public :: mortar_pair_t, mortar_options_t, mortar_tie_t
  public :: mortar_face_pair, mortar_pair_stiffness, mortar_status_name
  public :: MORTAR_FACE_NODES_MAX, MORTAR_DEFAULT_MIN_COSINE
  public :: MORTAR_FOUND, MORTAR_NO_OVERLAP, MORTAR_TOO_FAR, MORTAR_NOT_PARALLEL, &
            MORTAR_BAD_POLYGON, MORTAR_NOT_CONVERGED, MORTAR_UNSUPPORTED_FACE, MORTAR_BAD_OPTIONS
  public :: MORTAR_MAX_DEGREE
  public :: mortar_overlap_points, MORTAR_MAX_OVERLAP_POINTS

  !> Largest number of nodes of a face kind handled (4: bilinear quads).
  integer, parameter :: MORTAR_FACE_NODES_MAX = 4
  integer, parameter :: QUAD4_NODES = 4

  !> Outcome of one face pair.
  integer, parameter :: MORTAR_FOUND = 0
  !> The projected faces do not overlap, or touch along an edge or at a corner only.
  integer, parameter :: MORTAR_NO_OVERLAP = 1
  !> The master surface is farther from the slave than the caller's distance.
  integer, parameter :: MORTAR_TOO_FAR = 2
  !> The normals at the face centres are not opposed (or parallel) within the tolerance.
  integer, parameter :: MORTAR_NOT_PARALLEL = 3
  !> A projected face is non-convex or degenerate: refused.
  integer, parameter :: MORTAR_BAD_POLYGON = 4
  !> A Newton inverse map or the closest-point projection failed.
  integer, parameter :: MORTAR_NOT_CONVERGED = 5
  !> A face kind (node count) that this module does not handle.
  integer, parameter :: MORTAR_UNSUPPORTED_FACE = 6
  !> Options out of range (degree outside 5..MORTAR_MAX_DEGREE, min_cosine outside (0, 1]).
  integer, parameter :: MORTAR_BAD_OPTIONS = 7
  integer, parameter :: STATUS_LAST = 7

  !> Default smallest |n_s . n_m| accepted: the normals within 45 degrees of (anti)parallel.
  real(dp), parameter :: MORTAR_DEFAULT_MIN_COSINE = 0.70710678118654752_dp

  !> Vertices a clip polygon may hold (two convex quads intersect in at most 8).
  integer, parameter :: MAX_POLYGON = 16
  !> Sine of the smallest corner angle of a projected face accepted as convex.
  real(dp), parameter :: CONVEX_TOLERANCE = 1.0e-6_dp
  !> Distances to a clip line below this fraction of the slave size count as on the line.
  real(dp), parameter :: LINE_TOLERANCE = 1.0e-14_dp
  !> A clip polygon smaller than this fraction of the smaller face is no overlap (touching).
  real(dp), parameter :: AREA_TOLERANCE = 1.0e-13_dp
  integer, parameter :: NEWTON_MAX_ITERATIONS = 30
  !> A plane point inside a projected face maps to |xi_alpha| <= 1 + this.
  real(dp), parameter :: INSIDE_TOLERANCE = 1.0e-8_dp
  !> Natural coordinates of the 4 corners of a bilinear quad.
  real(dp), parameter :: XI_CORNER(2, QUAD4_NODES) = reshape([-1.0_dp, -1.0_dp, 1.0_dp, -1.0_dp, &
    1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp], [2, 4])

  !> Radon's 7-point rule, Dunavant (1985) degree 5: barycentric points and weights (sum 1).
  real(dp), parameter :: SQRT15 = sqrt(15.0_dp)
  real(dp), parameter :: RA = (6.0_dp - SQRT15) / 21.0_dp, RB = (6.0_dp + SQRT15) / 21.0_dp
  real(dp), parameter :: WA = (155.0_dp - SQRT15) / 1200.0_dp, WB = (155.0_dp + SQRT15) / 1200.0_dp
  integer, parameter :: RULE_POINTS = 7
  real(dp), parameter :: RULE_POINT(3, RULE_POINTS) = reshape([ &
    1.0_dp / 3, 1.0_dp / 3, 1.0_dp / 3, &
    RA, RA, 1.0_dp - 2 * RA, RA, 1.0_dp - 2 * RA, RA, 1.0_dp - 2 * RA, RA, RA, &
    RB, RB, 1.0_dp - 2 * RB, RB, 1.0_dp - 2 * RB, RB, 1.0_dp - 2 * RB, RB, RB], [3, RULE_POINTS])
  real(dp), parameter :: RULE_WEIGHT(RULE_POINTS) = [9.0_dp / 40, WA, WA, WA, WB, WB, WB]
  !> Highest polynomial degree offered: the conical product rule of 16 x 16 points.
  integer, parameter :: MAX_DIRECTION_POINTS = 16
  integer, parameter :: MORTAR_MAX_DEGREE = 2 * MAX_DIRECTION_POINTS - 2
  integer, parameter :: MAX_RULE_POINTS = MAX_DIRECTION_POINTS**2
  !> Strang & Fix's 3-point rule of degree 2 on a triangle (barycentric, weights 1/3 each).
  real(dp), parameter :: DEGREE2_POINT(3, 3) = reshape([ &
    2.0_dp / 3, 1.0_dp / 6, 1.0_dp / 6, 1.0_dp / 6, 2.0_dp / 3, 1.0_dp / 6, &
    1.0_dp / 6, 1.0_dp / 6, 2.0_dp / 3], [3, 3])
  !> Most points mortar_overlap_points returns: 7 per triangle of a fan of the clip polygon.
  integer, parameter :: MORTAR_MAX_OVERLAP_POINTS = RULE_POINTS * (MAX_POLYGON - 2)

  !> One face pair's coupling matrices (only the leading slave_nodes x master_nodes parts are
  !> used): d(a, b) = int N^S_a N^S_b, m(a, b) = int N^S_a N^M_b, e(a, b) = int N^M_a N^M_b
  !> over the overlap, in units of area; `area` = int 1 dA over the overlap (slave surface).
  type :: mortar_pair_t
    integer :: slave_face = 0
    integer :: master_face = 0
    integer :: slave_nodes = 0
    integer :: master_nodes = 0
    real(dp) :: d(MORTAR_FACE_NODES_MAX, MORTAR_FACE_NODES_MAX) = 0.0_dp
    real(dp) :: m(MORTAR_FACE_NODES_MAX, MORTAR_FACE_NODES_MAX) = 0.0_dp
    real(dp) :: e(MORTAR_FACE_NODES_MAX, MORTAR_FACE_NODES_MAX) = 0.0_dp
    real(dp) :: area = 0.0_dp
  end type mortar_pair_t

  !> Tolerances of the pair test besides the distance.
  type :: mortar_options_t
    !> Smallest accepted cosine of the angle between n_s and -n_m (opposed) or +-n_m (not
    !> opposed), the unit normals at the face centres; in (0, 1].
    real(dp) :: min_cosine = MORTAR_DEFAULT_MIN_COSINE
    !> .true.: the normals must be opposed (outward faces of two bodies); .false.: either
    !> opposed or pointing the same way.
    logical :: opposed = .true.
    !> Polynomial degree integrated exactly on each triangle of the overlap: 5 (the default)
    !> is exact on flat parallelogram faces; up to MORTAR_MAX_DEGREE, for general quads,
    !> whose integrands are not polynomial (the error then falls quickly with the degree).
    integer :: degree = 5
  end type mortar_options_t

  !> A quadrature rule on a triangle: barycentric points and weights (sum 1).
  type :: triangle_rule_t
    integer :: n = 0
    real(dp) :: point(3, MAX_RULE_POINTS) = 0.0_dp
    real(dp) :: weight(MAX_RULE_POINTS) = 0.0_dp
  end type triangle_rule_t

  !> The pairs of a whole tie, built from candidate lists (init), with the count of each
  !> outcome and the list of refused pairs (bad polygon, no convergence, unsupported face,
  !> bad options): the benign outcomes (no overlap, too far, not parallel) are only counted.
  type :: mortar_tie_t
    type(mortar_pair_t), allocatable :: pairs(:)
    integer :: n_pairs = 0
    integer :: status_count(0:STATUS_LAST) = 0
    !> refused(:, i) = [slave face, master face, status].
    integer, allocatable :: refused(:, :)
    integer :: n_refused = 0
  contains
    procedure :: init => tie_init
    procedure :: free => tie_free
  end type mortar_tie_t

  !> The slave face's mid-plane: origin, unit normal n_0 and in-plane axes (e_1 x e_2 = n_0).
  type :: mid_plane_t
    real(dp) :: origin(3) = 0.0_dp
    real(dp) :: normal(3) = 0.0_dp
    real(dp) :: axis(3, 2) = 0.0_dp
  end type mid_plane_t

  !> One face pair seen from the slave mid-plane: both faces' nodes, and the plane
  !> coordinates of their corners in node order (the projected faces' bilinear maps).
  type :: pair_geometry_t
    type(mid_plane_t) :: plane
    real(dp) :: xs(3, QUAD4_NODES) = 0.0_dp
    real(dp) :: xm(3, QUAD4_NODES) = 0.0_dp
    real(dp) :: slave_corners(2, QUAD4_NODES) = 0.0_dp
    real(dp) :: master_corners(2, QUAD4_NODES) = 0.0_dp
  end type pair_geometry_t

  !> The slave and master points of one plane point y (master: the closest point P(x_s)), and
  !> the master coordinates of the point below y along n_0.
  type :: point_pair_t
    type(segment_point_t) :: slave
    type(segment_point_t) :: master
    real(dp) :: master_below(2) = 0.0_dp
  end type point_pair_t

  !> A polygon in the plane coordinates, counter-clockwise about n_0.
  type :: polygon_t
    integer :: n = 0
    real(dp) :: y(2, MAX_POLYGON) = 0.0_dp
  end type polygon_t

contains

  !> Coupling matrices of slave face xs(3, nodes) and master face xm(3, nodes) (coordinates,
  !> nodes ordered so that a_1 x a_2 points out of each body). status = MORTAR_FOUND when
  !> they overlap and pair holds the matrices (slave_face, master_face left 0); otherwise the
  !> reason, and pair is zero. max_distance (length): pairs whose master surface is farther
  !> than it from the slave surface, at the centroid of the overlap, are skipped (status
  !> MORTAR_TOO_FAR). options: angle tolerance, orientation, quadrature degree.
  pure subroutine mortar_face_pair(xs, xm, max_distance, pair, status, options)
    real(dp), intent(in) :: xs(:, :), xm(:, :)
    real(dp), intent(in) :: max_distance
    type(mortar_pair_t), intent(out) :: pair
    integer, intent(out) :: status
    type(mortar_options_t), intent(in), optional :: options
    type(mortar_options_t) :: opts
    type(pair_geometry_t) :: geometry
    type(polygon_t) :: overlap
    type(point_pair_t) :: points
    if (present(options)) opts = options
    if (opts%degree < 5 .or. opts%degree > MORTAR_MAX_DEGREE .or. opts%min_cosine <= 0.0_dp &
        .or. opts%min_cosine > 1.0_dp) then
      status = MORTAR_BAD_OPTIONS
      return
    end if
    if (size(xs, 1) /= 3 .or. size(xm, 1) /= 3 .or. size(xs, 2) /= QUAD4_NODES &
        .or. size(xm, 2) /= QUAD4_NODES) then
      status = MORTAR_UNSUPPORTED_FACE
      return
    end if
    call face_overlap(xs, xm, max_distance, opts, geometry, overlap, points, status)
    if (status /= MORTAR_FOUND) return
    pair%slave_nodes = QUAD4_NODES
    pair%master_nodes = QUAD4_NODES
    call integrate_overlap(geometry, overlap, triangle_rule(opts%degree), points, pair, status)
    if (status /= MORTAR_FOUND) pair = mortar_pair_t()
  end subroutine mortar_face_pair

  !> The overlap of slave face xs(3, 4) and master face xm(3, 4), shared by the tie and the
  !> surface-to-surface points: the orientation check, both faces as convex polygons on the
  !> slave mid-plane, the master polygon clipped by the slave's, an overlap of at least
  !> AREA_TOLERANCE of the smaller face, and the distance check. status: MORTAR_FOUND or the
  !> reason there is no overlap to integrate.
  pure subroutine face_overlap(xs, xm, max_distance, opts, geometry, overlap, points, status)
    real(dp), intent(in) :: xs(:, :), xm(:, :), max_distance
    type(mortar_options_t), intent(in) :: opts
    type(pair_geometry_t), intent(out) :: geometry
    type(polygon_t), intent(out) :: overlap
    type(point_pair_t), intent(out) :: points
    integer, intent(out) :: status
    type(polygon_t) :: slave_polygon, master_polygon
    call orientation_check(xs, xm, opts, geometry, status)
    if (status /= MORTAR_FOUND) return
    slave_polygon = corner_polygon(geometry%slave_corners)
    master_polygon = corner_polygon(geometry%master_corners)
    if (.not. (is_convex(slave_polygon) .and. is_convex(master_polygon))) then
      status = MORTAR_BAD_POLYGON
      return
    end if
    call clip_polygon(master_polygon, slave_polygon, overlap, status)
    if (status /= MORTAR_FOUND) return
    if (overlap%n < 3 .or. polygon_area(overlap) <= AREA_TOLERANCE * &
        min(polygon_area(slave_polygon), polygon_area(master_polygon))) then
      status = MORTAR_NO_OVERLAP
      return
    end if
    call distance_check(geometry, overlap, max_distance, points, status)
  end subroutine face_overlap

  !> Integration points of the overlap of slave face xs(3, 4) and master face xm(3, 4) (as
  !> mortar_face_pair: projected onto the slave mid-plane, the master polygon clipped by the
  !> slave's), for surface-to-surface contact (doc/theory.md 4.10): the clip polygon is split
  !> into a fan of triangles from its first vertex, each integrated with the 3-point rule of
  !> degree 2 (Strang & Fix 1973), or with `quadratic` Radon's 7-point rule of degree 5 (for
  !> 8-node faces, given here by their corners: exact when their edges are straight, mid-side
  !> nodes at mid-edge), and each plane point mapped to the slave face. xi(:, i) are
  !> the slave natural coordinates of point i, weight(i) its area on the slave surface (rule
  !> weight x triangle area x area factor); n_points of them (at most
  !> MORTAR_MAX_OVERLAP_POINTS). status as mortar_face_pair; n_points = 0 unless FOUND.
  pure subroutine mortar_overlap_points(xs, xm, max_distance, quadratic, xi, weight, n_points, status)
    real(dp), intent(in) :: xs(:, :), xm(:, :), max_distance
    logical, intent(in) :: quadratic
    real(dp), intent(out) :: xi(:, :), weight(:)
    integer, intent(out) :: n_points, status
    type(mortar_options_t) :: opts
    type(pair_geometry_t) :: geometry
    type(polygon_t) :: overlap
    type(point_pair_t) :: points
    type(triangle_rule_t) :: rule
    real(dp) :: corner(2, 3), triangle_area
    logical :: converged
    integer :: i, q
    n_points = 0
    if (quadratic) then
      rule = triangle_rule(5)
    else
      rule%n = 3
      rule%point(:, 1:3) = DEGREE2_POINT
      rule%weight(1:3) = 1.0_dp / 3.0_dp
    end if
    if (size(xs, 2) /= QUAD4_NODES .or. size(xm, 2) /= QUAD4_NODES) then
      status = MORTAR_UNSUPPORTED_FACE
      return
    end if
    call face_overlap(xs, xm, max_distance, opts, geometry, overlap, points, status)
    if (status /= MORTAR_FOUND) return
    status = MORTAR_NOT_CONVERGED
    corner(:, 1) = overlap%y(:, 1)
    do i = 2, overlap%n - 1
      corner(:, 2) = overlap%y(:, i)
      corner(:, 3) = overlap%y(:, i + 1)
      triangle_area = 0.5_dp * cross2(corner(:, 2) - corner(:, 1), corner(:, 3) - corner(:, 1))
      do q = 1, rule%n
        call map_plane_point(geometry, matmul(corner, rule%point(:, q)), points, converged)
        if (.not. converged) then
          n_points = 0
          return
        end if
        n_points = n_points + 1
        xi(:, n_points) = points%slave%xi
        weight(n_points) = rule%weight(q) * triangle_area * area_factor(points%slave, geometry%plane)
      end do
    end do
    status = MORTAR_FOUND
  end subroutine mortar_overlap_points

  !> The pair's geometry (slave mid-plane, corners in it), and whether the normals at the
  !> face centres are parallel enough.
  pure subroutine orientation_check(xs, xm, opts, geometry, status)
    real(dp), intent(in) :: xs(3, QUAD4_NODES), xm(3, QUAD4_NODES)
    type(mortar_options_t), intent(in) :: opts
    type(pair_geometry_t), intent(out) :: geometry
    integer, intent(out) :: status
    type(segment_point_t) :: ps, pm
    real(dp) :: cosine
    integer :: i
    ps = segment_point(xs, [0.0_dp, 0.0_dp])
    pm = segment_point(xm, [0.0_dp, 0.0_dp])
    status = MORTAR_BAD_POLYGON
    if (ps%area_factor <= tiny(1.0_dp) .or. pm%area_factor <= tiny(1.0_dp)) return
    geometry%plane = mid_plane_t(ps%x, ps%normal, ps%e)
    geometry%xs = xs
    geometry%xm = xm
    do i = 1, QUAD4_NODES
      geometry%slave_corners(:, i) = plane_coordinates(geometry%plane, xs(:, i))
      geometry%master_corners(:, i) = plane_coordinates(geometry%plane, xm(:, i))
    end do
    cosine = dot_product(ps%normal, pm%normal)
    if (opts%opposed) then
      cosine = -cosine
    else
      cosine = abs(cosine)
    end if
    status = MORTAR_FOUND
    if (cosine < opts%min_cosine) status = MORTAR_NOT_PARALLEL
  end subroutine orientation_check

  !> Plane coordinates of a point: y_alpha = (x - origin) . e_alpha.
  pure function plane_coordinates(plane, x) result(y)
    type(mid_plane_t), intent(in) :: plane
    real(dp), intent(in) :: x(3)
    real(dp) :: y(2)
    y = matmul(x - plane%origin, plane%axis)
  end function plane_coordinates

  !> The polygon of a face's projected corners, made counter-clockwise.
  pure function corner_polygon(corners) result(polygon)
    real(dp), intent(in) :: corners(:, :)
    type(polygon_t) :: polygon
    polygon%n = size(corners, 2)
    polygon%y(:, 1:polygon%n) = corners
    if (signed_area(polygon) < 0.0_dp) polygon%y(:, 1:polygon%n) = polygon%y(:, polygon%n:1:-1)
  end function corner_polygon

  !> Shoelace area, positive for a counter-clockwise polygon.
  pure function signed_area(polygon) result(area)
    type(polygon_t), intent(in) :: polygon
    real(dp) :: area
    integer :: i, j
    area = 0.0_dp
    do i = 1, polygon%n
      j = modulo(i, polygon%n) + 1
      area = area + cross2(polygon%y(:, i), polygon%y(:, j))
    end do
    area = 0.5_dp * area
  end function signed_area

  pure function polygon_area(polygon) result(area)
    type(polygon_t), intent(in) :: polygon
    real(dp) :: area
    area = abs(signed_area(polygon))
  end function polygon_area

  pure function cross2(a, b) result(c)
    real(dp), intent(in) :: a(2), b(2)
    real(dp) :: c
    c = a(1) * b(2) - a(2) * b(1)
  end function cross2

  !> Strictly convex and counter-clockwise: every corner turns left by an angle whose sine
  !> exceeds CONVEX_TOLERANCE (zero-length edges and collinear corners are refused).
  pure function is_convex(polygon) result(convex)
    type(polygon_t), intent(in) :: polygon
    logical :: convex
    real(dp) :: edge_in(2), edge_out(2)
    integer :: i
    convex = .false.
    do i = 1, polygon%n
      edge_in = polygon%y(:, i) - polygon%y(:, modulo(i - 2, polygon%n) + 1)
      edge_out = polygon%y(:, modulo(i, polygon%n) + 1) - polygon%y(:, i)
      if (cross2(edge_in, edge_out) <= CONVEX_TOLERANCE * norm2(edge_in) * norm2(edge_out)) return
    end do
    convex = .true.
  end function is_convex

  !> Sutherland-Hodgman: the part of the convex polygon `subject` inside the convex polygon
  !> `clip` (both counter-clockwise), clipped by one edge line of `clip` after the other.
  pure subroutine clip_polygon(subject, clip, overlap, status)
    type(polygon_t), intent(in) :: subject, clip
    type(polygon_t), intent(out) :: overlap
    integer, intent(out) :: status
    type(polygon_t) :: current
    real(dp) :: tolerance
    integer :: i
    tolerance = LINE_TOLERANCE * sqrt(polygon_area(clip))
    overlap = subject
    status = MORTAR_FOUND
    do i = 1, clip%n
      current = overlap
      call clip_half_plane(current, clip%y(:, i), clip%y(:, modulo(i, clip%n) + 1), tolerance, &
                           overlap, status)
      if (status /= MORTAR_FOUND .or. overlap%n == 0) return
    end do
    call remove_duplicates(overlap, 10 * tolerance)
  end subroutine clip_polygon

  !> One Sutherland-Hodgman pass: keep the part of `polygon` left of the line p -> q. Points
  !> within `tolerance` of the line count as on it (kept, never split).
  pure subroutine clip_half_plane(polygon, p, q, tolerance, result, status)
    type(polygon_t), intent(in) :: polygon
    real(dp), intent(in) :: p(2), q(2), tolerance
    type(polygon_t), intent(out) :: result
    integer, intent(inout) :: status
    real(dp) :: distance(MAX_POLYGON), direction(2)
    integer :: i, j
    direction = (q - p) / norm2(q - p)
    do i = 1, polygon%n
      distance(i) = cross2(direction, polygon%y(:, i) - p)
      if (abs(distance(i)) <= tolerance) distance(i) = 0.0_dp
    end do
    result%n = 0
    do i = 1, polygon%n
      j = modulo(i, polygon%n) + 1
      if (distance(i) * distance(j) < 0.0_dp) then
        call add_vertex(result, polygon%y(:, i) + distance(i) / (distance(i) - distance(j)) &
                        * (polygon%y(:, j) - polygon%y(:, i)), status)
      end if
      if (distance(j) >= 0.0_dp) call add_vertex(result, polygon%y(:, j), status)
    end do
  end subroutine clip_half_plane

  pure subroutine add_vertex(polygon, y, status)
    type(polygon_t), intent(inout) :: polygon
    real(dp), intent(in) :: y(2)
    integer, intent(inout) :: status
    if (polygon%n == MAX_POLYGON) then
      status = MORTAR_BAD_POLYGON
      return
    end if
    polygon%n = polygon%n + 1
    polygon%y(:, polygon%n) = y
  end subroutine add_vertex

  !> Drop vertices closer than `tolerance` to the previous kept one (and the last to the first).
  pure subroutine remove_duplicates(polygon, tolerance)
    type(polygon_t), intent(inout) :: polygon
    real(dp), intent(in) :: tolerance
    integer :: i, n
    n = min(polygon%n, 1)
    do i = 2, polygon%n
      if (norm2(polygon%y(:, i) - polygon%y(:, n)) > tolerance) then
        n = n + 1
        polygon%y(:, n) = polygon%y(:, i)
      end if
    end do
    if (n > 1) then
      if (norm2(polygon%y(:, n) - polygon%y(:, 1)) <= tolerance) n = n - 1
    end if
    polygon%n = n
  end subroutine remove_duplicates

  !> Vertex centroid (inside a convex polygon).
  pure function vertex_centroid(polygon) result(c)
    type(polygon_t), intent(in) :: polygon
    real(dp) :: c(2)
    c = sum(polygon%y(:, 1:polygon%n), dim=2) / polygon%n
  end function vertex_centroid

  !> Bilinear shape functions N_a(xi) and their derivatives dN_a/dxi_alpha as dshape(alpha, a).
  pure subroutine bilinear_shape(xi, shape, dshape)
    real(dp), intent(in) :: xi(2)
    real(dp), intent(out) :: shape(QUAD4_NODES), dshape(2, QUAD4_NODES)
    shape = 0.25_dp * (1.0_dp + XI_CORNER(1, :) * xi(1)) * (1.0_dp + XI_CORNER(2, :) * xi(2))
    dshape(1, :) = 0.25_dp * XI_CORNER(1, :) * (1.0_dp + XI_CORNER(2, :) * xi(2))
    dshape(2, :) = 0.25_dp * XI_CORNER(2, :) * (1.0_dp + XI_CORNER(1, :) * xi(1))
  end subroutine bilinear_shape

  !> Natural coordinates of plane point y in the projected face with plane corners
  !> `corners`: Newton on y(xi) = sum_a N_a(xi) y_a from xi_start. A face projects onto
  !> the bilinear map of its projected corners, so xi is that of the face point above y.
  pure subroutine newton_plane(corners, y, xi_start, xi, converged)
    real(dp), intent(in) :: corners(2, QUAD4_NODES), y(2), xi_start(2)
    real(dp), intent(out) :: xi(2)
    logical, intent(out) :: converged
    real(dp) :: shape(QUAD4_NODES), dshape(2, QUAD4_NODES), residual(2), jac(2, 2), step(2), det
    integer :: iteration
    converged = .false.
    xi = xi_start
    do iteration = 1, NEWTON_MAX_ITERATIONS
      call bilinear_shape(xi, shape, dshape)
      residual = matmul(corners, shape) - y
      jac = matmul(corners, transpose(dshape))
      det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
      if (abs(det) <= tiny(1.0_dp)) return
      step = -[jac(2, 2) * residual(1) - jac(1, 2) * residual(2), &
               jac(1, 1) * residual(2) - jac(2, 1) * residual(1)] / det
      if (any(abs(xi + step) > 1.0e3_dp)) return
      xi = xi + step
      if (maxval(abs(step)) <= 1.0e-13_dp * max(1.0_dp, maxval(abs(xi)))) then
        converged = .true.
        return
      end if
    end do
  end subroutine newton_plane

  !> newton_plane for y inside the projected face: from xi_start, and again from the centre if
  !> that fails or lands outside the face (the bilinear map has a second root, outside a
  !> convex face). converged: found within the face (|xi_alpha| <= 1 + INSIDE_TOLERANCE).
  pure subroutine plane_inverse(corners, y, xi_start, xi, converged)
    real(dp), intent(in) :: corners(2, QUAD4_NODES), y(2), xi_start(2)
    real(dp), intent(out) :: xi(2)
    logical, intent(out) :: converged
    call newton_plane(corners, y, xi_start, xi, converged)
    if (converged) converged = maxval(abs(xi)) <= 1.0_dp + INSIDE_TOLERANCE
    if (converged) return
    call newton_plane(corners, y, [0.0_dp, 0.0_dp], xi, converged)
    if (converged) converged = maxval(abs(xi)) <= 1.0_dp + INSIDE_TOLERANCE
  end subroutine plane_inverse

  !> The points of plane point y: the slave point above it, the master point below it along
  !> n_0, and from there the closest-point projection P(x_s) onto the master. `points` holds
  !> the previous plane point's results on entry (the starts of the Newton iterations).
  pure subroutine map_plane_point(geometry, y, points, converged)
    type(pair_geometry_t), intent(in) :: geometry
    real(dp), intent(in) :: y(2)
    type(point_pair_t), intent(inout) :: points
    logical, intent(out) :: converged
    type(segment_point_t) :: slave, master
    real(dp) :: xi_slave(2), xi_below(2), gap
    call plane_inverse(geometry%slave_corners, y, points%slave%xi, xi_slave, converged)
    if (.not. converged) return
    call plane_inverse(geometry%master_corners, y, points%master_below, xi_below, converged)
    if (.not. converged) return
    slave = segment_point(geometry%xs, xi_slave)
    call project_to_segment(geometry%xm, slave%x, xi_below, master, gap, converged)
    if (.not. converged) return
    points = point_pair_t(slave, master, xi_below)
  end subroutine map_plane_point

  !> Area factor dA_surface / dA_plane = |a_1 x a_2| / |(a_1 x a_2) . n_0| at slave point p.
  pure function area_factor(p, plane) result(factor)
    type(segment_point_t), intent(in) :: p
    type(mid_plane_t), intent(in) :: plane
    real(dp) :: factor
    factor = 1.0_dp / abs(dot_product(p%normal, plane%normal))
  end function area_factor

  !> Distance between the slave surface and its closest point on the master at the overlap's
  !> centroid; MORTAR_TOO_FAR beyond max_distance. points: the points found there.
  pure subroutine distance_check(geometry, overlap, max_distance, points, status)
    type(pair_geometry_t), intent(in) :: geometry
    real(dp), intent(in) :: max_distance
    type(polygon_t), intent(in) :: overlap
    type(point_pair_t), intent(out) :: points
    integer, intent(out) :: status
    logical :: converged
    call map_plane_point(geometry, vertex_centroid(overlap), points, converged)
    status = MORTAR_NOT_CONVERGED
    if (.not. converged) return
    status = MORTAR_FOUND
    if (norm2(points%slave%x - points%master%x) > max_distance) status = MORTAR_TOO_FAR
  end subroutine distance_check

  !> Integrate D, M, E and the area over the clip polygon: a fan of triangles from the vertex
  !> centroid, `rule` on each (see the module comment). D and E are made exactly symmetric.
  !> points: those of the centroid, where the searches start.
  pure subroutine integrate_overlap(geometry, overlap, rule, points, pair, status)
    type(pair_geometry_t), intent(in) :: geometry
    type(polygon_t), intent(in) :: overlap
    type(triangle_rule_t), intent(in) :: rule
    type(point_pair_t), intent(inout) :: points
    type(mortar_pair_t), intent(inout) :: pair
    integer, intent(out) :: status
    real(dp) :: corner(2, 3), triangle_area, weight
    logical :: converged
    integer :: i, q
    status = MORTAR_NOT_CONVERGED
    corner(:, 1) = vertex_centroid(overlap)
    do i = 1, overlap%n
      corner(:, 2) = overlap%y(:, i)
      corner(:, 3) = overlap%y(:, modulo(i, overlap%n) + 1)
      triangle_area = 0.5_dp * cross2(corner(:, 2) - corner(:, 1), corner(:, 3) - corner(:, 1))
      do q = 1, rule%n
        call map_plane_point(geometry, matmul(corner, rule%point(:, q)), points, converged)
        if (.not. converged) return
        weight = rule%weight(q) * triangle_area * area_factor(points%slave, geometry%plane)
        call add_point(pair, weight, points%slave%shape, points%master%shape)
      end do
    end do
    pair%d = 0.5_dp * (pair%d + transpose(pair%d))
    pair%e = 0.5_dp * (pair%e + transpose(pair%e))
    status = MORTAR_FOUND
  end subroutine integrate_overlap

  !> The triangle rule exact to polynomial degree `degree` (5 <= degree <= MORTAR_MAX_DEGREE):
  !> degree 5, Radon's 7 points (Dunavant 1985); above, the conical product rule (Stroud 1971,
  !> "Approximate calculation of multiple integrals", section 2.7): Gauss-Legendre in u and v
  !> on the square, mapped by (u, v) -> (l_2, l_3) = (u, v (1 - u)) with the weight factor
  !> (1 - u); n points per direction integrate degree 2n - 2 exactly.
  pure function triangle_rule(degree) result(rule)
    integer, intent(in) :: degree
    type(triangle_rule_t) :: rule
    real(dp) :: u(MAX_DIRECTION_POINTS), wu(MAX_DIRECTION_POINTS)
    integer :: n, i, j
    if (degree <= 5) then
      rule%n = RULE_POINTS
      rule%point(:, 1:RULE_POINTS) = RULE_POINT
      rule%weight(1:RULE_POINTS) = RULE_WEIGHT
      return
    end if
    n = (degree + 3) / 2
    call gauss_legendre(n, u, wu)
    rule%n = n * n
    do j = 1, n
      do i = 1, n
        rule%point(2:3, i + n * (j - 1)) = [u(i), u(j) * (1.0_dp - u(i))]
        rule%point(1, i + n * (j - 1)) = 1.0_dp - u(i) - u(j) * (1.0_dp - u(i))
        rule%weight(i + n * (j - 1)) = 2.0_dp * wu(i) * wu(j) * (1.0_dp - u(i))
      end do
    end do
  end function triangle_rule

  !> n-point Gauss-Legendre rule on [0, 1]: the roots t of the Legendre polynomial P_n by
  !> Newton from cos(pi (i - 1/4) / (n + 1/2)), weights 2 / ((1 - t^2) P_n'(t)^2)
  !> (Abramowitz & Stegun 25.4.29), mapped to [0, 1].
  pure subroutine gauss_legendre(n, x, w)
    integer, intent(in) :: n
    real(dp), intent(out) :: x(:), w(:)
    real(dp), parameter :: PI = 3.14159265358979323846_dp
    real(dp) :: t, p, derivative, step
    integer :: i, iteration
    do i = 1, n
      t = cos(PI * (i - 0.25_dp) / (n + 0.5_dp))
      do iteration = 1, 100
        call legendre(n, t, p, derivative)
        step = p / derivative
        t = t - step
        if (abs(step) <= 1.0e-15_dp) exit
      end do
      call legendre(n, t, p, derivative)
      x(i) = 0.5_dp * (1.0_dp - t)
      w(i) = 1.0_dp / ((1.0_dp - t * t) * derivative**2)
    end do
  end subroutine gauss_legendre

  !> P_n(t) by Bonnet's recurrence (k + 1) P_{k+1} = (2k + 1) t P_k - k P_{k-1}, and
  !> P_n'(t) = n (t P_n - P_{n-1}) / (t^2 - 1), for |t| < 1.
  pure subroutine legendre(n, t, p, derivative)
    integer, intent(in) :: n
    real(dp), intent(in) :: t
    real(dp), intent(out) :: p, derivative
    real(dp) :: p_previous, p_next
    integer :: k
    p_previous = 1.0_dp
    p = t
    do k = 1, n - 1
      p_next = ((2 * k + 1) * t * p - k * p_previous) / (k + 1)
      p_previous = p
      p = p_next
    end do
    derivative = n * (t * p - p_previous) / (t * t - 1.0_dp)
  end subroutine legendre

  !> Add one quadrature point of weight w (area) with slave and master shape values.
  pure subroutine add_point(pair, w, shape_s, shape_m)
    type(mortar_pair_t), intent(inout) :: pair
    real(dp), intent(in) :: w, shape_s(:), shape_m(:)
    integer :: b, ns, nm
    ns = pair%slave_nodes
    nm = pair%master_nodes
    do b = 1, ns
      pair%d(1:ns, b) = pair%d(1:ns, b) + w * shape_s(1:ns) * shape_s(b)
    end do
    do b = 1, nm
      pair%m(1:ns, b) = pair%m(1:ns, b) + w * shape_s(1:ns) * shape_m(b)
      pair%e(1:nm, b) = pair%e(1:nm, b) + w * shape_m(1:nm) * shape_m(b)
    end do
    pair%area = pair%area + w
  end subroutine add_point

  !> The pair's tie stiffness penalty * [D, -M; -M^T, E] x I_3 (penalty: force per length^3),
  !> on the degrees of freedom ordered node by node (x, y, z), slave nodes then master nodes.
  pure function mortar_pair_stiffness(pair, penalty) result(k)
    type(mortar_pair_t), intent(in) :: pair
    real(dp), intent(in) :: penalty
    real(dp) :: k(3 * (pair%slave_nodes + pair%master_nodes), &
                  3 * (pair%slave_nodes + pair%master_nodes))
    real(dp) :: scalar(pair%slave_nodes + pair%master_nodes, pair%slave_nodes + pair%master_nodes)
    integer :: ns, nm, a, b, i
    ns = pair%slave_nodes
    nm = pair%master_nodes
    scalar(1:ns, 1:ns) = pair%d(1:ns, 1:ns)
    scalar(1:ns, ns + 1:) = -pair%m(1:ns, 1:nm)
    scalar(ns + 1:, 1:ns) = -transpose(pair%m(1:ns, 1:nm))
    scalar(ns + 1:, ns + 1:) = pair%e(1:nm, 1:nm)
    k = 0.0_dp
    do b = 1, ns + nm
      do a = 1, ns + nm
        do i = 1, 3
          k(3 * (a - 1) + i, 3 * (b - 1) + i) = penalty * scalar(a, b)
        end do
      end do
    end do
  end function mortar_pair_stiffness

  !> Text for a status, for messages.
  pure function mortar_status_name(status) result(name)
    integer, intent(in) :: status
    character(len=:), allocatable :: name
    select case (status)
    case (MORTAR_FOUND)
      name = 'overlap found'
    case (MORTAR_NO_OVERLAP)
      name = 'no overlap'
    case (MORTAR_TOO_FAR)
      name = 'master surface beyond the distance tolerance'
    case (MORTAR_NOT_PARALLEL)
      name = 'normals not opposed within the angle tolerance'
    case (MORTAR_BAD_POLYGON)
      name = 'non-convex or degenerate projected face'
    case (MORTAR_NOT_CONVERGED)
      name = 'inverse map or closest-point projection did not converge'
    case (MORTAR_UNSUPPORTED_FACE)
      name = 'unsupported face kind (node count)'
    case (MORTAR_BAD_OPTIONS)
      name = 'options out of range (degree or min_cosine)'
    case default
      name = 'unknown status'
    end select
  end function mortar_status_name

  !> All pairs of a tie: slave face s (node coordinates slave_x(:, :, s), of shape (3, nodes
  !> per face, slave faces)) against the master faces candidates(candidate_start(s) :
  !> candidate_start(s + 1) - 1) (indices into master_x(3, nodes per face, master faces)),
  !> e.g. from a bucket grid; candidate_start has one entry per slave face plus one. The
  !> pairs found are kept in slave, candidate order, with their face indices set.
  pure subroutine tie_init(this, slave_x, master_x, candidate_start, candidates, max_distance, &
                           options)
    class(mortar_tie_t), intent(inout) :: this
    real(dp), intent(in) :: slave_x(:, :, :), master_x(:, :, :), max_distance
    integer, intent(in) :: candidate_start(:), candidates(:)
    type(mortar_options_t), intent(in), optional :: options
    type(mortar_pair_t) :: pair
    integer :: s, i, status
    call this%free()
    allocate (this%pairs(max(16, size(slave_x, 3))), this%refused(3, 16))
    do s = 1, size(slave_x, 3)
      do i = candidate_start(s), candidate_start(s + 1) - 1
        call mortar_face_pair(slave_x(:, :, s), master_x(:, :, candidates(i)), max_distance, &
                              pair, status, options)
        this%status_count(status) = this%status_count(status) + 1
        if (status == MORTAR_FOUND) then
          pair%slave_face = s
          pair%master_face = candidates(i)
          call append_pair(this, pair)
        else if (status >= MORTAR_BAD_POLYGON) then
          call append_refusal(this, [s, candidates(i), status])
        end if
      end do
    end do
  end subroutine tie_init

  !> Release the pairs and refusals; zero the counts.
  pure subroutine tie_free(this)
    class(mortar_tie_t), intent(inout) :: this
    if (allocated(this%pairs)) deallocate (this%pairs)
    if (allocated(this%refused)) deallocate (this%refused)
    this%n_pairs = 0
    this%n_refused = 0
    this%status_count = 0
  end subroutine tie_free

  pure subroutine append_pair(tie, pair)
    class(mortar_tie_t), intent(inout) :: tie
    type(mortar_pair_t), intent(in) :: pair
    type(mortar_pair_t), allocatable :: grown(:)
    if (tie%n_pairs == size(tie%pairs)) then
      allocate (grown(2 * size(tie%pairs)))
      grown(1:tie%n_pairs) = tie%pairs(1:tie%n_pairs)
      call move_alloc(grown, tie%pairs)
    end if
    tie%n_pairs = tie%n_pairs + 1
    tie%pairs(tie%n_pairs) = pair
  end subroutine append_pair

  pure subroutine append_refusal(tie, refusal)
    class(mortar_tie_t), intent(inout) :: tie
    integer, intent(in) :: refusal(3)
    integer, allocatable :: grown(:, :)
    if (tie%n_refused == size(tie%refused, 2)) then
      allocate (grown(3, 2 * size(tie%refused, 2)))
      grown(:, 1:tie%n_refused) = tie%refused(:, 1:tie%n_refused)
      call move_alloc(grown, tie%refused)
    end if
    tie%n_refused = tie%n_refused + 1
    tie%refused(:, tie%n_refused) = refusal
  end subroutine append_refusal

end module fcs_tie_mortar
