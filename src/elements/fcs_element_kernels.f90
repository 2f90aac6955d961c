!> The element kernels of any element kind: what the element loops (fcs_element_loops) compute
!> for one element - the shape-function gradients and volumes at its integration points, its
!> internal force and tangent, the strain and rotation increments of its points, the
!> extrapolation of point values to its nodes, its Jacobian checks and volume, and the
!> pressure load on one of its faces. Each procedure dispatches on the kind's `kernel`:
!> - KERNEL_HEX8 (C3D8): the hand-written kernels of the 8-node hexahedron (fcs_hex8_element,
!>   fcs_hex8_shape, fcs_hex8_face), so that a C3D8 model runs the same floating-point
!>   operations in the same order as before the element interface;
!> - KERNEL_TABLES (every other kind): the kind's tables (element_kind_t: natural derivatives
!>   at the points, weights, extrapolation matrix, face tables), for any number of nodes and
!>   points.
!>
!> The formulation is the updated Lagrangian rate form of doc/theory.md, section 1 (Xing, Mora
!> & Makinouchi 2003, eq. 1): B^T C B with the initial-stress terms of 1.2, the B-bar option of
!> 1.3 (Hughes 1980), Voigt order (11, 22, 33, 12, 13, 23) with engineering shear strains. The
!> table kernels follow the hexahedron kernels term by term; with the hexahedron's tables they
!> agree with them to round-off (tests/unit/test_fcs_element_loops.f90).
module fcs_element_kernels
  use fcs_kinds, only: dp
  use fcs_element_kind, only: element_kind_t, MAX_NODES, MAX_POINTS, KERNEL_HEX8
  use fcs_hex8_element, only: hex8_geometry_t, hex8_geometry, hex8_tangent, hex8_internal_force, &
                              hex8_strain_increments, hex8_extrapolate, voigt_to_tensor, &
                              point_strain_increment
  use fcs_hex8_shape, only: hex8_min_jacobian_ratio, hex8_jacobian, hex8_gauss_points, det3, &
                            N_GAUSS_HEX8
  use fcs_hex8_face, only: face_pressure_load, HEX8_FACE_LOCAL_NODES, cross, skew
  implicit none
  private
  public :: element_geometry_t, element_geometry, element_internal_force, element_tangent
  public :: element_strain_increments, element_point_volumes, element_extrapolate
  public :: element_min_jacobian_ratio, element_volume, element_face_nodes, element_face_pressure
  public :: element_face_area

  !> Nonzeros of the strain-displacement matrix B (as fcs_hex8_element): column (a, i) has
  !> dN_a/dx_B_GRADIENT(n, i) in row B_ROW(n, i), n = 1..3.
  integer, parameter :: B_ROW(3, 3) = reshape([1, 4, 5, 2, 4, 6, 3, 5, 6], [3, 3])
  integer, parameter :: B_GRADIENT(3, 3) = reshape([1, 2, 3, 2, 1, 3, 3, 1, 2], [3, 3])

  !> Gradients of the shape functions and volume weights at the integration points of one
  !> element: `hex8` for KERNEL_HEX8, the other components for KERNEL_TABLES.
  type :: element_geometry_t
    integer :: n_nodes = 0
    integer :: n_points = 0
    type(hex8_geometry_t) :: hex8
    !> grad(j, a, q) = dN_a/dx_j at point q; dv(q) = det J w_q; the element volume and mean
    !> gradient (1/V) sum_q grad dv (B-bar).
    real(dp) :: grad(3, MAX_NODES, MAX_POINTS)
    real(dp) :: dv(MAX_POINTS)
    real(dp) :: volume
    real(dp) :: mean_grad(3, MAX_NODES)
  end type element_geometry_t

