!> Geometry of the 8-node hexahedron: trilinear shape functions, their derivatives, the 2x2x2
!> Gauss rule and the Jacobian. Node order and natural coordinates as in Abaqus/CalculiX C3D8
!> (node 1 at (-1,-1,-1), 2 at (1,-1,-1), 3 at (1,1,-1), 4 at (-1,1,-1), 5..8 the same at
!> zeta = +1). Integration points are numbered with xi fastest, then eta, then zeta, each
!> running from -1/sqrt(3) to +1/sqrt(3) - the order CalculiX prints them in.
module fcs_hex8_shape
  use fcs_kinds, only: dp
  implicit none
  private
  public :: HEX8_NODE_XI, hex8_shape, hex8_shape_derivatives, hex8_gauss_points
  public :: hex8_jacobian, hex8_min_jacobian_ratio, N_GAUSS_HEX8, det3, inverse3

  !> Number of integration points of the full rule.
  integer, parameter :: N_GAUSS_HEX8 = 8
  !> Natural coordinates of the 8 nodes (columns).
  real(dp), parameter :: HEX8_NODE_XI(3, 8) = reshape([ &
    -1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, &
    -1.0_dp, 1.0_dp, -1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp, &
    1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp], [3, 8])

contains

  !> Shape function values N_a(xi), a = 1..8.
  pure function hex8_shape(xi) result(n)
    real(dp), intent(in) :: xi(3)
    real(dp) :: n(8)
    integer :: a
    do a = 1, 8
      n(a) = 0.125_dp * (1.0_dp + HEX8_NODE_XI(1, a) * xi(1)) * &
             (1.0_dp + HEX8_NODE_XI(2, a) * xi(2)) * (1.0_dp + HEX8_NODE_XI(3, a) * xi(3))
    end do
  end function hex8_shape

  !> Derivatives dN_a/dxi_i, as dn(i, a).
  pure function hex8_shape_derivatives(xi) result(dn)
    real(dp), intent(in) :: xi(3)
    real(dp) :: dn(3, 8)
    real(dp) :: f(3)
    integer :: a
    do a = 1, 8
      f = 1.0_dp + HEX8_NODE_XI(:, a) * xi
      dn(1, a) = 0.125_dp * HEX8_NODE_XI(1, a) * f(2) * f(3)
      dn(2, a) = 0.125_dp * HEX8_NODE_XI(2, a) * f(1) * f(3)
      dn(3, a) = 0.125_dp * HEX8_NODE_XI(3, a) * f(1) * f(2)
    end do
  end function hex8_shape_derivatives

  !> The 2x2x2 Gauss points (columns) and weights (all 1).
  pure subroutine hex8_gauss_points(points, weights)
    real(dp), intent(out) :: points(3, N_GAUSS_HEX8)
    real(dp), intent(out) :: weights(N_GAUSS_HEX8)
    real(dp), parameter :: g = 0.57735026918962576451_dp
    integer :: i, j, k, q
    q = 0
    do k = 1, 2
      do j = 1, 2
        do i = 1, 2
          q = q + 1
          points(:, q) = [merge(-g, g, i == 1), merge(-g, g, j == 1), merge(-g, g, k == 1)]
        end do
      end do
    end do
    weights = 1.0_dp
  end subroutine hex8_gauss_points

  !> Jacobian J(i,j) = dx_i/dxi_j at natural point xi, for nodal coordinates x(3,8).
  pure function hex8_jacobian(x, xi) result(jac)
    real(dp), intent(in) :: x(3, 8), xi(3)
    real(dp) :: jac(3, 3)
    real(dp) :: dn(3, 8)
    integer :: i, j
    dn = hex8_shape_derivatives(xi)
    do j = 1, 3
      do i = 1, 3
        jac(i, j) = sum(x(i, :) * dn(j, :))
      end do
    end do
  end function hex8_jacobian

  !> Smallest det J over the Gauss points and the nodes, divided by the element's mean det J
  !> (the volume / 8). Negative: the element is inverted or badly distorted.
  pure real(dp) function hex8_min_jacobian_ratio(x) result(ratio)
    real(dp), intent(in) :: x(3, 8)
    real(dp) :: points(3, N_GAUSS_HEX8), weights(N_GAUSS_HEX8), d, volume, smallest
    integer :: q
    call hex8_gauss_points(points, weights)
    volume = 0.0_dp
    smallest = huge(1.0_dp)
    do q = 1, N_GAUSS_HEX8
      d = det3(hex8_jacobian(x, points(:, q)))
      volume = volume + d * weights(q)
      smallest = min(smallest, d)
    end do
    do q = 1, 8
      smallest = min(smallest, det3(hex8_jacobian(x, HEX8_NODE_XI(:, q))))
    end do
    if (abs(volume) <= tiny(1.0_dp)) then
      ratio = -1.0_dp
    else
      ratio = smallest / abs(volume / 8.0_dp)
    end if
  end function hex8_min_jacobian_ratio

  !> Determinant of a 3x3 matrix.
  pure real(dp) function det3(a)
    real(dp), intent(in) :: a(3, 3)
    det3 = a(1, 1) * (a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)) &
         - a(1, 2) * (a(2, 1) * a(3, 3) - a(2, 3) * a(3, 1)) &
         + a(1, 3) * (a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1))
  end function det3

  !> Inverse of a 3x3 matrix with determinant `det` (computed by the caller with det3).
  pure function inverse3(a, det) result(inv)
    real(dp), intent(in) :: a(3, 3), det
    real(dp) :: inv(3, 3)
    inv(1, 1) = a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)
    inv(1, 2) = a(1, 3) * a(3, 2) - a(1, 2) * a(3, 3)
    inv(1, 3) = a(1, 2) * a(2, 3) - a(1, 3) * a(2, 2)
    inv(2, 1) = a(2, 3) * a(3, 1) - a(2, 1) * a(3, 3)
    inv(2, 2) = a(1, 1) * a(3, 3) - a(1, 3) * a(3, 1)
    inv(2, 3) = a(1, 3) * a(2, 1) - a(1, 1) * a(2, 3)
    inv(3, 1) = a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1)
    inv(3, 2) = a(1, 2) * a(3, 1) - a(1, 1) * a(3, 2)
    inv(3, 3) = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)
    inv = inv / det
  end function inverse3

end module fcs_hex8_shape
