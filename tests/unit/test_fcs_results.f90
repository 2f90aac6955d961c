!> Unit tests of fcs_hdf5 and fcs_results: a two-hexahedron mesh with three frames is written,
!> read back with fcs_hdf5 and compared exactly (values pass through HDF5 unchanged, so the
!> tolerance is zero: IEEE doubles stored as IEEE doubles); open_append after an incomplete
!> frame; and error cases, which must give messages, not crashes.
!>
!> Output stays next to the executable for post/check_xdmf.py:
!> `<directory of this program>/test_fcs_results_out/{three_frames,volume_only,append}.{h5,xdmf}`
!> (3, 2 and 4 frames),
!> e.g. build/h-io/tests/test_fcs_results_out/three_frames.xdmf.
program test_fcs_results
  use fcs_kinds, only: dp, i8
  use fcs_error, only: error_t, EXIT_INPUT
  use fcs_strings, only: string_t, dirname
  use fcs_hdf5, only: h5_file_t
  use fcs_files, only: make_directory, remove_file
  use fcs_results, only: results_file_t, GRID_POINTS, GRID_QUADS, TENSOR6_TO_XDMF
  use fcs_test_assertions, only: test_suite_t
  implicit none

  !> Values are stored bit for bit; compare exactly.
  real(dp), parameter :: EXACT = 0.0_dp
  integer, parameter :: N_NODES = 12, N_ELEMENTS = 2, N_TOP = 6, N_IP = 8
  type(test_suite_t) :: suite
  character(len=:), allocatable :: out
  integer :: node_ids(N_NODES), element_ids(N_ELEMENTS), connectivity(8, N_ELEMENTS)
  real(dp) :: x_ref(3, N_NODES)
  integer :: top_nodes(N_TOP)
  type(error_t), allocatable :: err

  suite%name = 'test_fcs_results'
  out = output_directory()
  call make_directory(out, err)
  call expect_ok(err, 'creating the output directory')
  call build_mesh()

  call test_hdf5_helpers()
  call test_three_frames()
  call test_volume_only()
  call test_read_back()
  call test_open_append()
  call test_errors()
  call suite%report()

