!> Kinds used throughout fcs3d: the only place where real and integer kinds are chosen.
module fcs_kinds
  use, intrinsic :: iso_fortran_env, only: real64, int64, int32
  implicit none
  private
  public :: dp, i8, i4

  !> Double precision real, used for every physical quantity.
  integer, parameter :: dp = real64
  !> 64-bit integer: sparse-matrix indices, counts that can exceed 2**31.
  integer, parameter :: i8 = int64
  !> Default 32-bit integer, named for the few places that must say so.
  integer, parameter :: i4 = int32
end module fcs_kinds
