!> Interpolation bases described as data, as Elmer's `fem/src/elements.def` describes its element
!> kinds: the natural coordinates of the nodes and the monomials that span the basis. The shape
!> functions are the unique combination of the monomials p_k that interpolates the nodes,
!> N_a(x_b) = delta_ab: with the Vandermonde matrix V(b, k) = p_k(x_b),
!>   N_a(x) = sum_k C(k, a) p_k(x),   C = V^-1.
!> For the node sets and monomials of the element kinds (hexahedra, tetrahedra, wedges and their
!> faces) this gives the textbook Lagrange and serendipity shape functions (Zienkiewicz, Taylor &
!> Zhu, The Finite Element Method: Its Basis and Fundamentals, 6th ed., 2005, chapter "Standard
!> and hierarchical element shape functions"; Dhondt 2004, ch. 3), which the unit test checks
!> against their closed forms.
!>
!> Also the small dense solver the bases and the extrapolation matrices are built with
!> (set-up only: nothing here runs in the element loops except `values` and `derivatives`).
module fcs_element_basis
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error
  implicit none
  private
  public :: polynomial_basis_t, solve_linear_system, MAX_BASIS_SIZE, MAX_EXPONENT

  !> Most shape functions of one basis (the 20-node hexahedron).
  integer, parameter :: MAX_BASIS_SIZE = 20
  !> Highest power of one coordinate in a monomial.
  integer, parameter :: MAX_EXPONENT = 4

  !> A polynomial interpolation basis in `dimension` (2 or 3) natural coordinates.
  type :: polynomial_basis_t
    integer :: dimension = 0
    !> Number of shape functions (= nodes = monomials).
    integer :: n = 0
    !> exponents(i, k): power of coordinate i in monomial k.
    integer, allocatable :: exponents(:, :)
    !> coefficients(k, a): coefficient of monomial k in shape function a.
    real(dp), allocatable :: coefficients(:, :)
  contains
    procedure :: init => basis_init
    procedure :: free => basis_free
    procedure :: values => basis_values
    procedure :: derivatives => basis_derivatives
  end type polynomial_basis_t

contains

  !> Build the basis of nodes `node_xi(dimension, n)` spanned by the monomials
  !> `exponents(dimension, n)`. Fails if the nodes do not determine the monomials (singular
  !> Vandermonde matrix) or the sizes disagree.
  subroutine basis_init(this, node_xi, exponents, err)
    class(polynomial_basis_t), intent(inout) :: this
    real(dp), intent(in) :: node_xi(:, :)
    integer, intent(in) :: exponents(:, :)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: vandermonde(:, :), identity(:, :)
    integer :: n, b, k
    logical :: ok
    call this%free()
    n = size(node_xi, 2)
    if (size(exponents, 2) /= n .or. size(exponents, 1) /= size(node_xi, 1) .or. n < 1 .or. &
        n > MAX_BASIS_SIZE .or. size(node_xi, 1) < 1 .or. size(node_xi, 1) > 3) then
      call fatal_error(err, 'polynomial basis: node coordinates and monomials do not match')
      return
    end if
    if (any(exponents < 0) .or. any(exponents > MAX_EXPONENT)) then
      call fatal_error(err, 'polynomial basis: a monomial exponent is outside 0..4')
      return
    end if
    this%dimension = size(node_xi, 1)
    this%n = n
    this%exponents = exponents
    allocate (vandermonde(n, n), identity(n, n))
    do b = 1, n
      call monomials(this, node_xi(:, b), vandermonde(b, :))
    end do
    identity = 0.0_dp
    do k = 1, n
      identity(k, k) = 1.0_dp
    end do
    call solve_linear_system(vandermonde, identity, ok)
    if (.not. ok) then
      call this%free()
      call fatal_error(err, 'polynomial basis: the nodes do not determine the monomials ' // &
                       '(singular Vandermonde matrix)')
      return
    end if
    this%coefficients = identity
  end subroutine basis_init

  !> Forget the basis.
  subroutine basis_free(this)
    class(polynomial_basis_t), intent(inout) :: this
    this%dimension = 0
    this%n = 0
    if (allocated(this%exponents)) deallocate (this%exponents)
    if (allocated(this%coefficients)) deallocate (this%coefficients)
  end subroutine basis_free

  !> Shape function values n(a) = N_a(xi), a = 1..this%n.
  pure subroutine basis_values(this, xi, n)
    class(polynomial_basis_t), intent(in) :: this
    real(dp), intent(in) :: xi(:)
    real(dp), intent(out) :: n(:)
    real(dp) :: p(MAX_BASIS_SIZE), s
    integer :: a, k
    call monomials(this, xi, p)
    do a = 1, this%n
      s = 0.0_dp
      do k = 1, this%n
        s = s + this%coefficients(k, a) * p(k)
      end do
      n(a) = s
    end do
  end subroutine basis_values

  !> Natural derivatives dn(i, a) = dN_a/dxi_i at xi.
  pure subroutine basis_derivatives(this, xi, dn)
    class(polynomial_basis_t), intent(in) :: this
    real(dp), intent(in) :: xi(:)
    real(dp), intent(out) :: dn(:, :)
    real(dp) :: dp_dxi(3, MAX_BASIS_SIZE), s
    integer :: a, k, i
    call monomial_derivatives(this, xi, dp_dxi)
    do a = 1, this%n
      do i = 1, this%dimension
        s = 0.0_dp
        do k = 1, this%n
          s = s + this%coefficients(k, a) * dp_dxi(i, k)
        end do
        dn(i, a) = s
      end do
    end do
  end subroutine basis_derivatives

  !> Values p(k) of the monomials at xi.
  pure subroutine monomials(this, xi, p)
    type(polynomial_basis_t), intent(in) :: this
    real(dp), intent(in) :: xi(:)
    real(dp), intent(out) :: p(:)
    real(dp) :: powers(0:MAX_EXPONENT, 3)
    integer :: i, k
    call power_table(xi, this%dimension, powers)
    do k = 1, this%n
      p(k) = 1.0_dp
      do i = 1, this%dimension
        p(k) = p(k) * powers(this%exponents(i, k), i)
      end do
    end do
  end subroutine monomials

  !> Derivatives dp(i, k) = d p_k / d xi_i of the monomials at xi.
  pure subroutine monomial_derivatives(this, xi, dp_dxi)
    type(polynomial_basis_t), intent(in) :: this
    real(dp), intent(in) :: xi(:)
    real(dp), intent(out) :: dp_dxi(:, :)
    real(dp) :: powers(0:MAX_EXPONENT, 3), term
    integer :: i, j, k, e
    call power_table(xi, this%dimension, powers)
    do k = 1, this%n
      do i = 1, this%dimension
        e = this%exponents(i, k)
        if (e == 0) then
          dp_dxi(i, k) = 0.0_dp
          cycle
        end if
        term = e * powers(e - 1, i)
        do j = 1, this%dimension
          if (j /= i) term = term * powers(this%exponents(j, k), j)
        end do
        dp_dxi(i, k) = term
      end do
    end do
  end subroutine monomial_derivatives

  !> powers(e, i) = xi(i)**e for e = 0..MAX_EXPONENT.
  pure subroutine power_table(xi, dimension, powers)
    real(dp), intent(in) :: xi(:)
    integer, intent(in) :: dimension
    real(dp), intent(out) :: powers(0:MAX_EXPONENT, 3)
    integer :: i, e
    powers = 1.0_dp
    do i = 1, dimension
      do e = 1, MAX_EXPONENT
        powers(e, i) = powers(e - 1, i) * xi(i)
      end do
    end do
  end subroutine power_table

  !> Solve A X = B for X by Gauss-Jordan elimination with partial pivoting: `a` (n x n) is
  !> destroyed, `b` (n x m) is overwritten with X. `ok` is false if a pivot is below
  !> 1e-13 times the largest entry of A (singular to working precision). For the small,
  !> well-conditioned matrices of element set-up only.
  pure subroutine solve_linear_system(a, b, ok)
    real(dp), intent(inout) :: a(:, :), b(:, :)
    logical, intent(out) :: ok
    real(dp) :: scale, factor, row_a(size(a, 2)), row_b(size(b, 2))
    integer :: n, col, pivot, r
    n = size(a, 1)
    scale = maxval(abs(a))
    ok = scale > 0.0_dp
    if (.not. ok) return
    do col = 1, n
      pivot = col - 1 + maxloc(abs(a(col:n, col)), 1)
      if (abs(a(pivot, col)) <= 1.0e-13_dp * scale) then
        ok = .false.
        return
      end if
      if (pivot /= col) then
        row_a = a(col, :)
        a(col, :) = a(pivot, :)
        a(pivot, :) = row_a
        row_b = b(col, :)
        b(col, :) = b(pivot, :)
        b(pivot, :) = row_b
      end if
      factor = 1.0_dp / a(col, col)
      a(col, :) = a(col, :) * factor
      b(col, :) = b(col, :) * factor
      do r = 1, n
        if (r == col .or. a(r, col) == 0.0_dp) cycle
        factor = a(r, col)
        a(r, :) = a(r, :) - factor * a(col, :)
        b(r, :) = b(r, :) - factor * b(col, :)
      end do
    end do
  end subroutine solve_linear_system

end module fcs_element_basis
