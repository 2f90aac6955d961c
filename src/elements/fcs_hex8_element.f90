!> The 8-node hexahedron in the updated Lagrangian rate formulation (Xing, Mora & Makinouchi
!> 2003, eq. 1): tangent stiffness with the initial-stress terms, internal force, objective
!> stress update, and the strain and rotation increments the R-minimum strategy limits.
!>
!> Notation: x(3,8) nodal coordinates of the configuration the integrals are taken on,
!> g_a = grad N_a (dN_a/dx_j at a Gauss point), sigma the Cauchy stress, Voigt order
!> (11,22,33,12,13,23) with engineering shear strains. Without NLGEOM the reference
!> configuration is used throughout and the geometric terms and rotations are dropped (small
!> strain, linear geometry).
module fcs_hex8_element
  use fcs_kinds, only: dp
  use fcs_hex8_shape, only: hex8_shape, hex8_shape_derivatives, hex8_gauss_points, det3, &
                            inverse3, N_GAUSS_HEX8
  implicit none
  private
  public :: hex8_geometry_t, hex8_geometry, hex8_tangent, hex8_internal_force
  public :: hex8_strain_increments, hex8_rotate_stress, voigt_to_tensor, tensor_to_voigt
  public :: mises_stress, hex8_extrapolate, point_strain_increment

  !> Nonzeros of the strain-displacement matrix B (Voigt order 11,22,33,12,13,23, engineering
  !> shear): column (a, i) has dN_a/dx_B_GRADIENT(n,i) in row B_ROW(n,i), n = 1..3.
  integer, parameter :: B_ROW(3, 3) = reshape([1, 4, 5, 2, 4, 6, 3, 5, 6], [3, 3])
  integer, parameter :: B_GRADIENT(3, 3) = reshape([1, 2, 3, 2, 1, 3, 3, 1, 2], [3, 3])
  !> Index a + 8 (i - 1) (direction-major) of node a, direction i, in node-major order
  !> 3 (a - 1) + i.
  integer, parameter :: DIRECTION_MAJOR(24) = [1, 9, 17, 2, 10, 18, 3, 11, 19, 4, 12, 20, &
                                               5, 13, 21, 6, 14, 22, 7, 15, 23, 8, 16, 24]

  !> Gradients of the shape functions and volume weights at the 8 Gauss points.
  type :: hex8_geometry_t
    !> grad(j, a, q) = dN_a/dx_j at Gauss point q.
    real(dp) :: grad(3, 8, N_GAUSS_HEX8)
    !> det J times the Gauss weight: the volume each point represents.
    real(dp) :: dv(N_GAUSS_HEX8)
    !> Element volume and mean gradient (for B-bar): mean_grad(j,a) = (1/V) sum_q grad dv.
    real(dp) :: volume
    real(dp) :: mean_grad(3, 8)
  end type hex8_geometry_t