contains

  !> `<directory of the executable>/test_fcs_results_out`.
  function output_directory() result(path)
    character(len=:), allocatable :: path
    character(len=4096) :: program_path
    call get_command_argument(0, program_path)
    path = dirname(trim(program_path)) // '/test_fcs_results_out'
  end function output_directory

  !> Two unit cubes side by side along x: nodes on a 3 x 2 x 2 lattice, C3D8 order.
  subroutine build_mesh()
    integer :: i, j, k, e
    do k = 0, 1
      do j = 0, 1
        do i = 0, 2
          x_ref(:, lattice(i, j, k)) = [real(i, dp), real(j, dp), real(k, dp)]
          node_ids(lattice(i, j, k)) = 101 + lattice(i, j, k)
        end do
      end do
    end do
    do e = 1, N_ELEMENTS
      connectivity(:, e) = [lattice(e - 1, 0, 0), lattice(e, 0, 0), lattice(e, 1, 0), &
        lattice(e - 1, 1, 0), lattice(e - 1, 0, 1), lattice(e, 0, 1), lattice(e, 1, 1), &
        lattice(e - 1, 1, 1)]
      element_ids(e) = 10 + e
    end do
    do j = 0, 1
      do i = 0, 2
        top_nodes(1 + i + 3 * j) = lattice(i, j, 1)
      end do
    end do
  end subroutine build_mesh

  pure integer function lattice(i, j, k)
    integer, intent(in) :: i, j, k
    lattice = 1 + i + 3 * j + 6 * k
  end function lattice

  ! Field values of frame f, all distinct, so that a transposition or a reordering shows.

  pure function displacement(f) result(u)
    integer, intent(in) :: f
    real(dp) :: u(3, N_NODES)
    integer :: n
    do n = 1, N_NODES
      u(:, n) = 0.01_dp * f * [x_ref(1, n) + n, 0.5_dp * x_ref(2, n) - n, -0.2_dp * x_ref(3, n)]
    end do
  end function displacement

  !> Stress in fcs3d's internal order xx, yy, zz, xy, xz, yz: component c of node n.
  pure function stress(f) result(s)
    integer, intent(in) :: f
    real(dp) :: s(6, N_NODES)
    integer :: n, c
    do n = 1, N_NODES
      do c = 1, 6
        s(c, n) = 1000.0_dp * f + 10.0_dp * n + c
      end do
    end do
  end function stress

  pure function mises(f) result(m)
    integer, intent(in) :: f
    real(dp) :: m(1, N_ELEMENTS)
    m(1, :) = [100.0_dp * f + 1.0_dp, 100.0_dp * f + 2.0_dp]
  end function mises

  pure function ip_stress(f) result(s)
    integer, intent(in) :: f
    real(dp) :: s(6, N_IP, N_ELEMENTS)
    integer :: c, q, e
    do e = 1, N_ELEMENTS
      do q = 1, N_IP
        do c = 1, 6
          s(c, q, e) = 10000.0_dp * f + 1000.0_dp * e + 10.0_dp * q + c
        end do
      end do
    end do
  end function ip_stress

  pure function pressure(f) result(p)
    integer, intent(in) :: f
    real(dp) :: p(1, N_TOP)
    integer :: i
    p(1, :) = [(-1.5_dp * f - i, i = 1, N_TOP)]
  end function pressure

  ! ---------------------------------------------------------------------------------------------

  !> fcs_hdf5 on its own: round trips, listing, existence, shapes, two files at once.
  subroutine test_hdf5_helpers()
    type(h5_file_t) :: first, second
    real(dp), allocatable :: r2(:, :), r3(:, :, :), r1(:)
    integer, allocatable :: i2(:, :)
    type(string_t), allocatable :: names(:)
    integer(i8), allocatable :: dims(:)
    character(len=:), allocatable :: text
    real(dp) :: a(2, 3), b(2, 3, 4), value
    integer :: n
    a = reshape([1.0_dp, 2.0_dp, 3.0_dp, 4.0_dp, 5.0_dp, 6.0_dp], [2, 3])
    b = reshape([(real(n, dp), n = 1, 24)], [2, 3, 4])
    call first%create(out // '/helpers.h5', err)
    call expect_ok(err, 'h5 create')
    call second%create(out // '/helpers_second.h5', err)
    call expect_ok(err, 'h5 create of a second file')
    call first%write_dataset('/a/b/matrix', a, err)
    call expect_ok(err, 'write rank 2 with intermediate groups')
    call first%write_dataset('/a/cube', b, err)
    call expect_ok(err, 'write rank 3')
    call first%write_dataset('/a/vector', [1.5_dp, -2.5_dp], err)
    call expect_ok(err, 'write rank 1')
    call first%write_dataset('/ints', reshape([1, 2, 3, 4, 5, 6], [3, 2]), err)
    call expect_ok(err, 'write int rank 2')
    call first%write_dataset('/text', 'hello, HDF5', err)
    call expect_ok(err, 'write string')
    call first%write_dataset('/empty_text', '', err)
    call expect_ok(err, 'write empty string')
    call first%write_attribute('/a', 'scale', 2.5_dp, err)
    call expect_ok(err, 'write real attribute')
    call first%write_attribute('/a', 'scale', 3.5_dp, err)
    call expect_ok(err, 'replace real attribute')
    call first%write_attribute('/a/b/matrix', 'unit', 'MPa', err)
    call expect_ok(err, 'write string attribute')
    call first%close(err)
    call expect_ok(err, 'close first file while the second is open')
    call second%write_dataset('/still_open', [7, 8, 9], err)
    call expect_ok(err, 'second file still usable after the first closed the library')
    call second%close(err)
    call expect_ok(err, 'close second file')

    call first%open(out // '/helpers.h5', .false., err)
    call expect_ok(err, 'reopen read-only after the library was closed')
    call first%read_dataset('/a/b/matrix', r2, err, expected_shape=[2, 3])
    call expect_ok(err, 'read rank 2')
    if (allocated(r2)) call suite%close_array(reshape(r2, [6]), reshape(a, [6]), EXACT, &
      'rank 2 round trip')
    call first%read_dataset('/a/cube', r3, err)
    call expect_ok(err, 'read rank 3')
    if (allocated(r3)) call suite%check(all(shape(r3) == [2, 3, 4]) .and. all(r3 == b), &
      'rank 3 round trip')
    call first%read_dataset('/a/vector', r1, err)
    call expect_ok(err, 'read rank 1')
    if (allocated(r1)) call suite%check(all(r1 == [1.5_dp, -2.5_dp]), 'rank 1 round trip')
    call first%read_dataset('/ints', i2, err)
    call expect_ok(err, 'read int rank 2')
    if (allocated(i2)) call suite%check(all(i2 == reshape([1, 2, 3, 4, 5, 6], [3, 2])), &
      'int rank 2 round trip')
    call first%read_dataset('/text', text, err)
    call expect_ok(err, 'read string')
    call suite%check(text == 'hello, HDF5', 'string round trip: "' // text // '"')
    call first%read_dataset('/empty_text', text, err)
    call expect_ok(err, 'read empty string')
    call suite%equal_int(len(text), 0, 'empty string round trip')
    call first%read_attribute('/a', 'scale', value, err)
    call expect_ok(err, 'read real attribute')
    call suite%check(value == 3.5_dp, 'replaced attribute holds the new value')
    call first%read_attribute('/a/b/matrix', 'unit', text, err)
    call expect_ok(err, 'read string attribute')
    call suite%check(text == 'MPa', 'string attribute round trip')
    call first%dataset_shape('/a/cube', dims, err)
    call expect_ok(err, 'dataset_shape')
    call suite%check(all(dims == [2_i8, 3_i8, 4_i8]), 'dataset_shape in Fortran order')
    call first%list_group('/a', names, err)
    call expect_ok(err, 'list_group')
    call suite%equal_int(size(names), 3, 'three links in /a')
    if (size(names) == 3) call suite%check(names(1)%s == 'b' .and. names(2)%s == 'cube' .and. &
      names(3)%s == 'vector', 'links listed in name order')
    call suite%check(first%exists('/a/b/matrix'), 'exists: nested dataset')
    call suite%check(.not. first%exists('/a/missing/deeper'), 'exists: missing intermediate')
    call suite%check(.not. first%exists('/a/vector/below_a_dataset'), 'exists: below a dataset')
    call suite%check(first%is_group('/a/b'), 'is_group of a group')
    call suite%check(.not. first%is_group('/a/vector'), 'is_group of a dataset')
    call first%read_dataset('/a/b/matrix', r2, err, expected_shape=[3, 2])
    call expect_error(err, 'has shape (2, 3), expected (3, 2)', 'read with the wrong shape')
    call first%read_dataset('/ints', r2, err)
    call expect_error(err, 'holds integer values, expected floating-point', 'read ints as reals')
    call first%read_dataset('/a/vector', r2, err)
    call expect_error(err, 'has rank 1, expected 2', 'read with the wrong rank')
    call first%read_dataset('/nothing/here', r1, err)
    call expect_error(err, 'dataset /nothing/here not found', 'read a missing dataset')
    call first%write_dataset('/a/new', [1.0_dp], err)
    call expect_error(err, 'the file is read-only', 'write to a read-only file')
    call first%read_attribute('/a', 'nothing', value, err)
    call expect_error(err, 'has no attribute nothing', 'read a missing attribute')
    call first%close(err)
    call expect_ok(err, 'close after reading')
  end subroutine test_hdf5_helpers

  ! ---------------------------------------------------------------------------------------------

  !> Write three frames with every kind of field.
  subroutine test_three_frames()
    type(results_file_t) :: results
    integer :: f
    call results%create(out // '/three_frames', node_ids, x_ref, element_ids, connectivity, err)
    call expect_ok(err, 'results create')
    if (allocated(err)) return
    call define_grids(results)
    do f = 1, 3
      call write_frame(results, f)
    end do
    call suite%equal_int(results%n_frames(), 3, 'n_frames after three frames')
    call results%close(err)
    call expect_ok(err, 'results close')
  end subroutine test_three_frames

  !> A point grid on the top nodes and a quadrilateral grid on the top faces.
  subroutine define_grids(results)
    type(results_file_t), intent(inout) :: results
    integer :: i
    call results%define_surface_grid('slave', GRID_POINTS, reshape([(i, i = 0, N_TOP - 1)], &
      [1, N_TOP]), err)
    call expect_ok(err, 'define POINTS grid')
    call results%define_surface_grid('top', GRID_QUADS, reshape([0, 1, 4, 3, 1, 2, 5, 4], &
      [4, 2]), err)
    call expect_ok(err, 'define QUADS grid')
  end subroutine define_grids

  !> Frame f: coordinates, displacement, stress, mises, ip stress, both surface grids.
  subroutine write_frame(results, f)
    type(results_file_t), intent(inout) :: results
    integer, intent(in) :: f
    real(dp) :: x(3, N_NODES), u(3, N_NODES)
    u = displacement(f)
    x = x_ref + u
    call results%begin_frame(0.1_dp * f, 1, f, err)
    call expect_ok(err, 'begin_frame')
    call results%write_coordinates(x, err)
    call expect_ok(err, 'write_coordinates')
    call results%write_nodal('displacement', displacement(f), err)
    call expect_ok(err, 'write_nodal vector')
    call results%write_nodal('stress', stress(f), err)
    call expect_ok(err, 'write_nodal tensor')
    call results%write_cell('mises', mises(f), err)
    call expect_ok(err, 'write_cell scalar')
    call results%write_integration_points('stress', ip_stress(f), err)
    call expect_ok(err, 'write_integration_points')
    call results%write_surface_coordinates('slave', x(:, top_nodes), err)
    call expect_ok(err, 'write_surface_coordinates POINTS')
    call results%write_surface_field('slave', 'pressure', pressure(f), err)
    call expect_ok(err, 'write_surface_field scalar')
    call results%write_surface_field('slave', 'slip', displacement(f) * 0 + 0.5_dp * f, err)
    call expect_error(err, 'values have 12 columns, expected 6 (one per node)', &
      'surface field with the volume''s node count')
    call results%write_surface_field('slave', 'slip', u(:, top_nodes), err)
    call expect_ok(err, 'write_surface_field vector')
    call results%write_surface_coordinates('top', x(:, top_nodes), err)
    call expect_ok(err, 'write_surface_coordinates QUADS')
    call results%write_surface_field('top', 'gap', pressure(f) * 2, err)
    call expect_ok(err, 'write_surface_field on QUADS')
    call results%end_frame(err)
    call expect_ok(err, 'end_frame')
  end subroutine write_frame

  !> Without surface grids, frames are single grids; a frame without write_coordinates is drawn
  !> on the reference coordinates.
  subroutine test_volume_only()
    type(results_file_t) :: results
    real(dp) :: temperature(1, N_NODES)
    integer :: n
    temperature(1, :) = [(20.0_dp + n, n = 1, N_NODES)]
    call results%create(out // '/volume_only', node_ids, x_ref, element_ids, connectivity, err)
    call expect_ok(err, 'create volume_only')
    if (allocated(err)) return
    call results%begin_frame(0.0_dp, 1, 0, err)
    call results%write_coordinates(x_ref + displacement(1), err)
    call results%write_nodal('temperature', temperature, err)
    call results%end_frame(err)
    call expect_ok(err, 'volume_only frame 1')
    call results%begin_frame(1.0_dp, 1, 1, err)
    call results%write_nodal('temperature', temperature + 1, err)
    call results%end_frame(err)
    call expect_ok(err, 'volume_only frame 2, without coordinates')
    call results%close(err)
    call expect_ok(err, 'close volume_only')
    call check_xdmf_mentions(out // '/volume_only.xdmf', 'volume_only.h5:/mesh/coordinates', 2)
  end subroutine test_volume_only

  ! ---------------------------------------------------------------------------------------------

  !> Read three_frames.h5 back with fcs_hdf5.
  subroutine test_read_back()
    type(h5_file_t) :: file
    real(dp), allocatable :: r1(:), r2(:, :), r3(:, :, :)
    integer, allocatable :: i1(:), i2(:, :)
    real(dp) :: time, expected_stress(6, N_NODES), expected_ip(6, N_IP, N_ELEMENTS)
    real(dp) :: cell_values(1, N_ELEMENTS), point_values(1, N_TOP)
    integer :: value
    character(len=:), allocatable :: text
    call file%open(out // '/three_frames.h5', .false., err)
    call expect_ok(err, 'open three_frames.h5')
    if (allocated(err)) return
    call file%read_attribute('/', 'format', text, err)
    call suite%check(text == 'fcs3d results', 'format attribute')
    call file%read_attribute('/', 'creator', text, err)
    call suite%check(text(1:min(6, len(text))) == 'fcs3d ', 'creator attribute (fcs3d version)')
    call file%read_dataset('/mesh/coordinates', r2, err, expected_shape=[3, N_NODES])
    call expect_ok(err, 'mesh coordinates shape (3, 12)')
    if (allocated(r2)) call suite%check(all(r2 == x_ref), 'reference coordinates')
    call file%read_dataset('/mesh/connectivity', i2, err, expected_shape=[8, N_ELEMENTS])
    call expect_ok(err, 'connectivity shape (8, 2)')
    if (allocated(i2)) call suite%check(all(i2 == connectivity - 1), 'connectivity is 0-based')
    call file%read_dataset('/mesh/node_ids', i1, err, expected_shape=[N_NODES])
    if (allocated(i1)) call suite%check(all(i1 == node_ids), 'node ids')
    call file%read_dataset('/mesh/element_ids', i1, err, expected_shape=[N_ELEMENTS])
    if (allocated(i1)) call suite%check(all(i1 == element_ids), 'element ids')

    call file%read_attribute('/frames/000002', 'time', time, err)
    call suite%close_to(time, 0.2_dp, EXACT, 'time of frame 2')
    call file%read_attribute('/frames/000002', 'increment', value, err)
    call suite%equal_int(value, 2, 'increment of frame 2')
    call file%read_attribute('/frames/000003', 'complete', value, err)
    call suite%equal_int(value, 1, 'frame 3 complete')
    call file%read_dataset('/frames/000002/coordinates', r2, err, expected_shape=[3, N_NODES])
    call expect_ok(err, 'frame coordinates')
    if (allocated(r2)) call suite%check(all(r2 == x_ref + displacement(2)), 'current coordinates')
    call file%read_dataset('/frames/000002/nodal/displacement', r2, err, &
      expected_shape=[3, N_NODES])
    call expect_ok(err, 'displacement')
    if (allocated(r2)) call suite%close_array(reshape(r2, [3 * N_NODES]), &
      reshape(displacement(2), [3 * N_NODES]), EXACT, 'displacement of frame 2')
    expected_stress = stress(3)
    expected_stress = expected_stress(TENSOR6_TO_XDMF, :)
    call file%read_dataset('/frames/000003/nodal/stress', r2, err, expected_shape=[6, N_NODES])
    call expect_ok(err, 'stress')
    if (allocated(r2)) then
      call suite%check(all(r2 == expected_stress), 'stress stored in XDMF Tensor6 order')
      call suite%check(r2(2, 5) == 3000.0_dp + 50 + 4, 'stored component 2 is xy (internal 4)')
      call suite%check(r2(6, 5) == 3000.0_dp + 50 + 3, 'stored component 6 is zz (internal 3)')
    end if
    call file%read_attribute('/frames/000003/nodal/stress', 'components', text, err)
    call suite%check(text == 'xx xy xz yy yz zz', 'components attribute of a tensor')
    call file%read_dataset('/frames/000001/cell/mises', r1, err, expected_shape=[N_ELEMENTS])
    call expect_ok(err, 'mises is a 1-D dataset')
    cell_values = mises(1)
    if (allocated(r1)) call suite%check(all(r1 == cell_values(1, :)), 'mises values')
    expected_ip = ip_stress(2)
    call file%read_dataset('/frames/000002/integration_points/stress', r3, err, &
      expected_shape=[6, N_IP, N_ELEMENTS])
    call expect_ok(err, 'integration-point stress shape (6, 8, 2)')
    if (allocated(r3)) call suite%check(all(r3 == expected_ip(TENSOR6_TO_XDMF, :, :)), &
      'integration-point stress values')
    call file%read_dataset('/frames/000003/surfaces/slave/nodal/pressure', r1, err, &
      expected_shape=[N_TOP])
    call expect_ok(err, 'surface pressure')
    point_values = pressure(3)
    if (allocated(r1)) call suite%check(all(r1 == point_values(1, :)), 'surface pressure values')
    call file%read_dataset('/surfaces/top/connectivity', i2, err, expected_shape=[4, 2])
    call expect_ok(err, 'quad connectivity')
    call file%close(err)
    call expect_ok(err, 'close after reading back')
    call check_xdmf_mentions(out // '/three_frames.xdmf', &
      'three_frames.h5:/frames/000003/nodal/displacement', 3)
  end subroutine test_read_back

  !> The XDMF file mentions `reference` and lists `n_frames` frames (counted by <Time> tags).
  subroutine check_xdmf_mentions(path, reference, n_frames)
    character(len=*), intent(in) :: path, reference
    integer, intent(in) :: n_frames
    character(len=1024) :: line
    integer :: unit, status, n_times
    logical :: found
    found = .false.
    n_times = 0
    open (newunit=unit, file=path, status='old', action='read', iostat=status)
    call suite%check(status == 0, 'open ' // path)
    if (status /= 0) return
    do
      read (unit, '(a)', iostat=status) line
      if (status /= 0) exit
      if (index(line, reference) > 0) found = .true.
      if (index(line, '<Time ') > 0) n_times = n_times + 1
    end do
    close (unit)
    call suite%check(found, path // ' refers to ' // reference)
    call suite%equal_int(n_times, n_frames, 'frames listed in ' // path)
  end subroutine check_xdmf_mentions

  ! ---------------------------------------------------------------------------------------------

  !> Two frames, a third left incomplete; open_append drops it and continues at 3.
  subroutine test_open_append()
    type(results_file_t) :: results
    type(h5_file_t) :: file
    real(dp) :: time
    call results%create(out // '/append', node_ids, x_ref, element_ids, connectivity, err)
    call expect_ok(err, 'create append')
    if (allocated(err)) return
    call define_grids(results)
    call write_frame(results, 1)
    call write_frame(results, 2)
    call results%begin_frame(0.3_dp, 1, 3, err)
    call results%write_nodal('displacement', displacement(3), err)
    call expect_ok(err, 'half of frame 3')
    call results%close(err)
    call expect_ok(err, 'close inside a frame')

    call results%open_append(out // '/append', err)
    call expect_ok(err, 'open_append')
    if (allocated(err)) return
    call suite%equal_int(results%n_frames(), 2, 'incomplete frame dropped')
    call check_xdmf_mentions(out // '/append.xdmf', 'append.h5:/frames/000002/nodal/stress', 2)
    call define_grids(results)
    call results%begin_frame(0.35_dp, 2, 1, err)
    call expect_ok(err, 'begin_frame after open_append')
    call results%write_nodal('displacement', displacement(4), err)
    call results%end_frame(err)
    call expect_ok(err, 'end_frame after open_append')
    call write_frame(results, 5)
    call suite%equal_int(results%n_frames(), 4, 'frames after appending two')
    call results%close(err)
    call expect_ok(err, 'close appended file')

    call file%open(out // '/append.h5', .false., err)
    call expect_ok(err, 'open append.h5')
    call file%read_attribute('/frames/000003', 'time', time, err)
    call suite%close_to(time, 0.35_dp, EXACT, 'frame 3 is the new one')
    call suite%check(.not. file%exists('/frames/000003/nodal/stress'), &
      'nothing of the dropped frame survives')
    call suite%check(file%exists('/frames/000004/surfaces/top/nodal/gap'), 'frame 4 written')
    call suite%check(.not. file%exists('/frames/000005'), 'no frame 5')
    call file%close(err)
    call expect_ok(err, 'close append.h5')
    call check_xdmf_mentions(out // '/append.xdmf', 'append.h5:/frames/000004/nodal/stress', 4)
  end subroutine test_open_append

  ! ---------------------------------------------------------------------------------------------

  !> Misuse and bad files give messages.
  subroutine test_errors()
    type(results_file_t) :: results
    type(h5_file_t) :: file
    real(dp) :: two(2, N_NODES), u(3, N_NODES)
    integer :: i
    call results%create(out // '/no/such/dir/job', node_ids, x_ref, element_ids, &
      connectivity, err)
    call expect_error(err, 'directory ' // out // '/no/such/dir does not exist', &
      'create in a missing directory')
    call suite%check(.not. results%is_open(), 'nothing open after a failed create')
    call results%open_append(out // '/missing', err)
    call expect_error(err, 'missing.h5: file not found', 'open_append of a missing file')
    if (allocated(err)) call suite%equal_int(err%exit_code, EXIT_INPUT, 'missing file is input')
    call file%create(out // '/not_results.h5', err)
    call file%write_dataset('/x', [1, 2], err)
    call file%close(err)
    call results%open_append(out // '/not_results', err)
    call expect_error(err, 'not an fcs3d results file', 'open_append of another HDF5 file')
    call results%create(out // '/bad_mesh', node_ids(1:3), x_ref, element_ids, connectivity, err)
    call expect_error(err, '3 node ids for 12 nodes', 'node ids and coordinates disagree')
    call results%create(out // '/bad_mesh', node_ids, x_ref, element_ids, connectivity + 20, err)
    call expect_error(err, 'outside 1..12', 'connectivity out of range')

    call results%create(out // '/errors', node_ids, x_ref, element_ids, connectivity, err)
    call expect_ok(err, 'create errors')
    if (allocated(err)) return
    call results%write_nodal('displacement', displacement(1), err)
    call expect_error(err, 'no frame begun', 'write before begin_frame')
    call results%define_surface_grid('bad', GRID_QUADS, reshape([0, 1, 2, -3], [4, 1]), err)
    call expect_error(err, 'connectivity refers to points outside', 'negative quad index')
    call results%define_surface_grid('volume', GRID_POINTS, reshape([0], [1, 1]), err)
    call expect_error(err, 'reserved', 'grid named volume')
    call results%define_surface_grid('pts', GRID_POINTS, reshape([(i, i = 0, 3)], [1, 4]), err)
    call expect_ok(err, 'define pts')
    call results%define_surface_grid('pts', GRID_POINTS, reshape([(i, i = 0, 4)], [1, 5]), err)
    call expect_error(err, 'already defined differently', 'redefine a grid differently')
    call results%begin_frame(1.0_dp, 1, 1, err)
    call expect_ok(err, 'begin_frame')
    call results%begin_frame(2.0_dp, 1, 2, err)
    call expect_error(err, 'is still open', 'begin_frame twice')
    two = 1.0_dp
    call results%write_nodal('two', two, err)
    call expect_error(err, 'expected 1 (scalar), 3 (vector) or 6 (tensor)', '2 components')
    u = displacement(1)
    call results%write_nodal('u', u(:, 1:5), err)
    call expect_error(err, 'values have 5 columns, expected 12', 'too few nodes')
    call results%write_nodal('a/b', displacement(1), err)
    call expect_error(err, 'invalid character "/"', 'slash in a field name')
    call results%write_nodal('u', displacement(1), err)
    call expect_ok(err, 'write u')
    call results%write_nodal('u', displacement(1), err)
    call expect_error(err, 'already in frame 1', 'same field twice')
    call results%write_cell('u', reshape([1.0_dp, 2.0_dp], [1, 2]), err)
    call expect_ok(err, 'a cell field may share a nodal field''s name')
    call results%write_coordinates(x_ref(:, 1:4), err)
    call expect_error(err, 'shape (3, 4), expected (3, 12)', 'coordinates of too few nodes')
    call results%write_surface_field('pts', 'p', reshape([1.0_dp, 2.0_dp, 3.0_dp, 4.0_dp], &
      [1, 4]), err)
    call expect_error(err, 'write the grid''s coordinates first', 'surface field first')
    call results%write_surface_coordinates('nowhere', x_ref(:, 1:4), err)
    call expect_error(err, 'surface grid "nowhere" is not defined', 'unknown surface grid')
    call results%end_frame(err)
    call expect_ok(err, 'end_frame')
    call results%close(err)
    call expect_ok(err, 'close errors')
    call results%write_nodal('u', displacement(1), err)
    call expect_error(err, 'not open', 'write after close')
    call remove_file(out // '/not_results.h5', err)
  end subroutine test_errors

  ! ---------------------------------------------------------------------------------------------

  subroutine expect_ok(error, what)
    type(error_t), allocatable, intent(in) :: error
    character(len=*), intent(in) :: what
    if (allocated(error)) then
      call suite%check(.false., what // ': unexpected error: ' // error%message)
    else
      call suite%check(.true., what)
    end if
  end subroutine expect_ok

  !> An error whose message contains `fragment`.
  subroutine expect_error(error, fragment, what)
    type(error_t), allocatable, intent(in) :: error
    character(len=*), intent(in) :: fragment, what
    if (.not. allocated(error)) then
      call suite%check(.false., what // ': no error')
    else
      call suite%check(index(error%message, fragment) > 0, what // ': message "' // &
        error%message // '" lacks "' // fragment // '"')
    end if
  end subroutine expect_error

end program test_fcs_results
