!> Local material axes (*ORIENTATION) and the Voigt transformations between local and global
!> components, as CalculiX defines them (ccx manual, *ORIENTATION; doc/theory.md 2.9).
!>
!> The axes at a point are the columns of A = [e1 e2 e3] (global components of the local unit
!> vectors). A rectangular system is given by two vectors a and b: e1 = a / |a|, e2 the part
!> of b normal to e1, normalised, e3 = e1 x e2. A cylindrical system is given by two points a
!> and b of its axis: e3 = (b - a) / |b - a|, e1 the radial direction from the axis to the
!> point, e2 = e3 x e1 (local x radial, y tangential, z axial). Components transform as
!> sigma_local = A^T sigma A and sigma = A sigma_local A^T; the stiffness as C = T C_local T^T
!> with T the Voigt form of the stress rotation by A.
module fcs_orientation
  use fcs_kinds, only: dp
  use fcs_voigt, only: rotate_stress_like, rotate_strain_like
  implicit none
  private
  public :: orientation_t, orientation_axes, stress_to_local, stress_to_global, strain_to_local
  public :: rotate_stiffness, rotate_about_axis, orientation_is_valid

  !> Below this length (relative to the vectors given) two vectors count as parallel, a
  !> point as on the axis of a cylindrical system.
  real(dp), parameter :: PARALLEL_TOLERANCE = 1.0e-10_dp

  !> One *ORIENTATION: a, b as given (RECTANGULAR: two vectors; CYLINDRICAL: two points of
  !> the axis), already turned by the optional rotation line.
  type :: orientation_t
    character(len=:), allocatable :: name
    real(dp) :: a(3) = [1.0_dp, 0.0_dp, 0.0_dp]
    real(dp) :: b(3) = [0.0_dp, 1.0_dp, 0.0_dp]
    logical :: cylindrical = .false.
  end type orientation_t

