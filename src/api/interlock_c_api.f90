!> The C API (include/interlock.h; docs/c-api.md): a material from the UMAT's PROPS or from
!> named properties, the state of a point (the UMAT's STATEV, then the separation and the
!> traction of the last update), the batched update and the material description, as
!> `bind(C)` procedures over the library.
!>
!> **Same answers as the UMAT.** A material is read by the UMAT's props_n_to_material(_3d),
!> its state checked by statev_bad_index(_3d), the start separation and traction by the
!> UMAT's bounds, the step fraction is the UMAT's PNEWDT (interlock_step_control), the
!> symmetric tangent of property `tangent` = 2 is the UMAT's: a host moving from the UMAT to
!> the C API gets the same numbers.
!>
!> **Memory.** A material is one allocation (interlock_material_from_*), freed by
!> interlock_material_free; the update allocates nothing (the caller's arrays are viewed by
!> c_f_pointer), writes no file and builds no message (interlock_update_message reruns a point
!> for its message).
!>
!> **Threads.** No module variable is written (the version string is a constant); the
!> procedures are `recursive` so that every local lives on the stack, and a material is
!> read-only after its creation: many threads may update disjoint points with one material.
module interlock_c_api
  use, intrinsic :: iso_c_binding, only: c_int, c_double, c_size_t, c_ptr, c_char, c_null_char, &
      c_null_ptr, c_associated, c_f_pointer, c_loc
  use interlock_kinds, only: dp, separation_bound
  use interlock_status, only: interlock_info_t, status_ok, status_bad_input, message_len
  use interlock_numbers, only: key_in_range, format_integer, format_real, format_reals
  use interlock_material_table, only: properties, n_properties, n_required_properties, &
      property_index, check_property, property_defaults, umat_nstatv, umat_nstatv_3d, &
      umat_planes, statevar_3d, statevar_t, kind_real
  use interlock_material, only: interlock_material_t, interlock_solver_t, max_planes
  use interlock_state, only: interlock_state_t, interlock_state_init, interlock_state_3d_t, &
      interlock_state_3d_init
  use interlock_integrate, only: interlock_update
  use interlock_integrate_3d, only: interlock_update_3d
  use interlock_props, only: umat_controls_t, state_bound, props_n_to_material, &
      props_n_to_material_3d, nprops_message, statev_bad_index, statev_message, &
      statev_bad_index_3d, statev_message_3d, statev_to_state, state_to_statev, &
      statev_to_state_3d, state_to_statev_3d, statev_range, statev_variable
  use interlock_host_tangent, only: interlock_symmetric_tangent, interlock_symmetric_tangent_3d
  use interlock_step_control, only: step_fraction, step_fraction_3d, pnewdt_local_failure, &
      pnewdt_diverged, separation_bits, state_bits
  use interlock_version, only: interlock_version_string
  implicit none
  private
  public :: c_material_from_props, c_material_from_names, c_material_free, c_dim, c_plane_count, &
            c_state_size, c_statev_size, c_state_init, c_update, c_update_message, &
            c_property_count, c_property_info, c_property_check, c_state_variable_count, &
            c_state_variable_info, c_version

  !> The status codes of include/interlock.h.
  integer(c_int), parameter :: c_ok = 0, c_bad_input = 1, c_local_failure = 2, c_diverged = 3
  !> The flags of interlock_property_info.
  integer(c_int), parameter :: flag_required = 1, flag_lower_open = 2, flag_upper_open = 4, &
                               flag_infinite_ok = 8, flag_integer = 16
  !> The sizes of a material (material_size).
  integer, parameter :: size_dim = 1, size_planes = 2, size_state = 3, size_statev = 4
  !> The longest name a C caller may give (interlock_material_from_names).
  integer, parameter :: name_len = 64
  !> The largest state of a point: STATEV for max_planes planes, separation and traction.
  integer, parameter :: max_state_size = 8 * max_planes + 4 + 6

  !> The material behind the C handle.
  type :: c_material_t
    integer :: dim = 0          !< 2 or 3
    integer :: nstatv = 0       !< the UMAT's STATEV slots
    integer :: state_size = 0   !< nstatv + 2 dim
    logical :: symmetric = .false.   !< property tangent = 2
    type(interlock_material_t) :: mat
    type(interlock_solver_t) :: solver
    type(umat_controls_t) :: controls
  end type c_material_t

  !> The version as a C string (never written).
  character(kind=c_char, len=len(interlock_version_string) + 1), target, protected :: &
    version_c = interlock_version_string // c_null_char

