!> Generic checks over everything that is registered: every end kind (the
!> factory's list) and every material law (the words the schema allows for
!> &material law), alone and with the options that change the equations
!> (compression = 'none', damping, a fluid with a current, the force and
!> motion histories). Each
!> combination is built from a configuration, as a user's case is, and must
!> (1) solve its statics, (2) run with the energy ledger closed to the Newton
!> tolerance (5e-11 of its largest energy), and (3) have the analytic Jacobian of its time step agree with
!> central differences. A new end kind or law registered in the factory or the
!> schema is covered here without a new test.
module suite_registry
   use xcable_core_kinds, only: dp
   use xcable_testing, only: error_type, unittest_type, new_unittest, check
   use xcable_core_strings, only: str
   use xcable_io_config, only: case_config
   use xcable_io_schema, only: schema_entry, schema_table, find_entry
   use xcable_ends_factory, only: end_kinds
   use xcable_material_law, only: tanh_law
   use xcable_model_rod, only: rod_kl, rod_ku
   use xcable_driver_simulation, only: simulation
   use xcable_fdcheck, only: check_jacobian
   use suite_rod_statics, only: statics_config
   use, intrinsic :: iso_fortran_env, only: output_unit
   implicit none
   private
   public :: collect_registry, scene_config, variants

