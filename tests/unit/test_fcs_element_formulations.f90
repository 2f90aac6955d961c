!> Unit tests of every element kind through the element loops and kernels (fcs_element_loops,
!> fcs_element_kernels), C3D8R's hourglass control and C3D8I's incompatible modes included:
!> - patch tests on a distorted 3 x 3 x 3 patch of every kind (C3D4, C3D6, C3D8, C3D8R, C3D8I,
!>   C3D10, C3D15, C3D20, C3D20R; corners moved at random, straight edges): with a linear
!>   displacement on the boundary nodes, the interior nodes solved from the assembled tangent
!>   take the linear field, every point the stress C eps and the interior nodes no force, to
!>   round-off (Zienkiewicz & Taylor's test B); small strain with and without B-bar, and with
!>   NLGEOM on a pre-stressed patch (the tangent with its initial-stress terms);
!> - a rigid rotation of a pre-stressed patch of every kind under NLGEOM, in increments: the
!>   stress rotates with the body, sigma = R sigma_0 R^T (the Hughes-Winget update is exact
!>   for a rigid rotation), and the interior nodes stay force-free;
!> - C3D8R: CalculiX's hourglass stiffness on a cube (the closed form E a h.h), no hourglass
!>   force under homogeneous strain, f_int = K du for an element with hourglass modes; under
!>   NLGEOM an hourglass-deformed element turned rigidly keeps its hourglass forces, turned
!>   with it (f = R f_0; they are element state, rotated with the spin);
!> - on a distorted and a parallelepiped hexahedron, fcs3d's hourglass vectors and mode
!>   gradients against CalculiX's variants (which agree only on the parallelepiped);
!> - C3D8I: pure bending of a rectangular element (nu = 0) is exact - strain energy
!>   E kappa^2 I L / 2 and sigma_xx = E kappa z at every point after the update, where C3D8
!>   locks - and f_int = K du on a distorted element (condensed tangent and mode solve agree).
program test_fcs_element_formulations
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t
  use fcs_element_kind, only: element_kind_t, TOPOLOGY_HEXAHEDRON, TOPOLOGY_TETRAHEDRON, &
    TOPOLOGY_WEDGE, determinant3
  use fcs_element_catalogue, only: element_catalogue_t, ELEMENT_KIND_NAMES
  use fcs_element_kernels, only: element_geometry_t, element_geometry, element_hourglass_force, &
    element_hourglass_stiffness, element_hourglass_increment, HOURGLASS_SCALE
  use fcs_element_loops, only: element_loops_t, mesh_kinds
  use fcs_element_state, only: element_state_t
  use fcs_element_basis, only: solve_linear_system
  use fcs_mesh, only: mesh_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_material, only: material_slot_t, isotropic_elastic_matrix
  use fcs_material_factory, only: create_material, plastic_def_t
  use fcs_test_assertions, only: test_suite_t
  implicit none

  !> Round-off of the patch's sums and of a dense solve of a few hundred unknowns with
  !> condition numbers of about 1e3 (distorted elements).
  real(dp), parameter :: ROUND_OFF = 1.0e-10_dp
  real(dp), parameter :: YOUNGS = 1000.0_dp, POISSON = 0.3_dp
  !> Cells of the patch per direction, and the largest random move of a corner [cell sizes].
  integer, parameter :: CELLS = 3
  real(dp), parameter :: MOVE = 0.12_dp
  !> Homogeneous displacement gradients: the patch test's field and the pre-stress.
  real(dp), parameter :: H_PATCH(3, 3) = reshape([1.0e-3_dp, 2.0e-4_dp, -1.0e-4_dp, 3.0e-4_dp, &
    -5.0e-4_dp, 2.5e-4_dp, -2.0e-4_dp, 4.0e-4_dp, 7.0e-4_dp], [3, 3])
  real(dp), parameter :: H_PRE(3, 3) = reshape([2.0e-3_dp, 5.0e-4_dp, 0.0_dp, 5.0e-4_dp, &
    -1.0e-3_dp, 3.0e-4_dp, 0.0_dp, 3.0e-4_dp, 1.5e-3_dp], [3, 3])

  !> A patch: its mesh, which nodes are on its boundary, and the loops over it.
  type :: patch_t
    type(mesh_t) :: mesh
    logical, allocatable :: boundary(:)
    type(element_loops_t) :: loops
    type(element_state_t) :: fields
  end type patch_t

  type(test_suite_t) :: suite
  type(element_catalogue_t) :: catalogue
  type(error_t), allocatable :: err
  integer :: k

  suite%name = 'element_formulations'
  call random_seed(put=[(12345 + 7 * k, k = 1, 64)])
  call catalogue%init(err)
  call suite%check(.not. allocated(err), 'catalogue')
  if (allocated(err)) error stop 1
  do k = 1, size(ELEMENT_KIND_NAMES)
    call check_patch_small_strain(trim(ELEMENT_KIND_NAMES(k)), .false.)
    call check_patch_small_strain(trim(ELEMENT_KIND_NAMES(k)), .true.)
    call check_patch_nlgeom(trim(ELEMENT_KIND_NAMES(k)))
    call check_rigid_rotation(trim(ELEMENT_KIND_NAMES(k)))
  end do
  call check_hourglass_cube()
  call check_single_element_consistency('C3D8R')
  call check_single_element_consistency('C3D8I')
  call check_hourglass_rotation()
  call check_against_calculix_variants()
  call check_pure_bending()
  call suite%report()

contains

  !> A distorted CELLS^3 patch of `name` elements on [0, CELLS]^3: hexahedral cells, six
  !> tetrahedra (Kuhn's subdivision along the main diagonal) or two wedges per cell; every
  !> corner moved by up to MOVE at random; mid-side nodes at the midpoints of straight edges.
  subroutine build_patch(name, patch, bbar)
    character(len=*), intent(in) :: name
    type(patch_t), intent(out) :: patch
    logical, intent(in) :: bbar
    integer, parameter :: NG = CELLS + 1
    integer, parameter :: HEX(3, 8) = reshape([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, &
      1, 0, 1, 1, 1, 1, 0, 1, 1], [3, 8])
    integer, parameter :: PERMUTATIONS(3, 6) = reshape([1, 2, 3, 1, 3, 2, 2, 1, 3, 2, 3, 1, &
      3, 1, 2, 3, 2, 1], [3, 6])
    integer, parameter :: WEDGES(6, 2) = reshape([1, 2, 3, 5, 6, 7, 1, 3, 4, 5, 7, 8], [6, 2])
    type(material_slot_t), allocatable :: materials(:)
    type(plastic_def_t) :: elastic
    real(dp) :: x(3), noise(3)
    integer, allocatable :: corners(:, :), edge_node(:, :), connectivity(:)
    integer :: kind_index, i, j, l, c, p, e, a, n_grid, id, cell(8), v(3), tmp
    logical :: duplicate
    kind_index = catalogue%find(name)
    associate (kind => catalogue%kinds(kind_index))
      call patch%mesh%init(mesh_kinds(catalogue))
      n_grid = NG**3
      do l = 0, CELLS
        do j = 0, CELLS
          do i = 0, CELLS
            call random_number(noise)
            x = real([i, j, l], dp) + MOVE * (2.0_dp * noise - 1.0_dp)
            call patch%mesh%add_node(grid(i, j, l), x, duplicate)
          end do
        end do
      end do
      allocate (corners(kind%n_corners, 0))
      do l = 0, CELLS - 1
        do j = 0, CELLS - 1
          do i = 0, CELLS - 1
            do a = 1, 8
              cell(a) = grid(i + HEX(1, a), j + HEX(2, a), l + HEX(3, a))
            end do
            select case (kind%topology)
            case (TOPOLOGY_HEXAHEDRON)
              corners = reshape([corners, cell], [8, size(corners, 2) + 1])
            case (TOPOLOGY_TETRAHEDRON)
              do p = 1, 6
                v = 0
                connectivity = [cell(1)]
                do c = 1, 3
                  v(PERMUTATIONS(c, p)) = 1
                  connectivity = [connectivity, grid(i + v(1), j + v(2), l + v(3))]
                end do
                if (signed_volume(patch%mesh, connectivity) < 0.0_dp) then
                  tmp = connectivity(2)
                  connectivity(2) = connectivity(3)
                  connectivity(3) = tmp
                end if
                corners = reshape([corners, connectivity], [4, size(corners, 2) + 1])
              end do
            case (TOPOLOGY_WEDGE)
              do p = 1, 2
                corners = reshape([corners, cell(WEDGES(:, p))], [6, size(corners, 2) + 1])
              end do
            end select
          end do
        end do
      end do
      ! Mid-side nodes, one per edge, shared by the elements of the edge.
      allocate (edge_node(n_grid, n_grid))
      edge_node = 0
      id = n_grid
      do e = 1, size(corners, 2)
        connectivity = corners(:, e)
        do a = kind%n_corners + 1, kind%n_nodes
          associate (c1 => corners(kind%edge_corners(1, a), e), c2 => corners(kind%edge_corners(2, a), e))
            if (edge_node(c1, c2) == 0) then
              id = id + 1
              call patch%mesh%add_node(id, 0.5_dp * (patch%mesh%x(:, c1) + patch%mesh%x(:, c2)), &
                                       duplicate)
              edge_node(c1, c2) = id
              edge_node(c2, c1) = id
            end if
            connectivity = [connectivity, edge_node(c1, c2)]
          end associate
        end do
        call patch%mesh%add_element(e, connectivity, duplicate, kind_index)
      end do
      call patch%mesh%compact()
      ! Boundary nodes: grid corners on the outer planes, mid-side nodes between two corners on
      ! the same outer plane.
      allocate (patch%boundary(patch%mesh%n_nodes))
      do a = 1, n_grid
        patch%boundary(a) = on_boundary(a)
      end do
      do c = 1, n_grid
        do a = 1, n_grid
          if (edge_node(a, c) > 0) patch%boundary(edge_node(a, c)) = shared_plane(a, c)
        end do
      end do
    end associate
    allocate (materials(1))
    call create_material(YOUNGS, POISSON, elastic, materials(1)%m, err)
    call patch%loops%init(catalogue, patch%mesh, spread(1, 1, patch%mesh%n_elements), &
                          spread(bbar, 1, patch%mesh%n_elements), materials, err)
    call suite%check(.not. allocated(err), name // ': loops on the patch')
    call patch%fields%init(patch%loops%max_points, patch%mesh%n_elements, &
                           patch%loops%n_material_state())
  end subroutine build_patch

  !> Node number of grid point (i, j, l).
  pure integer function grid(i, j, l)
    integer, intent(in) :: i, j, l
    grid = 1 + i + (CELLS + 1) * (j + (CELLS + 1) * l)
  end function grid

  !> Grid coordinates of grid node a.
  pure function grid_index(a) result(ijl)
    integer, intent(in) :: a
    integer :: ijl(3)
    ijl = [mod(a - 1, CELLS + 1), mod((a - 1) / (CELLS + 1), CELLS + 1), (a - 1) / (CELLS + 1)**2]
  end function grid_index

  pure logical function on_boundary(a)
    integer, intent(in) :: a
    on_boundary = any(grid_index(a) == 0) .or. any(grid_index(a) == CELLS)
  end function on_boundary

  pure logical function shared_plane(a, c)
    integer, intent(in) :: a, c
    integer :: ia(3), ic(3)
    ia = grid_index(a)
    ic = grid_index(c)
    shared_plane = any(ia == ic .and. (ia == 0 .or. ia == CELLS))
  end function shared_plane

  !> Six times the signed volume of the tetrahedron of the first four nodes.
  real(dp) function signed_volume(mesh, nodes)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: nodes(:)
    real(dp) :: a(3), b(3), c(3)
    a = mesh%x(:, nodes(2)) - mesh%x(:, nodes(1))
    b = mesh%x(:, nodes(3)) - mesh%x(:, nodes(1))
    c = mesh%x(:, nodes(4)) - mesh%x(:, nodes(1))
    signed_volume = dot_product(a, [b(2) * c(3) - b(3) * c(2), b(3) * c(1) - b(1) * c(3), &
                                    b(1) * c(2) - b(2) * c(1)])
  end function signed_volume

  !> The tangent of the patch on coordinates x as a dense matrix, and the internal forces.
  subroutine dense_tangent(patch, x, nlgeom, k, f_int)
    type(patch_t), intent(in) :: patch
    real(dp), intent(in) :: x(:, :)
    logical, intent(in) :: nlgeom
    real(dp), allocatable, intent(out) :: k(:, :), f_int(:)
    type(sparse_matrix_t) :: matrix
    integer, allocatable :: clique_ptr(:), clique_nodes(:)
    integer :: row, e
    integer(i8) :: p
    call patch%loops%cliques([(e, e = 1, patch%mesh%n_elements)], clique_ptr, clique_nodes)
    call matrix%build(patch%mesh%n_nodes, clique_ptr, clique_nodes)
    call matrix%zero()
    allocate (f_int(3 * patch%mesh%n_nodes), k(matrix%n, matrix%n))
    call patch%loops%assemble(x, patch%fields, nlgeom, f_int, err, matrix)
    call suite%check(.not. allocated(err), 'assemble')
    k = 0.0_dp
    do row = 1, matrix%n
      do p = matrix%row_ptr(row), matrix%row_ptr(row + 1) - 1
        k(row, matrix%col(p)) = matrix%val(p)
      end do
    end do
  end subroutine dense_tangent

  !> Degrees of freedom of the interior (free) nodes.
  function free_dofs(patch) result(dofs)
    type(patch_t), intent(in) :: patch
    integer, allocatable :: dofs(:)
    integer :: a
    dofs = [integer ::]
    do a = 1, patch%mesh%n_nodes
      if (.not. patch%boundary(a)) dofs = [dofs, 3 * a - 2, 3 * a - 1, 3 * a]
    end do
  end function free_dofs

  !> The patch test's increment: du = H x on the boundary nodes, the interior nodes solved
  !> from K_ff du_f = -K_fb du_b - f_f on coordinates x; `exact` is H x everywhere.
  subroutine solve_patch(patch, x, nlgeom, h, du, exact)
    type(patch_t), intent(in) :: patch
    real(dp), intent(in) :: x(:, :), h(3, 3)
    logical, intent(in) :: nlgeom
    real(dp), allocatable, intent(out) :: du(:), exact(:)
    real(dp), allocatable :: k(:, :), f_int(:), k_ff(:, :), rhs(:, :)
    integer, allocatable :: free(:)
    integer :: a
    logical :: ok
    allocate (exact(3 * patch%mesh%n_nodes))
    do a = 1, patch%mesh%n_nodes
      exact(3 * a - 2:3 * a) = matmul(h, x(:, a))
    end do
    call dense_tangent(patch, x, nlgeom, k, f_int)
    free = free_dofs(patch)
    du = exact
    du(free) = 0.0_dp
    k_ff = k(free, free)
    allocate (rhs(size(free), 1))
    rhs(:, 1) = -matmul(k(free, :), du) - f_int(free)
    call solve_linear_system(k_ff, rhs, ok)
    call suite%check(ok, 'patch tangent regular on the interior nodes')
    du(free) = rhs(:, 1)
  end subroutine solve_patch

  !> Stresses of every point equal to `expected`, interior forces zero, on coordinates x.
  subroutine check_uniform_state(patch, x, nlgeom, expected, what)
    type(patch_t), intent(in) :: patch
    real(dp), intent(in) :: x(:, :), expected(6)
    logical, intent(in) :: nlgeom
    character(len=*), intent(in) :: what
    real(dp), allocatable :: f_int(:), flux(:)
    real(dp) :: worst
    integer :: e, q
    integer, allocatable :: free(:)
    worst = 0.0_dp
    do e = 1, patch%mesh%n_elements
      do q = 1, patch%loops%n_points(e)
        worst = max(worst, maxval(abs(patch%fields%stress(:, q, e) - expected)))
      end do
    end do
    call suite%check(worst <= ROUND_OFF * maxval(abs(expected)), what // ': stress uniform')
    if (worst > ROUND_OFF * maxval(abs(expected))) print '(a,es10.3)', '    worst stress error ', &
      worst / maxval(abs(expected))
    allocate (f_int(3 * patch%mesh%n_nodes), flux(patch%mesh%n_nodes))
    call patch%loops%assemble(x, patch%fields, nlgeom, f_int, err, flux=flux)
    free = free_dofs(patch)
    call suite%check(maxval(abs(f_int(free))) <= ROUND_OFF * maxval(flux), &
                     what // ': interior nodes force-free')
  end subroutine check_uniform_state

  !> Voigt strain (engineering shear) of a displacement gradient.
  pure function voigt_strain(h) result(strain)
    real(dp), intent(in) :: h(3, 3)
    real(dp) :: strain(6)
    strain = [h(1, 1), h(2, 2), h(3, 3), h(1, 2) + h(2, 1), h(1, 3) + h(3, 1), h(2, 3) + h(3, 2)]
  end function voigt_strain

  !> Patch test, small strain: the solved interior nodes take the linear field, every point
  !> the stress C eps, the interior nodes no force.
  subroutine check_patch_small_strain(name, bbar)
    character(len=*), intent(in) :: name
    logical, intent(in) :: bbar
    type(patch_t) :: patch
    real(dp), allocatable :: du(:), exact(:)
    character(len=:), allocatable :: what
    what = name // ' patch, small strain' // trim(merge(', B-bar', '       ', bbar))
    call build_patch(name, patch, bbar)
    call solve_patch(patch, patch%mesh%x, .false., H_PATCH, du, exact)
    call suite%close_array(du, exact, ROUND_OFF, what // ': interior nodes linear')
    call patch%loops%update(patch%mesh%x, du, patch%fields, .false., err)
    call suite%check(.not. allocated(err), what // ': update')
    call check_uniform_state(patch, patch%mesh%x + reshape(du, shape(patch%mesh%x)), .false., &
      matmul(isotropic_elastic_matrix(YOUNGS, POISSON), voigt_strain(H_PATCH)), what)
  end subroutine check_patch_small_strain

  !> Patch test with NLGEOM: a homogeneous pre-stress, then the patch test's increment solved
  !> with the tangent on the deformed patch (initial-stress terms included).
  subroutine check_patch_nlgeom(name)
    character(len=*), intent(in) :: name
    type(patch_t) :: patch
    real(dp), allocatable :: x(:, :), du(:), exact(:)
    real(dp) :: sigma(6)
    integer :: a
    character(len=:), allocatable :: what
    what = name // ' patch, NLGEOM'
    call build_patch(name, patch, .false.)
    x = patch%mesh%x
    allocate (du(3 * size(x, 2)))
    do a = 1, size(x, 2)
      du(3 * a - 2:3 * a) = matmul(H_PRE, x(:, a))
    end do
    call patch%loops%update(x, du, patch%fields, .true., err)
    x = x + reshape(du, shape(x))
    sigma = patch%fields%stress(:, 1, 1)
    call check_uniform_state(patch, x, .true., sigma, what // ' (pre-stress)')
    call solve_patch(patch, x, .true., H_PATCH, du, exact)
    call suite%close_array(du, exact, ROUND_OFF, what // ': interior nodes linear')
    call patch%loops%update(x, du, patch%fields, .true., err)
    call suite%check(.not. allocated(err), what // ': update')
    x = x + reshape(du, shape(x))
    sigma = patch%fields%stress(:, 1, 1)
    call check_uniform_state(patch, x, .true., sigma, what)
  end subroutine check_patch_nlgeom

  !> A pre-stressed patch turned rigidly by 90 degrees about an oblique axis in 9 increments
  !> (NLGEOM): sigma = R sigma_0 R^T at every point, interior nodes force-free.
  subroutine check_rigid_rotation(name)
    character(len=*), intent(in) :: name
    integer, parameter :: STEPS = 9
    type(patch_t) :: patch
    real(dp), allocatable :: x(:, :), du(:)
    real(dp) :: sigma0(6), rotation(3, 3), turn(3, 3), centre(3), axis(3), s(3, 3)
    integer :: a, step
    character(len=:), allocatable :: what
    what = name // ' rigid rotation of a pre-stressed patch'
    call build_patch(name, patch, .false.)
    x = patch%mesh%x
    allocate (du(3 * size(x, 2)))
    do a = 1, size(x, 2)
      du(3 * a - 2:3 * a) = matmul(H_PRE, x(:, a))
    end do
    call patch%loops%update(x, du, patch%fields, .true., err)
    x = x + reshape(du, shape(x))
    sigma0 = patch%fields%stress(:, 1, 1)
    axis = [1.0_dp, 2.0_dp, 2.0_dp] / 3.0_dp
    turn = axis_rotation(axis, 2.0_dp * atan(1.0_dp) / STEPS)
    centre = [1.5_dp, 1.5_dp, 1.5_dp]
    rotation = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [3, 3])
    do step = 1, STEPS
      do a = 1, size(x, 2)
        du(3 * a - 2:3 * a) = matmul(turn, x(:, a) - centre) + centre - x(:, a)
      end do
      call patch%loops%check_geometry(x, du, err)
      call patch%loops%update(x, du, patch%fields, .true., err)
      call suite%check(.not. allocated(err), what // ': update')
      x = x + reshape(du, shape(x))
      rotation = matmul(turn, rotation)
    end do
    s = matmul(rotation, matmul(tensor(sigma0), transpose(rotation)))
    call check_uniform_state(patch, x, .true., [s(1, 1), s(2, 2), s(3, 3), s(1, 2), s(1, 3), s(2, 3)], &
                             what)
  end subroutine check_rigid_rotation

  pure function tensor(v) result(t)
    real(dp), intent(in) :: v(6)
    real(dp) :: t(3, 3)
    t = reshape([v(1), v(4), v(5), v(4), v(2), v(6), v(5), v(6), v(3)], [3, 3])
  end function tensor

  !> Rotation by `angle` about the unit vector `axis` (Rodrigues).
  pure function axis_rotation(axis, angle) result(r)
    real(dp), intent(in) :: axis(3), angle
    real(dp) :: r(3, 3), k(3, 3)
    integer :: i
    k = reshape([0.0_dp, axis(3), -axis(2), -axis(3), 0.0_dp, axis(1), axis(2), -axis(1), 0.0_dp], [3, 3])
    r = sin(angle) * k + (1.0_dp - cos(angle)) * matmul(k, k)
    do i = 1, 3
      r(i, i) = r(i, i) + 1.0_dp
    end do
  end function axis_rotation

  !> C3D8R on a cube of side L: Gamma = h (a parallelepiped), a = 0.0005 sum b^2 / V with
  !> b_aj = +-L^2/4, so a = 0.00075 L, and the hourglass force of u = h^k e_i is
  !> E a (h^k.h^k) h^k e_i = 8 E a h^k e_i (CalculiX hgforce.f); homogeneous strains have none.
  subroutine check_hourglass_cube()
    real(dp), parameter :: L = 2.0_dp
    type(element_geometry_t) :: geo
    real(dp) :: x(3, 8), u(3, 8), f(24), k(24, 24), expected(3, 8)
    integer :: m, i
    logical :: ok
    associate (kind => catalogue%kinds(catalogue%find('C3D8R')))
      x = 0.5_dp * L * (kind%node_xi + 1.0_dp) + spread([1.0_dp, -2.0_dp, 0.5_dp], 2, 8)
      call element_geometry(kind, x, geo, ok)
      call suite%check(ok, 'C3D8R cube accepted')
      call suite%close_to(geo%volume, L**3, ROUND_OFF, 'C3D8R cube: exact volume')
      call suite%close_to(geo%hourglass_factor, HOURGLASS_SCALE * 1.5_dp * L, ROUND_OFF, &
                          'C3D8R cube: hourglass factor a = 0.00075 L (CalculiX shape8hr.f)')
      call suite%close_array(reshape(geo%hourglass, [32]), reshape(kind%hourglass_base, [32]), &
                             ROUND_OFF, 'C3D8R cube: Gamma = h')
      do m = 1, 4
        do i = 1, 3
          u = 0.0_dp
          u(i, :) = kind%hourglass_base(:, m)
          f = 0.0_dp
          call element_hourglass_force(kind, geo, element_hourglass_increment(kind, geo, u, YOUNGS), f)
          expected = 8.0_dp * YOUNGS * geo%hourglass_factor * u
          call suite%close_array(f, reshape(expected, [24]), ROUND_OFF, 'C3D8R cube: hourglass force')
          k = 0.0_dp
          call element_hourglass_stiffness(kind, geo, YOUNGS, k)
          call suite%close_array(matmul(k, reshape(u, [24])), f, ROUND_OFF, &
                                 'C3D8R cube: hourglass stiffness = d force / d u')
        end do
      end do
      u = matmul(H_PATCH, x)
      f = 0.0_dp
      call element_hourglass_force(kind, geo, element_hourglass_increment(kind, geo, u, YOUNGS), f)
      call suite%check(maxval(abs(f)) <= ROUND_OFF * YOUNGS * geo%hourglass_factor * maxval(abs(u)), &
                       'C3D8R cube: no hourglass force under homogeneous strain')
    end associate
  end subroutine check_hourglass_cube

  !> One distorted element of `name` (C3D8R, C3D8I), small strain, elastic: after the update
  !> of a random du from zero stress, f_int = K du (C3D8R with the hourglass force, C3D8I with
  !> the modes found by the update and the condensed tangent).
  subroutine check_single_element_consistency(name)
    character(len=*), intent(in) :: name
    type(patch_t) :: patch
    real(dp), allocatable :: k(:, :), f_int(:), du(:), x(:, :)
    logical :: duplicate
    integer :: a
    type(material_slot_t), allocatable :: materials(:)
    type(plastic_def_t) :: elastic
    real(dp) :: noise(3)
    associate (kind => catalogue%kinds(catalogue%find(name)))
      call patch%mesh%init(mesh_kinds(catalogue))
      do a = 1, 8
        call random_number(noise)
        call patch%mesh%add_node(a, kind%node_xi(:, a) + 0.3_dp * (noise - 0.5_dp), duplicate)
      end do
      call patch%mesh%add_element(1, [(a, a = 1, 8)], duplicate, catalogue%find(name))
      call patch%mesh%compact()
    end associate
    allocate (materials(1), patch%boundary(8))
    patch%boundary = .true.
    call create_material(YOUNGS, POISSON, elastic, materials(1)%m, err)
    call patch%loops%init(catalogue, patch%mesh, [1], [.false.], materials, err)
    call patch%fields%init(patch%loops%max_points, 1, patch%loops%n_material_state())
    x = patch%mesh%x
    allocate (du(24))
    call random_number(du)
    du = 1.0e-3_dp * (du - 0.5_dp)
    call dense_tangent(patch, x, .false., k, f_int)
    call patch%loops%update(x, du, patch%fields, .false., err)
    call suite%check(.not. allocated(err), name // ': update of one element')
    deallocate (f_int)
    allocate (f_int(24))
    call patch%loops%assemble(x + reshape(du, [3, 8]), patch%fields, .false., f_int, err)
    call suite%close_array(f_int, matmul(k, du), ROUND_OFF, name // ': f_int = K du (distorted element)')
  end subroutine check_single_element_consistency

  !> Why fcs3d departs from ccx on distorted elements (doc/theory.md 1.5), on one distorted
  !> hexahedron: fcs3d's hourglass vectors (all three terms of FB's appendix 2) are orthogonal
  !> to a homogeneous strain field, ccx's (shape8hr.f keeps the j = 3 term only) are not; the
  !> modes' gradients with Taylor's factor integrate to zero over the element, ccx's
  !> (shape8hu.f, without the factor) do not. On a parallelepiped both pairs agree.
  subroutine check_against_calculix_variants()
    type(element_geometry_t) :: geo
    real(dp) :: x(3, 8), noise(3, 8), u(3, 8), gamma_ccx(8, 4), integral(3), integral_ccx(3)
    real(dp) :: det0, det_q
    integer :: m, q, variant
    logical :: ok
    character(len=:), allocatable :: shape_name
    do variant = 1, 2
      shape_name = trim(merge('distorted     ', 'parallelepiped', variant == 1))
      associate (kind => catalogue%kinds(catalogue%find('C3D8R')))
        call random_number(noise)
        x = matmul(reshape([1.0_dp, 0.2_dp, 0.0_dp, 0.1_dp, 1.1_dp, 0.1_dp, 0.0_dp, -0.2_dp, 0.9_dp], &
                   [3, 3]), kind%node_xi)
        if (variant == 1) x = x + 0.25_dp * (noise - 0.5_dp)
        call element_geometry(kind, x, geo, ok)
        u = matmul(H_PATCH, x)
        gamma_ccx = kind%hourglass_base - matmul(transpose(geo%grad(3:3, 1:8, 1)), &
                                                 matmul(x(3:3, :), kind%hourglass_base))
        call suite%check(maxval(abs(matmul(u, geo%hourglass))) <= ROUND_OFF * maxval(abs(u)), &
                         'C3D8R ' // shape_name // ': Gamma orthogonal to a homogeneous strain')
        if (variant == 1) then
          call suite%check(maxval(abs(matmul(u, gamma_ccx))) > 1.0e-3_dp * maxval(abs(u)), &
                           'C3D8R distorted: ccx''s one-term vectors are not')
        else
          call suite%close_array(reshape(gamma_ccx, [32]), reshape(geo%hourglass, [32]), ROUND_OFF, &
                                 'C3D8R parallelepiped: ccx''s vectors are the same')
        end if
      end associate
      associate (kind => catalogue%kinds(catalogue%find('C3D8I')))
        call element_geometry(kind, x, geo, ok)
        det0 = determinant3(matmul(x, transpose(kind%centre_derivatives)))
        do m = 1, 3
          integral = 0.0_dp
          integral_ccx = 0.0_dp
          do q = 1, kind%n_points
            det_q = geo%dv(q) / kind%weight(q)
            integral = integral + geo%grad(:, 8 + m, q) * geo%dv(q)
            integral_ccx = integral_ccx + geo%grad(:, 8 + m, q) * (det_q / det0) * geo%dv(q)
          end do
          call suite%check(maxval(abs(integral)) <= ROUND_OFF * geo%volume, 'C3D8I ' // &
                           shape_name // ': mode gradients integrate to zero (Taylor)')
          if (variant == 1) then
            call suite%check(maxval(abs(integral_ccx)) > 1.0e-4_dp * geo%volume, &
                             'C3D8I distorted: without Taylor''s factor (ccx) they do not')
          else
            call suite%check(maxval(abs(integral_ccx)) <= ROUND_OFF * geo%volume, &
                             'C3D8I parallelepiped: without the factor they do too')
          end if
        end do
      end associate
    end do
  end subroutine check_against_calculix_variants

  !> One C3D8R element given an hourglass displacement (NLGEOM), then turned rigidly by 90
  !> degrees in 9 increments: the internal forces turn with it, f = R f_0 (the generalised
  !> hourglass forces rotate with the spin; Gamma and a are invariant under rotations).
  subroutine check_hourglass_rotation()
    integer, parameter :: STEPS = 9
    type(patch_t) :: patch
    type(material_slot_t), allocatable :: materials(:)
    type(plastic_def_t) :: elastic
    real(dp) :: x(3, 8), du(3, 8), f0(24), f(24), rotation(3, 3), turn(3, 3), centre(3)
    integer :: a, step
    logical :: duplicate
    associate (kind => catalogue%kinds(catalogue%find('C3D8R')))
      call patch%mesh%init(mesh_kinds(catalogue))
      do a = 1, 8
        call patch%mesh%add_node(a, kind%node_xi(:, a), duplicate)
      end do
      call patch%mesh%add_element(1, [(a, a = 1, 8)], duplicate, catalogue%find('C3D8R'))
      call patch%mesh%compact()
      allocate (materials(1))
      call create_material(YOUNGS, POISSON, elastic, materials(1)%m, err)
      call patch%loops%init(catalogue, patch%mesh, [1], [.false.], materials, err)
      call patch%fields%init(patch%loops%max_points, 1, patch%loops%n_material_state())
      call suite%equal_int(patch%loops%n_material_state(), 12, 'C3D8R: 12 hourglass forces as state')
      call suite%check(.not. patch%loops%has_states(), 'C3D8R: no yield surface for it')
      x = patch%mesh%x
      du = 0.0_dp
      du(1, :) = 1.0e-3_dp * kind%hourglass_base(:, 1)
      du(3, :) = -2.0e-3_dp * kind%hourglass_base(:, 4)
      call patch%loops%update(x, reshape(du, [24]), patch%fields, .true., err)
      x = x + du
      call patch%loops%assemble(x, patch%fields, .true., f0, err)
      call suite%check(maxval(abs(f0)) > 0.0_dp, 'C3D8R: an hourglass mode carries force')
      turn = axis_rotation([0.0_dp, 0.6_dp, 0.8_dp], 2.0_dp * atan(1.0_dp) / STEPS)
      centre = [0.2_dp, -0.1_dp, 0.3_dp]
      rotation = reshape([1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp], [3, 3])
      do step = 1, STEPS
        do a = 1, 8
          du(:, a) = matmul(turn, x(:, a) - centre) + centre - x(:, a)
        end do
        call patch%loops%update(x, reshape(du, [24]), patch%fields, .true., err)
        x = x + du
        rotation = matmul(turn, rotation)
      end do
      call patch%loops%assemble(x, patch%fields, .true., f, err)
      call suite%close_array(f, reshape(matmul(rotation, reshape(f0, [3, 8])), [24]), ROUND_OFF, &
                             'C3D8R: hourglass forces turn with the element (NLGEOM)')
    end associate
  end subroutine check_hourglass_rotation

  !> Pure bending of one rectangular C3D8I element, length L, width W, height T, nu = 0: the
  !> nodal values of u_x = kappa x z, u_z = -kappa x^2 / 2 have the exact strain energy
  !> E kappa^2 (W T^3 / 12) L / 2 in the condensed tangent, and the update gives
  !> sigma_xx = E kappa z at every point (the modes carry the quadratic part); C3D8 locks.
  subroutine check_pure_bending()
    real(dp), parameter :: L = 4.0_dp, W = 1.0_dp, T = 1.0_dp, KAPPA = 1.0e-3_dp
    character(len=5), parameter :: NAMES(2) = ['C3D8I', 'C3D8 ']
    type(patch_t) :: patch
    type(material_slot_t), allocatable :: materials(:)
    type(plastic_def_t) :: elastic
    real(dp), allocatable :: k(:, :), f_int(:), du(:)
    real(dp) :: x(3, 8), energy, exact_energy, z
    integer :: a, m, q
    logical :: duplicate
    exact_energy = 0.5_dp * YOUNGS * KAPPA**2 * W * T**3 / 12.0_dp * L
    do m = 1, 2
      associate (kind => catalogue%kinds(catalogue%find(trim(NAMES(m)))))
        call patch%mesh%init(mesh_kinds(catalogue))
        do a = 1, 8
          x(:, a) = 0.5_dp * kind%node_xi(:, a) * [L, W, T]
          call patch%mesh%add_node(a, x(:, a), duplicate)
        end do
        call patch%mesh%add_element(1, [(a, a = 1, 8)], duplicate, catalogue%find(trim(NAMES(m))))
        call patch%mesh%compact()
      end associate
      if (allocated(patch%boundary)) deallocate (patch%boundary)
      allocate (materials(1), patch%boundary(8))
      patch%boundary = .true.
      call create_material(YOUNGS, 0.0_dp, elastic, materials(1)%m, err)
      call patch%loops%init(catalogue, patch%mesh, [1], [.false.], materials, err)
      call patch%fields%init(patch%loops%max_points, 1, patch%loops%n_material_state())
      allocate (du(24))
      do a = 1, 8
        du(3 * a - 2:3 * a) = KAPPA * [x(1, a) * x(3, a), 0.0_dp, -0.5_dp * x(1, a)**2]
      end do
      call dense_tangent(patch, x, .false., k, f_int)
      energy = 0.5_dp * dot_product(du, matmul(k, du))
      if (m == 1) then
        call suite%close_to(energy, exact_energy, ROUND_OFF, 'C3D8I pure bending: exact strain energy')
        call patch%loops%update(x, du, patch%fields, .false., err)
        do q = 1, 8
          z = 0.5_dp * T * catalogue%kinds(catalogue%find('C3D8I'))%point_xi(3, q)
          call suite%close_array(patch%fields%stress(:, q, 1), [YOUNGS * KAPPA * z, 0.0_dp, 0.0_dp, &
                                 0.0_dp, 0.0_dp, 0.0_dp], ROUND_OFF, 'C3D8I pure bending: sigma_xx = E kappa z')
        end do
      else
        call suite%check(energy > 2.0_dp * exact_energy, 'C3D8 in pure bending locks (energy > 2x exact)')
        print '(a,f8.3,a)', '    C3D8 bending energy / exact: ', energy / exact_energy, &
          ' (C3D8I: 1 to round-off)'
      end if
      deallocate (du)
      call patch%mesh%free()
    end do
  end subroutine check_pure_bending

end program test_fcs_element_formulations
