!> Geometry of a slave node against a master segment of gamma = 3, 4, 6 or 8 nodes (a TRI3,
!> QUAD4, TRI6 or QUAD8 element face, fcs_face_kind; Xing & Makinouchi 2002, method notes 1.1;
!> Xing, Mora & Makinouchi 2003, "gamma = 4 if without special notation"): the segment's own
!> shape functions N_I(xi), natural base vectors a_alpha = dx/dxi_alpha, metric
!> m_ab = a_a.a_b, unit normal n = a_1 x a_2 / |a_1 x a_2| (outward from the master body when
!> the face nodes are ordered outward), the second derivatives x_,ab (a bilinear segment has
!> only the twist x_,12; quadratic ones also x_,11 and x_,22), the local Cartesian frame
!> e_1 = a_1/|a_1|, e_2 = n x e_1 in which the friction force components are kept (the
!> paper's e_i), and the closest-point projection of a slave node (Newton in natural
!> coordinates). Natural domains: [-1, 1]^2 for quadrilaterals, s, t >= 0, s + t <= 1 for
!> triangles. The 4-node segment keeps its own bilinear formulas (bit for bit those of the
!> runs before the other kinds came).
module fcs_contact_geometry
  use fcs_kinds, only: dp
  use fcs_face_kind, only: face_shape_functions
  implicit none
  private
  public :: segment_point_t, segment_point, project_to_segment, cross3, calculix_tangents
  public :: PROJECTION_MAX_ITERATIONS, MAX_SEGMENT_NODES, segment_centre, segment_clamp
  public :: is_triangle

  !> Newton iterations allowed for the closest-point projection.
  integer, parameter :: PROJECTION_MAX_ITERATIONS = 30
  !> Most nodes of a master segment (the 8-node quadrilateral).
  integer, parameter :: MAX_SEGMENT_NODES = 8
  real(dp), parameter :: XI_NODE(2, 4) = reshape([-1.0_dp, -1.0_dp, 1.0_dp, -1.0_dp, &
                                                   1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp], [2, 4])

  !> 1 - |n_x| below which CalculiX takes the normal as parallel to the x axis (0.1 degree).
  real(dp), parameter :: CALCULIX_X_PARALLEL = 1.5231e-6_dp

  !> Everything about one point xi of a master segment.
  type :: segment_point_t
    real(dp) :: xi(2) = 0.0_dp
    !> Nodes of the segment (3, 4, 6 or 8); shape(1:n_nodes) are its shape functions.
    integer :: n_nodes = 4
    real(dp) :: shape(MAX_SEGMENT_NODES) = 0.0_dp
    !> dN_I/dxi_alpha as dshape(alpha, I).
    real(dp) :: dshape(2, MAX_SEGMENT_NODES) = 0.0_dp
    real(dp) :: x(3) = 0.0_dp
    !> a(:, alpha): natural base vectors; dual(:, alpha): contravariant a^alpha.
    real(dp) :: a(3, 2) = 0.0_dp
    real(dp) :: dual(3, 2) = 0.0_dp
    real(dp) :: metric(2, 2) = 0.0_dp
    real(dp) :: normal(3) = 0.0_dp
    !> x_,12 (twist) and second(:, alpha) = x_,alpha alpha (zero on a bilinear segment).
    real(dp) :: twist(3) = 0.0_dp
    real(dp) :: second(3, 2) = 0.0_dp
    !> Local Cartesian frame: e(:,1) = a_1/|a_1|, e(:,2) = n x e_1.
    real(dp) :: e(3, 2) = 0.0_dp
    real(dp) :: area_factor = 0.0_dp
  end type segment_point_t

