!> HDF5 result file (and, when asked, gnuplot-ready text beside it).
!>
!> Layout (h5py reads 2-D datasets as [time, node]):
!>   /  attributes status ('running', 'complete', 'failed' or 'interrupted'),
!>      failure_reason, failure_time, warnings, namelist, input_file,
!>      code_version, compiler_version, compiler_options, scheme, terms,
!>      run_id (the run's identifier, also in its checkpoints), resumes (how
!>      often it was resumed from a checkpoint), model ('2d' or '3d')
!>   /s, /time, and one 2-D dataset per field asked for in &output fields;
!>      a 3-D run also /y, /vy, /curvature_z, /twist, /binormal_shear,
!>      /curvature_n (field3_names; driver/rod3d_fields.f90)
!>   /static/{s,x,z,tension,shear,strain,u,v,curvature} (+ beta0, beta3 of the
!>      box scheme; + the 3-D fields of a 3-D run), attributes span, sag,
!>      end_angle, tension_a, tension_b, newton_iterations
!>   /history/{time,dt,newton_iterations,rejected}
!>   /history/<end>/{x,z,vx,vz,tension,force_x,force_z} for each end (+ y, vy,
!>      force_y of a 3-D run)
!>   /history/energy/{strain,kinetic,bending,gravity,work,dissipation,ledger} with the ledger
!>   /summary attributes
!> Every dataset, group and attribute is one of the output registry
!> (io/output_registry.f90), which gives each dataset its `units` and
!> `description` attributes and each group its `description`; a path it does
!> not list is not written (the write fails, naming it). /time and /s are
!> dimension scales ('time', 'node') attached to every [time, node] dataset,
!> /static/s to the static fields, /history/time to the history. Texts are
!> variable-length UTF-8 strings.
!> The status is 'running' from creation, so a run that is killed never looks
!> complete; 'interrupted' (with /summary, without /history) when it stopped
!> at SIGTERM with a checkpoint. Only the fields asked for are written.
!>
!> A resumed run reopens its file (reopen): the snapshots up to its
!> checkpoint stay, those written after it (by a process killed later) are
!> cut, as is the gnuplot text; /summary, /history and the failure and
!> warning attributes of an earlier stop are removed; status 'running'.
module xcable_io_output
   use xcable_kinds, only: dp
   use xcable_error, only: error_type, fatal_error, stat_io, stat_input
   use xcable_strings, only: str
   use xcable_run_records, only: run_history, run_summary, static_info, run_observer, n_energy, energy_names, &
                                 field_names, n_fields, n_end_quantities, end_quantity_names, n_end_quantities_y, &
                                 end_quantity_names_y, n_fields3, field3_names
   use xcable_io_hdf5, only: put_real_vector, put_int_vector, put_real_attr, put_int_attr, put_text_attr, &
                             get_text_attr, get_int_attr, get_real_attr
   use xcable_io_output_registry, only: output_item, find_output, output_items
   use xcable_system_posix, only: replace_file
   use xcable_version, only: code_version
   use xcable_io_number_text, only: put_es, put_int
   use hdf5
   use h5ds, only: h5dsset_scale_f, h5dsattach_scale_f, h5dsis_attached_f, h5dsset_label_f
   use, intrinsic :: iso_fortran_env, only: compiler_version, compiler_options
   implicit none
   private
   public :: result_file

   !> Fields of the gnuplot snapshot columns 2-9 (x z tension strain u v shear curvature).
   integer, parameter :: text_columns(8) = [6, 7, 1, 3, 4, 5, 2, 8]
   !> Energies of the history columns 5-11 (strain kinetic bending gravity work ledger dissipation).
   integer, parameter :: ledger_columns(7) = [1, 2, 3, 4, 5, 7, 6]

   !> An open result file; receives the static state and the snapshots of a run.
   type, extends(run_observer) :: result_file
      !> Path of the HDF5 file.
      character(:), allocatable :: path
      !> HDF5 identifier of the file.
      integer(hid_t) :: file = -1
      !> The snapshot datasets kept open between snapshots (0: /time, then
      !> field_names; -1: not open): opening and closing them for every snapshot
      !> took half of the HDF5 work of a snapshot (10 million instructions on
      !> fast_180kN). Closed before the file is (close_kept).
      integer(hid_t) :: kept(0:n_fields) = -1
      !> Output node arc lengths.
      real(dp), allocatable :: s(:)
      !> Which of field_names are written.
      logical :: want(n_fields) = .false.
      !> Snapshots written so far.
      integer :: snapshots = 0
      !> Whether gnuplot text is written, and the unit of its snapshot file.
      logical :: gnuplot_text = .false.
      integer :: text_unit = -1
      !> Stem of the gnuplot text files.
      character(:), allocatable :: text_stem
      !> Output columns where a new piece starts (a blank line in the gnuplot text).
      integer, allocatable :: piece_starts(:)
      !> A 3-D run: its snapshots come with the fields of field3_names (snapshot_extra),
      !> which the gnuplot text appends as columns 10-15; the planar fields wait in
      !> pending until they arrive.
      logical :: three_d = .false.
      !> Which snapshot fields (field_names, field3_names, beta0, beta3) this process has given
      !> their dimension scales: /time and /s on the top-level datasets, /static/s on the static
      !> ones (lay_out attaches each once: asking HDF5 whether a scale is attached costs more than
      !> the run's output).
      logical :: scaled(n_fields + n_fields3 + 2) = .false., static_scaled(n_fields + n_fields3 + 2) = .false.
      real(dp), allocatable :: pending(:, :)
      !> The first path a write found missing from the output registry (for the error message).
      character(:), allocatable :: unregistered
   contains
      procedure :: create => result_create
      procedure :: reopen => result_reopen
      procedure :: static => result_static
      procedure :: snapshot => result_snapshot
      procedure :: write_history => result_write_history
      procedure :: write_summary => result_write_summary
      procedure :: finish => result_finish
      !> The 3-D run's extra fields of a snapshot (y, w, ...): one 2-D dataset each.
      procedure :: snapshot_extra => result_snapshot_extra
      !> A text attribute of the file (the model that ran).
      procedure :: mark => result_mark
   end type result_file

contains

   !> Create the file (status 'running') and write the provenance.
   subroutine result_create(self, path, s, fields, namelist_text, input_file, gnuplot, scheme, terms, piece_starts, error, &
                            run_id, three_d)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Path of the HDF5 file.
      character(*), intent(in) :: path
      !> Output node arc lengths, m.
      real(dp), intent(in) :: s(:)
      !> Snapshot fields, separated by blanks or commas.
      character(*), intent(in) :: fields
      !> The resolved namelist.
      character(*), intent(in) :: namelist_text
      !> Namelist file of the case.
      character(*), intent(in) :: input_file
      !> Write gnuplot-ready text too.
      logical, intent(in) :: gnuplot
      !> Discretisation and the terms of the model that were computed.
      character(*), intent(in) :: scheme, terms
      !> Output columns where a new piece starts (empty: one piece).
      integer, intent(in) :: piece_starts(:)
      !> Error when the file cannot be created.
      type(error_type), allocatable, intent(out) :: error
      !> Identifier of the run (written as the attribute run_id; its checkpoints carry it too).
      character(*), intent(in), optional :: run_id
      !> A 3-D run (its snapshots come with the fields of field3_names; default: no).
      logical, intent(in), optional :: three_d
      integer :: hdferr, i, ios, status
      integer(hid_t) :: access
      character(len=256) :: msg
      logical :: ok
      self%path = path
      self%s = s
      self%piece_starts = piece_starts
      self%three_d = .false.
      if (present(three_d)) self%three_d = three_d
      do i = 1, n_fields
         self%want(i) = has_word(fields, trim(field_names(i)))
      end do
      call h5open_f(hdferr)
      call h5eset_auto_f(0, hdferr)
      ! The file format of HDF5 1.8 and later stores attributes above 64 KB (the
      ! echo of a case with 1000-row tables) in dense storage.
      call h5pcreate_f(H5P_FILE_ACCESS_F, access, hdferr)
      call h5pset_libver_bounds_f(access, H5F_LIBVER_V18_F, H5F_LIBVER_LATEST_F, hdferr)
      call h5fcreate_f(path, H5F_ACC_TRUNC_F, self%file, hdferr, access_prp=access)
      call h5pclose_f(access, status)
      if (hdferr /= 0) then
         call fatal_error(error, "cannot create the output file '"//path// &
                          "' (&output file): does its directory exist and is it writable?", stat_io)
         self%file = -1
         return
      end if
      ok = .true.
      call put_text(self%file, 'status', 'running', ok)
      call put_text(self%file, 'namelist', namelist_text, ok)
      call put_text(self%file, 'input_file', input_file, ok)
      call put_text(self%file, 'code_version', code_version, ok)
      call put_text(self%file, 'compiler_version', compiler_version(), ok)
      call put_text(self%file, 'compiler_options', compiler_options(), ok)
      call put_text(self%file, 'scheme', scheme, ok)
      call put_text(self%file, 'terms', terms, ok)
      if (present(run_id)) call put_text(self%file, 'run_id', run_id, ok)
      call describe_group(self, self%file, '/', ok)
      call put_reals(self, self%file, '', 's', s, ok)
      if (.not. ok) then
         call fatal_error(error, "writing the provenance to '"//path//"' failed"//why(self), stat_io)
         return
      end if
      if (gnuplot) then
         self%text_stem = text_stem_of(path)
         open (newunit=self%text_unit, file=self%text_stem//'.snapshots.dat', status='replace', action='write', &
               iostat=ios, iomsg=msg)
         if (ios /= 0) then
            call fatal_error(error, 'cannot create '//self%text_stem//'.snapshots.dat (&output gnuplot): '// &
                             trim(msg), stat_io)
            ! No result file may be left by a run refused before it started.
            call close_kept(self)
            call h5fclose_f(self%file, hdferr)
            self%file = -1
            open (newunit=self%text_unit, file=path, status='old', iostat=ios)
            if (ios == 0) close (self%text_unit, status='delete')
            self%text_unit = -1
            return
         end if
         self%gnuplot_text = .true.
         write (self%text_unit, '(a)') '# xcable snapshots: one block per time (gnuplot index), blocks separated by '// &
            'two blank lines; a single blank line separates the pieces of a broken cable'
         if (self%three_d) then
            write (self%text_unit, '(a)') '# columns: s[m] x[m] z[m] tension[N] strain[-] u[m/s] v[m/s] shear[N] '// &
               'curvature[1/m]'//extra_header()
         else
            write (self%text_unit, '(a)') '# columns: s[m] x[m] z[m] tension[N] strain[-] u[m/s] v[m/s] shear[N] '// &
               'curvature[1/m]'
         end if
      end if

   contains

      !> The 3-D columns of the header: ' y[m] vy[m/s] ...'.
      function extra_header() result(text)
         character(:), allocatable :: text
         integer :: q
         type(output_item) :: item
         logical :: found
         text = ''
         do q = 1, n_fields3
            call find_output('/'//trim(field3_names(q)), item, found)
            text = text//' '//trim(field3_names(q))//'['//trim(item%units)//']'
         end do
      end function extra_header
   end subroutine result_create

   !> Reopen the result file of a run that continues from a checkpoint. It
   !> must be the file of that run (run_id), not finished ('running' or
   !> 'interrupted'), with at least the snapshots the checkpoint counts and
   !> the same output nodes; with gnuplot text, its snapshot file must hold
   !> them too. All of this is checked before anything is changed. Then the
   !> part of the file the checkpoint counts is copied into a new file that
   !> replaces it (the snapshots after the checkpoint, /summary, /history and
   !> the failure and warning attributes of an earlier stop left behind), the
   !> text cut alike, the provenance updated (namelist, input_file; resumes
   !> counted) and the status set to 'running'.
   subroutine result_reopen(self, path, s, fields, namelist_text, input_file, gnuplot, piece_starts, snapshots, run_id, &
                            error, three_d)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Path of the HDF5 file.
      character(*), intent(in) :: path
      !> Output node arc lengths, m.
      real(dp), intent(in) :: s(:)
      !> Snapshot fields, separated by blanks or commas.
      character(*), intent(in) :: fields
      !> The resolved namelist (as the resumed run reads it).
      character(*), intent(in) :: namelist_text
      !> Namelist file of the case.
      character(*), intent(in) :: input_file
      !> Whether gnuplot text is written.
      logical, intent(in) :: gnuplot
      !> Output columns where a new piece starts (empty: one piece).
      integer, intent(in) :: piece_starts(:)
      !> Snapshots the checkpoint counts (the one at t = 0 included).
      integer, intent(in) :: snapshots
      !> Identifier of the run of the checkpoint.
      character(*), intent(in) :: run_id
      !> Error (stat_input) naming what does not fit; the file is then unchanged.
      type(error_type), allocatable, intent(out) :: error
      !> A 3-D run: its snapshots have the fields of field3_names too (default .false.).
      logical, intent(in), optional :: three_d
      integer :: hdferr, i, resumes, ios
      logical :: ok, exists
      character(:), allocatable :: status, stored_id, reason, lines(:)
      character(len=*), parameter :: fresh = '; run without --resume to start again'
      integer :: keep_lines
      self%path = path
      self%s = s
      self%piece_starts = piece_starts
      self%three_d = .false.
      if (present(three_d)) self%three_d = three_d
      do i = 1, n_fields
         self%want(i) = has_word(fields, trim(field_names(i)))
      end do
      inquire (file=path, exist=exists)
      if (.not. exists) then
         call fatal_error(error, "the result file '"//path//"' of the checkpoint is missing"//fresh, stat_input)
         return
      end if
      call h5open_f(hdferr)
      call h5eset_auto_f(0, hdferr)
      call h5fopen_f(path, H5F_ACC_RDWR_F, self%file, hdferr)
      if (hdferr /= 0) then
         self%file = -1
         call fatal_error(error, "the result file '"//path//"' cannot be opened for writing (damaged, or in use)"//fresh, &
                          stat_input)
         return
      end if
      ok = .true.
      call get_text_attr(self%file, 'status', status, ok)
      call get_text_attr(self%file, 'run_id', stored_id, ok)
      if (.not. ok) then
         call refuse("'"//path//"' has no status or run_id: not the result file of a run with checkpoints"//fresh)
         return
      end if
      select case (status)
      case ('running', 'interrupted')
      case ('complete')
         call refuse("the result file '"//path//"' is already complete: nothing to resume")
         return
      case ('failed')
         ok = .true.
         call get_text_attr(self%file, 'failure_reason', reason, ok)
         call refuse("the result file '"//path//"' says the run failed ("//reason//'): resuming would fail again'//fresh)
         return
      case default
         call refuse("the result file '"//path//"' has the status '"//status//"'"//fresh)
         return
      end select
      if (stored_id /= run_id) then
         call refuse("the result file '"//path//"' belongs to run "//stored_id//', the checkpoint to run '//run_id// &
                     ' (the file was written again since)'//fresh)
         return
      end if
      if (dataset_length(self%file, 's', 1) /= size(s)) then
         call refuse("the result file '"//path//"' has other output nodes than this case"//fresh)
         return
      end if
      if (dataset_length(self%file, 'time', 1) < snapshots) then
         call refuse("the result file '"//path//"' holds "//str(max(dataset_length(self%file, 'time', 1), 0))// &
                     ' snapshots, the checkpoint counts '//str(snapshots)//fresh)
         return
      end if
      do i = 1, n_fields
         if (.not. self%want(i)) cycle
         if (dataset_length(self%file, trim(field_names(i)), 2) < snapshots) then
            call refuse("the result file '"//path//"' lacks snapshots of "//trim(field_names(i))//fresh)
            return
         end if
      end do
      do i = 1, merge(n_fields3, 0, self%three_d)
         if (dataset_length(self%file, trim(field3_names(i)), 2) < snapshots) then
            call refuse("the result file '"//path//"' lacks snapshots of "//trim(field3_names(i))// &
                        ' (a 3-D run writes them)'//fresh)
            return
         end if
      end do
      if (gnuplot) then
         self%text_stem = text_stem_of(path)
         call kept_text(self%text_stem//'.snapshots.dat', snapshots, lines, keep_lines, reason)
         if (len(reason) > 0) then
            call refuse(reason//fresh)
            return
         end if
      end if
      ! Checked: now change it. A process killed inside an HDF5 flush can leave the chunk
      ! indexes of the snapshot datasets out of step with their extents and with the space the
      ! superblock records (entries past the extent or past the end of allocated space); a
      ! file cut in place and written on could then read a row back as zeros (seen after a
      ! SIGKILL of a 3-D run: one chunk too many in /shear, its row zero after the resume).
      ! So the kept part is copied into a new file, which replaces this one: the provenance
      ! attributes, /s and /static as they are, and the first `snapshots` rows of /time and
      ! of every snapshot dataset (rows the checkpoint counts, flushed before it was written),
      ! each dataset built afresh. Until the rename the old file stays as it was.
      call copy_kept(error)
      if (allocated(error)) return
      call lay_out(self, ok)
      resumes = 0
      call get_int_attr(self%file, 'resumes', resumes, exists)
      call put_int_attr(self%file, 'resumes', resumes + 1, ok)
      call put_text(self%file, 'namelist', namelist_text, ok)
      call put_text(self%file, 'input_file', input_file, ok)
      call put_text(self%file, 'status', 'running', ok)
      call h5fflush_f(self%file, H5F_SCOPE_GLOBAL_F, hdferr)
      if (.not. ok .or. hdferr /= 0) then
         call fatal_error(error, "reopening '"//path//"' to resume: an HDF5 write failed"//why(self), stat_io)
         return
      end if
      self%snapshots = snapshots
      if (gnuplot) then
         call rewrite_text(self%text_stem//'.snapshots.dat', lines(1:keep_lines), reason)
         if (len(reason) == 0) open (newunit=self%text_unit, file=self%text_stem//'.snapshots.dat', status='old', &
                                     position='append', action='write', iostat=ios)
         if (len(reason) > 0 .or. ios /= 0) then
            call fatal_error(error, 'cannot rewrite '//self%text_stem//'.snapshots.dat to resume (&output gnuplot)', &
                             stat_io)
            return
         end if
         self%gnuplot_text = .true.
      end if

   contains

      !> The kept part of the file into path.resume, which then replaces path and is
      !> opened as self%file (see above). Errors: stat_io; the old file is then unchanged
      !> (closed), and the partial copy removed.
      subroutine copy_kept(error)
         type(error_type), allocatable, intent(out) :: error
         character(len=*), parameter :: text_attrs(11) = [character(len=16) :: 'status', 'namelist', &
            'input_file', 'code_version', 'compiler_version', 'compiler_options', 'scheme', 'terms', 'run_id', &
            'model', 'description']
         integer(hid_t) :: new, access, copy_list
         character(:), allocatable :: temporary, text, message
         logical :: found, copied
         integer :: q, unit, status_code
         temporary = path//'.resume'
         open (newunit=unit, file=temporary, status='old', iostat=ios)
         if (ios == 0) close (unit, status='delete')
         call h5pcreate_f(H5P_FILE_ACCESS_F, access, hdferr)
         call h5pset_libver_bounds_f(access, H5F_LIBVER_V18_F, H5F_LIBVER_LATEST_F, hdferr)
         call h5fcreate_f(temporary, H5F_ACC_TRUNC_F, new, hdferr, access_prp=access)
         call h5pclose_f(access, status_code)
         if (hdferr /= 0) then
            call fatal_error(error, "cannot create '"//temporary//"' to resume (is the directory writable?)", stat_io)
            call close_kept(self)
            call h5fclose_f(self%file, hdferr)
            self%file = -1
            return
         end if
         copied = .true.
         do q = 1, size(text_attrs)
            call h5aexists_f(self%file, trim(text_attrs(q)), found, hdferr)
            if (.not. found) cycle
            call get_text_attr(self%file, trim(text_attrs(q)), text, copied)
            call put_text(new, trim(text_attrs(q)), text, copied)
         end do
         call h5aexists_f(self%file, 'resumes', found, hdferr)
         if (found) then
            call get_int_attr(self%file, 'resumes', resumes, copied)
            call put_int_attr(new, 'resumes', resumes, copied)
         end if
         ! /s and /static are copied without their attributes: HDF5 1.10 crashes copying the
         ! dimension scales' references (H5Ocopy of /s, in H5T_convert). Their units and
         ! descriptions come again from the registry, their scales from lay_out, the static
         ! figures are copied one by one.
         call h5pcreate_f(H5P_OBJECT_COPY_F, copy_list, hdferr)
         call h5pset_copy_object_f(copy_list, H5O_COPY_WITHOUT_ATTR_FLAG_F, hdferr)
         call h5ocopy_f(self%file, 's', new, 's', hdferr, ocpypl_id=copy_list)
         copied = copied .and. hdferr == 0
         call h5lexists_f(self%file, 'static', found, hdferr)
         if (found) call copy_static(new, copy_list, copied)
         call h5pclose_f(copy_list, hdferr)
         call copy_rows(self%file, new, 'time', 1, snapshots, copied)
         do q = 1, n_fields
            if (self%want(q)) call copy_rows(self%file, new, trim(field_names(q)), 2, snapshots, copied)
         end do
         do q = 1, merge(n_fields3, 0, self%three_d)
            call copy_rows(self%file, new, trim(field3_names(q)), 2, snapshots, copied)
         end do
         call h5fflush_f(new, H5F_SCOPE_GLOBAL_F, hdferr)
         copied = copied .and. hdferr == 0
         call h5fclose_f(new, hdferr)
         copied = copied .and. hdferr == 0
         call close_kept(self)
         call h5fclose_f(self%file, hdferr)
         self%file = -1
         message = ''
         if (copied) message = replace_file(temporary, path)
         if (.not. copied .or. len(message) > 0) then
            open (newunit=unit, file=temporary, status='old', iostat=ios)
            if (ios == 0) close (unit, status='delete')
            if (.not. copied) message = 'an HDF5 read or write failed'
            call fatal_error(error, "reopening '"//path//"' to resume: copying its kept part failed ("// &
                             message//"); the file is unchanged", stat_io)
            return
         end if
         call h5fopen_f(path, H5F_ACC_RDWR_F, self%file, hdferr)
         if (hdferr /= 0) then
            self%file = -1
            call fatal_error(error, "the result file '"//path//"' cannot be opened again after its kept part "// &
                             "was copied", stat_io)
         end if

      end subroutine copy_kept
      !> /static into new: its datasets without attributes (copy_list), described from the
      !> registry; its figures (attributes) one by one.
      subroutine copy_static(new, copy_list, copied)
         integer(hid_t), intent(in) :: new, copy_list
         logical, intent(inout) :: copied
         character(len=*), parameter :: names(n_fields + n_fields3 + 3) = [character(len=14) :: 's', &
                                                                             field_names, field3_names, 'beta0', 'beta3']
         type(output_item), allocatable :: items(:)
         integer(hid_t) :: from, to
         integer :: k, value_int, hdferr
         real(dp) :: value
         logical :: exists
         call h5gopen_f(self%file, 'static', from, hdferr)
         call h5gcreate_f(new, 'static', to, hdferr)
         copied = copied .and. hdferr == 0
         if (hdferr /= 0) return
         call describe_group(self, to, '/static', copied)
         do k = 1, size(names)
            call h5lexists_f(from, trim(names(k)), exists, hdferr)
            if (.not. exists) cycle
            call h5ocopy_f(from, trim(names(k)), to, trim(names(k)), hdferr, ocpypl_id=copy_list)
            copied = copied .and. hdferr == 0
            call describe_dataset(self, to, '/static', trim(names(k)), copied)
         end do
         items = output_items()
         do k = 1, size(items)
            if (index(items(k)%path, '/static@') /= 1) cycle
            call h5aexists_f(from, trim(items(k)%path(9:)), exists, hdferr)
            if (.not. exists) cycle
            if (items(k)%units == '1') then
               call get_int_attr(from, trim(items(k)%path(9:)), value_int, copied)
               call put_int_attr(to, trim(items(k)%path(9:)), value_int, copied)
            else
               call get_real_attr(from, trim(items(k)%path(9:)), value, copied)
               call put_real_attr(to, trim(items(k)%path(9:)), value, copied)
            end if
         end do
         call h5gclose_f(to, hdferr)
         call h5gclose_f(from, hdferr)
      end subroutine copy_static

      !> Refuse: close the file unchanged.
      subroutine refuse(message)
         character(*), intent(in) :: message
         call fatal_error(error, message, stat_input)
         call close_kept(self)
         call h5fclose_f(self%file, hdferr)
         self%file = -1
      end subroutine refuse
   end subroutine result_reopen

   !> Number of snapshots of a dataset (rank 1: its length; rank 2: its second
   !> dimension); -1 when it is missing or of another rank.
   integer function dataset_length(loc, name, rank) result(n)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name
      integer, intent(in) :: rank
      integer(hid_t) :: dset, space
      integer(hsize_t) :: dims(2), maxdims(2)
      integer :: hdferr, stored_rank
      n = -1
      call h5dopen_f(loc, name, dset, hdferr)
      if (hdferr /= 0) return
      call h5dget_space_f(dset, space, hdferr)
      call h5sget_simple_extent_ndims_f(space, stored_rank, hdferr)
      if (stored_rank == rank) then
         call h5sget_simple_extent_dims_f(space, dims(1:rank), maxdims(1:rank), hdferr)
         if (hdferr >= 0) n = int(dims(rank))
      end if
      call h5sclose_f(space, hdferr)
      call h5dclose_f(dset, hdferr)
   end function dataset_length

   !> The first `keep` snapshots of a snapshot dataset of one file into a new
   !> dataset of that name in another (written as the run writes them, a row at
   !> a time). Only rows inside the dataset's extent are read.
   subroutine copy_rows(from, to, name, rank, keep, ok)
      integer(hid_t), intent(in) :: from, to
      character(*), intent(in) :: name
      integer, intent(in) :: rank, keep
      logical, intent(inout) :: ok
      integer(hid_t) :: dset, space, memspace
      integer(hsize_t) :: dims(2), maxdims(2), count(2), start(2)
      real(dp), allocatable :: rows(:, :)
      integer :: hdferr, j
      call h5dopen_f(from, name, dset, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      call h5dget_space_f(dset, space, hdferr)
      call h5sget_simple_extent_dims_f(space, dims(1:rank), maxdims(1:rank), hdferr)
      if (rank == 1) dims(2) = dims(1)
      if (rank == 1) dims(1) = 1
      if (dims(2) < keep) then
         ok = .false.
      else
         allocate (rows(dims(1), keep))
         start = 0
         if (rank == 1) then
            count(1) = int(keep, hsize_t)
         else
            count = [dims(1), int(keep, hsize_t)]
         end if
         call h5sselect_hyperslab_f(space, H5S_SELECT_SET_F, start(1:rank), count(1:rank), hdferr)
         call h5screate_simple_f(rank, count(1:rank), memspace, hdferr)
         call h5dread_f(dset, H5T_NATIVE_DOUBLE, rows, count(1:rank), hdferr, memspace, space)
         ok = ok .and. hdferr == 0
         call h5sclose_f(memspace, hdferr)
      end if
      call h5sclose_f(space, hdferr)
      call h5dclose_f(dset, hdferr)
      if (.not. ok) return
      do j = 1, keep
         call append(to, name, rows(:, j), rank, ok)
      end do
   end subroutine copy_rows

   !> The lines of a gnuplot snapshot file that hold its first `keep` blocks
   !> (the blank lines between blocks after the last kept one left out):
   !> lines(1:count). reason is '' or why the file does not do.
   subroutine kept_text(path, keep, lines, count, reason)
      character(*), intent(in) :: path
      integer, intent(in) :: keep
      character(:), allocatable, intent(out) :: lines(:)
      integer, intent(out) :: count
      character(:), allocatable, intent(out) :: reason
      character(len=512) :: line
      character(len=512), allocatable :: all(:), grown(:)
      integer :: unit, ios, n, blocks
      reason = ''
      count = 0
      allocate (character(len=512) :: lines(0))
      open (newunit=unit, file=path, status='old', action='read', iostat=ios)
      if (ios /= 0) then
         reason = 'the gnuplot text '//path//' of the run is missing'
         return
      end if
      allocate (all(1024))
      n = 0
      blocks = 0
      do
         read (unit, '(a)', iostat=ios) line
         if (ios /= 0) exit
         if (index(line, '# t = ') == 1) then
            blocks = blocks + 1
            if (blocks > keep) exit
         end if
         if (n == size(all)) then
            allocate (grown(2*n))
            grown(1:n) = all(1:n)
            call move_alloc(grown, all)
         end if
         n = n + 1
         all(n) = line
      end do
      close (unit)
      if (blocks < keep) then
         reason = 'the gnuplot text '//path//' holds '//str(blocks)//' snapshots, the checkpoint counts '//str(keep)
         return
      end if
      do while (n > 0)
         if (len_trim(all(n)) > 0) exit
         n = n - 1
      end do
      deallocate (lines)
      allocate (character(len=512) :: lines(n))
      lines = all(1:n)
      count = n
   end subroutine kept_text

   !> Write lines (trimmed) to path through path.tmp and a rename; reason '' or why not.
   subroutine rewrite_text(path, lines, reason)
      character(*), intent(in) :: path
      character(len=*), intent(in) :: lines(:)
      character(:), allocatable, intent(out) :: reason
      integer :: unit, ios, i
      reason = ''
      open (newunit=unit, file=path//'.tmp', status='replace', action='write', iostat=ios)
      if (ios /= 0) then
         reason = 'cannot create '//path//'.tmp'
         return
      end if
      do i = 1, size(lines)
         write (unit, '(a)', iostat=ios) trim(lines(i))
         if (ios /= 0) exit
      end do
      close (unit)
      if (ios /= 0) then
         reason = 'cannot write '//path//'.tmp'
         return
      end if
      reason = replace_file(path//'.tmp', path)
   end subroutine rewrite_text

   !> Stem of the gnuplot text files of a result path (without its extension).
   pure function text_stem_of(path) result(stem)
      character(*), intent(in) :: path
      character(:), allocatable :: stem
      integer :: dot
      dot = index(path, '.', back=.true.)
      if (dot <= index(path, '/', back=.true.)) dot = len(path) + 1
      stem = path(1:dot - 1)
   end function text_stem_of

   !> Write the static state (run_observer).
   subroutine result_static(self, info, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Static state.
      type(static_info), intent(in) :: info
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      integer(hid_t) :: group
      integer :: hdferr, i
      logical :: ok
      call h5gcreate_f(self%file, 'static', group, hdferr)
      ok = hdferr == 0
      if (ok) then
         call describe_group(self, group, '/static', ok)
         call put_reals(self, group, '/static', 's', info%s, ok)
         do i = 1, n_fields
            call put_reals(self, group, '/static', trim(field_names(i)), info%fields(:, i), ok)
         end do
         if (allocated(info%beta0)) then
            call put_reals(self, group, '/static', 'beta0', info%beta0, ok)
            call put_reals(self, group, '/static', 'beta3', info%beta3, ok)
         end if
         if (allocated(info%extra)) then
            do i = 1, n_fields3
               call put_reals(self, group, '/static', trim(field3_names(i)), info%extra(:, i), ok)
            end do
         end if
         call put_real_attr(group, 'span', info%span, ok)
         call put_real_attr(group, 'sag', info%sag, ok)
         call put_real_attr(group, 'end_angle', info%end_angle, ok)
         call put_real_attr(group, 'tension_a', info%tension_a, ok)
         call put_real_attr(group, 'tension_b', info%tension_b, ok)
         call put_real_attr(group, 'end_angle_b', info%end_angle_b, ok)
         call put_real_attr(group, 'lowest_z', info%lowest_z, ok)
         call put_real_attr(group, 'lowest_s', info%lowest_s, ok)
         call put_real_attr(group, 'max_tension', info%max_tension, ok)
         call put_int_attr(group, 'newton_iterations', info%newton_iterations, ok)
         call check_attributes(self, group, '/static', ok)
         call h5gclose_f(group, hdferr)
      end if
      call lay_out(self, ok)
      call h5fflush_f(self%file, H5F_SCOPE_GLOBAL_F, hdferr)
      if (.not. ok .or. hdferr /= 0) call fatal_error(error, "writing /static to '"//self%path//"' failed"//why(self), &
                                                      stat_io)
   end subroutine result_static

   !> Append one snapshot (run_observer).
   subroutine result_snapshot(self, t, fields, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      !> Fields (nodes, n_fields).
      real(dp), intent(in) :: fields(:, :)
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      integer :: i, hdferr
      logical :: ok
      ok = .true.
      self%snapshots = self%snapshots + 1
      call append(self%file, 'time', [t], 1, ok, self%kept(0))
      do i = 1, n_fields
         if (self%want(i)) call append(self%file, trim(field_names(i)), fields(:, i), 2, ok, self%kept(i))
      end do
      if (self%snapshots == 1) call lay_out(self, ok)
      call h5fflush_f(self%file, H5F_SCOPE_GLOBAL_F, hdferr)
      if (.not. ok .or. hdferr /= 0) then
         call fatal_error(error, "writing snapshot at t = "//str(t)//" s to '"//self%path//"' failed"//why(self), stat_io)
         return
      end if
      if (self%gnuplot_text) then
         if (self%three_d) then
            ! The text waits for the 3-D fields (result_snapshot_extra).
            self%pending = fields
         else
            call write_text_block(self, t, fields)
         end if
      end if
   end subroutine result_snapshot

   !> One snapshot block of the gnuplot text: columns s x z tension strain u
   !> v shear curvature, and with extra (a 3-D run) the fields of
   !> field3_names, as '(9es16.8[,6es16.8])' (put_es).
   subroutine write_text_block(self, t, fields, extra)
      type(result_file), intent(inout) :: self
      real(dp), intent(in) :: t, fields(:, :)
      real(dp), intent(in), optional :: extra(:, :)
      character(len=(9 + n_fields3)*16) :: line
      integer :: k, q, pos
      if (self%snapshots > 1) write (self%text_unit, '(/)')
      write (self%text_unit, '(a,es14.6)') '# t = ', t
      do k = 1, size(self%s)
         if (any(self%piece_starts == k)) write (self%text_unit, '(a)') ''
         pos = 1
         call put_es(line, pos, self%s(k), 16, 8)
         do q = 1, 8
            call put_es(line, pos, fields(k, text_columns(q)), 16, 8)
         end do
         if (present(extra)) then
            do q = 1, size(extra, 2)
               call put_es(line, pos, extra(k, q), 16, 8)
            end do
         end if
         write (self%text_unit, '(a)') line(1:pos - 1)
      end do
      flush (self%text_unit)
   end subroutine write_text_block

   !> Extra fields of the snapshot just written, one 2-D dataset per name
   !> (a 3-D run's y, w, curvature_z, twist).
   subroutine result_snapshot_extra(self, t, names, fields, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Time, s.
      real(dp), intent(in) :: t
      !> Dataset names.
      character(*), intent(in) :: names(:)
      !> Fields (nodes, size(names)).
      real(dp), intent(in) :: fields(:, :)
      !> Error when writing fails (a name the output registry lacks is not written).
      type(error_type), allocatable, intent(out) :: error
      integer :: i, hdferr
      logical :: ok
      character(:), allocatable :: units, description
      ok = .true.
      do i = 1, size(names)
         call lookup(self, '/'//trim(names(i)), units, description, ok)
         if (len(description) > 0) call append(self%file, trim(names(i)), fields(:, i), 2, ok)
      end do
      if (self%snapshots == 1) call lay_out(self, ok)
      ! On disk before a checkpoint can count this snapshot (as result_snapshot's fields).
      call h5fflush_f(self%file, H5F_SCOPE_GLOBAL_F, hdferr)
      ok = ok .and. hdferr == 0
      if (.not. ok) then
         call fatal_error(error, 'writing the 3-D fields at t = '//str(t)//" s to '"//self%path//"' failed"// &
                          why(self), stat_io)
         return
      end if
      if (self%gnuplot_text .and. self%three_d .and. allocated(self%pending)) then
         call write_text_block(self, t, self%pending, fields)
         deallocate (self%pending)
      end if
   end subroutine result_snapshot_extra

   !> Write a text attribute of the file's root.
   subroutine result_mark(self, name, text, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Attribute name and value.
      character(*), intent(in) :: name, text
      !> Error when writing fails.
      type(error_type), allocatable, intent(out) :: error
      logical :: ok
      ok = .true.
      call put_text(self%file, name, text, ok)
      call check_attributes(self, self%file, '/', ok)
      if (.not. ok) call fatal_error(error, "writing the attribute '"//name//"' to '"//self%path//"' failed"// &
                                     why(self), stat_io)
   end subroutine result_mark

   !> Write the history of the run (and its gnuplot text).
   subroutine result_write_history(self, history, error)
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
   subroutine result_write_summary(self, summary, end_labels, error, info)
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
            call put_real_attr(group, 'static_tension_a', info%tension_a, ok)
            call put_real_attr(group, 'static_tension_b', info%tension_b, ok)
            call put_real_attr(group, 'static_angle_a', info%end_angle, ok)
            call put_real_attr(group, 'static_angle_b', info%end_angle_b, ok)
            call put_real_attr(group, 'static_span', info%span, ok)
            call put_real_attr(group, 'static_lowest_z', info%lowest_z, ok)
            call put_real_attr(group, 'static_lowest_s', info%lowest_s, ok)
            call put_real_attr(group, 'static_max_tension', info%max_tension, ok)
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

   !> Close the snapshot datasets kept open by result_snapshot (before the file).
   subroutine close_kept(self, ok)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> Set to .false. when a close fails.
      logical, intent(inout), optional :: ok
      integer :: i, hdferr
      do i = 0, n_fields
         if (self%kept(i) < 0) cycle
         call h5dclose_f(self%kept(i), hdferr)
         if (present(ok)) ok = ok .and. hdferr == 0
         self%kept(i) = -1
      end do
   end subroutine close_kept

   !> Set the final status ('complete' or 'failed' with reason and time), the
   !> warnings, and close.
   subroutine result_finish(self, status, reason, time, warnings, error)
      !> Result file.
      class(result_file), intent(inout) :: self
      !> 'complete' or 'failed'.
      character(*), intent(in) :: status
      !> Why it failed.
      character(*), intent(in), optional :: reason
      !> Simulated time at the failure, s.
      real(dp), intent(in), optional :: time
      !> Warnings of the run, one per line ('' : none).
      character(*), intent(in), optional :: warnings
      !> Error when the status cannot be written or the file not closed (the
      !> file then still reads 'running').
      type(error_type), allocatable, intent(out), optional :: error
      integer :: hdferr
      logical :: ok
      if (self%file < 0) return
      ok = .true.
      if (present(reason)) call put_text(self%file, 'failure_reason', reason, ok)
      if (present(time)) call put_real_attr(self%file, 'failure_time', time, ok)
      if (present(warnings)) call put_text(self%file, 'warnings', warnings, ok)
      call put_text(self%file, 'status', status, ok)
      call check_attributes(self, self%file, '/', ok)
      call close_kept(self, ok)
      call h5fclose_f(self%file, hdferr)
      if ((.not. ok .or. hdferr /= 0) .and. present(error)) &
         call fatal_error(error, "writing the status '"//status//"' to '"//self%path//"' failed"//why(self), stat_io)
      self%file = -1
      call h5close_f(hdferr)
      if (self%gnuplot_text) close (self%text_unit)
      self%gnuplot_text = .false.
   end subroutine result_finish

   !> A text attribute of the result file: a variable-length UTF-8 string.
   subroutine put_text(loc, name, text, ok)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name, text
      logical, intent(inout) :: ok
      call put_text_attr(loc, name, text, ok, utf8=.true.)
   end subroutine put_text

   !> The registry's units and description of a path ('/group/name' or '/group@name'); when the
   !> registry does not list it, ok is cleared and the path kept for the error message.
   subroutine lookup(self, path, units, description, ok)
      class(result_file), intent(inout) :: self
      character(*), intent(in) :: path
      character(:), allocatable, intent(out) :: units, description
      logical, intent(inout) :: ok
      type(output_item) :: item
      logical :: found
      call find_output(path, item, found)
      units = trim(item%units)
      description = trim(item%description)
      if (.not. found) then
         ok = .false.
         description = ''
         if (.not. allocated(self%unregistered)) self%unregistered = path
      end if
   end subroutine lookup

   !> ' (the path is not in the output registry)' after a failed write that found one, else ''.
   function why(self) result(text)
      class(result_file), intent(in) :: self
      character(:), allocatable :: text
      text = ''
      if (allocated(self%unregistered)) text = " ('"//self%unregistered// &
                                               "' is not in the output registry, io/output_registry.f90)"
   end function why

   !> A real dataset name of the group at path group ('' : the root) with the registry's units
   !> and description; not written when the registry does not list it (ok cleared).
   subroutine put_reals(self, loc, group, name, values, ok)
      class(result_file), intent(inout) :: self
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: group, name
      real(dp), intent(in) :: values(:)
      logical, intent(inout) :: ok
      character(:), allocatable :: units, description
      call lookup(self, group//'/'//name, units, description, ok)
      if (len(description) > 0) call put_real_vector(loc, name, values, ok, units, description)
   end subroutine put_reals

   !> An integer dataset as put_reals.
   subroutine put_ints(self, loc, group, name, values, ok)
      class(result_file), intent(inout) :: self
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: group, name
      integer, intent(in) :: values(:)
      logical, intent(inout) :: ok
      character(:), allocatable :: units, description
      call lookup(self, group//'/'//name, units, description, ok)
      if (len(description) > 0) call put_int_vector(loc, name, values, ok, units, description)
   end subroutine put_ints

   !> The registry's description of a group (or the root, path '/') as its attribute.
   subroutine describe_group(self, loc, path, ok)
      class(result_file), intent(inout) :: self
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: path
      logical, intent(inout) :: ok
      character(:), allocatable :: units, description
      call lookup(self, path, units, description, ok)
      if (len(description) > 0) call put_text(loc, 'description', description, ok)
   end subroutine describe_group

   !> The registry's units and description on the dataset name of the group at path group
   !> ('' : the root), when it exists and lacks them (the snapshot datasets, made row by row).
   subroutine describe_dataset(self, loc, group, name, ok)
      class(result_file), intent(inout) :: self
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: group, name
      logical, intent(inout) :: ok
      character(:), allocatable :: units, description
      integer(hid_t) :: dset
      integer :: hdferr
      logical :: exists
      call h5lexists_f(loc, name, exists, hdferr)
      if (.not. exists) return
      call h5dopen_f(loc, name, dset, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      call h5aexists_f(dset, 'description', exists, hdferr)
      if (.not. exists) then
         call lookup(self, group//'/'//name, units, description, ok)
         if (len(description) > 0) then
            call put_text(dset, 'units', units, ok)
            call put_text(dset, 'description', description, ok)
         end if
      end if
      call h5dclose_f(dset, hdferr)
   end subroutine describe_dataset

   !> Every attribute of loc (the group at path, '/' for the root) must be in the registry
   !> (those of HDF5's dimension scales and `description` aside); ok cleared if one is not.
   subroutine check_attributes(self, loc, path, ok)
      class(result_file), intent(inout) :: self
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: path
      logical, intent(inout) :: ok
      integer :: count, k, hdferr
      character(len=64) :: name
      character(:), allocatable :: units, description
      call h5aget_num_attrs_f(loc, count, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      do k = 0, count - 1
         call h5aget_name_by_idx_f(loc, '.', H5_INDEX_NAME_F, H5_ITER_NATIVE_F, int(k, hsize_t), name, hdferr)
         if (hdferr /= 0) then
            ok = .false.
            cycle
         end if
         if (trim(name) == 'description') cycle
         if (path == '/') then
            call lookup(self, '/@'//trim(name), units, description, ok)
         else
            call lookup(self, path//'@'//trim(name), units, description, ok)
         end if
      end do
   end subroutine check_attributes

   !> The snapshot and static datasets described (describe_dataset) and given their dimension
   !> scales: /time ('time') and /s ('node') made scales and attached to every [time, node]
   !> dataset, /static/s to the static fields. Each step is skipped when done already, so this
   !> runs after the static state, the first snapshot, its 3-D fields and a reopen alike.
   subroutine lay_out(self, ok)
      class(result_file), intent(inout) :: self
      logical, intent(inout) :: ok
      character(len=*), parameter :: names(n_fields + n_fields3 + 2) = [character(len=14) :: field_names, &
                                                                          field3_names, 'beta0', 'beta3']
      integer(hid_t) :: time_scale, node_scale, group
      integer :: q, hdferr
      logical :: exists
      call describe_dataset(self, self%file, '', 'time', ok)
      call describe_dataset(self, self%file, '', 's', ok)
      do q = 1, n_fields + n_fields3
         call describe_dataset(self, self%file, '', trim(names(q)), ok)
      end do
      call open_scale(self%file, 'time', 'time', time_scale, ok)
      call open_scale(self%file, 's', 'node', node_scale, ok)
      if (time_scale >= 0 .and. node_scale >= 0) then
         do q = 1, n_fields + n_fields3
            if (self%scaled(q)) cycle
            call h5lexists_f(self%file, trim(names(q)), exists, hdferr)
            if (.not. exists) cycle
            call attach(time_scale, self%file, trim(names(q)), 0, 'time', ok, fresh=.true.)
            call attach(node_scale, self%file, trim(names(q)), 1, 'node', ok, fresh=.true.)
            self%scaled(q) = .true.
         end do
      end if
      if (time_scale >= 0) call h5dclose_f(time_scale, hdferr)
      if (node_scale >= 0) call h5dclose_f(node_scale, hdferr)
      call h5lexists_f(self%file, 'static', exists, hdferr)
      if (.not. exists) return
      call h5gopen_f(self%file, 'static', group, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      call open_scale(group, 's', 'node', node_scale, ok)
      if (node_scale >= 0) then
         do q = 1, size(names)
            if (self%static_scaled(q)) cycle
            call h5lexists_f(group, trim(names(q)), exists, hdferr)
            if (.not. exists) cycle
            call attach(node_scale, group, trim(names(q)), 0, 'node', ok, fresh=.true.)
            self%static_scaled(q) = .true.
         end do
         call h5dclose_f(node_scale, hdferr)
      end if
      call h5gclose_f(group, hdferr)
   end subroutine lay_out

   !> Open the dataset name of loc as a dimension scale called scale_name (made one if it is
   !> not yet); scale is -1 when the dataset does not exist.
   subroutine open_scale(loc, name, scale_name, scale, ok)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name, scale_name
      integer(hid_t), intent(out) :: scale
      logical, intent(inout) :: ok
      integer :: hdferr
      logical :: exists
      scale = -1
      call h5lexists_f(loc, name, exists, hdferr)
      if (.not. exists) return
      call h5dopen_f(loc, name, scale, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         scale = -1
         return
      end if
      call h5aexists_f(scale, 'CLASS', exists, hdferr)
      if (.not. exists) then
         call h5dsset_scale_f(scale, hdferr, scale_name)
         ok = ok .and. hdferr == 0
      end if
   end subroutine open_scale

   !> Attach the dimension scale `scale` to dimension `dimension` (0 the slowest, as h5py
   !> and C count) of the dataset name of loc, labelled `label`, unless it is attached
   !> already; nothing when the dataset does not exist.
   subroutine attach(scale, loc, name, dimension, label, ok, fresh)
      integer(hid_t), intent(in) :: scale, loc
      character(*), intent(in) :: name, label
      integer, intent(in) :: dimension
      logical, intent(inout) :: ok
      !> The dataset is known to have no scale on this dimension yet (no check).
      logical, intent(in), optional :: fresh
      integer(hid_t) :: dset
      integer :: hdferr, index
      logical :: exists, attached
      call h5lexists_f(loc, name, exists, hdferr)
      if (.not. exists) return
      call h5dopen_f(loc, name, dset, hdferr)
      if (hdferr /= 0) then
         ok = .false.
         return
      end if
      ! HDF5 1.10's Fortran interface takes the dimension as C counts it, from 1 (checked with
      ! h5py: test/test_outputs.py).
      index = dimension + 1
      attached = .false.
      if (.not. present(fresh)) then
         call h5dsis_attached_f(dset, scale, index, attached, hdferr)
         if (hdferr /= 0) attached = .false.
      end if
      if (.not. attached) then
         call h5dsattach_scale_f(dset, scale, index, hdferr)
         ok = ok .and. hdferr == 0
         call h5dsset_label_f(dset, index, label, hdferr)
         ok = ok .and. hdferr == 0
      end if
      call h5dclose_f(dset, hdferr)
   end subroutine attach



   !> Append a value (rank 1) or a row of node values (rank 2) to the
   !> extendible dataset name, created on first use.
   !> ok is cleared when the dataset cannot be created or opened, extended or
   !> written.
   subroutine append(loc, name, values, rank, ok, kept)
      integer(hid_t), intent(in) :: loc
      character(*), intent(in) :: name
      real(dp), intent(in) :: values(:)
      integer, intent(in) :: rank
      logical, intent(inout) :: ok
      !> The dataset kept open: used when >= 0, else set to the dataset opened
      !> (which then stays open); absent: the dataset is closed again.
      integer(hid_t), intent(inout), optional :: kept
      integer :: hdferr, err
      integer(hid_t) :: dset, space, memspace, plist
      integer(hsize_t) :: dims(2), maxdims(2), offset(2), count(2)
      logical :: exists, open_already
      count = [int(size(values), hsize_t), 1_hsize_t]
      err = 0
      open_already = .false.
      if (present(kept)) open_already = kept >= 0
      if (open_already) then
         dset = kept
      else
         call h5lexists_f(loc, name, exists, hdferr)
         if (.not. exists) then
            call create_dataset()
         else
            call h5dopen_f(loc, name, dset, err)
         end if
         if (err /= 0) then
            ok = .false.
            return
         end if
         if (present(kept)) kept = dset
      end if
      call h5dget_space_f(dset, space, hdferr)
      call h5sget_simple_extent_dims_f(space, dims(1:rank), maxdims(1:rank), hdferr)
      call h5sclose_f(space, hdferr)
      if (rank == 1) then
         offset(1) = dims(1)
         dims(1) = dims(1) + 1
         count(1) = 1
      else
         offset = [0_hsize_t, dims(2)]
         dims(2) = dims(2) + 1
      end if
      call h5dset_extent_f(dset, dims(1:rank), hdferr)
      ok = ok .and. hdferr == 0
      call h5dget_space_f(dset, space, hdferr)
      call h5sselect_hyperslab_f(space, H5S_SELECT_SET_F, offset(1:rank), count(1:rank), hdferr)
      call h5screate_simple_f(rank, count(1:rank), memspace, hdferr)
      call h5dwrite_f(dset, H5T_NATIVE_DOUBLE, values, count(1:rank), hdferr, memspace, space)
      ok = ok .and. hdferr == 0
      call h5sclose_f(memspace, hdferr)
      call h5sclose_f(space, hdferr)
      if (.not. present(kept)) call h5dclose_f(dset, hdferr)
   contains
      subroutine create_dataset()
         call h5pcreate_f(H5P_DATASET_CREATE_F, plist, hdferr)
         if (rank == 1) then
            dims(1) = 0
            maxdims(1) = H5S_UNLIMITED_F
            call h5pset_chunk_f(plist, 1, [64_hsize_t], hdferr)
         else
            dims = [count(1), 0_hsize_t]
            maxdims = [count(1), H5S_UNLIMITED_F]
            call h5pset_chunk_f(plist, 2, count, hdferr)
         end if
         call h5screate_simple_f(rank, dims(1:rank), space, hdferr, maxdims(1:rank))
         call h5dcreate_f(loc, name, H5T_NATIVE_DOUBLE, space, dset, err, plist)
         call h5sclose_f(space, hdferr)
         call h5pclose_f(plist, hdferr)
      end subroutine create_dataset
   end subroutine append

   !> Whether a blank- or comma-separated list contains a word.
   pure logical function has_word(list, word)
      character(*), intent(in) :: list, word
      integer :: i, start
      character :: ch
      has_word = .false.
      start = 0
      do i = 1, len(list) + 1
         if (i <= len(list)) then
            ch = list(i:i)
         else
            ch = ' '
         end if
         if (ch == ' ' .or. ch == ',') then
            if (start > 0) then
               if (list(start:i - 1) == word) has_word = .true.
            end if
            start = 0
         else if (start == 0) then
            start = i
         end if
      end do
   end function has_word
end module xcable_io_output
