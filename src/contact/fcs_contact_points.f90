!> Slave points of a surface-to-surface contact pair (*CONTACT PAIR, TYPE=SURFACE TO SURFACE;
!> doc/theory.md 4.10): integration points of the slave faces, each a slave "node" of the
!> node-to-point element x_s = sum_a N_a(xi_q) x_a with the tributary area
!> A_q = w_q |a_1 x a_2|(xi_q) (Gauss weight times surface Jacobian, on the reference
!> configuration), so that the penalties E_n, E_t per unit area turn into the point's
!> springs as for a node (f_n = E_n A_q (-g)) and its forces spread to the face's nodes by
!> N_a(xi_q).
!>
!> Where the points lie:
!>   - a 4-node slave face that the 4-node master faces cover completely (in the reference
!>     configuration, within the search reach) is cut by the projected master faces, as
!>     CalculiX cuts its slave faces (gencontelem_f2f.f; ccx manual, "Surface-to-surface
!>     penalty contact"): each overlap polygon (fcs_tie_mortar's clipping, Puso & Laursen
!>     2004) is split into triangles with 3 points of a degree-2 rule each, so that every
!>     point lies inside one master face and a uniform pressure gives the master nodes
!>     their exact consistent forces int p N^M_I dA (the contact patch test);
!>   - any other face (triangles, 8-node quadrilaterals, faces partly beyond the master's
!>     edge or out of reach at the start): its plain Gauss rule (QUAD4 2 x 2, QUAD8 3 x 3,
!>     TRI3 and TRI6 the 3-point rule of degree 2). The slave side is then exact for a uniform
!>     pressure; the master side only as far as the points resolve the master faces.
!> The points are fixed on the slave faces; under finite sliding they are followed over the
!> master surface as nodes are (ccx cuts again in every iteration).
module fcs_contact_points
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error
  use fcs_mesh, only: mesh_t
  use fcs_contact_geometry, only: segment_point_t, segment_point
  use fcs_contact_areas, only: surface_face_nodes
  use fcs_tie_mortar, only: mortar_overlap_points, MORTAR_MAX_OVERLAP_POINTS, MORTAR_FOUND
  use fcs_strings, only: str
  implicit none
  private
  public :: slave_points_t, slave_face_points

  !> A face whose overlap points sum to within this fraction of its area is covered.
  real(dp), parameter :: COVER_TOLERANCE = 1.0e-6_dp
  real(dp), parameter :: GAUSS2 = 0.57735026918962576_dp, GAUSS3 = 0.77459666924148338_dp

  !> The slave points of one pair: point i is sum_a weight(a) x(nodes(a)) over
  !> a = ptr(i) .. ptr(i + 1) - 1, with area(i); node(i) is the face node nearest to it
  !> (largest shape function), which names it in events and outputs.
  type :: slave_points_t
    integer, allocatable :: node(:), ptr(:), nodes(:)
    real(dp), allocatable :: weight(:), area(:)
  end type slave_points_t

