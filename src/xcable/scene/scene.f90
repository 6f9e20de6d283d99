!> The scene a case describes: the cable (its material, weight and bending
!> stiffness), its two ends, how its static state is defined, and the break.
!> Built once from a validated case; the models and the driver read it.
!>
!> The static state is defined either by the two end positions (every held
!> end at its point, loaded ends where the statics puts them), or, in the
!> paper's symmetric case (&static tension, both ends fixed and no position
!> given for end b), by the end tension: end b then lies at the height of
!> end a, at the span the tension gives.
module xcable_scene_scene
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type, fatal_error, prefix_error, stat_input
   use xcable_core_strings, only: str
   use xcable_io_config, only: case_config
   use xcable_material_law, only: material_law
   use xcable_material_factory, only: new_case_law
   use xcable_ends_end_condition, only: end_condition
   use xcable_ends_factory, only: new_end
   use xcable_loads_load, only: load_slot
   use xcable_loads_point, only: point_body
   use xcable_loads_factory, only: case_loads
   implicit none
   private
   public :: scene_type, section_type, scene_from_config, scene_grid, set_break, section_cells, section_at, sections_on

   !> One segment of the line, between arc lengths s_start and s_end from end a: its own
   !> material, weight, stiffnesses, loads and breaking load. A line of one segment has one
   !> section, whose values are also the scene's own (law, mass, weight, ei, gip, loads).
   type :: section_type
      !> Its arc lengths from end a, m.
      real(dp) :: s_start = 0, s_end = 0
      !> Its nodes, end nodes included (0: a share of the line's by length; scene_grid).
      integer :: nodes = 0
      !> Mass and weight (net of the loads' lift) per unstretched length, kg/m and N/m.
      real(dp) :: mass = 0, weight = 0
      !> Bending and torsional stiffness, N m^2.
      real(dp) :: ei = 0, gip = 0
      !> Internal damping of the law, N s.
      real(dp) :: damping = 0
      !> Minimum breaking load, N (0: none).
      real(dp) :: mbl = 0
      !> Tension-strain law (with the compression option applied).
      class(material_law), allocatable :: law
      !> Distributed loads on it (none: not allocated).
      type(load_slot), allocatable :: loads(:)
   end type section_type

   !> A scene.
   type :: scene_type
      !> Namelist file of the case (for messages).
      character(:), allocatable :: source
      !> Unstretched length, m; mass and weight per unstretched length, kg/m and N/m.
      real(dp) :: length = 60, mass = 0, weight = 0
      !> Gravity, m/s^2; bending stiffness EI, N m^2.
      real(dp) :: gravity = 9.81_dp, ei = 0
      !> Torsional stiffness GIp of the 3-D model, N m^2 (0: EI / 1.4).
      real(dp) :: gip = 0
      !> Tension-strain law (with the compression option applied).
      class(material_law), allocatable :: law
      !> End a (s = 0) and end b (s = L).
      class(end_condition), allocatable :: end_a, end_b
      !> The paper's symmetric case: statics from the end tension.
      logical :: from_tension = .false.
      !> End tension of the symmetric case, N.
      real(dp) :: tension = 0
      !> Whether and where (arc length from end a, m) the cable breaks, when it
      !> starts (s) and the duration of the force ramp (s).
      logical :: breaks = .false.
      real(dp) :: s_break = 0, break_time = 0, t_break = 0
      !> The break by tension (&rupture criterion = 'tension'): the line parts where and when a
      !> cell's tension first reaches mbl (N). breaks, s_break and break_time are then set by the
      !> driver once it has found the crossing (driver/simulation.f90).
      logical :: by_tension = .false.
      real(dp) :: mbl = 0
      !> Whether the break is at end a, at end b, or inside the cable.
      logical :: break_at_a = .false., break_at_b = .false.
      !> Distributed loads (none: not allocated). The weight above is net of their lift.
      type(load_slot), allocatable :: loads(:)
      !> The segments of the line from end a (one for a uniform line: the values above).
      type(section_type), allocatable :: sections(:)
      !> Bodies at joints of the segments or at an end that is not held (&point_k: clump weights,
      !> buoys).
      type(point_body), allocatable :: points(:)
   contains
      !> Whether the break splits the cable in two.
      procedure :: interior_break
   end type scene_type

contains

   !> Whether the break is inside the cable (two pieces).
   pure logical function interior_break(self)
      !> Scene.
      class(scene_type), intent(in) :: self
      interior_break = self%breaks .and. .not. (self%break_at_a .or. self%break_at_b)
   end function interior_break

   !> Build the scene of a validated case (zero area, EI or EA derived as the reader does).
   subroutine scene_from_config(config, scene, error)
      !> Validated case.
      type(case_config), intent(in) :: config
      !> The scene.
      type(scene_type), intent(out) :: scene
      !> Error (stat_input) naming what is inconsistent.
      type(error_type), allocatable, intent(out) :: error
      type(case_config) :: seg
      integer :: k, j
      scene%source = config%source
      allocate (scene%sections(config%segments_of_line()))
      do k = 1, size(scene%sections)
         seg = config%segment_case(k)
         call build_section(seg, scene%sections(k), error)
         if (allocated(error)) then
            if (config%segment_count == 0) then
               call prefix_error(error, config%source//': &material: ')
            else
               call prefix_error(error, config%source//': &segment_'//str(k)//': ')
            end if
            return
         end if
         if (k > 1) scene%sections(k)%s_start = scene%sections(k - 1)%s_end
         scene%sections(k)%s_end = scene%sections(k)%s_start + seg%length
         if (config%segment_count > 0) scene%sections(k)%nodes = config%segments(k)%nodes
      end do
      scene%length = scene%sections(size(scene%sections))%s_end
      if (config%segment_count == 0) scene%length = config%length
      scene%gravity = config%gravity
      ! The scene's own material is its first section's (the whole line's without segments).
      ! On a line of segments the scene's mass and weight are the means over the line (what a
      ! uniform first guess takes), and its loads those of every section, each on its part.
      associate (first => scene%sections(1))
         allocate (scene%law, source=first%law)
         scene%mass = first%mass
         scene%weight = first%weight
         scene%ei = first%ei
         scene%gip = first%gip
         if (size(scene%sections) == 1) then
            if (allocated(first%loads)) then
               allocate (scene%loads(size(first%loads)))
               do k = 1, size(first%loads)
                  allocate (scene%loads(k)%load, source=first%loads(k)%load)
               end do
            end if
         end if
      end associate
      if (size(scene%sections) > 1) then
         scene%mass = sum(scene%sections%mass*(scene%sections%s_end - scene%sections%s_start))/scene%length
         scene%weight = sum(scene%sections%weight*(scene%sections%s_end - scene%sections%s_start))/scene%length
         allocate (scene%loads(0))
         do k = 1, size(scene%sections)
            associate (sec => scene%sections(k))
               if (.not. allocated(sec%loads)) cycle
               do j = 1, size(sec%loads)
                  scene%loads = [scene%loads, sec%loads(j)]
                  if (k > 1) scene%loads(size(scene%loads))%s_from = sec%s_start
                  if (k < size(scene%sections)) scene%loads(size(scene%loads))%s_to = sec%s_end
               end do
            end associate
         end do
      end if

      ! Bodies at the joints: in the water (the fluid's density and current) if there is water.
      allocate (scene%points(config%point_count))
      do k = 1, config%point_count
         associate (p => scene%points(k), pc => config%points(k))
            p%s = 0
            if (pc%joint > 0) p%s = scene%sections(pc%joint)%s_end
            p%mass = pc%mass
            p%volume = pc%volume
            p%ca = pc%ca
            p%cd = pc%cd
            p%area = pc%area
            p%gravity = config%gravity
            p%density = max(config%fluid_density, 0.0_dp)
            if (p%density > 0) then
               p%current = [config%current_x, config%current_y, config%current_z]
               p%surface = config%surface_z
            end if
         end associate
      end do

      call new_end(config%end_a, 'end_a', scene%end_a, error)
      if (allocated(error)) then
         call prefix_error(error, config%source//': &end_a: ')
         return
      end if
      call new_end(config%end_b, 'end_b', scene%end_b, error)
      if (allocated(error)) then
         call prefix_error(error, config%source//': &end_b: ')
         return
      end if

      ! The paper's symmetric case: both ends fixed and no position given for end b.
      scene%from_tension = trim(config%end_a%kind) == 'fixed' .and. trim(config%end_b%kind) == 'fixed' .and. &
                           .not. (config%is_given('end_b', 'x') .or. config%is_given('end_b', 'y') .or. &
                                  config%is_given('end_b', 'z'))
      scene%tension = config%tension
      if (scene%from_tension) then
         if (scene%law%strain_at(config%tension) > config%strain_max) then
            call fatal_error(error, config%source//': &static: tension = '//str(config%tension)//': needs strain '// &
                             str(scene%law%strain_at(config%tension))//', above the range of the '//trim(config%law)// &
                             ' law (strain_max = '//str(config%strain_max)//', tension '// &
                             str(scene%law%tension(config%strain_max))//' N)', stat_input)
            return
         end if
      end if
      if (scene%from_tension .and. config%tension <= 1.001_dp*0.5_dp*scene%weight*scene%length) then
         call fatal_error(error, config%source//': &static: tension = '//str(config%tension)// &
                          ': must exceed half the weight of the cable, w0 L / 2 = '// &
                          str(0.5_dp*scene%weight*scene%length)//' N (tensions are in N: 180 kN is 180000)', stat_input)
         return
      end if

      scene%t_break = config%t_break
      scene%by_tension = config%break_enabled .and. trim(config%break_criterion) == 'tension'
      if (scene%by_tension) then
         ! The line's MBL, or on a line of segments the smallest a segment gives.
         scene%mbl = config%mbl
         if (size(scene%sections) > 1) scene%mbl = minval(scene%sections%mbl, mask=scene%sections%mbl > 0)
      else if (config%break_enabled) then
         call set_break(scene, config%s_break, config%break_time, error)
      end if
   end subroutine scene_from_config

   !> One section from the case as its segment sees it (zero area, EI or EA derived as the
   !> reader does): its law, mass, weight net of its loads' lift, stiffnesses, damping, loads
   !> and breaking load; its arc lengths are set by the caller.
   subroutine build_section(config, section, error)
      !> The case as the segment sees it (case_config%segment_case).
      type(case_config), intent(in) :: config
      !> The section.
      type(section_type), intent(out) :: section
      !> Error from the law.
      type(error_type), allocatable, intent(out) :: error
      real(dp), parameter :: pi = acos(-1.0_dp)
      real(dp) :: area, ea
      integer :: k
      area = config%area
      if (area == 0) area = 0.25_dp*pi*config%diameter**2
      section%ei = config%bending_stiffness
      if (section%ei == 0) section%ei = config%young*pi*config%diameter**4/64
      ea = config%ea
      if (ea == 0) ea = config%young*area
      call new_case_law(config, ea, section%law, error)
      if (allocated(error)) return
      section%mass = config%density*area
      section%weight = section%mass*config%gravity
      section%gip = config%gip
      if (section%gip == 0) section%gip = section%ei/1.4_dp
      section%damping = config%damping
      section%mbl = config%mbl
      ! Distributed loads, one line each; their lift (buoyancy) comes off the weight.
      call case_loads(config, area, section%loads)
      do k = 1, size(section%loads)
         section%weight = section%weight - section%loads(k)%load%lift()
      end do
   end subroutine build_section

   !> The break of a scene: at arc length s_break (m; negative: L, the end b) from end a, starting
   !> at time (s), with the scene's ramp t_break. Error (stat_input) for a break at an end that is
   !> not held.
   subroutine set_break(scene, s_break, time, error)
      !> Scene.
      type(scene_type), intent(inout) :: scene
      !> Where (m) and when (s) the break starts.
      real(dp), intent(in) :: s_break, time
      !> Error naming the end.
      type(error_type), allocatable, intent(out) :: error
      real(dp) :: rel
      scene%breaks = .true.
      scene%s_break = s_break
      if (scene%s_break < 0) scene%s_break = scene%length
      scene%break_time = time
      rel = scene%s_break/scene%length
      scene%break_at_a = rel <= 1.0e-12_dp
      scene%break_at_b = rel >= 1 - 1.0e-12_dp
      if (scene%break_at_a .and. .not. scene%end_a%held()) then
         call fatal_error(error, scene%source//': &rupture: s_break = '//str(scene%s_break)//': end a is '// &
                          scene%end_a%kind()//', not held, so nothing breaks there', stat_input)
         return
      end if
      if (scene%break_at_b .and. .not. scene%end_b%held()) then
         call fatal_error(error, scene%source//': &rupture: s_break = '//str(scene%s_break)//': end b is '// &
                          scene%end_b%kind()//', not held, so nothing breaks there', stat_input)
         return
      end if
   end subroutine set_break

   !> Node arc lengths: uniform on [0, L], or, with a break inside the cable,
   !> uniform on each side of it with the break point a node (the nodes split
   !> in proportion to the lengths of the two sides, at least two cells each).
   !> On a line of segments every joint is a node too: each part between two
   !> joints (or a joint and the break) is uniform, with the cells of its segment
   !> (nodes given per segment) or a share of all cells by length.
   subroutine scene_grid(scene, nodes, s, break_node)
      !> Scene.
      type(scene_type), intent(in) :: scene
      !> Number of nodes.
      integer, intent(in) :: nodes
      !> Arc lengths, m.
      real(dp), allocatable, intent(out) :: s(:)
      !> Node at the break (0 without an interior break).
      integer, intent(out) :: break_node
      integer :: k, cells_a, cells
      allocate (s(nodes))
      cells = nodes - 1
      break_node = 0
      if (allocated(scene%sections)) then
         if (size(scene%sections) > 1) then
            call segment_grid(scene, nodes, s, break_node)
            return
         end if
      end if
      if (scene%interior_break() .and. cells >= 4) then
         cells_a = min(max(nint(cells*scene%s_break/scene%length), 2), cells - 2)
         break_node = cells_a + 1
         do k = 1, break_node
            s(k) = scene%s_break*real(k - 1, dp)/cells_a
         end do
         do k = break_node + 1, nodes
            s(k) = scene%s_break + (scene%length - scene%s_break)*real(k - break_node, dp)/(cells - cells_a)
         end do
      else
         do k = 1, nodes
            s(k) = scene%length*real(k - 1, dp)/cells
         end do
      end if
   end subroutine scene_grid

   !> The section at arc length s from end a (m): the first whose end lies beyond s.
   pure integer function section_at(scene, s)
      !> Scene.
      type(scene_type), intent(in) :: scene
      !> Arc length, m.
      real(dp), intent(in) :: s
      do section_at = 1, size(scene%sections) - 1
         if (s < scene%sections(section_at)%s_end) return
      end do
      section_at = size(scene%sections)
   end function section_at

   !> The last cell of each section on the node arc lengths s (scene_grid's) of the part of
   !> the line s(1) .. s(n): 0 for a section before the part, n - 1 for one beyond it.
   pure function section_cells(scene, s) result(last)
      !> Scene.
      type(scene_type), intent(in) :: scene
      !> Node arc lengths of the piece, m.
      real(dp), intent(in) :: s(:)
      integer :: last(size(scene%sections))
      integer :: j, c
      do j = 1, size(scene%sections)
         last(j) = 0
         do c = 1, size(s) - 1
            if (0.5_dp*(s(c) + s(c + 1)) < scene%sections(j)%s_end) last(j) = c
         end do
      end do
      last(size(last)) = size(s) - 1
   end function section_cells

   !> The sections with cells on the part of the line whose nodes have the arc lengths s, in
   !> order (section_cells' last cells of them increase strictly).
   pure function sections_on(scene, s) result(keep)
      !> Scene.
      type(scene_type), intent(in) :: scene
      !> Node arc lengths of the piece, m.
      real(dp), intent(in) :: s(:)
      integer, allocatable :: keep(:), last(:)
      integer :: j, prev
      last = section_cells(scene, s)
      allocate (keep(0))
      prev = 0
      do j = 1, size(last)
         if (last(j) > prev) keep = [keep, j]
         prev = max(prev, last(j))
      end do
   end function sections_on

   !> scene_grid on a line of segments: the parts between the joints and the break.
   subroutine segment_grid(scene, nodes, s, break_node)
      type(scene_type), intent(in) :: scene
      integer, intent(in) :: nodes
      real(dp), intent(inout) :: s(:)
      integer, intent(out) :: break_node
      real(dp), allocatable :: bounds(:), part(:)
      integer, allocatable :: cells(:), owner(:)
      integer :: m, j, k, node, spare, big
      real(dp) :: tol
      tol = 1.0e-9_dp*scene%length
      bounds = [scene%sections%s_start, scene%length]
      owner = [(j, j=1, size(scene%sections))]
      break_node = 0
      ! The break splits the part it falls in (at a joint it is that joint).
      if (scene%interior_break()) then
         if (all(abs(bounds - scene%s_break) > tol)) then
            do j = 1, size(owner)
               if (scene%s_break > bounds(j) .and. scene%s_break < bounds(j + 1)) exit
            end do
            bounds = [bounds(1:j), scene%s_break, bounds(j + 1:)]
            owner = [owner(1:j), owner(j:)]
         end if
      end if
      m = size(bounds) - 1
      part = bounds(2:m + 1) - bounds(1:m)
      allocate (cells(m))
      if (all(scene%sections%nodes > 0)) then
         ! The segments' own cells; a part of a segment its share by length.
         do j = 1, m
            associate (sec => scene%sections(owner(j)))
               cells(j) = max(1, nint((sec%nodes - 1)*part(j)/(sec%s_end - sec%s_start)))
            end associate
         end do
         do j = 1, m - 1
            if (owner(j) == owner(j + 1)) then
               cells(j + 1) = max(1, scene%sections(owner(j))%nodes - 1 - cells(j))
            end if
         end do
      else
         do j = 1, m
            cells(j) = max(2, nint((nodes - 1)*part(j)/scene%length))
         end do
      end if
      ! The total to nodes - 1: the largest parts give or take the difference.
      spare = (nodes - 1) - sum(cells)
      do while (spare /= 0)
         big = maxloc(part/cells, 1)
         if (spare < 0) big = maxloc(merge(cells, 0, cells > 2), 1)
         if (cells(big) + sign(1, spare) < 1) exit
         cells(big) = cells(big) + sign(1, spare)
         spare = spare - sign(1, spare)
      end do
      node = 1
      s(1) = 0
      do j = 1, m
         do k = 1, cells(j)
            s(node + k) = bounds(j) + part(j)*real(k, dp)/cells(j)
         end do
         node = node + cells(j)
         s(node) = bounds(j + 1)
         if (scene%interior_break()) then
            if (abs(bounds(j + 1) - scene%s_break) <= tol) break_node = node
         end if
      end do
   end subroutine segment_grid
end module xcable_scene_scene
