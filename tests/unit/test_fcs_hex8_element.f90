!> Unit tests of the hexahedron kernel: patch-type checks of B, the tangent against finite
!> differences of the internal force with the objective stress update (the consistency of
!> eq. 1's initial-stress terms), Hughes-Winget rotation, extrapolation, pressure loads.
program test_fcs_hex8_element
  use fcs_kinds, only: dp
  use fcs_test_assertions, only: test_suite_t
  use fcs_hex8_element, only: hex8_geometry_t, hex8_geometry, hex8_tangent, hex8_internal_force, &
                              hex8_strain_increments, hex8_rotate_stress, hex8_extrapolate, &
                              mises_stress
  use fcs_hex8_face, only: face_pressure_load
  use fcs_hex8_shape, only: HEX8_NODE_XI
  use fcs_material, only: isotropic_elastic_matrix
  implicit none
  type(test_suite_t) :: suite
  suite%name = 'hex8_element'
  call test_volume_and_gradients(suite)
  call test_tangent_finite_difference(suite, .false.)
  call test_tangent_finite_difference(suite, .true.)
  call test_rigid_rotation(suite)
  call test_extrapolation(suite)
  call test_pressure(suite)
  call suite%report()

contains

  !> A distorted element (random corner perturbations of a 2 x 1 x 1.5 box).
  function distorted_element() result(x)
    real(dp) :: x(3, 8), noise(3, 8)
    integer :: seed_size
    integer, allocatable :: seed(:)
    call random_seed(size=seed_size)
    allocate (seed(seed_size))
    seed = 12345
    call random_seed(put=seed)
    call random_number(noise)
    x = 0.5_dp * (HEX8_NODE_XI + 1.0_dp)
    x(1, :) = 2.0_dp * x(1, :)
    x(3, :) = 1.5_dp * x(3, :)
    x = x + 0.15_dp * (noise - 0.5_dp)
  end function distorted_element

  subroutine test_volume_and_gradients(suite)
    type(test_suite_t), intent(inout) :: suite
    type(hex8_geometry_t) :: geo
    real(dp) :: x(3, 8), du(3, 8), strain(6, 8), spin(3, 3, 8), eq(8), angle(8), g(3, 3)
    logical :: ok
    integer :: a
    x = 0.5_dp * (HEX8_NODE_XI + 1.0_dp)
    x(1, :) = 2.0_dp * x(1, :)
    call hex8_geometry(x, geo, ok)
    call suite%check(ok, 'box geometry is valid')
    call suite%close_to(geo%volume, 2.0_dp, 1.0e-14_dp, 'box volume 2 x 1 x 1')
    ! A linear displacement field du = G x gives the constant strain sym(G) at every point,
    ! also on a distorted element (patch test of the gradients), to round-off.
    x = distorted_element()
    call hex8_geometry(x, geo, ok)
    g = reshape([1.0e-3_dp, 2.0e-4_dp, -3.0e-4_dp, 5.0e-4_dp, -2.0e-3_dp, 1.0e-4_dp, &
                 7.0e-4_dp, 4.0e-4_dp, 1.5e-3_dp], [3, 3])
    do a = 1, 8
      du(:, a) = matmul(g, x(:, a))
    end do
    call hex8_strain_increments(geo, du, .false., strain, spin, eq, angle)
    do a = 1, 8
      call suite%close_array(strain(:, a), [g(1, 1), g(2, 2), g(3, 3), g(1, 2) + g(2, 1), &
                             g(1, 3) + g(3, 1), g(2, 3) + g(3, 2)], 1.0e-11_dp, 'constant strain at ip')
    end do
    call hex8_strain_increments(geo, du, .true., strain, spin, eq, angle)
    call suite%close_to(strain(1, 5), g(1, 1), 1.0e-11_dp, 'B-bar keeps a constant strain')
  end subroutine test_volume_and_gradients

  !> Internal force after moving the nodes by eps*v with the Hughes-Winget update of the
  !> stress on the mid configuration.
  function force_after(x, stress, c, v, eps, bbar) result(f)
    real(dp), intent(in) :: x(3, 8), stress(6, 8), c(6, 6), v(3, 8), eps
    logical, intent(in) :: bbar
    real(dp) :: f(24)
    type(hex8_geometry_t) :: geo
    real(dp) :: s(6, 8), strain(6, 8), spin(3, 3, 8), eq(8), angle(8)
    logical :: ok
    integer :: q
    call hex8_geometry(x + 0.5_dp * eps * v, geo, ok)
    call hex8_strain_increments(geo, eps * v, bbar, strain, spin, eq, angle)
    do q = 1, 8
      s(:, q) = hex8_rotate_stress(stress(:, q), spin(:, :, q)) + matmul(c, strain(:, q))
    end do
    call hex8_geometry(x + eps * v, geo, ok)
    call hex8_internal_force(geo, s, bbar, f)
  end function force_after

  subroutine test_tangent_finite_difference(suite, bbar)
    type(test_suite_t), intent(inout) :: suite
    logical, intent(in) :: bbar
    type(hex8_geometry_t) :: geo
    real(dp) :: x(3, 8), stress(6, 8), c(6, 6), cq(6, 6, 8), k(24, 24), v(3, 8), kv(24), fd(24)
    real(dp) :: eps
    logical :: ok
    integer :: q
    x = distorted_element()
    c = isotropic_elastic_matrix(100.0_dp, 0.3_dp)
    do q = 1, 8
      cq(:, :, q) = c
      stress(:, q) = [3.0_dp, -1.0_dp, 2.0_dp, 0.7_dp, -0.4_dp, 1.1_dp] * (1.0_dp + 0.1_dp * q)
    end do
    call random_number(v)
    v = v - 0.5_dp
    call hex8_geometry(x, geo, ok)
    call hex8_tangent(geo, stress, cq, bbar, .true., k)
    kv = matmul(k, reshape(v, [24]))
    eps = 1.0e-5_dp
    fd = (force_after(x, stress, c, v, eps, bbar) - force_after(x, stress, c, v, -eps, bbar)) / (2 * eps)
    ! Central differences: truncation error O(eps^2) ~ 1e-10 relative; tolerance 1e-7.
    call suite%close_array(kv, fd, 1.0e-7_dp, 'tangent = d f_int / d u (central differences), bbar=' // &
                           merge('T', 'F', bbar))
    ! Without the initial-stress terms the check must fail (the test can fail).
    call hex8_tangent(geo, stress, cq, bbar, .false., k)
    kv = matmul(k, reshape(v, [24]))
    call suite%check(maxval(abs(kv - fd)) / maxval(abs(fd)) > 1.0e-4_dp, &
                     'material-only tangent differs from the finite differences')
  end subroutine test_tangent_finite_difference

  !> Hughes-Winget: rotating by 90 degrees in many steps swaps sxx and syy exactly (up to
  !> round-off), Mises unchanged.
  subroutine test_rigid_rotation(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: s(6), w(3, 3), dtheta, m0
    integer :: i, n
    s = [1.5_dp, 0.75_dp, 0.75_dp, 0.0_dp, 0.0_dp, 0.0_dp]
    m0 = mises_stress(s)
    n = 90
    dtheta = 2.0_dp * atan(1.0_dp) / n
    ! Q = (I - W/2)^-1 (I + W/2) rotates by 2 atan(w/2); pick w so that each step is dtheta.
    w = 0.0_dp
    w(2, 1) = 2.0_dp * tan(0.5_dp * dtheta)
    w(1, 2) = -w(2, 1)
    do i = 1, n
      s = hex8_rotate_stress(s, w)
    end do
    call suite%close_to(s(1), 0.75_dp, 1.0e-12_dp, 'sxx after 90 degrees')
    call suite%close_to(s(2), 1.5_dp, 1.0e-12_dp, 'syy after 90 degrees')
    call suite%close_to(s(4), 0.0_dp, 1.0e-12_dp, 'sxy after 90 degrees', floor=1.0_dp)
    call suite%close_to(mises_stress(s), m0, 1.0e-12_dp, 'Mises preserved')
  end subroutine test_rigid_rotation

  !> A trilinear field sampled at the Gauss points is extrapolated exactly to the nodes.
  subroutine test_extrapolation(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: ip(1, 8), nodes(1, 8), g
    integer :: i, j, k, q
    g = 1.0_dp / sqrt(3.0_dp)
    q = 0
    do k = -1, 1, 2
      do j = -1, 1, 2
        do i = -1, 1, 2
          q = q + 1
          ip(1, q) = field(g * [real(i, dp), real(j, dp), real(k, dp)])
        end do
      end do
    end do
    nodes = hex8_extrapolate(ip)
    do q = 1, 8
      call suite%close_to(nodes(1, q), field(HEX8_NODE_XI(:, q)), 1.0e-12_dp, 'extrapolated node value')
    end do
  end subroutine test_extrapolation

  pure real(dp) function field(xi)
    real(dp), intent(in) :: xi(3)
    field = 1.0_dp + 2.0_dp * xi(1) - xi(2) + 0.5_dp * xi(3) + 0.3_dp * xi(1) * xi(2) * xi(3)
  end function field

  !> Pressure on a flat face: total force = -p A n; load stiffness against finite differences.
  subroutine test_pressure(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: xf(3, 4), f(12), dfdx(12, 12), v(12), fp(12), fm(12), eps, total(3)
    integer :: a
    xf = reshape([0.0_dp, 0.0_dp, 1.0_dp, 2.0_dp, 0.0_dp, 1.0_dp, 2.0_dp, 3.0_dp, 1.0_dp, &
                  0.0_dp, 3.0_dp, 1.0_dp], [3, 4])
    call face_pressure_load(xf, 5.0_dp, f, dfdx)
    total = 0.0_dp
    do a = 1, 4
      total = total + f(3 * a - 2:3 * a)
    end do
    call suite%close_array(total, [0.0_dp, 0.0_dp, -30.0_dp], 1.0e-14_dp, 'pressure resultant -p A n')
    xf(3, 3) = 1.4_dp
    call face_pressure_load(xf, 5.0_dp, f, dfdx)
    call random_number(v)
    eps = 1.0e-6_dp
    call face_pressure_load(xf + eps * reshape(v, [3, 4]), 5.0_dp, fp)
    call face_pressure_load(xf - eps * reshape(v, [3, 4]), 5.0_dp, fm)
    call suite%close_array(matmul(dfdx, v), (fp - fm) / (2 * eps), 1.0e-8_dp, 'follower load stiffness')
  end subroutine test_pressure

end program test_fcs_hex8_element