contains

  !> Shape-function gradients on configuration x(3, n_nodes). `ok` is false if det J <= 0 at
  !> an integration point.
  pure subroutine element_geometry(kind, x, geo, ok)
    type(element_kind_t), intent(in) :: kind
    real(dp), intent(in) :: x(:, :)
    type(element_geometry_t), intent(out) :: geo
    logical, intent(out) :: ok
    real(dp) :: det
    integer :: q, n
    n = kind%n_nodes
    geo%n_nodes = n
    geo%n_points = kind%n_points
    if (kind%kernel == KERNEL_HEX8) then
      call hex8_geometry(x(:, 1:8), geo%hex8, ok)
      return
    end if
    ok = .true.
    geo%volume = 0.0_dp
    geo%mean_grad(:, 1:n) = 0.0_dp
    do q = 1, kind%n_points
      call kind%point_gradients(q, x(:, 1:n), geo%grad(:, 1:n, q), det)
      if (det <= 0.0_dp) then
        ok = .false.
        return
      end if
      geo%dv(q) = det * kind%weight(q)
      geo%volume = geo%volume + geo%dv(q)
      geo%mean_grad(:, 1:n) = geo%mean_grad(:, 1:n) + geo%grad(:, 1:n, q) * geo%dv(q)
    end do
    geo%mean_grad(:, 1:n) = geo%mean_grad(:, 1:n) / geo%volume
  end subroutine element_geometry

  !> The volume each integration point represents, dv(q) = det J w_q.
  pure function element_point_volumes(kind, geo) result(dv)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp) :: dv(kind%n_points)
    if (kind%kernel == KERNEL_HEX8) then
      dv = geo%hex8%dv
    else
      dv = geo%dv(1:kind%n_points)
    end if
  end function element_point_volumes

  !> Internal force f = sum_q Bbar^T sigma dv (3 n_nodes values, node-major) from the stresses
  !> stress(6, q) at the points.
  pure subroutine element_internal_force(kind, geo, stress, bbar, f)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: stress(:, :)
    logical, intent(in) :: bbar
    real(dp), intent(out) :: f(:)
    real(dp) :: force(3, MAX_NODES), s(6)
    integer :: q, i, m, n
    if (kind%kernel == KERNEL_HEX8) then
      call hex8_internal_force(geo%hex8, stress(:, 1:8), bbar, f(1:24))
      return
    end if
    n = kind%n_nodes
    force(:, 1:n) = 0.0_dp
    do q = 1, kind%n_points
      s = stress(:, q) * geo%dv(q)
      do i = 1, 3
        do m = 1, 3
          force(i, 1:n) = force(i, 1:n) + s(B_ROW(m, i)) * geo%grad(B_GRADIENT(m, i), 1:n, q)
        end do
      end do
      if (bbar) force(:, 1:n) = force(:, 1:n) + (s(1) + s(2) + s(3)) * &
                                (geo%mean_grad(:, 1:n) - geo%grad(:, 1:n, q)) / 3.0_dp
    end do
    f(1:3 * n) = reshape(force(:, 1:n), [3 * n])
  end subroutine element_internal_force

  !> Tangent stiffness k(3 n, 3 n) (node-major) on the configuration of `geo`: the material
  !> part Bbar^T C Bbar dv with the material tangents c(:, :, q) and, with NLGEOM, the
  !> initial-stress part and the volume-change term sigma tr(D) (doc/theory.md 1.2), plus the
  !> geometric derivative of the B-bar correction (1.3).
  pure subroutine element_tangent(kind, geo, stress, c, bbar, nlgeom, k)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: stress(:, :), c(:, :, :)
    logical, intent(in) :: bbar, nlgeom
    real(dp), intent(out) :: k(:, :)
    integer :: q, n
    if (kind%kernel == KERNEL_HEX8) then
      call hex8_tangent(geo%hex8, stress(:, 1:8), c(:, :, 1:8), bbar, nlgeom, k(1:24, 1:24))
      return
    end if
    n = kind%n_nodes
    k(1:3 * n, 1:3 * n) = 0.0_dp
    do q = 1, kind%n_points
      call add_material_part(geo, q, n, c(:, :, q) * geo%dv(q), bbar, k(1:3 * n, 1:3 * n))
      if (nlgeom) call add_initial_stress_part(geo%grad(:, 1:n, q), stress(:, q) * geo%dv(q), &
                                               k(1:3 * n, 1:3 * n))
    end do
    if (nlgeom .and. bbar) call add_bbar_geometric_part(geo, kind%n_points, n, stress, &
                                                        k(1:3 * n, 1:3 * n))
  end subroutine element_tangent

  !> The strain-displacement matrix of point q, b(6, 3 n) (node-major columns, engineering
  !> shear), with the B-bar correction of the volumetric rows when `bbar`.
  pure function b_matrix(geo, q, n, bbar) result(b)
    type(element_geometry_t), intent(in) :: geo
    integer, intent(in) :: q, n
    logical, intent(in) :: bbar
    real(dp) :: b(6, 3 * n)
    integer :: a, i, m
    b = 0.0_dp
    do a = 1, n
      do i = 1, 3
        do m = 1, 3
          b(B_ROW(m, i), 3 * (a - 1) + i) = geo%grad(B_GRADIENT(m, i), a, q)
        end do
        if (bbar) b(1:3, 3 * (a - 1) + i) = b(1:3, 3 * (a - 1) + i) + &
                                            (geo%mean_grad(i, a) - geo%grad(i, a, q)) / 3.0_dp
      end do
    end do
  end function b_matrix

  !> B^T (C dv) B of point q added to k.
  pure subroutine add_material_part(geo, q, n, c_dv, bbar, k)
    type(element_geometry_t), intent(in) :: geo
    integer, intent(in) :: q, n
    real(dp), intent(in) :: c_dv(6, 6)
    logical, intent(in) :: bbar
    real(dp), intent(inout) :: k(:, :)
    real(dp) :: b(6, 3 * n)
    b = b_matrix(geo, q, n, bbar)
    k = k + matmul(transpose(b), matmul(c_dv, b))
  end subroutine add_material_part

  !> Initial-stress terms of one point, as add_initial_stress of fcs_hex8_element (its doc
  !> comment derives them): for nodes a (test) and b (trial), with s = sigma dv, g_a = grad N_a,
  !>   K_ab(i,m) += 1/2 delta_im (g_a.s.g_b) - 1/2 g_b,i (s g_a)_m - 1/2 s_im (g_a.g_b)
  !>              - 1/2 (s g_b)_i g_a,m + (s g_a)_i g_b,m.
  pure subroutine add_initial_stress_part(grad, s_dv, k)
    real(dp), intent(in) :: grad(:, :), s_dv(6)
    real(dp), intent(inout) :: k(:, :)
    real(dp) :: s(3, 3), sg(3, size(grad, 2)), block(3, 3), gg
    integer :: a, b, i, m
    s = voigt_to_tensor(s_dv)
    sg = matmul(s, grad)
    do b = 1, size(grad, 2)
      do a = 1, size(grad, 2)
        gg = dot_product(grad(:, a), grad(:, b))
        do m = 1, 3
          do i = 1, 3
            block(i, m) = -0.5_dp * grad(i, b) * sg(m, a) - 0.5_dp * s(i, m) * gg - &
                          0.5_dp * sg(i, b) * grad(m, a) + sg(i, a) * grad(m, b)
          end do
          block(m, m) = block(m, m) + 0.5_dp * dot_product(grad(:, a), sg(:, b))
        end do
        k(3 * a - 2:3 * a, 3 * b - 2:3 * b) = k(3 * a - 2:3 * a, 3 * b - 2:3 * b) + block
      end do
    end do
  end subroutine add_initial_stress_part

  !> Geometric derivative of the B-bar correction of the internal force, as add_bbar_geometric
  !> of fcs_hex8_element: with w_q = tr(sigma_q) dv_q - (sum_r tr(sigma_r) dv_r) dv_q / V,
  !> u_b = sum_q w_q g_bq and Z_ab(j,m) = sum_q w_q g_aj g_bm,
  !>   K_ab(j,m) += 1/3 [gbar_aj u_bm + Z_ab(m,j) - Z_ab(j,m)].
  pure subroutine add_bbar_geometric_part(geo, n_points, n, stress, k)
    type(element_geometry_t), intent(in) :: geo
    integer, intent(in) :: n_points, n
    real(dp), intent(in) :: stress(:, :)
    real(dp), intent(inout) :: k(:, :)
    real(dp) :: w(n_points), u(3, n), z(3, 3), block(3, 3)
    integer :: a, b, q, m
    w = (stress(1, 1:n_points) + stress(2, 1:n_points) + stress(3, 1:n_points)) * geo%dv(1:n_points)
    w = w - sum(w) * geo%dv(1:n_points) / geo%volume
    u = 0.0_dp
    do q = 1, n_points
      u = u + w(q) * geo%grad(:, 1:n, q)
    end do
    do b = 1, n
      do a = 1, n
        z = 0.0_dp
        do q = 1, n_points
          do m = 1, 3
            z(:, m) = z(:, m) + w(q) * geo%grad(:, a, q) * geo%grad(m, b, q)
          end do
        end do
        do m = 1, 3
          block(:, m) = geo%mean_grad(:, a) * u(m, b)
        end do
        block = block + transpose(z) - z
        k(3 * a - 2:3 * a, 3 * b - 2:3 * b) = k(3 * a - 2:3 * a, 3 * b - 2:3 * b) + block / 3.0_dp
      end do
    end do
  end subroutine add_bbar_geometric_part

  !> Strain increment (Voigt, engineering shear), spin increment (skew), equivalent strain and
  !> rotation angle at each point for nodal displacement increments du(3, n_nodes), gradients
  !> from `geo` (the mid-increment configuration for the update, Hughes & Winget 1980).
  pure subroutine element_strain_increments(kind, geo, du, bbar, strain, spin, equivalent, angle)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: du(:, :)
    logical, intent(in) :: bbar
    real(dp), intent(out) :: strain(:, :), spin(:, :, :), equivalent(:), angle(:)
    real(dp) :: mean_volumetric
    integer :: q, i, n
    if (kind%kernel == KERNEL_HEX8) then
      call hex8_strain_increments(geo%hex8, du(:, 1:8), bbar, strain(:, 1:8), spin(:, :, 1:8), &
                                  equivalent(1:8), angle(1:8))
      return
    end if
    n = kind%n_nodes
    mean_volumetric = 0.0_dp
    if (bbar) then
      do i = 1, 3
        mean_volumetric = mean_volumetric + sum(du(i, 1:n) * geo%mean_grad(i, 1:n))
      end do
    end if
    do q = 1, kind%n_points
      call point_strain_increment(matmul(du(:, 1:n), transpose(geo%grad(:, 1:n, q))), bbar, &
                                  mean_volumetric, strain(:, q), spin(:, :, q), equivalent(q), angle(q))
    end do
  end subroutine element_strain_increments

  !> Values at the element's nodes, node_values(:, 1:n_nodes), from values at its points,
  !> point_values(:, 1:n_points) (CalculiX's extrapolation; fcs_element_kind).
  pure subroutine element_extrapolate(kind, point_values, node_values)
    type(element_kind_t), intent(in) :: kind
    real(dp), intent(in) :: point_values(:, :)
    real(dp), intent(out) :: node_values(:, :)
    if (kind%kernel == KERNEL_HEX8) then
      node_values(:, 1:8) = hex8_extrapolate(point_values(:, 1:8))
    else
      call kind%extrapolate(point_values(:, 1:kind%n_points), node_values(:, 1:kind%n_nodes))
    end if
  end subroutine element_extrapolate

  !> Smallest det J at the integration points and nodes over the mean det J: <= 0 for an
  !> inverted or degenerate element.
  pure real(dp) function element_min_jacobian_ratio(kind, x) result(ratio)
    type(element_kind_t), intent(in) :: kind
    real(dp), intent(in) :: x(:, :)
    if (kind%kernel == KERNEL_HEX8) then
      ratio = hex8_min_jacobian_ratio(x(:, 1:8))
    else
      ratio = kind%min_jacobian_ratio(x(:, 1:kind%n_nodes))
    end if
  end function element_min_jacobian_ratio

  !> Volume sum_q det J w_q of the element by its rule.
  pure real(dp) function element_volume(kind, x) result(volume)
    type(element_kind_t), intent(in) :: kind
    real(dp), intent(in) :: x(:, :)
    real(dp) :: points(3, N_GAUSS_HEX8), weights(N_GAUSS_HEX8)
    integer :: q
    if (kind%kernel /= KERNEL_HEX8) then
      volume = kind%volume(x(:, 1:kind%n_nodes))
      return
    end if
    call hex8_gauss_points(points, weights)
    volume = 0.0_dp
    do q = 1, N_GAUSS_HEX8
      volume = volume + det3(hex8_jacobian(x(:, 1:8), points(:, q))) * weights(q)
    end do
  end function element_volume

  !> Local nodes of face f (S1..Sn) of the kind, corners first, ordered so that the area
  !> vector points out of the element (KERNEL_HEX8: fcs_hex8_face's HEX8_FACE_LOCAL_NODES,
  !> the same cycles as the kind's faces, starting at the lowest node).
  pure function element_face_nodes(kind, f) result(nodes)
    type(element_kind_t), intent(in) :: kind
    integer, intent(in) :: f
    integer, allocatable :: nodes(:)
    if (kind%kernel == KERNEL_HEX8) then
      nodes = HEX8_FACE_LOCAL_NODES(:, f)
    else
      nodes = kind%faces(f)%nodes(1:kind%faces(f)%n_nodes)
    end if
  end function element_face_nodes

  !> Nodal forces force(3 m) of pressure p on face f with nodal coordinates xf(3, m) (the
  !> face's nodes as element_face_nodes lists them; positive pressure pushes into the body)
  !> and, optionally, their derivative dfdx = d force / d xf of a follower pressure. The
  !> forces are f_k = -p sum_q M_k a(s_q) w_q with the area vector a = dx/ds x dx/dt of the
  !> face's rule (CalculiX's load rule; KERNEL_HEX8: face_pressure_load, 2x2 points).
  pure subroutine element_face_pressure(kind, f, xf, p, force, dfdx)
    type(element_kind_t), intent(in) :: kind
    integer, intent(in) :: f
    real(dp), intent(in) :: xf(:, :), p
    real(dp), intent(out) :: force(:)
    real(dp), intent(out), optional :: dfdx(:, :)
    real(dp) :: t(3, 2), a(3)
    integer :: q, k, b, m
    if (kind%kernel == KERNEL_HEX8) then
      if (present(dfdx)) then
        call face_pressure_load(xf(:, 1:4), p, force(1:12), dfdx(1:12, 1:12))
      else
        call face_pressure_load(xf(:, 1:4), p, force(1:12))
      end if
      return
    end if
    associate (face => kind%faces(f))
      m = face%n_nodes
      force(1:3 * m) = 0.0_dp
      if (present(dfdx)) dfdx(1:3 * m, 1:3 * m) = 0.0_dp
      do q = 1, face%n_points
        t = matmul(xf(:, 1:m), transpose(face%point_derivatives(:, 1:m, q)))
        a = cross(t(:, 1), t(:, 2))
        do k = 1, m
          force(3 * k - 2:3 * k) = force(3 * k - 2:3 * k) - p * face%point_values(k, q) * a * &
                                   face%weight(q)
        end do
        if (.not. present(dfdx)) cycle
        ! d a = dM_b/ds dx_b x t_2 + t_1 x dM_b/dt dx_b
        do b = 1, m
          do k = 1, m
            dfdx(3 * k - 2:3 * k, 3 * b - 2:3 * b) = dfdx(3 * k - 2:3 * k, 3 * b - 2:3 * b) - &
              p * face%point_values(k, q) * face%weight(q) * &
              (face%point_derivatives(2, b, q) * skew(t(:, 1)) - &
               face%point_derivatives(1, b, q) * skew(t(:, 2)))
          end do
        end do
      end do
    end associate
  end subroutine element_face_pressure

  !> Area of face f with nodal coordinates xf(3, m) (KERNEL_HEX8: half the cross product of
  !> the diagonals, exact for a plane quadrilateral; otherwise the face's rule).
  pure real(dp) function element_face_area(kind, f, xf) result(area)
    type(element_kind_t), intent(in) :: kind
    integer, intent(in) :: f
    real(dp), intent(in) :: xf(:, :)
    real(dp) :: t(3, 2)
    integer :: q, m
    if (kind%kernel == KERNEL_HEX8) then
      area = 0.5_dp * norm2(cross(xf(:, 3) - xf(:, 1), xf(:, 4) - xf(:, 2)))
      return
    end if
    area = 0.0_dp
    associate (face => kind%faces(f))
      m = face%n_nodes
      do q = 1, face%n_points
        t = matmul(xf(:, 1:m), transpose(face%point_derivatives(:, 1:m, q)))
        area = area + norm2(cross(t(:, 1), t(:, 2))) * face%weight(q)
      end do
    end associate
  end function element_face_area

end module fcs_element_kernels