contains

   subroutine collect_registry(tests)
      type(unittest_type), allocatable, intent(out) :: tests(:)
      tests = [new_unittest('every_end_kind_and_law', test_every)]
   end subroutine collect_registry

   !> A 10 m line on 21 nodes, end a fixed at the origin, end b of the given
   !> kind (and variant), with the given law and options.
   function scene_config(kind, variant, law, compression, damping, fluid) result(c)
      character(*), intent(in) :: kind, variant, law, compression
      real(dp), intent(in) :: damping
      logical, intent(in) :: fluid
      type(case_config) :: c
      type(tanh_law) :: tanh
      integer :: k
      c = statics_config(21)
      c%length = 10
      c%law = law
      c%compression = compression
      c%damping = damping
      c%energy = .true.
      c%interval = 0
      c%dt = 5.0e-4_dp
      c%t_end = 0.02_dp
      c%newton_tol = 1.0e-11_dp
      if (law == 'table') then
         c%material_table_rows = 30
         c%material_table_strain(1:30) = [(-0.5_dp + 0.8_dp*(k - 1)/29, k=1, 30)]
         c%material_table_tension(1:30) = tanh%tension(c%material_table_strain(1:30))
      end if
      if (law == 'linear') c%ea = 4.0e5_dp
      if (fluid) then
         c%fluid_density = 1025
         c%cd_normal = 1.2_dp
         c%cd_tangential = 0.05_dp
         c%ca_normal = 1
         c%current_x = 0.4_dp
         c%current_z = 0.1_dp
         ! The surface across the line (end b at -1.5 m), the air above it.
         c%surface_z = -0.7_dp
         c%air_density = 1.225_dp
         ! A sloping seabed the sagging line rests on, with friction.
         c%seabed_depth = 1.2_dp
         c%seabed_slope_x = -0.1_dp
         c%seabed_stiffness = 1.0e6_dp
         c%mu_axial = 0.5_dp
         c%mu_lateral = 0.8_dp
         ! Slip regularised over 0.5 m/s: the central differences' steps (1e-6 m over a 0.5 ms
         ! step, 2e-3 m/s) stay well inside it.
         c%slip_velocity = 0.5_dp
         ! The contact's damping acts on the fraction of a cell below the bottom, whose slope jumps
         ! where a cell's end touches: central differences within a step of such a cell are not a
         ! derivative. A tenth of the default keeps that error (1.2e-6 of the row scale with the
         ! default) below the tolerance; suite seabed checks the derivatives away from the jumps.
         c%seabed_damping = 3.0e4_dp
      end if
      c%end_b%kind = kind
      c%given = ''
      select case (kind)
      case ('fixed')
         c%end_b%x = 9.6_dp
         c%end_b%z = -1.5_dp
         c%given = 'end_b%x end_b%z'
      case ('motion')
         c%end_b%x = 9.6_dp
         c%end_b%z = -1.5_dp
         c%given = 'end_b%x end_b%z'
         c%end_b%motion = variant
         if (variant == 'harmonic') then
            c%end_b%amplitude = 0.05_dp
            c%end_b%period = 0.03_dp
            c%end_b%direction_x = 0.6_dp
            c%end_b%direction_z = 0.8_dp
         else
            c%end_b%table_rows = 3
            c%end_b%table_time(1:3) = [0.0_dp, 0.01_dp, 0.02_dp]
            c%end_b%table_x(1:3) = [0.0_dp, 0.03_dp, -0.01_dp]
            c%end_b%table_z(1:3) = [0.0_dp, -0.02_dp, 0.04_dp]
         end if
      case ('force')
         c%end_b%force_x = 400
         c%end_b%force_z = -150
         c%end_b%history = variant
         if (variant == 'ramp') c%end_b%ramp_time = 0.015_dp
         if (variant == 'table') then
            c%end_b%table_rows = 3
            c%end_b%table_time(1:3) = [0.0_dp, 0.01_dp, 0.02_dp]
            c%end_b%table_x(1:3) = [400.0_dp, 300.0_dp, 500.0_dp]
            c%end_b%table_z(1:3) = [-150.0_dp, -100.0_dp, -250.0_dp]
         end if
      case ('mass')
         c%end_b%mass = 20
      case ('spring')
         ! The anchor beyond the line's reach at rest: the spring stretches it (tanh law: 0.4 %).
         c%end_b%x = 10.6_dp
         c%end_b%z = -1.8_dp
         c%given = 'end_b%x end_b%z'
         c%end_b%stiffness = 3.0e3_dp
         if (variant == 'damped') then
            c%end_b%damping = 150
            c%end_b%rest_length = 0.4_dp
            c%end_b%mass = 2
         end if
      end select
   end function scene_config

   !> The case c as a line of three segments (3, 4 and 3 m of its 10 m): the first with c's
   !> law, three times as dense and twice as stiff in bending; the second a linear rope of EA
   !> 2e5 N with damping 100 N s and a larger drag; the third the tanh law on a thinner line.
   !> Every joint a node of the 21. (A segment that cannot push is left to suite segments:
   !> the statics of a free end hanging onto the bottom with compression = 'none' fails, with
   !> or without segments.)
   function in_segments(c0) result(c)
      type(case_config), intent(in) :: c0
      type(case_config) :: c
      c = c0
      c%segment_count = 3
      c%segments(1:3)%length = [3.0_dp, 4.0_dp, 3.0_dp]
      c%segments(1)%density = 3*c%density
      c%segments(1)%bending_stiffness = 2*acos(-1.0_dp)*c%young*c%diameter**4/64
      c%segments(2)%law = 'linear'
      c%segments(2)%ea = 2.0e5_dp
      c%segments(2)%damping = 100
      c%segments(2)%cd_normal = 2.5_dp
      c%segments(3)%law = 'tanh'
      c%segments(3)%diameter = 0.8_dp*c%diameter
      c%given = c%given//' segment_1%length segment_1%density segment_1%bending_stiffness segment_2%length '// &
                'segment_2%law segment_2%ea segment_2%damping segment_2%cd_normal '// &
                'segment_3%length segment_3%law segment_3%diameter'
   end function in_segments

   !> The variants of an end kind that change its equations.
   function variants(kind) result(v)
      character(*), intent(in) :: kind
      character(len=8), allocatable :: v(:)
      select case (kind)
      case ('force')
         v = [character(len=8) :: 'constant', 'ramp', 'table']
      case ('motion')
         v = [character(len=8) :: 'harmonic', 'table']
      case ('spring')
         ! 'plain': rest length 0, no dashpot; 'damped': rest length, dashpot and a point mass.
         v = [character(len=8) :: 'plain', 'damped']
      case default
         v = [character(len=8) :: '-']
      end select
   end function variants

   subroutine test_every(error)
      type(error_type), allocatable, intent(out) :: error
      type(schema_entry), allocatable :: t(:)
      character(len=16), allocatable :: laws(:)
      character(len=8), allocatable :: vs(:)
      character(len=16), allocatable :: kinds(:)
      character(len=96) :: words
      real(dp) :: worst_drift, worst_jacobian, drift, jac, worst_static, jac_static
      integer :: i, j, k, m, n_cases
      kinds = end_kinds()
      t = schema_table()
      words = t(find_entry(t, 'material', 'law'))%choices
      laws = split_words(words)
      call check(error, size(laws) >= 3, 'the schema lists '//str(size(laws))//' laws: "'//trim(words)//'"')
      if (allocated(error)) return
      worst_drift = 0
      worst_jacobian = 0
      worst_static = 0
      n_cases = 0
      do i = 1, size(end_kinds())
         vs = variants(trim(kinds(i)))
         do k = 1, size(vs)
            do j = 1, size(laws)
               do m = 1, 5
                  associate (comp => merge('none', 'law ', m == 2), damp => merge(300.0_dp, 0.0_dp, m == 3))
                     if (m == 5) then
                        ! A line of three segments (the law's, a linear rope that cannot push, a
                        ! lighter tanh rope), in water on the seabed.
                        call one_case(in_segments(scene_config(trim(kinds(i)), trim(vs(k)), trim(laws(j)), &
                                                               'law', 0.0_dp, .true.)), &
                                      trim(kinds(i))//' '//trim(vs(k))//', law '//trim(laws(j))//', in three '// &
                                      'segments, in water', drift, jac, jac_static, error)
                     else
                        call one_case(scene_config(trim(kinds(i)), trim(vs(k)), trim(laws(j)), trim(comp), damp, &
                                                   m == 4), &
                                      trim(kinds(i))//' '//trim(vs(k))//', law '//trim(laws(j))//', compression '// &
                                      trim(comp)//', damping '//str(damp)//merge(', in water', '          ', m == 4), &
                                      drift, jac, jac_static, error)
                     end if
                  end associate
                  if (allocated(error)) return
                  worst_drift = max(worst_drift, drift)
                  worst_jacobian = max(worst_jacobian, jac)
                  worst_static = max(worst_static, jac_static)
                  n_cases = n_cases + 1
               end do
            end do
         end do
      end do
      write (output_unit, '(4x,i0,a,es9.2,a,es9.2,a,es9.2)') n_cases, ' combinations of end kind, law and options: '// &
         'largest ledger drift', worst_drift, ', largest Jacobian deviation / row scale: step', worst_jacobian, &
         ', statics', worst_static
   end subroutine test_every

   !> Statics, a run with the ledger, then the step Jacobian at a perturbed state, and the
   !> statics' Jacobian there.
   subroutine one_case(c, what, drift, worst, worst_static, error)
      type(case_config), intent(in) :: c
      character(*), intent(in) :: what
      real(dp), intent(out) :: drift, worst, worst_static
      type(error_type), allocatable, intent(out) :: error
      type(simulation) :: sim
      real(dp), allocatable :: x(:)
      integer :: k, np
      drift = 0
      worst = 0
      worst_static = 0
      call sim%prepare(c, error)
      if (allocated(error)) then
         error%message = what//': '//error%message
         return
      end if
      ! Stir the line so that every term moves.
      np = size(sim%rod%pieces(1)%v, 2)
      do k = 2, np - 1
         sim%rod%pieces(1)%v(:, k) = sim%rod%pieces(1)%v(:, k) + 0.3_dp*[sin(1.7_dp*k), cos(2.3_dp*k)]
      end do
      call sim%run(error=error)
      if (allocated(error)) then
         error%message = what//': '//error%message
         return
      end if
      ! The ledger's drift over the largest energy of the initial state (the run's own figure is
      ! over the initial strain energy, which is tiny in a slack line of a stiff linear law).
      associate (en => sim%rod%history%energy)
         drift = maxval(abs(en(7, 0:sim%rod%history%n) - en(7, 0)))/maxval(abs(en(1:4, 0)))
      end associate
      call check(error, drift < 5.0e-11_dp, what//': the ledger drifts by '//str(drift)//' of the largest energy')
      if (allocated(error)) return
      ! The step from the final state, at a perturbed guess.
      associate (run => sim%rod%pieces(1))
         run%problem%t0 = sim%rod%t
         run%problem%dt = c%dt
         run%problem%theta = c%theta
         call run%problem%piece%prepare_step(run%r, run%v)
         x = reshape(run%r + c%dt*run%v, [2*np])
         do k = 1, size(x)
            x(k) = x(k) + 1.0e-3_dp*sin(0.7_dp*k)
         end do
         call check_jacobian(run%problem, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*np), 1.0e-6_dp, worst, error)
         if (allocated(error)) then
            error%message = 'step: '//error%message
         else if (c%compression == 'law') then
            ! The statics' system at the same positions (an end's force at rest, d/dx only; not
            ! under compression = 'none', whose tension has a kink at zero strain that the
            ! perturbed state's slack cells straddle: central differences across it are not a
            ! derivative).
            run%problem%dt = 0
            call check_jacobian(run%problem, x, rod_kl, rod_ku, spread(1.0e-6_dp, 1, 2*np), 1.0e-6_dp, &
                                worst_static, error)
            if (allocated(error)) error%message = 'statics: '//error%message
         end if
      end associate
      if (allocated(error)) error%message = what//': '//error%message
   end subroutine one_case

   !> Words separated by blanks.
   function split_words(text) result(words)
      character(*), intent(in) :: text
      character(len=16), allocatable :: words(:)
      integer :: i, start
      allocate (words(0))
      start = 0
      do i = 1, len(text) + 1
         if (i > len(text)) then
            if (start > 0) words = [character(len=16) :: words, text(start:i - 1)]
         else if (text(i:i) == ' ' .or. text(i:i) == ',') then
            if (start > 0) words = [character(len=16) :: words, text(start:i - 1)]
            start = 0
         else if (start == 0) then
            start = i
         end if
      end do
      words = [(strip(words(i)), i=1, size(words))]
   contains
      pure function strip(w) result(s)
         character(*), intent(in) :: w
         character(len=16) :: s
         integer :: a, b
         a = verify(w, "' ")
         b = verify(w, "' ", back=.true.)
         s = ''
         if (a > 0) s = w(a:b)
      end function strip
   end function split_words
end module suite_registry
