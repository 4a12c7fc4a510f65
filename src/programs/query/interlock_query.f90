!> interlock-query: what the material table says, for people and scripts (in the spirit of
!> mfront-query). Every table is generated from src/material/interlock_material_table.f90;
!> docs/material.md is the output of `interlock-query --markdown`.
program interlock_query
  use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
  use interlock_cli, only: exit_program, command_argument
  use interlock, only: properties, statevars, n_properties, n_required_properties, &
      umat_planes, umat_nstatv, format_range, format_real, property_t, statevar_t, kind_real, &
      kind_flag, kind_choice, &
      interlock_version_string, format_integer, statevar_index_3d, statevar_3d, &
      umat_nstatv_3d, n_statevars_strike, prop_ria, max_azimuths, format_statevar_range
  implicit none
  character(len=:), allocatable :: arg
  integer :: iarg, n


  n = command_argument_count()
  if (n == 0) then
    write (error_unit, '(a)') 'interlock-query: error: no option given'
    call usage(error_unit)
    call exit_program(2)
  end if
  ! every option is checked before anything is printed
  do iarg = 1, n
    arg = command_argument(iarg)
    select case (arg)
    case ('--help', '-h', '--version', '--properties', '--state-variables', '--props', &
          '--statev', '--markdown')
    case default
      write (error_unit, '(a)') "interlock-query: error: unknown option '" // arg // "'"
      call usage(error_unit)
      call exit_program(2)
    end select
  end do
  do iarg = 1, n
    arg = command_argument(iarg)
    select case (arg)
    case ('--help', '-h')
      call usage(output_unit)
    case ('--version')
      write (output_unit, '(a)') 'interlock-query ' // interlock_version_string
    case ('--properties')
      call print_properties()
    case ('--state-variables')
      call print_state_variables()
    case ('--props')
      call print_props()
    case ('--statev')
      call print_statev()
    case ('--markdown')
      call print_markdown()
    end select
  end do
  call exit_program(0)

