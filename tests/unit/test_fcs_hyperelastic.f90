!> Unit test of fcs_hyperelastic (doc/theory.md 2.11):
!> - closed forms derived from the energies by hand, on homogeneous stretches F = diag(l1, l2, l3):
!>   incompressible uniaxial (l, l^-1/2, l^-1/2) and equibiaxial (l, l, l^-2) stretch of
!>   Neo-Hooke (sigma_11 - sigma_22 = 2 C10 (l^2 - 1/l); 2 C10 (l^2 - l^-4)), Mooney-Rivlin
!>   (2 (l^2 - 1/l)(C10 + C01/l); 2 (l^2 - l^-4)(C10 + C01 l^2)) and Ogden (2 mu/alpha
!>   (l^alpha - l^(-alpha/2))), the pressure of a compressible stretch (sum of the principal
!>   stresses = 3 dU/dJ), and hyperfoam under confined uniaxial and equibiaxial stretch
!>   (sigma_a = 2 mu / (alpha J) (l_a^alpha - J^(-alpha beta)));
!> - Ogden with N=1, alpha = 2 is Neo-Hooke with C10 = mu/2 at a general F (2 mu/alpha^2 = mu/2);
!> - every form: sigma = (1/J) dU/dF F^T against central differences of U coded here from the
!>   manual's formulas (C = F^T F invariants and stretches), at a general F;
!> - the tangent c (Miehe's numerical one) gives the Jaumann rate sigma^J = sigma' - W sigma +
!>   sigma W = c : D against central differences of sigma(F) along F' = L F (L with spin);
!> - the element: one distorted C3D8 of a Mooney-Rivlin material under NLGEOM, the assembled
!>   tangent K times a nodal direction v against central differences of the internal forces
!>   f_int(u + h v) - f_int(u - h v) over 2h (the stress of each configuration from `update`).
program test_fcs_hyperelastic
  use fcs_kinds, only: dp
  use fcs_error, only: error_t
  use fcs_hyperelastic, only: hyperelastic_law_t, hyperelastic_stress, &
    hyperelastic_jaumann_tangent, symmetric_eigen, HYPER_POLYNOMIAL, HYPER_ARRUDA_BOYCE, &
    HYPER_OGDEN, HYPER_FOAM
  use fcs_hyperelastic_material, only: hyperelastic_from_law
  use fcs_st_venant_kirchhoff, only: voigt_tensor, tensor_voigt, determinant_of
  use fcs_element_catalogue, only: element_catalogue_t
  use fcs_element_loops, only: element_loops_t, mesh_kinds
  use fcs_element_state, only: element_state_t
  use fcs_mesh, only: mesh_t
  use fcs_material, only: material_slot_t
  use fcs_sparse, only: sparse_matrix_t
  use fcs_test_assertions, only: test_suite_t
  implicit none
  type(test_suite_t) :: suite
  !> Closed forms evaluated in a different order of operations: round-off of order 1e-14.
  real(dp), parameter :: EXACT = 1.0e-12_dp
  !> Central differences with step 1e-5 of functions of order one: truncation ~1e-10, round-off
  !> ~1e-11, relative to the largest entry; the tangent compares two such differences.
  real(dp), parameter :: DIFFERENCE = 1.0e-7_dp
  !> A general deformation gradient (stretch, shear and rotation, det F = 1.07).
  real(dp), parameter :: F_GENERAL(3, 3) = reshape([1.15_dp, 0.08_dp, -0.05_dp, 0.25_dp, 0.9_dp, &
    0.06_dp, -0.12_dp, 0.07_dp, 1.1_dp], [3, 3])

  suite%name = 'fcs_hyperelastic'
  call check_closed_forms(suite)
  call check_ogden_is_neo_hooke(suite)
  call check_energy_derivative(suite)
  call check_tangent(suite)
  call check_element(suite)
  call suite%report()

contains

  function neo_hooke(c10, d1) result(law)
    real(dp), intent(in) :: c10, d1
    type(hyperelastic_law_t) :: law
    law%family = HYPER_POLYNOMIAL
    law%order = 1
    law%c(1, 0) = c10
    law%d(1) = d1
  end function neo_hooke

  function mooney_rivlin(c10, c01, d1) result(law)
    real(dp), intent(in) :: c10, c01, d1
    type(hyperelastic_law_t) :: law
    law = neo_hooke(c10, d1)
    law%c(0, 1) = c01
  end function mooney_rivlin

  function ogden(mu, alpha, d) result(law)
    real(dp), intent(in) :: mu(:), alpha(:), d(:)
    type(hyperelastic_law_t) :: law
    law%family = HYPER_OGDEN
    law%order = size(mu)
    law%mu(1:size(mu)) = mu
    law%alpha(1:size(mu)) = alpha
    law%d(1:size(mu)) = d
  end function ogden

  function foam(mu, alpha, nu) result(law)
    real(dp), intent(in) :: mu(:), alpha(:), nu(:)
    type(hyperelastic_law_t) :: law
    law%family = HYPER_FOAM
    law%order = size(mu)
    law%mu(1:size(mu)) = mu
    law%alpha(1:size(mu)) = alpha
    law%beta(1:size(mu)) = nu / (1.0_dp - 2.0_dp * nu)
  end function foam

  pure function diag(l1, l2, l3) result(f)
    real(dp), intent(in) :: l1, l2, l3
    real(dp) :: f(3, 3)
    f = 0.0_dp
    f(1, 1) = l1
    f(2, 2) = l2
    f(3, 3) = l3
  end function diag

  subroutine check_closed_forms(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: L = 1.4_dp, C10 = 0.8_dp, C01 = 0.3_dp, D1 = 0.05_dp
    real(dp), parameter :: MU = 1.7_dp, ALPHA = 3.3_dp, NU = 0.2_dp
    real(dp) :: s(6), j, beta, lt
    ! Incompressible stretches: J = 1, no pressure from the D terms.
    s = hyperelastic_stress(neo_hooke(C10, D1), diag(L, L**(-0.5_dp), L**(-0.5_dp)))
    call suite%close_to(s(1) - s(2), 2.0_dp * C10 * (L**2 - 1.0_dp / L), EXACT, &
                        'Neo-Hooke uniaxial: sigma_11 - sigma_22 = 2 C10 (l^2 - 1/l)')
    call suite%close_to(s(2) - s(3), 0.0_dp, EXACT, 'Neo-Hooke uniaxial: lateral stresses equal', 1.0_dp)
    s = hyperelastic_stress(neo_hooke(C10, D1), diag(L, L, L**(-2)))
    call suite%close_to(s(1) - s(3), 2.0_dp * C10 * (L**2 - L**(-4)), EXACT, &
                        'Neo-Hooke equibiaxial: sigma_11 - sigma_33 = 2 C10 (l^2 - l^-4)')
    s = hyperelastic_stress(mooney_rivlin(C10, C01, D1), diag(L, L**(-0.5_dp), L**(-0.5_dp)))
    call suite%close_to(s(1) - s(2), 2.0_dp * (L**2 - 1.0_dp / L) * (C10 + C01 / L), EXACT, &
                        'Mooney-Rivlin uniaxial: 2 (l^2 - 1/l)(C10 + C01/l)')
    s = hyperelastic_stress(mooney_rivlin(C10, C01, D1), diag(L, L, L**(-2)))
    call suite%close_to(s(1) - s(3), 2.0_dp * (L**2 - L**(-4)) * (C10 + C01 * L**2), EXACT, &
                        'Mooney-Rivlin equibiaxial: 2 (l^2 - l^-4)(C10 + C01 l^2)')
    s = hyperelastic_stress(ogden([MU], [ALPHA], [D1]), diag(L, L**(-0.5_dp), L**(-0.5_dp)))
    call suite%close_to(s(1) - s(2), 2.0_dp * MU / ALPHA * (L**ALPHA - L**(-0.5_dp * ALPHA)), &
                        EXACT, 'Ogden uniaxial: 2 mu/alpha (l^alpha - l^(-alpha/2))')
    ! A compressible stretch: the mean stress is dU/dJ = 2 (J - 1)/D1 (the deviatoric part is
    ! traceless), whatever the form.
    lt = 0.93_dp
    j = L * lt**2
    s = hyperelastic_stress(mooney_rivlin(C10, C01, D1), diag(L, lt, lt))
    call suite%close_to(sum(s(1:3)) / 3.0_dp, 2.0_dp * (j - 1.0_dp) / D1, EXACT, &
                        'Mooney-Rivlin compressible: mean stress 2 (J - 1)/D1')
    s = hyperelastic_stress(ogden([MU, -0.4_dp], [ALPHA, -1.5_dp], [D1, 0.3_dp]), diag(L, lt, lt))
    call suite%close_to(sum(s(1:3)) / 3.0_dp, 2.0_dp * (j - 1.0_dp) / D1 + &
                        4.0_dp * (j - 1.0_dp)**3 / 0.3_dp, EXACT, &
                        'Ogden N=2: mean stress 2 (J - 1)/D1 + 4 (J - 1)^3/D2')
    ! Hyperfoam: sigma_a = 2 mu / (alpha J) (l_a^alpha - J^(-alpha beta)).
    beta = NU / (1.0_dp - 2.0_dp * NU)
    s = hyperelastic_stress(foam([MU], [ALPHA], [NU]), diag(L, 1.0_dp, 1.0_dp))
    call suite%close_to(s(1), 2.0_dp * MU / (ALPHA * L) * (L**ALPHA - L**(-ALPHA * beta)), EXACT, &
                        'hyperfoam confined uniaxial: sigma_11')
    call suite%close_to(s(2), 2.0_dp * MU / (ALPHA * L) * (1.0_dp - L**(-ALPHA * beta)), EXACT, &
                        'hyperfoam confined uniaxial: sigma_22')
    s = hyperelastic_stress(foam([MU], [ALPHA], [NU]), diag(L, L, 1.0_dp))
    call suite%close_to(s(1), 2.0_dp * MU / (ALPHA * L**2) * (L**ALPHA - L**(-2.0_dp * ALPHA * beta)), &
                        EXACT, 'hyperfoam equibiaxial: sigma_11')
    call suite%close_to(s(3), 2.0_dp * MU / (ALPHA * L**2) * (1.0_dp - L**(-2.0_dp * ALPHA * beta)), &
                        EXACT, 'hyperfoam equibiaxial: sigma_33')
    call suite%close_array(hyperelastic_stress(ogden([MU], [ALPHA], [D1]), diag(1.0_dp, 1.0_dp, &
                           1.0_dp)), [0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], EXACT, &
                           'Ogden: no stress at F = I (three equal stretches)')
  end subroutine check_closed_forms

  subroutine check_ogden_is_neo_hooke(suite)
    type(test_suite_t), intent(inout) :: suite
    call suite%close_array(hyperelastic_stress(ogden([1.3_dp], [2.0_dp], [0.07_dp]), F_GENERAL), &
                           hyperelastic_stress(neo_hooke(0.65_dp, 0.07_dp), F_GENERAL), EXACT, &
                           'Ogden N=1, alpha=2 is Neo-Hooke with C10 = mu/2 (general F)')
  end subroutine check_ogden_is_neo_hooke

  !> U of `law` at F, coded from the manual's formulas on C = F^T F.
  function energy(law, f) result(u)
    type(hyperelastic_law_t), intent(in) :: law
    real(dp), intent(in) :: f(3, 3)
    real(dp) :: u
    real(dp) :: c(3, 3), i1, i2, i3, i1b, i2b, j, stretch2(3), vectors(3, 3), lm2
    integer :: i, k
    c = matmul(transpose(f), f)
    i1 = c(1, 1) + c(2, 2) + c(3, 3)
    i2 = 0.5_dp * (i1**2 - sum(c * transpose(c)))
    i3 = determinant_of(c)
    i1b = i3**(-1.0_dp / 3.0_dp) * i1
    i2b = i3**(-2.0_dp / 3.0_dp) * i2
    j = sqrt(i3)
    call symmetric_eigen(c, stretch2, vectors)
    u = 0.0_dp
    select case (law%family)
    case (HYPER_POLYNOMIAL)
      do i = 0, law%order
        do k = 0, law%order - i
          u = u + law%c(i, k) * (i1b - 3.0_dp)**i * (i2b - 3.0_dp)**k
        end do
      end do
      do i = 1, law%order
        u = u + (j - 1.0_dp)**(2 * i) / law%d(i)
      end do
    case (HYPER_ARRUDA_BOYCE)
      lm2 = law%lambda_m**2
      u = law%mu(1) * (0.5_dp * (i1b - 3.0_dp) + (i1b**2 - 9.0_dp) / (20.0_dp * lm2) + &
          11.0_dp * (i1b**3 - 27.0_dp) / (1050.0_dp * lm2**2) + 19.0_dp * (i1b**4 - 81.0_dp) / &
          (7000.0_dp * lm2**3) + 519.0_dp * (i1b**5 - 243.0_dp) / (673750.0_dp * lm2**4)) + &
          (0.5_dp * (j**2 - 1.0_dp) - log(j)) / law%d(1)
    case (HYPER_OGDEN)
      do i = 1, law%order
        u = u + 2.0_dp * law%mu(i) / law%alpha(i)**2 * &
            (sum((i3**(-1.0_dp / 3.0_dp) * stretch2)**(0.5_dp * law%alpha(i))) - 3.0_dp) + &
            (j - 1.0_dp)**(2 * i) / law%d(i)
      end do
    case (HYPER_FOAM)
      do i = 1, law%order
        ! (J^(-alpha beta) - 1)/beta, whose limit at beta = 0 (nu = 0) is -alpha ln J.
        if (law%beta(i) == 0.0_dp) then
          lm2 = -law%alpha(i) * log(j)
        else
          lm2 = (j**(-law%alpha(i) * law%beta(i)) - 1.0_dp) / law%beta(i)
        end if
        u = u + 2.0_dp * law%mu(i) / law%alpha(i)**2 * (sum(stretch2**(0.5_dp * law%alpha(i))) - &
            3.0_dp + lm2)
      end do
    end select
  end function energy

  !> Every form the builder makes, with constants of order one.
  function all_forms() result(laws)
    type(hyperelastic_law_t) :: laws(7)
    laws(1) = neo_hooke(0.8_dp, 0.05_dp)
    laws(2) = mooney_rivlin(0.8_dp, 0.3_dp, 0.05_dp)
    laws(3)%family = HYPER_POLYNOMIAL
    laws(3)%order = 3
    laws(3)%c(1, 0) = 0.8_dp
    laws(3)%c(0, 1) = 0.3_dp
    laws(3)%c(2, 0) = 0.1_dp
    laws(3)%c(1, 1) = -0.05_dp
    laws(3)%c(0, 2) = 0.04_dp
    laws(3)%c(3, 0) = 0.02_dp
    laws(3)%c(2, 1) = 0.01_dp
    laws(3)%c(1, 2) = -0.01_dp
    laws(3)%c(0, 3) = 0.005_dp
    laws(3)%d = [0.05_dp, 0.2_dp, 0.5_dp]
    laws(4)%family = HYPER_POLYNOMIAL
    laws(4)%order = 3
    laws(4)%c(1:3, 0) = [0.8_dp, -0.1_dp, 0.03_dp]
    laws(4)%d = [0.05_dp, 0.2_dp, 0.5_dp]
    laws(5)%family = HYPER_ARRUDA_BOYCE
    laws(5)%mu(1) = 1.2_dp
    laws(5)%lambda_m = 2.5_dp
    laws(5)%d(1) = 0.05_dp
    laws(6) = ogden([1.3_dp, 0.2_dp, -0.05_dp], [2.5_dp, 5.0_dp, -2.0_dp], [0.05_dp, 0.2_dp, 0.5_dp])
    laws(7) = foam([0.16_dp, 2.3e-5_dp, 0.05_dp], [8.88_dp, -4.8_dp, 2.0_dp], [0.0_dp, 0.1_dp, 0.3_dp])
  end function all_forms

  character(len=20) function form_name(k)
    integer, intent(in) :: k
    character(len=20), parameter :: NAMES(7) = [character(len=20) :: 'NEO HOOKE', 'MOONEY-RIVLIN', &
      'POLYNOMIAL N=3', 'REDUCED POLY N=3', 'ARRUDA-BOYCE', 'OGDEN N=3', 'HYPERFOAM N=3']
    form_name = NAMES(k)
  end function form_name

  !> sigma = (1/J) P F^T, P_iJ = dU/dF_iJ by central differences.
  subroutine check_energy_derivative(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: H = 1.0e-5_dp
    type(hyperelastic_law_t) :: laws(7)
    real(dp) :: p(3, 3), df(3, 3)
    integer :: k, i, jj
    laws = all_forms()
    do k = 1, size(laws)
      do jj = 1, 3
        do i = 1, 3
          df = 0.0_dp
          df(i, jj) = H
          p(i, jj) = (energy(laws(k), F_GENERAL + df) - energy(laws(k), F_GENERAL - df)) / (2.0_dp * H)
        end do
      end do
      call suite%close_array(hyperelastic_stress(laws(k), F_GENERAL), &
                             tensor_voigt(matmul(p, transpose(F_GENERAL))) / determinant_of(F_GENERAL), &
                             DIFFERENCE, trim(form_name(k)) // ': sigma = (1/J) dU/dF F^T')
    end do
  end subroutine check_energy_derivative

  subroutine check_tangent(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: H = 1.0e-5_dp
    real(dp), parameter :: L(3, 3) = reshape([0.3_dp, -0.7_dp, 0.2_dp, 0.5_dp, -0.4_dp, 0.9_dp, &
      -0.6_dp, 0.1_dp, 0.25_dp], [3, 3])
    type(hyperelastic_law_t) :: laws(7)
    real(dp) :: d(3, 3), w(3, 3), sigma(6), rate(6), jaumann(6), d_voigt(6), eye(3, 3)
    integer :: k
    eye = diag(1.0_dp, 1.0_dp, 1.0_dp)
    d = 0.5_dp * (L + transpose(L))
    w = 0.5_dp * (L - transpose(L))
    d_voigt = [d(1, 1), d(2, 2), d(3, 3), 2.0_dp * d(1, 2), 2.0_dp * d(1, 3), 2.0_dp * d(2, 3)]
    laws = all_forms()
    do k = 1, size(laws)
      sigma = hyperelastic_stress(laws(k), F_GENERAL)
      rate = (hyperelastic_stress(laws(k), matmul(eye + H * L, F_GENERAL)) - &
              hyperelastic_stress(laws(k), matmul(eye - H * L, F_GENERAL))) / (2.0_dp * H)
      jaumann = rate - tensor_voigt(matmul(w, voigt_tensor(sigma)) - matmul(voigt_tensor(sigma), w))
      call suite%close_array(matmul(hyperelastic_jaumann_tangent(laws(k), F_GENERAL), d_voigt), &
                             jaumann, 1.0e-6_dp, trim(form_name(k)) // &
                             ': Jaumann tangent c : D = sigma^J (finite differences)')
    end do
  end subroutine check_tangent

  !> K v = d f_int / d x . v for one distorted C3D8 of a Mooney-Rivlin material under NLGEOM.
  subroutine check_element(suite)
    type(test_suite_t), intent(inout) :: suite
    real(dp), parameter :: H = 1.0e-6_dp
    type(element_catalogue_t) :: catalogue
    type(mesh_t) :: mesh
    type(element_loops_t) :: loops
    type(element_state_t) :: fields
    type(material_slot_t), allocatable :: materials(:)
    type(sparse_matrix_t) :: matrix
    type(error_t), allocatable :: err
    integer, allocatable :: clique_ptr(:), clique_nodes(:)
    real(dp), allocatable :: u(:), v(:), x(:, :), f_plus(:), f_minus(:), f_int(:), kv(:)
    real(dp) :: noise(3, 8)
    integer :: a, k
    logical :: duplicate
    call catalogue%init(err)
    if (allocated(err)) error stop 1
    call mesh%init(mesh_kinds(catalogue))
    k = catalogue%find('C3D8')
    do a = 1, 8
      call mesh%add_node(a, catalogue%kinds(k)%node_xi(:, a), duplicate)
    end do
    call mesh%add_element(1, [(a, a = 1, 8)], duplicate, mesh%find_kind('C3D8'))
    call mesh%compact()
    allocate (materials(1))
    allocate (materials(1)%m, source=hyperelastic_from_law(mooney_rivlin(0.8_dp, 0.3_dp, 0.05_dp)))
    call loops%init(catalogue, mesh, [1], [.false.], materials, err)
    call suite%check(.not. allocated(err), 'element: loops of one C3D8')
    if (allocated(err)) return
    call fields%init(loops%max_points, 1, loops%n_material_state())
    ! A large deformation (an affine stretch and shear plus a perturbation of every node) and a
    ! direction v of the nodes.
    call random_seed()
    call random_number(noise)
    allocate (u(24), v(24))
    do a = 1, 8
      u(3 * a - 2:3 * a) = matmul(reshape([0.3_dp, 0.1_dp, -0.05_dp, 0.2_dp, -0.15_dp, 0.0_dp, &
        0.05_dp, 0.1_dp, 0.1_dp], [3, 3]), mesh%x(:, a)) + 0.05_dp * (noise(:, a) - 0.5_dp)
    end do
    call random_number(v)
    v = v - 0.5_dp
    allocate (f_plus(24), f_minus(24), f_int(24), kv(24))
    call internal_force(loops, mesh, fields, u + H * v, f_plus)
    call internal_force(loops, mesh, fields, u - H * v, f_minus)
    call loops%cliques([1], clique_ptr, clique_nodes)
    call matrix%build(8, clique_ptr, clique_nodes)
    call matrix%zero()
    call loops%update(mesh%x, u, fields, .true., err)
    x = mesh%x + reshape(u, [3, 8])
    call loops%assemble(x, fields, .true., f_int, err, matrix)
    call suite%check(.not. allocated(err), 'element: tangent assembled')
    call matrix%multiply(v, kv)
    call suite%close_array(kv, (f_plus - f_minus) / (2.0_dp * H), 1.0e-6_dp, &
                           'element: K v = d f_int/dx v (central differences, Mooney-Rivlin, NLGEOM)')
  end subroutine check_element

  !> The internal forces of the nodes at mesh%x + displacement, with the stresses of that
  !> configuration.
  subroutine internal_force(loops, mesh, fields, displacement, force)
    type(element_loops_t), intent(in) :: loops
    type(mesh_t), intent(in) :: mesh
    type(element_state_t), intent(inout) :: fields
    real(dp), intent(in) :: displacement(:)
    real(dp), intent(out) :: force(:)
    type(error_t), allocatable :: err
    call loops%update(mesh%x, displacement, fields, .true., err)
    if (allocated(err)) error stop 1
    call loops%assemble(mesh%x + reshape(displacement, [3, 8]), fields, .true., force, err)
    if (allocated(err)) error stop 1
  end subroutine internal_force

end program test_fcs_hyperelastic
