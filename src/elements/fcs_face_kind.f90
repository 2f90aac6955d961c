!> The four face kinds of the solid elements - 3- and 6-node triangles, 4- and 8-node
!> quadrilaterals - used for pressure loads, element-face surfaces and contact master segments
!> (a segment of gamma = 3, 4, 6 or 8 nodes).
!>
!> Natural coordinates and node order are CalculiX's (shape3tri.f, shape6tri.f, shape4q.f,
!> shape8q.f; CalculiX manual, section 6.2, the 2D element kinds S3/S6/S4/S8):
!> - TRI3: 1 (0,0), 2 (1,0), 3 (0,1); TRI6 adds the mid-side nodes 4 (1-2), 5 (2-3), 6 (3-1).
!> - QUAD4: 1 (-1,-1), 2 (1,-1), 3 (1,1), 4 (-1,1); QUAD8 adds 5 (1-2), 6 (2-3), 7 (3-4),
!>   8 (4-1).
!> The shape functions are the Lagrange (TRI3, TRI6, QUAD4) and serendipity (QUAD8) ones, built
!> from node coordinates and monomials by `polynomial_basis_t`. With x(3, n) the coordinates of
!> the face nodes, the area vector a = dx/ds x dx/dt points by the right-hand rule of the node
!> order; the element kinds list their faces so that it points out of the element.
module fcs_face_kind
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, fatal_error
  use fcs_element_basis, only: polynomial_basis_t
  implicit none
  private
  public :: face_kind_t, face_shape_nodes, MAX_FACE_NODES, face_shape_functions
  public :: FACE_TRI3, FACE_TRI6, FACE_QUAD4, FACE_QUAD8, FACE_KIND_NAMES

  !> Face kinds (named, never by number).
  integer, parameter :: FACE_TRI3 = 1, FACE_TRI6 = 2, FACE_QUAD4 = 3, FACE_QUAD8 = 4
  !> Their names, indexed by the constants above (blank-padded: trim them).
  character(len=5), parameter :: FACE_KIND_NAMES(4) = [character(len=5) :: &
    'TRI3', 'TRI6', 'QUAD4', 'QUAD8']
  !> Most nodes of a face.
  integer, parameter :: MAX_FACE_NODES = 8

  real(dp), parameter :: TRI6_ST(2, 6) = reshape([0.0_dp, 0.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, &
    0.5_dp, 0.0_dp, 0.5_dp, 0.5_dp, 0.0_dp, 0.5_dp], [2, 6])
  integer, parameter :: TRI6_TERMS(2, 6) = reshape([0, 0, 1, 0, 0, 1, 2, 0, 1, 1, 0, 2], [2, 6])
  real(dp), parameter :: QUAD8_ST(2, 8) = reshape([-1.0_dp, -1.0_dp, 1.0_dp, -1.0_dp, &
    1.0_dp, 1.0_dp, -1.0_dp, 1.0_dp, 0.0_dp, -1.0_dp, 1.0_dp, 0.0_dp, 0.0_dp, 1.0_dp, &
    -1.0_dp, 0.0_dp], [2, 8])
  integer, parameter :: QUAD4_TERMS(2, 4) = reshape([0, 0, 1, 0, 0, 1, 1, 1], [2, 4])
  integer, parameter :: QUAD8_TERMS(2, 8) = reshape([0, 0, 1, 0, 0, 1, 1, 1, 2, 0, 0, 2, &
    2, 1, 1, 2], [2, 8])

  !> A face kind: its nodes in natural coordinates (s, t) and its shape functions.
  type :: face_kind_t
    !> FACE_TRI3, FACE_TRI6, FACE_QUAD4 or FACE_QUAD8.
    integer :: id = 0
    character(len=:), allocatable :: name
    integer :: n_nodes = 0
    integer :: n_corners = 0
    !> Area of the reference domain (1/2 for triangles, 4 for quadrilaterals).
    real(dp) :: reference_area = 0.0_dp
    !> node_st(:, k): natural coordinates of node k.
    real(dp), allocatable :: node_st(:, :)
    type(polynomial_basis_t) :: basis
  contains
    procedure :: init => face_kind_init
    procedure :: free => face_kind_free
    procedure :: shape_values => face_kind_shape_values
    procedure :: shape_derivatives => face_kind_shape_derivatives
    procedure :: area_vector => face_kind_area_vector
  end type face_kind_t