contains

  !> The points of the faces of slave surface `slave_surface` against the master faces
  !> `master_faces` (node indices, columns padded with 0) on coordinates x; `reach`: master
  !> faces farther than this from a slave face do not cut it.
  subroutine slave_face_points(mesh, slave_surface, master_faces, x, reach, points, err)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: slave_surface, master_faces(:, :)
    real(dp), intent(in) :: x(:, :), reach
    type(slave_points_t), intent(out) :: points
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: faces(:, :)
    real(dp), allocatable :: xi(:, :), w(:), low(:, :), high(:, :)
    integer :: f, n, q, n_points
    call surface_face_nodes(mesh, slave_surface, faces, err)
    if (allocated(err)) return
    if (size(faces, 2) == 0) then
      call input_error(err, 'surface ' // mesh%surfaces(slave_surface)%name // ' has no faces: ' // &
        'a surface-to-surface pair integrates over the slave faces')
      return
    end if
    call face_boxes(master_faces, x, low, high)
    allocate (points%node(0), points%ptr(1), points%nodes(0), points%weight(0), points%area(0))
    points%ptr(1) = 1
    do f = 1, size(faces, 2)
      n = count(faces(:, f) /= 0)
      call cut_points(faces(1:n, f), master_faces, x, reach, low, high, xi, w, n_points)
      if (n_points == 0) call gauss_points(x(:, faces(1:n, f)), xi, w, n_points)
      do q = 1, n_points
        call add_point(points, faces(1:n, f), segment_point(x(:, faces(1:n, f)), xi(:, q)), w(q))
      end do
    end do
    if (size(points%area) == 0) call input_error(err, 'surface ' // &
      mesh%surfaces(slave_surface)%name // ': no integration point on its ' // str(size(faces, 2)) // ' faces')
  end subroutine slave_face_points

  !> Append the point p of the face `nodes` with area w.
  subroutine add_point(points, nodes, p, w)
    type(slave_points_t), intent(inout) :: points
    integer, intent(in) :: nodes(:)
    type(segment_point_t), intent(in) :: p
    real(dp), intent(in) :: w
    points%node = [points%node, nodes(maxloc(p%shape(1:size(nodes)), 1))]
    points%nodes = [points%nodes, nodes]
    points%weight = [points%weight, p%shape(1:size(nodes))]
    points%ptr = [points%ptr, size(points%nodes) + 1]
    points%area = [points%area, w]
  end subroutine add_point

  !> Bounding boxes of the master faces.
  pure subroutine face_boxes(master_faces, x, low, high)
    integer, intent(in) :: master_faces(:, :)
    real(dp), intent(in) :: x(:, :)
    real(dp), allocatable, intent(out) :: low(:, :), high(:, :)
    integer :: f, n
    allocate (low(3, size(master_faces, 2)), high(3, size(master_faces, 2)))
    do f = 1, size(master_faces, 2)
      n = count(master_faces(:, f) /= 0)
      low(:, f) = minval(x(:, master_faces(1:n, f)), dim=2)
      high(:, f) = maxval(x(:, master_faces(1:n, f)), dim=2)
    end do
  end subroutine face_boxes

  !> The points of a 4- or 8-node slave face cut by the 4- or 8-node master faces overlapping
  !> it, when they cover it (n_points = 0 otherwise: the caller takes the plain Gauss rule).
  !> The cut takes the faces' corners: exact for straight-edged 8-node faces (the points'
  !> areas must then sum to the face's: a curved face falls back to the Gauss rule).
  subroutine cut_points(nodes, master_faces, x, reach, low, high, xi, w, n_points)
    integer, intent(in) :: nodes(:), master_faces(:, :)
    real(dp), intent(in) :: x(:, :), reach, low(:, :), high(:, :)
    real(dp), allocatable, intent(out) :: xi(:, :), w(:)
    integer, intent(out) :: n_points
    real(dp) :: xi_cut(2, MORTAR_MAX_OVERLAP_POINTS), w_cut(MORTAR_MAX_OVERLAP_POINTS)
    real(dp) :: slave_low(3), slave_high(3), face_area
    real(dp), allocatable :: gauss_w(:), unused(:, :)
    integer :: m, n_cut, status, n_gauss, n_master
    n_points = 0
    allocate (xi(2, 0), w(0))
    if (size(nodes) /= 4 .and. size(nodes) /= 8) return
    do m = 1, size(master_faces, 2)
      n_master = count(master_faces(:, m) /= 0)
      if (n_master /= 4 .and. n_master /= 8) return
    end do
    slave_low = minval(x(:, nodes), dim=2) - reach
    slave_high = maxval(x(:, nodes), dim=2) + reach
    do m = 1, size(master_faces, 2)
      if (any(high(:, m) < slave_low) .or. any(low(:, m) > slave_high)) cycle
      call mortar_overlap_points(x(:, nodes(1:4)), x(:, master_faces(1:4, m)), reach, &
                                 size(nodes) == 8 .or. count(master_faces(:, m) /= 0) == 8, &
                                 xi_cut, w_cut, n_cut, status)
      if (status /= MORTAR_FOUND) cycle
      xi = reshape([xi, xi_cut(:, 1:n_cut)], [2, size(w) + n_cut])
      w = [w, w_cut(1:n_cut)]
    end do
    call gauss_points(x(:, nodes), unused, gauss_w, n_gauss)
    face_area = sum(gauss_w)
    if (size(w) == 0) return
    if (abs(sum(w) - face_area) > COVER_TOLERANCE * face_area) return
    n_points = size(w)
  end subroutine cut_points

  !> The face's plain Gauss rule (module header): natural points and areas w_q |a_1 x a_2|.
  subroutine gauss_points(xf, xi, w, n_points)
    real(dp), intent(in) :: xf(:, :)
    real(dp), allocatable, intent(out) :: xi(:, :), w(:)
    integer, intent(out) :: n_points
    real(dp), allocatable :: rule_w(:)
    real(dp) :: g(3), gw(3)
    type(segment_point_t) :: p
    integer :: i, j, q
    select case (size(xf, 2))
    case (4)
      xi = reshape([-GAUSS2, -GAUSS2, GAUSS2, -GAUSS2, GAUSS2, GAUSS2, -GAUSS2, GAUSS2], [2, 4])
      rule_w = [1.0_dp, 1.0_dp, 1.0_dp, 1.0_dp]
    case (8)
      g = [-GAUSS3, 0.0_dp, GAUSS3]
      gw = [5.0_dp, 8.0_dp, 5.0_dp] / 9.0_dp
      allocate (xi(2, 9), rule_w(9))
      do j = 1, 3
        do i = 1, 3
          xi(:, i + 3 * (j - 1)) = [g(i), g(j)]
          rule_w(i + 3 * (j - 1)) = gw(i) * gw(j)
        end do
      end do
    case default
      xi = reshape([1.0_dp / 6, 1.0_dp / 6, 2.0_dp / 3, 1.0_dp / 6, 1.0_dp / 6, 2.0_dp / 3], [2, 3])
      rule_w = [1.0_dp, 1.0_dp, 1.0_dp] / 6.0_dp
    end select
    n_points = size(rule_w)
    allocate (w(n_points))
    do q = 1, n_points
      p = segment_point(xf, xi(:, q))
      w(q) = rule_w(q) * p%area_factor
    end do
  end subroutine gauss_points

end module fcs_contact_points