contains

  !> Shape-function gradients on configuration x. `ok` is false if det J <= 0 somewhere.
  pure subroutine hex8_geometry(x, geo, ok)
    real(dp), intent(in) :: x(3, 8)
    type(hex8_geometry_t), intent(out) :: geo
    logical, intent(out) :: ok
    real(dp) :: points(3, N_GAUSS_HEX8), weights(N_GAUSS_HEX8), dn(3, 8), jac(3, 3), jinv(3, 3)
    real(dp) :: det
    integer :: q, i, j
    call hex8_gauss_points(points, weights)
    ok = .true.
    geo%volume = 0.0_dp
    geo%mean_grad = 0.0_dp
    do q = 1, N_GAUSS_HEX8
      dn = hex8_shape_derivatives(points(:, q))
      do j = 1, 3
        do i = 1, 3
          jac(i, j) = sum(x(i, :) * dn(j, :))
        end do
      end do
      det = det3(jac)
      if (det <= 0.0_dp) then
        ok = .false.
        return
      end if
      jinv = inverse3(jac, det)
      ! dN/dx_j = sum_i dN/dxi_i dxi_i/dx_j
      do j = 1, 3
        geo%grad(j, :, q) = jinv(1, j) * dn(1, :) + jinv(2, j) * dn(2, :) + jinv(3, j) * dn(3, :)
      end do
      geo%dv(q) = det * weights(q)
      geo%volume = geo%volume + geo%dv(q)
      geo%mean_grad = geo%mean_grad + geo%grad(:, :, q) * geo%dv(q)
    end do
    geo%mean_grad = geo%mean_grad / geo%volume
  end subroutine hex8_geometry

  !> Material part of the tangent at one Gauss point, B^T C B dv, added to k_dir in
  !> direction-major order: k_dir(a, i, b, m), entry (a + 8 (i - 1), b + 8 (m - 1)) of the
  !> 24x24 matrix, couples direction i of node a with direction m of node b. g(a, j) =
  !> dN_a/dx_j. Column (a, i) of the strain-displacement matrix B has g(a, B_GRADIENT(n, i))
  !> in row B_ROW(n, i), n = 1..3 (Voigt order, engineering shear);
  !> with `bbar` the volumetric part is replaced by its element mean (Hughes 1980,
  !> "Generalization of selective integration procedures to anisotropic and nonlinear media",
  !> IJNME 15, 1413-1418): rows 1-3 of column (a, i) gain correction(a, i) =
  !> (gbar_ai - g_ai) / 3. Only these nonzeros are visited; with `symmetric` (C = C^T, so
  !> B^T C B is symmetric) only the direction blocks i <= m are formed.
  pure subroutine add_material_stiffness(g, correction, bbar, c_dv, symmetric, k_dir)
    real(dp), intent(in) :: g(8, 3), correction(8, 3), c_dv(6, 6)
    logical, intent(in) :: bbar, symmetric
    real(dp), intent(inout) :: k_dir(8, 3, 8, 3)
    real(dp) :: cb(8, 6, 3), volumetric
    integer :: r, b, i, m, n
    ! cb(b, r, m) = (C B dv)(r, column (b, m)).
    cb = 0.0_dp
    do m = 1, 3
      do r = 1, 6
        do n = 1, 3
          cb(:, r, m) = cb(:, r, m) + c_dv(r, B_ROW(n, m)) * g(:, B_GRADIENT(n, m))
        end do
        if (bbar) cb(:, r, m) = cb(:, r, m) + (c_dv(r, 1) + c_dv(r, 2) + c_dv(r, 3)) * &
                                correction(:, m)
      end do
    end do
    do m = 1, 3
      do b = 1, 8
        volumetric = cb(b, 1, m) + cb(b, 2, m) + cb(b, 3, m)
        do i = 1, merge(m, 3, symmetric)
          do n = 1, 3
            k_dir(:, i, b, m) = k_dir(:, i, b, m) + g(:, B_GRADIENT(n, i)) * cb(b, B_ROW(n, i), m)
          end do
          if (bbar) k_dir(:, i, b, m) = k_dir(:, i, b, m) + correction(:, i) * volumetric
        end do
      end do
    end do
  end subroutine add_material_stiffness

  !> Tangent stiffness (24x24) on the current configuration: material part B^T C B and, with
  !> NLGEOM, the initial-stress part of eq. (1) plus the volume-change term sigma tr(D).
  !> `c(:,:,q)` is the material tangent at Gauss point q, `stress(:,q)` the Cauchy stress.
  !> The material part is summed in direction-major order (add_material_stiffness); when
  !> every c(:,:,q) is symmetric, so is B^T C B, and only its upper direction blocks are
  !> formed, their upper triangle then mirrored; otherwise (unsymmetric, e.g. non-associated
  !> plastic tangents) all of it.
  pure subroutine hex8_tangent(geo, stress, c, bbar, nlgeom, k)
    type(hex8_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: stress(6, N_GAUSS_HEX8), c(6, 6, N_GAUSS_HEX8)
    logical, intent(in) :: bbar, nlgeom
    real(dp), intent(out) :: k(24, 24)
    real(dp) :: k_dir(24, 24)
    logical :: symmetric
    integer :: q, j
    symmetric = .true.
    do q = 1, N_GAUSS_HEX8
      symmetric = symmetric .and. all(c(:, :, q) == transpose(c(:, :, q)))
    end do
    k_dir = 0.0_dp
    do q = 1, N_GAUSS_HEX8
      call add_material_stiffness(transpose(geo%grad(:, :, q)), &
                                  transpose(geo%mean_grad - geo%grad(:, :, q)) / 3.0_dp, bbar, &
                                  c(:, :, q) * geo%dv(q), symmetric, k_dir)
    end do
    if (symmetric) then
      do j = 1, 23
        k_dir(j + 1:24, j) = k_dir(j, j + 1:24)
      end do
    end if
    k = k_dir(DIRECTION_MAJOR, DIRECTION_MAJOR)
    if (nlgeom) call add_initial_stress(geo, stress, k)
    if (nlgeom .and. bbar) call add_bbar_geometric(geo, stress, k)
  end subroutine hex8_tangent

  !> Geometric derivative of the B-bar correction of the internal force,
  !> f_a += 1/3 sum_q tr(sigma_q) (gbar_a - g_aq) dv_q, at fixed stress (its dependence on
  !> the stress is in Bbar^T C Bbar). With d(g_aj dv) = (g_aj g_bm - g_am g_bj) dv dx_bm and
  !> d gbar_aj = [(1/V) sum_r (g_aj g_bm - g_am g_bj) dv_r - gbar_aj gbar_bm] dx_bm.
  !> Summed over the points, with w_q = tr(sigma_q) dv_q - (sum_r tr(sigma_r) dv_r) dv_q / V,
  !> u_b = sum_q w_q g_bq and Z_ab(j,m) = sum_q w_q g_aj g_bm (one 24x8 by 8x24 product):
  !>   K_ab(j,m) += 1/3 [gbar_aj u_bm + Z_ab(m,j) - Z_ab(j,m)].
  pure subroutine add_bbar_geometric(geo, stress, k)
    type(hex8_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: stress(6, N_GAUSS_HEX8)
    real(dp), intent(inout) :: k(24, 24)
    real(dp) :: w(N_GAUSS_HEX8), g(24, N_GAUSS_HEX8), z(24, 24), u(24), mean(24), block(3, 3)
    integer :: a, b, m, ra, rb
    w = (stress(1, :) + stress(2, :) + stress(3, :)) * geo%dv
    w = w - sum(w) * geo%dv / geo%volume
    g = reshape(geo%grad, [24, N_GAUSS_HEX8])
    u = matmul(g, w)
    z = matmul(g * spread(w, 1, 24), transpose(g))
    mean = reshape(geo%mean_grad, [24])
    do b = 1, 8
      rb = 3 * b - 2
      do a = 1, 8
        ra = 3 * a - 2
        do m = 1, 3
          block(:, m) = mean(ra:ra + 2) * u(rb + m - 1)
        end do
        block = block + transpose(z(ra:ra + 2, rb:rb + 2)) - z(ra:ra + 2, rb:rb + 2)
        k(ra:ra + 2, rb:rb + 2) = k(ra:ra + 2, rb:rb + 2) + block / 3.0_dp
      end do
    end do
  end subroutine add_bbar_geometric

  !> Initial-stress (geometric) stiffness from the rate form of the virtual work on the
  !> current configuration. With L = grad v, D = sym L, the stress terms of the integrand
  !> contracted with delta L are  L sigma - D sigma - sigma D + sigma tr(D)  (the terms of
  !> eq. (1) of Xing, Mora & Makinouchi 2003, transposed to the convention delta L_ij =
  !> d(delta v_i)/dx_j, plus sigma tr(D), which makes the tangent the exact linearisation of
  !> equilibrium for a Cauchy-stress Jaumann law). For nodes a (test) and b (trial):
  !>   K_ab(i,m) = 1/2 delta_im (g_a.s.g_b) - 1/2 g_b,i (s g_a)_m - 1/2 s_im (g_a.g_b)
  !>             - 1/2 (s g_b)_i g_a,m + (s g_a)_i g_b,m
  !> Summed over the Gauss points (stresses s_q, volumes dv_q) with
  !> M_ab(i,m) = sum_q (s_q g_a)_i g_b,m dv_q (one 24x8 by 8x24 product) and
  !> R_ab = sum_q s_q (g_a.g_b) dv_q (one 64x8 by 8x6 product, in Voigt order):
  !>   K_ab = 1/2 tr(M_ba) I - 1/2 M_ab^T - 1/2 R_ab - 1/2 M_ba + M_ab  (term by term).
  pure subroutine add_initial_stress(geo, stress, k)
    type(hex8_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: stress(6, N_GAUSS_HEX8)
    real(dp), intent(inout) :: k(24, 24)
    real(dp) :: sg(24, N_GAUSS_HEX8), gg(64, N_GAUSS_HEX8), weights(N_GAUSS_HEX8, 6)
    real(dp) :: m(24, 24), r(64, 6), block(3, 3), trace
    integer :: q, a, b, i, ra, rb
    do q = 1, N_GAUSS_HEX8
      sg(:, q) = reshape(matmul(voigt_to_tensor(stress(:, q)), geo%grad(:, :, q)), [24]) * geo%dv(q)
      gg(:, q) = reshape(matmul(transpose(geo%grad(:, :, q)), geo%grad(:, :, q)), [64])
      weights(q, :) = stress(:, q) * geo%dv(q)
    end do
    m = matmul(sg, transpose(reshape(geo%grad, [24, N_GAUSS_HEX8])))
    r = matmul(gg, weights)
    do b = 1, 8
      rb = 3 * b - 2
      do a = 1, 8
        ra = 3 * a - 2
        trace = m(rb, ra) + m(rb + 1, ra + 1) + m(rb + 2, ra + 2)
        block = m(ra:ra + 2, rb:rb + 2) - 0.5_dp * (transpose(m(ra:ra + 2, rb:rb + 2)) + &
                m(rb:rb + 2, ra:ra + 2) + voigt_to_tensor(r(a + 8 * (b - 1), :)))
        do i = 1, 3
          block(i, i) = block(i, i) + 0.5_dp * trace
        end do
        k(ra:ra + 2, rb:rb + 2) = k(ra:ra + 2, rb:rb + 2) + block
      end do
    end do
  end subroutine add_initial_stress

  !> Internal force f_a = sum_q Bbar^T sigma dv (24 values, node-major), with the nonzeros of
  !> B as in add_material_stiffness.
  pure subroutine hex8_internal_force(geo, stress, bbar, f)
    type(hex8_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: stress(6, N_GAUSS_HEX8)
    logical, intent(in) :: bbar
    real(dp), intent(out) :: f(24)
    real(dp) :: force(3, 8), s(6)
    integer :: q, i, n
    force = 0.0_dp
    do q = 1, N_GAUSS_HEX8
      s = stress(:, q) * geo%dv(q)
      do i = 1, 3
        do n = 1, 3
          force(i, :) = force(i, :) + s(B_ROW(n, i)) * geo%grad(B_GRADIENT(n, i), :, q)
        end do
      end do
      if (bbar) force = force + (s(1) + s(2) + s(3)) * (geo%mean_grad - geo%grad(:, :, q)) / 3.0_dp
    end do
    f = reshape(force, [24])
  end subroutine hex8_internal_force

  !> Strain increment (Voigt, engineering shear), rotation increment (skew tensor) and the
  !> equivalent strain and rotation angle at each Gauss point, for displacement increment
  !> du(3,8) with gradients taken on `geo` (the mid-increment configuration for the update,
  !> Hughes & Winget 1980).
  pure subroutine hex8_strain_increments(geo, du, bbar, strain, spin, equivalent, angle)
    type(hex8_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: du(3, 8)
    logical, intent(in) :: bbar
    real(dp), intent(out) :: strain(6, N_GAUSS_HEX8), spin(3, 3, N_GAUSS_HEX8)
    real(dp), intent(out) :: equivalent(N_GAUSS_HEX8), angle(N_GAUSS_HEX8)
    real(dp) :: mean_volumetric
    integer :: q, i
    mean_volumetric = 0.0_dp
    if (bbar) then
      do i = 1, 3
        mean_volumetric = mean_volumetric + sum(du(i, :) * geo%mean_grad(i, :))
      end do
    end if
    do q = 1, N_GAUSS_HEX8
      call point_strain_increment(matmul(du, transpose(geo%grad(:, :, q))), bbar, mean_volumetric, &
                                  strain(:, q), spin(:, :, q), equivalent(q), angle(q))
    end do
  end subroutine hex8_strain_increments

  !> At one point with displacement-increment gradient h = d(du)/dx: the strain increment
  !> (Voigt, engineering shear; with B-bar its volumetric part replaced by the element mean
  !> `mean_volumetric`), the spin increment (skew part of h), the equivalent strain
  !> sqrt(2/3 e:e) and the rotation angle |w| (doc/theory.md 1.4 and 6.4).
  pure subroutine point_strain_increment(h, bbar, mean_volumetric, strain, spin, equivalent, angle)
    real(dp), intent(in) :: h(3, 3), mean_volumetric
    logical, intent(in) :: bbar
    real(dp), intent(out) :: strain(6), spin(3, 3), equivalent, angle
    real(dp) :: e(3, 3)
    integer :: i
    e = 0.5_dp * (h + transpose(h))
    spin = 0.5_dp * (h - transpose(h))
    if (bbar) then
      do i = 1, 3
        e(i, i) = e(i, i) + (mean_volumetric - (h(1, 1) + h(2, 2) + h(3, 3))) / 3.0_dp
      end do
    end if
    strain = [e(1, 1), e(2, 2), e(3, 3), 2.0_dp * e(1, 2), 2.0_dp * e(1, 3), 2.0_dp * e(2, 3)]
    equivalent = sqrt(2.0_dp / 3.0_dp * sum(e * e))
    angle = sqrt(0.5_dp * sum(spin**2))
  end subroutine point_strain_increment

  !> Rotate a stress objectively over an increment with spin increment w (skew):
  !> sigma <- Q sigma Q^T, Q = (I - w/2)^-1 (I + w/2) (Hughes & Winget 1980, IJNME 15, 1862),
  !> an exact rotation, so that |sigma| is preserved under rigid rotation.
  pure function hex8_rotate_stress(stress, w) result(rotated)
    real(dp), intent(in) :: stress(6), w(3, 3)
    real(dp) :: rotated(6)
    real(dp) :: a(3, 3), b(3, 3), q(3, 3), s(3, 3), a_inverse(3, 3)
    integer :: i
    a = -0.5_dp * w
    b = 0.5_dp * w
    do i = 1, 3
      a(i, i) = a(i, i) + 1.0_dp
      b(i, i) = b(i, i) + 1.0_dp
    end do
    a_inverse = inverse3(a, det3(a))
    q = matmul(a_inverse, b)
    s = voigt_to_tensor(stress)
    s = matmul(matmul(q, s), transpose(q))
    rotated = tensor_to_voigt(s)
  end function hex8_rotate_stress

  !> Values at the 8 nodes from values at the 8 Gauss points (ncomp, 8): the trilinear field
  !> through the Gauss-point values, evaluated at the nodes (natural coordinate +-sqrt(3) in
  !> the coordinates of the Gauss points).
  pure function hex8_extrapolate(ip_values) result(node_values)
    real(dp), intent(in) :: ip_values(:, :)
    real(dp) :: node_values(size(ip_values, 1), 8)
    real(dp) :: points(3, N_GAUSS_HEX8), weights(N_GAUSS_HEX8), weights_at_node(8)
    integer :: a
    call hex8_gauss_points(points, weights)
    do a = 1, 8
      ! Gauss point q sits at natural sign pattern sign(points(:,q)); node a at HEX8 corner a.
      weights_at_node = hex8_shape(sqrt(3.0_dp) * node_corner(a))
      node_values(:, a) = matmul(ip_values, weights_at_node(gauss_to_corner()))
    end do
  end function hex8_extrapolate

  !> Natural coordinates of hexahedron node a.
  pure function node_corner(a) result(xi)
    integer, intent(in) :: a
    real(dp) :: xi(3)
    real(dp), parameter :: corner(3, 8) = reshape([ &
      -1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, &
      -1.0_dp, 1.0_dp, -1.0_dp, -1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp, &
      1.0_dp, 1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp, 1.0_dp], [3, 8])
    xi = corner(:, a)
  end function node_corner

  !> For Gauss point q (xi fastest, then eta, zeta), the hexahedron corner with the same
  !> sign pattern: the shape function of that corner interpolates the Gauss-point values.
  pure function gauss_to_corner() result(corner)
    integer :: corner(N_GAUSS_HEX8)
    corner = [1, 2, 4, 3, 5, 6, 8, 7]
  end function gauss_to_corner

  !> Symmetric tensor from a Voigt stress (11,22,33,12,13,23).
  pure function voigt_to_tensor(v) result(t)
    real(dp), intent(in) :: v(6)
    real(dp) :: t(3, 3)
    t(1, 1) = v(1)
    t(2, 2) = v(2)
    t(3, 3) = v(3)
    t(1, 2) = v(4)
    t(2, 1) = v(4)
    t(1, 3) = v(5)
    t(3, 1) = v(5)
    t(2, 3) = v(6)
    t(3, 2) = v(6)
  end function voigt_to_tensor

  !> Voigt stress from a symmetric tensor.
  pure function tensor_to_voigt(t) result(v)
    real(dp), intent(in) :: t(3, 3)
    real(dp) :: v(6)
    v = [t(1, 1), t(2, 2), t(3, 3), 0.5_dp * (t(1, 2) + t(2, 1)), 0.5_dp * (t(1, 3) + t(3, 1)), &
         0.5_dp * (t(2, 3) + t(3, 2))]
  end function tensor_to_voigt

  !> von Mises equivalent stress sqrt(3/2 s':s').
  pure real(dp) function mises_stress(v)
    real(dp), intent(in) :: v(6)
    real(dp) :: p
    p = (v(1) + v(2) + v(3)) / 3.0_dp
    mises_stress = sqrt(1.5_dp * ((v(1) - p)**2 + (v(2) - p)**2 + (v(3) - p)**2 + &
                                  2.0_dp * (v(4)**2 + v(5)**2 + v(6)**2)))
  end function mises_stress

end module fcs_hex8_element
