# rocking-q: the two commands a newcomer needs are `make reproduce` and `make test`.
BUILD   ?= build
OUT     ?= out
JOBS    ?= 2
# Debian packages the project needs (header-only Boost: Odeint, Math, Multiprecision;
# OpenMPI for rocking batch under mpirun: the build works without it, on threads only).
PACKAGES = g++ cmake make libgtest-dev libboost-dev libgsl-dev gnuplot-nox python3-matplotlib python3-mpmath libopenmpi-dev openmpi-bin

.PHONY: all deps build reproduce test bless bench bench-records bench-spectrum bench-fragility bench-overturning-set bench-batch bench-sliding bench-siconos report clean

all: build

# Installs what is missing: apt-get as root, otherwise prints the command.
deps:
	@missing=""; for p in $(PACKAGES); do \
	  dpkg-query -W -f='$${Status}' $$p 2>/dev/null | grep -q "install ok installed" || missing="$$missing $$p"; \
	done; \
	if [ -z "$$missing" ]; then echo "deps: all installed"; \
	elif [ "$$(id -u)" = 0 ]; then echo "deps: installing$$missing"; \
	  apt-get update -qq && DEBIAN_FRONTEND=noninteractive apt-get install -y -qq --no-install-recommends $$missing >/dev/null \
	  || { echo "deps: apt-get failed for$$missing" >&2; exit 1; }; \
	else echo "deps: missing$$missing; run:  sudo apt-get install -y$$missing" >&2; exit 1; fi

# The Python module rocking_q and its tests (issue 30, docs/python.md): pybind11 for
# Debian's /usr/bin/python3, its headers (pybind11-dev does not pull them in), numpy and pytest.
PACKAGES += python3-dev pybind11-dev python3-pybind11 python3-numpy python3-pytest

# pdftotext and pdffonts, with which ctest report_text reads the report as a reader's search does.
PACKAGES += poppler-utils

# Maintained libraries in place of hand-written code (issue 42): SHA-256 from OpenSSL's
# libcrypto, the manifest's RFC 4180 CSV from libcsv, the command line's JSON documents as
# nlohmann::ordered_json values (src/cli/json_text.hpp), the results' combinable checksum
# from xxHash (src/batch/row_digest.hpp).
PACKAGES += libssl-dev libcsv-dev nlohmann-json3-dev libxxhash-dev

# pip install . into a virtual environment (pyproject.toml, setup.py; ctest pip_install).
PACKAGES += python3-venv python3-pip python3-setuptools

# Siconos (nonsmooth mechanics) for /usr/bin/python3: tools/siconos_block.py, the second method
# against which ctest sliding_siconos checks the sliding-rocking engine (issue 41).
PACKAGES += python3-siconos

$(BUILD)/Makefile: CMakeLists.txt | deps
	cmake -S . -B $(BUILD) -DCMAKE_BUILD_TYPE=Release >/dev/null

build: deps $(BUILD)/Makefile
	cmake --build $(BUILD) -j $(JOBS)

# Runs every scene, writes out/<scene>/*.csv and *.png, diffs against expected/.
reproduce: build
	$(BUILD)/reproduce --out $(OUT)

test: build
	cd $(BUILD) && ctest --output-on-failure -j $(JOBS)

# make bless SCENE=fig04: rewrite expected/fig04 from a fresh run, after showing
# what changed; refused when the new values fail the scene's independent check.
bless: build
	@test -n "$(SCENE)" || { echo "usage: make bless SCENE=<scene>" >&2; exit 2; }
	$(BUILD)/reproduce --out $(OUT) --bless $(SCENE)

# The speed-accuracy trade (a benchmark, not a test): out/bench/work_precision.{csv,png}, summary.txt.
bench: build
	cmake --build $(BUILD) --target bench_work_precision -j $(JOBS)
	$(BUILD)/bench_work_precision --out $(OUT)/bench

# The half-periods (record info) against the record's length, 10^4 to 10^6 samples: time,
# peak memory and growth exponent in out/bench/record_size.{csv,_summary.txt} (about a minute).
bench-records: build
	cmake --build $(BUILD) --target bench_record_size -j $(JOBS)
	$(BUILD)/bench_record_size --out $(OUT)/bench

# The rocking spectrum's speed (a benchmark, not a test): out/bench/spectrum.txt, spectrum_records.csv.
bench-spectrum: build
	cmake --build $(BUILD) --target bench_spectrum -j $(JOBS)
	$(BUILD)/bench_spectrum --out $(OUT)/bench

# A fragility study's speed, 20 records x 25 blocks on 1 and 2 threads (a benchmark, not a
# test; about two minutes): out/bench/fragility.txt.
bench-fragility: build
	cmake --build $(BUILD) --target bench_fragility -j $(JOBS)
	$(BUILD)/bench_fragility --out $(OUT)/bench

# The refine IDA's cost against its width w (a benchmark, not a test; a few minutes at
# w = 1e-5): out/bench/overturning_set.txt.
bench-overturning-set: build
	cmake --build $(BUILD) --target bench_overturning_set -j $(JOBS)
	$(BUILD)/bench_overturning_set --out $(OUT)/bench

# The sliding-rocking run's cost against the rocking-only full model (a benchmark, not a
# test; issue 41): out/bench/sliding.txt and sliding_records.csv.
bench-sliding: build
	cmake --build $(BUILD) --target bench_sliding -j $(JOBS)
	$(BUILD)/bench_sliding --out $(OUT)/bench

# The sliding-rocking engine against Siconos at equal accuracy (a benchmark, not a test; issue 41,
# about 2-4 minutes): each one's error against rtol and dt, and the cost of each at the other's
# accuracy, in out/bench/siconos.{txt,csv}. Skips without python3-siconos.
bench-siconos: build
	/usr/bin/python3 bench/siconos_equal_accuracy.py --rocking $(BUILD)/rocking --python $(BUILD)/python --out $(OUT)/bench

# rocking batch's scale (a benchmark, not a test): jobs/s on 1 and 2 threads and 1-3 MPI ranks, the
# coordination's cost, a model of 10^9 simulations: out/bench/batch.{txt,csv} (BATCH_BENCH_JOBS=N, default 10^6).
bench-batch: build
	bench/batch.sh $(BUILD)/rocking $(OUT)/bench

# One PDF for a reviewer: every reproduced figure and table, the paper's claims, the
# comparison, the errata and the findings (matplotlib, Debian's /usr/bin/python3).
report: reproduce-for-report bench
	/usr/bin/python3 tools/report.py $(OUT)

# The report reads the scenes even when some differ (it says so on its first page).
reproduce-for-report: build
	-$(BUILD)/reproduce --out $(OUT)

clean:
	rm -rf $(BUILD) $(OUT)