contains

  ! --- The material.

  recursive integer(c_int) function c_material_from_props(dim, nprops, props, material, message, &
      message_len_c) result(stat) bind(C, name='interlock_material_from_props')
    integer(c_int), value :: dim, nprops
    type(c_ptr), value :: props, material, message
    integer(c_size_t), value :: message_len_c
    real(dp), pointer :: p(:)
    character(len=message_len) :: text
    stat = c_bad_input
    if (.not. null_handle_out(material, message, message_len_c)) return
    if (nprops < n_required_properties .or. nprops > n_properties) then
      call nprops_message(int(nprops), text)
      call copy_text(text, message, message_len_c)
      return
    end if
    if (.not. c_associated(props)) then
      call copy_text('props is NULL (NPROPS = ' // format_integer(int(nprops)) // ')', &
                     message, message_len_c)
      return
    end if
    call c_f_pointer(props, p, [nprops])
    stat = new_material(int(dim), p, material, text)
    if (stat /= c_ok) call copy_text(text, message, message_len_c)
  end function c_material_from_props

  recursive integer(c_int) function c_material_from_names(dim, n, names, values, material, &
      message, message_len_c) result(stat) bind(C, name='interlock_material_from_names')
    integer(c_int), value :: dim, n
    type(c_ptr), value :: names, values, material, message
    integer(c_size_t), value :: message_len_c
    type(c_ptr), pointer :: name_ptrs(:)
    real(dp), pointer :: v(:)
    real(dp) :: props(n_properties)
    logical :: given(n_properties), ok
    character(len=name_len) :: name
    character(len=message_len) :: text
    integer :: j, i
    stat = c_bad_input
    if (.not. null_handle_out(material, message, message_len_c)) return
    if (n < 0 .or. (n > 0 .and. (.not. c_associated(names) .or. .not. c_associated(values)))) then
      call copy_text('n = ' // format_integer(int(n)) // ' named properties with names or ' // &
                     'values NULL: admissible n >= 0, names and values arrays of n', message, &
                     message_len_c)
      return
    end if
    props = property_defaults
    given = .false.
    if (n > 0) then
      call c_f_pointer(names, name_ptrs, [n])
      call c_f_pointer(values, v, [n])
    end if
    do j = 1, n
      call c_string(name_ptrs(j), name)
      i = property_index(name)
      if (i == 0) then
        text = "unknown property '" // trim(name) // "': the properties are " // property_names() &
               // ' (interlock-query --props)'
      else if (given(i)) then
        text = "property '" // trim(name) // "' is given twice"
      else
        call check_property(i, v(j), ok, text)
        if (ok) then
          given(i) = .true.
          props(i) = v(j)
          cycle
        end if
      end if
      call copy_text(text, message, message_len_c)
      return
    end do
    do i = 1, n_required_properties
      if (.not. given(i)) then
        call copy_text("property '" // trim(properties(i)%name) // "' is required (it has no " // &
                       'default): the required properties are ' // &
                       property_names(n_required_properties), message, message_len_c)
        return
      end if
    end do
    stat = new_material(int(dim), props, material, text)
    if (stat /= c_ok) then
      ! (the names are the caller's: the PROPS index of the UMAT's message is left out)
      if (index(text, 'PROPS(') == 1 .and. index(text, '): ') > 0) text = text(index(text, '): ') + 3:)
      call copy_text(text, message, message_len_c)
    end if
  end function c_material_from_names

  !> The names of properties 1 .. n (every one by default), comma-separated.
  pure function property_names(n) result(text)
    integer, intent(in), optional :: n
    character(len=26 * n_properties) :: text
    integer :: i, last
    last = n_properties
    if (present(n)) last = n
    text = trim(properties(1)%name)
    do i = 2, last
      text = trim(text) // ', ' // trim(properties(i)%name)
    end do
  end function property_names

  !> The handle out-argument is not NULL (then set to NULL until a material is made).
  logical function null_handle_out(material, message, message_len_c) result(ok)
    type(c_ptr), intent(in) :: material, message
    integer(c_size_t), intent(in) :: message_len_c
    type(c_ptr), pointer :: out
    ok = c_associated(material)
    if (.not. ok) then
      call copy_text('material (the address of the handle) is NULL', message, message_len_c)
      return
    end if
    call c_f_pointer(material, out)
    out = c_null_ptr
  end function null_handle_out

  !> Read PROPS as the UMAT does for a `dim`-dimensional interface; on success a new handle in
  !> the C pointer `material` points to.
  recursive integer(c_int) function new_material(dim, props, material, message) result(stat)
    integer, intent(in) :: dim
    real(dp), intent(in) :: props(:)
    type(c_ptr), intent(in) :: material
    character(len=*), intent(out) :: message
    type(c_material_t) :: h
    type(c_material_t), pointer :: created
    type(c_ptr), pointer :: out
    integer :: s
    stat = c_bad_input
    select case (dim)
    case (2)
      call props_n_to_material(size(props), props, h%mat, h%solver, h%controls, s, message)
      h%nstatv = umat_nstatv
    case (3)
      call props_n_to_material_3d(size(props), props, h%mat, h%solver, h%controls, s, message)
      h%nstatv = umat_nstatv_3d(h%mat%n_planes)
    case default
      message = 'dim = ' // format_integer(dim) // ' is inadmissible: admissible dim = 2 (2D ' // &
                'interface: s_N, s_T) or 3 (3D interface: s_N, s_T1, s_T2)'
      return
    end select
    if (s /= status_ok) return
    h%dim = dim
    h%state_size = h%nstatv + 2 * dim
    h%symmetric = h%controls%symmetric_tangent
    allocate (created, source=h)
    call c_f_pointer(material, out)
    out = c_loc(created)
    stat = c_ok
  end function new_material

  recursive subroutine c_material_free(material) bind(C, name='interlock_material_free')
    type(c_ptr), value :: material
    type(c_material_t), pointer :: h
    if (.not. c_associated(material)) return
    call c_f_pointer(material, h)
    deallocate (h)
  end subroutine c_material_free

  !> The material behind a handle (NULL: not associated).
  function handle(material) result(h)
    type(c_ptr), intent(in) :: material
    type(c_material_t), pointer :: h
    h => null()
    if (c_associated(material)) call c_f_pointer(material, h)
  end function handle

  integer(c_int) function c_dim(material) result(n) bind(C, name='interlock_dim')
    type(c_ptr), value :: material
    n = material_size(material, size_dim)
  end function c_dim

  integer(c_int) function c_plane_count(material) result(n) bind(C, name='interlock_plane_count')
    type(c_ptr), value :: material
    n = material_size(material, size_planes)
  end function c_plane_count

  integer(c_int) function c_state_size(material) result(n) bind(C, name='interlock_state_size')
    type(c_ptr), value :: material
    n = material_size(material, size_state)
  end function c_state_size

  integer(c_int) function c_statev_size(material) result(n) bind(C, name='interlock_statev_size')
    type(c_ptr), value :: material
    n = material_size(material, size_statev)
  end function c_statev_size

  !> One of a material's sizes (`what`: size_*); 0 for NULL.
  integer(c_int) function material_size(material, what) result(n)
    type(c_ptr), intent(in) :: material
    integer, intent(in) :: what
    type(c_material_t), pointer :: h
    n = 0
    h => handle(material)
    if (.not. associated(h)) return
    select case (what)
    case (size_dim)
      n = h%dim
    case (size_planes)
      n = h%mat%n_planes
    case (size_state)
      n = h%state_size
    case (size_statev)
      n = h%nstatv
    end select
  end function material_size

  ! --- The state.

  recursive integer(c_int) function c_state_init(material, prefractured, n, state) result(stat) &
      bind(C, name='interlock_state_init')
    type(c_ptr), value :: material, state
    integer(c_int), value :: prefractured
    integer(c_size_t), value :: n
    type(c_material_t), pointer :: h
    real(dp), pointer :: out(:)
    real(dp) :: one(max_state_size)
    type(interlock_material_t) :: mat
    type(interlock_state_3d_t) :: st
    integer(c_size_t) :: i, ns
    stat = c_bad_input
    h => handle(material)
    if (.not. associated(h)) return
    if (prefractured /= 0 .and. prefractured /= 1) return
    if (h%mat%prefractured .and. prefractured == 0) return
    if (n == 0) then
      stat = c_ok
      return
    end if
    if (.not. c_associated(state)) return
    mat = h%mat
    mat%prefractured = prefractured == 1
    ns = h%state_size
    one = 0.0_dp
    if (h%dim == 2) then
      call interlock_state_init(mat, st%interlock_state_t)
      call state_to_statev(st%interlock_state_t, one(1:h%nstatv))
    else
      call interlock_state_3d_init(mat, st)
      call state_to_statev_3d(st, mat%n_planes, one(1:h%nstatv))
    end if
    call c_f_pointer(state, out, [n * ns])
    do i = 0, n - 1
      out(i * ns + 1:i * ns + ns) = one(1:ns)
    end do
    stat = c_ok
  end function c_state_init

  ! --- The update.

  recursive integer(c_size_t) function c_update(material, n, separation, state_old, state_new, &
      traction, tangent, status, fraction) result(n_failed) bind(C, name='interlock_update')
    type(c_ptr), value :: material, separation, state_old, state_new, traction, tangent, status, &
                          fraction
    integer(c_size_t), value :: n
    type(c_material_t), pointer :: h
    real(dp), pointer :: s(:), old(:), new(:), sigma(:), dsds(:), f(:)
    integer(c_int), pointer :: st(:)
    real(dp) :: no_tangent(9)
    integer(c_size_t) :: i, d, ns, dd
    character(len=1) :: no_message
    n_failed = n
    if (n == 0) return
    h => handle(material)
    if (.not. associated(h)) return
    if (.not. (c_associated(separation) .and. c_associated(state_old) .and. &
               c_associated(state_new) .and. c_associated(traction) .and. &
               c_associated(status) .and. c_associated(fraction))) return
    d = h%dim
    ns = h%state_size
    dd = d * d
    call c_f_pointer(separation, s, [n * d])
    call c_f_pointer(state_old, old, [n * ns])
    call c_f_pointer(state_new, new, [n * ns])
    call c_f_pointer(traction, sigma, [n * d])
    call c_f_pointer(status, st, [n])
    call c_f_pointer(fraction, f, [n])
    if (c_associated(tangent)) call c_f_pointer(tangent, dsds, [n * dd])
    n_failed = 0
    do i = 0, n - 1
      if (c_associated(tangent)) then
        call update_point(h, s(i * d + 1:i * d + d), old(i * ns + 1:i * ns + ns), &
                          new(i * ns + 1:i * ns + ns), sigma(i * d + 1:i * d + d), &
                          dsds(i * dd + 1:i * dd + dd), st(i + 1), f(i + 1), .false., no_message)
      else
        call update_point(h, s(i * d + 1:i * d + d), old(i * ns + 1:i * ns + ns), &
                          new(i * ns + 1:i * ns + ns), sigma(i * d + 1:i * d + d), &
                          no_tangent(1:dd), st(i + 1), f(i + 1), .false., no_message)
      end if
      if (st(i + 1) /= c_ok) n_failed = n_failed + 1
    end do
  end function c_update

  recursive integer(c_int) function c_update_message(material, separation, state_old, message, &
      message_len_c) result(stat) bind(C, name='interlock_update_message')
    type(c_ptr), value :: material, separation, state_old, message
    integer(c_size_t), value :: message_len_c
    type(c_material_t), pointer :: h
    real(dp), pointer :: s(:), old(:)
    real(dp) :: new(max_state_size), sigma(3), dsds(9), f
    character(len=message_len) :: text
    stat = c_bad_input
    h => handle(material)
    if (.not. associated(h)) then
      call copy_text('material is NULL', message, message_len_c)
      return
    end if
    if (.not. (c_associated(separation) .and. c_associated(state_old))) then
      call copy_text('separation or state_old is NULL', message, message_len_c)
      return
    end if
    call c_f_pointer(separation, s, [h%dim])
    call c_f_pointer(state_old, old, [h%state_size])
    text = ''
    call update_point(h, s, old, new(1:h%state_size), sigma(1:h%dim), dsds(1:h%dim**2), stat, &
                      f, .true., text)
    call copy_text(text, message, message_len_c)
  end function c_update_message

  !> One point: the UMAT's checks in its order (the start separation and traction and the
  !> STATEV are bad input; an end separation not finite or beyond the bound is a diverged
  !> iteration), the update, the outputs, the step fraction. A point refused or failed writes
  !> only `stat`, `fraction` and (when `want_message`) `message`.
  recursive subroutine update_point(h, s, old, new, sigma, dsds, stat, fraction, want_message, &
                                    message)
    type(c_material_t), intent(in) :: h
    real(dp), intent(in) :: s(h%dim), old(h%state_size)
    real(dp), intent(inout) :: new(h%state_size), sigma(h%dim), dsds(h%dim**2)
    integer(c_int), intent(out) :: stat
    real(dp), intent(out) :: fraction
    logical, intent(in) :: want_message
    character(len=*), intent(inout) :: message
    type(interlock_state_t) :: old_2d, new_2d
    type(interlock_state_3d_t) :: old_3d, new_3d
    type(interlock_info_t) :: info
    real(dp) :: sig(3), tangent(3, 3), tangent_2d(2, 2)
    integer :: d, nsv, bad, a

    d = h%dim
    nsv = h%nstatv
    stat = c_bad_input
    fraction = 0.0_dp
    if (.not. all(key_in_range(old(nsv + 1:nsv + d), -1 - separation_bits, separation_bits))) then
      if (want_message) message = 'the separation at the start of the increment (state[' // &
        format_integer(nsv) // '] .. state[' // format_integer(nsv + d - 1) // ']) = (' // &
        format_reals(old(nsv + 1:nsv + d)) // ') mm is inadmissible: admissible |s| <= ' // &
        format_real(separation_bound) // ' mm'
      return
    end if
    if (.not. all(key_in_range(old(nsv + d + 1:nsv + 2 * d), -1 - state_bits, state_bits))) then
      if (want_message) message = 'the traction at the start of the increment (state[' // &
        format_integer(nsv + d) // '] .. state[' // format_integer(nsv + 2 * d - 1) // ']) = (' // &
        format_reals(old(nsv + d + 1:nsv + 2 * d)) // ') MPa is inadmissible: admissible ' // &
        '|traction| <= ' // format_real(state_bound) // ' MPa'
      return
    end if
    if (d == 2) then
      bad = statev_bad_index(old(1:nsv), h%mat)
      if (bad /= 0 .and. want_message) call statev_message(old(1:nsv), bad, h%mat, message)
    else
      bad = statev_bad_index_3d(old(1:nsv), h%mat)
      if (bad /= 0 .and. want_message) call statev_message_3d(old(1:nsv), bad, h%mat, message)
    end if
    if (bad /= 0) then
      if (want_message) message = 'state[' // format_integer(bad - 1) // '], ' // trim(message)
      return
    end if
    if (.not. all(key_in_range(s, -1 - separation_bits, separation_bits))) then
      stat = c_diverged
      fraction = pnewdt_diverged
      if (want_message) message = 'diverged iteration: the separation (' // format_reals(s) // &
        ') mm is not finite or beyond the admissible |s| <= ' // format_real(separation_bound) // &
        ' mm (the start is sound: the host''s Newton iterate went astray): cut the increment ' // &
        '(step fraction ' // format_real(pnewdt_diverged) // ')'
      return
    end if

    if (d == 2) then
      call statev_to_state(old(1:nsv), h%mat, old_2d)
      old_2d%s = old(nsv + 1:nsv + 2)
      old_2d%sigma = old(nsv + 3:nsv + 4)
      call interlock_update(h%mat, h%solver, s, old_2d, new_2d, sig(1:2), tangent_2d, info)
      if (info%status == status_ok) then
        if (h%symmetric) call interlock_symmetric_tangent(tangent_2d)
        tangent(1:2, 1:2) = tangent_2d
        fraction = step_fraction(h%mat, h%solver, h%controls, old_2d, new_2d)
        call state_to_statev(new_2d, new(1:nsv))
      end if
    else
      call statev_to_state_3d(old(1:nsv), h%mat, old_3d)
      old_3d%s = old(nsv + 1:nsv + 2)
      old_3d%s_t2 = old(nsv + 3)
      old_3d%sigma = old(nsv + 4:nsv + 5)
      old_3d%sigma_t2 = old(nsv + 6)
      call interlock_update_3d(h%mat, h%solver, s, old_3d, new_3d, sig, tangent, info)
      if (info%status == status_ok) then
        if (h%symmetric) call interlock_symmetric_tangent_3d(tangent)
        fraction = step_fraction_3d(h%mat, h%solver, h%controls, old_3d, new_3d)
        call state_to_statev_3d(new_3d, h%mat%n_planes, new(1:nsv))
      end if
    end if
    if (info%status /= status_ok) then
      if (info%status == status_bad_input) then
        fraction = 0.0_dp
      else
        stat = c_local_failure
        fraction = pnewdt_local_failure
      end if
      if (want_message) message = info%message
      return
    end if
    new(nsv + 1:nsv + d) = s
    new(nsv + d + 1:nsv + 2 * d) = sig(1:d)
    sigma = sig(1:d)
    ! (row-major: d traction_a / d s_b at a d + b, 0-based)
    do a = 1, d
      dsds((a - 1) * d + 1:a * d) = tangent(a, 1:d)
    end do
    stat = c_ok
  end subroutine update_point

  ! --- The material description.

  integer(c_int) function c_property_count() result(n) bind(C, name='interlock_property_count')
    n = n_properties
  end function c_property_count

  recursive integer(c_int) function c_property_info(i, name, name_len_c, unit, unit_len_c, lo, hi, &
      default_value, flags) result(stat) bind(C, name='interlock_property_info')
    integer(c_int), value :: i
    type(c_ptr), value :: name, unit, lo, hi, default_value, flags
    integer(c_size_t), value :: name_len_c, unit_len_c
    integer(c_int) :: f
    stat = c_bad_input
    if (i < 0 .or. i >= n_properties) return
    associate (p => properties(i + 1))
      call copy_text(p%name, name, name_len_c)
      call copy_text(p%unit, unit, unit_len_c)
      call put_real(lo, p%lower)
      call put_real(hi, p%upper)
      call put_real(default_value, p%default)
      f = 0
      if (p%required) f = f + flag_required
      if (p%lower_open) f = f + flag_lower_open
      if (p%upper_open) f = f + flag_upper_open
      if (p%infinite_ok) f = f + flag_infinite_ok
      if (p%kind /= kind_real) f = f + flag_integer
    end associate
    call put_int(flags, f)
    stat = c_ok
  end function c_property_info

  recursive integer(c_int) function c_property_check(i, value, message, message_len_c) &
      result(stat) bind(C, name='interlock_property_check')
    integer(c_int), value :: i
    real(c_double), value :: value
    type(c_ptr), value :: message
    integer(c_size_t), value :: message_len_c
    character(len=message_len) :: text
    logical :: ok
    stat = c_bad_input
    if (i < 0 .or. i >= n_properties) then
      call copy_text('property index ' // format_integer(int(i)) // ' is inadmissible: ' // &
                     'admissible 0 <= i < ' // format_integer(n_properties), message, message_len_c)
      return
    end if
    call check_property(i + 1, value, ok, text)
    call copy_text(text, message, message_len_c)
    if (ok) stat = c_ok
  end function c_property_check

  integer(c_int) function c_state_variable_count(material) result(n) &
      bind(C, name='interlock_state_variable_count')
    type(c_ptr), value :: material
    n = c_state_size(material)
  end function c_state_variable_count

  recursive integer(c_int) function c_state_variable_info(material, i, name, name_len_c, unit, &
      unit_len_c, plane, lo, hi) result(stat) bind(C, name='interlock_state_variable_info')
    type(c_ptr), value :: material, name, unit, plane, lo, hi
    integer(c_int), value :: i
    integer(c_size_t), value :: name_len_c, unit_len_c
    type(c_material_t), pointer :: h
    real(dp) :: low, high
    type(statevar_t) :: row
    character(len=*), parameter :: components_2d(2) = ['n ', 't '], &
                                   components_3d(3) = ['n ', 't1', 't2']
    character(len=2) :: component
    integer :: slot, ivar, k, j
    stat = c_bad_input
    h => handle(material)
    if (.not. associated(h)) return
    if (i < 0 .or. i >= h%state_size) return
    slot = i + 1
    if (slot <= h%nstatv) then
      if (h%dim == 2) then
        call statev_variable(slot, umat_planes, ivar, k)
      else
        call statev_variable(slot, h%mat%n_planes, ivar, k)
      end if
      call statev_range(h%mat, ivar, k, low, high)
      row = statevar_3d(ivar)
      call copy_text(row%name, name, name_len_c)
      call copy_text(row%unit, unit, unit_len_c)
      call put_int(plane, k)
      call put_real(lo, low)
      call put_real(hi, high)
    else
      j = slot - h%nstatv
      if (h%dim == 2) then
        component = components_2d(mod(j - 1, 2) + 1)
      else
        component = components_3d(mod(j - 1, 3) + 1)
      end if
      call put_int(plane, 0)
      if (j <= h%dim) then
        call copy_text('separation_' // trim(component), name, name_len_c)
        call copy_text('mm', unit, unit_len_c)
        call put_real(lo, -separation_bound)
        call put_real(hi, separation_bound)
      else
        call copy_text('traction_' // trim(component), name, name_len_c)
        call copy_text('MPa', unit, unit_len_c)
        call put_real(lo, -state_bound)
        call put_real(hi, state_bound)
      end if
    end if
    stat = c_ok
  end function c_state_variable_info

  type(c_ptr) function c_version() result(p) bind(C, name='interlock_version')
    p = c_loc(version_c)
  end function c_version

  ! --- C strings and optional outputs.

  !> Copy `text` (trimmed) NUL-terminated into the caller's buffer of buffer_len bytes,
  !> truncated to buffer_len - 1 characters; a NULL buffer or buffer_len 0: nothing.
  subroutine copy_text(text, buffer, buffer_len)
    character(len=*), intent(in) :: text
    type(c_ptr), intent(in) :: buffer
    integer(c_size_t), intent(in) :: buffer_len
    character(kind=c_char), pointer :: chars(:)
    integer :: j, n
    if (.not. c_associated(buffer) .or. buffer_len < 1) return
    n = int(min(int(len_trim(text), c_size_t), buffer_len - 1))
    call c_f_pointer(buffer, chars, [n + 1])
    do j = 1, n
      chars(j) = text(j:j)
    end do
    chars(n + 1) = c_null_char
  end subroutine copy_text

  !> The C string at p (up to name_len characters; NULL: blank).
  subroutine c_string(p, text)
    type(c_ptr), intent(in) :: p
    character(len=*), intent(out) :: text
    character(kind=c_char), pointer :: chars(:)
    integer :: j
    text = ''
    if (.not. c_associated(p)) return
    call c_f_pointer(p, chars, [len(text)])
    do j = 1, len(text)
      if (chars(j) == c_null_char) return
      text(j:j) = chars(j)
    end do
  end subroutine c_string

  subroutine put_real(p, x)
    type(c_ptr), intent(in) :: p
    real(dp), intent(in) :: x
    real(c_double), pointer :: target_value
    if (.not. c_associated(p)) return
    call c_f_pointer(p, target_value)
    target_value = x
  end subroutine put_real

  subroutine put_int(p, i)
    type(c_ptr), intent(in) :: p
    integer, intent(in) :: i
    integer(c_int), pointer :: target_value
    if (.not. c_associated(p)) return
    call c_f_pointer(p, target_value)
    target_value = int(i, c_int)
  end subroutine put_int

end module interlock_c_api
