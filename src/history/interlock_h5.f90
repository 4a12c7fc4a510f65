!> A thin HDF5 write layer (in the spirit of h5fortran): generic procedures that hide the raw
!> h5*_f calls. Every procedure returns a status (0: success) instead of stopping, and every
!> dataset is written with its `unit` and `description` attributes (the self-describing output
!> of docs/history-output.md). Fortran arrays (m, n) appear in h5py as (n, m).
module interlock_h5
  use, intrinsic :: iso_fortran_env, only: real64, int32
  use, intrinsic :: iso_c_binding, only: c_ptr, c_loc
  use hdf5, only: hid_t, hsize_t, h5open_f, h5close_f, h5fcreate_f, h5fclose_f, h5gcreate_f, &
      h5gclose_f, h5screate_simple_f, h5screate_f, h5sclose_f, h5dcreate_f, h5dwrite_f, &
      h5dclose_f, h5acreate_f, h5awrite_f, h5aclose_f, h5tcopy_f, h5tset_size_f, &
      h5tset_strpad_f, h5tclose_f, h5pcreate_f, h5pclose_f, h5pset_libver_bounds_f, &
      h5eset_auto_f, H5F_ACC_TRUNC_F, H5S_SCALAR_F, H5T_NATIVE_DOUBLE, H5T_NATIVE_INTEGER, &
      H5T_FORTRAN_S1, H5T_STR_NULLPAD_F, H5P_FILE_ACCESS_F, H5F_LIBVER_V18_F, &
      H5F_LIBVER_LATEST_F
  implicit none
  private
  public :: h5_file_t, h5_open_library, h5_close_library, h5_create_file, h5_close_file
  public :: h5_create_group, h5_close_group, h5_write, h5_attribute

  integer, parameter :: dp = real64

  !> An open file or group (a location that can hold datasets and attributes).
  type :: h5_file_t
    integer(hid_t) :: id = -1
  end type h5_file_t

  !> Write a dataset (with `unit` and `description` attributes): real or integer, rank 1 or 2.
  interface h5_write
    module procedure write_real_1d, write_real_2d, write_int_1d
  end interface h5_write

  !> Write an attribute: character, real scalar or array, integer scalar.
  interface h5_attribute
    module procedure attr_text, attr_real, attr_real_1d, attr_int
  end interface h5_attribute

