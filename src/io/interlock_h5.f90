!> A thin HDF5 write layer (in the spirit of h5fortran): generic procedures that hide the raw
!> h5*_f calls. Every procedure returns a status (0: success) instead of stopping, and every
!> dataset is written with its `unit` and `description` attributes (the self-describing output
!> of docs/history-output.md). Fortran arrays (m, n) appear in h5py as (n, m).
module interlock_h5
  use, intrinsic :: iso_fortran_env, only: real64, int32
  use, intrinsic :: iso_c_binding, only: c_ptr, c_loc, c_char, c_null_char
  use hdf5, only: hid_t, hsize_t, h5open_f, h5close_f, h5fcreate_f, h5fopen_f, h5fclose_f, &
      h5fis_hdf5_f, h5gcreate_f, h5gclose_f, h5screate_simple_f, h5screate_f, h5sclose_f, &
      h5sselect_hyperslab_f, h5dcreate_f, h5dwrite_f, h5dclose_f, h5dset_extent_f, &
      h5dget_space_f, h5acreate_f, h5awrite_f, h5aclose_f, h5aexists_f, h5lexists_f, &
      h5tcopy_f, h5tset_cset_f, h5tclose_f, h5pcreate_f, h5pclose_f, h5pset_libver_bounds_f, &
      h5pset_chunk_f, h5pset_fclose_degree_f, h5eset_auto_f, H5F_ACC_TRUNC_F, &
      H5F_ACC_RDONLY_F, H5S_SCALAR_F, H5S_UNLIMITED_F, H5S_SELECT_SET_F, H5T_NATIVE_DOUBLE, &
      H5T_NATIVE_INTEGER, H5T_STRING, H5T_CSET_UTF8_F, H5P_FILE_ACCESS_F, &
      H5P_DATASET_CREATE_F, H5F_LIBVER_V18_F, H5F_LIBVER_LATEST_F, H5F_CLOSE_STRONG_F
  implicit none
  private
  public :: h5_file_t, h5_series_t, h5_open_library, h5_close_library, h5_create_file, &
            h5_close_file, h5_has_marks, h5_create_group, h5_close_group, h5_create_series, &
            h5_append, h5_close_series, h5_attribute

  integer, parameter :: dp = real64

  !> An open file or group (a location that can hold datasets and attributes).
  type :: h5_file_t
    integer(hid_t) :: id = -1
  end type h5_file_t

  !> An extendible dataset written row by row (h5_append): `width` values per row (0: one
  !> scalar per row, a 1-d dataset), `rows` written so far.
  type :: h5_series_t
    integer(hid_t) :: id = -1
    integer(hid_t) :: mem_type = -1
    integer :: width = 0
    integer :: rows = 0
  end type h5_series_t

  !> Append rows to a series: real (n) or (width, n), integer (n).
  interface h5_append
    module procedure append_real_1d, append_real_2d, append_int_1d
  end interface h5_append

  !> Write an attribute: character scalar or array, real scalar or array, integer scalar.
  interface h5_attribute
    module procedure attr_text, attr_text_1d, attr_real, attr_real_1d, attr_int
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
    ! Closing the file closes whatever is still open in it (a failed write leaves nothing open
    ! for the library's exit handlers to trip over).
    if (stat == 0) call h5pset_fclose_degree_f(fapl, H5F_CLOSE_STRONG_F, stat)
    if (stat == 0) call h5fcreate_f(name, H5F_ACC_TRUNC_F, file%id, stat, access_prp=fapl)
    call h5pclose_f(fapl, ignore)
  end subroutine h5_create_file

  !> `name` is an HDF5 file (signature checked by the library) whose root holds the attribute
  !> `attribute` and the link `link`: the marks our writer leaves. Only call it for a regular
  !> file (a FIFO would block).
  logical function h5_has_marks(name, attribute, link)
    character(len=*), intent(in) :: name, attribute, link
    integer(hid_t) :: file
    logical :: is_hdf5, exists
    integer :: stat, ignore
    h5_has_marks = .false.
    call h5fis_hdf5_f(name, is_hdf5, stat)
    if (stat /= 0 .or. .not. is_hdf5) return
    call h5fopen_f(name, H5F_ACC_RDONLY_F, file, stat)
    if (stat /= 0) return
    call h5aexists_f(file, attribute, exists, stat)
    if (stat == 0 .and. exists) then
      call h5lexists_f(file, link, exists, stat)
      h5_has_marks = stat == 0 .and. exists
    end if
    call h5fclose_f(file, ignore)
  end function h5_has_marks

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

  !> Create an empty extendible dataset of `width` columns (0: a 1-d dataset) that grows by rows
  !> (h5_append), chunked by `chunk_rows` rows, with its `unit` and `description`.
  subroutine h5_create_series(loc, name, integer_values, width, chunk_rows, unit, description, &
                              series, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name, unit, description
    logical, intent(in) :: integer_values
    integer, intent(in) :: width, chunk_rows
    type(h5_series_t), intent(out) :: series
    integer, intent(out) :: stat
    integer(hid_t) :: space, dcpl
    integer(hsize_t), allocatable :: dims(:), maxdims(:), chunk(:)
    integer :: ignore
    series%width = width
    series%mem_type = H5T_NATIVE_DOUBLE
    if (integer_values) series%mem_type = H5T_NATIVE_INTEGER
    if (width > 0) then
      dims = [integer(hsize_t) :: width, 0]
      maxdims = [integer(hsize_t) :: width, H5S_UNLIMITED_F]
      chunk = [integer(hsize_t) :: width, max(1, chunk_rows)]
    else
      dims = [integer(hsize_t) :: 0]
      maxdims = [integer(hsize_t) :: H5S_UNLIMITED_F]
      chunk = [integer(hsize_t) :: max(1, chunk_rows)]
    end if
    call h5screate_simple_f(size(dims), dims, space, stat, maxdims)
    if (stat /= 0) return
    call h5pcreate_f(H5P_DATASET_CREATE_F, dcpl, stat)
    if (stat == 0) then
      call h5pset_chunk_f(dcpl, size(chunk), chunk, stat)
      if (stat == 0) call h5dcreate_f(loc%id, name, series%mem_type, space, series%id, stat, &
                                      dcpl_id=dcpl)
      if (stat == 0) call describe(series%id, unit, description, stat)
      call h5pclose_f(dcpl, ignore)
    end if
    call h5sclose_f(space, ignore)
  end subroutine h5_create_series

  subroutine append_real_1d(series, x, stat)
    type(h5_series_t), intent(inout) :: series
    real(dp), intent(in), target, contiguous :: x(:)
    integer, intent(out) :: stat
    call append_rows(series, size(x), c_loc(x), stat)
  end subroutine append_real_1d

  subroutine append_real_2d(series, x, stat)
    type(h5_series_t), intent(inout) :: series
    real(dp), intent(in), target, contiguous :: x(:, :)
    integer, intent(out) :: stat
    call append_rows(series, size(x, 2), c_loc(x), stat)
  end subroutine append_real_2d

  subroutine append_int_1d(series, x, stat)
    type(h5_series_t), intent(inout) :: series
    integer, intent(in), target, contiguous :: x(:)
    integer, intent(out) :: stat
    call append_rows(series, size(x), c_loc(x), stat)
  end subroutine append_int_1d

  !> Append `n` rows from the contiguous buffer at `buf` (width x n values) to the series.
  subroutine append_rows(series, n, buf, stat)
    type(h5_series_t), intent(inout) :: series
    integer, intent(in) :: n
    type(c_ptr), intent(in) :: buf
    integer, intent(out) :: stat
    integer(hid_t) :: file_space, mem_space
    integer(hsize_t), allocatable :: total(:), start(:), count(:)
    integer :: ignore
    stat = 0
    if (n < 1) return
    if (series%width > 0) then
      total = [integer(hsize_t) :: series%width, series%rows + n]
      start = [integer(hsize_t) :: 0, series%rows]
      count = [integer(hsize_t) :: series%width, n]
    else
      total = [integer(hsize_t) :: series%rows + n]
      start = [integer(hsize_t) :: series%rows]
      count = [integer(hsize_t) :: n]
    end if
    call h5dset_extent_f(series%id, total, stat)
    if (stat /= 0) return
    call h5dget_space_f(series%id, file_space, stat)
    if (stat /= 0) return
    call h5sselect_hyperslab_f(file_space, H5S_SELECT_SET_F, start, count, stat)
    if (stat == 0) call h5screate_simple_f(size(count), count, mem_space, stat)
    if (stat == 0) then
      call h5dwrite_f(series%id, series%mem_type, buf, stat, mem_space_id=mem_space, &
                      file_space_id=file_space)
      call h5sclose_f(mem_space, ignore)
    end if
    call h5sclose_f(file_space, ignore)
    if (stat == 0) series%rows = series%rows + n
  end subroutine append_rows

  subroutine h5_close_series(series, stat)
    type(h5_series_t), intent(inout) :: series
    integer, intent(out) :: stat
    stat = 0
    if (series%id >= 0) call h5dclose_f(series%id, stat)
    series%id = -1
  end subroutine h5_close_series

  !> The two attributes every dataset carries.
  subroutine describe(dset, unit, description, stat)
    integer(hid_t), intent(in) :: dset
    character(len=*), intent(in) :: unit, description
    integer, intent(out) :: stat
    call text_attribute(dset, 'unit', [unit], .true., stat)
    if (stat == 0) call text_attribute(dset, 'description', [description], .true., stat)
  end subroutine describe

  ! -------------------------------------------------------------- attributes

  subroutine attr_text(loc, name, text, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name, text
    integer, intent(out) :: stat
    call text_attribute(loc%id, name, [text], .true., stat)
  end subroutine attr_text

  !> An array of strings (each without its trailing blanks): h5py returns an array of str.
  subroutine attr_text_1d(loc, name, texts, stat)
    type(h5_file_t), intent(in) :: loc
    character(len=*), intent(in) :: name, texts(:)
    integer, intent(out) :: stat
    call text_attribute(loc%id, name, texts, .false., stat)
  end subroutine attr_text_1d

  !> A variable-length string attribute, scalar (one text) or an array, marked UTF-8 when
  !> the texts are valid UTF-8 (h5py returns str; text that is not, e.g. a Latin-1 comment in a
  !> deck, is marked ASCII and keeps its bytes).
  subroutine text_attribute(id, name, texts, scalar, stat)
    integer(hid_t), intent(in) :: id
    character(len=*), intent(in) :: name, texts(:)
    logical, intent(in) :: scalar
    integer, intent(out) :: stat
    integer(hid_t) :: space, attr, stype
    character(kind=c_char), allocatable, target :: buffer(:)
    type(c_ptr), allocatable, target :: pointers(:)
    integer :: ignore, k, at, n
    logical :: utf8
    allocate (buffer(size(texts) * (len(texts) + 1) + 1), pointers(max(1, size(texts))))
    at = 1
    utf8 = .true.
    do k = 1, size(texts)
      n = len(texts(k))
      if (.not. scalar) n = len_trim(texts(k))
      buffer(at:at + n - 1) = transfer(texts(k)(1:n), buffer(1:n))
      buffer(at + n) = c_null_char
      pointers(k) = c_loc(buffer(at))
      at = at + n + 1
      utf8 = utf8 .and. is_utf8(texts(k)(1:n))
    end do
    call h5tcopy_f(H5T_STRING, stype, stat)
    if (stat /= 0) return
    if (utf8) call h5tset_cset_f(stype, H5T_CSET_UTF8_F, stat)
    if (stat == 0) then
      if (scalar) then
        call h5screate_f(H5S_SCALAR_F, space, stat)
      else
        call h5screate_simple_f(1, [int(size(texts), hsize_t)], space, stat)
      end if
    end if
    if (stat == 0) then
      call h5acreate_f(id, name, stype, space, attr, stat)
      if (stat == 0) then
        call h5awrite_f(attr, stype, c_loc(pointers), stat)
        call h5aclose_f(attr, ignore)
      end if
      call h5sclose_f(space, ignore)
    end if
    call h5tclose_f(stype, ignore)
  end subroutine text_attribute

  !> Well-formed UTF-8 (RFC 3629: no overlong forms, no surrogates, at most U+10FFFF).
  pure logical function is_utf8(text)
    character(len=*), intent(in) :: text
    integer :: i, k, c, n, lo, hi
    is_utf8 = .false.
    i = 1
    do while (i <= len(text))
      c = iachar(text(i:i))
      lo = 128
      hi = 191
      if (c < 128) then
        n = 0
      else if (c >= 194 .and. c <= 223) then
        n = 1
      else if (c >= 224 .and. c <= 239) then
        n = 2
        if (c == 224) lo = 160
        if (c == 237) hi = 159
      else if (c >= 240 .and. c <= 244) then
        n = 3
        if (c == 240) lo = 144
        if (c == 244) hi = 143
      else
        return
      end if
      if (i + n > len(text)) return
      do k = 1, n
        c = iachar(text(i + k:i + k))
        if (c < lo .or. c > hi) return
        lo = 128
        hi = 191
      end do
      i = i + n + 1
    end do
    is_utf8 = .true.
  end function is_utf8

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
