!> Tributary areas of slave nodes: the slave node's share A_s of the slave surface, so that
!> penalty stiffnesses and frictional stresses per unit area turn into nodal forces
!> (f_n = E_n A_s (-g)). On a face of the slave surface:
!>   - 3-node triangles, 4-node quadrilaterals and 6-node triangles: the consistent share
!>     A_k = int M_k dA (the nodal forces of a uniform traction), by Gauss quadrature with the
!>     face's own shape functions (2x2 points on the bilinear face, as before; 3 points on
!>     triangles, exact for the quadratic M_k on a flat face). On a flat 6-node triangle this
!>     gives 1/3 of the face's area to each mid-side node and nothing to the corners.
!>   - 8-node quadrilaterals: the plain integral gives the corners -1/12 and the mid-sides
!>     1/3 of the area (a uniform pressure pulls the corners); like CalculiX (ccx manual,
!>     section "Node-to-face penalty contact": "the weights are modified into 24/100 and
!>     1/100"), the corners get 1/100 and the mid-side nodes 24/100 of the face's area
!>     A = int dA (3x3 Gauss points).
!> A node whose total share is not positive (the corners of a surface of 6-node triangles)
!> carries no contact force under a uniform pressure: it is left out of the pair's slave
!> nodes (slave_node_areas marks it) rather than given a penalty spring of zero area.
!> A node-based slave surface has no faces of its own: the exterior element faces of the mesh
!> whose nodes all belong to it are used. A node of it on no such face (a single slave node)
!> gets CalculiX's area instead: each exterior element face that contains the node gives it
!> its area divided by its number of nodes (gencontelem_n2f.f sums areaslav/nodes over the
!> faces at the node; measured with ccx 2.20 on a corner node of a block: the three faces'
!> quarters).
module fcs_contact_areas
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error
  use fcs_mesh, only: mesh_t, SURFACE_FACES
  use fcs_contact_geometry, only: segment_point_t, segment_point
  use fcs_face_kind, only: face_shape_functions
  use fcs_strings, only: str
  implicit none
  private
  public :: slave_node_areas, surface_face_nodes, face_node_areas

  !> CalculiX's shares of the face area for the corner and mid-side nodes of an 8-node
  !> quadrilateral slave face.
  real(dp), parameter :: QUAD8_CORNER_SHARE = 0.01_dp, QUAD8_MIDSIDE_SHARE = 0.24_dp
  !> A node's share at most this fraction of the largest one counts as none.
  real(dp), parameter :: NO_AREA = 1.0e-12_dp

contains

  !> Areas of `slaves` (node indices) from surface `k` of the mesh. `carries(i)` is false for
  !> a slave node whose consistent share of the surface is zero (the corner of 6-node
  !> triangles); a node of the surface on no face of it is an input error.
  subroutine slave_node_areas(mesh, k, slaves, areas, err, carries)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: k, slaves(:)
    real(dp), allocatable, intent(out) :: areas(:)
    type(error_t), allocatable, intent(out) :: err
    logical, allocatable, intent(out), optional :: carries(:)
    real(dp), allocatable :: nodal(:), shares(:)
    logical, allocatable :: on_face(:)
    integer, allocatable :: face_nodes(:, :)
    integer :: i, f, n
    call surface_face_nodes(mesh, k, face_nodes, err)
    if (allocated(err)) return
    allocate (nodal(mesh%n_nodes), on_face(mesh%n_nodes))
    nodal = 0.0_dp
    on_face = .false.
    do f = 1, size(face_nodes, 2)
      n = count(face_nodes(:, f) /= 0)
      if (n == 4) then
        ! Summed into the nodes point by point, as always (the same round-off).
        shares = nodal(face_nodes(1:4, f))
        call add_face(mesh%x(:, face_nodes(1:4, f)), shares)
        nodal(face_nodes(1:4, f)) = shares
      else
        nodal(face_nodes(1:n, f)) = nodal(face_nodes(1:n, f)) + face_node_areas(mesh%x(:, face_nodes(1:n, f)))
      end if
      on_face(face_nodes(1:n, f)) = .true.
    end do
    areas = nodal(slaves)
    if (mesh%surfaces(k)%kind /= SURFACE_FACES .and. .not. all(on_face(slaves))) &
      call add_lonely_node_areas(mesh, slaves, on_face(slaves), areas)
    if (present(carries)) carries = areas > NO_AREA * maxval(areas, mask=areas > 0.0_dp)
    do i = 1, size(slaves)
      if (areas(i) > 0.0_dp) cycle
      if (on_face(slaves(i)) .and. present(carries)) cycle
      call input_error(err, 'slave node ' // str(mesh%node_id(slaves(i))) // ' of surface ' // &
        mesh%surfaces(k)%name // ' lies on no exterior face of the slave body, so it has no ' // &
        'contact area (define the slave surface by element faces)')
      return
    end do
  end subroutine slave_node_areas

  !> Areas of the slave nodes of a node-based surface that lie on no face of it (on_face
  !> false), as CalculiX gives them (module header): the sum over the exterior element faces
  !> containing the node of the face's area divided by its number of nodes.
  subroutine add_lonely_node_areas(mesh, slaves, on_face, areas)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: slaves(:)
    logical, intent(in) :: on_face(:)
    real(dp), intent(inout) :: areas(:)
    integer, allocatable :: lonely(:), faces(:, :)
    integer :: f, i, n
    real(dp) :: share
    lonely = pack(slaves, .not. on_face)
    call exterior_faces_of_nodes(mesh, lonely, faces, touching=.true.)
    do f = 1, size(faces, 2)
      n = count(faces(:, f) /= 0)
      share = sum(face_node_areas(mesh%x(:, faces(1:n, f)))) / n
      do i = 1, size(slaves)
        if (.not. on_face(i) .and. any(faces(1:n, f) == slaves(i))) areas(i) = areas(i) + share
      end do
    end do
  end subroutine add_lonely_node_areas

  !> The faces of surface k (node indices, outward, corners first; a column as long as the
  !> largest face, a smaller face padded with 0): its element faces, or for a node-based
  !> surface the exterior element faces of the mesh whose nodes all belong to it.
  subroutine surface_face_nodes(mesh, k, face_nodes, err)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: k
    integer, allocatable, intent(out) :: face_nodes(:, :)
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: nodes(:)
    integer :: f, width
    if (mesh%surfaces(k)%kind == SURFACE_FACES) then
      width = 0
      do f = 1, size(mesh%surfaces(k)%element)
        width = max(width, size(mesh%face_nodes(mesh%surfaces(k)%element(f), mesh%surfaces(k)%face(f))))
      end do
      allocate (face_nodes(width, size(mesh%surfaces(k)%element)))
      face_nodes = 0
      do f = 1, size(face_nodes, 2)
        nodes = mesh%face_nodes(mesh%surfaces(k)%element(f), mesh%surfaces(k)%face(f))
        if (all(size(nodes) /= [3, 4, 6, 8])) then
          call input_error(err, 'surface ' // mesh%surfaces(k)%name // ': face S' // &
            str(mesh%surfaces(k)%face(f)) // ' of element ' // &
            str(mesh%element_id(mesh%surfaces(k)%element(f))) // ' has ' // str(size(nodes)) // &
            ' nodes; contact faces have 3, 4, 6 or 8 nodes')
          return
        end if
        face_nodes(1:size(nodes), f) = nodes
      end do
    else
      call exterior_faces_of_nodes(mesh, mesh%surfaces(k)%nodes, face_nodes)
    end if
  end subroutine surface_face_nodes

  !> The slave areas a face with node coordinates xf(3, n) gives its n nodes (module header).
  function face_node_areas(xf) result(a)
    real(dp), intent(in) :: xf(:, :)
    real(dp) :: a(size(xf, 2))
    select case (size(xf, 2))
    case (4)
      a = 0.0_dp
      call add_face(xf, a)
    case (3, 6)
      a = triangle_integrals(xf)
    case (8)
      a(1:4) = QUAD8_CORNER_SHARE * quad8_area(xf)
      a(5:8) = QUAD8_MIDSIDE_SHARE / QUAD8_CORNER_SHARE * a(1:4)
    case default
      a = 0.0_dp
    end select
  end function face_node_areas

  !> int N_a dA of a bilinear face, 2x2 Gauss points.
  subroutine add_face(xf, nodal)
    real(dp), intent(in) :: xf(:, :)
    real(dp), intent(inout) :: nodal(:)
    real(dp), parameter :: g = 0.57735026918962576451_dp
    real(dp), parameter :: points(2, 4) = reshape([-g, -g, g, -g, g, g, -g, g], [2, 4])
    type(segment_point_t) :: p
    integer :: q
    do q = 1, 4
      p = segment_point(xf, points(:, q))
      nodal = nodal + p%shape(1:4) * p%area_factor
    end do
  end subroutine add_face

  !> int M_k dA of a 3- or 6-node triangle: the 3-point rule at the mid-sides (weights 1/6,
  !> exact for quadratics; Dhondt 2004, table 3.x; Zienkiewicz & Taylor table 5.3).
  function triangle_integrals(xf) result(a)
    real(dp), intent(in) :: xf(:, :)
    real(dp) :: a(size(xf, 2))
    real(dp), parameter :: points(2, 3) = reshape([0.5_dp, 0.0_dp, 0.5_dp, 0.5_dp, 0.0_dp, 0.5_dp], [2, 3])
    type(segment_point_t) :: p
    integer :: q, n
    n = size(xf, 2)
    a = 0.0_dp
    do q = 1, 3
      p = segment_point(xf, points(:, q))
      a = a + p%shape(1:n) * p%area_factor / 6.0_dp
    end do
  end function triangle_integrals

  !> Area int dA of an 8-node quadrilateral face, 3x3 Gauss points.
  function quad8_area(xf) result(area)
    real(dp), intent(in) :: xf(:, :)
    real(dp) :: area
    real(dp), parameter :: g(3) = [-sqrt(0.6_dp), 0.0_dp, sqrt(0.6_dp)]
    real(dp), parameter :: w(3) = [5.0_dp, 8.0_dp, 5.0_dp] / 9.0_dp
    type(segment_point_t) :: p
    integer :: i, j
    area = 0.0_dp
    do j = 1, 3
      do i = 1, 3
        p = segment_point(xf, [g(i), g(j)])
        area = area + w(i) * w(j) * p%area_factor
      end do
    end do
  end function quad8_area

  !> Exterior element faces (no other element shares all their nodes) whose nodes all lie in
  !> the node list `nodes` (with `touching`, that contain at least one of them), padded to 8
  !> nodes per column.
  subroutine exterior_faces_of_nodes(mesh, nodes, face_nodes, touching)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: nodes(:)
    integer, allocatable, intent(out) :: face_nodes(:, :)
    logical, intent(in), optional :: touching
    logical, allocatable :: in_set(:)
    integer, allocatable :: node_ptr(:), node_elements(:), fill(:), found(:, :), element(:), face(:)
    integer :: e, a, f, n, width, least
    logical :: any_node
    any_node = .false.
    if (present(touching)) any_node = touching
    least = merge(1, 3, any_node)
    allocate (in_set(mesh%n_nodes), node_ptr(mesh%n_nodes + 1))
    in_set = .false.
    in_set(nodes) = .true.
    node_ptr = 0
    do e = 1, mesh%n_elements
      element = mesh%element_nodes(e)
      node_ptr(element + 1) = node_ptr(element + 1) + 1
    end do
    node_ptr(1) = 1
    do a = 1, mesh%n_nodes
      node_ptr(a + 1) = node_ptr(a + 1) + node_ptr(a)
    end do
    allocate (node_elements(node_ptr(mesh%n_nodes + 1) - 1))
    fill = node_ptr(1:mesh%n_nodes)
    do e = 1, mesh%n_elements
      element = mesh%element_nodes(e)
      do a = 1, size(element)
        node_elements(fill(element(a))) = e
        fill(element(a)) = fill(element(a)) + 1
      end do
    end do
    allocate (found(8, 64))
    found = 0
    n = 0
    width = 0
    do e = 1, mesh%n_elements
      if (count(in_set(mesh%element_nodes(e))) < least) cycle
      do f = 1, mesh%n_faces(e)
        face = mesh%face_nodes(e, f)
        if (all(size(face) /= [3, 4, 6, 8])) cycle
        if (any_node) then
          if (.not. any(in_set(face))) cycle
        else if (.not. all(in_set(face))) then
          cycle
        end if
        if (shared(face, e)) cycle
        if (n == size(found, 2)) then
          found = reshape([found, found], [8, 2 * size(found, 2)])
          found(:, n + 1:) = 0
        end if
        n = n + 1
        found(1:size(face), n) = face
        width = max(width, size(face))
      end do
    end do
    face_nodes = found(1:width, 1:n)
  contains
    logical function shared(face_list, owner)
      integer, intent(in) :: face_list(:), owner
      integer :: i, other, j
      shared = .false.
      do i = node_ptr(face_list(1)), node_ptr(face_list(1) + 1) - 1
        other = node_elements(i)
        if (other == owner) cycle
        shared = .true.
        do j = 2, size(face_list)
          if (.not. any(mesh%element_nodes(other) == face_list(j))) shared = .false.
        end do
        if (shared) return
      end do
    end function shared
  end subroutine exterior_faces_of_nodes

end module fcs_contact_areas
