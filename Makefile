# fcs3d: Frictional Contact Systems in 3D.
#   make run       install missing Debian packages (as root), build, run the default deck
#   make test      the same set-up, then the whole test suite
#   make validate  long validations (not part of make test), then make ccx-suite
#   make ccx-suite CalculiX's static test decks through ccx and fcs3d (table of agreement)
#   make bench     benchmarks that print figures (not part of make test)
#   make bench-compare BEFORE=/path/to/fcs3d   that build and this one side by side
#   make figures   figures of the default run into doc/figures/ (make figures-runs: runs first)
#   make DEBUG=1 ... bounds checks and floating-point traps
#   make MPI=1 ...   the Open MPI variant bin/fcs3d-mpi instead (MUMPS distributed)

VERSION := 0.1.0

ifeq ($(origin FC),default)
FC := gfortran
endif
PYTHON := /usr/bin/python3
MULTIARCH := $(shell gcc -print-multiarch 2>/dev/null || echo x86_64-linux-gnu)

PACKAGES := gfortran liblapack-dev libopenblas-dev libsuitesparse-dev libhdf5-dev hdf5-tools \
            gmsh python3-numpy python3-matplotlib python3-h5py calculix-ccx libmumps-seq-dev \
            openmpi-bin libopenmpi-dev libmumps-dev libmetis-dev python3-paraview
# Needed by make validate / make ccx-suite only: CalculiX's test decks (ccx 2.11's, with results).
VALIDATE_PACKAGES := calculix-ccx-test

ifeq ($(MPI),1)
VARIANT := mpi
FC := mpif90
BIN_NAME := fcs3d-mpi
MUMPS_INC :=
MUMPS_LIBS := -ldmumps -lmumps_common -lpord -lmetis
else
VARIANT := serial
BIN_NAME := fcs3d
MUMPS_INC := -I /usr/include/mumps_seq
MUMPS_LIBS := -ldmumps_seq -lmumps_common_seq -lmpiseq_seq -lpord_seq -lmetis
endif
BUILD := build/$(VARIANT)
comma := ,
ifeq ($(DEBUG),1)
FFLAGS_OPT := -O0 -g -fcheck=all,no-array-temps -ffpe-trap=invalid,zero,overflow -fbacktrace -finit-real=snan
BUILD := build/debug-$(VARIANT)
else
FFLAGS_OPT := -O2 -g -funroll-loops
endif
# bin/ holds the default builds only; a DEBUG=1 build or one in another BUILD directory keeps
# its executable there, so that no build silently replaces bin/fcs3d with another's.
ifeq ($(BUILD),build/$(VARIANT))
BIN := bin/$(BIN_NAME)
else
BIN := $(BUILD)/$(BIN_NAME)
endif
# Where `make test` builds the MPI variant next to this one.
MPI_BUILD := $(if $(findstring serial,$(BUILD)),$(subst serial,mpi,$(BUILD)),$(BUILD)-mpi)
MPI_BIN := $(if $(filter build/mpi,$(MPI_BUILD)),bin/fcs3d-mpi,$(MPI_BUILD)/fcs3d-mpi)
HDF5_INC := /usr/include/hdf5/serial
HDF5_LIB := /usr/lib/$(MULTIARCH)/hdf5/serial
# -Wno-uninitialized: gfortran 12 reports false positives on every allocatable assignment
# from a function result (array descriptors); DEBUG=1 builds trap uninitialised reals instead.
# -Wno-unused-dummy-argument: implementations of abstract interfaces need not use every dummy.
# -fcheck=mem: array temporaries and automatic reallocations are checked too, so that running
# out of memory there ends in fcs3d's message (fcs_memory) instead of a segmentation fault.
FFLAGS := -std=f2008 -Wall -Wextra -Wno-compare-reals -Wno-maybe-uninitialized -Wno-uninitialized \
          -Wno-unused-dummy-argument -fimplicit-none -fcheck=mem \
          $(FFLAGS_OPT) -J $(BUILD) -I $(BUILD) -I $(HDF5_INC) $(MUMPS_INC)
LDLIBS := -L$(HDF5_LIB) -lhdf5_fortran -lhdf5 -lumfpack -lamd -lsuitesparseconfig \
          $(MUMPS_LIBS) -llapack -lblas -lpthread

