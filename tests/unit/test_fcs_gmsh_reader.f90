!> Unit tests of fcs_gmsh_reader on the meshes of tests/data/gmsh (see make_data.sh there):
!> a 2 x 1 x 1 box of 2 x 2 x 1 hexahedra saved by gmsh 4.8.4 as text and binary, a hand-written
!> file with sparse tags, tetrahedra of first and second order, a box of hexahedra and prisms
!> of first order (binary) and second order (text, with 6-node triangles and 8-node quadrangles
!> on its physical surfaces), and malformed files that must give a clear message.
!> The data directory is $FCS3D_TEST_DATA/gmsh if that variable is set, else tests/data/gmsh
!> under the current directory (run from the repository root), else the one found from the
!> test binary's path <root>/build/<variant>/tests/ (tests/run_tests.sh runs each unit test in a
!> scratch directory).
program test_fcs_gmsh_reader
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, EXIT_INPUT
  use fcs_mesh, only: mesh_t
  use fcs_element_catalogue, only: element_catalogue_t
  use fcs_element_loops, only: mesh_kinds, element_volume_of, element_face_area_of
  use fcs_gmsh_reader, only: read_gmsh
  use fcs_strings, only: dirname, file_exists
  use fcs_test_assertions, only: test_suite_t
  implicit none
  character(len=:), allocatable :: data_dir
  !> Coordinates written by gmsh with 16 significant digits: text and binary agree to this.
  real(dp), parameter :: DIGITS_TOLERANCE = 1.0e-15_dp
  !> Transfinite interpolation leaves about 1e-12 of noise on the interior node coordinates.
  real(dp), parameter :: MESHER_TOLERANCE = 1.0e-10_dp
  type(test_suite_t) :: suite
  type(element_catalogue_t) :: catalogue
  type(error_t), allocatable :: catalogue_error

  suite%name = 'fcs_gmsh_reader'
  call catalogue%init(catalogue_error)
  call suite%check(.not. allocated(catalogue_error), 'element catalogue')
  data_dir = data_directory()
  call suite%check(file_exists(data_dir // 'cube.geo'), 'test data found in "' // data_dir // '"')
  call test_cube(suite, data_dir // 'cube_ascii.msh')
  call test_cube(suite, data_dir // 'cube_binary.msh')
  call test_cube(suite, data_dir // 'cube_crlf.msh')
  call test_text_equals_binary(suite)
  call test_no_groups(suite)
  call test_sparse_tags(suite)
  call test_clashing_ids(suite)
  call test_tetrahedra(suite)
  call test_mixed(suite, 'mixed8_binary.msh', 'C3D8', 'C3D6', [integer ::])
  call test_mixed(suite, 'mixed20.msh', 'C3D20', 'C3D15', [integer ::])
  call test_mixed(suite, 'mixed20.msh', 'C3D20R', 'C3D15', [catalogue%find('C3D20R')])
  call test_bad_files(suite)
  call suite%report()

contains

  !> The element kinds of the catalogue, as the mesh is to know them (fcs_element_loops).
  function catalogue_kinds() result(kinds)
    use fcs_mesh, only: mesh_kind_t
    use fcs_error, only: error_t
    type(mesh_kind_t), allocatable :: kinds(:)
    type(element_catalogue_t) :: catalogue
    type(error_t), allocatable :: err
    call catalogue%init(err)
    kinds = mesh_kinds(catalogue)
  end function catalogue_kinds

  !> Directory of the test meshes, ending in "/" (see the program comment).
  function data_directory() result(directory)
    character(len=:), allocatable :: directory
    character(len=4096) :: buffer
    integer :: length, stat
    call get_environment_variable('FCS3D_TEST_DATA', buffer, length, stat)
    if (stat == 0 .and. length > 0) then
      directory = buffer(1:length) // '/gmsh/'
      return
    end if
    directory = 'tests/data/gmsh/'
    if (file_exists(directory // 'cube.geo')) return
    call get_command_argument(0, buffer, length, stat)
    if (stat /= 0) return
    directory = dirname(dirname(dirname(dirname(buffer(1:length))))) // '/tests/data/gmsh/'
  end function data_directory

  !> Read `path` into a fresh mesh; `ok` false (and a failed check) on error.
  subroutine read_fresh(suite, path, mesh, ok)
    type(test_suite_t), intent(inout) :: suite
    character(len=*), intent(in) :: path
    type(mesh_t), intent(out) :: mesh
    logical, intent(out) :: ok
    type(error_t), allocatable :: err
    call mesh%init(catalogue_kinds())
    call read_gmsh(path, mesh, err)
    ok = .not. allocated(err)
    if (.not. ok) then
      call suite%check(.false., 'reading ' // path // ': ' // err%message)
    end if
  end subroutine read_fresh

  !> The box: counts, coordinates, right-handed hexahedra, sets and surfaces.
  subroutine test_cube(suite, path)
    type(test_suite_t), intent(inout) :: suite
    character(len=*), intent(in) :: path
    type(mesh_t) :: mesh
    logical :: ok
    integer :: k, n7
    call read_fresh(suite, path, mesh, ok)
    if (.not. ok) return
    call suite%equal_int(mesh%n_nodes, 18, path // ': nodes')
    call suite%equal_int(mesh%n_elements, 4, path // ': hexahedra')
    call suite%check(all(mesh%element_id(1:4) == [12, 13, 14, 15]), path // ': element ids')
    n7 = mesh%node_index(7)
    call suite%check(n7 > 0, path // ': node 7 exists')
    if (n7 > 0) call suite%check(all(mesh%x(:, n7) == [2.0_dp, 1.0_dp, 1.0_dp]), path // ': node 7 at (2, 1, 1)')
    call suite%close_to(mesh%x(1, mesh%node_index(17)), 1.0_dp, MESHER_TOLERANCE, path // ': node 17 x')
    call suite%close_to(mesh%x(2, mesh%node_index(17)), 0.5_dp, MESHER_TOLERANCE, path // ': node 17 y')
    do k = 1, mesh%n_elements
      call suite%check(hex_volume_sign(mesh, k) > 0.0_dp, path // ': hexahedron ' // &
        trim(int_text(mesh%element_id(k))) // ' is right-handed (C3D8 order)')
    end do
    call suite%equal_int(size(mesh%element_sets), 1, path // ': one element set')
    call suite%equal_int(set_size(mesh, 'BLOCK', .false.), 4, path // ': element set BLOCK')
    call suite%equal_int(size(mesh%node_sets), 6, path // ': six node sets')
    call suite%equal_int(set_size(mesh, 'BLOCK', .true.), 18, path // ': node set BLOCK')
    call suite%equal_int(set_size(mesh, 'FIXED', .true.), 6, path // ': node set FIXED')
    call suite%equal_int(set_size(mesh, 'LOADED', .true.), 6, path // ': node set LOADED')
    call suite%equal_int(set_size(mesh, 'TOP FACE', .true.), 9, path // ': node set TOP FACE')
    call suite%equal_int(set_size(mesh, 'CORNER', .true.), 1, path // ': node set CORNER')
    call suite%equal_int(set_size(mesh, 'CURVE_7', .true.), 3, path // ': node set CURVE_7 (unnamed)')
    if (mesh%find_node_set('CORNER') > 0) call suite%equal_int(mesh%node_sets(mesh%find_node_set('CORNER')) &
      %members(1), n7, path // ': CORNER is node 7')
    call suite%equal_int(size(mesh%surfaces), 3, path // ': three surfaces')
    call check_surface(suite, mesh, path, 'FIXED', 2, 1, 0.0_dp, -1.0_dp)
    call check_surface(suite, mesh, path, 'LOADED', 2, 1, 2.0_dp, 1.0_dp)
    call check_surface(suite, mesh, path, 'TOP FACE', 4, 3, 1.0_dp, 1.0_dp)
  end subroutine test_cube

  !> Surface `name` has `n_faces` faces; each face's nodes lie on the plane x(axis) = value and
  !> its outward normal (right-hand rule on the hex8 face order) is `sense` times that axis.
  subroutine check_surface(suite, mesh, path, name, n_faces, axis, value, sense)
    type(test_suite_t), intent(inout) :: suite
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: path, name
    integer, intent(in) :: n_faces, axis
    real(dp), intent(in) :: value, sense
    integer :: s, f, nodes(4)
    real(dp) :: normal(3), expected(3)
    s = mesh%find_surface(name)
    call suite%check(s > 0, path // ': surface ' // name // ' exists')
    if (s == 0) return
    call suite%equal_int(size(mesh%surfaces(s)%element), n_faces, path // ': faces of ' // name)
    expected = 0.0_dp
    expected(axis) = sense
    do f = 1, size(mesh%surfaces(s)%element)
      nodes = mesh%face_nodes(mesh%surfaces(s)%element(f), mesh%surfaces(s)%face(f))
      call suite%check(all(abs(mesh%x(axis, nodes) - value) <= MESHER_TOLERANCE), path // ': ' // name // &
        ' face on its plane')
      normal = face_normal(mesh, nodes)
      call suite%check(all(abs(normal - expected) <= MESHER_TOLERANCE), path // ': ' // name // &
        ' face normal points outward')
    end do
  end subroutine check_surface

  !> Unit normal of a quadrilateral face by the right-hand rule: (x3 - x1) x (x4 - x2).
  function face_normal(mesh, nodes) result(normal)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: nodes(4)
    real(dp) :: normal(3)
    real(dp) :: a(3), b(3)
    a = mesh%x(:, nodes(3)) - mesh%x(:, nodes(1))
    b = mesh%x(:, nodes(4)) - mesh%x(:, nodes(2))
    normal = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
    normal = normal / norm2(normal)
  end function face_normal

  !> (x2 - x1) . ((x4 - x1) x (x5 - x1)): positive for a right-handed C3D8 hexahedron.
  real(dp) function hex_volume_sign(mesh, k)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: k
    real(dp) :: a(3), b(3), c(3)
    associate (x => mesh%x, nodes => mesh%connectivity(:, k))
      a = x(:, nodes(2)) - x(:, nodes(1))
      b = x(:, nodes(4)) - x(:, nodes(1))
      c = x(:, nodes(5)) - x(:, nodes(1))
    end associate
    hex_volume_sign = a(1) * (b(2) * c(3) - b(3) * c(2)) + a(2) * (b(3) * c(1) - b(1) * c(3)) + &
      a(3) * (b(1) * c(2) - b(2) * c(1))
  end function hex_volume_sign

  !> Members of node set (or element set) `name`, -1 if it does not exist.
  integer function set_size(mesh, name, nodes)
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: name
    logical, intent(in) :: nodes
    integer :: k
    set_size = -1
    if (nodes) then
      k = mesh%find_node_set(name)
      if (k > 0) set_size = size(mesh%node_sets(k)%members)
    else
      k = mesh%find_element_set(name)
      if (k > 0) set_size = size(mesh%element_sets(k)%members)
    end if
  end function set_size

  function int_text(value) result(text)
    integer, intent(in) :: value
    character(len=12) :: text
    write (text, '(i0)') value
  end function int_text

  !> The text and binary files of the same mesh give the same mesh.
  subroutine test_text_equals_binary(suite)
    type(test_suite_t), intent(inout) :: suite
    type(mesh_t) :: text, binary
    logical :: ok_text, ok_binary
    integer :: k
    call read_fresh(suite, data_dir // 'cube_ascii.msh', text, ok_text)
    call read_fresh(suite, data_dir // 'cube_binary.msh', binary, ok_binary)
    if (.not. (ok_text .and. ok_binary)) return
    call suite%check(text%n_nodes == binary%n_nodes .and. text%n_elements == binary%n_elements, &
      'text = binary: counts')
    if (text%n_nodes /= binary%n_nodes .or. text%n_elements /= binary%n_elements) return
    call suite%check(all(text%node_id(1:text%n_nodes) == binary%node_id(1:text%n_nodes)), 'text = binary: node ids')
    call suite%check(all(abs(text%x(:, 1:text%n_nodes) - binary%x(:, 1:text%n_nodes)) <= DIGITS_TOLERANCE * &
      max(1.0_dp, abs(binary%x(:, 1:text%n_nodes)))), 'text = binary: coordinates')
    call suite%check(all(text%element_id(1:text%n_elements) == binary%element_id(1:text%n_elements)), &
      'text = binary: element ids')
    call suite%check(all(text%connectivity(:, 1:text%n_elements) == binary%connectivity(:, 1:text%n_elements)), &
      'text = binary: connectivity')
    call suite%check(size(text%node_sets) == size(binary%node_sets) .and. size(text%surfaces) == &
      size(binary%surfaces), 'text = binary: number of sets')
    if (size(text%node_sets) /= size(binary%node_sets) .or. size(text%surfaces) /= size(binary%surfaces)) return
    do k = 1, size(text%node_sets)
      call suite%check(text%node_sets(k)%name == binary%node_sets(k)%name .and. &
        same_list(text%node_sets(k)%members, binary%node_sets(k)%members), 'text = binary: node set ' // &
        text%node_sets(k)%name)
    end do
    do k = 1, size(text%surfaces)
      call suite%check(text%surfaces(k)%name == binary%surfaces(k)%name .and. &
        same_list(text%surfaces(k)%element, binary%surfaces(k)%element) .and. &
        same_list(text%surfaces(k)%face, binary%surfaces(k)%face), 'text = binary: surface ' // &
        text%surfaces(k)%name)
    end do
  end subroutine test_text_equals_binary

  logical function same_list(a, b)
    integer, intent(in) :: a(:), b(:)
    same_list = size(a) == size(b)
    if (same_list) same_list = all(a == b)
  end function same_list

  !> Without physical groups (gmsh saves every element, binary file): every hexahedron, no
  !> sets. With physical surfaces but no physical volume (saved with -save_all): every
  !> hexahedron, and the surfaces.
  subroutine test_no_groups(suite)
    type(test_suite_t), intent(inout) :: suite
    type(mesh_t) :: mesh, surfaces_only
    logical :: ok
    call read_fresh(suite, data_dir // 'cube_nogroups.msh', mesh, ok)
    if (ok) then
      call suite%equal_int(mesh%n_elements, 4, 'no groups: all hexahedra')
      call suite%equal_int(mesh%n_nodes, 18, 'no groups: nodes of the hexahedra')
      call suite%check(size(mesh%node_sets) == 0 .and. size(mesh%element_sets) == 0 .and. &
        size(mesh%surfaces) == 0, 'no groups: no sets')
    end if
    call read_fresh(suite, data_dir // 'cube_saveall_surfaces.msh', surfaces_only, ok)
    if (.not. ok) return
    call suite%equal_int(surfaces_only%n_elements, 4, 'no physical volume: all hexahedra')
    call suite%equal_int(size(surfaces_only%element_sets), 0, 'no physical volume: no element set')
    call check_surface(suite, surfaces_only, 'cube_saveall_surfaces.msh', 'LOADED', 2, 1, 2.0_dp, 1.0_dp)
  end subroutine test_no_groups

  !> Hand-written file: sparse tags up to 1e9, blocks out of order, parametric coordinates,
  !> a quad block before the hexahedra, a point outside groups, sections to skip.
  subroutine test_sparse_tags(suite)
    type(test_suite_t), intent(inout) :: suite
    type(mesh_t) :: mesh
    logical :: ok
    integer :: s
    integer, parameter :: IDS(8) = [7, 3, 1000000000, 12, 50, 60, 70, 80]
    real(dp), parameter :: CORNERS(3, 8) = reshape([0, 0, 0, 1, 0, 0, 1, 1, 0, 0, 1, 0, 0, 0, 1, &
      1, 0, 1, 1, 1, 1, 0, 1, 1], [3, 8]) * 1.0_dp
    call read_fresh(suite, data_dir // 'sparse.msh', mesh, ok)
    if (.not. ok) return
    call suite%equal_int(mesh%n_nodes, 8, 'sparse: nodes')
    call suite%equal_int(mesh%n_elements, 1, 'sparse: one hexahedron')
    call suite%equal_int(mesh%element_index(42), 1, 'sparse: element 42')
    call suite%check(all(mesh%node_id(mesh%connectivity(:, 1)) == IDS), 'sparse: connectivity')
    call suite%check(all(mesh%x(:, mesh%connectivity(:, 1)) == CORNERS), 'sparse: coordinates')
    call suite%equal_int(set_size(mesh, 'BODY', .false.), 1, 'sparse: element set BODY')
    call suite%equal_int(set_size(mesh, 'BODY', .true.), 8, 'sparse: node set BODY')
    call suite%equal_int(set_size(mesh, 'BOTTOM', .true.), 4, 'sparse: node set BOTTOM')
    s = mesh%find_surface('BOTTOM')
    call suite%check(s > 0, 'sparse: surface BOTTOM')
    if (s == 0) return
    call suite%check(same_list(mesh%surfaces(s)%element, [1]) .and. same_list(mesh%surfaces(s)%face, [1]), &
      'sparse: BOTTOM is face S1 of element 42')
  end subroutine test_sparse_tags

  !> tet.geo's tetrahedron cut into 4 tetrahedra: C3D4 and, second order, C3D10 with the
  !> mid-side nodes on their edges; volume 1/6.
  subroutine test_tetrahedra(suite)
    type(test_suite_t), intent(inout) :: suite
    type(mesh_t) :: mesh
    logical :: ok
    call read_fresh(suite, data_dir // 'tet4.msh', mesh, ok)
    if (ok) then
      call suite%check(mesh%n_elements == 4 .and. all(mesh%element_kind(1:4) == mesh%find_kind('C3D4')), &
        'tet4.msh: 4 C3D4')
      call suite%equal_int(mesh%n_nodes, 7, 'tet4.msh: nodes')
      call check_volumes(suite, mesh, 'tet4.msh', 1.0_dp / 6.0_dp)
    end if
    call read_fresh(suite, data_dir // 'tet10.msh', mesh, ok)
    if (.not. ok) return
    call suite%check(mesh%n_elements == 4 .and. all(mesh%element_kind(1:4) == mesh%find_kind('C3D10')), &
      'tet10.msh: 4 C3D10')
    call suite%equal_int(mesh%n_nodes, 22, 'tet10.msh: nodes')
    call check_volumes(suite, mesh, 'tet10.msh', 1.0_dp / 6.0_dp)
    call check_mid_side_nodes(suite, mesh, 'tet10.msh')
  end subroutine test_tetrahedra

  !> kinds.geo's box [0,2] x [0,1] x [0,1] (shape 3): hexahedra (kind `hexahedra`) for x < 1,
  !> prisms (kind `prisms`) for x > 1; `kinds` as read_gmsh's choice of kinds, indices into the
  !> catalogue. Volume 2; the physical surfaces XMIN, XMAX (quadrilaterals), YMIN, ZMIN
  !> (quadrilaterals and triangles) on their planes, outward, with their areas; the internal
  !> surface MID on the elements its normal points out of.
  subroutine test_mixed(suite, name, hexahedra, prisms, kinds)
    type(test_suite_t), intent(inout) :: suite
    character(len=*), intent(in) :: name, hexahedra, prisms
    integer, intent(in) :: kinds(:)
    type(mesh_t) :: mesh
    type(error_t), allocatable :: err
    character(len=:), allocatable :: what
    integer :: n_hex, n_prism, s
    what = name // ' (' // hexahedra // ', ' // prisms // ')'
    call mesh%init(catalogue_kinds())
    call read_gmsh(data_dir // name, mesh, err, kinds=kinds)
    call suite%check(.not. allocated(err), 'reading ' // what)
    if (allocated(err)) then
      call suite%check(.false., err%message)
      return
    end if
    n_hex = count(mesh%element_kind(1:mesh%n_elements) == mesh%find_kind(hexahedra))
    n_prism = count(mesh%element_kind(1:mesh%n_elements) == mesh%find_kind(prisms))
    call suite%check(n_hex == 8 .and. n_prism == 28 .and. mesh%n_elements == 36, what // &
      ': 8 hexahedra and 28 prisms of the kinds named')
    call check_volumes(suite, mesh, what, 2.0_dp)
    call check_mid_side_nodes(suite, mesh, what)
    call check_faces(suite, mesh, what, 'XMIN', 1, 0.0_dp, -1.0_dp, 1.0_dp)
    call check_faces(suite, mesh, what, 'XMAX', 1, 2.0_dp, 1.0_dp, 1.0_dp)
    call check_faces(suite, mesh, what, 'YMIN', 2, 0.0_dp, -1.0_dp, 2.0_dp)
    call check_faces(suite, mesh, what, 'ZMIN', 3, 0.0_dp, -1.0_dp, 2.0_dp)
    ! MID, the internal surface x = 1, has elements with normal +x (kinds.geo): each is the
    ! face of the hexahedron (x < 1) out of which that normal points, not the prism's.
    call check_faces(suite, mesh, what, 'MID', 1, 1.0_dp, 1.0_dp, 1.0_dp)
    s = mesh%find_surface('MID')
    if (s > 0) call suite%check(all(mesh%element_kind(mesh%surfaces(s)%element) == &
      mesh%find_kind(hexahedra)), what // ': MID faces are the hexahedra''s')
    call suite%equal_int(set_size(mesh, 'BLOCK', .false.), 36, what // ': element set BLOCK')
    call suite%equal_int(set_size(mesh, 'BLOCK', .true.), mesh%n_nodes, what // ': node set BLOCK')
  end subroutine test_mixed

  !> Every element has a positive volume; together `total`.
  subroutine check_volumes(suite, mesh, what, total)
    type(test_suite_t), intent(inout) :: suite
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: what
    real(dp), intent(in) :: total
    real(dp) :: volume(mesh%n_elements)
    integer :: e
    do e = 1, mesh%n_elements
      volume(e) = element_volume_of(catalogue, mesh, e)
    end do
    call suite%check(all(volume > 0.0_dp), what // ': every element has a positive volume')
    call suite%close_to(sum(volume), total, MESHER_TOLERANCE, what // ': total volume')
  end subroutine check_volumes

  !> In these straight-edged meshes every mid-side node of an element lies half-way between the
  !> two corners of its edge in CalculiX's numbering (`edge_corners` of the kind): the gmsh
  !> node order was permuted right.
  subroutine check_mid_side_nodes(suite, mesh, what)
    type(test_suite_t), intent(inout) :: suite
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: what
    integer :: e, a, n_bad, n_checked
    n_bad = 0
    n_checked = 0
    do e = 1, mesh%n_elements
      associate (kind => catalogue%kinds(mesh%element_kind(e)), nodes => mesh%connectivity(:, e))
        do a = kind%n_corners + 1, kind%n_nodes
          n_checked = n_checked + 1
          if (any(abs(mesh%x(:, nodes(a)) - 0.5_dp * (mesh%x(:, nodes(kind%edge_corners(1, a))) + &
              mesh%x(:, nodes(kind%edge_corners(2, a))))) > MESHER_TOLERANCE)) n_bad = n_bad + 1
        end do
      end associate
    end do
    call suite%equal_int(n_bad, 0, what // ': mid-side nodes off their edges (of ' // &
      trim(int_text(n_checked)) // ')')
  end subroutine check_mid_side_nodes

  !> Surface `name`: every face's nodes on the plane x(axis) = value, its normal (right-hand
  !> rule on its first three corners) `sense` times that axis, total area `area`.
  subroutine check_faces(suite, mesh, what, name, axis, value, sense, area)
    type(test_suite_t), intent(inout) :: suite
    type(mesh_t), intent(in) :: mesh
    character(len=*), intent(in) :: what, name
    integer, intent(in) :: axis
    real(dp), intent(in) :: value, sense, area
    integer, allocatable :: nodes(:)
    integer :: s, f, n_off, n_inward
    real(dp) :: a(3), b(3), normal(3), total
    s = mesh%find_surface(name)
    call suite%check(s > 0, what // ': surface ' // name // ' exists')
    if (s == 0) return
    n_off = 0
    n_inward = 0
    total = 0.0_dp
    do f = 1, size(mesh%surfaces(s)%element)
      nodes = mesh%face_nodes(mesh%surfaces(s)%element(f), mesh%surfaces(s)%face(f))
      if (any(abs(mesh%x(axis, nodes) - value) > MESHER_TOLERANCE)) n_off = n_off + 1
      a = mesh%x(:, nodes(2)) - mesh%x(:, nodes(1))
      b = mesh%x(:, nodes(3)) - mesh%x(:, nodes(1))
      normal = [a(2) * b(3) - a(3) * b(2), a(3) * b(1) - a(1) * b(3), a(1) * b(2) - a(2) * b(1)]
      if (sense * normal(axis) <= 0.0_dp) n_inward = n_inward + 1
      total = total + element_face_area_of(catalogue, mesh, mesh%surfaces(s)%element(f), &
                                           mesh%surfaces(s)%face(f))
    end do
    call suite%equal_int(n_off, 0, what // ': ' // name // ' faces off their plane')
    call suite%equal_int(n_inward, 0, what // ': ' // name // ' faces not pointing outward')
    call suite%close_to(total, area, MESHER_TOLERANCE, what // ': area of ' // name)
  end subroutine check_faces

  !> Node and element ids already in the mesh are errors naming the id and the file.
  subroutine test_clashing_ids(suite)
    type(test_suite_t), intent(inout) :: suite
    type(mesh_t) :: mesh, other
    type(error_t), allocatable :: err
    logical :: duplicate
    call mesh%init(catalogue_kinds())
    call mesh%add_node(5, [9.0_dp, 9.0_dp, 9.0_dp], duplicate)
    call read_gmsh(data_dir // 'cube_ascii.msh', mesh, err)
    call check_message(suite, err, 'clashing node', 'cube_ascii.msh', 'node 5 already exists')
    call other%init(catalogue_kinds())
    call other%add_node(100, [9.0_dp, 9.0_dp, 9.0_dp], duplicate)
    call other%add_element(13, [1, 1, 1, 1, 1, 1, 1, 1], duplicate, other%find_kind('C3D8'))
    call read_gmsh(data_dir // 'cube_binary.msh', other, err)
    call check_message(suite, err, 'clashing element', 'cube_binary.msh', 'element 13 already exists')
  end subroutine test_clashing_ids

  !> Malformed and unsupported files: an input error with the expected words, no crash.
  subroutine test_bad_files(suite)
    type(test_suite_t), intent(inout) :: suite
    call expect_error(suite, 'bad_truncated.msh', 'bad_truncated.msh:43:', 'truncated')
    call expect_error(suite, 'bad_truncated_elements.msh', 'bad_truncated_elements.msh:', 'truncated')
    call expect_error(suite, 'bad_truncated_binary.msh', '$Nodes (byte', 'truncated')
    call expect_error(suite, 'bad_v22.msh', 'version 2.2 is not supported', 'gmsh -format msh41')
    call expect_error(suite, 'bad_partitioned.msh', 'partitioned .msh files are not supported', '-part 0')
    call expect_error(suite, 'bad_no_hexahedra.msh', 'no 3D elements to read', 'Physical Volume')
    call expect_error(suite, 'bad_quad9.msh', 'bad_quad9.msh:561: 9-node quadrangle (second order) &
      &elements (gmsh element type 10) in physical surface 5 "ZMIN"', 'Mesh.SecondOrderIncomplete = 1')
    call expect_error(suite, 'bad_hex27.msh', '27-node hexahedron (second order) elements (gmsh &
      &element type 12) in volume 1', 'Mesh.SecondOrderIncomplete = 1')
    call expect_error(suite, 'bad_missing_node_tet10.msh', 'bad_missing_node_tet10.msh:93: element 3 &
      &refers to node 99', 'not in $Nodes')
    call expect_error(suite, 'bad_quad.msh', 'bad_quad.msh:115: 4-node quadrangle 8 (nodes 1 12 16 6)', &
      'matches no face')
    call expect_error(suite, 'bad_number.msh', 'bad_number.msh:73:', '3 coordinates of node 10')
    call expect_error(suite, 'bad_missing_node.msh', 'element 12 refers to node 99', 'not in $Nodes')
    call expect_error(suite, 'bad_not_msh.msh', 'bad_not_msh.msh:1:', 'not a gmsh mesh file')
    call expect_error(suite, 'no_such_file.msh', 'no_such_file.msh: ', 'does not exist')
  end subroutine test_bad_files

  subroutine expect_error(suite, name, fragment, other_fragment)
    type(test_suite_t), intent(inout) :: suite
    character(len=*), intent(in) :: name, fragment, other_fragment
    type(mesh_t) :: mesh
    type(error_t), allocatable :: err
    call mesh%init(catalogue_kinds())
    call read_gmsh(data_dir // name, mesh, err)
    call check_message(suite, err, name, fragment, other_fragment)
  end subroutine expect_error

  !> `err` is an input error whose message holds both fragments.
  subroutine check_message(suite, err, what, fragment, other_fragment)
    type(test_suite_t), intent(inout) :: suite
    type(error_t), allocatable, intent(in) :: err
    character(len=*), intent(in) :: what, fragment, other_fragment
    call suite%check(allocated(err), what // ': an error')
    if (.not. allocated(err)) return
    call suite%check(err%exit_code == EXIT_INPUT, what // ': an input error')
    call suite%check(index(err%message, fragment) > 0 .and. index(err%message, other_fragment) > 0, &
      what // ': message "' // err%message // '" holds "' // fragment // '" and "' // other_fragment // '"')
  end subroutine check_message

end program test_fcs_gmsh_reader
