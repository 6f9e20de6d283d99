!> Cost per node and step of the 3-D rod against the planar rod (issue 15).
!>
!>   fpm run --example cost3d --profile release -- [nodes=241] [steps=200] [rounds=7]
!>
!> The same planar scene in both models: the paper's cable, 60 m, held at end a,
!> end b released from 180 kN (force ramp of 5 ms), started from the straight
!> stretched line at rest, steps of 20 microseconds (Courant number about 0.8
!> at 241 nodes), full Newton to a scaled update of 1e-9 from the guess R + dt V.
!> Each round times the planar run and then the 3-D run (CPU time of this
!> process); it prints the medians over the rounds of the time per node-step,
!> of the paired ratio 3-D / planar, and the Newton iterations per step.
program cost3d
   use xcable_core_kinds, only: dp
   use xcable_core_error, only: error_type
   use xcable_material_law, only: tanh_law
   use xcable_ends_fixed, only: fixed_end
   use xcable_ends_force, only: force_end
   use xcable_model_rod, only: rod_problem, rod_kl, rod_ku
   use xcable_driver_rod3d_run, only: rod3d_run
   use xcable_solver_newton, only: newton_workspace, newton_options, newton_report, newton_solve
   use, intrinsic :: iso_fortran_env, only: output_unit, error_unit
   implicit none
   real(dp), parameter :: len = 60.0_dp, m = 2.239_dp, g = 9.81_dp, ei = 70.6_dp, gip = 47.0_dp
   real(dp), parameter :: tension = 1.8e5_dp, dt = 2.0e-5_dp
   integer :: nodes, steps, rounds, r, it2, it3
   real(dp), allocatable :: t2(:), t3(:), ratio(:)
   character(len=64) :: arg
   integer :: i
   nodes = 241
   steps = 200
   rounds = 7
   do i = 1, command_argument_count()
      call get_command_argument(i, arg)
      if (index(arg, 'nodes=') == 1) read (arg(7:), *) nodes
      if (index(arg, 'steps=') == 1) read (arg(7:), *) steps
      if (index(arg, 'rounds=') == 1) read (arg(8:), *) rounds
   end do
   allocate (t2(rounds), t3(rounds), ratio(rounds))
   do r = 1, rounds
      t2(r) = time_planar(it2)
      t3(r) = time_3d(it3)
      ratio(r) = t3(r)/t2(r)
   end do
   write (output_unit, '(a,i0,a,i0,a,i0,a)') 'cost per node-step, ', nodes, ' nodes, ', steps, ' steps, ', rounds, ' rounds'
   write (output_unit, '(a,f8.3,a,f6.2,a)') '  planar rod: ', 1.0e6_dp*median(t2)/(nodes*steps), ' us (', &
      real(it2, dp)/steps, ' Newton iterations per step)'
   write (output_unit, '(a,f8.3,a,f6.2,a)') '  3-D rod:    ', 1.0e6_dp*median(t3)/(nodes*steps), ' us (', &
      real(it3, dp)/steps, ' Newton iterations per step)'
   write (output_unit, '(a,f6.2)') '  median paired ratio 3-D / planar: ', median(ratio)

contains

   real(dp) function time_planar(iterations) result(seconds)
      integer, intent(out) :: iterations
      type(rod_problem) :: p
      type(newton_workspace) :: work
      type(newton_options) :: options
      type(newton_report) :: report
      type(error_type), allocatable :: error
      real(dp), allocatable :: x(:), r(:, :), v(:, :), v1(:, :)
      real(dp) :: s(nodes), eps, start, finish
      integer :: k, step
      type(tanh_law) :: law
      s = [(len*(k - 1)/(nodes - 1), k=1, nodes)]
      eps = law%strain_at(tension)
      call p%piece%init(s, m, m*g, ei, g, 1.0_dp, law, fixed_end(point=[0.0_dp, 0.0_dp]), &
                        force_end(history='ramp', force0=[tension, 0.0_dp], duration=0.005_dp), tension)
      call work%init(2*nodes, rod_kl, rod_ku, spread(p%piece%length_ref, 1, 2*nodes))
      options%tolerance = 1.0e-9_dp
      allocate (r(2, nodes), v(2, nodes), v1(2, nodes))
      r(1, :) = s*(1 + eps)
      r(2, :) = 0
      v = 0
      iterations = 0
      call cpu_time(start)
      do step = 1, steps
         call p%piece%prepare_step(r, v)
         p%dt = dt
         p%t0 = (step - 1)*dt
         x = reshape(r + dt*v, [2*nodes])
         call newton_solve(p, x, work, options, report, error)
         if (allocated(error)) then
            write (error_unit, '(a)') 'planar: '//error%message
            error stop 1
         end if
         iterations = iterations + report%iterations
         call p%piece%new_velocity(reshape(x, [2, nodes]), dt, 0.5_dp, v1)
         r = reshape(x, [2, nodes])
         v = v1
      end do
      call cpu_time(finish)
      seconds = finish - start
   end function time_planar

   real(dp) function time_3d(iterations) result(seconds)
      integer, intent(out) :: iterations
      type(rod3d_run) :: run
      type(error_type), allocatable :: error
      real(dp) :: s(nodes), eps, start, finish
      integer :: k, step
      type(tanh_law) :: law
      s = [(len*(k - 1)/(nodes - 1), k=1, nodes)]
      eps = law%strain_at(tension)
      call run%problem%piece%init(s, m, m*g, ei, gip, g, 1.0_dp, law, fixed_end(point=[0.0_dp, 0.0_dp]), &
                                  force_end(history='ramp', force0=[tension, 0.0_dp], duration=0.005_dp), tension, error)
      if (allocated(error)) error stop 1
      call run%init(1.0e-9_dp)
      do k = 1, nodes
         run%x(3*k - 2:3*k) = [s(k)*(1 + eps), 0.0_dp, 0.0_dp]
      end do
      call run%start(run%x, run%v, 0.0_dp)
      call cpu_time(start)
      do step = 1, steps
         call run%step(dt, 0.5_dp, error)
         if (allocated(error)) then
            write (error_unit, '(a)') '3-D: '//error%message
            error stop 1
         end if
      end do
      call cpu_time(finish)
      iterations = run%iterations
      seconds = finish - start
   end function time_3d

   real(dp) function median(a)
      real(dp), intent(in) :: a(:)
      real(dp) :: b(size(a)), t
      integer :: i, j
      b = a
      do i = 2, size(b)
         t = b(i)
         j = i - 1
         do while (j >= 1)
            if (b(j) <= t) exit
            b(j + 1) = b(j)
            j = j - 1
         end do
         b(j + 1) = t
      end do
      median = b((size(b) + 1)/2)
   end function median
end program cost3d
