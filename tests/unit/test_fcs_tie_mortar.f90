!> Unit tests of the segment-to-segment (mortar) tie integration (fcs_tie_mortar): matching
!> faces give the consistent face mass; non-matching flat patches reproduce both surfaces'
!> consistent mass and shape-function integrals (Puso 2004, the conditions for the patch
!> test); the tie is stress-free under any linear displacement field; surfaces that end at
!> edges; invariance under a rigid rotation; convergence as a face's warp vanishes; every
!> refusal flag. Oracles: 3 x 3 Gauss on each face in its natural coordinates (exact for
!> flat quads: N_a N_b J is of degree 3 in each coordinate).
program test_fcs_tie_mortar
  use fcs_kinds, only: dp
  use fcs_test_assertions, only: test_suite_t
  use fcs_contact_geometry, only: segment_point_t, segment_point
  use fcs_tie_mortar, only: mortar_pair_t, mortar_options_t, mortar_tie_t, mortar_face_pair, &
                            mortar_pair_stiffness, mortar_status_name, MORTAR_FOUND, &
                            MORTAR_NO_OVERLAP, MORTAR_TOO_FAR, MORTAR_NOT_PARALLEL, &
                            MORTAR_BAD_POLYGON, MORTAR_UNSUPPORTED_FACE, MORTAR_BAD_OPTIONS
  implicit none
  type(test_suite_t) :: suite

  !> A flat or curved patch of 4-node faces: nodes x(3, n) and faces(4, nf).
  type :: patch_t
    real(dp), allocatable :: x(:, :)
    integer, allocatable :: faces(:, :)
  end type patch_t

  real(dp), parameter :: GAUSS3(3) = [-sqrt(0.6_dp), 0.0_dp, sqrt(0.6_dp)]
  real(dp), parameter :: GAUSS3_W(3) = [5.0_dp, 8.0_dp, 5.0_dp] / 9.0_dp
  real(dp), parameter :: BIG_DISTANCE = 1.0_dp

  suite%name = 'tie_mortar'
  call test_matching_faces(suite)
  ! Parallelograms: integrands of degree <= 4, exact to round-off (some 300 points), 1e-12.
  call test_nonmatching(suite, .false., 5, 1.0e-12_dp, 'parallelogram faces')
  ! General quads: the degree-5 rule's error, measured 1.4e-6; the degree-24 rule's, 3e-15.
  call test_nonmatching(suite, .true., 5, 1.0e-5_dp, 'distorted faces, degree 5')
  call test_nonmatching(suite, .true., 24, 1.0e-12_dp, 'distorted faces, degree 24')
  call test_surface_ends(suite)
  call test_rotation(suite)
  call test_warp(suite)
  call test_warped_area(suite)
  call test_tilted(suite)
  call test_inclusion(suite)
  call test_flags(suite)
  call test_stiffness(suite)
  call suite%report()