contains

  !> Geometry of the segment with nodes xm(3, gamma) (gamma = 3, 4, 6, 8) at natural point xi.
  pure function segment_point(xm, xi) result(p)
    real(dp), intent(in) :: xm(:, :), xi(2)
    type(segment_point_t) :: p
    real(dp) :: c(3), det, inverse(2, 2), ddshape(3, MAX_SEGMENT_NODES)
    integer :: alpha, n
    n = size(xm, 2)
    p%xi = xi
    p%n_nodes = n
    if (n == 4) then
      p%shape(1:4) = 0.25_dp * (1.0_dp + XI_NODE(1, :) * xi(1)) * (1.0_dp + XI_NODE(2, :) * xi(2))
      p%dshape(1, 1:4) = 0.25_dp * XI_NODE(1, :) * (1.0_dp + XI_NODE(2, :) * xi(2))
      p%dshape(2, 1:4) = 0.25_dp * XI_NODE(2, :) * (1.0_dp + XI_NODE(1, :) * xi(1))
      p%x = matmul(xm, p%shape(1:4))
      do alpha = 1, 2
        p%a(:, alpha) = matmul(xm, p%dshape(alpha, 1:4))
      end do
      p%twist = 0.25_dp * matmul(xm, XI_NODE(1, :) * XI_NODE(2, :))
    else
      call face_shape_functions(n, xi, p%shape, p%dshape, ddshape)
      p%x = matmul(xm, p%shape(1:n))
      do alpha = 1, 2
        p%a(:, alpha) = matmul(xm, p%dshape(alpha, 1:n))
        p%second(:, alpha) = matmul(xm, ddshape(alpha, 1:n))
      end do
      p%twist = matmul(xm, ddshape(3, 1:n))
    end if
    c = cross3(p%a(:, 1), p%a(:, 2))
    p%area_factor = norm2(c)
    if (p%area_factor <= tiny(1.0_dp)) return
    p%normal = c / p%area_factor
    p%metric = matmul(transpose(p%a), p%a)
    det = p%metric(1, 1) * p%metric(2, 2) - p%metric(1, 2) * p%metric(2, 1)
    inverse = reshape([p%metric(2, 2), -p%metric(2, 1), -p%metric(1, 2), p%metric(1, 1)], [2, 2]) / det
    p%dual = matmul(p%a, inverse)
    p%e(:, 1) = p%a(:, 1) / norm2(p%a(:, 1))
    p%e(:, 2) = cross3(p%normal, p%e(:, 1))
  end function segment_point

  !> True for the triangular segments (3 or 6 nodes).
  pure logical function is_triangle(n_nodes)
    integer, intent(in) :: n_nodes
    is_triangle = n_nodes == 3 .or. n_nodes == 6
  end function is_triangle

  !> The centre of the natural domain of a segment of n_nodes nodes: where projections start.
  pure function segment_centre(n_nodes) result(xi)
    integer, intent(in) :: n_nodes
    real(dp) :: xi(2)
    xi = 0.0_dp
    if (is_triangle(n_nodes)) xi = 1.0_dp / 3.0_dp
  end function segment_centre

  !> The point of the natural domain of the segment nearest (in natural coordinates) to xi:
  !> xi clamped to [-1, 1] for quadrilaterals; for triangles s, t >= 0, then onto the edge
  !> s + t = 1 if past it.
  pure function segment_clamp(xi, n_nodes) result(c)
    real(dp), intent(in) :: xi(2)
    integer, intent(in) :: n_nodes
    real(dp) :: c(2)
    if (.not. is_triangle(n_nodes)) then
      c = max(-1.0_dp, min(1.0_dp, xi))
      return
    end if
    c = xi
    if (c(1) + c(2) > 1.0_dp) then
      c(1) = 0.5_dp * (1.0_dp + c(1) - c(2))
      c(1) = max(0.0_dp, min(1.0_dp, c(1)))
      c(2) = 1.0_dp - c(1)
    end if
    c = max(0.0_dp, c)
  end function segment_clamp

  !> Closest-point projection of x_slave onto the (unbounded) surface of the segment: solve
  !> (x_s - x(xi)).a_alpha(xi) = 0 by Newton with the matrix A_ab = m_ab - g h_ab,
  !> h_ab = n.x_,ab (on a bilinear segment h_11 = h_22 = 0), starting from xi_start.
  !> `converged` is false when Newton fails (degenerate segment or far-away point).
  pure subroutine project_to_segment(xm, x_slave, xi_start, p, gap, converged)
    real(dp), intent(in) :: xm(:, :), x_slave(3), xi_start(2)
    type(segment_point_t), intent(out) :: p
    real(dp), intent(out) :: gap
    logical, intent(out) :: converged
    real(dp) :: d(3), residual(2), jac(2, 2), step(2), det, scale
    integer :: iteration
    p = segment_point(xm, xi_start)
    converged = .false.
    gap = 0.0_dp
    scale = segment_scale(xm)
    do iteration = 1, PROJECTION_MAX_ITERATIONS
      if (p%area_factor <= tiny(1.0_dp)) return
      d = x_slave - p%x
      residual = matmul(d, p%a)
      gap = dot_product(d, p%normal)
      jac = p%metric
      jac(1, 2) = jac(1, 2) - dot_product(d, p%twist)
      jac(2, 1) = jac(1, 2)
      if (p%n_nodes /= 4) then
        jac(1, 1) = jac(1, 1) - dot_product(d, p%second(:, 1))
        jac(2, 2) = jac(2, 2) - dot_product(d, p%second(:, 2))
      end if
      det = jac(1, 1) * jac(2, 2) - jac(1, 2) * jac(2, 1)
      if (abs(det) <= tiny(1.0_dp)) return
      step = [jac(2, 2) * residual(1) - jac(1, 2) * residual(2), &
              jac(1, 1) * residual(2) - jac(2, 1) * residual(1)] / det
      if (any(abs(p%xi + step) > 1.0e3_dp)) return
      p = segment_point(xm, p%xi + step)
      if (maxval(abs(step)) <= 1.0e-13_dp * max(1.0_dp, maxval(abs(p%xi)))) then
        converged = .true.
        exit
      end if
    end do
    d = x_slave - p%x
    gap = dot_product(d, p%normal)
    if (.not. converged) converged = norm2(matmul(d, p%dual)) <= 1.0e-10_dp * max(scale, 1.0_dp)
  end subroutine project_to_segment

  !> Size of a segment for the projection's tolerance: the longer diagonal of a
  !> quadrilateral, the longest edge of a triangle (corner nodes).
  pure real(dp) function segment_scale(xm) result(scale)
    real(dp), intent(in) :: xm(:, :)
    if (is_triangle(size(xm, 2))) then
      scale = max(norm2(xm(:, 2) - xm(:, 1)), norm2(xm(:, 3) - xm(:, 2)), norm2(xm(:, 1) - xm(:, 3)))
    else
      scale = max(norm2(xm(:, 3) - xm(:, 1)), norm2(xm(:, 4) - xm(:, 2)))
    end if
  end function segment_scale

  pure function cross3(a, b) result(c)
    real(dp), intent(in) :: a(3), b(3)
    real(dp) :: c(3)
    c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
  end function cross3

  !> The tangent frame in which CalculiX reports node-to-face contact (*CONTACT PRINT, CDIS and
  !> CSTR): t_1 the global x axis projected on the plane normal to n and normalised (the z
  !> axis when n is within 0.1 degree of the x axis), t_2 = n x t_1. A global frame, unlike
  !> the face frame e_1, e_2 of segment_point_t, so that tables compare line by line
  !> (CalculiX's springforc_n2f, read for its convention).
  pure function calculix_tangents(normal) result(t)
    real(dp), intent(in) :: normal(3)
    real(dp) :: t(3, 2)
    real(dp) :: axis(3)
    if (1.0_dp - abs(normal(1)) < CALCULIX_X_PARALLEL) then
      axis = [0.0_dp, 0.0_dp, 1.0_dp]
    else
      axis = [1.0_dp, 0.0_dp, 0.0_dp]
    end if
    t(:, 1) = axis - dot_product(axis, normal) * normal
    t(:, 1) = t(:, 1) / norm2(t(:, 1))
    t(:, 2) = cross3(normal, t(:, 1))
  end function calculix_tangents

end module fcs_contact_geometry
