!> Unit tests of the element loops and kernels (fcs_element_loops, fcs_element_kernels):
!> - C3D8 through the kind's tables (KERNEL_TABLES) agrees with the hand-written 8-node
!>   hexahedron kernels (KERNEL_HEX8) to round-off: internal force, tangent (with and without
!>   NLGEOM and B-bar), strain and rotation increments, extrapolation, Jacobian ratio, volume,
!>   face pressure forces and their derivative;
!> - for every kind of the standard formulation, the table kernels are consistent: with
!>   stresses from the strain increments of du, the internal force equals K du (small strain,
!>   the tangent's material part), and a rigid translation has no strain and no force;
!> - the loops on a mesh mixing C3D8, C3D4 and C3D6: a homogeneous strain increment gives
!>   the same stress C eps at every point of every element (zero beyond an element's points),
!>   sum_a f_a x_a^T = sigma V (the internal forces of a constant stress), nodal averages,
!>   point volumes, cliques and face nodes sized by the kind, a face pressure's total force,
!>   and an inverted tetrahedron refused by the geometry check.
program test_fcs_element_loops
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_element_kind, only: element_kind_t, MAX_NODES, MAX_POINTS, KERNEL_HEX8, &
    KERNEL_TABLES, FORMULATION_STANDARD
  use fcs_element_catalogue, only: element_catalogue_t
  use fcs_element_kernels, only: element_geometry_t, element_geometry, element_internal_force, &
    element_tangent, element_strain_increments, element_extrapolate, element_min_jacobian_ratio, &
    element_volume, element_face_nodes, element_face_pressure, element_point_volumes
  use fcs_element_loops, only: element_loops_t, mesh_kinds
  use fcs_element_state, only: element_state_t
  use fcs_mesh, only: mesh_t
  use fcs_material, only: material_slot_t, isotropic_elastic_matrix
  use fcs_material_factory, only: create_material, plastic_def_t
  use fcs_test_assertions, only: test_suite_t
  implicit none

  !> Round-off of sums of a few hundred products of order-one numbers: the two kernels of
  !> C3D8 add the same terms in different orders.
  real(dp), parameter :: TIGHT = 1.0e-12_dp
  real(dp), parameter :: YOUNGS = 1000.0_dp, POISSON = 0.25_dp

  type(test_suite_t) :: suite
  type(element_catalogue_t) :: catalogue
  type(error_t), allocatable :: err

  suite%name = 'element_loops'
  call catalogue%init(err)
  call suite%check(.not. allocated(err), 'catalogue')
  if (allocated(err)) error stop 1
  call check_hex8_against_tables(suite, catalogue)
  call check_table_consistency(suite, catalogue)
  call check_mixed_mesh(suite, catalogue)
  call suite%report()

contains

  !> A distorted element of `kind`: an affine map of its natural node coordinates plus a
  !> small random perturbation of every node.
  function distorted(kind) result(x)
    type(element_kind_t), intent(in) :: kind
    real(dp) :: x(3, kind%n_nodes)
    real(dp), parameter :: map(3, 3) = reshape([1.2_dp, -0.1_dp, 0.05_dp, 0.2_dp, 0.9_dp, &
      -0.2_dp, 0.1_dp, 0.15_dp, 1.1_dp], [3, 3])
    real(dp) :: noise(3, kind%n_nodes)
    integer :: a
    call random_number(noise)
    do a = 1, kind%n_nodes
      x(:, a) = matmul(map, kind%node_xi(:, a)) + [0.3_dp, -0.2_dp, 0.5_dp] + &
                0.04_dp * (2.0_dp * noise(:, a) - 1.0_dp)
    end do
  end function distorted

  !> Random stresses (6, n) of order one.
  function random_stress(n) result(stress)
    integer, intent(in) :: n
    real(dp) :: stress(6, n)
    call random_number(stress)
    stress = 2.0_dp * stress - 1.0_dp
  end function random_stress

  !> C3D8 on its tables against the hand-written hexahedron kernels.
  subroutine check_hex8_against_tables(suite, catalogue)
    type(test_suite_t), intent(inout) :: suite
    type(element_catalogue_t), intent(in) :: catalogue
    type(element_kind_t) :: hex8, tables
    type(element_geometry_t) :: geo_hex8, geo_tables
    real(dp) :: x(3, 8), stress(6, 8), c(6, 6, 8), du(3, 8)
    real(dp) :: f1(24), f2(24), k1(24, 24), k2(24, 24)
    real(dp) :: s1(6, MAX_POINTS), s2(6, MAX_POINTS), w1(3, 3, MAX_POINTS), w2(3, 3, MAX_POINTS)
    real(dp) :: e1(MAX_POINTS), e2(MAX_POINTS), a1(MAX_POINTS), a2(MAX_POINTS)
    real(dp) :: n1(6, MAX_NODES), n2(6, MAX_NODES)
    logical :: ok1, ok2, bbar, nlgeom
    integer :: q, variant
    hex8 = catalogue%kinds(catalogue%find('C3D8'))
    call suite%check(hex8%kernel == KERNEL_HEX8, 'the catalogue runs C3D8 on the hexahedron kernels')
    tables = hex8
    tables%kernel = KERNEL_TABLES
    x = distorted(hex8)
    stress = random_stress(8)
    do q = 1, 8
      c(:, :, q) = isotropic_elastic_matrix(1.0_dp + 0.1_dp * q, 0.3_dp)
    end do
    call random_number(du)
    du = 0.01_dp * (du - 0.5_dp)
    call element_geometry(hex8, x, geo_hex8, ok1)
    call element_geometry(tables, x, geo_tables, ok2)
    call suite%check(ok1 .and. ok2, 'C3D8 geometry accepted by both kernels')
    call suite%close_array(element_point_volumes(tables, geo_tables), &
                           element_point_volumes(hex8, geo_hex8), TIGHT, 'C3D8 point volumes')
    do variant = 0, 3
      bbar = mod(variant, 2) == 1
      nlgeom = variant >= 2
      call element_internal_force(hex8, geo_hex8, stress, bbar, f1)
      call element_internal_force(tables, geo_tables, stress, bbar, f2)
      call suite%close_array(f2, f1, TIGHT, 'C3D8 internal force ' // label(bbar, nlgeom))
      call element_tangent(hex8, geo_hex8, stress, c, bbar, nlgeom, k1)
      call element_tangent(tables, geo_tables, stress, c, bbar, nlgeom, k2)
      call suite%close_array(reshape(k2, [24 * 24]), reshape(k1, [24 * 24]), TIGHT, &
                             'C3D8 tangent ' // label(bbar, nlgeom))
      call element_strain_increments(hex8, geo_hex8, du, bbar, s1, w1, e1, a1)
      call element_strain_increments(tables, geo_tables, du, bbar, s2, w2, e2, a2)
      call suite%close_array(reshape(s2(:, 1:8), [48]), reshape(s1(:, 1:8), [48]), TIGHT, &
                             'C3D8 strain increments ' // label(bbar, .false.))
      call suite%close_array(reshape(w2(:, :, 1:8), [72]), reshape(w1(:, :, 1:8), [72]), TIGHT, &
                             'C3D8 spin increments ' // label(bbar, .false.))
      call suite%close_array(e2(1:8), e1(1:8), TIGHT, 'C3D8 equivalent strain ' // label(bbar, .false.))
      call suite%close_array(a2(1:8), a1(1:8), TIGHT, 'C3D8 rotation angle ' // label(bbar, .false.))
    end do
    call element_extrapolate(hex8, stress, n1)
    call element_extrapolate(tables, stress, n2)
    call suite%close_array(reshape(n2(:, 1:8), [48]), reshape(n1(:, 1:8), [48]), TIGHT, &
                           'C3D8 extrapolation')
    call suite%close_to(element_min_jacobian_ratio(tables, x), element_min_jacobian_ratio(hex8, x), &
                        TIGHT, 'C3D8 Jacobian ratio')
    call suite%close_to(element_volume(tables, x), element_volume(hex8, x), TIGHT, 'C3D8 volume')
    call check_hex8_faces(suite, hex8, tables, x)
  end subroutine check_hex8_against_tables

  !> Face pressure forces and their derivatives of the two C3D8 kernels, node by node (the
  !> kernels list a face's nodes in the same cycle from different starts).
  subroutine check_hex8_faces(suite, hex8, tables, x)
    type(test_suite_t), intent(inout) :: suite
    type(element_kind_t), intent(in) :: hex8, tables
    real(dp), intent(in) :: x(:, :)
    integer, allocatable :: nodes1(:), nodes2(:)
    real(dp) :: f1(12), f2(12), d1(12, 12), d2(12, 12), mapped(12), mapped_d(12, 12)
    integer :: f, i, j, ii, jj
    logical :: same_set
    do f = 1, 6
      nodes1 = element_face_nodes(hex8, f)
      nodes2 = element_face_nodes(tables, f)
      same_set = size(nodes1) == 4 .and. size(nodes2) == 4
      do i = 1, size(nodes2)
        same_set = same_set .and. any(nodes1 == nodes2(i))
      end do
      call suite%check(same_set, 'C3D8 face ' // achar(48 + f) // ': same nodes')
      if (.not. same_set) cycle
      call element_face_pressure(hex8, f, x(:, nodes1), 2.5_dp, f1, d1)
      call element_face_pressure(tables, f, x(:, nodes2), 2.5_dp, f2, d2)
      ! Node i of the table face is node ii of the hexahedron face.
      do i = 1, 4
        ii = findloc(nodes1, nodes2(i), 1)
        mapped(3 * i - 2:3 * i) = f1(3 * ii - 2:3 * ii)
        do j = 1, 4
          jj = findloc(nodes1, nodes2(j), 1)
          mapped_d(3 * i - 2:3 * i, 3 * j - 2:3 * j) = d1(3 * ii - 2:3 * ii, 3 * jj - 2:3 * jj)
        end do
      end do
      call suite%close_array(f2, mapped, TIGHT, 'C3D8 face ' // achar(48 + f) // ' pressure forces')
      call suite%close_array(reshape(d2, [144]), reshape(mapped_d, [144]), TIGHT, &
                             'C3D8 face ' // achar(48 + f) // ' follower derivative')
    end do
  end subroutine check_hex8_faces

  pure function label(bbar, nlgeom) result(text)
    logical, intent(in) :: bbar, nlgeom
    character(len=:), allocatable :: text
    text = '(' // trim(merge('B-bar   ', 'full    ', bbar)) // trim(merge(', NLGEOM', '        ', nlgeom)) // ')'
  end function label

  !> Every kind of the standard formulation on its tables: f_int(C B du) = K du (material
  !> part, small strain) with and without B-bar, and a rigid translation strain- and force-free.
  subroutine check_table_consistency(suite, catalogue)
    type(test_suite_t), intent(inout) :: suite
    type(element_catalogue_t), intent(in) :: catalogue
    type(element_kind_t) :: kind
    type(element_geometry_t) :: geo
    real(dp), allocatable :: x(:, :), du(:, :), k(:, :), f(:), stress(:, :), c(:, :, :)
    real(dp) :: strain(6, MAX_POINTS), spin(3, 3, MAX_POINTS), eq(MAX_POINTS), angle(MAX_POINTS)
    integer :: m, n, np, q, variant
    logical :: ok, bbar
    do m = 1, catalogue%size()
      kind = catalogue%kinds(m)
      if (kind%formulation /= FORMULATION_STANDARD) cycle
      kind%kernel = KERNEL_TABLES
      n = kind%n_nodes
      np = kind%n_points
      x = distorted(kind)
      call element_geometry(kind, x, geo, ok)
      call suite%check(ok, kind%name // ': distorted element accepted')
      if (.not. ok) cycle
      allocate (du(3, n), k(3 * n, 3 * n), f(3 * n), stress(6, np), c(6, 6, np))
      do q = 1, np
        c(:, :, q) = isotropic_elastic_matrix(YOUNGS, POISSON)
      end do
      do variant = 0, 1
        bbar = variant == 1
        call random_number(du)
        du = 0.01_dp * (du - 0.5_dp)
        call element_strain_increments(kind, geo, du, bbar, strain, spin, eq, angle)
        do q = 1, np
          stress(:, q) = matmul(c(:, :, q), strain(:, q))
        end do
        call element_internal_force(kind, geo, stress, bbar, f)
        call element_tangent(kind, geo, stress, c, bbar, .false., k)
        call suite%close_array(f, matmul(k, reshape(du, [3 * n])), TIGHT, &
                               kind%name // ': f_int(C B du) = K du ' // label(bbar, .false.))
        du = spread([0.3_dp, -0.2_dp, 0.1_dp], 2, n)
        call element_strain_increments(kind, geo, du, bbar, strain, spin, eq, angle)
        call suite%check(maxval(abs(strain(:, 1:np))) <= TIGHT .and. maxval(eq(1:np)) <= TIGHT &
                         .and. maxval(angle(1:np)) <= TIGHT, kind%name // ': translation strain-free ' &
                         // label(bbar, .false.))
        call suite%check(maxval(abs(matmul(k, reshape(du, [3 * n])))) <= TIGHT * maxval(abs(k)), &
                         kind%name // ': K translation = 0 ' // label(bbar, .false.))
      end do
      deallocate (du, k, f, stress, c)
    end do
  end subroutine check_table_consistency

  !> The loops on three separate elements, C3D8, C3D4 and C3D6 (affine images of their
  !> reference elements), under the homogeneous strain increment du = H x.
  subroutine check_mixed_mesh(suite, catalogue)
    type(test_suite_t), intent(inout) :: suite
    type(element_catalogue_t), intent(in) :: catalogue
    character(len=4), parameter :: NAMES(3) = ['C3D8', 'C3D4', 'C3D6']
    real(dp), parameter :: MAP(3, 3) = reshape([1.0_dp, 0.1_dp, 0.0_dp, -0.2_dp, 0.8_dp, &
      0.1_dp, 0.05_dp, 0.0_dp, 1.3_dp], [3, 3])
    real(dp), parameter :: H(3, 3) = reshape([1.0e-3_dp, 2.0e-4_dp, -1.0e-4_dp, 2.0e-4_dp, &
      -5.0e-4_dp, 3.0e-4_dp, -1.0e-4_dp, 3.0e-4_dp, 7.0e-4_dp], [3, 3])
    type(mesh_t) :: mesh
    type(element_loops_t) :: loops
    type(element_state_t) :: fields
    type(material_slot_t), allocatable :: materials(:)
    type(plastic_def_t) :: elastic
    real(dp), allocatable :: du(:), f_int(:), nodal(:, :), volume(:, :), du_bad(:), force(:)
    integer, allocatable :: clique_ptr(:), clique_nodes(:), nodes(:)
    real(dp) :: sigma(6), moment(3, 3), expected_moment(3, 3), total_volume, det_map, pressure_total(3)
    integer :: e, k, a, node, q, first
    logical :: duplicate
    call mesh%init(mesh_kinds(catalogue))
    total_volume = 0.0_dp
    det_map = MAP(1, 1) * (MAP(2, 2) * MAP(3, 3) - MAP(3, 2) * MAP(2, 3)) - &
              MAP(1, 2) * (MAP(2, 1) * MAP(3, 3) - MAP(3, 1) * MAP(2, 3)) + &
              MAP(1, 3) * (MAP(2, 1) * MAP(3, 2) - MAP(3, 1) * MAP(2, 2))
    do e = 1, 3
      k = catalogue%find(NAMES(e))
      associate (kind => catalogue%kinds(k))
        first = mesh%n_nodes + 1
        do a = 1, kind%n_nodes
          call mesh%add_node(mesh%n_nodes + 1, matmul(MAP, kind%node_xi(:, a)) + &
                             [3.0_dp * e, 0.0_dp, 0.0_dp], duplicate)
        end do
        call mesh%add_element(10 * e, [(node, node = first, mesh%n_nodes)], duplicate, &
                              mesh%find_kind(NAMES(e)))
        total_volume = total_volume + det_map * kind%reference_volume
      end associate
    end do
    call mesh%compact()
    call suite%equal_int(size(mesh%connectivity, 1), 8, 'connectivity rows: the largest element')
    call suite%check(all(mesh%element_nodes(2) == [9, 10, 11, 12]), 'element_nodes of the C3D4')
    allocate (materials(1))
    call create_material(YOUNGS, POISSON, elastic, materials(1)%m, err)
    call loops%init(catalogue, mesh, [1, 1, 1], [.false., .false., .false.], materials, err)
    call suite%check(.not. allocated(err), 'loops on C3D8 + C3D4 + C3D6')
    if (allocated(err)) return
    call suite%equal_int(loops%max_points, 8, 'max_points of the model')
    call suite%check(all(loops%point_counts() == [8, 1, 2]), 'integration points per element')
    call fields%init(loops%max_points, 3, loops%n_material_state())
    allocate (du(3 * mesh%n_nodes), f_int(3 * mesh%n_nodes))
    do node = 1, mesh%n_nodes
      du(3 * node - 2:3 * node) = matmul(H, mesh%x(:, node))
    end do
    call loops%check_geometry(mesh%x, du, err)
    call suite%check(.not. allocated(err), 'small homogeneous increment: geometry accepted')
    call loops%update(mesh%x, du, fields, .false., err)
    call suite%check(.not. allocated(err), 'update')
    sigma = matmul(isotropic_elastic_matrix(YOUNGS, POISSON), &
                   [H(1, 1), H(2, 2), H(3, 3), 2.0_dp * H(1, 2), 2.0_dp * H(1, 3), 2.0_dp * H(2, 3)])
    do e = 1, 3
      do q = 1, loops%max_points
        if (q <= loops%n_points(e)) then
          call suite%close_array(fields%stress(:, q, e), sigma, TIGHT, NAMES(e) // ': stress C eps')
        else
          call suite%check(all(fields%stress(:, q, e) == 0.0_dp), NAMES(e) // ': no stress beyond its points')
        end if
      end do
    end do
    nodal = loops%nodal_average(fields%stress, mesh%n_nodes)
    call suite%close_array(reshape(nodal, [size(nodal)]), reshape(spread(sigma, 2, mesh%n_nodes), &
                           [size(nodal)]), TIGHT, 'nodal averages of a constant stress')
    volume = loops%point_volumes()
    call suite%close_to(sum(volume), total_volume, TIGHT, 'point volumes add up to the elements')
    call loops%assemble(mesh%x, fields, .false., f_int, err)
    call suite%check(.not. allocated(err), 'assemble')
    moment = 0.0_dp
    do node = 1, mesh%n_nodes
      do a = 1, 3
        moment(:, a) = moment(:, a) + f_int(3 * node - 2:3 * node) * mesh%x(a, node)
      end do
    end do
    expected_moment = reshape([sigma(1), sigma(4), sigma(5), sigma(4), sigma(2), sigma(6), sigma(5), &
                               sigma(6), sigma(3)], [3, 3]) * total_volume
    call suite%close_array(reshape(moment, [9]), reshape(expected_moment, [9]), TIGHT, &
                           'sum_a f_a x_a^T = sigma V')
    call suite%check(maxval(abs([sum(f_int(1::3)), sum(f_int(2::3)), sum(f_int(3::3))])) <= &
                     TIGHT * maxval(abs(f_int)), 'internal forces in equilibrium')
    call loops%cliques([1, 2, 3], clique_ptr, clique_nodes)
    call suite%check(all(clique_ptr == [1, 9, 13, 19]), 'cliques sized by the kinds')
    nodes = loops%face_nodes(2, 1)
    call suite%check(size(nodes) == 3 .and. all(nodes == [9, 11, 10]), 'C3D4 face S1 = nodes 1-3-2')
    allocate (force(3 * size(nodes)))
    call loops%face_pressure(2, 1, mesh%x, .false., 2.0_dp, force)
    pressure_total = [sum(force(1::3)), sum(force(2::3)), sum(force(3::3))]
    ! The face S1 (zeta = 0) maps to the plane spanned by MAP's first two columns; its outward
    ! area vector is -(c1 x c2)/2 and a positive pressure pushes into the body: F = p (c1 x c2)/2.
    call suite%close_array(pressure_total, 2.0_dp * 0.5_dp * cross(MAP(:, 1), MAP(:, 2)), TIGHT, &
                           'C3D4 face pressure: total force p A n_in')
    du_bad = 0.0_dp * du
    du_bad(3 * 12 - 2:3 * 12) = -2.0_dp * MAP(:, 3)
    call loops%check_geometry(mesh%x, du_bad, err)
    call suite%check(allocated(err), 'tetrahedron turned inside out: refused')
    if (allocated(err)) call suite%check(index(err%message, 'element 20 is inverted') > 0, &
                                         'the refusal names the element')
  end subroutine check_mixed_mesh

  pure function cross(a, b) result(c)
    real(dp), intent(in) :: a(3), b(3)
    real(dp) :: c(3)
    c = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
  end function cross

end program test_fcs_element_loops