contains

  ! ---------------------------------------------------------------- oracles and meshes

  !> Consistent mass int N_a N_b dA and int N_a dA of one face (3 x 3 Gauss).
  subroutine face_mass(x, mass, integral)
    real(dp), intent(in) :: x(3, 4)
    real(dp), intent(out) :: mass(4, 4), integral(4)
    type(segment_point_t) :: p
    integer :: i, j, a
    mass = 0.0_dp
    integral = 0.0_dp
    do j = 1, 3
      do i = 1, 3
        p = segment_point(x, [GAUSS3(i), GAUSS3(j)])
        do a = 1, 4
          mass(:, a) = mass(:, a) + GAUSS3_W(i) * GAUSS3_W(j) * p%area_factor * p%shape(1:4) * p%shape(a)
        end do
        integral = integral + GAUSS3_W(i) * GAUSS3_W(j) * p%area_factor * p%shape(1:4)
      end do
    end do
  end subroutine face_mass

  !> Global consistent mass and int N_a of a patch.
  subroutine patch_mass(patch, mass, integral)
    type(patch_t), intent(in) :: patch
    real(dp), allocatable, intent(out) :: mass(:, :), integral(:)
    real(dp) :: m(4, 4), s(4)
    integer :: f
    allocate (mass(size(patch%x, 2), size(patch%x, 2)), integral(size(patch%x, 2)))
    mass = 0.0_dp
    integral = 0.0_dp
    do f = 1, size(patch%faces, 2)
      call face_mass(patch%x(:, patch%faces(:, f)), m, s)
      mass(patch%faces(:, f), patch%faces(:, f)) = mass(patch%faces(:, f), patch%faces(:, f)) + m
      integral(patch%faces(:, f)) = integral(patch%faces(:, f)) + s
    end do
  end subroutine patch_mass

  !> A deterministic pseudo-random number in [0, 1) for integer k.
  pure function hashed(k) result(r)
    integer, intent(in) :: k
    real(dp) :: r
    r = 43758.5453123_dp * sin(12.9898_dp * k + 78.233_dp)
    r = r - floor(r)
  end function hashed

  !> An nx x ny grid of the rectangle [x0, x0 + lx] x [y0, y0 + ly] in z = 0. upward: faces
  !> ordered with normal +z (slave side), else -z (master side). perturb > 0 moves each
  !> interior node by up to perturb x the cell size (seeded by `seed`); perturb < 0 moves
  !> whole grid lines instead (the faces stay rectangles).
  function grid_patch(nx, ny, x0, y0, lx, ly, upward, perturb, seed) result(patch)
    integer, intent(in) :: nx, ny, seed
    real(dp), intent(in) :: x0, y0, lx, ly, perturb
    logical, intent(in) :: upward
    type(patch_t) :: patch
    real(dp) :: lines_x(0:nx), lines_y(0:ny), hx, hy
    integer :: i, j, n, corners(4)
    hx = lx / nx
    hy = ly / ny
    lines_x = [(x0 + i * hx, i = 0, nx)]
    lines_y = [(y0 + j * hy, j = 0, ny)]
    if (perturb < 0.0_dp) then
      lines_x(1:nx - 1) = lines_x(1:nx - 1) - perturb * hx * [(hashed(seed + i) - 0.5_dp, i = 1, nx - 1)]
      lines_y(1:ny - 1) = lines_y(1:ny - 1) - perturb * hy * [(hashed(seed + 50 + j) - 0.5_dp, j = 1, ny - 1)]
    end if
    allocate (patch%x(3, (nx + 1) * (ny + 1)), patch%faces(4, nx * ny))
    do j = 0, ny
      do i = 0, nx
        n = grid_node(nx, i, j)
        patch%x(:, n) = [lines_x(i), lines_y(j), 0.0_dp]
        if (perturb > 0.0_dp .and. i > 0 .and. i < nx .and. j > 0 .and. j < ny) then
          patch%x(1:2, n) = patch%x(1:2, n) + perturb * [hx, hy] * &
                            ([hashed(seed + 2 * n), hashed(seed + 2 * n + 1)] - 0.5_dp)
        end if
      end do
    end do
    do j = 0, ny - 1
      do i = 0, nx - 1
        corners = [grid_node(nx, i, j), grid_node(nx, i + 1, j), grid_node(nx, i + 1, j + 1), &
                   grid_node(nx, i, j + 1)]
        if (.not. upward) corners = corners([1, 4, 3, 2])
        patch%faces(:, 1 + i + nx * j) = corners
      end do
    end do
  end function grid_patch

  pure integer function grid_node(nx, i, j)
    integer, intent(in) :: nx, i, j
    grid_node = 1 + i + (nx + 1) * j
  end function grid_node

  !> Face coordinates (3, 4, nf) of a patch.
  function face_coordinates(patch) result(fx)
    type(patch_t), intent(in) :: patch
    real(dp) :: fx(3, 4, size(patch%faces, 2))
    integer :: f
    do f = 1, size(patch%faces, 2)
      fx(:, :, f) = patch%x(:, patch%faces(:, f))
    end do
  end function face_coordinates

  !> The tie between two patches with every master face a candidate of every slave face.
  subroutine tie_all_pairs(slave, master, tie, options)
    type(patch_t), intent(in) :: slave, master
    type(mortar_tie_t), intent(out) :: tie
    type(mortar_options_t), intent(in), optional :: options
    integer :: ns, nm, s, candidate_index
    integer, allocatable :: start(:), candidates(:)
    ns = size(slave%faces, 2)
    nm = size(master%faces, 2)
    start = [(1 + nm * s, s = 0, ns)]
    allocate (candidates(nm * ns))
    do s = 1, ns
      candidates(nm * (s - 1) + 1:nm * s) = [(candidate_index, candidate_index = 1, nm)]
    end do
    call tie%init(face_coordinates(slave), face_coordinates(master), start, candidates, BIG_DISTANCE, &
                  options)
  end subroutine tie_all_pairs

  !> Sums over the pairs of a tie, scattered to the nodes of each side: D, E, the row and
  !> column sums of M, and the mismatch D u_s - M u_m (slave) and E u_m - M^T u_s (master).
  subroutine tie_sums(tie, slave, master, d, e, rows, columns, area)
    type(mortar_tie_t), intent(in) :: tie
    type(patch_t), intent(in) :: slave, master
    real(dp), allocatable, intent(out) :: d(:, :), e(:, :), rows(:), columns(:)
    real(dp), intent(out) :: area
    integer :: i, sn(4), mn(4)
    allocate (d(size(slave%x, 2), size(slave%x, 2)), e(size(master%x, 2), size(master%x, 2)))
    allocate (rows(size(slave%x, 2)), columns(size(master%x, 2)))
    d = 0.0_dp
    e = 0.0_dp
    rows = 0.0_dp
    columns = 0.0_dp
    area = 0.0_dp
    do i = 1, tie%n_pairs
      sn = slave%faces(:, tie%pairs(i)%slave_face)
      mn = master%faces(:, tie%pairs(i)%master_face)
      d(sn, sn) = d(sn, sn) + tie%pairs(i)%d
      e(mn, mn) = e(mn, mn) + tie%pairs(i)%e
      rows(sn) = rows(sn) + sum(tie%pairs(i)%m, dim=2)
      columns(mn) = columns(mn) + sum(tie%pairs(i)%m, dim=1)
      area = area + tie%pairs(i)%area
    end do
  end subroutine tie_sums

  !> Largest tie residual under the linear displacement field u(x) = u0 + G x, on either side:
  !> r_s = sum (D u_s - M u_m), r_m = sum (E u_m - M^T u_s), relative to area x max |u|.
  function linear_field_residual(tie, slave, master) result(worst)
    type(mortar_tie_t), intent(in) :: tie
    type(patch_t), intent(in) :: slave, master
    real(dp) :: worst
    real(dp), parameter :: U0(3) = [0.3_dp, -0.2_dp, 0.1_dp]
    real(dp), parameter :: G(3, 3) = reshape([1.0_dp, 0.4_dp, -0.7_dp, -0.3_dp, 2.0_dp, 0.5_dp, &
                                              0.8_dp, -1.1_dp, 0.6_dp], [3, 3])
    real(dp), allocatable :: us(:, :), um(:, :), rs(:, :), rm(:, :)
    real(dp) :: area, scale
    integer :: i, sn(4), mn(4)
    us = spread(U0, 2, size(slave%x, 2)) + matmul(G, slave%x)
    um = spread(U0, 2, size(master%x, 2)) + matmul(G, master%x)
    allocate (rs, mold=us)
    allocate (rm, mold=um)
    rs = 0.0_dp
    rm = 0.0_dp
    area = 0.0_dp
    do i = 1, tie%n_pairs
      sn = slave%faces(:, tie%pairs(i)%slave_face)
      mn = master%faces(:, tie%pairs(i)%master_face)
      rs(:, sn) = rs(:, sn) + matmul(us(:, sn), tie%pairs(i)%d) - matmul(um(:, mn), transpose(tie%pairs(i)%m))
      rm(:, mn) = rm(:, mn) + matmul(um(:, mn), tie%pairs(i)%e) - matmul(us(:, sn), tie%pairs(i)%m)
      area = area + tie%pairs(i)%area
    end do
    scale = area * max(maxval(abs(us)), maxval(abs(um)))
    worst = max(maxval(abs(rs)), maxval(abs(rm))) / scale
  end function linear_field_residual

  !> A rotation about the axis (1, 2, 3) by 0.7 rad, as a matrix.
  pure function rotation() result(r)
    real(dp) :: r(3, 3)
    real(dp) :: axis(3), k(3, 3), angle
    integer :: i
    axis = [1.0_dp, 2.0_dp, 3.0_dp] / sqrt(14.0_dp)
    angle = 0.7_dp
    k = reshape([0.0_dp, axis(3), -axis(2), -axis(3), 0.0_dp, axis(1), axis(2), -axis(1), 0.0_dp], [3, 3])
    r = sin(angle) * k + (1.0_dp - cos(angle)) * matmul(k, k)
    do i = 1, 3
      r(i, i) = r(i, i) + 1.0_dp
    end do
  end function rotation

  ! ---------------------------------------------------------------- tests

  !> (1) Matching faces (a parallelogram, master nodes in the opposite order): D = E = M =
  !> the consistent face mass (M with the master's node order), entries summing to the area.
  subroutine test_matching_faces(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: xs(3, 4), xm(3, 4), mass(4, 4), integral(4)
    type(mortar_pair_t) :: pair
    integer :: status
    integer, parameter :: MASTER_ORDER(4) = [1, 4, 3, 2]
    xs = reshape([0.0_dp, 0.0_dp, 0.0_dp, 2.0_dp, 0.5_dp, 0.0_dp, 2.6_dp, 1.7_dp, 0.0_dp, &
                  0.6_dp, 1.2_dp, 0.0_dp], [3, 4])
    xm = xs(:, MASTER_ORDER)
    call face_mass(xs, mass, integral)
    call mortar_face_pair(xs, xm, BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_FOUND, 'matching faces overlap')
    ! Parallelogram faces: degree-4 integrands under a degree-5 rule, exact to round-off.
    call suite%close_array(reshape(pair%d, [16]), reshape(mass, [16]), 1.0e-13_dp, 'matching: D = mass')
    call suite%close_array(reshape(pair%e, [16]), reshape(mass(MASTER_ORDER, MASTER_ORDER), [16]), &
                           1.0e-13_dp, 'matching: E = mass')
    call suite%close_array(reshape(pair%m, [16]), reshape(mass(:, MASTER_ORDER), [16]), 1.0e-13_dp, &
                           'matching: M = mass')
    call suite%close_to(sum(pair%d), sum(integral), 1.0e-14_dp, 'matching: sum of D = area')
    call suite%close_to(pair%area, 2.0_dp * 1.2_dp - 0.5_dp * 0.6_dp, 1.0e-14_dp, 'matching: area')
  end subroutine test_matching_faces

  !> (2) and (3): a 3 x 3 slave mesh over a 2 x 2 master mesh of the same square, interior
  !> nodes perturbed (flat). The sums over the pairs reproduce both surfaces' consistent mass
  !> and int N (row and column sums of M), and a linear field leaves no tie residual.
  !> distorted = .false.: grid lines moved (rectangular faces), then the whole plane sheared
  !> (parallelograms): all integrands are polynomials of degree <= 4, integrated exactly.
  !> distorted = .true.: every interior node moved independently (general quads): the
  !> inverse bilinear maps are not polynomial, so the sums carry the quadrature error of the
  !> rule of the given degree; `tolerance` bounds the relative errors of the sums.
  subroutine test_nonmatching(suite, distorted, degree, tolerance, label)
    type(test_suite_t), intent(inout) :: suite
    logical, intent(in) :: distorted
    integer, intent(in) :: degree
    real(dp), intent(in) :: tolerance
    character(len=*), intent(in) :: label
    type(patch_t) :: slave, master
    type(mortar_tie_t) :: tie
    real(dp), allocatable :: d(:, :), e(:, :), rows(:), columns(:), mass_s(:, :), mass_m(:, :)
    real(dp), allocatable :: integral_s(:), integral_m(:)
    real(dp), parameter :: SHEAR(2, 2) = reshape([1.0_dp, 0.2_dp, 0.45_dp, 0.9_dp], [2, 2])
    real(dp) :: area
    character(len=40) :: measured
    if (distorted) then
      slave = grid_patch(3, 3, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, .true., 0.5_dp, 11)
      master = grid_patch(2, 2, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, .false., 0.6_dp, 23)
    else
      slave = grid_patch(3, 3, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, .true., -0.5_dp, 11)
      master = grid_patch(2, 2, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, .false., -0.6_dp, 23)
      slave%x(1:2, :) = matmul(SHEAR, slave%x(1:2, :))
      master%x(1:2, :) = matmul(SHEAR, master%x(1:2, :))
    end if
    call tie_all_pairs(slave, master, tie, mortar_options_t(degree=degree))
    call patch_mass(slave, mass_s, integral_s)
    call patch_mass(master, mass_m, integral_m)
    call tie_sums(tie, slave, master, d, e, rows, columns, area)
    call suite%check(tie%n_refused == 0, label // ': no pair refused')
    call suite%equal_int(tie%status_count(MORTAR_FOUND), tie%n_pairs, label // ': pairs counted')
    call suite%close_to(area, sum(integral_s), 1.0e-13_dp, label // ': overlap area = slave area')
    call suite%close_array(reshape(d, [size(d)]), reshape(mass_s, [size(mass_s)]), tolerance, &
                           label // ': sum of D = slave consistent mass')
    call suite%close_array(reshape(e, [size(e)]), reshape(mass_m, [size(mass_m)]), tolerance, &
                           label // ': sum of E = master consistent mass')
    call suite%close_array(rows, integral_s, tolerance, label // ': row sums of M = int N^S')
    call suite%close_array(columns, integral_m, tolerance, label // ': column sums of M = int N^M')
    write (measured, '(es9.2)') max(maxval(abs(d - mass_s)) / maxval(abs(mass_s)), &
                                     maxval(abs(e - mass_m)) / maxval(abs(mass_m)), &
                                     maxval(abs(rows - integral_s)) / maxval(abs(integral_s)), &
                                     maxval(abs(columns - integral_m)) / maxval(abs(integral_m)))
    print '(a)', '  ' // label // ': largest relative error of the sums ' // trim(measured)
    ! (3) Pointwise identity at every quadrature point: round-off only, whatever the shapes.
    call suite%close_to(linear_field_residual(tie, slave, master), 0.0_dp, 1.0e-14_dp, &
                        label // ': linear field, no tie residual', floor=1.0_dp)
  end subroutine test_nonmatching

  !> (4) Surfaces that end at edges: a 3 x 2 slave mesh of [-0.3, 1.2] x [0.2, 1.4] over a
  !> 2 x 2 master mesh of the unit square: only [0, 1] x [0.2, 1] (area 0.8) is integrated.
  subroutine test_surface_ends(suite)
    type(test_suite_t), intent(inout) :: suite
    type(patch_t) :: slave, master
    type(mortar_tie_t) :: tie
    real(dp), allocatable :: d(:, :), e(:, :), rows(:), columns(:)
    real(dp) :: area, expected_columns(9)
    real(dp), parameter :: HAT_X(0:2) = [0.25_dp, 0.5_dp, 0.25_dp]
    real(dp), parameter :: HAT_Y(0:2) = [0.09_dp, 0.21_dp + 0.25_dp, 0.25_dp]
    integer :: i, j
    slave = grid_patch(3, 2, -0.3_dp, 0.2_dp, 1.5_dp, 1.2_dp, .true., 0.0_dp, 0)
    master = grid_patch(2, 2, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, .false., 0.0_dp, 0)
    call tie_all_pairs(slave, master, tie)
    call tie_sums(tie, slave, master, d, e, rows, columns, area)
    call suite%close_to(area, 0.8_dp, 1.0e-14_dp, 'edges: overlap area')
    call suite%close_to(sum(d), 0.8_dp, 1.0e-13_dp, 'edges: sum of D = overlap area')
    call suite%close_to(sum(e), 0.8_dp, 1.0e-13_dp, 'edges: sum of E = overlap area')
    call suite%close_to(sum(rows), 0.8_dp, 1.0e-13_dp, 'edges: sum of M = overlap area')
    ! Master cells 0.5 x 0.5; rows y = 0, 0.5, 1 of its nodes; the strip y < 0.2 is left out.
    ! int over [0.2, 0.5] of the hat functions of y = 0 and y = 0.5: 0.09 and 0.21 (per unit
    ! length in x), and over [0.5, 1]: 0.25 each side of y = 0.5 and 0.25 for y = 1.
    do j = 0, 2
      do i = 0, 2
        expected_columns(1 + i + 3 * j) = HAT_X(i) * HAT_Y(j)
      end do
    end do
    call suite%close_array(columns, expected_columns, 1.0e-13_dp, &
                           'edges: column sums of M = int N^M over the overlap')
    call suite%check(all(tie%pairs(1:tie%n_pairs)%area > 0.0_dp), 'edges: only overlapping pairs kept')
  end subroutine test_surface_ends

  !> (5) The parallelogram patches of test 2, rotated and moved: the same matrices.
  subroutine test_rotation(suite)
    type(test_suite_t), intent(inout) :: suite
    type(patch_t) :: slave, master, slave_r, master_r
    type(mortar_tie_t) :: tie, tie_r
    real(dp) :: r(3, 3), worst
    integer :: i
    slave = grid_patch(3, 3, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, .true., -0.5_dp, 5)
    master = grid_patch(2, 2, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, .false., -0.6_dp, 7)
    r = rotation()
    slave_r = slave
    master_r = master
    slave_r%x = matmul(r, slave%x) + spread([3.0_dp, -1.0_dp, 2.0_dp], 2, size(slave%x, 2))
    master_r%x = matmul(r, master%x) + spread([3.0_dp, -1.0_dp, 2.0_dp], 2, size(master%x, 2))
    call tie_all_pairs(slave, master, tie)
    call tie_all_pairs(slave_r, master_r, tie_r)
    call suite%equal_int(tie_r%n_pairs, tie%n_pairs, 'rotated: same pairs')
    if (tie_r%n_pairs /= tie%n_pairs) return
    worst = 0.0_dp
    do i = 1, tie%n_pairs
      worst = max(worst, maxval(abs(tie_r%pairs(i)%d - tie%pairs(i)%d)), &
                  maxval(abs(tie_r%pairs(i)%m - tie%pairs(i)%m)), &
                  maxval(abs(tie_r%pairs(i)%e - tie%pairs(i)%e)))
    end do
    ! Round-off of the rotated coordinates (size 3) against entries of ~1e-3: 1e-12 absolute.
    call suite%close_to(worst, 0.0_dp, 1.0e-12_dp, 'rotated: same D, M, E', floor=1.0_dp)
  end subroutine test_rotation

  !> (6) A slave face warped by +-w at its corners over a flat matching master: the matrices
  !> tend to the flat ones as w -> 0, as w^2 (the area factor and the lift are even in w).
  subroutine test_warp(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: xs(3, 4), xm(3, 4), w, change(4)
    type(mortar_pair_t) :: flat, warped
    integer :: status, k
    xs = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, &
                  0.0_dp, 1.0_dp, 0.0_dp], [3, 4])
    xm = xs(:, [1, 4, 3, 2])
    call mortar_face_pair(xs, xm, BIG_DISTANCE, flat, status)
    do k = 1, 4
      w = 0.1_dp / 2**(k - 1)
      xs(3, :) = w * [1.0_dp, -1.0_dp, 1.0_dp, -1.0_dp]
      call mortar_face_pair(xs, xm, BIG_DISTANCE, warped, status)
      call suite%equal_int(status, MORTAR_FOUND, 'warped face overlaps')
      change(k) = max(maxval(abs(warped%d - flat%d)), maxval(abs(warped%m - flat%m)), &
                      maxval(abs(warped%e - flat%e)))
    end do
    print '(a, 4es10.2)', '  warp 0.1, 0.05, 0.025, 0.0125: largest change of D, M, E', change
    call suite%check(all(change(2:) < change(:3)), 'warp: the change decreases with the warp')
    ! O(w^2): halving w divides the change by 4 (3.9-4.1 allows the w^4 term at w = 0.1).
    call suite%check(all(abs(change(:3) / change(2:) - 4.0_dp) < 0.1_dp), 'warp: the change is O(w^2)')
    call suite%check(change(4) < 1.0e-4_dp, 'warp: small warp, small change')
  end subroutine test_warp

  !> A strongly warped slave face (corners +-0.2 out of plane on a unit square) over a larger
  !> flat master: D is the warped face's consistent mass and the area its surface area, which
  !> checks the plane-to-surface area factor. Reference: 3-point Gauss on a 24 x 24
  !> subdivision of the natural square (error ~ (1/24)^6 relative). Measured agreement at
  !> degree 24: 2e-14 (area), 2.4e-13 (D); asserted 1e-10.
  subroutine test_warped_area(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: xs(3, 4), xm(3, 4), mass(4, 4), area, wq
    type(segment_point_t) :: p
    type(mortar_pair_t) :: pair
    integer :: status, cell_i, cell_j, i, j, a
    integer, parameter :: CELLS = 24
    xs = reshape([0.0_dp, 0.0_dp, 0.2_dp, 1.0_dp, 0.0_dp, -0.2_dp, 1.0_dp, 1.0_dp, 0.2_dp, &
                  0.0_dp, 1.0_dp, -0.2_dp], [3, 4])
    xm = reshape([-1.0_dp, -1.0_dp, -0.3_dp, -1.0_dp, 2.0_dp, -0.3_dp, 2.0_dp, 2.0_dp, -0.3_dp, &
                  2.0_dp, -1.0_dp, -0.3_dp], [3, 4])
    mass = 0.0_dp
    area = 0.0_dp
    do cell_j = 1, CELLS
      do cell_i = 1, CELLS
        do j = 1, 3
          do i = 1, 3
            p = segment_point(xs, -1.0_dp + ([cell_i, cell_j] - 0.5_dp + 0.5_dp * [GAUSS3(i), GAUSS3(j)]) &
                              * 2.0_dp / CELLS)
            wq = GAUSS3_W(i) * GAUSS3_W(j) * p%area_factor / CELLS**2
            do a = 1, 4
              mass(:, a) = mass(:, a) + wq * p%shape(1:4) * p%shape(a)
            end do
            area = area + wq
          end do
        end do
      end do
    end do
    call mortar_face_pair(xs, xm, BIG_DISTANCE, pair, status, mortar_options_t(degree=24))
    call suite%equal_int(status, MORTAR_FOUND, 'warped slave over a flat master: found')
    call suite%close_to(pair%area, area, 1.0e-10_dp, 'warped slave: area = surface area')
    call suite%close_array(reshape(pair%d, [16]), reshape(mass, [16]), 1.0e-10_dp, &
                           'warped slave: D = consistent mass of the warped face')
  end subroutine test_warped_area

  !> A master face tilted by 20 degrees (accepted): M still sums row-wise to D's row sums
  !> (the master functions' partition of unity at the closest points), so a rigid
  !> translation of both sides leaves no tie force.
  subroutine test_tilted(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: xs(3, 4), xm(3, 4)
    type(mortar_pair_t) :: pair
    integer :: status
    xs = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, &
                  0.0_dp, 1.0_dp, 0.0_dp], [3, 4])
    xm = reshape([0.2_dp, 0.1_dp, 0.0_dp, 0.2_dp, 1.3_dp, 0.0_dp, 1.4_dp, 1.3_dp, 0.0_dp, &
                  1.4_dp, 0.1_dp, 0.0_dp], [3, 4])
    xm(3, :) = 0.05_dp + tan(20.0_dp * acos(-1.0_dp) / 180) * (xm(1, :) - 0.5_dp)
    call mortar_face_pair(xs, xm, BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_FOUND, 'master tilted by 20 degrees: found')
    call suite%close_to(pair%area, 0.8_dp * 0.9_dp, 1.0e-14_dp, 'tilted: overlap area (projected)')
    call suite%close_array(sum(pair%m, dim=2), sum(pair%d, dim=2), 1.0e-14_dp, &
                           'tilted: row sums of M = row sums of D')
    call suite%close_to(sum(pair%e), pair%area, 1.0e-14_dp, 'tilted: sum of E = area')
  end subroutine test_tilted

  !> A master face inside a slave face, and the other way round.
  subroutine test_inclusion(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: big(3, 4), small(3, 4), mass(4, 4), integral(4)
    type(mortar_pair_t) :: pair
    integer :: status
    big = reshape([0.0_dp, 0.0_dp, 0.0_dp, 2.0_dp, 0.0_dp, 0.0_dp, 2.0_dp, 2.0_dp, 0.0_dp, &
                   0.0_dp, 2.0_dp, 0.0_dp], [3, 4])
    small = reshape([0.5_dp, 0.6_dp, 0.0_dp, 0.7_dp, 1.5_dp, 0.0_dp, 1.4_dp, 1.3_dp, 0.0_dp, &
                     1.2_dp, 0.4_dp, 0.0_dp], [3, 4])
    call face_mass(small(:, [1, 4, 3, 2]), mass, integral)
    call mortar_face_pair(big, small, BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_FOUND, 'master inside slave: found')
    call suite%close_to(pair%area, sum(integral), 1.0e-14_dp, 'master inside slave: area = master area')
    ! E integrates the master's functions over the whole (flat, general) master face: the
    ! degree-5 rule's error on this quad, measured below 1e-6.
    call suite%close_array(reshape(pair%e, [16]), reshape(mass(:, :), [16]), 1.0e-5_dp, &
                           'master inside slave: E = master mass')
    call face_mass(small(:, [1, 4, 3, 2]), mass, integral)
    call mortar_face_pair(small(:, [1, 4, 3, 2]), big(:, [1, 4, 3, 2]), BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_FOUND, 'slave inside master: found')
    call suite%close_to(pair%area, sum(integral), 1.0e-14_dp, 'slave inside master: area = slave area')
    call suite%close_array(reshape(pair%d, [16]), reshape(mass, [16]), 1.0e-5_dp, &
                           'slave inside master: D = slave mass')
  end subroutine test_inclusion

  !> Refusals: separated, touching, far, tilted, same-facing, non-convex, degenerate faces,
  !> an unsupported node count.
  subroutine test_flags(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: xs(3, 4), xm(3, 4), unit(3, 4), tilted(3, 4)
    type(mortar_pair_t) :: pair
    type(mortar_options_t) :: options
    integer :: status
    unit = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, &
                    0.0_dp, 1.0_dp, 0.0_dp], [3, 4])
    xs = unit
    xm = unit(:, [1, 4, 3, 2]) + spread([2.0_dp, 0.0_dp, 0.0_dp], 2, 4)
    call mortar_face_pair(xs, xm, BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_NO_OVERLAP, 'separated faces: no overlap')
    call suite%check(pair%area == 0.0_dp .and. all(pair%d == 0.0_dp), 'no overlap: nothing returned')
    xm = unit(:, [1, 4, 3, 2]) + spread([1.0_dp, 0.0_dp, 0.0_dp], 2, 4)
    call mortar_face_pair(xs, xm, BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_NO_OVERLAP, 'faces touching along an edge: no overlap')
    xm = unit(:, [1, 4, 3, 2]) + spread([1.0_dp, 1.0_dp, 0.0_dp], 2, 4)
    call mortar_face_pair(xs, xm, BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_NO_OVERLAP, 'faces touching at a corner: no overlap')
    xm = unit(:, [1, 4, 3, 2]) + spread([0.3_dp, 0.2_dp, 0.05_dp], 2, 4)
    call mortar_face_pair(xs, xm, 0.01_dp, pair, status)
    call suite%equal_int(status, MORTAR_TOO_FAR, 'master 0.05 away, tolerance 0.01: too far')
    call mortar_face_pair(xs, xm, 0.06_dp, pair, status)
    call suite%equal_int(status, MORTAR_FOUND, 'master 0.05 away, tolerance 0.06: found')
    call suite%close_to(pair%area, 0.7_dp * 0.8_dp, 1.0e-14_dp, 'offset master: overlap area')
    tilted = unit(:, [1, 4, 3, 2])
    tilted(3, :) = [0.0_dp, 0.0_dp, 1.2_dp, 1.2_dp]
    call mortar_face_pair(xs, tilted, BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_NOT_PARALLEL, 'master tilted by 50 degrees: not parallel')
    options%min_cosine = 0.6_dp
    call mortar_face_pair(xs, tilted, BIG_DISTANCE, pair, status, options)
    call suite%equal_int(status, MORTAR_FOUND, 'tilted by 50 degrees, 53 allowed: found')
    call mortar_face_pair(xs, unit, BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_NOT_PARALLEL, 'normals pointing the same way: refused')
    options = mortar_options_t(opposed=.false.)
    call mortar_face_pair(xs, unit, BIG_DISTANCE, pair, status, options)
    call suite%equal_int(status, MORTAR_FOUND, 'same way, opposed=.false.: found')
    xm = unit(:, [1, 4, 3, 2])
    xm(1:2, 3) = [0.3_dp, 0.3_dp]
    call mortar_face_pair(xs, xm, BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_BAD_POLYGON, 'non-convex master: refused')
    xm = unit(:, [1, 4, 3, 2])
    xm(:, 3) = xm(:, 4)
    call mortar_face_pair(xs, xm, BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_BAD_POLYGON, 'degenerate master (two nodes coincide): refused')
    call mortar_face_pair(xs(:, 1:3), xm(:, 1:3), BIG_DISTANCE, pair, status)
    call suite%equal_int(status, MORTAR_UNSUPPORTED_FACE, '3-node faces: unsupported for now')
    call mortar_face_pair(unit, unit(:, [1, 4, 3, 2]), BIG_DISTANCE, pair, status, &
                          mortar_options_t(degree=4))
    call suite%equal_int(status, MORTAR_BAD_OPTIONS, 'degree 4: bad options')
    call suite%check(mortar_status_name(MORTAR_BAD_POLYGON) == 'non-convex or degenerate projected face', &
                     'status names')
    call test_tie_refusals(suite, unit)
  end subroutine test_flags

  !> mortar_tie_t keeps the pairs found, counts every outcome and lists the refused pairs:
  !> one slave face against a matching master, a separated one and a non-convex one.
  subroutine test_tie_refusals(suite, unit)
    type(test_suite_t), intent(inout) :: suite
    real(dp), intent(in) :: unit(3, 4)
    type(mortar_tie_t) :: tie
    real(dp) :: slave_x(3, 4, 1), master_x(3, 4, 3)
    slave_x(:, :, 1) = unit
    master_x(:, :, 1) = unit(:, [1, 4, 3, 2])
    master_x(:, :, 2) = unit(:, [1, 4, 3, 2]) + spread([5.0_dp, 0.0_dp, 0.0_dp], 2, 4)
    master_x(:, :, 3) = unit(:, [1, 4, 3, 2])
    master_x(1:2, 3, 3) = [0.3_dp, 0.3_dp]
    call tie%init(slave_x, master_x, [1, 4], [3, 2, 1], BIG_DISTANCE)
    call suite%equal_int(tie%n_pairs, 1, 'tie: one pair found')
    call suite%equal_int(tie%pairs(1)%master_face, 1, 'tie: the matching master face')
    call suite%equal_int(tie%status_count(MORTAR_NO_OVERLAP), 1, 'tie: one pair without overlap')
    call suite%equal_int(tie%n_refused, 1, 'tie: one pair refused')
    call suite%check(all(tie%refused(:, 1) == [1, 3, MORTAR_BAD_POLYGON]), &
                     'tie: refusal names slave 1, master 3, bad polygon')
    call tie%free()
    call suite%check(.not. allocated(tie%pairs) .and. tie%n_pairs == 0, 'tie: free')
  end subroutine test_tie_refusals

  !> The pair stiffness k [D, -M; -M^T, E] x I_3: symmetric, no force under a rigid
  !> translation, energy (k/2) |delta|^2 area for a uniform gap delta, positive semidefinite.
  subroutine test_stiffness(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp) :: xs(3, 4), xm(3, 4), translation(24), gap(24), v(24), k(24, 24)
    real(dp), parameter :: PENALTY = 1.0e3_dp, DELTA(3) = [0.01_dp, -0.02_dp, 0.005_dp]
    type(mortar_pair_t) :: pair
    integer :: status, trial, i
    xs = reshape([0.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, 1.0_dp, 0.0_dp, &
                  0.0_dp, 1.0_dp, 0.0_dp], [3, 4])
    xm = xs(:, [1, 4, 3, 2]) + spread([0.3_dp, -0.2_dp, 0.0_dp], 2, 4)
    call mortar_face_pair(xs, xm, BIG_DISTANCE, pair, status)
    k = mortar_pair_stiffness(pair, PENALTY)
    call suite%check(all(k == transpose(k)), 'stiffness symmetric')
    translation = [([0.2_dp, -0.4_dp, 0.7_dp], trial = 1, 8)]
    call suite%close_to(maxval(abs(matmul(k, translation))), 0.0_dp, 1.0e-12_dp, &
                        'stiffness: rigid translation, no force', floor=PENALTY)
    gap = [([DELTA], trial = 1, 4), ([0.0_dp, 0.0_dp, 0.0_dp], trial = 1, 4)]
    call suite%close_to(0.5_dp * dot_product(gap, matmul(k, gap)), 0.5_dp * PENALTY * &
                        sum(DELTA**2) * pair%area, 1.0e-13_dp, 'stiffness: energy of a uniform gap')
    do trial = 1, 5
      v = [(hashed(24 * trial + i), i = 1, 24)] - 0.5_dp
      call suite%check(dot_product(v, matmul(k, v)) >= -1.0e-12_dp * PENALTY, &
                       'stiffness positive semidefinite')
    end do
  end subroutine test_stiffness

end program test_fcs_tie_mortar
