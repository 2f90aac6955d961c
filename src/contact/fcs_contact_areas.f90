!> Tributary areas of slave nodes: the slave node's share of the slave surface,
!> A_s = sum over slave faces of the integral of N_s dA (2x2 Gauss on the bilinear face), so
!> that penalty stiffnesses and frictional stresses per unit area turn into nodal forces.
!> A node-based slave surface has no faces of its own: the exterior 4-node faces of the mesh
!> whose four nodes all belong to it are used.
module fcs_contact_areas
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, input_error
  use fcs_mesh, only: mesh_t, SURFACE_FACES
  use fcs_contact_geometry, only: segment_point_t, segment_point
  use fcs_strings, only: str
  implicit none
  private
  public :: slave_node_areas, surface_face_nodes

contains

  !> Areas of `slaves` (node indices) from surface `k` of the mesh.
  subroutine slave_node_areas(mesh, k, slaves, areas, err)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: k, slaves(:)
    real(dp), allocatable, intent(out) :: areas(:)
    type(error_t), allocatable, intent(out) :: err
    real(dp), allocatable :: nodal(:)
    integer, allocatable :: face_nodes(:, :)
    integer :: i, f
    call surface_face_nodes(mesh, k, face_nodes, err)
    if (allocated(err)) return
    allocate (nodal(mesh%n_nodes))
    nodal = 0.0_dp
    do f = 1, size(face_nodes, 2)
      call add_face(mesh%x(:, face_nodes(:, f)), face_nodes(:, f), nodal)
    end do
    areas = nodal(slaves)
    do i = 1, size(slaves)
      if (areas(i) > 0.0_dp) cycle
      call input_error(err, 'slave node ' // str(mesh%node_id(slaves(i))) // ' of surface ' // &
        mesh%surfaces(k)%name // ' lies on no exterior face of the slave body, so it has no ' // &
        'contact area (define the slave surface by element faces)')
      return
    end do
  end subroutine slave_node_areas

  !> Add the integrals of N_a dA of one face to its nodes.
  !> The faces of surface k (4 node indices each, outward): its element faces, or for a
  !> node-based surface the exterior faces of the mesh whose four nodes all belong to it. The
  !> contact segments are bilinear quadrilaterals: an element face of another shape is an
  !> input error.
  subroutine surface_face_nodes(mesh, k, face_nodes, err)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: k
    integer, allocatable, intent(out) :: face_nodes(:, :)
    type(error_t), allocatable, intent(out) :: err
    integer, allocatable :: nodes(:)
    integer :: f
    if (mesh%surfaces(k)%kind == SURFACE_FACES) then
      allocate (face_nodes(4, size(mesh%surfaces(k)%element)))
      do f = 1, size(face_nodes, 2)
        nodes = mesh%face_nodes(mesh%surfaces(k)%element(f), mesh%surfaces(k)%face(f))
        if (size(nodes) /= 4) then
          call input_error(err, 'surface ' // mesh%surfaces(k)%name // ': face S' // &
            str(mesh%surfaces(k)%face(f)) // ' of element ' // &
            str(mesh%element_id(mesh%surfaces(k)%element(f))) // ' has ' // str(size(nodes)) // &
            ' nodes; contact and ties need 4-node (quadrilateral) faces')
          return
        end if
        face_nodes(:, f) = nodes
      end do
    else
      call exterior_faces_of_nodes(mesh, mesh%surfaces(k)%nodes, face_nodes)
    end if
  end subroutine surface_face_nodes

  subroutine add_face(xf, nodes, nodal)
    real(dp), intent(in) :: xf(3, 4)
    integer, intent(in) :: nodes(4)
    real(dp), intent(inout) :: nodal(:)
    real(dp), parameter :: g = 0.57735026918962576451_dp
    real(dp), parameter :: points(2, 4) = reshape([-g, -g, g, -g, g, g, -g, g], [2, 4])
    type(segment_point_t) :: p
    integer :: q
    do q = 1, 4
      p = segment_point(xf, points(:, q))
      nodal(nodes) = nodal(nodes) + p%shape * p%area_factor
    end do
  end subroutine add_face

  !> Exterior element faces (no other element shares all four nodes) whose nodes all lie in
  !> the sorted node list `nodes`.
  subroutine exterior_faces_of_nodes(mesh, nodes, face_nodes)
    type(mesh_t), intent(in) :: mesh
    integer, intent(in) :: nodes(:)
    integer, allocatable, intent(out) :: face_nodes(:, :)
    logical, allocatable :: in_set(:)
    integer, allocatable :: node_ptr(:), node_elements(:), fill(:), found(:, :), element(:), face(:)
    integer :: e, a, f, n, quad(4)
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
    allocate (found(4, 64))
    n = 0
    do e = 1, mesh%n_elements
      if (count(in_set(mesh%element_nodes(e))) < 4) cycle
      do f = 1, mesh%n_faces(e)
        face = mesh%face_nodes(e, f)
        if (size(face) /= 4) cycle
        quad = face
        if (.not. all(in_set(quad))) cycle
        if (shared(quad, e)) cycle
        if (n == size(found, 2)) found = reshape([found, found], [4, 2 * size(found, 2)])
        n = n + 1
        found(:, n) = quad
      end do
    end do
    face_nodes = found(:, 1:n)
  contains
    logical function shared(quad, owner)
      integer, intent(in) :: quad(4), owner
      integer :: i, other, j
      shared = .false.
      do i = node_ptr(quad(1)), node_ptr(quad(1) + 1) - 1
        other = node_elements(i)
        if (other == owner) cycle
        shared = .true.
        do j = 2, 4
          if (.not. any(mesh%element_nodes(other) == quad(j))) shared = .false.
        end do
        if (shared) return
      end do
    end function shared
  end subroutine exterior_faces_of_nodes

end module fcs_contact_areas