contains

  subroutine usage(unit)
    integer, intent(in) :: unit
    write (unit, '(a)') &
      'usage: interlock-query OPTION...', &
      '  The material description of interlock ' // interlock_version_string // &
      ', generated from its material table.', &
      '  --properties       every material property: name, symbol, unit, group, kind, default,', &
      '                     admissible range, description', &
      '  --state-variables  every state variable: name, unit, per plane or not, description', &
      '  --props            the UMAT PROPS layout: index, name, unit, default, range, description', &
      '  --statev           the UMAT STATEV layouts (2D and 3D elements): index, name, plane,', &
      '                     unit, description', &
      '  --markdown         the whole reference page (docs/material.md)', &
      '  --version          the library version', &
      '  --help             this text', &
      '  Exit status: 0 done, 2 a usage error (no option, an unknown option), 3 an internal', &
      '  inconsistency of the material table.'
  end subroutine usage


  !> Text padded (or cut) to width w.
  pure function pad(text, w) result(out)
    character(len=*), intent(in) :: text
    integer, intent(in) :: w
    character(len=w) :: out
    out = text
  end function pad


  pure function default_text(i) result(text)
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    if (properties(i)%required) then
      text = 'required'
    else
      text = format_real(properties(i)%default)
    end if
  end function default_text

  pure function kind_text(i) result(text)
    integer, intent(in) :: i
    character(len=:), allocatable :: text
    select case (properties(i)%kind)
    case (kind_real)
      text = 'real'
    case (kind_flag)
      text = 'flag'
    case (kind_choice)
      text = 'choice'
    case default
      text = '?'
    end select
  end function kind_text

  pure function plane_text(k) result(text)
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    select case (k)
    case (1)
      text = '1 (-theta_0)'
    case (2)
      text = '2 (flat)'
    case (3)
      text = '3 (+theta_0)'
    case default
      text = format_integer(k)
    end select
  end function plane_text

  pure function plane_column(per_plane, k) result(text)
    logical, intent(in) :: per_plane
    integer, intent(in) :: k
    character(len=:), allocatable :: text
    if (per_plane) then
      text = plane_text(k)
    else
      text = '-'
    end if
  end function plane_column

  subroutine print_properties()
    integer :: i
    type(property_t) :: p
    write (output_unit, '(a)') pad('name', 25) // pad('symbol', 12) // pad('unit', 6) // &
      pad('group', 12) // pad('kind', 7) // pad('default', 10) // pad('admissible', 58) // &
      'description'
    do i = 1, n_properties
      p = properties(i)
      write (output_unit, '(a)') pad(p%name, 25) // pad(p%symbol, 12) // pad(p%unit, 6) // &
        pad(p%group, 12) // pad(kind_text(i), 7) // pad(default_text(i), 10) // &
        pad(format_range(i), 58) // trim(p%description)
    end do
  end subroutine print_properties

  subroutine print_props()
    integer :: i
    type(property_t) :: p
    write (output_unit, '(a)') pad('PROPS', 6) // pad('name', 25) // pad('unit', 6) // &
      pad('default', 10) // pad('admissible', 58) // 'description'
    do i = 1, n_properties
      p = properties(i)
      write (output_unit, '(a)') pad(format_integer(i), 6) // pad(p%name, 25) // pad(p%unit, 6) // &
        pad(default_text(i), 10) // pad(format_range(i), 58) // trim(p%description)
    end do
    write (output_unit, '(a)') 'NPROPS from ' // format_integer(n_required_properties) // ' to ' // &
      format_integer(n_properties) // '; properties after NPROPS take their defaults.', &
      trim(props_3d_note())
  end subroutine print_props

  subroutine print_state_variables()
    integer :: i
    type(statevar_t) :: v
    write (output_unit, '(a)') pad('name', 25) // pad('unit', 6) // pad('per plane', 11) // &
      pad('admissible', 64) // 'description'
    do i = 1, size(statevars) + n_statevars_strike
      v = statevar_3d(i)
      write (output_unit, '(a)') pad(v%name, 25) // pad(v%unit, 6) // &
        pad(merge('yes', 'no ', v%per_plane), 11) // pad(format_statevar_range(i), 64) // &
        trim(v%description)
    end do
  end subroutine print_state_variables

  subroutine print_statev()
    integer :: i, k, slot
    type(statevar_t) :: v
    write (output_unit, '(a)') pad('STATEV', 8) // pad('name', 25) // pad('plane', 14) // &
      pad('unit', 6) // pad('admissible', 64) // 'description'
    do slot = 1, umat_nstatv
      call locate(slot, .false., i, k)
      v = statevars(i)
      write (output_unit, '(a)') pad(format_integer(slot), 8) // pad(v%name, 25) // &
        pad(plane_column(v%per_plane, k), 14) // pad(v%unit, 6) // &
        pad(format_statevar_range(i), 64) // trim(v%description)
    end do
    write (output_unit, '(a)') 'NSTATV >= ' // format_integer(umat_nstatv) // ' (*DEPVAR ' // &
      format_integer(umat_nstatv) // '); all zero before the first increment.'
    write (output_unit, '(a)') '', '3D cohesive element (NTENS = 3), the paper''s RIA (ria = 0):'
    write (output_unit, '(a)') pad('STATEV', 8) // pad('name', 25) // pad('plane', 14) // &
      pad('unit', 6) // pad('admissible', 64) // 'description'
    do slot = 1, umat_nstatv_3d(umat_planes)
      call locate(slot, .true., i, k)
      v = statevar_3d(i)
      write (output_unit, '(a)') pad(format_integer(slot), 8) // pad(v%name, 25) // &
        pad(plane_column(v%per_plane, k), 14) // pad(v%unit, 6) // &
        pad(format_statevar_range(i), 64) // trim(v%description)
    end do
    write (output_unit, '(a)') trim(statev_3d_note())
  end subroutine print_statev

  !> What PROPS 21-22 mean by element.
  pure function props_3d_note() result(text)
    character(len=:), allocatable :: text
    text = 'PROPS ' // format_integer(prop_ria) // ', ' // format_integer(n_properties) // &
           ' select the RIA of a 3D cohesive element (NTENS = 3); a 2D element (NTENS = 2) ' // &
           'admits ria = 0 only.'
  end function props_3d_note

  !> The size and order of the 3D STATEV for any RIA.
  pure function statev_3d_note() result(text)
    character(len=:), allocatable :: text
    text = 'NSTATV >= ' // format_integer(umat_nstatv_3d(umat_planes)) // ' (*DEPVAR ' // &
           format_integer(umat_nstatv_3d(umat_planes)) // '); with ria = 1 and N_a azimuths ' // &
           'the RIA has n = 1 + 2 N_a planes (planes 1-3 as above, then (phi_j, -theta_0), ' // &
           '(phi_j, +theta_0) for j = 1 .. N_a - 1) and NSTATV >= 8 n + 4 (' // &
           format_integer(umat_nstatv_3d(1 + 2 * max_azimuths)) // ' at N_a = ' // &
           format_integer(max_azimuths) // '), in the same order: the 2D variables by ' // &
           'variable, then plane; the four of the point; the strike components by variable, ' // &
           'then plane. frictional_slip and friction_traction are the dip components (along ' // &
           'e_k), the strike ones along q_k (SPEC section 9). All zero before the first increment.'
  end function statev_3d_note

  !> Which state variable (ivar, statevar_3d) and plane (k, 0 for global ones) STATEV(slot)
  !> holds with the paper's RIA: of a 2D point (three_d false: the variables of `statevars`), or
  !> of a 3D point (the strike ones too); statevar_index_3d with the paper's planes is the 2D
  !> layout for the 2D variables.
  subroutine locate(slot, three_d, ivar, k)
    integer, intent(in) :: slot
    logical, intent(in) :: three_d
    integer, intent(out) :: ivar, k
    integer :: j, m, n_vars
    type(statevar_t) :: row
    n_vars = size(statevars)
    if (three_d) n_vars = n_vars + n_statevars_strike
    do j = 1, n_vars
      row = statevar_3d(j)
      do m = 0, umat_planes
        if (row%per_plane .neqv. (m > 0)) cycle
        if (statevar_index_3d(j, m, umat_planes) == slot) then
          ivar = j
          k = m
          return
        end if
      end do
    end do
    ivar = 1
    k = 0
    write (error_unit, '(a)') 'interlock-query: STATEV(' // format_integer(slot) // &
      ') is not in the table'
    call exit_program(3)
  end subroutine locate


  subroutine print_markdown()
    integer :: i, k, slot
    type(property_t) :: p
    type(statevar_t) :: v
    write (output_unit, '(a)') &
      '# interlock: material properties and state variables', &
      '', &
      '<!-- Generated by `interlock-query --markdown` from ' // &
      'src/material/interlock_material_table.f90.', &
      '     Do not edit: refresh with `interlock-query --markdown > docs/material.md`. -->', &
      '', &
      'Units: mm, N, MPa, N/mm. Component 1 is normal, 2 tangential. A property that admits', &
      'infinity takes any value >= 1e30 (or +Inf) to switch its effect off.', &
      '', &
      '## Properties', &
      '', &
      '| name | symbol | unit | group | kind | default | admissible | description |', &
      '|---|---|---|---|---|---|---|---|'
    do i = 1, n_properties
      p = properties(i)
      write (output_unit, '(a)') '| `' // trim(p%name) // '` | ' // trim(p%symbol) // ' | ' // &
        trim(p%unit) // ' | ' // trim(p%group) // ' | ' // kind_text(i) // ' | ' // &
        default_text(i) // ' | ' // format_range(i) // ' | ' // trim(p%description) // ' |'
    end do
    write (output_unit, '(a)') &
      '', &
      '## State variables', &
      '', &
      '| name | unit | per plane | admissible | description |', &
      '|---|---|---|---|---|'
    do i = 1, size(statevars) + n_statevars_strike
      v = statevar_3d(i)
      write (output_unit, '(a)') '| `' // trim(v%name) // '` | ' // trim(v%unit) // ' | ' // &
        trim(merge('yes', 'no ', v%per_plane)) // ' | ' // format_statevar_range(i) // ' | ' // &
        trim(v%description) // ' |'
    end do
    write (output_unit, '(a)') &
      '', &
      '## UMAT', &
      '', &
      'The UMAT (`umat/interlock_umat.f90`, library `interlock::interlock_umat`, or the single', &
      'file `interlock_umat_bundle.f90`) is for 2D cohesive elements, NTENS = 2 (1 normal,', &
      '2 shear), and 3D cohesive elements, NTENS = 3 (Abaqus COH3D8: NDI = 1, NSHR = 2; 1', &
      'normal, 2 shear along t1, the element''s first local shear direction, 3 shear along', &
      't2 = n x t1). STRAN/DSTRAN are separations (constitutive thickness 1). The RIA is the', &
      'three-plane RIA of the paper (planes -theta_0, 0, +theta_0 with area fraction 1/3', &
      'each; in 3D every azimuth is 0: ridges across t1), or in 3D the `azimuthal` RIA', &
      '(`ria` = 1, SPEC section 9). A 2D deck''s PROPS give the paper''s RIA in 3D unchanged. DDSDDE is not', &
      'symmetric once friction or wear acts: declare `*USER MATERIAL, UNSYMM` (for a host', &
      'that symmetrizes, e.g. CalculiX, `tangent` = 2: docs/calculix.md). SSE is the', &
      'stored energy, SCD the total dissipation (damage + friction), SPD = 0. PNEWDT is only', &
      'lowered: -1 on bad input (with a one-line message naming element and point, once per', &
      'material and kind of message), 0.25 on a diverged global iteration (DSTRAN not finite', &
      'or huge, or the increment ending beyond 1e6 mm), 0.5 on a local integration failure;', &
      'when an increment exceeds `max_damage_increment` or `max_angle_increment_deg`, f is the', &
      'first-order fraction of the increment that meets them, and max(0.01, f) is requested', &
      'only when f < 0.8 and a cut can meet the bound (docs/umat.md).', &
      '', &
      '### PROPS', &
      '', &
      'NPROPS from ' // format_integer(n_required_properties) // ' to ' // format_integer(n_properties) // &
      '; properties after NPROPS take their defaults. ' // props_3d_note(), &
      '', &
      '| PROPS | name | unit | default | admissible | description |', &
      '|---|---|---|---|---|---|'
    do i = 1, n_properties
      p = properties(i)
      write (output_unit, '(a)') '| ' // format_integer(i) // ' | `' // trim(p%name) // '` | ' // &
        trim(p%unit) // ' | ' // default_text(i) // ' | ' // format_range(i) // ' | ' // &
        trim(p%description) // ' |'
    end do
    write (output_unit, '(a)') &
      '', &
      '### STATEV', &
      '', &
      'NSTATV >= ' // format_integer(umat_nstatv) // ' (`*DEPVAR` ' // format_integer(umat_nstatv) // &
      '); all zero before the first increment.', &
      '', &
      '| STATEV | name | plane | unit | admissible | description |', &
      '|---|---|---|---|---|---|'
    do slot = 1, umat_nstatv
      call locate(slot, .false., i, k)
      v = statevars(i)
      write (output_unit, '(a)') '| ' // format_integer(slot) // ' | `' // trim(v%name) // '` | ' // &
        plane_column(v%per_plane, k) // ' | ' // trim(v%unit) // ' | ' // &
        format_statevar_range(i) // ' | ' // trim(v%description) // ' |'
    end do
    write (output_unit, '(a)') &
      '', &
      '### STATEV of a 3D cohesive element (NTENS = 3)', &
      '', &
      'The paper''s RIA (`ria` = 0): STATEV 1-22 as in 2D, then the strike components.', &
      statev_3d_note(), &
      '', &
      '| STATEV | name | plane | unit | admissible | description |', &
      '|---|---|---|---|---|---|'
    do slot = 1, umat_nstatv_3d(umat_planes)
      call locate(slot, .true., i, k)
      v = statevar_3d(i)
      write (output_unit, '(a)') '| ' // format_integer(slot) // ' | `' // trim(v%name) // '` | ' // &
        plane_column(v%per_plane, k) // ' | ' // trim(v%unit) // ' | ' // &
        format_statevar_range(i) // ' | ' // trim(v%description) // ' |'
    end do
  end subroutine print_markdown

end program interlock_query
