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
!>
!> Two formulations add to the table kernels (doc/theory.md, section 1.5):
!> - FORMULATION_HOURGLASS (C3D8R): one point carrying the exact mean gradient and volume of the
!>   trilinear hexahedron (Flanagan & Belytschko 1981, eqs. 15-16), plus the hourglass force
!>   and stiffness of CalculiX (hgforce.f, hgstiffness.f): f = E a Gamma Gamma^T u with the
!>   orthogonal hourglass vectors Gamma (FB 1981, appendix 2) - `element_hourglass_force`,
!>   `element_hourglass_stiffness`;
!> - FORMULATION_INCOMPATIBLE_MODES (C3D8I): three modes 1 - xi_m^2 whose gradients use the
!>   Jacobian at the element centre with Taylor's det J0 / det J factor (Taylor, Beresford &
!>   Wilson 1976), carried as three extra gradient columns 9..11 of the geometry; the tangent
!>   is condensed to the nodes (`element_tangent`), and `element_mode_correction` and
!>   `element_mode_residual` give the loops what they need to find the mode increments.
module fcs_element_kernels
  use fcs_kinds, only: dp
  use fcs_element_kind, only: element_kind_t, MAX_NODES, MAX_POINTS, KERNEL_HEX8, &
    FORMULATION_HOURGLASS, FORMULATION_INCOMPATIBLE_MODES, determinant3
  use fcs_element_basis, only: solve_linear_system
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
  public :: element_face_area, element_hourglass_force, element_hourglass_stiffness
  public :: element_hourglass_increment
  public :: element_mode_residual, element_mode_correction, MAX_MODES, HOURGLASS_SCALE
  public :: element_displacement_gradients

  !> Nonzeros of the strain-displacement matrix B (as fcs_hex8_element): column (a, i) has
  !> dN_a/dx_B_GRADIENT(n, i) in row B_ROW(n, i), n = 1..3.
  integer, parameter :: B_ROW(3, 3) = reshape([1, 4, 5, 2, 4, 6, 3, 5, 6], [3, 3])
  integer, parameter :: B_GRADIENT(3, 3) = reshape([1, 2, 3, 2, 1, 3, 3, 1, 2], [3, 3])

  !> Most incompatible modes of a kind (C3D8I: 3), each a displacement vector (3 unknowns).
  integer, parameter :: MAX_MODES = 3
  !> Gradient columns of the geometry: the nodes, then the incompatible modes.
  integer, parameter :: MAX_COLUMNS = MAX_NODES + MAX_MODES
  !> CalculiX's hourglass stiffness factor (shape8hr.f): a = HOURGLASS_SCALE sum_aj b_aj^2 / V
  !> with b_aj = int dN_a/dx_j dV; the hourglass stiffness is E a Gamma Gamma^T.
  real(dp), parameter :: HOURGLASS_SCALE = 0.0005_dp

  !> Gradients of the shape functions and volume weights at the integration points of one
  !> element: `hex8` for KERNEL_HEX8, the other components for KERNEL_TABLES.
  type :: element_geometry_t
    integer :: n_nodes = 0
    integer :: n_points = 0
    !> Gradient columns: n_nodes, plus the incompatible modes of C3D8I.
    integer :: n_columns = 0
    type(hex8_geometry_t) :: hex8
    !> grad(j, a, q) = dN_a/dx_j at point q (columns n_nodes + m: the gradient of mode m);
    !> dv(q) = det J w_q; the element volume and mean gradient (1/V) sum_q grad dv (B-bar).
    real(dp) :: grad(3, MAX_COLUMNS, MAX_POINTS)
    real(dp) :: dv(MAX_POINTS)
    real(dp) :: volume
    real(dp) :: mean_grad(3, MAX_COLUMNS)
    !> C3D8R: the orthogonal hourglass vectors hourglass(a, k) = Gamma_a^k and the factor a of
    !> the hourglass stiffness E a Gamma Gamma^T (CalculiX shape8hr.f).
    real(dp) :: hourglass(8, 4)
    real(dp) :: hourglass_factor = 0.0_dp
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
    geo%n_columns = n
    if (kind%kernel == KERNEL_HEX8) then
      call hex8_geometry(x(:, 1:8), geo%hex8, ok)
      return
    end if
    if (kind%formulation == FORMULATION_HOURGLASS) then
      call hourglass_geometry(kind, x(:, 1:n), geo, ok)
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
    if (kind%formulation == FORMULATION_INCOMPATIBLE_MODES) call mode_gradients(kind, x(:, 1:n), geo, ok)
  end subroutine element_geometry

  !> C3D8R (Flanagan & Belytschko 1981): the one point carries the exact volume V and mean
  !> gradient b_a / V, b_aj = int dN_a/dx_j dV (eqs. 15-16, integrated exactly by 2x2x2 Gauss
  !> points in the cofactor form b_aj = sum_p dN_a/dxi_i adj(J)_ij, which needs no inverse),
  !> and the hourglass vectors of appendix 2,
  !>   Gamma_a^k = h_a^k - (b_aj / V) sum_l x_jl h_l^k   (summed over j = 1..3)
  !> with h^k the base vectors eta zeta, xi zeta, xi eta, xi eta zeta at the nodes, orthogonal
  !> to every linear field: Gamma^T u = 0 for u = c + A x, so the hourglass force vanishes
  !> under rigid motions and homogeneous strains (the patch test). CalculiX's shape8hr.f
  !> resets Gamma to h inside its loop over j and so keeps only the j = 3 term; the two agree
  !> on parallelepipeds (where sum_l x_jl h_l^k = 0), not on distorted elements, where ccx's
  !> hourglass force is not orthogonal to homogeneous strains (doc/theory.md 1.5).
  !> Hourglass stiffness factor a = 0.0005 sum_aj b_aj^2 / V (shape8hr.f). ok: V > 0 (CalculiX
  !> checks the mean Jacobian V/8 only).
  pure subroutine hourglass_geometry(kind, x, geo, ok)
    type(element_kind_t), intent(in) :: kind
    real(dp), intent(in) :: x(:, :)
    type(element_geometry_t), intent(inout) :: geo
    logical, intent(out) :: ok
    real(dp) :: jac(3, 3), adj(3, 3), b(3, 8), xh(3, 4)
    integer :: p, a, j
    b = 0.0_dp
    geo%volume = 0.0_dp
    do p = 1, size(kind%mean_derivatives, 3)
      associate (dn => kind%mean_derivatives(:, :, p))
        jac = matmul(x(:, 1:8), transpose(dn))
        adj = adjugate3(jac)
        geo%volume = geo%volume + determinant3(jac)
        do a = 1, 8
          do j = 1, 3
            b(j, a) = b(j, a) + dot_product(dn(:, a), adj(:, j))
          end do
        end do
      end associate
    end do
    ok = geo%volume > 0.0_dp
    if (.not. ok) return
    geo%dv(1) = geo%volume
    geo%grad(:, 1:8, 1) = b / geo%volume
    geo%mean_grad(:, 1:8) = geo%grad(:, 1:8, 1)
    xh = matmul(x(:, 1:8), kind%hourglass_base)
    geo%hourglass = kind%hourglass_base - matmul(transpose(geo%grad(:, 1:8, 1)), xh)
    geo%hourglass_factor = HOURGLASS_SCALE * sum(b**2) / geo%volume
  end subroutine hourglass_geometry

  !> C3D8I: gradient columns n_nodes + m of the incompatible modes P_m = 1 - xi_m^2 at every
  !> point, with the Jacobian J0 at the element centre and Taylor's factor det J0 / det J(q)
  !> (Taylor, Beresford & Wilson 1976, IJNME 10, 1211-1219):
  !>   G_m(q) = (det J0 / det J(q)) J0^-T dP_m/dxi(q),
  !> so that sum_q G_m(q) dv_q = det J0 J0^-T sum_q dP_m/dxi(q) w_q = 0: the modes add nothing
  !> to a homogeneous strain, and the element passes the patch test on any hexahedron. CalculiX's
  !> shape8hu.f uses J0 without the factor; the two agree on parallelepipeds (constant det J).
  pure subroutine mode_gradients(kind, x, geo, ok)
    type(element_kind_t), intent(in) :: kind
    real(dp), intent(in) :: x(:, :)
    type(element_geometry_t), intent(inout) :: geo
    logical, intent(inout) :: ok
    real(dp) :: jac0(3, 3), inv0(3, 3), det0, det_q
    integer :: q, m, col, n
    n = kind%n_nodes
    jac0 = matmul(x(:, 1:n), transpose(kind%centre_derivatives(:, 1:n)))
    det0 = determinant3(jac0)
    if (det0 <= 0.0_dp) then
      ok = .false.
      return
    end if
    inv0 = adjugate3(jac0) / det0
    do m = 1, kind%n_modes
      col = n + m
      geo%mean_grad(:, col) = 0.0_dp
      do q = 1, kind%n_points
        det_q = geo%dv(q) / kind%weight(q)
        geo%grad(:, col, q) = (det0 / det_q) * matmul(kind%mode_derivatives(:, m, q), inv0)
        geo%mean_grad(:, col) = geo%mean_grad(:, col) + geo%grad(:, col, q) * geo%dv(q)
      end do
      geo%mean_grad(:, col) = geo%mean_grad(:, col) / geo%volume
    end do
    geo%n_columns = n + kind%n_modes
  end subroutine mode_gradients

  !> The adjugate adj(A) = det(A) A^-1 of a 3x3 matrix.
  pure function adjugate3(a) result(adj)
    real(dp), intent(in) :: a(3, 3)
    real(dp) :: adj(3, 3)
    adj(1, 1) = a(2, 2) * a(3, 3) - a(2, 3) * a(3, 2)
    adj(1, 2) = a(1, 3) * a(3, 2) - a(1, 2) * a(3, 3)
    adj(1, 3) = a(1, 2) * a(2, 3) - a(1, 3) * a(2, 2)
    adj(2, 1) = a(2, 3) * a(3, 1) - a(2, 1) * a(3, 3)
    adj(2, 2) = a(1, 1) * a(3, 3) - a(1, 3) * a(3, 1)
    adj(2, 3) = a(1, 3) * a(2, 1) - a(1, 1) * a(2, 3)
    adj(3, 1) = a(2, 1) * a(3, 2) - a(2, 2) * a(3, 1)
    adj(3, 2) = a(1, 2) * a(3, 1) - a(1, 1) * a(3, 2)
    adj(3, 3) = a(1, 1) * a(2, 2) - a(1, 2) * a(2, 1)
  end function adjugate3

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

  !> Displacement gradients h(:, :, q) = du/dX = sum_a u_a (x) grad N_a at the points, for nodal
  !> displacements u(3, n_nodes) and gradients of `geo` (on the configuration X they are taken
  !> from; the nodes only: C3D8I's modes are not included).
  pure function element_displacement_gradients(kind, geo, u) result(h)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: u(:, :)
    real(dp) :: h(3, 3, kind%n_points)
    integer :: q, n
    n = kind%n_nodes
    do q = 1, kind%n_points
      if (kind%kernel == KERNEL_HEX8) then
        h(:, :, q) = matmul(u(:, 1:8), transpose(geo%hex8%grad(:, 1:8, q)))
      else
        h(:, :, q) = matmul(u(:, 1:n), transpose(geo%grad(:, 1:n, q)))
      end if
    end do
  end function element_displacement_gradients

  !> Internal force f = sum_q Bbar^T sigma dv (3 n_nodes values, node-major) from the stresses
  !> stress(6, q) at the points.
  pure subroutine element_internal_force(kind, geo, stress, bbar, f)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: stress(:, :)
    logical, intent(in) :: bbar
    real(dp), intent(out) :: f(:)
    real(dp) :: force(3, MAX_NODES)
    integer :: n
    if (kind%kernel == KERNEL_HEX8) then
      call hex8_internal_force(geo%hex8, stress(:, 1:8), bbar, f(1:24))
      return
    end if
    n = kind%n_nodes
    call column_forces(geo, kind%n_points, 1, n, stress, bbar, force(:, 1:n))
    f(1:3 * n) = reshape(force(:, 1:n), [3 * n])
  end subroutine element_internal_force

  !> C3D8I: the generalised forces of the incompatible modes, residual(3 m - 2: 3 m) =
  !> sum_q Bbar_m(q)^T sigma(q) dv_q for mode m (zero when the modes are in equilibrium, which
  !> the element loops' update enforces; doc/theory.md 1.5). Empty for other kinds.
  pure subroutine element_mode_residual(kind, geo, stress, bbar, residual)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: stress(:, :)
    logical, intent(in) :: bbar
    real(dp), intent(out) :: residual(:)
    real(dp) :: force(3, MAX_MODES)
    integer :: n
    n = kind%n_nodes
    if (kind%n_modes == 0) return
    call column_forces(geo, kind%n_points, n + 1, n + kind%n_modes, stress, bbar, &
                       force(:, 1:kind%n_modes))
    residual(1:3 * kind%n_modes) = reshape(force(:, 1:kind%n_modes), [3 * kind%n_modes])
  end subroutine element_mode_residual

  !> force(:, c) = sum_q Bbar_c(q)^T sigma(q) dv_q for the gradient columns c = first..last.
  pure subroutine column_forces(geo, n_points, first, last, stress, bbar, force)
    type(element_geometry_t), intent(in) :: geo
    integer, intent(in) :: n_points, first, last
    real(dp), intent(in) :: stress(:, :)
    logical, intent(in) :: bbar
    real(dp), intent(out) :: force(:, :)
    real(dp) :: s(6)
    integer :: q, i, m
    force = 0.0_dp
    do q = 1, n_points
      s = stress(:, q) * geo%dv(q)
      do i = 1, 3
        do m = 1, 3
          force(i, :) = force(i, :) + s(B_ROW(m, i)) * geo%grad(B_GRADIENT(m, i), first:last, q)
        end do
      end do
      if (bbar) force = force + (s(1) + s(2) + s(3)) * &
                        (geo%mean_grad(:, first:last) - geo%grad(:, first:last, q)) / 3.0_dp
    end do
  end subroutine column_forces

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
    real(dp) :: full(3 * MAX_COLUMNS, 3 * MAX_COLUMNS)
    integer :: n, nc
    logical :: ok
    if (kind%kernel == KERNEL_HEX8) then
      call hex8_tangent(geo%hex8, stress(:, 1:8), c(:, :, 1:8), bbar, nlgeom, k(1:24, 1:24))
      return
    end if
    n = kind%n_nodes
    nc = geo%n_columns
    if (nc == n) then
      call column_tangent(geo, kind%n_points, n, stress, c, bbar, nlgeom, k(1:3 * n, 1:3 * n))
      return
    end if
    call column_tangent(geo, kind%n_points, nc, stress, c, bbar, nlgeom, full(1:3 * nc, 1:3 * nc))
    call condense_modes(full(1:3 * nc, 1:3 * nc), 3 * n, k(1:3 * n, 1:3 * n), ok)
  end subroutine element_tangent

  !> The tangent over the gradient columns 1..nc (nodes, then modes): material part, and with
  !> NLGEOM the initial-stress part and the B-bar geometric part.
  pure subroutine column_tangent(geo, n_points, nc, stress, c, bbar, nlgeom, k)
    type(element_geometry_t), intent(in) :: geo
    integer, intent(in) :: n_points, nc
    real(dp), intent(in) :: stress(:, :), c(:, :, :)
    logical, intent(in) :: bbar, nlgeom
    real(dp), intent(out) :: k(:, :)
    integer :: q
    k = 0.0_dp
    do q = 1, n_points
      call add_material_part(geo, q, nc, c(:, :, q) * geo%dv(q), bbar, k)
      if (nlgeom) call add_initial_stress_part(geo%grad(:, 1:nc, q), stress(:, q) * geo%dv(q), k)
    end do
    if (nlgeom .and. bbar) call add_bbar_geometric_part(geo, n_points, nc, stress, k)
  end subroutine column_tangent

  !> Static condensation of the mode unknowns (the rows and columns after the first nu):
  !> k = K_uu - K_ua K_aa^-1 K_au (Wilson et al. 1973). ok false (and k = K_uu) if K_aa is
  !> singular.
  pure subroutine condense_modes(full, nu, k, ok)
    real(dp), intent(in) :: full(:, :)
    integer, intent(in) :: nu
    real(dp), intent(out) :: k(:, :)
    logical, intent(out) :: ok
    real(dp) :: k_aa(size(full, 1) - nu, size(full, 1) - nu), k_au(size(full, 1) - nu, nu)
    integer :: nt
    nt = size(full, 1)
    k_aa = full(nu + 1:nt, nu + 1:nt)
    k_au = full(nu + 1:nt, 1:nu)
    call solve_linear_system(k_aa, k_au, ok)
    k = full(1:nu, 1:nu)
    if (ok) k = k - matmul(full(1:nu, nu + 1:nt), k_au)
  end subroutine condense_modes

  !> C3D8I: mode increments modes(:, m) = -K_aa^-1 (K_au du + residual) from the tangent over
  !> the nodes and modes of `geo` (stresses and material tangents c at the points): with
  !> residual = 0 the modes that go with nodal increments du in the condensed tangent, with
  !> du = 0 a Newton correction of modes whose generalised forces are `residual`. ok false
  !> if K_aa is singular.
  pure subroutine element_mode_correction(kind, geo, stress, c, bbar, nlgeom, du, residual, &
                                          modes, ok)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: stress(:, :), c(:, :, :), du(:, :), residual(:)
    logical, intent(in) :: bbar, nlgeom
    real(dp), intent(out) :: modes(:, :)
    logical, intent(out) :: ok
    real(dp) :: full(3 * MAX_COLUMNS, 3 * MAX_COLUMNS), rhs(3 * MAX_MODES, 1)
    real(dp) :: k_aa(3 * MAX_MODES, 3 * MAX_MODES)
    integer :: nu, nt, na
    nu = 3 * kind%n_nodes
    na = 3 * kind%n_modes
    nt = nu + na
    modes(:, 1:kind%n_modes) = 0.0_dp
    ok = kind%n_modes > 0 .and. geo%n_columns == kind%n_nodes + kind%n_modes
    if (.not. ok) return
    call column_tangent(geo, kind%n_points, geo%n_columns, stress, c, bbar, nlgeom, &
                        full(1:nt, 1:nt))
    rhs(1:na, 1) = -(matmul(full(nu + 1:nt, 1:nu), reshape(du(:, 1:kind%n_nodes), [nu])) + &
                     residual(1:na))
    k_aa(1:na, 1:na) = full(nu + 1:nt, nu + 1:nt)
    call solve_linear_system(k_aa(1:na, 1:na), rhs(1:na, :), ok)
    if (ok) modes(:, 1:kind%n_modes) = reshape(rhs(1:na, 1), [3, kind%n_modes])
  end subroutine element_mode_correction

  !> C3D8R: the increment of the generalised hourglass forces Q(i, k) = E a sum_b u_ib
  !> Gamma_b^k (CalculiX hgforce.f's hglf; Flanagan & Belytschko 1981, eqs. 56-62 with the
  !> stiffness of shape8hr.f) for nodal increments du(3, 8): dQ = E a du Gamma, E the Young's
  !> modulus. Summed over the increments (the element loops keep Q as state) it is CalculiX's
  !> E a u Gamma in small strain.
  pure function element_hourglass_increment(kind, geo, du, youngs) result(dq)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: du(:, :), youngs
    real(dp) :: dq(3, 4)
    dq = 0.0_dp
    if (kind%formulation /= FORMULATION_HOURGLASS) return
    dq = youngs * geo%hourglass_factor * matmul(du(:, 1:8), geo%hourglass)
  end function element_hourglass_increment

  !> C3D8R: the hourglass forces of the generalised hourglass forces q(3, 4) added to f
  !> (node-major): f_a = sum_k q(:, k) Gamma_a^k (CalculiX hgforce.f).
  pure subroutine element_hourglass_force(kind, geo, q, f)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: q(3, 4)
    real(dp), intent(inout) :: f(:)
    if (kind%formulation /= FORMULATION_HOURGLASS) return
    f(1:24) = f(1:24) + reshape(matmul(q, transpose(geo%hourglass)), [24])
  end subroutine element_hourglass_force

  !> C3D8R: the hourglass stiffness E a Gamma Gamma^T (x) I_3 added to k (CalculiX
  !> hgstiffness.f; the derivative of Gamma and a with the geometry is left out, as there).
  pure subroutine element_hourglass_stiffness(kind, geo, youngs, k)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: youngs
    real(dp), intent(inout) :: k(:, :)
    real(dp) :: coupling(8, 8)
    integer :: a, b, i
    if (kind%formulation /= FORMULATION_HOURGLASS) return
    coupling = youngs * geo%hourglass_factor * matmul(geo%hourglass, transpose(geo%hourglass))
    do b = 1, 8
      do a = 1, 8
        do i = 1, 3
          k(3 * a - 3 + i, 3 * b - 3 + i) = k(3 * a - 3 + i, 3 * b - 3 + i) + coupling(a, b)
        end do
      end do
    end do
  end subroutine element_hourglass_stiffness

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
  !> C3D8I: `modes(:, m)`, the increments of the incompatible modes, add their gradients
  !> (without them the modes are taken as zero).
  pure subroutine element_strain_increments(kind, geo, du, bbar, strain, spin, equivalent, angle, &
                                            modes)
    type(element_kind_t), intent(in) :: kind
    type(element_geometry_t), intent(in) :: geo
    real(dp), intent(in) :: du(:, :)
    logical, intent(in) :: bbar
    real(dp), intent(out) :: strain(:, :), spin(:, :, :), equivalent(:), angle(:)
    real(dp), intent(in), optional :: modes(:, :)
    real(dp) :: columns(3, MAX_COLUMNS)
    integer :: n
    if (present(modes) .and. kind%n_modes > 0 .and. kind%kernel /= KERNEL_HEX8) then
      n = geo%n_columns
      columns(:, 1:kind%n_nodes) = du(:, 1:kind%n_nodes)
      columns(:, kind%n_nodes + 1:n) = modes(:, 1:n - kind%n_nodes)
      call column_strain_increments(geo, kind%n_points, columns(:, 1:n), bbar, strain, spin, &
                                    equivalent, angle)
      return
    end if
    if (kind%kernel == KERNEL_HEX8) then
      call hex8_strain_increments(geo%hex8, du(:, 1:8), bbar, strain(:, 1:8), spin(:, :, 1:8), &
                                  equivalent(1:8), angle(1:8))
      return
    end if
    call column_strain_increments(geo, kind%n_points, du(:, 1:kind%n_nodes), bbar, strain, spin, &
                                  equivalent, angle)
  end subroutine element_strain_increments

  !> Strain increments from the increments du(3, n) of the first n gradient columns.
  pure subroutine column_strain_increments(geo, n_points, du, bbar, strain, spin, equivalent, angle)
    type(element_geometry_t), intent(in) :: geo
    integer, intent(in) :: n_points
    real(dp), intent(in) :: du(:, :)
    logical, intent(in) :: bbar
    real(dp), intent(out) :: strain(:, :), spin(:, :, :), equivalent(:), angle(:)
    real(dp) :: mean_volumetric
    integer :: q, i, n
    n = size(du, 2)
    mean_volumetric = 0.0_dp
    if (bbar) then
      do i = 1, 3
        mean_volumetric = mean_volumetric + sum(du(i, 1:n) * geo%mean_grad(i, 1:n))
      end do
    end if
    do q = 1, n_points
      call point_strain_increment(matmul(du(:, 1:n), transpose(geo%grad(:, 1:n, q))), bbar, &
                                  mean_volumetric, strain(:, q), spin(:, :, q), equivalent(q), angle(q))
    end do
  end subroutine column_strain_increments

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