contains

  !> Number of nodes of face kind `id` (0 if unknown).
  pure integer function face_shape_nodes(id) result(n)
    integer, intent(in) :: id
    select case (id)
    case (FACE_TRI3)
      n = 3
    case (FACE_TRI6)
      n = 6
    case (FACE_QUAD4)
      n = 4
    case (FACE_QUAD8)
      n = 8
    case default
      n = 0
    end select
  end function face_shape_nodes

  !> Set up face kind `id` (FACE_TRI3 ...).
  subroutine face_kind_init(this, id, err)
    class(face_kind_t), intent(inout) :: this
    integer, intent(in) :: id
    type(error_t), allocatable, intent(out) :: err
    call this%free()
    select case (id)
    case (FACE_TRI3)
      this%node_st = TRI6_ST(:, 1:3)
      call this%basis%init(this%node_st, TRI6_TERMS(:, 1:3), err)
      this%n_corners = 3
      this%reference_area = 0.5_dp
    case (FACE_TRI6)
      this%node_st = TRI6_ST
      call this%basis%init(this%node_st, TRI6_TERMS, err)
      this%n_corners = 3
      this%reference_area = 0.5_dp
    case (FACE_QUAD4)
      this%node_st = QUAD8_ST(:, 1:4)
      call this%basis%init(this%node_st, QUAD4_TERMS, err)
      this%n_corners = 4
      this%reference_area = 4.0_dp
    case (FACE_QUAD8)
      this%node_st = QUAD8_ST
      call this%basis%init(this%node_st, QUAD8_TERMS, err)
      this%n_corners = 4
      this%reference_area = 4.0_dp
    case default
      call fatal_error(err, 'unknown face kind')
      return
    end select
    if (allocated(err)) return
    this%id = id
    this%name = trim(FACE_KIND_NAMES(id))
    this%n_nodes = size(this%node_st, 2)
  end subroutine face_kind_init

  !> Forget the face kind.
  subroutine face_kind_free(this)
    class(face_kind_t), intent(inout) :: this
    this%id = 0
    this%n_nodes = 0
    this%n_corners = 0
    this%reference_area = 0.0_dp
    if (allocated(this%name)) deallocate (this%name)
    if (allocated(this%node_st)) deallocate (this%node_st)
    call this%basis%free()
  end subroutine face_kind_free

  !> Face shape function values n(k) = M_k(st), k = 1..n_nodes.
  pure subroutine face_kind_shape_values(this, st, n)
    class(face_kind_t), intent(in) :: this
    real(dp), intent(in) :: st(2)
    real(dp), intent(out) :: n(:)
    call this%basis%values(st, n)
  end subroutine face_kind_shape_values

  !> Natural derivatives dn(alpha, k) = dM_k/ds_alpha at st.
  pure subroutine face_kind_shape_derivatives(this, st, dn)
    class(face_kind_t), intent(in) :: this
    real(dp), intent(in) :: st(2)
    real(dp), intent(out) :: dn(:, :)
    call this%basis%derivatives(st, dn)
  end subroutine face_kind_shape_derivatives

  !> Area vector a = dx/ds x dx/dt at st for face node coordinates x(3, n_nodes): its length
  !> is the area per unit natural area, its direction the normal by the right-hand rule of the
  !> node order (outward for the faces of the element kinds). The nodal forces of a pressure p
  !> are f_k = -p sum_q M_k a w_q (Dhondt 2004, eq. 3.54 for their stiffness).
  pure function face_kind_area_vector(this, x, st) result(a)
    class(face_kind_t), intent(in) :: this
    real(dp), intent(in) :: x(:, :), st(2)
    real(dp) :: a(3)
    real(dp) :: dn(2, MAX_FACE_NODES), t1(3), t2(3)
    integer :: k
    call this%basis%derivatives(st, dn)
    t1 = 0.0_dp
    t2 = 0.0_dp
    do k = 1, this%n_nodes
      t1 = t1 + x(:, k) * dn(1, k)
      t2 = t2 + x(:, k) * dn(2, k)
    end do
    a = [t1(2) * t2(3) - t1(3) * t2(2), t1(3) * t2(1) - t1(1) * t2(3), t1(1) * t2(2) - t1(2) * t2(1)]
  end function face_kind_area_vector

  !> Closed-form shape functions of the face kind with `n_nodes` nodes (3, 4, 6 or 8: TRI3,
  !> QUAD4, TRI6, QUAD8, nodes and natural coordinates as in the module header) at st, with
  !> their first derivatives dm(alpha, k) = dM_k/ds_alpha and second derivatives
  !> ddm(:, k) = [d2M_k/ds2, d2M_k/dt2, d2M_k/dsdt] (the curvature terms x_,ab of a contact
  !> segment). The same functions as `polynomial_basis_t` builds for the kind (the unit test
  !> compares them), written out so that pure contact kernels evaluate them without a basis
  !> object: TRI6 M_1 = r(2r - 1), M_4 = 4 s r, ... with r = 1 - s - t (CalculiX shape6tri.f);
  !> QUAD8 corners 1/4 (1 + s s_k)(1 + t t_k)(s s_k + t t_k - 1), mid-sides 1/2 (1 - s^2)
  !> (1 + t t_k) and 1/2 (1 + s s_k)(1 - t^2) (shape8q.f; Zienkiewicz & Taylor, ch. 8).
  !> Unknown n_nodes: all zero.
  pure subroutine face_shape_functions(n_nodes, st, m, dm, ddm)
    integer, intent(in) :: n_nodes
    real(dp), intent(in) :: st(2)
    real(dp), intent(out) :: m(:), dm(:, :), ddm(:, :)
    real(dp) :: s, t, r, a, b, sk, tk
    integer :: k
    m = 0.0_dp
    dm = 0.0_dp
    ddm = 0.0_dp
    s = st(1)
    t = st(2)
    select case (n_nodes)
    case (3)
      m(1:3) = [1.0_dp - s - t, s, t]
      dm(:, 1) = [-1.0_dp, -1.0_dp]
      dm(:, 2) = [1.0_dp, 0.0_dp]
      dm(:, 3) = [0.0_dp, 1.0_dp]
    case (6)
      r = 1.0_dp - s - t
      m(1:6) = [r * (2.0_dp * r - 1.0_dp), s * (2.0_dp * s - 1.0_dp), t * (2.0_dp * t - 1.0_dp), &
                4.0_dp * s * r, 4.0_dp * s * t, 4.0_dp * t * r]
      dm(:, 1) = [1.0_dp - 4.0_dp * r, 1.0_dp - 4.0_dp * r]
      dm(:, 2) = [4.0_dp * s - 1.0_dp, 0.0_dp]
      dm(:, 3) = [0.0_dp, 4.0_dp * t - 1.0_dp]
      dm(:, 4) = [4.0_dp * (r - s), -4.0_dp * s]
      dm(:, 5) = [4.0_dp * t, 4.0_dp * s]
      dm(:, 6) = [-4.0_dp * t, 4.0_dp * (r - t)]
      ddm(:, 1) = [4.0_dp, 4.0_dp, 4.0_dp]
      ddm(:, 2) = [4.0_dp, 0.0_dp, 0.0_dp]
      ddm(:, 3) = [0.0_dp, 4.0_dp, 0.0_dp]
      ddm(:, 4) = [-8.0_dp, 0.0_dp, -4.0_dp]
      ddm(:, 5) = [0.0_dp, 0.0_dp, 4.0_dp]
      ddm(:, 6) = [0.0_dp, -8.0_dp, -4.0_dp]
    case (4)
      do k = 1, 4
        sk = QUAD8_ST(1, k)
        tk = QUAD8_ST(2, k)
        m(k) = 0.25_dp * (1.0_dp + sk * s) * (1.0_dp + tk * t)
        dm(:, k) = 0.25_dp * [sk * (1.0_dp + tk * t), tk * (1.0_dp + sk * s)]
        ddm(:, k) = [0.0_dp, 0.0_dp, 0.25_dp * sk * tk]
      end do
    case (8)
      do k = 1, 4
        sk = QUAD8_ST(1, k)
        tk = QUAD8_ST(2, k)
        a = 1.0_dp + sk * s
        b = 1.0_dp + tk * t
        m(k) = 0.25_dp * a * b * (sk * s + tk * t - 1.0_dp)
        dm(:, k) = 0.25_dp * [sk * b * (2.0_dp * sk * s + tk * t), tk * a * (sk * s + 2.0_dp * tk * t)]
        ddm(:, k) = [0.5_dp * b, 0.5_dp * a, 0.25_dp * sk * tk * (2.0_dp * sk * s + 2.0_dp * tk * t + 1.0_dp)]
      end do
      do k = 5, 8
        sk = QUAD8_ST(1, k)
        tk = QUAD8_ST(2, k)
        if (sk == 0.0_dp) then
          m(k) = 0.5_dp * (1.0_dp - s * s) * (1.0_dp + tk * t)
          dm(:, k) = [-s * (1.0_dp + tk * t), 0.5_dp * tk * (1.0_dp - s * s)]
          ddm(:, k) = [-(1.0_dp + tk * t), 0.0_dp, -s * tk]
        else
          m(k) = 0.5_dp * (1.0_dp + sk * s) * (1.0_dp - t * t)
          dm(:, k) = [0.5_dp * sk * (1.0_dp - t * t), -t * (1.0_dp + sk * s)]
          ddm(:, k) = [0.0_dp, -(1.0_dp + sk * s), -t * sk]
        end if
      end do
    end select
  end subroutine face_shape_functions

end module fcs_face_kind
