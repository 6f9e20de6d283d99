# Batch runs (batch/): parameter sweeps as Slurm job arrays.
#   make test-batch   the sweep scripts without Slurm (generate, sweep-local, collect); seconds
#   make test-slurm   the same against a real Slurm: installs slurm-wlm and munge if missing,
#                     runs a private munged/slurmctld/slurmd on localhost; about a minute

.PHONY: test-batch test-slurm

test-batch: build
	bash batch/test-batch.sh

test-slurm: build
	bash batch/test-slurm.sh
