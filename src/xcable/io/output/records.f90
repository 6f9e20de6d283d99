!> The history and the summary of a run in the result file (and the history's gnuplot text).
!> (A submodule of io/output.f90: it sees the result file's type and helpers.)
submodule (xcable_io_output) xcable_io_output_records
   implicit none

contains

   !> Write the history of the run (and its gnuplot text).
   module subroutine result_write_history(self, history, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> One record per accepted step.
      type(run_history), intent(in) :: history
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: group, egroup, scale
      integer :: hdferr, n, i, j, q, unit, ios, n_ends, pos
      logical :: ok
      character(:), allocatable :: header, line
      n = history%n
      n_ends = size(history%end_labels)
      call h5gcreate_f(self%file, 'history', group, hdferr)
      ok = hdferr == 0
      if (ok) then
         call describe_group(self, group, '/history', ok)
         call put_reals(self, group, '/history', 'time', history%time(0:n), ok)
         call put_reals(self, group, '/history', 'dt', history%step(0:n), ok)
         call put_ints(self, group, '/history', 'newton_iterations', history%newton_iterations(0:n), ok)
         call put_ints(self, group, '/history', 'rejected', history%rejected(0:n), ok)
         ! /history/time is the dimension scale of every history dataset.
         call open_scale(group, 'time', 'time', scale, ok)
         call attach(scale, group, 'dt', 0, 'time', ok, fresh=.true.)
         call attach(scale, group, 'newton_iterations', 0, 'time', ok, fresh=.true.)
         call attach(scale, group, 'rejected', 0, 'time', ok, fresh=.true.)
         do j = 1, n_ends
            call h5gcreate_f(group, trim(history%end_labels(j)), egroup, hdferr)
            ok = ok .and. hdferr == 0
            if (hdferr /= 0) cycle
            call describe_group(self, egroup, '/history/'//trim(history%end_labels(j)), ok)
            do q = 1, n_end_quantities
               call put_reals(self, egroup, '/history/'//trim(history%end_labels(j)), trim(end_quantity_names(q)), &
                             history%ends(q, j, 0:n), ok)
               call attach(scale, egroup, trim(end_quantity_names(q)), 0, 'time', ok, fresh=.true.)
            end do
            if (allocated(history%ends_y)) then
               do q = 1, n_end_quantities_y
                  call put_reals(self, egroup, '/history/'//trim(history%end_labels(j)), &
                                trim(end_quantity_names_y(q)), history%ends_y(q, j, 0:n), ok)
                  call attach(scale, egroup, trim(end_quantity_names_y(q)), 0, 'time', ok, fresh=.true.)
               end do
            end if
            call h5gclose_f(egroup, hdferr)
         end do
         if (allocated(history%energy)) then
            call h5gcreate_f(group, 'energy', egroup, hdferr)
            ok = ok .and. hdferr == 0
            if (hdferr == 0) then
               call describe_group(self, egroup, '/history/energy', ok)
               do i = 1, n_energy
                  call put_reals(self, egroup, '/history/energy', trim(energy_names(i)), history%energy(i, 0:n), ok)
                  call attach(scale, egroup, trim(energy_names(i)), 0, 'time', ok, fresh=.true.)
               end do
               call h5gclose_f(egroup, hdferr)
            end if
         end if
         if (allocated(history%measures)) then
            do i = 1, size(history%measures, 1)
               call put_reals(self, group, '/history', trim(history%measure_names(i)), history%measures(i, 0:n), ok)
               call attach(scale, group, trim(history%measure_names(i)), 0, 'time', ok, fresh=.true.)
            end do
         end if
         if (scale >= 0) call h5dclose_f(scale, hdferr)
         call h5gclose_f(group, hdferr)
      end if
      if (.not. ok) then
         call fatal_error(error, "writing /history to '"//self%path//"' failed"//why(self), stat_io)
         return
      end if
      if (.not. allocated(self%text_stem)) return
      open (newunit=unit, file=self%text_stem//'.history.dat', status='replace', action='write', iostat=ios)
      if (ios /= 0) then
         call fatal_error(error, 'cannot create '//self%text_stem//'.history.dat (&output gnuplot)', stat_io)
         return
      end if
      ! Columns 1-4: t, velocity u of end b along the cable (the released end of the
      ! paper's case), tension at end a, Newton iterations; 5-11 the energy ledger
      ! (strain kinetic bending gravity work ledger dissipation) or zeros without it;
      ! then per end: speed, tension of the end cell, |external force| (with the y components
      ! in 3-D); then, with the ledger, the work of the distributed loads (fluid); last, for a
      ! 3-D run, per end: y, vy, force_y.
      header = '# columns: t[s] end_b_u[m/s] end_a_tension[N] newton_iterations E_strain[J] E_kinetic[J] '// &
               'E_bending[J] E_gravity[J] W_end[J] ledger[J] dissipation[J]'
      do j = 1, n_ends
         header = header//' '//trim(history%end_labels(j))//':speed[m/s] '//trim(history%end_labels(j))// &
                  ':tension[N] '//trim(history%end_labels(j))//':force[N]'
      end do
      if (allocated(history%energy)) header = header//' W_loads[J]'
      if (allocated(history%ends_y)) then
         do j = 1, n_ends
            header = header//' '//trim(history%end_labels(j))//':y[m] '//trim(history%end_labels(j))// &
                     ':vy[m/s] '//trim(history%end_labels(j))//':force_y[N]'
         end do
      end if
      if (.not. allocated(history%energy)) header = header//' (no energy ledger)'
      write (unit, '(a)') header
      ! One line per record, as '(3es16.8,i4,7es17.9,<3 n_ends>es16.8[,es17.9][,<3 n_ends>es16.8])' (put_es).
      allocate (character(len=3*16 + 4 + 8*17 + 6*16*n_ends) :: line)
      do i = 0, n
         pos = 1
         call put_es(line, pos, history%time(i), 16, 8)
         call put_es(line, pos, end_b_u(i), 16, 8)
         call put_es(line, pos, history%ends(5, 1, i), 16, 8)
         call put_int(line, pos, history%newton_iterations(i), 4)
         do q = 1, 7
            if (allocated(history%energy)) then
               call put_es(line, pos, history%energy(ledger_columns(q), i), 17, 9)
            else
               call put_es(line, pos, 0.0_dp, 17, 9)
            end if
         end do
         do j = 1, n_ends
            call put_es(line, pos, magnitude(history%ends(3:4, j, i), 2, j, i), 16, 8)
            call put_es(line, pos, history%ends(5, j, i), 16, 8)
            call put_es(line, pos, magnitude(history%ends(6:7, j, i), 3, j, i), 16, 8)
         end do
         if (allocated(history%energy)) call put_es(line, pos, history%energy(8, i), 17, 9)
         if (allocated(history%ends_y)) then
            do j = 1, n_ends
               do q = 1, n_end_quantities_y
                  call put_es(line, pos, history%ends_y(q, j, i), 16, 8)
               end do
            end do
         end if
         write (unit, '(a)') line(1:pos - 1)
      end do
      close (unit)

   contains

      !> Velocity of end b along the direction from end a to end b at the start (the recoil is negative).
      real(dp) function end_b_u(i)
         integer, intent(in) :: i
         real(dp) :: d(2), d3(3)
         if (allocated(history%ends_y)) then
            d3 = [history%ends(1, 2, 0) - history%ends(1, 1, 0), history%ends_y(1, 2, 0) - history%ends_y(1, 1, 0), &
                  history%ends(2, 2, 0) - history%ends(2, 1, 0)]
            end_b_u = 0
            if (norm2(d3) > 0) end_b_u = dot_product([history%ends(3, 2, i), history%ends_y(2, 2, i), &
                                                      history%ends(4, 2, i)], d3)/norm2(d3)
            return
         end if
         d = history%ends(1:2, 2, 0) - history%ends(1:2, 1, 0)
         if (norm2(d) > 0) then
            end_b_u = dot_product(history%ends(3:4, 2, i), d)/norm2(d)
         else
            end_b_u = 0
         end if
      end function end_b_u

      !> Length of an end vector given by its x and z components xz and, in a 3-D run, its
      !> y component q of ends_y (2 velocity, 3 force) for end j in record i.
      real(dp) function magnitude(xz, q, j, i)
         real(dp), intent(in) :: xz(2)
         integer, intent(in) :: q, j, i
         if (allocated(history%ends_y)) then
            magnitude = norm2([xz(1), history%ends_y(q, j, i), xz(2)])
         else
            magnitude = norm2(xz)
         end if
      end function magnitude
   end subroutine result_write_history

   !> Write the summary figures as attributes of /summary.
   module subroutine result_write_summary(self, summary, end_labels, error, info)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Figures of the run.
      type(run_summary), intent(in) :: summary
      !> Names of the ends.
      character(len=*), intent(in) :: end_labels(:)
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      !> The static state (its figures go first: static_*).
      type(static_info), intent(in), optional :: info
      integer(hid_t) :: group
      integer :: hdferr, j
      logical :: ok
      character(:), allocatable :: label
      call h5gcreate_f(self%file, 'summary', group, hdferr)
      ok = hdferr == 0
      if (ok) then
         call describe_group(self, group, '/summary', ok)
         ! A figure that does not apply to the scene is absent (no -1, no 0 for "none").
         if (present(info)) then
            if (info%one_line) then
               call put_real_attr(group, 'static_tension_a', info%tension_a, ok)
               call put_real_attr(group, 'static_tension_b', info%tension_b, ok)
               call put_real_attr(group, 'static_angle_a', info%end_angle, ok)
               call put_real_attr(group, 'static_angle_b', info%end_angle_b, ok)
               call put_real_attr(group, 'static_span', info%span, ok)
               call put_real_attr(group, 'static_lowest_z', info%lowest_z, ok)
               call put_real_attr(group, 'static_lowest_s', info%lowest_s, ok)
            end if
            call put_real_attr(group, 'static_max_tension', info%max_tension, ok)
         end if
         if (allocated(summary%static_measures)) then
            do j = 1, size(summary%static_measures)
               call put_real_attr(group, 'static_'//trim(summary%measure_names(j)), summary%static_measures(j), ok)
            end do
         end if
         if (allocated(summary%notes)) then
            if (len(summary%notes) > 0) call put_text(group, 'notes', summary%notes, ok)
         end if
         call put_real_attr(group, 'peak_end_speed', summary%peak_end_speed, ok)
         call put_real_attr(group, 'peak_end_speed_time', summary%peak_end_speed_time, ok)
         if (len_trim(summary%peak_end_speed_end) > 0) &
            call put_text(group, 'peak_end_speed_end', trim(summary%peak_end_speed_end), ok)
         if (summary%has_fixed_end) then
            call put_real_attr(group, 'min_fixed_end_tension', summary%min_fixed_end_tension, ok)
            call put_real_attr(group, 'min_fixed_end_tension_time', summary%min_fixed_end_tension_time, ok)
         end if
         if (summary%has_front .and. summary%front_arrival_time >= 0) &
            call put_real_attr(group, 'front_arrival_time', summary%front_arrival_time, ok)
         if (summary%broke) then
            call put_real_attr(group, 'break_time', summary%break_time, ok)
            call put_real_attr(group, 'break_s', summary%break_s, ok)
            call put_real_attr(group, 'break_ramp', summary%break_ramp, ok)
            if (summary%break_line > 0) call put_int_attr(group, 'break_line', summary%break_line, ok)
         end if
         if (summary%by_tension) then
            call put_real_attr(group, 'mbl', summary%mbl, ok)
            if (summary%broke) then
               call put_real_attr(group, 'break_tension', summary%break_tension, ok)
               call put_real_attr(group, 'break_cell_s', summary%break_cell_s, ok)
            else
               call put_real_attr(group, 'largest_tension', summary%largest_tension, ok)
               call put_real_attr(group, 'largest_tension_s', summary%largest_tension_s, ok)
               call put_real_attr(group, 'largest_tension_time', summary%largest_tension_time, ok)
            end if
         end if
         if (summary%energy_drift >= 0) call put_real_attr(group, 'energy_drift', summary%energy_drift, ok)
         call put_real_attr(group, 'dissipated', summary%dissipated, ok)
         call put_real_attr(group, 'time_reached', summary%time_reached, ok)
         call put_real_attr(group, 'wall_time', summary%wall_time, ok)
         call put_real_attr(group, 'dt_requested', summary%dt_requested, ok)
         call put_real_attr(group, 'dt_used', summary%dt_used, ok)
         call put_real_attr(group, 'courant_requested', summary%courant_requested, ok)
         call put_real_attr(group, 'courant_used', summary%courant_used, ok)
         call put_real_attr(group, 'max_unit_norm_error', summary%max_unit_norm_error, ok)
         call put_real_attr(group, 'max_turning_angle', summary%max_turning_angle, ok)
         call put_real_attr(group, 'min_strain', summary%min_strain, ok)
         call put_real_attr(group, 'max_strain', summary%max_strain, ok)
         call put_int_attr(group, 'steps', summary%steps, ok)
         call put_int_attr(group, 'rejected_steps', summary%rejected_steps, ok)
         call put_int_attr(group, 'newton_iterations', summary%newton_iterations, ok)
         call put_int_attr(group, 'max_newton_iterations', summary%max_newton_iterations, ok)
         call put_int_attr(group, 'factorisations', summary%factorisations, ok)
         if (allocated(summary%warnings)) call put_text(group, 'warnings', summary%warnings, ok)
         if (allocated(summary%ends)) then
            do j = 1, size(summary%ends)
               label = trim(end_labels(j))
               associate (e => summary%ends(j))
                  if (len_trim(e%kind) > 0) call put_text(group, label//'_kind', trim(e%kind), ok)
                  call put_real_attr(group, label//'_peak_speed', e%peak_speed, ok)
                  call put_real_attr(group, label//'_peak_speed_time', e%peak_speed_time, ok)
                  call put_real_attr(group, label//'_min_tension', e%min_tension, ok)
                  call put_real_attr(group, label//'_min_tension_time', e%min_tension_time, ok)
                  call put_real_attr(group, label//'_max_tension', e%max_tension, ok)
                  call put_real_attr(group, label//'_max_tension_time', e%max_tension_time, ok)
                  call put_real_attr(group, label//'_slack_time', e%slack_time, ok)
                  if (summary%has_front .and. e%front_arrival_time >= 0) &
                     call put_real_attr(group, label//'_front_arrival_time', e%front_arrival_time, ok)
                  if (allocated(e%slack_intervals)) then
                     if (size(e%slack_intervals, 2) > 0) then
                        call put_reals(self, group, '/summary', label//'_slack_start', e%slack_intervals(1, :), ok)
                        call put_reals(self, group, '/summary', label//'_slack_end', e%slack_intervals(2, :), ok)
                     end if
                  end if
               end associate
            end do
         end if
         call check_attributes(self, group, '/summary', ok)
         call h5gclose_f(group, hdferr)
      end if
      if (.not. ok) call fatal_error(error, "writing /summary to '"//self%path//"' failed"//why(self), stat_io)
   end subroutine result_write_summary
end submodule xcable_io_output_records
