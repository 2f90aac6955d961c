!> Unit tests of the hexahedron kernel: patch-type checks of B, the tangent against finite
!> differences of the internal force with the objective stress update (the consistency of
!> eq. 1's initial-stress terms), the tangent and internal force against a direct evaluation
!> (dense B, the node-pair loops of the geometric terms), Hughes-Winget rotation,
!> extrapolation, pressure loads.
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
  call test_tangent_reference(suite)
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

  !> The tangent and internal force against a direct evaluation of the same equations
  !> (reference_tangent, reference_b_matrix): both sum the same products, in another order
  !> and grouping, so they agree to round-off (a few 1e-16 relative to the largest entry);
  !> 1e-12 leaves a wide margin and still catches any missing or misplaced term. Material
  !> tangents: symmetric (the half product), unsymmetric (the general product) and zero (the
  !> geometric terms alone); B-bar and NLGEOM on and off.
  subroutine test_tangent_reference(suite)
    type(test_suite_t), intent(inout) :: suite
    integer, parameter :: SYMMETRIC_C = 1, UNSYMMETRIC_C = 2, ZERO_C = 3
    character(len=*), parameter :: material(3) = [character(len=11) :: 'symmetric', &
                                                  'unsymmetric', 'zero']
    type(hex8_geometry_t) :: geo
    real(dp) :: x(3, 8), stress(6, 8), cq(6, 6, 8), k(24, 24), k_ref(24, 24), f(24), f_ref(24)
    real(dp) :: perturbation(6, 6)
    logical :: ok, bbar, nlgeom
    integer :: q, material_case, i
    character(len=40) :: label
    x = distorted_element()
    call hex8_geometry(x, geo, ok)
    do q = 1, 8
      stress(:, q) = [3.0_dp, -1.0_dp, 2.0_dp, 0.7_dp, -0.4_dp, 1.1_dp] * (1.0_dp + 0.1_dp * q)
      stress(mod(q, 3) + 1, q) = stress(mod(q, 3) + 1, q) - 0.3_dp * q
    end do
    do material_case = SYMMETRIC_C, ZERO_C
      do q = 1, 8
        cq(:, :, q) = isotropic_elastic_matrix(100.0_dp * (1.0_dp + 0.05_dp * q), 0.3_dp)
        if (material_case == UNSYMMETRIC_C) then
          call random_number(perturbation)
          cq(:, :, q) = cq(:, :, q) + 20.0_dp * (perturbation - 0.5_dp)
        else if (material_case == ZERO_C) then
          cq(:, :, q) = 0.0_dp
        end if
      end do
      do i = 0, 3
        bbar = i >= 2
        nlgeom = mod(i, 2) == 1
        if (material_case == ZERO_C .and. .not. nlgeom) cycle
        write (label, '(a,", bbar=",l1,", nlgeom=",l1)') trim(material(material_case)), bbar, nlgeom
        call hex8_tangent(geo, stress, cq, bbar, nlgeom, k)
        k_ref = reference_tangent(geo, stress, cq, bbar, nlgeom)
        call suite%close_array(reshape(k, [576]), reshape(k_ref, [576]), 1.0e-12_dp, &
                               'tangent = direct evaluation, C ' // trim(label))
        if (nlgeom) cycle
        if (material_case == SYMMETRIC_C) then
          call suite%check(all(k == transpose(k)), 'B^T C B exactly symmetric, C ' // trim(label))
        else if (material_case == UNSYMMETRIC_C) then
          call suite%check(maxval(abs(k - transpose(k))) > 1.0e-3_dp * maxval(abs(k)), &
                           'B^T C B unsymmetric, C ' // trim(label))
        end if
      end do
    end do
    do i = 0, 1
      bbar = i == 1
      call hex8_internal_force(geo, stress, bbar, f)
      f_ref = 0.0_dp
      do q = 1, 8
        f_ref = f_ref + matmul(stress(:, q), reference_b_matrix(geo, q, bbar)) * geo%dv(q)
      end do
      call suite%close_array(f, f_ref, 1.0e-12_dp, 'internal force = sum B^T sigma dv, bbar=' // &
                             merge('T', 'F', bbar))
    end do
  end subroutine test_tangent_reference

  !> Dense strain-displacement matrix B (6x24), B-bar (Hughes 1980) with `bbar`.
  function reference_b_matrix(geo, q, bbar) result(b)
    type(hex8_geometry_t), intent(in) :: geo
    integer, intent(in) :: q
    logical, intent(in) :: bbar
    real(dp) :: b(6, 24)
    real(dp) :: g(3), correction(3)
    integer :: a, c, i
    b = 0.0_dp
    do a = 1, 8
      c = 3 * (a - 1)
      g = geo%grad(:, a, q)
      b(1, c + 1) = g(1)
      b(2, c + 2) = g(2)
      b(3, c + 3) = g(3)
      b(4, c + 1) = g(2)
      b(4, c + 2) = g(1)
      b(5, c + 1) = g(3)
      b(5, c + 3) = g(1)
      b(6, c + 2) = g(3)
      b(6, c + 3) = g(2)
      if (bbar) then
        correction = (geo%mean_grad(:, a) - g) / 3.0_dp
        do i = 1, 3
          b(i, c + 1:c + 3) = b(i, c + 1:c + 3) + correction
        end do
      end if
    end do
  end function reference_b_matrix

  !> Tangent by direct evaluation: dense B^T C B dv, and with NLGEOM the initial-stress terms
  !> of eq. (1) (Xing, Mora & Makinouchi 2003) for each node pair and point,
  !>   K_ab(i,m) = 1/2 delta_im (g_a.s.g_b) - 1/2 g_b,i (s g_a)_m - 1/2 s_im (g_a.g_b)
  !>             - 1/2 (s g_b)_i g_a,m + (s g_a)_i g_b,m,
  !> plus, with B-bar, the geometric derivative of the B-bar correction (reference_bbar_block).
  function reference_tangent(geo, stress, c, bbar, nlgeom) result(k)
    type(hex8_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: stress(6, 8), c(6, 6, 8)
    logical, intent(in) :: bbar, nlgeom
    real(dp) :: k(24, 24)
    real(dp) :: b(6, 24), s(3, 3), sg(3, 8), block(3, 3), gsg, gg
    integer :: q, a, bn, i, m
    k = 0.0_dp
    do q = 1, 8
      b = reference_b_matrix(geo, q, bbar)
      k = k + matmul(transpose(b), matmul(c(:, :, q), b)) * geo%dv(q)
      if (.not. nlgeom) cycle
      s = reshape([stress(1, q), stress(4, q), stress(5, q), stress(4, q), stress(2, q), &
                   stress(6, q), stress(5, q), stress(6, q), stress(3, q)], [3, 3])
      sg = matmul(s, geo%grad(:, :, q))
      do bn = 1, 8
        do a = 1, 8
          gsg = dot_product(geo%grad(:, a, q), sg(:, bn))
          gg = dot_product(geo%grad(:, a, q), geo%grad(:, bn, q))
          do m = 1, 3
            do i = 1, 3
              block(i, m) = 0.5_dp * merge(gsg, 0.0_dp, i == m) &
                            - 0.5_dp * geo%grad(i, bn, q) * sg(m, a) - 0.5_dp * s(i, m) * gg &
                            - 0.5_dp * sg(i, bn) * geo%grad(m, a, q) + sg(i, a) * geo%grad(m, bn, q)
            end do
          end do
          k(3 * a - 2:3 * a, 3 * bn - 2:3 * bn) = k(3 * a - 2:3 * a, 3 * bn - 2:3 * bn) + &
                                                  block * geo%dv(q)
        end do
      end do
    end do
    if (.not. (nlgeom .and. bbar)) return
    do bn = 1, 8
      do a = 1, 8
        k(3 * a - 2:3 * a, 3 * bn - 2:3 * bn) = k(3 * a - 2:3 * a, 3 * bn - 2:3 * bn) + &
                                                reference_bbar_block(geo, stress, a, bn)
      end do
    end do
  end function reference_tangent

  !> Geometric derivative of the B-bar correction f_a += 1/3 sum_q tr(sigma_q) (gbar_a - g_aq)
  !> dv_q for nodes a, b: d(g_aj dv) = (g_aj g_bm - g_am g_bj) dv dx_bm and
  !> d gbar_aj = [(1/V) sum_r (g_aj g_bm - g_am g_bj) dv_r - gbar_aj gbar_bm] dx_bm.
  function reference_bbar_block(geo, stress, a, b) result(block)
    type(hex8_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: stress(6, 8)
    integer, intent(in) :: a, b
    real(dp) :: block(3, 3)
    real(dp) :: tr(8), total, mean_pair(3, 3)
    integer :: q, j, m
    tr = (stress(1, :) + stress(2, :) + stress(3, :)) * geo%dv
    total = sum(tr)
    mean_pair = 0.0_dp
    block = 0.0_dp
    do q = 1, 8
      do m = 1, 3
        do j = 1, 3
          mean_pair(j, m) = mean_pair(j, m) + (geo%grad(j, a, q) * geo%grad(m, b, q) - &
                            geo%grad(m, a, q) * geo%grad(j, b, q)) * geo%dv(q)
          block(j, m) = block(j, m) + tr(q) * (geo%mean_grad(j, a) * geo%grad(m, b, q) + &
                        geo%grad(m, a, q) * geo%grad(j, b, q) - &
                        geo%grad(j, a, q) * geo%grad(m, b, q))
        end do
      end do
    end do
    do m = 1, 3
      do j = 1, 3
        block(j, m) = block(j, m) + total * (mean_pair(j, m) / geo%volume - &
                      geo%mean_grad(j, a) * geo%mean_grad(m, b))
      end do
    end do
    block = block / 3.0_dp
  end function reference_bbar_block

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
