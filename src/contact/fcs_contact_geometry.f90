!> Geometry of a slave node against a bilinear 4-node master segment (Xing & Makinouchi 2002;
!> method notes 1.1): shape functions N_I(xi), natural base vectors a_alpha = dx/dxi_alpha,
!> metric m_ab = a_a.a_b, unit normal n = a_1 x a_2 / |a_1 x a_2| (outward from the master
!> body when the face nodes are ordered outward), the twist x_,12 (a bilinear segment has
!> x_,11 = x_,22 = 0), the local Cartesian frame e_1 = a_1/|a_1|, e_2 = n x e_1 in which the
!> friction force components are kept (the paper's e_i), and the closest-point projection of
!> a slave node (Newton in natural coordinates).
module fcs_contact_geometry
  use fcs_kinds, only: dp
  implicit none
  private
  public :: segment_point_t, segment_point, project_to_segment, cross3, calculix_tangents
  public :: PROJECTION_MAX_ITERATIONS

  !> Newton iterations allowed for the closest-point projection.
  integer, parameter :: PROJECTION_MAX_ITERATIONS = 30
  real(dp), parameter :: XI_NODE(2, 4) = reshape([-1.0_dp, -1.0_dp, 1.0_dp, -1.0_dp, &
                                                   1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp], [2, 4])

  !> 1 - |n_x| below which CalculiX takes the normal as parallel to the x axis (0.1 degree).
  real(dp), parameter :: CALCULIX_X_PARALLEL = 1.5231e-6_dp

  !> Everything about one point xi of a master segment.
  type :: segment_point_t
    real(dp) :: xi(2) = 0.0_dp
    real(dp) :: shape(4) = 0.0_dp
    !> dN_I/dxi_alpha as dshape(alpha, I).
    real(dp) :: dshape(2, 4) = 0.0_dp
    real(dp) :: x(3) = 0.0_dp
    !> a(:, alpha): natural base vectors; dual(:, alpha): contravariant a^alpha.
    real(dp) :: a(3, 2) = 0.0_dp
    real(dp) :: dual(3, 2) = 0.0_dp
    real(dp) :: metric(2, 2) = 0.0_dp
    real(dp) :: normal(3) = 0.0_dp
    real(dp) :: twist(3) = 0.0_dp
    !> Local Cartesian frame: e(:,1) = a_1/|a_1|, e(:,2) = n x e_1.
    real(dp) :: e(3, 2) = 0.0_dp
    real(dp) :: area_factor = 0.0_dp
  end type segment_point_t

contains

  !> Geometry of the segment with nodes xm(3,4) at natural point xi.
  pure function segment_point(xm, xi) result(p)
    real(dp), intent(in) :: xm(3, 4), xi(2)
    type(segment_point_t) :: p
    real(dp) :: c(3), det, inverse(2, 2)
    integer :: alpha
    p%xi = xi
    p%shape = 0.25_dp * (1.0_dp + XI_NODE(1, :) * xi(1)) * (1.0_dp + XI_NODE(2, :) * xi(2))
    p%dshape(1, :) = 0.25_dp * XI_NODE(1, :) * (1.0_dp + XI_NODE(2, :) * xi(2))
    p%dshape(2, :) = 0.25_dp * XI_NODE(2, :) * (1.0_dp + XI_NODE(1, :) * xi(1))
    p%x = matmul(xm, p%shape)
    do alpha = 1, 2
      p%a(:, alpha) = matmul(xm, p%dshape(alpha, :))
    end do
    p%twist = 0.25_dp * matmul(xm, XI_NODE(1, :) * XI_NODE(2, :))
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

  !> Closest-point projection of x_slave onto the (unbounded) bilinear surface of the
  !> segment: solve (x_s - x(xi)).a_alpha(xi) = 0 by Newton with the matrix
  !> A_ab = m_ab - g h_ab (h_12 = h_21 = n.x_,12, h_11 = h_22 = 0), starting from xi_start.
  !> `converged` is false when Newton fails (degenerate segment or far-away point).
  pure subroutine project_to_segment(xm, x_slave, xi_start, p, gap, converged)
    real(dp), intent(in) :: xm(3, 4), x_slave(3), xi_start(2)
    type(segment_point_t), intent(out) :: p
    real(dp), intent(out) :: gap
    logical, intent(out) :: converged
    real(dp) :: d(3), residual(2), jac(2, 2), step(2), det, scale
    integer :: iteration
    p = segment_point(xm, xi_start)
    converged = .false.
    gap = 0.0_dp
    scale = max(norm2(xm(:, 3) - xm(:, 1)), norm2(xm(:, 4) - xm(:, 2)))
    do iteration = 1, PROJECTION_MAX_ITERATIONS
      if (p%area_factor <= tiny(1.0_dp)) return
      d = x_slave - p%x
      residual = matmul(d, p%a)
      gap = dot_product(d, p%normal)
      jac = p%metric
      jac(1, 2) = jac(1, 2) - dot_product(d, p%twist)
      jac(2, 1) = jac(1, 2)
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