contains

  !> Initialise the library and silence its own error printing (errors come back as status).
  subroutine h5_open_library(stat)
    integer, intent(out) :: stat
    call h5open_f(stat)
    if (stat == 0) call h5eset_auto_f(0, stat)
  end subroutine h5_open_library

  subroutine h5_close_library(stat)
    integer, intent(out) :: stat
    call h5close_f(stat)
  end subroutine h5_close_library

  !> Create (truncate) a file; the 1.8+ format allows attributes larger than 64 KiB (the deck).
  subroutine h5_create_file(name, file, stat)
    character(len=*), intent(in) :: name
    type(h5_file_t), intent(out) :: file
    integer, intent(out) :: stat
    integer(hid_t) :: fapl
    integer :: ignore
    call h5pcreate_f(H5P_FILE_ACCESS_F, fapl, stat)
    if (stat /= 0) return
    call h5pset_libver_bounds_f(fapl, H5F_LIBVER_V18_F, H5F_LIBVER_LATEST_F, stat)
    if (stat == 0) call h5fcreate_f(name, H5F_ACC_TRUNC_F, file%id, stat, access_prp=fapl)
    call h5pclose_f(fapl, ignore)
  end subroutine h5_create_file

  subroutine h5_close_file(file, stat)
    type(h5_file_t), intent(inout) :: file
    integer, intent(out) :: stat
    call h5fclose_f(file%id, stat)
    file%id = -1
  end subroutine h5_close_file

  subroutine h5_create_group(parent, name, group, stat)
    type(h5_file_t), intent(in) :: parent
    character(len=*), intent(in) :: name
    type(h5_file_t), intent(out) :: group
    integer, intent(out) :: stat
    call h5gcreate_f(parent%id, name, group%id, stat)
  end subroutine h5_create_group

  subroutine h5_close_group(group, stat)
    type(h5_file_t), intent(inout) :: group
    integer, intent(out) :: stat
    call h5gclose_f(group%id, stat)
    group%id = -1
  end subroutine h5_close_group

  ! ---------------------------------------------------------------- datasets

  subroutine write_real_1d(loc, name, x, unit, description, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name, unit, description
    real(dp), intent(in), target, contiguous :: x(:)
    integer, intent(out) :: stat
    call write_dataset(loc, name, H5T_NATIVE_DOUBLE, int(shape(x), hsize_t), c_loc(x), unit, &
                       description, stat)
  end subroutine write_real_1d

  subroutine write_real_2d(loc, name, x, unit, description, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name, unit, description
    real(dp), intent(in), target, contiguous :: x(:, :)
    integer, intent(out) :: stat
    call write_dataset(loc, name, H5T_NATIVE_DOUBLE, int(shape(x), hsize_t), c_loc(x), unit, &
                       description, stat)
  end subroutine write_real_2d

  subroutine write_int_1d(loc, name, x, unit, description, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name, unit, description
    integer, intent(in), target, contiguous :: x(:)
    integer, intent(out) :: stat
    call write_dataset(loc, name, H5T_NATIVE_INTEGER, int(shape(x), hsize_t), c_loc(x), unit, &
                       description, stat)
  end subroutine write_int_1d

  !> One dataset of memory type `mem_type` and shape `dims` from the contiguous buffer at `buf`
  !> (nothing is read from it when the dataset is empty), with its two attributes.
  subroutine write_dataset(loc, name, mem_type, dims, buf, unit, description, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name, unit, description
    integer(hid_t), intent(in) :: mem_type
    integer(hsize_t), intent(in) :: dims(:)
    type(c_ptr), intent(in) :: buf
    integer, intent(out) :: stat
    integer(hid_t) :: space, dset
    integer :: ignore
    call h5screate_simple_f(size(dims), dims, space, stat)
    if (stat /= 0) return
    call h5dcreate_f(loc%id, name, mem_type, space, dset, stat)
    if (stat == 0) then
      if (product(dims) > 0) call h5dwrite_f(dset, mem_type, buf, stat)
      if (stat == 0) call describe(dset, unit, description, stat)
      call h5dclose_f(dset, ignore)
    end if
    call h5sclose_f(space, ignore)
  end subroutine write_dataset

  !> The two attributes every dataset carries.
  subroutine describe(dset, unit, description, stat)
    integer(hid_t), intent(in) :: dset
    character(len=*), intent(in) :: unit, description
    integer, intent(out) :: stat
    call text_attribute(dset, 'unit', unit, stat)
    if (stat == 0) call text_attribute(dset, 'description', description, stat)
  end subroutine describe

  ! -------------------------------------------------------------- attributes

  subroutine attr_text(loc, name, text, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name, text
    integer, intent(out) :: stat
    call text_attribute(loc%id, name, text, stat)
  end subroutine attr_text

  !> A scalar fixed-length string attribute (null-padded, so h5py shows it without padding).
  subroutine text_attribute(id, name, text, stat)
    integer(hid_t), intent(in) :: id
    character(len=*), intent(in) :: name, text
    integer, intent(out) :: stat
    integer(hid_t) :: space, attr, stype
    integer(hsize_t) :: dims(1)
    integer :: ignore
    character(len=max(1, len(text))) :: buffer
    buffer = text
    if (len(text) == 0) buffer = achar(0)
    dims = 1
    call h5tcopy_f(H5T_FORTRAN_S1, stype, stat)
    if (stat /= 0) return
    call h5tset_size_f(stype, int(len(buffer), kind(dims)), stat)
    if (stat == 0) call h5tset_strpad_f(stype, H5T_STR_NULLPAD_F, stat)
    if (stat == 0) call h5screate_f(H5S_SCALAR_F, space, stat)
    if (stat == 0) then
      call h5acreate_f(id, name, stype, space, attr, stat)
      if (stat == 0) then
        call h5awrite_f(attr, stype, buffer, dims, stat)
        call h5aclose_f(attr, ignore)
      end if
      call h5sclose_f(space, ignore)
    end if
    call h5tclose_f(stype, ignore)
  end subroutine text_attribute

  subroutine attr_real(loc, name, x, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name
    real(dp), intent(in), target :: x
    integer, intent(out) :: stat
    call write_attribute(loc, name, H5T_NATIVE_DOUBLE, [integer(hsize_t) ::], c_loc(x), stat)
  end subroutine attr_real

  subroutine attr_real_1d(loc, name, x, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name
    real(dp), intent(in), target, contiguous :: x(:)
    integer, intent(out) :: stat
    call write_attribute(loc, name, H5T_NATIVE_DOUBLE, int(shape(x), hsize_t), c_loc(x), stat)
  end subroutine attr_real_1d

  subroutine attr_int(loc, name, i, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name
    integer(int32), intent(in), target :: i
    integer, intent(out) :: stat
    call write_attribute(loc, name, H5T_NATIVE_INTEGER, [integer(hsize_t) ::], c_loc(i), stat)
  end subroutine attr_int

  !> One attribute of memory type `mem_type` from the buffer at `buf`: a scalar when `dims` is
  !> empty, else an array of shape `dims`.
  subroutine write_attribute(loc, name, mem_type, dims, buf, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name
    integer(hid_t), intent(in) :: mem_type
    integer(hsize_t), intent(in) :: dims(:)
    type(c_ptr), intent(in) :: buf
    integer, intent(out) :: stat
    integer(hid_t) :: space, attr
    integer :: ignore
    if (size(dims) == 0) then
      call h5screate_f(H5S_SCALAR_F, space, stat)
    else
      call h5screate_simple_f(size(dims), dims, space, stat)
    end if
    if (stat /= 0) return
    call h5acreate_f(loc%id, name, mem_type, space, attr, stat)
    if (stat == 0) then
      call h5awrite_f(attr, mem_type, buf, stat)
      call h5aclose_f(attr, ignore)
    end if
    call h5sclose_f(space, ignore)
  end subroutine write_attribute

end module interlock_h5
