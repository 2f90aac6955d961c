!> Unit test of fcs_material_factory: the built-in registry (names, the model each PLASTICITY_
!> value builds), an unknown model refused with the valid names, and the registry: a test-only
!> material (TEST LINEAR ELASTIC, fcs_test_materials) registered at run time is listed, built
!> by create_material by name with its elastic constants, and one point update gives the
!> closed-form stress of linear elasticity.
program test_fcs_material_factory
  use fcs_kinds, only: dp
  use fcs_error, only: error_t, EXIT_INPUT
  use fcs_strings, only: join_strings
  use fcs_material, only: material_t
  use fcs_material_factory, only: create_material, plastic_def_t, material_registry_t, &
    MATERIAL_MODEL_NAMES, PLASTICITY_NONE, builtin_material_registry
  use fcs_hardening_table, only: constant_table
  use fcs_test_assertions, only: test_suite_t
  use fcs_test_materials, only: test_elastic_entry, TEST_ELASTIC_NAME
  implicit none
  type(test_suite_t) :: suite
  real(dp), parameter :: YOUNGS = 210000.0_dp, POISSON = 0.3_dp
  character(len=*), parameter :: MATERIAL_NAMES = 'HYPOELASTIC, VON MISES, DRUCKER PRAGER'

  suite%name = 'fcs_material_factory'
  call check_builtin(suite)
  call check_registered_material(suite)
  call suite%report()

contains

  !> Each PLASTICITY_ value builds the model of its name; the registry's names are the three
  !> built-in models; a model the registry does not know is an input error listing them.
  subroutine check_builtin(suite)
    type(test_suite_t), intent(inout) :: suite
    type(material_registry_t) :: registry
    type(plastic_def_t) :: plastic
    class(material_t), allocatable :: material
    type(error_t), allocatable :: err
    registry = builtin_material_registry()
    call suite%check(join_strings(registry%names(), ', ') == MATERIAL_NAMES, &
                     'built-in names: the three models')
    call suite%equal_int(registry%find('von mises'), 2, 'find ignores case')
    plastic%model = PLASTICITY_NONE
    call create_material(YOUNGS, POISSON, plastic, material, err)
    call suite%check(.not. allocated(err) .and. allocated(material), 'HYPOELASTIC built')
    if (allocated(material)) call suite%check(material%name() == 'hypoelastic' .and. &
      material%youngs_modulus == YOUNGS .and. material%poisson_ratio == POISSON, &
      'HYPOELASTIC: name and elastic constants')
    plastic%hardening = 'ISOTROPIC'
    plastic%curve = constant_table(250.0_dp)
    call create_material(YOUNGS, POISSON, plastic, material, err, name='Von Mises')
    call suite%check(.not. allocated(err) .and. allocated(material), 'VON MISES built by name')
    if (allocated(material)) call suite%check(material%is_plastic(), 'VON MISES is plastic')
    plastic%model = 7
    call create_material(YOUNGS, POISSON, plastic, material, err)
    call suite%check(allocated(err), 'an unknown PLASTICITY_ value refused')
    call create_material(YOUNGS, POISSON, plastic, material, err, name=TEST_ELASTIC_NAME)
    call suite%check(allocated(err), 'the built-in registry does not know ' // TEST_ELASTIC_NAME)
    if (.not. allocated(err)) return
    call suite%equal_int(err%exit_code, EXIT_INPUT, 'unknown model: an input error')
    call suite%check(index(err%message, MATERIAL_NAMES) > 0, 'unknown model: lists the names')
    call suite%check(trim(MATERIAL_MODEL_NAMES(PLASTICITY_NONE)) == 'HYPOELASTIC', &
                     'PLASTICITY_NONE is HYPOELASTIC')
  end subroutine check_builtin

  !> The recipe "How to add a material" on a test-only material: registered, listed, built by
  !> create_material by name; one update with a uniaxial strain increment d gives
  !> sigma_11 = (lambda + 2 G) d and sigma_22 = sigma_33 = lambda d, no shear (to round-off).
  subroutine check_registered_material(suite)
    type(test_suite_t), intent(inout) :: suite
    type(material_registry_t) :: registry
    type(plastic_def_t) :: plastic
    class(material_t), allocatable :: material
    type(error_t), allocatable :: err
    real(dp) :: stress(6), tangent(6, 6), state(0), lambda, shear
    real(dp), parameter :: D = 1.0e-3_dp
    call registry%init()
    call registry%register(test_elastic_entry(), err)
    call suite%check(.not. allocated(err), 'registry: ' // TEST_ELASTIC_NAME // ' registered')
    call suite%check(join_strings(registry%names(), ', ') == MATERIAL_NAMES // ', ' // &
                     TEST_ELASTIC_NAME, 'registry: names list it')
    call create_material(YOUNGS, POISSON, plastic, material, err, name=TEST_ELASTIC_NAME, &
                         registry=registry)
    call suite%check(.not. allocated(err) .and. allocated(material), 'created by name')
    if (.not. allocated(material)) return
    call suite%check(material%name() == TEST_ELASTIC_NAME, 'its name()')
    call suite%check(material%youngs_modulus == YOUNGS .and. material%poisson_ratio == POISSON, &
                     'its elastic constants set by create_material')
    stress = 0.0_dp
    call material%update(stress, [D, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp, 0.0_dp], state, tangent)
    shear = YOUNGS / (2.0_dp * (1.0_dp + POISSON))
    lambda = YOUNGS * POISSON / ((1.0_dp + POISSON) * (1.0_dp - 2.0_dp * POISSON))
    call suite%close_array(stress, [(lambda + 2.0_dp * shear) * D, lambda * D, lambda * D, &
                           0.0_dp, 0.0_dp, 0.0_dp], 1.0e-14_dp, 'one update: uniaxial strain')
    call suite%close_array(reshape(tangent, [36]), reshape(material%elastic_matrix(), [36]), &
                           1.0e-15_dp, 'its consistent tangent is C')
    plastic%model = PLASTICITY_NONE
    call create_material(YOUNGS, POISSON, plastic, material, err, registry=registry)
    call suite%check(.not. allocated(err) .and. material%name() == 'hypoelastic', &
                     'the registry still builds the deck''s models')
    call registry%register(test_elastic_entry(), err)
    call suite%check(allocated(err), 'a second ' // TEST_ELASTIC_NAME // ' refused')
  end subroutine check_registered_material

end program test_fcs_material_factory
