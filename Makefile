# xcable: the two commands of the README are `make run` and `make test`.
# Each installs what is missing first (tools/install-deps.sh).

SHELL := /bin/bash
export PATH := $(HOME)/.local/bin:$(PATH)
FPM ?= fpm
PROFILE ?= release
CASE ?= slow_315kN

.PHONY: all deps build run test clean

all: build

deps:
	@tools/install-deps.sh

build: deps
	$(FPM) install --profile $(PROFILE) --prefix . >/dev/null
	@echo "built bin/xcable"

run: build
	./bin/xcable input/$(CASE).nml
	@$(MAKE) --no-print-directory figures-case CASE=$(CASE)
	@echo "figures of $(CASE) in results/figures/$(CASE)/"

test: build
	$(FPM) test --profile $(PROFILE)
	test/test_figures.sh
	test/test_fuzz.sh bin/xcable
	test/test_checkpoint.sh bin/xcable
	test/test_xdmf.sh bin/xcable

clean:
	rm -rf build bin

# Further targets (figures, bench, stress, test-slurm) live in mk/*.mk.
-include mk/*.mk
