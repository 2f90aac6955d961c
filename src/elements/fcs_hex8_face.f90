!> Pressure on a face of the hexahedron: consistent nodal forces and the load stiffness of a
!> follower pressure (the force follows the current area and normal).
!>
!> The face is the bilinear quadrilateral through xf(3,4), ordered so that the right-hand rule
!> gives the outward normal. With a = dx/dxi x dx/deta (area vector per unit natural area),
!> the nodal forces are f_a = -p sum_q N_a a w_q (2x2 Gauss), positive pressure pushing into
!> the body. Their derivative with respect to the face coordinates (da = dx_xi x x_eta +
!> x_xi x dx_eta) gives the load stiffness dF/dx, which enters the tangent with a minus sign.
module fcs_hex8_face
  use fcs_kinds, only: dp
  implicit none
  private
  public :: face_pressure_load, quad_shape, quad_shape_derivatives, quad_area_vector
  public :: HEX8_FACE_LOCAL_NODES, cross, skew

  !> Local node numbers of faces S1..S6 of the 8-node hexahedron (columns), ordered so that
  !> the right-hand rule gives the outward normal. The node sets are those of the
  !> Abaqus/CalculiX C3D8 faces (S1: 1-2-3-4, S2: 5-8-7-6, S3: 1-5-6-2, S4: 2-6-7-3, S5: 3-7-8-4,
  !> S6: 4-8-5-1); the C3D8 kernel's faces (fcs_element_kernels).
  integer, parameter :: HEX8_FACE_LOCAL_NODES(4, 6) = reshape([ &
    1, 4, 3, 2, &
    5, 6, 7, 8, &
    1, 2, 6, 5, &
    2, 3, 7, 6, &
    3, 4, 8, 7, &
    4, 1, 5, 8], [4, 6])

  real(dp), parameter :: XI_NODE(2, 4) = reshape([-1.0_dp, -1.0_dp, 1.0_dp, -1.0_dp, &
                                                   1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp], [2, 4])

contains

  !> Bilinear shape functions of the quadrilateral at (xi, eta).
  pure function quad_shape(xi) result(n)
    real(dp), intent(in) :: xi(2)
    real(dp) :: n(4)
    n = 0.25_dp * (1.0_dp + XI_NODE(1, :) * xi(1)) * (1.0_dp + XI_NODE(2, :) * xi(2))
  end function quad_shape

  !> dN_a/dxi_alpha as dn(alpha, a).
  pure function quad_shape_derivatives(xi) result(dn)
    real(dp), intent(in) :: xi(2)
    real(dp) :: dn(2, 4)
    dn(1, :) = 0.25_dp * XI_NODE(1, :) * (1.0_dp + XI_NODE(2, :) * xi(2))
    dn(2, :) = 0.25_dp * XI_NODE(2, :) * (1.0_dp + XI_NODE(1, :) * xi(1))
  end function quad_shape_derivatives

  !> Area vector dx/dxi x dx/deta at (xi, eta).
  pure function quad_area_vector(xf, xi) result(a)
    real(dp), intent(in) :: xf(3, 4), xi(2)
    real(dp) :: a(3)
    real(dp) :: dn(2, 4), t1(3), t2(3)
    dn = quad_shape_derivatives(xi)
    t1 = matmul(xf, dn(1, :))
    t2 = matmul(xf, dn(2, :))
    a = cross(t1, t2)
  end function quad_area_vector

  !> Nodal forces f(12) of pressure p on the face, and (optional) the derivative
  !> dfdx(12,12) = d f / d xf of a follower pressure.
  pure subroutine face_pressure_load(xf, p, f, dfdx)
    real(dp), intent(in) :: xf(3, 4), p
    real(dp), intent(out) :: f(12)
    real(dp), intent(out), optional :: dfdx(12, 12)
    real(dp), parameter :: g = 0.57735026918962576451_dp
    real(dp) :: xi(2), n(4), dn(2, 4), t1(3), t2(3), a(3)
    integer :: i, j, q, b
    f = 0.0_dp
    if (present(dfdx)) dfdx = 0.0_dp
    do q = 1, 4
      xi = g * XI_NODE(:, q)
      n = quad_shape(xi)
      dn = quad_shape_derivatives(xi)
      t1 = matmul(xf, dn(1, :))
      t2 = matmul(xf, dn(2, :))
      a = cross(t1, t2)
      do i = 1, 4
        f(3 * i - 2:3 * i) = f(3 * i - 2:3 * i) - p * n(i) * a
      end do
      if (.not. present(dfdx)) cycle
      ! d a = dn(1,b) dx_b x t2 + t1 x dn(2,b) dx_b = (dn(2,b) [t1]x - dn(1,b) [t2]x) dx_b
      do b = 1, 4
        do i = 1, 4
          j = 3 * b
          dfdx(3 * i - 2:3 * i, j - 2:j) = dfdx(3 * i - 2:3 * i, j - 2:j) - p * n(i) * &
            (dn(2, b) * skew(t1) - dn(1, b) * skew(t2))
        end do
      end do
    end do
  end subroutine face_pressure_load

  !> Cross product a x b.
  pure function cross(a, b) result(c)
    real(dp), intent(in) :: a(3), b(3)
    real(dp) :: c(3)
    c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
  end function cross

  !> Matrix of the cross product: skew(a) b = a x b.
  pure function skew(a) result(s)
    real(dp), intent(in) :: a(3)
    real(dp) :: s(3, 3)
    s = reshape([0.0_dp, a(3), -a(2), -a(3), 0.0_dp, a(1), a(2), -a(1), 0.0_dp], [3, 3])
  end function skew

end module fcs_hex8_face