LIB_SRC := $(shell find src -name '*.f90' ! -name main.f90 ! -path 'src/parallel/*/*' | sort) \
           $(sort $(wildcard src/parallel/$(VARIANT)/*.f90)) $(BUILD)/fcs_version.f90
LIB_OBJ := $(patsubst %.f90,$(BUILD)/%.o,$(notdir $(LIB_SRC)))
TEST_SRC := $(sort $(wildcard tests/unit/*.f90))
TEST_BIN := $(patsubst tests/unit/%.f90,$(BUILD)/tests/%,$(filter tests/unit/test_%,$(TEST_SRC)))
TEST_SUPPORT := $(patsubst tests/unit/%.f90,$(BUILD)/%.o,$(filter-out tests/unit/test_%,$(TEST_SRC)))
vpath %.f90 $(sort $(dir $(LIB_SRC) $(TEST_SRC))) src

# The version module is regenerated on every make, but rewritten only when the revision changes.
$(BUILD)/fcs_version.f90: FORCE | $(BUILD)
	@sh tools/gen_version.sh $@ "$(VARIANT)$(if $(filter 1,$(DEBUG)),$(comma) debug)"
.PHONY: FORCE
FORCE:

.PHONY: all build run test validate ccx-suite bench bench-compare figures figures-runs doc packages \
        clean help unit-tests
.DEFAULT_GOAL := all
all: build
build: $(BIN)

help:
	@sed -n '2,11p' Makefile | sed 's/^# \{0,1\}//'

packages:
	@sh tools/ensure_packages.sh $(PACKAGES)

$(BUILD)/deps.mk: $(filter-out $(BUILD)/fcs_version.f90,$(LIB_SRC)) $(TEST_SRC) src/main.f90 \
                  tools/gen_deps.sh | $(BUILD)/fcs_version.f90
	@sh tools/gen_deps.sh $(BUILD) $(LIB_SRC) $(TEST_SRC) src/main.f90 > $@

-include $(BUILD)/deps.mk

$(BUILD) $(BUILD)/tests bin:
	@mkdir -p $@

$(BUILD)/%.o: %.f90 | $(BUILD)
	$(FC) $(FFLAGS) -c $< -o $@

# MUMPS's Fortran header dmumps_struc.h (and the dmumps_root.h it includes) lives in /usr/include,
# which gfortran does not search for INCLUDE lines; only the MUMPS wrapper includes it.
$(BUILD)/fcs_mumps.o: private FFLAGS += -I /usr/include

$(BUILD)/libfcs3d.a: $(LIB_OBJ)
	@rm -f $@
	ar rcs $@ $^

$(BIN): $(BUILD)/main.o $(BUILD)/libfcs3d.a
	@mkdir -p $(dir $@)
	$(FC) $(FFLAGS) -o $@ $^ $(LDLIBS)

$(BUILD)/tests/%: $(BUILD)/%.o $(TEST_SUPPORT) $(BUILD)/libfcs3d.a | $(BUILD)/tests
	$(FC) $(FFLAGS) -o $@ $^ $(LDLIBS)

unit-tests: $(TEST_BIN)

test: packages
	@$(MAKE) --no-print-directory build unit-tests
	@$(MAKE) --no-print-directory MPI=1 BUILD=$(MPI_BUILD) build
	@FCS3D=$(abspath $(BIN)) FCS3D_MPI=$(abspath $(MPI_BIN)) \
	  UNIT_DIR=$(abspath $(BUILD)/tests) \
	  PYTHON=$(PYTHON) OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 \
	  sh tests/run_tests.sh

run: packages
	@$(MAKE) --no-print-directory build
	@sh tools/run_default.sh $(abspath $(BIN))

validate: packages
	@sh tools/ensure_packages.sh $(VALIDATE_PACKAGES)
	@$(MAKE) --no-print-directory build
	@status=0; FCS3D=$(abspath $(BIN)) PYTHON=$(PYTHON) sh tests/validate/run_validate.sh || status=1; \
	  echo; echo "== CalculiX's static test decks (make ccx-suite)"; \
	  FCS3D=$(abspath $(BIN)) PYTHON=$(PYTHON) sh tests/validate/calculix_suite.sh; suite=$$?; \
	  [ $$suite -eq 0 ] || [ $$suite -eq 77 ] || status=1; exit $$status

# CCX_SUITE_ARGS: more arguments for tests/validate/calculix_suite.py, e.g. "--only beam8p".
ccx-suite: packages
	@sh tools/ensure_packages.sh $(VALIDATE_PACKAGES)
	@$(MAKE) --no-print-directory build
	@FCS3D=$(abspath $(BIN)) PYTHON=$(PYTHON) sh tests/validate/calculix_suite.sh $(CCX_SUITE_ARGS)

bench: packages
	@$(MAKE) --no-print-directory build
	@$(MAKE) --no-print-directory MPI=1 BUILD=$(MPI_BUILD) build
	@FCS3D=$(abspath $(BIN)) FCS3D_MPI=$(abspath $(MPI_BIN)) PYTHON=$(PYTHON) \
	  OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 sh tests/bench/run_bench.sh

# Two builds side by side (fault-bend run and contact benchmark, alternately; speed and outputs):
# make bench-compare BEFORE=/path/to/other/fcs3d
bench-compare: packages
	@$(MAKE) --no-print-directory build
	@test -n "$(BEFORE)" || { echo "make bench-compare needs BEFORE=/path/to/fcs3d"; exit 2; }
	@PYTHON=$(PYTHON) sh tests/bench/compare_builds.sh $(abspath $(BEFORE)) $(abspath $(BIN))

# make figures: the figures of the default run (run/fault_bend, from make run) into doc/figures/,
# with the flat-fault run of run/fault_bend_flat side by side if it exists, and the zone maps of
# post/fault_bend_zones.py (its report goes to run/fault_bend/zones.md).
# make figures-runs: both runs (make run, then the flat fault), then make figures.
FIGURES_RUN := run/fault_bend
FIGURES_COMPARE := run/fault_bend_flat
figures:
	@$(PYTHON) post/make_figures.py --results $(FIGURES_RUN)/fault_bend.h5 --out doc/figures \
	  $(if $(wildcard $(FIGURES_COMPARE)/fault_bend.h5),--compare-results $(FIGURES_COMPARE)/fault_bend.h5)
	@$(PYTHON) post/fault_bend_zones.py --results $(FIGURES_RUN)/fault_bend.h5 \
	  --figure doc/figures/fault_bend_mises_change.png > $(FIGURES_RUN)/zones.md
	@echo "doc/figures regenerated; the zones report is in $(FIGURES_RUN)/zones.md"

figures-runs:
	@$(MAKE) --no-print-directory run
	@FAULT_BEND_GMSH="-setnumber bend_angle 0" FAULT_BEND_DIR=$(abspath $(FIGURES_COMPARE)) \
	  $(MAKE) --no-print-directory run
	@$(MAKE) --no-print-directory figures

doc: build
	@$(BIN) --list-keywords --markdown > doc/deck_reference.md
	@echo "doc/deck_reference.md regenerated"

clean:
	rm -rf build bin