contains

  !> Whether a and b define axes: a rectangular system needs a /= 0 and b not parallel to a;
  !> a cylindrical one two distinct points.
  pure logical function orientation_is_valid(o) result(ok)
    type(orientation_t), intent(in) :: o
    real(dp) :: e1(3), e2(3)
    if (o%cylindrical) then
      ok = norm2(o%b - o%a) > PARALLEL_TOLERANCE * max(norm2(o%a), norm2(o%b))
      return
    end if
    ok = .false.
    if (norm2(o%a) <= 0.0_dp .or. norm2(o%b) <= 0.0_dp) return
    e1 = o%a / norm2(o%a)
    e2 = o%b - dot_product(o%b, e1) * e1
    ok = norm2(e2) > PARALLEL_TOLERANCE * norm2(o%b)
  end function orientation_is_valid

  !> The axes A = [e1 e2 e3] of orientation o at point p (p matters for a cylindrical system
  !> only; on its axis any radial direction is taken, as CalculiX's transformatrix does).
  pure function orientation_axes(o, p) result(axes)
    type(orientation_t), intent(in) :: o
    real(dp), intent(in) :: p(3)
    real(dp) :: axes(3, 3)
    real(dp) :: e1(3), e2(3), e3(3)
    if (o%cylindrical) then
      e3 = (o%b - o%a) / norm2(o%b - o%a)
      e1 = p - o%a
      e1 = e1 - dot_product(e1, e3) * e3
      if (norm2(e1) <= PARALLEL_TOLERANCE * max(1.0_dp, norm2(p - o%a))) e1 = any_normal(e3)
      e1 = e1 / norm2(e1)
      e2 = cross(e3, e1)
    else
      e1 = o%a / norm2(o%a)
      e2 = o%b - dot_product(o%b, e1) * e1
      e2 = e2 / norm2(e2)
      e3 = cross(e1, e2)
    end if
    axes(:, 1) = e1
    axes(:, 2) = e2
    axes(:, 3) = e3
  end function orientation_axes

  !> The rectangular orientation o turned by `angle` [degree] about its own local axis
  !> `axis` (1..3), right-handed: the second data line of *ORIENTATION (CalculiX applies it
  !> to rectangular systems only). The turned e1, e2 become the new a, b.
  pure function rotate_about_axis(o, axis, angle) result(turned)
    type(orientation_t), intent(in) :: o
    integer, intent(in) :: axis
    real(dp), intent(in) :: angle
    type(orientation_t) :: turned
    real(dp) :: axes(3, 3), r(3, 3), n(3), c, s
    real(dp), parameter :: DEGREE = acos(-1.0_dp) / 180.0_dp
    integer :: i
    axes = orientation_axes(o, [0.0_dp, 0.0_dp, 0.0_dp])
    n = axes(:, axis)
    c = cos(angle * DEGREE)
    s = sin(angle * DEGREE)
    ! Rodrigues: R = c I + s [n]x + (1 - c) n n^T.
    r = (1.0_dp - c) * spread(n, 2, 3) * spread(n, 1, 3)
    do i = 1, 3
      r(i, i) = r(i, i) + c
    end do
    r(1, 2) = r(1, 2) - s * n(3)
    r(1, 3) = r(1, 3) + s * n(2)
    r(2, 1) = r(2, 1) + s * n(3)
    r(2, 3) = r(2, 3) - s * n(1)
    r(3, 1) = r(3, 1) - s * n(2)
    r(3, 2) = r(3, 2) + s * n(1)
    turned = o
    turned%a = matmul(r, axes(:, 1))
    turned%b = matmul(r, axes(:, 2))
  end function rotate_about_axis

  !> Local components A^T sigma A of a (global) stress-like Voigt vector.
  pure function stress_to_local(stress, axes) result(local)
    real(dp), intent(in) :: stress(6), axes(3, 3)
    real(dp) :: local(6)
    local = rotate_stress_like(stress, transpose(axes))
  end function stress_to_local

  !> Global components A sigma_local A^T of a local stress-like Voigt vector.
  pure function stress_to_global(local, axes) result(stress)
    real(dp), intent(in) :: local(6), axes(3, 3)
    real(dp) :: stress(6)
    stress = rotate_stress_like(local, axes)
  end function stress_to_global

  !> Local components of a (global) strain with engineering shears.
  pure function strain_to_local(strain, axes) result(local)
    real(dp), intent(in) :: strain(6), axes(3, 3)
    real(dp) :: local(6)
    local = rotate_strain_like(strain, transpose(axes))
  end function strain_to_local

  !> The global stiffness C = T C_local T^T of a stiffness in local axes (engineering shear
  !> strains): sigma = T sigma_local, eps_local = T^T eps, T the Voigt matrix of
  !> stress_to_global (its columns the global images of the unit local stresses).
  pure function rotate_stiffness(local, axes) result(c)
    real(dp), intent(in) :: local(6, 6), axes(3, 3)
    real(dp) :: c(6, 6)
    real(dp) :: t(6, 6), unit(6)
    integer :: j
    do j = 1, 6
      unit = 0.0_dp
      unit(j) = 1.0_dp
      t(:, j) = stress_to_global(unit, axes)
    end do
    c = matmul(t, matmul(local, transpose(t)))
  end function rotate_stiffness

  pure function cross(u, v) result(w)
    real(dp), intent(in) :: u(3), v(3)
    real(dp) :: w(3)
    w = [u(2) * v(3) - u(3) * v(2), u(3) * v(1) - u(1) * v(3), u(1) * v(2) - u(2) * v(1)]
  end function cross

  !> A vector normal to the unit vector n.
  pure function any_normal(n) result(v)
    real(dp), intent(in) :: n(3)
    real(dp) :: v(3)
    if (abs(n(1)) <= abs(n(2)) .and. abs(n(1)) <= abs(n(3))) then
      v = cross(n, [1.0_dp, 0.0_dp, 0.0_dp])
    else if (abs(n(2)) <= abs(n(3))) then
      v = cross(n, [0.0_dp, 1.0_dp, 0.0_dp])
    else
      v = cross(n, [0.0_dp, 0.0_dp, 1.0_dp])
    end if
  end function any_normal

end module fcs_orientation
