!> The keywords CalculiX (ccx 2.20) interprets, for the reader's unknown-keyword rule.
!>
!> CalculiX compares a keyword line by its leading characters with blanks removed
!> (`calinput.f`: `textpart(1)(1:n) .eq. '*NODEPRINT'`, n the length of the known name), so
!> a card whose name starts with a known name is read as that keyword (*NODEE as *NODE), and
!> a card that starts with none of them is skipped with the warning "Card image cannot be
!> interpreted" (CalculiX 2.20 on its own test deck c3d6.inp, whose *MEMBRANE card it skips).
!> fcs3d refuses every card of the first kind that it does not support (CalculiX would act on
!> it) and, like CalculiX, passes over cards of the second kind with a warning naming
!> file:line, unless the name is a near miss of a keyword fcs3d knows (then it is a typo and
!> refused with a suggestion: stricter than CalculiX, which would skip it silently but for a
!> warning on its screen output).
!>
!> The list: the keyword comparisons of CalculiX's calinput.f (ccx 2.20) and the keyword
!> strings of Debian's ccx 2.20 binary, blanks removed.
module fcs_calculix_keywords
  use fcs_strings, only: to_upper
  use fcs_keywords, only: without_blanks
  implicit none
  private
  public :: is_calculix_keyword

  integer, parameter :: NAME_LENGTH = 33
  character(len=NAME_LENGTH), parameter :: CALCULIX_KEYWORDS(*) = [character(len=NAME_LENGTH) :: &
    'AMPLITUDE', 'BASEMOTION', 'BEAMGENERALSECTION', 'BEAMSECTION', 'BOUNDARY', &
    'BUCKLE', 'CFD', 'CFLUX', 'CHANGECONTACTTYPE', 'CHANGEFRICTION', 'CHANGEMATERIAL', &
    'CHANGEPLASTIC', 'CHANGESOLIDSECTION', 'CHANGESURFACEBEHAVIOR', 'CLEARANCE', 'CLOAD', &
    'COMPLEXFREQUENCY', 'CONDUCTIVITY', 'CONSTRAINT', 'CONTACTDAMPING', 'CONTACTFILE', &
    'CONTACTOUTPUT', 'CONTACTPAIR', 'CONTACTPRINT', 'CONTROLS', 'CORRELATIONLENGTH', &
    'COUPLEDTEMPERATURE-DISPLACEMENT', 'COUPLING', 'CRACKPROPAGATION', 'CREEP', &
    'CYCLICHARDENING', 'CYCLICSYMMETRYMODEL', 'DAMAGEINITIATION', 'DAMPING', 'DASHPOT', &
    'DEFORMATIONPLASTICITY', 'DENSITY', 'DEPVAR', 'DESIGNRESPONSE', 'DESIGNVARIABLES', &
    'DFLUX', 'DISTRIBUTING', 'DISTRIBUTION', 'DLOAD', 'DSLOAD', 'DYNAMIC', 'ELASTIC', &
    'ELECTRICALCONDUCTIVITY', 'ELECTROMAGNETICS', 'ELEMENT', 'ELFILE', 'ELPRINT', 'ELSET', &
    'ENDSTEP', 'EQUATION', 'EXPANSION', 'FEASIBLEDIRECTION', 'FILM', 'FILTER', &
    'FLUIDCONSTANTS', 'FLUIDSECTION', 'FREQUENCY', 'FRICTION', 'GAP', 'GEOMETRICCONSTRAINT', &
    'GEOMETRICTOLERANCE', 'GREEN', 'HCF', 'HEADING', 'HEATTRANSFER', 'HYPERELASTIC', &
    'HYPERFOAM', 'INCLUDE', 'INITIALCONDITIONS', 'INITIALSTRAININCREASE', 'KINEMATIC', &
    'MAGNETICPERMEABILITY', 'MASS', 'MATERIAL', 'MATRIX', 'MEMBRANESECTION', 'MODALDAMPING', &
    'MODALDYNAMIC', 'MODELCHANGE', 'MPC', 'NETWORKMPC', 'NOANALYSIS', 'NODALTHICKNESS', &
    'NODE', 'NORMAL', 'NSET', 'OBJECTIVE', 'ORIENTATION', 'OUTPUT', 'PHYSICALCONSTANTS', &
    'PLASTIC', 'PRE-TENSIONSECTION', 'RADIATE', 'RANDOMFIELD', 'REFINEMESH', 'RESTART', &
    'RETAINEDNODALDOFS', 'RIGIDBODY', 'ROBUSTDESIGN', 'SECTIONPRINT', &
    'SELECTCYCLICSYMMETRYMODES', 'SENSITIVITY', 'SHELLSECTION', 'SOLIDSECTION', &
    'SPECIFICGASCONSTANT', 'SPECIFICHEAT', 'SPRING', 'STATIC', 'STEADYSTATEDYNAMICS', &
    'STEP', 'SUBMODEL', 'SUBSTRUCTUREGENERATE', 'SUBSTRUCTUREMATRIXOUTPUT', 'SURFACE', &
    'TEMPERATURE', 'TIE', 'TIMEPOINTS', 'TRANSFORM', 'UNCOUPLEDTEMPERATURE-DISPLACEMENT', &
    'USERELEMENT', 'USERMATERIAL', 'USERSECTION', 'VALUESATINFINITY', 'VIEWFACTOR', 'VISCO']

contains

  !> True when CalculiX reads a card named `keyword` (without the '*') as one of its
  !> keywords: some known name, blanks removed, begins the name with its blanks removed.
  pure logical function is_calculix_keyword(keyword) result(known)
    character(len=*), intent(in) :: keyword
    character(len=:), allocatable :: name
    integer :: i, n
    name = without_blanks(to_upper(keyword))
    known = .false.
    do i = 1, size(CALCULIX_KEYWORDS)
      n = len_trim(CALCULIX_KEYWORDS(i))
      if (len(name) < n) cycle
      if (name(1:n) == CALCULIX_KEYWORDS(i)(1:n)) then
        known = .true.
        return
      end if
    end do
  end function is_calculix_keyword
end module fcs_calculix_keywords
