!> Integration rules on the reference domains of the element kinds and their faces, with the
!> points in the order CalculiX numbers them (so that integration point k of fcs3d is
!> integration point k of a CalculiX `.dat` table).
!>
!> Reference domains: line and square and cube [-1, 1]^d; triangle 0 <= s, t, s + t <= 1;
!> tetrahedron 0 <= xi, eta, zeta, xi + eta + zeta <= 1; wedge = triangle (xi, eta) times
!> zeta in [-1, 1]. The rules are those of CalculiX's `gauss.f` (ccx 2.20, checked point by
!> point): gauss3d1/2/3 (hexahedron 1, 2x2x2, 3x3x3), gauss2d1/2/3 (square), gauss2d4/5
!> (triangle 1 and 3 points), gauss3d4/5 (tetrahedron 1 and 4 points), gauss3d7/8 (wedge 2 and
!> 9 points); the formulas are the textbook ones (Gauss-Legendre products; the symmetric
!> triangle and tetrahedron rules of degree 1 and 2: Zienkiewicz, Taylor & Zhu, The Finite
!> Element Method: Its Basis and Fundamentals, 6th ed., 2005, tables of triangle and
!> tetrahedron integration; Dhondt, The Finite Element Method for Three-Dimensional
!> Thermomechanical Applications, Wiley 2004, ch. 3). Here they are computed from closed
!> forms (1/sqrt(3), sqrt(3/5), (5 -+ sqrt(5))/20 ...), so they are exact to round-off where
!> CalculiX's tables carry 15 digits.
!>
!> Point order: tensor rules run xi fastest, then eta, then zeta; wedge rules run the triangle
!> points fastest, then zeta.
module fcs_quadrature
  use fcs_kinds, only: dp
  implicit none
  private
  public :: quadrature_rule_t, gauss_line, gauss_square, gauss_cube, triangle_rule, &
            tetrahedron_rule, wedge_rule

  !> An integration rule: points (dimension, n) in natural coordinates and their weights.
  !> `degree` is the total degree of the polynomials it integrates exactly (tensor rules of
  !> n points per direction also integrate every monomial of degree <= 2n - 1 in each
  !> coordinate separately; the wedge rules, their line part's degree in zeta).
  type :: quadrature_rule_t
    integer :: dimension = 0
    integer :: n = 0
    integer :: degree = -1
    !> Points per direction of a tensor rule (line, square, cube) or of the zeta direction of a
    !> wedge rule; 0 for the triangle and tetrahedron rules.
    integer :: line_points = 0
    character(len=:), allocatable :: name
    real(dp), allocatable :: points(:, :)
    real(dp), allocatable :: weights(:)
  end type quadrature_rule_t

  !> 1/sqrt(3) and sqrt(3/5): the 2- and 3-point Gauss-Legendre abscissae.
  real(dp), parameter :: G2 = 0.57735026918962576451_dp
  real(dp), parameter :: G3 = 0.77459666924148337704_dp

contains

  !> Gauss-Legendre rule with n = 1, 2 or 3 points on [-1, 1] (exact to degree 2n - 1). Any
  !> other n gives an empty rule (n = 0).
  pure function gauss_line(n) result(rule)
    integer, intent(in) :: n
    type(quadrature_rule_t) :: rule
    rule%dimension = 1
    rule%name = 'empty'
    select case (n)
    case (1)
      call set(rule, reshape([0.0_dp], [1, 1]), [2.0_dp])
    case (2)
      call set(rule, reshape([-G2, G2], [1, 2]), [1.0_dp, 1.0_dp])
    case (3)
      call set(rule, reshape([-G3, 0.0_dp, G3], [1, 3]), &
               [5.0_dp / 9.0_dp, 8.0_dp / 9.0_dp, 5.0_dp / 9.0_dp])
    case default
      return
    end select
    rule%degree = 2 * n - 1
    rule%line_points = n
    rule%name = 'Gauss ' // digit(n)
  end function gauss_line

  !> Product Gauss rule with n x n points on the square (CalculiX gauss2d1/2/3), xi fastest.
  pure function gauss_square(n) result(rule)
    integer, intent(in) :: n
    type(quadrature_rule_t) :: rule
    type(quadrature_rule_t) :: line
    integer :: i, j, q
    line = gauss_line(n)
    rule%dimension = 2
    rule%name = 'empty'
    if (line%n == 0) return
    allocate (rule%points(2, n * n), rule%weights(n * n))
    q = 0
    do j = 1, n
      do i = 1, n
        q = q + 1
        rule%points(:, q) = [line%points(1, i), line%points(1, j)]
        rule%weights(q) = line%weights(i) * line%weights(j)
      end do
    end do
    rule%n = n * n
    rule%degree = line%degree
    rule%line_points = n
    rule%name = 'Gauss ' // digit(n) // 'x' // digit(n)
  end function gauss_square

  !> Product Gauss rule with n x n x n points on the cube (CalculiX gauss3d1/2/3), xi fastest,
  !> then eta, then zeta.
  pure function gauss_cube(n) result(rule)
    integer, intent(in) :: n
    type(quadrature_rule_t) :: rule
    type(quadrature_rule_t) :: line
    integer :: i, j, k, q
    line = gauss_line(n)
    rule%dimension = 3
    rule%name = 'empty'
    if (line%n == 0) return
    allocate (rule%points(3, n**3), rule%weights(n**3))
    q = 0
    do k = 1, n
      do j = 1, n
        do i = 1, n
          q = q + 1
          rule%points(:, q) = [line%points(1, i), line%points(1, j), line%points(1, k)]
          rule%weights(q) = line%weights(i) * line%weights(j) * line%weights(k)
        end do
      end do
    end do
    rule%n = n**3
    rule%degree = line%degree
    rule%line_points = n
    rule%name = 'Gauss ' // digit(n) // 'x' // digit(n) // 'x' // digit(n)
  end function gauss_cube

  !> Triangle rules: n = 1, the centroid (degree 1; CalculiX gauss2d4), or n = 3, the points
  !> (1/6, 1/6), (2/3, 1/6), (1/6, 2/3) with weights 1/6 (degree 2; CalculiX gauss2d5).
  pure function triangle_rule(n) result(rule)
    integer, intent(in) :: n
    type(quadrature_rule_t) :: rule
    rule%dimension = 2
    rule%name = 'empty'
    select case (n)
    case (1)
      call set(rule, reshape([1.0_dp, 1.0_dp] / 3.0_dp, [2, 1]), [0.5_dp])
      rule%degree = 1
    case (3)
      call set(rule, reshape([1.0_dp, 1.0_dp, 4.0_dp, 1.0_dp, 1.0_dp, 4.0_dp] / 6.0_dp, [2, 3]), &
               [1.0_dp, 1.0_dp, 1.0_dp] / 6.0_dp)
      rule%degree = 2
    case default
      return
    end select
    rule%name = 'triangle ' // digit(n) // '-point'
  end function triangle_rule

  !> Tetrahedron rules: n = 1, the centroid with weight 1/6 (degree 1; CalculiX gauss3d4), or
  !> n = 4, points (a, a, a), (b, a, a), (a, b, a), (a, a, b) with a = (5 - sqrt(5))/20,
  !> b = (5 + 3 sqrt(5))/20 and weights 1/24 (degree 2; CalculiX gauss3d5).
  pure function tetrahedron_rule(n) result(rule)
    integer, intent(in) :: n
    type(quadrature_rule_t) :: rule
    real(dp), parameter :: a = (5.0_dp - 2.2360679774997896964_dp) / 20.0_dp
    real(dp), parameter :: b = (5.0_dp + 3.0_dp * 2.2360679774997896964_dp) / 20.0_dp
    rule%dimension = 3
    rule%name = 'empty'
    select case (n)
    case (1)
      call set(rule, reshape([0.25_dp, 0.25_dp, 0.25_dp], [3, 1]), [1.0_dp / 6.0_dp])
      rule%degree = 1
    case (4)
      call set(rule, reshape([a, a, a, b, a, a, a, b, a, a, a, b], [3, 4]), &
               [1.0_dp, 1.0_dp, 1.0_dp, 1.0_dp] / 24.0_dp)
      rule%degree = 2
    case default
      return
    end select
    rule%name = 'tetrahedron ' // digit(n) // '-point'
  end function tetrahedron_rule

  !> Wedge rules, the product of a triangle rule and a Gauss rule in zeta: n = 2, centroid x
  !> 2 Gauss points (CalculiX gauss3d7: degree 1, 3 in zeta), or n = 9, the 3-point triangle
  !> rule x 3 Gauss points (CalculiX gauss3d8: degree 2, 5 in zeta). Triangle points run
  !> fastest.
  pure function wedge_rule(n) result(rule)
    integer, intent(in) :: n
    type(quadrature_rule_t) :: rule
    type(quadrature_rule_t) :: triangle, line
    integer :: i, k, q
    rule%dimension = 3
    rule%name = 'empty'
    select case (n)
    case (2)
      triangle = triangle_rule(1)
      line = gauss_line(2)
    case (9)
      triangle = triangle_rule(3)
      line = gauss_line(3)
    case default
      return
    end select
    allocate (rule%points(3, n), rule%weights(n))
    q = 0
    do k = 1, line%n
      do i = 1, triangle%n
        q = q + 1
        rule%points(:, q) = [triangle%points(:, i), line%points(1, k)]
        rule%weights(q) = triangle%weights(i) * line%weights(k)
      end do
    end do
    rule%n = n
    rule%degree = triangle%degree
    rule%line_points = line%n
    rule%name = 'wedge ' // digit(triangle%n) // 'x' // digit(line%n)
  end function wedge_rule

  !> Store points and weights in `rule`.
  pure subroutine set(rule, points, weights)
    type(quadrature_rule_t), intent(inout) :: rule
    real(dp), intent(in) :: points(:, :), weights(:)
    rule%points = points
    rule%weights = weights
    rule%n = size(weights)
  end subroutine set

  !> A digit 1..9 as text.
  pure function digit(n) result(text)
    integer, intent(in) :: n
    character(len=1) :: text
    text = achar(iachar('0') + n)
  end function digit

end module fcs_quadrature
