!> Unit tests of CalculiX's contact print frame (calculix_tangents): the global x axis
!> projected on the contact plane (the z axis for a normal along x), t2 = n x t1; the six
!> axis normals give the frames ccx 2.20 prints (measured by tests/integration/
!> contact_print_frame.sh), and a tilted normal an orthonormal, right-handed frame.
program test_fcs_contact_geometry
  use fcs_kinds, only: dp
  use fcs_test_assertions, only: test_suite_t
  use fcs_contact_geometry, only: calculix_tangents, cross3
  implicit none
  type(test_suite_t) :: suite
  real(dp), parameter :: X(3) = [1.0_dp, 0.0_dp, 0.0_dp], Y(3) = [0.0_dp, 1.0_dp, 0.0_dp], &
                         Z(3) = [0.0_dp, 0.0_dp, 1.0_dp]
  suite%name = 'contact_geometry'
  call check_axis(suite, X, Z, -Y, '+x')
  call check_axis(suite, -X, Z, Y, '-x')
  call check_axis(suite, Y, X, -Z, '+y')
  call check_axis(suite, -Y, X, Z, '-y')
  call check_axis(suite, Z, X, Y, '+z')
  call check_axis(suite, -Z, X, -Y, '-z')
  call check_tilted(suite)
  call suite%report()

contains

  !> The frame of an axis normal, exactly.
  subroutine check_axis(suite, normal, t1, t2, name)
    type(test_suite_t), intent(inout) :: suite
    real(dp), intent(in) :: normal(3), t1(3), t2(3)
    character(len=*), intent(in) :: name
    real(dp) :: t(3, 2)
    t = calculix_tangents(normal)
    call suite%close_array(t(:, 1), t1, 1.0e-15_dp, 'normal ' // name // ': t1')
    call suite%close_array(t(:, 2), t2, 1.0e-15_dp, 'normal ' // name // ': t2')
  end subroutine check_axis

  !> A tilted normal: t1 along x - (x.n) n, orthonormal frame with t1 x t2 = n; a normal
  !> 0.05 degree from x (inside CalculiX's 0.1 degree) takes z projected instead.
  subroutine check_tilted(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: n(3), t(3, 2), expected(3), angle
    n = [0.3_dp, -0.5_dp, 0.8_dp] / norm2([0.3_dp, -0.5_dp, 0.8_dp])
    t = calculix_tangents(n)
    expected = X - n(1) * n
    expected = expected / norm2(expected)
    call suite%close_array(t(:, 1), expected, 1.0e-14_dp, 'tilted: t1 along x - (x.n) n')
    call suite%close_to(dot_product(t(:, 1), t(:, 2)), 0.0_dp, 1.0e-14_dp, 'tilted: t1.t2', floor=1.0_dp)
    call suite%close_to(norm2(t(:, 2)), 1.0_dp, 1.0e-14_dp, 'tilted: |t2|')
    call suite%close_array(cross3(t(:, 1), t(:, 2)), n, 1.0e-14_dp, 'tilted: t1 x t2 = n')
    angle = 0.05_dp * acos(-1.0_dp) / 180.0_dp
    n = [cos(angle), sin(angle), 0.0_dp]
    t = calculix_tangents(n)
    call suite%close_array(t(:, 1), Z, 1.0e-14_dp, 'normal 0.05 degree from x: t1 = z')
  end subroutine check_tilted

end program test_fcs_contact_geometry
