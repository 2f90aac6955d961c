!> The keyword table: every keyword fcs3d accepts, with its parameters, defaults, units and
!> documentation. It is the single source of truth: the model builder validates cards against
!> it, `fcs3d --list-keywords` prints it and `doc/deck_reference.md` is generated from it.
!>
!> Keywords marked "CalculiX" keep the meaning they have in CalculiX 2.20 (ccx manual §6) and
!> Abaqus; "Abaqus" marks Abaqus keywords that CalculiX lacks (with Abaqus's meaning);
!> keywords marked "fcs3d" are our extensions in the same syntax.
module fcs_keywords
  use fcs_strings, only: string_t, to_upper
  use fcs_solver_factory, only: linear_solver_names, DEFAULT_LINEAR_SOLVER
  use fcs_element_catalogue, only: ELEMENT_KIND_NAMES
  use fcs_friction_factory, only: friction_parameter_t, friction_parameters, friction_laws, &
                                  friction_registry_t
  implicit none
  private
  public :: keyword_spec_t, param_spec_t, keyword_table, find_keyword, find_param_spec, same_name
  public :: without_blanks
  public :: PARAM_FLAG, PARAM_TEXT, PARAM_NAME, PARAM_REAL, PARAM_INTEGER, PARAM_CHOICE, PARAM_FILE
  public :: PARAM_IGNORED, friction_keyword_params
  public :: CONTEXT_MODEL, CONTEXT_STEP, CONTEXT_ANY, param_kind_name, context_name

  !> Parameter kinds: a flag without value, free text, a (case-insensitive) name of a set or
  !> material, a real or integer number, one of a list of choices, a file path; or a
  !> parameter that CalculiX decks carry and CalculiX only warns about ("parameter not
  !> recognized"): read with or without a value, ignored, and reported as a warning.
  integer, parameter :: PARAM_FLAG = 1, PARAM_TEXT = 2, PARAM_NAME = 3, PARAM_REAL = 4, &
                        PARAM_INTEGER = 5, PARAM_CHOICE = 6, PARAM_FILE = 7, PARAM_IGNORED = 8
  !> Where a keyword may appear: model definition (before the first *STEP), inside a step, or both.
  integer, parameter :: CONTEXT_MODEL = 1, CONTEXT_STEP = 2, CONTEXT_ANY = 3

  !> Output parameters that fcs3d honours by what it always does.
  character(len=*), parameter :: GLOBAL_ONLY = 'YES or NO give the same: results frames hold ' // &
    'global components (local *TRANSFORM axes are used by *NODE PRINT only, *ORIENTATION ' // &
    'axes by *EL PRINT only).'
  character(len=*), parameter :: SOLIDS_IN_3D = 'CalculiX''s choice for expanded shell and ' // &
    'beam elements; fcs3d''s solid elements are written in 3D either way (OUTPUT=2D is ' // &
    'accepted with a warning).'
  character(len=*), parameter :: WHOLE_FRAMES = 'Accepted with a warning: every result frame ' // &
    'holds every node (and every contact node), so the set does not restrict it.'
  !> The description of a PARAM_IGNORED parameter (also the text of its warning).
  character(len=*), parameter :: IGNORED_AS_CALCULIX = 'ignored, as CalculiX ignores it ' // &
    '("parameter not recognized")'

  type :: param_spec_t
    character(len=:), allocatable :: name
    integer :: kind = PARAM_TEXT
    !> Default value as text ('' = no default).
    character(len=:), allocatable :: default
    logical :: required = .false.
    !> Valid values of a PARAM_CHOICE, upper case.
    type(string_t), allocatable :: choices(:)
    !> For a PARAM_CHOICE that may also be written as a bare flag: the value the flag means.
    character(len=:), allocatable :: flag_value
    character(len=:), allocatable :: unit
    character(len=:), allocatable :: description
  end type param_spec_t

  type :: keyword_spec_t
    character(len=:), allocatable :: name
    integer :: context = CONTEXT_MODEL
    !> "CalculiX" (standard meaning), "Abaqus" (Abaqus's meaning) or "fcs3d" (our extension).
    character(len=:), allocatable :: origin
    character(len=:), allocatable :: summary
    !> What the data lines hold ('' = the keyword takes no data lines).
    character(len=:), allocatable :: data
    logical :: data_required = .false.
    type(param_spec_t), allocatable :: params(:)
  end type keyword_spec_t

contains

  !> The whole table, in the order of the deck reference.
  function keyword_table() result(table)
    type(keyword_spec_t), allocatable :: table(:)
    table = [ model_keywords(), material_keywords(), contact_keywords(), constraint_keywords(), &
              step_keywords(), output_keywords() ]
  end function keyword_table

  function model_keywords() result(t)
    type(keyword_spec_t), allocatable :: t(:)
    t = [ &
      kw('HEADING', CONTEXT_MODEL, 'CalculiX', 'Title of the analysis.', &
         'Free text; the first line becomes the title in the echo, the log and the results.', &
         [p_none()]), &
      kw('INCLUDE', CONTEXT_ANY, 'CalculiX', 'Insert another file at this point.', '', &
         [p('INPUT', PARAM_FILE, required=.true., &
            description='File to insert, relative to the file holding the *INCLUDE.')]), &
      kw('NODE', CONTEXT_MODEL, 'CalculiX', 'Define nodes.', &
         'node id, x, y, z (a missing coordinate is 0).', &
         [p('NSET', PARAM_NAME, description='Also add the nodes to this node set.')], &
         data_required=.true.), &
      kw('ELEMENT', CONTEXT_MODEL, 'CalculiX', 'Define elements.', &
         'element id, then its node ids in CalculiX order (a record continues on the next ' // &
         'line after a trailing comma).', &
         [p('TYPE', PARAM_CHOICE, required=.true., choices=names(ELEMENT_KIND_NAMES), &
            description='Element type, CalculiX''s 3D solids: C3D4 (linear tetrahedron, 1 point), ' // &
            'C3D6 (linear wedge, 2 points), C3D8 (8-node hexahedron, 2x2x2 points; *SOLID ' // &
            'SECTION, FORMULATION=BBAR against volumetric locking), C3D8R (1 point, hourglass ' // &
            'control), C3D8I (incompatible modes), C3D10 (quadratic tetrahedron, 4 points), ' // &
            'C3D15 (quadratic wedge, 9 points), C3D20 (20-node hexahedron, 3x3x3 points), ' // &
            'C3D20R (20-node hexahedron, 2x2x2 points). Node numbering and integration as ' // &
            'CalculiX''s (doc/elements.md).'), &
          p('ELSET', PARAM_NAME, description='Also add the elements to this element set.')], &
         data_required=.true.), &
      kw('NSET', CONTEXT_MODEL, 'CalculiX', 'Define or extend a node set.', &
         'node ids or names of node sets; with GENERATE: first, last[, increment].', &
         [p('NSET', PARAM_NAME, required=.true., description='Name of the set.'), &
          p('GENERATE', PARAM_FLAG, description='Data lines are first, last, increment.'), &
          p('FREQUENCY', PARAM_IGNORED, description=IGNORED_AS_CALCULIX)], &
         data_required=.true.), &
      kw('ELSET', CONTEXT_MODEL, 'CalculiX', 'Define or extend an element set.', &
         'element ids or names of element sets; with GENERATE: first, last[, increment].', &
         [p('ELSET', PARAM_NAME, required=.true., description='Name of the set.'), &
          p('GENERATE', PARAM_FLAG, description='Data lines are first, last, increment.'), &
          p('FREQUENCY', PARAM_IGNORED, description=IGNORED_AS_CALCULIX)], &
         data_required=.true.), &
      kw('SURFACE', CONTEXT_MODEL, 'CalculiX', 'Define a surface.', &
         'TYPE=ELEMENT: element id or element set, face S1..S6. TYPE=NODE: node id or node set.', &
         [p('NAME', PARAM_NAME, required=.true., description='Name of the surface.'), &
          p('TYPE', PARAM_CHOICE, default='ELEMENT', choices=[s('ELEMENT'), s('NODE')], &
            description='Element-face surface or node-based surface.')], &
         data_required=.true.), &
      kw('MESH', CONTEXT_MODEL, 'fcs3d', 'Read nodes, 3D elements (tetrahedra, prisms, ' // &
         'hexahedra; first or second order; mixed) and physical groups from a gmsh mesh file ' // &
         '(MSH 4.1, ASCII or binary).', '', &
         [p('FILE', PARAM_FILE, required=.true., &
            description='The .msh file, relative to the deck holding *MESH. Read: 4- and ' // &
            '10-node tetrahedra (C3D4, C3D10), 6- and 15-node prisms (C3D6, C3D15), 8- and ' // &
            '20-node hexahedra (see HEX8, HEX20), their nodes renumbered from gmsh''s order to ' // &
            'CalculiX''s; for second order mesh with Mesh.ElementOrder = 2 and ' // &
            'Mesh.SecondOrderIncomplete = 1 (27-node hexahedra, 18-node prisms, 9-node ' // &
            'quadrangles and pyramids are refused). Physical volumes ' // &
            'become element and node sets; physical surfaces (3-, 6-node triangles, 4-, 8-node ' // &
            'quadrangles on element faces) become element-face surfaces and node sets; ' // &
            'physical curves and points become node sets; each named by the physical name ' // &
            '(upper case) or SURFACE_<tag> etc.'), &
          p('HEX8', PARAM_CHOICE, default='C3D8', choices=[s('C3D8'), s('C3D8R'), s('C3D8I')], &
            description='Element type of the 8-node hexahedra (gmsh type 5).'), &
          p('HEX20', PARAM_CHOICE, default='C3D20', choices=[s('C3D20'), s('C3D20R')], &
            description='Element type of the 20-node hexahedra (gmsh type 17).')]), &
      kw('RESTART', CONTEXT_ANY, 'CalculiX', 'Write checkpoints to continue the run later ' // &
         '(fcs3d job.inp --restart job.rst.h5). Whatever is set here, a checkpoint is also ' // &
         'written at the end of every step and when SIGTERM or SIGINT stops the run.', '', &
         [p('WRITE', PARAM_FLAG, required=.true., description='Write checkpoints (the only ' // &
            'mode: a restart is asked for on the command line).'), &
          p('FREQUENCY', PARAM_INTEGER, default='0', description='Every N increments (0: not ' // &
            'by count).'), &
          p('INTERVAL', PARAM_REAL, default='600', unit='s (wall time)', description='Every this ' // &
            'many seconds of wall time (0: not by time) (fcs3d extension).'), &
          p('GENERATIONS', PARAM_INTEGER, default='2', description='How many checkpoints are ' // &
            'kept: <job>.rst.h5 (newest), <job>.rst.1.h5, ... (fcs3d extension).')]), &
      kw('SOLVER', CONTEXT_MODEL, 'fcs3d', 'Choose the linear solver.', '', &
         [p('TYPE', PARAM_CHOICE, default=DEFAULT_LINEAR_SOLVER, &
            choices=linear_solver_names(), &
            description='UMFPACK (SuiteSparse, default), SKYLINE (profile LU with reverse ' // &
            'Cuthill-McKee numbering) or MUMPS. The command line option --solver overrides it.'), &
          p('REUSE TOLERANCE', PARAM_REAL, default='0', unit='-', description='Relative ' // &
            'residual |b - A x| / |b| to which a new tangent is solved with the factors of an ' // &
            'earlier one, by GMRES preconditioned by them, instead of factorising it ' // &
            '(doc/theory.md section 7.1); the factors are renewed when GMRES needs many ' // &
            'iterations or does not converge, and when the sparsity pattern changes. 0 ' // &
            '(default): factorise every tangent. Recommended when on: 1e-10, far below the ' // &
            'equilibrium tolerance (1e-3 of the force scale); on the block-sliding test deck ' // &
            'the results agree with those of fresh factorisations within 1e-12 of their ' // &
            'scale. A restarted run starts from a fresh factorisation, so with reuse on it ' // &
            'agrees with the uninterrupted run to that level, not bit for bit. Range ' // &
            '[0, 1e-3]. The command line option --reuse-tolerance overrides it.'), &
          p('LOW RANK TOLERANCE', PARAM_REAL, default='0', unit='-', description='Block ' // &
            'low-rank (BLR) factorisation with MUMPS (TYPE=MUMPS only): the dropping parameter ' // &
            'eps of the low-rank compressions of the frontal matrices (MUMPS ICNTL(35)=2, ' // &
            'CNTL(7)=eps). 0 (default): the exact, full-rank factorisation. With eps > 0 the ' // &
            'factors are approximate: a solve with them has a relative error of order eps times a ' // &
            'condition factor. The equilibrium iterations of each increment correct the ' // &
            'out-of-balance force to the EQUILIBRIUM TOLERANCE of *RMIN (1e-3 of the force ' // &
            'scale by default), so the converged answers stay within that tolerance; the ' // &
            'R-minimum event fractions, which come from the trial solve, move by about eps ' // &
            'relative times a condition factor, so near-simultaneous events may be taken in ' // &
            'another order. The gain grows with the size of the fronts; on the contact benchmark ' // &
            'at 102,408 ' // &
            'degrees of freedom (doc/performance.md section 10) eps = 1e-6 cut the factor ' // &
            'entries to 78 % and the peak memory to 89 %, but no factorisation was faster ' // &
            'than full rank (MUMPS 5.5.1, one thread). The run summary gives the effective entries and flops. MUMPS ' // &
            '5.5.1''s BLR factors are repeatable only to round-off from run to run. Range ' // &
            '[0, 1e-2]. The command line option --low-rank-tolerance overrides it.')]) &
      ]
  end function model_keywords

  function material_keywords() result(t)
    type(keyword_spec_t), allocatable :: t(:)
    t = [ &
      kw('MATERIAL', CONTEXT_MODEL, 'CalculiX', 'Start a material definition; the ' // &
         'following *ELASTIC, *HYPOELASTIC, *HYPERELASTIC, *HYPERFOAM, *DEFORMATION PLASTICITY, ' // &
         '*DENSITY, *PLASTIC, ' // &
         '*CYCLIC HARDENING, *DRUCKER PRAGER and ' // &
         '*DRUCKER PRAGER HARDENING lines belong to it.', '', &
         [p('NAME', PARAM_NAME, required=.true., description='Name of the material.')]), &
      kw('ELASTIC', CONTEXT_MODEL, 'CalculiX', 'Elastic constants of the current material. ' // &
         'Small strain: sigma = C : eps. Under NLGEOM, CalculiX''s St Venant-Kirchhoff law: ' // &
         'the second Piola-Kirchhoff stress S = C : (E - E_th) of the Green-Lagrange strain E, ' // &
         'C in the reference axes, and E output is E (doc/theory.md section 2.10); with ' // &
         '*PLASTIC, CalculiX''s multiplicative finite-strain plasticity (section 2.8); with ' // &
         '*DRUCKER PRAGER, and in C3D8I elements, the hypoelastic rate form of *HYPOELASTIC. ' // &
         'TYPE=ISO: isotropic, constant or as a table over ' // &
         'temperature (linear between the lines, constant beyond the first and last, as ' // &
         'CalculiX; elastic materials only, not with plasticity); with a table the stress ' // &
         'follows sigma = C(T) eps_el as in CalculiX (doc/theory.md section 2.5). ' // &
         'TYPE=ORTHO, ENGINEERING CONSTANTS, ANISO: a constant stiffness in the material ' // &
         'axes of the section''s *ORIENTATION (global axes without one), CalculiX''s order ' // &
         'of the constants (doc/theory.md section 2.9); it must be positive definite; not with ' // &
         'plasticity, temperature tables, C3D8I or C3D8R elements.', &
         'TYPE=ISO: Young''s modulus [stress], Poisson''s ratio [-][, temperature]: one line, ' // &
         'or one line per temperature, temperatures strictly increasing. ORTHO: D1111, D1122, ' // &
         'D2222, D1133, D2233, D3333, D1212, D1313, D2323 [stress][, temperature]. ' // &
         'ENGINEERING CONSTANTS: E1, E2, E3 [stress], nu12, nu13, nu23 [-], G12, G13, G23 ' // &
         '[stress][, temperature]. ANISO: D1111, D1122, D2222, D1133, D2233, D3333, D1112, ' // &
         'D2212, D3312, D1212, D1113, D2213, D3313, D1213, D1313, D1123, D2223, D3323, D1223, ' // &
         'D1323, D2323 [stress][, temperature]. The constants may be spread over lines as ' // &
         'CalculiX writes them (8 per line); one set only (the temperature is ignored).', &
         [p('TYPE', PARAM_CHOICE, default='ISO', choices=[s('ISO'), s('ISOTROPIC'), s('ORTHO'), &
            s('ORTHOTROPIC'), s('ENGINEERING CONSTANTS'), s('ANISO'), s('ANISOTROPIC')], &
            description='Isotropic, orthotropic (9 stiffness constants, or 9 engineering ' // &
            'constants) or fully anisotropic (21 constants).')], data_required=.true.), &
      kw('HYPOELASTIC', CONTEXT_MODEL, 'Abaqus', 'Isotropic hypoelastic constants of the ' // &
         'current material: the rate form sigma^J = C : D of Xing, Mora & Makinouchi (2003), ' // &
         'eq. 1 (Jaumann rate of the Cauchy stress, constant isotropic C; doc/theory.md ' // &
         'section 1.2), the law of the fault-bend reference run. Without NLGEOM the same as ' // &
         '*ELASTIC. Abaqus'' dependence on the strain invariants, on temperature or on field ' // &
         'variables, and its user subroutine (USER) are not available.', &
         'Young''s modulus [stress], Poisson''s ratio [-]: one line.', &
         [p_none()], data_required=.true.), &
      kw('HYPERELASTIC', CONTEXT_MODEL, 'CalculiX', 'Isotropic hyperelastic law of the ' // &
         'current material (ccx manual, *HYPERELASTIC): the Cauchy stress from the strain ' // &
         'energy U of the reduced invariants Ibar_1, Ibar_2 and J of C = F^T F (polynomial ' // &
         'forms, Arruda-Boyce) or of the deviatoric stretches (Ogden), as CalculiX defines ' // &
         'them (doc/theory.md section 2.11). NEO HOOKE: U = C10 (Ibar_1 - 3) + (J - 1)^2/D1; ' // &
         'MOONEY-RIVLIN adds C01 (Ibar_2 - 3); POLYNOMIAL: sum C_ij (Ibar_1 - 3)^i (Ibar_2 - ' // &
         '3)^j, i + j <= N; REDUCED POLYNOMIAL: C_i0 only; YEOH: REDUCED POLYNOMIAL with N=3; ' // &
         'OGDEN: sum 2 mu_i/alpha_i^2 (lambdabar_1^alpha_i + lambdabar_2^alpha_i + ' // &
         'lambdabar_3^alpha_i - 3); volumetric sum (J - 1)^(2i)/D_i. As CalculiX, NLGEOM is ' // &
         'turned on in every step (NLGEOM=NO is refused) and a D_i given as 0 becomes ' // &
         '(0.1/mu_0)^i (an initial Poisson''s ratio of 0.475), with a warning. Not with ' // &
         'plasticity, *EXPANSION, C3D8I elements or *EL PRINT ENER/ELSE; VAN DER WAALS is ' // &
         'not available.', &
         'ARRUDA-BOYCE: mu, lambda_m, D. MOONEY-RIVLIN: C10, C01, D1. NEO HOOKE: C10, D1. ' // &
         'OGDEN, N=1: mu_1, alpha_1, D1; N=2: mu_1, alpha_1, mu_2, alpha_2, D1, D2; N=3: a ' // &
         'pair of lines, mu_1, alpha_1, mu_2, alpha_2, mu_3, alpha_3, D1, D2 / D3. POLYNOMIAL, ' // &
         'N=1: C10, C01, D1; N=2: C10, C01, C20, C11, C02, D1, D2; N=3: a pair of lines, C10, ' // &
         'C01, C20, C11, C02, C30, C21, C12 / C03, D1, D2, D3. REDUCED POLYNOMIAL, N=1: C10, ' // &
         'D1; N=2: C10, C20, D1, D2; N=3: C10, C20, C30, D1, D2, D3. YEOH: C10, C20, C30, D1, ' // &
         'D2, D3. Each set ends with an optional temperature; one set only (constants that ' // &
         'depend on temperature are refused). Left-out D_i are 0.', &
         [p('ARRUDA-BOYCE', PARAM_FLAG, description='Arruda-Boyce form.'), &
          p('MOONEY-RIVLIN', PARAM_FLAG, description='Mooney-Rivlin form (POLYNOMIAL, N=1).'), &
          p('NEO HOOKE', PARAM_FLAG, description='Neo-Hooke form (REDUCED POLYNOMIAL, N=1).'), &
          p('OGDEN', PARAM_FLAG, description='Ogden form, order N.'), &
          p('POLYNOMIAL', PARAM_FLAG, description='Polynomial form, order N (the default form).'), &
          p('REDUCED POLYNOMIAL', PARAM_FLAG, description='Reduced polynomial form, order N.'), &
          p('YEOH', PARAM_FLAG, description='Yeoh form (REDUCED POLYNOMIAL, N=3).'), &
          p('VAN DER WAALS', PARAM_FLAG, description='Refused: not available in fcs3d.'), &
          p('N', PARAM_INTEGER, default='1', description='Order of OGDEN, POLYNOMIAL and ' // &
            'REDUCED POLYNOMIAL: 1, 2 or 3.')], data_required=.true.), &
      kw('HYPERFOAM', CONTEXT_MODEL, 'CalculiX', 'Hyperfoam law of the current material ' // &
         '(ccx manual, *HYPERFOAM): U = sum 2 mu_i/alpha_i^2 (lambda_1^alpha_i + ' // &
         'lambda_2^alpha_i + lambda_3^alpha_i - 3 + (J^(-alpha_i beta_i) - 1)/beta_i) of the ' // &
         'principal stretches, beta_i = nu_i/(1 - 2 nu_i) (doc/theory.md section 2.11). As ' // &
         'CalculiX, NLGEOM is turned on in every step (NLGEOM=NO is refused). Not with ' // &
         'plasticity, *EXPANSION, C3D8I elements or *EL PRINT ENER/ELSE.', 'N=1: mu_1, alpha_1, nu_1; N=2: mu_1, ' // &
         'alpha_1, mu_2, alpha_2, nu_1, nu_2; N=3: a pair of lines, mu_1, alpha_1, mu_2, ' // &
         'alpha_2, mu_3, alpha_3, nu_1, nu_2 / nu_3; each set ends with an optional ' // &
         'temperature; one set only (constants that depend on temperature are refused).', &
         [p('N', PARAM_INTEGER, default='1', description='Number of terms: 1, 2 or 3.')], &
         data_required=.true.), &
      kw('DEFORMATION PLASTICITY', CONTEXT_MODEL, 'CalculiX', 'Ramberg-Osgood deformation ' // &
         'plasticity of the current material (ccx manual, *DEFORMATION PLASTICITY; Ramberg & ' // &
         'Osgood 1943): a total, nonlinear elastic law, E e = (1 + nu) s - (1 - 2 nu) p I + ' // &
         '3/2 alpha (q/sigma_0)^(n - 1) s of the Cauchy stress (s its deviator, p the ' // &
         'pressure, q the Mises stress) and the Almansi strain e; in uniaxial stress E eps = ' // &
         'sigma + alpha (|sigma|/sigma_0)^(n - 1) sigma (doc/theory.md section 2.12). As ' // &
         'CalculiX, NLGEOM is turned on in every step (NLGEOM=NO is refused); unloading ' // &
         'follows the loading curve. Not with *ELASTIC, *PLASTIC, *EXPANSION, C3D8I elements ' // &
         'or *EL PRINT ENER/ELSE.', &
         'Young''s modulus E [stress], Poisson''s ratio nu [-], yield stress sigma_0 [stress], ' // &
         'exponent n [-] (>= 1), yield offset alpha [-] (>= 0), an optional temperature: one ' // &
         'line (constants that depend on temperature are refused).', &
         [p_none()], data_required=.true.), &
      kw('EXPANSION', CONTEXT_MODEL, 'CalculiX', 'Isotropic thermal expansion of the ' // &
         'current material: the secant coefficient alpha from the reference temperature ZERO, ' // &
         'thermal strain alpha(T) (T - ZERO) - alpha(T0) (T0 - ZERO) from the initial ' // &
         'temperature T0, as CalculiX (doc/theory.md section 2.5).', 'alpha [1/temperature]' // &
         '[, temperature]: one line, or one line per temperature, temperatures strictly ' // &
         'increasing (linear between them, constant beyond the first and last).', &
         [p('ZERO', PARAM_REAL, default='0', unit='temperature', description='Reference ' // &
            'temperature of the secant coefficients.'), &
          p('TYPE', PARAM_CHOICE, default='ISO', choices=[s('ISO')], description='Only ' // &
            'isotropic expansion is available.')], data_required=.true.), &
      kw('DENSITY', CONTEXT_MODEL, 'CalculiX', 'Mass density of the current material ' // &
         '(used by the body loads GRAV and CENTRIF of *DLOAD and by radiation damping).', &
         'density [mass/length^3][, temperature]: one line, or a table over temperature whose ' // &
         'lines all give the same density (a density that varies with temperature is refused).', &
         [p_none()], data_required=.true.), &
      kw('PLASTIC', CONTEXT_MODEL, 'CalculiX', 'von Mises plasticity of the current material ' // &
         '(radial return in the rotated frame; doc/theory.md section 2.2; under NLGEOM with ' // &
         '*ELASTIC, CalculiX''s multiplicative finite-strain model of Simo 1988, section ' // &
         '2.8, with *HYPOELASTIC the rotated-frame rate form). The curve is read as ' // &
         'CalculiX reads it: ISOTROPIC, the yield stress; KINEMATIC, the yield surface keeps ' // &
         'the first stress as its radius and its centre (back stress) moves so that uniaxial ' // &
         'loading follows the curve; COMBINED, as KINEMATIC with the radius from *CYCLIC ' // &
         'HARDENING.', 'von Mises stress [stress], equivalent plastic strain [-]: one point ' // &
         'per line, the first at plastic strain 0, plastic strains strictly increasing, ' // &
         'stresses positive; linear between the points, constant beyond the last. A third ' // &
         'field (temperature) is refused: temperature-dependent curves are not available.', &
         [p('HARDENING', PARAM_CHOICE, default='ISOTROPIC', &
            choices=[s('ISOTROPIC'), s('KINEMATIC'), s('COMBINED')], &
            description='Isotropic, kinematic (linear in the curve''s slope, Prager-Ziegler ' // &
            'type, as CalculiX) or combined hardening (needs *CYCLIC HARDENING).')], &
         data_required=.true.), &
      kw('CYCLIC HARDENING', CONTEXT_MODEL, 'CalculiX', 'The isotropic part (yield surface ' // &
         'radius against equivalent plastic strain) of *PLASTIC, HARDENING=COMBINED.', &
         'von Mises stress [stress], equivalent plastic strain [-], as for *PLASTIC.', &
         [p_none()], data_required=.true.), &
      kw('DRUCKER PRAGER', CONTEXT_MODEL, 'Abaqus', 'Linear Drucker-Prager plasticity of the ' // &
         'current material (Abaqus''s extended Drucker-Prager model, linear criterion): ' // &
         'F = q - p tan(beta) - d, flow potential q - p tan(psi) (doc/theory.md section 2.3). ' // &
         'Needs *DRUCKER PRAGER HARDENING.', 'friction angle beta [degree] in [0, 71.565) ' // &
         '(tan(beta) < 3) for TYPE=COMPRESSION hardening, [0, 90) otherwise; flow stress ' // &
         'ratio K (empty or 1: other values are refused); dilation angle psi [degree] in the ' // &
         'same range (psi = beta: associated flow; psi /= beta: non-associated, unsymmetric ' // &
         'tangent). A temperature (fourth field) is refused.', &
         [p('SHEAR CRITERION', PARAM_CHOICE, default='LINEAR', choices=[s('LINEAR')], &
            description='Only the linear criterion is available.')], data_required=.true.), &
      kw('DRUCKER PRAGER HARDENING', CONTEXT_MODEL, 'Abaqus', 'Hardening curve of the ' // &
         'current *DRUCKER PRAGER material.', 'yield stress [stress], absolute value of the ' // &
         'plastic strain [-] of the test TYPE names: one point per line, the first at plastic ' // &
         'strain 0, plastic strains strictly increasing, stresses positive; constant beyond ' // &
         'the last. Further fields (rate, temperature) are refused.', &
         [p('TYPE', PARAM_CHOICE, default='COMPRESSION', &
            choices=[s('COMPRESSION'), s('TENSION'), s('SHEAR')], &
            description='The test the curve comes from: uniaxial compression (d = (1 - ' // &
            'tan(beta)/3) sigma_c), uniaxial tension (d = (1 + tan(beta)/3) sigma_t) or pure ' // &
            'shear (d = sqrt(3) tau), as Abaqus defines them for K = 1.')], &
         data_required=.true.), &
      kw('INITIAL CONDITIONS', CONTEXT_MODEL, 'CalculiX', 'Initial values: nodal ' // &
         'temperatures (TYPE=TEMPERATURE; a node not named starts at temperature 0, as in ' // &
         'CalculiX) or stresses at the integration points (TYPE=STRESS: the stress the ' // &
         'analysis starts from; what it does not balance is the out-of-balance force of the ' // &
         'first increment) or plastic strains at the integration points (TYPE=PLASTIC ' // &
         'STRAIN: as CalculiX, a strain eps_0 the material does not resist, for elastic and ' // &
         'von Mises materials: the stress starts at -C : eps_0, a von Mises point''s plastic ' // &
         'strain at eps_0 and its equivalent plastic strain at 0; doc/theory.md 2.7).', &
         'TEMPERATURE: node or node set, temperature. STRESS: element ' // &
         '(or element set), integration point, sxx, syy, szz, sxy, sxz, syz [stress], as ' // &
         'CalculiX. STRESS with GEOSTATIC: element or element set, s1, z1, s2, z2, k_x[, k_y]: ' // &
         'szz linear in the height z (third coordinate) through (z1, s1) and (z2, s2), ' // &
         'sxx = k_x szz, syy = k_y szz (k_y = k_x when empty), no shear: a lithostatic ' // &
         'pre-stress (Abaqus syntax). PLASTIC STRAIN: element (or element set), integration ' // &
         'point, exx, eyy, ezz, exy, exz, eyz [-], tensor shears, as CalculiX; with a von ' // &
         'Mises material the tensor is deviatoric (plastic flow keeps the volume).', &
         [p('TYPE', PARAM_CHOICE, required=.true., choices=[s('TEMPERATURE'), s('STRESS'), &
            s('PLASTIC STRAIN')], &
            description='What is given.'), &
          p('GEOSTATIC', PARAM_FLAG, description='TYPE=STRESS: the stress varies linearly ' // &
            'with height, given by two points and the lateral coefficients (Abaqus).')], &
         data_required=.true.), &
      kw('SOLID SECTION', CONTEXT_MODEL, 'CalculiX', 'Assign a material to an element set ' // &
         '(the material may be defined after the section, as in CalculiX).', &
         'optional: the thickness of plane elements; for solid elements it is ignored, with a ' // &
         'warning, as CalculiX ignores it.', &
         [p('ELSET', PARAM_NAME, required=.true., description='Element set.'), &
          p('MATERIAL', PARAM_NAME, required=.true., description='Material name.'), &
          p('ORIENTATION', PARAM_NAME, description='Name of an *ORIENTATION: the material ' // &
            'axes of the elements (an anisotropic stiffness is given in them; *EL PRINT ' // &
            'with GLOBAL=NO prints S and E in them).'), &
          p('OFFSET', PARAM_IGNORED, description=IGNORED_AS_CALCULIX), &
          p('FORMULATION', PARAM_CHOICE, default='FULL', choices=[s('FULL'), s('BBAR')], &
            description='FULL: 2x2x2 Gauss integration of everything (CalculiX C3D8). BBAR: ' // &
            'volumetric strain taken as its element mean (selective reduced integration, ' // &
            'Hughes 1980), which removes volumetric locking (fcs3d extension).')]), &
      kw('ORIENTATION', CONTEXT_MODEL, 'CalculiX', 'Local material axes for the sections that ' // &
         'name it (*SOLID SECTION, ORIENTATION=), at every integration point (from its ' // &
         'position in the reference configuration), as CalculiX (doc/theory.md section 2.9). ' // &
         'RECTANGULAR: e1 along a, e2 the part of b normal to a, e3 = e1 x e2. CYLINDRICAL: ' // &
         'a and b are two points of the axis; e1 radial, e2 tangential, e3 along b - a.', &
         'a1, a2, a3, b1, b2, b3 [length]; optionally a second line: a local axis (1, 2 or 3) ' // &
         'and an angle [degree] to turn the axes about it (RECTANGULAR only).', &
         [p('NAME', PARAM_NAME, required=.true., description='Name of the orientation.'), &
          p('SYSTEM', PARAM_CHOICE, default='RECTANGULAR', choices=[s('RECTANGULAR'), &
            s('R'), s('CYLINDRICAL'), s('C')], description='Rectangular or cylindrical axes.'), &
          p('DEFINITION', PARAM_CHOICE, default='COORDINATES', choices=[s('COORDINATES')], &
            description='The axes are given by coordinates (the only way CalculiX reads).')], &
         data_required=.true.) &
      ]
  end function material_keywords

  function contact_keywords() result(t)
    type(keyword_spec_t), allocatable :: t(:)
    t = [ &
      kw('SURFACE INTERACTION', CONTEXT_MODEL, 'CalculiX', 'Start a contact interaction; ' // &
         'the following *SURFACE BEHAVIOR and *FRICTION belong to it. It may follow the ' // &
         '*CONTACT PAIR that names it, as in CalculiX.', '', &
         [p('NAME', PARAM_NAME, required=.true., description='Name of the interaction.')]), &
      kw('SURFACE BEHAVIOR', CONTEXT_ANY, 'CalculiX', 'Normal behaviour of the current ' // &
         'interaction: the contact pressure against the overclosure, linear (penalty slope ' // &
         'E_n) or exponential. In a step, right after *CHANGE SURFACE BEHAVIOR: the new ' // &
         'behaviour of that interaction.', &
         'EXPONENTIAL: c0 [length], p0 [stress]: p = p0 exp(-beta g), beta = ln(100)/c0, g ' // &
         'the clearance (negative in penetration), as CalculiX: p0 at contact, p0/100 at the ' // &
         'clearance c0; a node or contact point carries it while g <= c0 (CalculiX''s rule), so ' // &
         'also at positive clearance; past beta (-g) = 23 it continues linearly (CalculiX caps ' // &
         'the force at e^23 instead); c0 > 0, p0 >= 0 (doc/theory.md 4.11). ' // &
         'LINEAR and TIED: slope K = E_n [stress/length][, sigma_inf [stress][, c0 [-]]]. fcs3d''s penalty is ' // &
         'p = K max(overclosure, 0). sigma_inf and c0 are read and ignored, with a warning: ' // &
         'CalculiX''s node-to-face law is smoothed, with a tension tending to sigma_inf at ' // &
         'large clearance and p = K overclosure - sigma_inf at large overclosure (its ' // &
         'penetrations exceed fcs3d''s by sigma_inf / K at the same pressure); c0 scales the ' // &
         'clearance within which CalculiX makes contact elements. ' // &
         'Without *SURFACE BEHAVIOR, E_n = 10 E / h (E the master body''s Young''s modulus, ' // &
         'h the mean thickness of the master elements).', &
         [p('PRESSURE-OVERCLOSURE', PARAM_CHOICE, required=.true., &
            choices=[s('LINEAR'), s('EXPONENTIAL'), s('TIED')], &
            description='LINEAR: penalty contact (opens under tension). EXPONENTIAL: ' // &
            'CalculiX''s exponential law (soft contact acting up to the clearance c0). TIED: the pair is ' // &
            'tied (no separation, no slip), the "stick" segments of the paper.')], &
         data_required=.true.), &
      kw('FRICTION', CONTEXT_ANY, 'CalculiX', 'Friction of the current interaction, treated ' // &
         'like plasticity: stick with stiffness E_t, slip on the cone |f_t| = mu f_n with ' // &
         'mu = mu(f_n, V, phi) (paper eqs. 2-6). LAW= and the law''s parameters are fcs3d ' // &
         'extensions; doc/friction.md gives each law. In a step, right after *CHANGE ' // &
         'FRICTION: the new Coulomb friction of that interaction.', &
         'COULOMB only (the CalculiX form, instead of MU0=): mu, stick slope E_t [stress/length].', &
         friction_keyword_params()), &
      kw('CHANGE FRICTION', CONTEXT_STEP, 'CalculiX', 'Change the friction of an interaction ' // &
         'from this step on: the *FRICTION that follows (Coulomb: mu[, stick slope]) replaces ' // &
         'it. At the start of the step every closed node takes the new mu; a friction force ' // &
         'beyond the new cone is brought back onto it (the node slips), as a return mapping ' // &
         'does. Only Coulomb friction can be changed.', '', &
         [p('INTERACTION', PARAM_NAME, required=.true., description='The *SURFACE INTERACTION.')]), &
      kw('CHANGE SURFACE BEHAVIOR', CONTEXT_STEP, 'CalculiX', 'Change the normal behaviour ' // &
         'of an interaction from this step on: the *SURFACE BEHAVIOR that follows replaces it ' // &
         '(LINEAR: new penalty; EXPONENTIAL: new c0, p0; either law may replace the other). ' // &
         'A TIED interaction changed to LINEAR or EXPONENTIAL is released at the start of the ' // &
         'step: its tie stops coupling the surfaces and its slave nodes become contact nodes ' // &
         '(node to surface, also for a SURFACE TO SURFACE pair), open until they touch. ' // &
         'Tying an untied interaction in a step is refused.', '', &
         [p('INTERACTION', PARAM_NAME, required=.true., description='The *SURFACE INTERACTION.')]), &
      kw('CONTACT PAIR', CONTEXT_MODEL, 'CalculiX', 'A node-to-point contact pair: the slave ' // &
         'surface''s nodes (or, TYPE=SURFACE TO SURFACE, the integration points of its faces) ' // &
         'against points of the master surface''s faces.', &
         'slave surface (element-face or node based), master surface (element-face).', &
         [p('INTERACTION', PARAM_NAME, required=.true., description='The *SURFACE INTERACTION.'), &
          p('TYPE', PARAM_CHOICE, default='NODE TO SURFACE', choices=[s('NODE TO SURFACE'), &
            s('SURFACE TO SURFACE')], &
            description='NODE TO SURFACE: each slave node against a point of a master face, ' // &
            'with its tributary area. SURFACE TO SURFACE: each integration point of the slave ' // &
            'faces instead (area = Gauss weight x surface Jacobian, forces spread to the face''s ' // &
            'nodes by its shape functions); a 4- or 8-node slave face covered by 4- or 8-node ' // &
            'master faces is cut by them, other faces take their Gauss rule (doc/theory.md 4.10). The ' // &
            'penalties K of *SURFACE BEHAVIOR and the stick slope of *FRICTION are per unit ' // &
            'area in both, as CalculiX''s surface-to-surface ones are. TIED pairs are ' // &
            'segment-to-segment ties either way. SURFACE TO SURFACE needs an element-face ' // &
            'slave surface and excludes *CONTACT PRINT (no table by slave node).'), &
          p('NAME', PARAM_NAME, description='Name of the pair in the log and results ' // &
            '(default: slave-master) (fcs3d extension).'), &
          p('SMALL SLIDING', PARAM_FLAG, description='CalculiX then finds each slave ' // &
            'node''s master face once per increment instead of in every iteration. Accepted ' // &
            'with a warning: fcs3d always finds it once per increment (and keeps it through ' // &
            'the increment''s equilibrium iterations) and follows the node over the master ' // &
            'surface from increment to increment (finite sliding).'), &
          p('ADJUST', PARAM_TEXT, unit='length, or a node set', description='A clearance: slave nodes whose ' // &
            'gap to the master surface (signed, along its normal) is at most this, penetrating ' // &
            'ones included, are moved onto the master before the analysis (the mesh ' // &
            'coordinates change; doc/theory.md 4.13). Or a node set: its slave nodes are ' // &
            'moved, whatever their gap. Nodes whose projection falls on no master face stay.')], &
         data_required=.true.), &
      kw('TIE', CONTEXT_MODEL, 'CalculiX', 'Tie a slave surface to a master surface: no ' // &
         'relative motion ever. Between 4-node faces a segment-to-segment penalty tie ' // &
         '(penalty E_n = 10 E / h, passing the patch test on non-matching meshes); with ' // &
         'triangular or quadratic faces on either side, CalculiX''s tie: each slave node ' // &
         'bound to its closest master point by one linear equation per direction ' // &
         '(doc/theory.md 4.7). Slave nodes of ' // &
         'a contact pair that a tie holds are left to the tie (a note in the log).', &
         'slave surface, master surface.', &
         [p('NAME', PARAM_NAME, required=.true., description='Name of the tie.'), &
          p('POSITION TOLERANCE', PARAM_REAL, unit='length', description='Slave nodes ' // &
            'farther than this from the master surface are not tied (default: 5% of the ' // &
            'mean master face size).'), &
          p('ADJUST', PARAM_CHOICE, default='NO', choices=[s('NO'), s('YES')], &
            description='fcs3d ties each slave node at its initial distance from the master ' // &
            '(no initial stress); ADJUST=YES is accepted for CalculiX decks and behaves the same.')], &
         data_required=.true.) &
      ]
  end function contact_keywords

  !> Linear constraints (fcs_linear_constraints; doc/theory.md 6.2).
  function constraint_keywords() result(t)
    type(keyword_spec_t), allocatable :: t(:)
    t = [ &
      kw('EQUATION', CONTEXT_MODEL, 'CalculiX', 'Linear equations between displacement ' // &
         'components, sum_k a_k u_k = 0 (global axes). The first term''s degree of freedom ' // &
         'is dependent: it is eliminated from the system (u_d = -sum_k>1 a_k u_k / a_1, as ' // &
         'CalculiX does; a dependent term used in another equation is replaced by its own ' // &
         'equation), and may not be prescribed by *BOUNDARY. RF at the nodes of an equation ' // &
         'is their internal force, as CalculiX prints it (the constraint force).', &
         'per equation: the number of terms N on its own line, then N terms node, direction ' // &
         '(1..3), coefficient, at most four terms per line.', &
         [p_none()], data_required=.true.), &
      kw('MPC', CONTEXT_MODEL, 'CalculiX', 'Multi-point constraints PLANE (the nodes after ' // &
         'the first three stay in the plane of the first three), STRAIGHT (the nodes after ' // &
         'the first two stay on their line) and MEANROT (the mean rotation of the member ' // &
         'nodes about an axis is the first displacement of the last node, whose coordinates ' // &
         'give the axis). In steps with NLGEOM they are nonlinear, as CalculiX''s, and hold ' // &
         'exactly at the end of every increment (doc/theory.md 6.2.3); otherwise they are ' // &
         'linearised in the initial configuration (6.2.1: exact for small rotations). ' // &
         'CalculiX turns NLGEOM on for PLANE and STRAIGHT; fcs3d keeps each step''s NLGEOM ' // &
         '(a warning says so). RF at the MEANROT node is the moment it transmits. BEAM, DIST ' // &
         'and user MPCs are refused.', &
         'MPC name (PLANE, STRAIGHT or MEANROT) and up to 15 nodes, then further lines of up ' // &
         'to 16 nodes; zero entries are skipped. MEANROT: each member node three times in a ' // &
         'row, then the axis node.', [p_none()], data_required=.true.), &
      kw('RIGID BODY', CONTEXT_MODEL, 'CalculiX', 'The nodes of a set move rigidly with a ' // &
         'reference node (translation) and a rotation node (whose three degrees of freedom ' // &
         'are the rotation vector w, radians: *BOUNDARY and *CLOAD on it prescribe ' // &
         'rotations and apply moments). In steps with NLGEOM the motion is CalculiX''s ' // &
         'finite rotation, x_p = x_ref + C(w) (X_p - X_ref) with Rodrigues'' C (doc/theory.md ' // &
         '6.2.3); otherwise it is linearised in the initial configuration, u_p = u_ref + w x ' // &
         '(X_p - X_ref), exact for small rotations. RF at the reference and rotation nodes is ' // &
         'the force and moment the body transmits, as CalculiX prints them.', '', &
         [p('NSET', PARAM_NAME, description='The nodes of the body (or ELSET).'), &
          p('ELSET', PARAM_NAME, description='The elements whose nodes form the body (or NSET).'), &
          p('REF NODE', PARAM_INTEGER, required=.true., description='Reference node (its ' // &
            'displacement is the translation of the body); CalculiX generates one when it is ' // &
            'missing, fcs3d needs it defined by *NODE.'), &
          p('ROT NODE', PARAM_INTEGER, required=.true., description='Rotation node (its ' // &
            'three degrees of freedom are the rotation of the body, radians); defined by *NODE, ' // &
            'in no element.')]), &
      kw('COUPLING', CONTEXT_MODEL, 'CalculiX', 'Couples the nodes of a surface to a ' // &
         'reference node; the next card says how: *KINEMATIC (rigid) or *DISTRIBUTING ' // &
         '(area-weighted mean). No data lines.', '', &
         [p('REF NODE', PARAM_INTEGER, required=.true., description='Reference node, ' // &
            'defined by *NODE.'), &
          p('SURFACE', PARAM_NAME, required=.true., description='The coupled surface ' // &
            '(element faces; *KINEMATIC also takes a nodal surface).'), &
          p('CONSTRAINT NAME', PARAM_NAME, required=.true., description='Name of the ' // &
            'coupling (for messages).'), &
          p('ORIENTATION', PARAM_NAME, description='Local axes of the coupled degrees of ' // &
            'freedom: not available in fcs3d (an input error); the directions are global.')]), &
      kw('KINEMATIC', CONTEXT_MODEL, 'CalculiX', 'Follows *COUPLING: the surface nodes ' // &
         'follow, in the directions given, the rigid motion of the reference node. As ' // &
         'CalculiX, fcs3d generates a rotation node (the next node number, printed as a ' // &
         'warning) whose degrees of freedom 1-3 are the rotation of the reference node, ' // &
         'radians (CalculiX''s degrees of freedom 4-6 of the reference node: *BOUNDARY and ' // &
         '*CLOAD on the rotation go to that node), and writes the equations of *RIGID BODY: ' // &
         'linearised without NLGEOM, finite rotations with it (doc/theory.md 6.2.4). RF at ' // &
         'the reference node is the force the surface transmits.', &
         'first degree of freedom, last degree of freedom (1..3; last = first when absent); ' // &
         'several lines allowed.', [p_none()], data_required=.true.), &
      kw('DISTRIBUTING', CONTEXT_MODEL, 'CalculiX', 'Follows *COUPLING: the translation of ' // &
         'the reference node is the mean of the surface nodes'' translations weighted by ' // &
         'their nodal areas (CalculiX''s weights), a linear equation per direction whose ' // &
         'dependent term is the reference node''s: a *CLOAD there is spread over the ' // &
         'surface in proportion to the nodal areas (doc/theory.md 6.2.4). The three ' // &
         'translations are always coupled, as in CalculiX; the rotations 4-6 are not ' // &
         'available (an input error).', &
         'first degree of freedom, last degree of freedom (1..3; last = first when absent).', &
         [p_none()], data_required=.true.), &
      kw('TRANSFORM', CONTEXT_MODEL, 'CalculiX', 'Local axes for the nodes of a node set: ' // &
         '*BOUNDARY, *CLOAD and *EQUATION terms on them are in these axes, and *NODE PRINT ' // &
         'prints their U and RF in them (rows marked L), as CalculiX does. The three ' // &
         'unknowns of such a node are its local components (doc/theory.md 6.2.2).', &
         'a_x, a_y, a_z, b_x, b_y, b_z: TYPE=R: a point a on the local x axis and a point b ' // &
         'in the local x-y plane (both through the origin); TYPE=C: two points a, b on the ' // &
         'axis (local x radial, y tangential, z along b - a).', &
         [p('NSET', PARAM_NAME, required=.true., description='The nodes that get the axes.'), &
          p('TYPE', PARAM_CHOICE, default='R', choices=[s('R'), s('C')], &
            description='R: rectangular; C: cylindrical.')], data_required=.true.) &
      ]
  end function constraint_keywords

  !> Parameters of *FRICTION: LAW (the laws of `registry`, by default the built-in ones),
  !> STICK SLOPE and every law parameter of the friction library's catalogue
  !> (fcs_friction_factory), so that the table stays the library's.
  function friction_keyword_params(registry) result(params)
    type(friction_registry_t), intent(in), optional :: registry
    type(param_spec_t), allocatable :: params(:)
    type(friction_parameter_t), allocatable :: catalogue(:)
    integer :: i
    catalogue = friction_parameters()
    params = [p('LAW', PARAM_CHOICE, default='COULOMB', choices=friction_laws(registry), &
                description='Friction law.'), &
              p('STICK SLOPE', PARAM_REAL, unit='stress/length', description='Stick stiffness ' // &
                'E_t (default: E_n, the normal penalty).'), &
              p('RADIATION DAMPING', PARAM_TEXT, unit='stress time/length', description='Radiation ' // &
                'damping eta of the quasi-dynamic approximation (Rice 1993): a slipping node ' // &
                'resists with mu f_n + eta A V. MATERIAL: eta = G / (2 c_s) from the elastic ' // &
                'bodies on either side of each pair (1/eta = 1/Z_slave + 1/Z_master with ' // &
                'Z = sqrt(G rho) = G / c_s; needs *DENSITY), or a number eta >= 0. Default: none ' // &
                '(fcs3d extension; doc/theory.md, section 5, "Radiation damping").')]
    do i = 1, size(catalogue)
      if (size(catalogue(i)%choices) > 0) then
        params = [params, p(catalogue(i)%name, PARAM_CHOICE, choices=catalogue(i)%choices, &
                            description=catalogue(i)%description)]
      else
        params = [params, p(catalogue(i)%name, PARAM_REAL, unit=catalogue(i)%unit, &
                            description=catalogue(i)%description)]
      end if
    end do
  end function friction_keyword_params

  function step_keywords() result(t)
    type(keyword_spec_t), allocatable :: t(:)
    t = [ &
      kw('AMPLITUDE', CONTEXT_ANY, 'CalculiX', 'A tabular time function (linear between ' // &
         'points, constant outside them) scaling loads and prescribed values.', &
         'pairs time, value (several pairs per line allowed).', &
         [p('NAME', PARAM_NAME, required=.true., description='Name of the amplitude.'), &
          p('TIME', PARAM_CHOICE, default='STEP TIME', choices=[s('STEP TIME'), s('TOTAL TIME')], &
            description='Whether times are measured from the start of each step or of the analysis.'), &
          p('DEFINITION', PARAM_CHOICE, default='TABULAR', choices=[s('TABULAR')], &
            description='Only tabular amplitudes are available.'), &
          p('USER', PARAM_FLAG, description='A user amplitude (CalculiX''s subroutine ' // &
            'uamplitude): only the one CalculiX ships is available, NAME=QUADRATIC, a(t) = t^2 ' // &
            '(no data lines).')]), &
      kw('STEP', CONTEXT_MODEL, 'CalculiX', 'Start a step (a loading stage).', '', &
         [p('AMPLITUDE', PARAM_CHOICE, default='RAMP', choices=[s('RAMP')], &
            description='How loads without *AMPLITUDE change over the step: RAMP, linearly ' // &
            'from their values at the end of the previous step (STEP, applied at once, is ' // &
            'not available).'), &
          p('NLGEOM', PARAM_CHOICE, choices=[s('YES'), s('NO')], flag_value='YES', &
            description='Geometric nonlinearity: updated Lagrangian (paper eq. 1; *ELASTIC ' // &
            'is then St Venant-Kirchhoff, *HYPOELASTIC the Jaumann rate form). Once on, ' // &
            'it stays on in the following steps until a step says NLGEOM=NO (as CalculiX ' // &
            'and Abaqus); without it in any step so far, the step is ' // &
            'small-strain and linear in geometry.'), &
          p('INC', PARAM_INTEGER, default='1000000', &
            description='Maximum number of increments in the step. Unlike CalculiX (100), ' // &
            'the default is large: static-explicit runs take many small increments.'), &
          p('NAME', PARAM_TEXT, description='Name of the step (for the log and results).')]), &
      kw('STATIC', CONTEXT_STEP, 'CalculiX', 'Static step: the static-explicit R-minimum ' // &
         'stepper drives it (each increment scaled so that no state changes drastically ' // &
         'within it; equilibrium iterations as *RMIN sets them).', &
         'initial time increment, step time period, minimum time increment, maximum time ' // &
         'increment [time]. Defaults: 1, 1, 1e-5 of the period, the period.', &
         [p('DIRECT', PARAM_FLAG, description='Fixed increments, as CalculiX''s DIRECT: ' // &
            'every increment is tried with the initial time increment and never grows ' // &
            'beyond it; the R-minimum step control may still shorten an increment to an ' // &
            'event (contact, stick/slip, yield) or to its limits, down to the minimum ' // &
            'increment (doc/user_guide.md, section 4).'), &
          p('SOLVER', PARAM_TEXT, description='CalculiX''s linear solver (SPOOLES, PARDISO, ' // &
            '...): ignored, with a warning; fcs3d''s solver is chosen by *SOLVER or --solver.')]), &
      kw('END STEP', CONTEXT_STEP, 'CalculiX', 'End the current step.', '', [p_none()]), &
      kw('CONTROLS', CONTEXT_STEP, 'CalculiX', 'CalculiX''s controls of its Newton ' // &
         'iterations and automatic increments. Read and ignored, with a warning: fcs3d''s ' // &
         'increments and equilibrium iterations follow its R-minimum step control, whose ' // &
         'limits *RMIN sets.', 'CalculiX''s values for PARAMETERS= (ignored).', &
         [p('PARAMETERS', PARAM_CHOICE, choices=[s('TIME INCREMENTATION'), s('FIELD'), &
            s('LINE SEARCH'), s('CONTACT')], description='The group of CalculiX controls.'), &
          p('RESET', PARAM_FLAG, description='Reset CalculiX''s controls to their defaults.')]), &
      kw('RMIN', CONTEXT_STEP, 'fcs3d', 'Limits of the R-minimum step control of this step ' // &
         '(each increment is scaled so that no state changes drastically within it).', '', &
         [p('MAX STRAIN INCREMENT', PARAM_REAL, default='2e-3', unit='-', &
            description='Largest equivalent strain increment sqrt(2/3 de:de) at any ' // &
            'integration point in one increment (NLGEOM steps). 2e-3 keeps the midpoint ' // &
            'integration of the Jaumann rate well within 0.1% of the logarithmic-strain answer.'), &
          p('MAX ROTATION INCREMENT', PARAM_REAL, default='0.5', unit='degree', &
            description='Largest rotation increment of any integration point (NLGEOM steps). ' // &
            'The Hughes-Winget update is exact for rotations; the limit keeps the midpoint ' // &
            'configuration, the tangent and the contact linearisation accurate.'), &
          p('MAX PLASTIC STRAIN INCREMENT', PARAM_REAL, default='1e-3', unit='-', &
            description='Largest growth of the equivalent plastic strain (PEEQ) at any ' // &
            'integration point in one increment (every step, NLGEOM or not). The increment ' // &
            'uses the tangent of its start: the default, about the yield strain of steel and ' // &
            'rock, keeps the change of the flow direction within an increment small ' // &
            '(doc/theory.md section 6.7 gives the measurements).'), &
          p('EVENT TOLERANCE', PARAM_REAL, default='1e-3', unit='-', &
            description='Events (contact, stick/slip, yield) whose fractions r lie within this ' // &
            'relative tolerance of the smallest are taken together in one increment.'), &
          p('MAX LOG RATE CHANGE', PARAM_REAL, default='1', unit='-', description='Largest ' // &
            'change of ln V (slip rate) of a slipping node from one increment to the next. ' // &
            'Like the two below, it sets the next trial time increment: scaling an increment ' // &
            'does not change its slip rate, so rate effects are resolved in time instead.'), &
          p('MAX FRICTION CHANGE', PARAM_REAL, default='5e-3', unit='-', description='Largest ' // &
            'change of mu of a slipping node from one increment to the next.'), &
          p('MAX STATE CHANGE', PARAM_REAL, default='0.2', unit='-', description='Largest ' // &
            'change of ln(state) (rate-and-state laws) from one increment to the next.'), &
          p('MAX SLIP INCREMENT', PARAM_REAL, unit='L', description='Largest slip of a ' // &
            'slipping node in one increment, as a fraction xi of the characteristic slip L (DC) ' // &
            'of its rate-and-state law: the next trial increment is then at most xi L / V_max ' // &
            '(V_max the largest slip rate; Lapusta et al. 2000), so that the state evolution ' // &
            'of a fast event is resolved in time. Default: none (laws without L are never ' // &
            'limited by it).'), &
          p('EQUILIBRIUM TOLERANCE', PARAM_REAL, default='1e-3', unit='-', description='Largest ' // &
            'out-of-balance force left at the end of an increment: the largest nodal ' // &
            'residual over the mean nodal internal force flux. An increment that leaves more ' // &
            'is corrected by equilibrium iterations (Newton, contact and friction states ' // &
            'decided on the corrected solution), and cut if they do not converge.'), &
          p('MAX ITERATIONS', PARAM_INTEGER, default='12', description='Equilibrium ' // &
            'iterations allowed in one increment before it is cut in four.'), &
          p('NO EQUILIBRIUM', PARAM_CHOICE, default='STOP', choices=[s('STOP'), s('CARRY')], &
            description='What an increment whose equilibrium iterations do not converge ' // &
            'does: STOP: it is cut, down to the minimum increment, where the run stops naming ' // &
            'the node and direction of the largest out-of-balance force; CARRY: it is taken ' // &
            'without iterations and its out-of-balance force carried into the next one (the ' // &
            'static-explicit scheme of the paper), marked (carried) in the log. A ' // &
            'velocity-weakening slip event has no quasi-static equilibrium: without radiation ' // &
            'damping only CARRY runs through it.'), &
          p('CONTACT EVENTS', PARAM_CHOICE, choices=[s('ALL'), s('NORMAL'), s('CLOSING')], &
            description='Which contact state changes end an increment. ALL (when absent): ' // &
            'every one (an R-minimum event, the paper''s method: each onset of slip, each ' // &
            'hand-over of a node to the next master segment, each opening resolved in time). ' // &
            'NORMAL: only closing, opening and leaving the master surface; a node that ' // &
            'reaches the friction cone or a shared edge of its segment does not end the ' // &
            'increment, the equilibrium iterations decide its stick or slip (the return ' // &
            'mapping of eq. 5 from the start of the increment) and its segment on the ' // &
            'corrected solution, as an implicit code does. CLOSING: only closing; a node ' // &
            'whose normal force falls to zero, or that slides off the master surface, opens ' // &
            'in the iterations too (a node held closed that ends in tension is opened and the ' // &
            'iterations go on). Far fewer increments when many nodes start to slip, slide over ' // &
            'segment edges or lift off one after the other; those changes are then known only ' // &
            'to within an increment (doc/theory.md section 6.9). The command line option ' // &
            '--contact-events overrides it in every step. (Absent rather than a filled-in ' // &
            'default, so that the checkpoints of decks written before it existed still match ' // &
            'their steps.)')]), &
      kw('BOUNDARY', CONTEXT_ANY, 'CalculiX', 'Prescribed displacements (fixed or ' // &
         'given values) or velocities on nodes or node sets.', &
         'node or node set, first dof, last dof (default: first), value (default 0); ' // &
         'dofs 1..3 are x, y, z.', &
         [p('OP', PARAM_CHOICE, default='MOD', choices=[s('MOD'), s('NEW')], &
            description='MOD keeps earlier conditions; NEW removes all earlier ones first.'), &
          p('AMPLITUDE', PARAM_NAME, description='Scale the value by this amplitude.'), &
          p('TIME DELAY', PARAM_REAL, unit='time', description='Shift the amplitude by this ' // &
            'time: the value at time t is the amplitude''s at t - delay (CalculiX; needs ' // &
            'AMPLITUDE).'), &
          p('TYPE', PARAM_CHOICE, default='DISPLACEMENT', &
            choices=[s('DISPLACEMENT'), s('VELOCITY')], &
            description='DISPLACEMENT: the value is the displacement reached at the end of ' // &
            'the step (ramped over the step, or value x amplitude). VELOCITY: the value is a ' // &
            'velocity [length/time] held through the step (x amplitude) (fcs3d extension).'), &
          p('FIXED', PARAM_FLAG, description='Keep the displacement the nodes have at the ' // &
            'start of the step (CalculiX; in a step only; a value on the data line is ignored).')], &
         data_required=.true.), &
      kw('TEMPERATURE', CONTEXT_STEP, 'CalculiX', 'Nodal temperatures at the end of the ' // &
         'step: ramped linearly over the step from the temperature at its start, or value x ' // &
         'amplitude with AMPLITUDE= (as CalculiX for *STATIC). Nodes not named keep their ' // &
         'value of the previous step. The thermal strain enters the stress update at the ' // &
         'integration points (temperature interpolated from the nodes) and its load the ' // &
         'R-minimum increment like any other load.', 'node or node set, temperature.', &
         [p('OP', PARAM_CHOICE, default='MOD', choices=[s('MOD'), s('NEW')], &
            description='MOD changes the named nodes; NEW first returns every node to its ' // &
            'initial temperature.'), &
          p('AMPLITUDE', PARAM_NAME, description='The temperature is value x this amplitude.'), &
          p('TIME DELAY', PARAM_REAL, unit='time', description='Shift the amplitude by this ' // &
            'time: the value at time t is the amplitude''s at t - delay (CalculiX; needs ' // &
            'AMPLITUDE).')], &
         data_required=.true.), &
      kw('CLOAD', CONTEXT_STEP, 'CalculiX', 'Concentrated nodal forces.', &
         'node or node set, dof, magnitude [force].', &
         [p('OP', PARAM_CHOICE, default='MOD', choices=[s('MOD'), s('NEW')], &
            description='MOD keeps earlier loads; NEW removes all earlier ones first.'), &
          p('AMPLITUDE', PARAM_NAME, description='Scale the value by this amplitude.'), &
          p('TIME DELAY', PARAM_REAL, unit='time', description='Shift the amplitude by this ' // &
            'time: the value at time t is the amplitude''s at t - delay (CalculiX; needs ' // &
            'AMPLITUDE).')], &
         data_required=.true.), &
      kw('DSLOAD', CONTEXT_STEP, 'CalculiX', 'Pressure on an element-face surface ' // &
         '(positive pressure pushes into the surface). Under NLGEOM it follows the current ' // &
         'face area and normal, with its load stiffness.', &
         'surface name, P, magnitude [stress].', &
         [p('OP', PARAM_CHOICE, default='MOD', choices=[s('MOD'), s('NEW')], &
            description='MOD keeps earlier loads; NEW removes all earlier ones first.'), &
          p('AMPLITUDE', PARAM_NAME, description='Scale the value by this amplitude.'), &
          p('TIME DELAY', PARAM_REAL, unit='time', description='Shift the amplitude by this ' // &
            'time: the value at time t is the amplitude''s at t - delay (CalculiX; needs ' // &
            'AMPLITUDE).')], &
         data_required=.true.), &
      kw('DLOAD', CONTEXT_STEP, 'CalculiX', 'Distributed load: pressure on element faces, ' // &
         'as *DSLOAD (the same list of face pressures: OP=NEW of either removes both), and ' // &
         'the body loads GRAV (gravity) and CENTRIF (centrifugal) as CalculiX: rho times the ' // &
         'acceleration per unit volume (the material needs *DENSITY), as consistent nodal ' // &
         'forces over the element (any kind), ramped over the step or x amplitude. CENTRIF ' // &
         'acts at the current positions under NLGEOM, the reference ones without, without ' // &
         'load stiffness (doc/theory.md section 3.1). BX, BY, BZ and user loads are refused.', &
         'element or element set, Pn (face n, numbered as S1..S6 of *SURFACE), magnitude ' // &
         '[stress]; element or set, GRAV, g [length/time^2], direction x, y, z (normalised); ' // &
         'element or set, CENTRIF, omega^2 [1/time^2], a point of the axis x, y, z, the axis ' // &
         'direction x, y, z.', &
         [p('OP', PARAM_CHOICE, default='MOD', choices=[s('MOD'), s('NEW')], &
            description='MOD keeps earlier loads; NEW removes all earlier pressures and body ' // &
            'loads first.'), &
          p('AMPLITUDE', PARAM_NAME, description='Scale the value by this amplitude.'), &
          p('TIME DELAY', PARAM_REAL, unit='time', description='Shift the amplitude by this ' // &
            'time: the value at time t is the amplitude''s at t - delay (CalculiX; needs ' // &
            'AMPLITUDE).')], &
         data_required=.true.) &
      ]
  end function step_keywords

  function output_keywords() result(t)
    type(keyword_spec_t), allocatable :: t(:)
    t = [ &
      kw('TIME POINTS', CONTEXT_ANY, 'CalculiX', 'A list of output times; the stepper lands ' // &
         'on each exactly.', 'times; with GENERATE: start, end, increment.', &
         [p('NAME', PARAM_NAME, required=.true., description='Name of the list.'), &
          p('TIME', PARAM_CHOICE, default='STEP TIME', choices=[s('STEP TIME'), s('TOTAL TIME')], &
            description='Whether the times are measured from the start of each step or of the analysis.'), &
          p('GENERATE', PARAM_FLAG, description='Data lines are start, end, increment.')], &
         data_required=.true.), &
      kw('NODE PRINT', CONTEXT_STEP, 'CalculiX', 'Print nodal results to <job>.dat in ' // &
         'CalculiX''s layout.', 'U (displacements), RF (reaction forces), NT (nodal temperatures).', &
         [p('NSET', PARAM_NAME, required=.true., description='Node set to print.'), &
          p('GLOBAL', PARAM_CHOICE, choices=[s('YES'), s('NO')], &
            description='NO (the default when absent, as in CalculiX): U and RF of nodes with ' // &
            'local axes (*TRANSFORM) are printed in those axes, their rows marked L; YES: in ' // &
            'global axes. (Absent rather than a filled-in default, so that the checkpoints of ' // &
            'decks written before local axes existed still match their steps.)'), &
          p('FREQUENCY', PARAM_INTEGER, default='0', description='Also print every N ' // &
            'increments (0: only at the end of the step and at the time points).'), &
          p('TIME POINTS', PARAM_NAME, description='Print at these times.'), &
          p('TOTALS', PARAM_CHOICE, default='NO', choices=[s('NO'), s('YES'), s('ONLY')], &
            description='Also (YES) or only (ONLY) print the sum over the set.')], &
         data_required=.true.), &
      kw('EL PRINT', CONTEXT_STEP, 'CalculiX', 'Print integration-point results to ' // &
         '<job>.dat in CalculiX''s layout.', 'S (Cauchy stress), E (strain), PEEQ or PE ' // &
         '(equivalent plastic strain: CalculiX prints both as one column, "pe").', &
         [p('ELSET', PARAM_NAME, required=.true., description='Element set to print.'), &
          p('FREQUENCY', PARAM_INTEGER, default='0', description='Also print every N ' // &
            'increments (0: only at the end of the step and at the time points).'), &
          p('TIME POINTS', PARAM_NAME, description='Print at these times.'), &
          p('TOTALS', PARAM_CHOICE, default='NO', choices=[s('NO'), s('YES'), s('ONLY')], &
            description='CalculiX sums whole-element variables (ELSE, EVOL, ...), which ' // &
            'fcs3d does not compute; S, E and PE have no totals, so their tables are printed ' // &
            'as without TOTALS, as CalculiX prints them (a warning says so).'), &
          p('GLOBAL', PARAM_CHOICE, default='NO', choices=[s('YES'), s('NO')], &
            description='NO (CalculiX''s default): S and E of elements whose section has an ' // &
            '*ORIENTATION are printed in its local axes at each point, the orientation''s name ' // &
            'after the values, as CalculiX prints them; YES: in global axes. Elements without ' // &
            'an orientation print global components either way.')], &
         data_required=.true.), &
      kw('CONTACT PRINT', CONTEXT_STEP, 'CalculiX', 'Print the state of every closed contact ' // &
         'node to <job>.dat in CalculiX''s layout and frame: tangential components on t1, the ' // &
         'global x axis projected on the contact plane (the z axis when the master normal n ' // &
         'is along x), and t2 = n x t1.', 'CDIS (relative contact displacement: normal gap, ' // &
         'then the accumulated tangential displacement on t1, t2), CSTR (contact pressure, ' // &
         'then the shear on t1, t2 with the sign of the elastic slip, as CalculiX prints it: ' // &
         'the shear the slave exerts on the master); CDISP, CSTRESS are accepted as aliases.', &
         [p('FREQUENCY', PARAM_INTEGER, default='0', description='Also print every N ' // &
            'increments (0: only at the end of the step and at the time points).'), &
          p('TIME POINTS', PARAM_NAME, description='Print at these times.'), &
          p('TOTALS', PARAM_CHOICE, default='NO', choices=[s('NO'), s('YES'), s('ONLY')], &
            description='CDIS and CSTR have no totals (CalculiX sums contact energies only): ' // &
            'YES prints the tables as without TOTALS, ONLY prints nothing, as in CalculiX (a ' // &
            'warning says so).'), &
          p('NSET', PARAM_IGNORED, description=IGNORED_AS_CALCULIX // ': the tables list ' // &
            'every closed contact node')], &
         data_required=.true.), &
      kw('CONTACT FILE', CONTEXT_STEP, 'CalculiX', 'As *NODE FILE, for contact variables ' // &
         '(every frame holds the contact fields of every pair).', 'CDIS, CSTR, ...', &
         [p('FREQUENCY', PARAM_INTEGER, default='0', description='Also write every N increments.'), &
          p('TIME POINTS', PARAM_NAME, description='Write at these times.'), &
          p('NSET', PARAM_NAME, description=WHOLE_FRAMES)]), &
      kw('HISTORY', CONTEXT_MODEL, 'fcs3d', 'History output through the whole run, in ' // &
         '<job>_<name>.csv and /history/<name> of <job>.h5: one row per sample, the first ' // &
         'column the time.', 'NSET, <set>, U (mean displacement, 3 columns) | NSET, <set>, RF ' // &
         '(total force, 3) | CONTACT, <pair> (normal force, tangential force 3, stick, slip, ' // &
         'open counts, mean and largest slip, largest slip rate, mean pressure and shear ' // &
         'traction) | ENERGY (elastic strain energy, frictional work) | RESIDUAL (the ' // &
         'out-of-balance ratio the last increment left, as the log prints it).', &
         [p('NAME', PARAM_NAME, required=.true., description='Name of the history.'), &
          p('FREQUENCY', PARAM_INTEGER, default='1', description='Sample every N increments ' // &
            '(0: only at the time points and step ends).'), &
          p('TIME POINTS', PARAM_NAME, description='Also sample at these times.')], &
         data_required=.true.), &
      kw('EVENT CATALOG', CONTEXT_MODEL, 'fcs3d', 'Catalogue slip events on every contact ' // &
         'pair: an event starts when a node''s slip rate exceeds the threshold and ends when ' // &
         'no node exceeds it; onset, end, nodes, peak slip rate, slip, stress drop and ' // &
         'hypocentre go to <job>_events.csv, /events in <job>.h5 and the log.', '', &
         [p('SLIP RATE', PARAM_REAL, required=.true., unit='length/time', &
            description='Threshold slip rate.'), &
          p('MIN SLIP', PARAM_REAL, default='0', unit='length', description='Events whose ' // &
            'largest slip stays below this are not catalogued.')]), &
      kw('NODE FILE', CONTEXT_STEP, 'CalculiX', 'Request result frames in <job>.h5/.xdmf. ' // &
         'Every frame holds all fields (displacement, reactions, stresses, Mises stress); ' // &
         'the variables listed are checked, not used to select.', 'U, RF, NT (frames of a model with temperatures hold NT), ...', &
         [p('FREQUENCY', PARAM_INTEGER, default='0', description='Also write every N increments.'), &
          p('TIME POINTS', PARAM_NAME, description='Write at these times.'), &
          p('NSET', PARAM_NAME, description=WHOLE_FRAMES), &
          p('GLOBAL', PARAM_CHOICE, default='YES', choices=[s('YES'), s('NO')], &
            description=GLOBAL_ONLY), &
          p('OUTPUT', PARAM_CHOICE, default='3D', choices=[s('2D'), s('3D')], &
            description=SOLIDS_IN_3D), &
          p('CONTACT ELEMENTS', PARAM_IGNORED, description='ignored: CalculiX writes the ' // &
            'contact elements it generates to <job>.cel; fcs3d''s contact state is in the ' // &
            'frames of <job>.h5')]), &
      kw('EL FILE', CONTEXT_STEP, 'CalculiX', 'As *NODE FILE, for element variables ' // &
         '(with a plastic material, every frame also holds PEEQ, PE and the back stress ALPHA).', &
         'S, E, PEEQ, PE, ...', &
         [p('FREQUENCY', PARAM_INTEGER, default='0', description='Also write every N increments.'), &
          p('TIME POINTS', PARAM_NAME, description='Write at these times.'), &
          p('GLOBAL', PARAM_CHOICE, default='YES', choices=[s('YES'), s('NO')], &
            description=GLOBAL_ONLY), &
          p('OUTPUT', PARAM_CHOICE, default='3D', choices=[s('2D'), s('3D')], &
            description=SOLIDS_IN_3D), &
          p('POSITION', PARAM_IGNORED, description=IGNORED_AS_CALCULIX // ': fcs3d writes ' // &
            'integration-point values and their nodal averages')]) &
      ]
  end function output_keywords

  !> Build a keyword specification.
  function kw(name, context, origin, summary, data, params, data_required) result(k)
    character(len=*), intent(in) :: name, origin, summary, data
    integer, intent(in) :: context
    type(param_spec_t), intent(in) :: params(:)
    logical, intent(in), optional :: data_required
    type(keyword_spec_t) :: k
    integer :: i, n
    k%name = name
    k%context = context
    k%origin = origin
    k%summary = summary
    k%data = data
    if (present(data_required)) k%data_required = data_required
    n = 0
    do i = 1, size(params)
      if (len(params(i)%name) > 0) n = n + 1
    end do
    allocate (k%params(n))
    n = 0
    do i = 1, size(params)
      if (len(params(i)%name) == 0) cycle
      n = n + 1
      k%params(n) = params(i)
    end do
  end function kw

  !> Build a parameter specification.
  function p(name, kind, default, required, choices, flag_value, unit, description) result(q)
    character(len=*), intent(in) :: name
    integer, intent(in) :: kind
    character(len=*), intent(in), optional :: default, flag_value, unit, description
    logical, intent(in), optional :: required
    type(string_t), intent(in), optional :: choices(:)
    type(param_spec_t) :: q
    q%name = name
    q%kind = kind
    q%default = ''
    if (present(default)) q%default = default
    if (present(required)) q%required = required
    if (present(choices)) then
      q%choices = choices
    else
      allocate (q%choices(0))
    end if
    q%flag_value = ''
    if (present(flag_value)) q%flag_value = flag_value
    q%unit = ''
    if (present(unit)) q%unit = unit
    q%description = ''
    if (present(description)) q%description = description
  end function p

  !> Placeholder for "no parameters" (dropped by kw).
  function p_none() result(q)
    type(param_spec_t) :: q
    q = p('', PARAM_FLAG)
  end function p_none

  pure function s(text) result(out)
    character(len=*), intent(in) :: text
    type(string_t) :: out
    out%s = text
  end function s

  !> A list of blank-padded names as strings (trimmed): the choices a catalogue offers.
  pure function names(padded) result(out)
    character(len=*), intent(in) :: padded(:)
    type(string_t) :: out(size(padded))
    integer :: i
    do i = 1, size(padded)
      out(i)%s = trim(padded(i))
    end do
  end function names

  !> Index of keyword `name` in `table`, 0 if unknown (compared as `same_name`).
  pure integer function find_keyword(table, name) result(k)
    type(keyword_spec_t), intent(in) :: table(:)
    character(len=*), intent(in) :: name
    do k = 1, size(table)
      if (same_name(table(k)%name, name)) return
    end do
    k = 0
  end function find_keyword

  !> Index of parameter `name` of keyword `spec`, 0 if unknown (compared as `same_name`).
  pure integer function find_param_spec(spec, name) result(k)
    type(keyword_spec_t), intent(in) :: spec
    character(len=*), intent(in) :: name
    do k = 1, size(spec%params)
      if (same_name(spec%params(k)%name, name)) return
    end do
    k = 0
  end function find_param_spec

  !> True when two keyword, parameter or choice names are the same name for CalculiX, which
  !> ignores case and blanks in them: *ENDSTEP is *END STEP, *SOLIDSECTION is *SOLID SECTION,
  !> TIMEPOINTS= is TIME POINTS=, TYPE=NODETOSURFACE is TYPE=NODE TO SURFACE.
  pure logical function same_name(a, b)
    character(len=*), intent(in) :: a, b
    same_name = without_blanks(to_upper(a)) == without_blanks(to_upper(b))
  end function same_name

  pure function without_blanks(text) result(out)
    character(len=*), intent(in) :: text
    character(len=:), allocatable :: out
    integer :: i
    out = ''
    do i = 1, len(text)
      if (text(i:i) /= ' ') out = out // text(i:i)
    end do
  end function without_blanks

  pure function param_kind_name(kind) result(name)
    integer, intent(in) :: kind
    character(len=:), allocatable :: name
    select case (kind)
    case (PARAM_FLAG)
      name = 'flag'
    case (PARAM_NAME)
      name = 'name'
    case (PARAM_REAL)
      name = 'real'
    case (PARAM_INTEGER)
      name = 'integer'
    case (PARAM_CHOICE)
      name = 'choice'
    case (PARAM_FILE)
      name = 'file'
    case (PARAM_IGNORED)
      name = 'ignored'
    case default
      name = 'text'
    end select
  end function param_kind_name

  pure function context_name(context) result(name)
    integer, intent(in) :: context
    character(len=:), allocatable :: name
    select case (context)
    case (CONTEXT_MODEL)
      name = 'model definition'
    case (CONTEXT_STEP)
      name = 'step'
    case default
      name = 'model definition or step'
    end select
  end function context_name

end module fcs_keywords
