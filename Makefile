# Two commands do everything: `make report` and `make test` (README).
# Both build .venv from the pinned versions in requirements.lock when it is missing.
PYTHON ?= python3.11
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed

# Tests draw off-screen (tests/conftest.py sets Agg); notebook kernels use the inline
# backend, whose figure outputs are part of what nbval compares (`make lab`, `make report`).
NB_BACKEND := module://matplotlib_inline.backend_inline
# Imported once by a fork server from which every notebook kernel is forked (tests/kernel_forkserver.py):
# about 1 s of CPU less per notebook. Only modules that do not capture their surroundings at import.
NB_PRELOAD := numpy,sympy,matplotlib,numba,pinocchio
export PYTHONHASHSEED := 0
# Bytecode caches (src/, the venv, and pytest's rewritten test modules) are written and reused:
# an environment that sets PYTHONDONTWRITEBYTECODE would recompile them in every process (every
# xdist worker and notebook kernel), about 1 s each.
unexport PYTHONDONTWRITEBYTECODE

.PHONY: all venv test test-fast test-browser report bench lab lint clean notebooks st-engine st-engine-if-gxx

all: test

venv: $(STAMP)

$(STAMP): requirements.lock pyproject.toml
	@command -v $(PYTHON) >/dev/null || { echo "need $(PYTHON) on PATH (or make PYTHON=/path/to/python3.11)"; exit 2; }
	$(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --upgrade pip==25.2
	$(PY) -m pip install --quiet -r requirements.lock
	$(PY) -m pip install --quiet --no-deps --no-build-isolation -e .
	$(PY) -m ipykernel install --sys-prefix --name python3 --display-name "Python 3 (analysis)" >/dev/null
	@touch $(STAMP)

# The whole suite: the notebooks under nbval, the unit, property and cross-check tests and the
# doctests in one pytest session on two xdist workers, then the report site in a browser.
# One session, not two: the machine's two cores stay busy to the end, and the start-up (workers,
# collection) is paid once. --dist loadscope keeps each notebook's cells in one worker, in
# order (a unit test module is one scope too); --no-loadscope-reorder keeps the order of
# tests/conftest.py: the notebooks first, then the tests marked slow, longest work first.
# Tests draw with Agg; the notebook kernels get the inline backend (--nbval-kernel-env), whose
# figure outputs are part of what nbval compares. A cell may take 300 s (the longest takes about
# 3 s): a hung cell fails, naming itself, instead of holding the run for nbval's default 2000 s.
# tests/nbval_kernel.py starts the notebook kernels over IPC (no TCP port race between the
# xdist workers), forks them from a preloaded server, retries a kernel that dies at start-up
# and keeps each kernel's stderr in build/nbval-kernel-logs/.
# tests/browser builds the site once and checks it in Debian's /usr/bin/chromium (without it
# those tests are skipped, saying why); here from the notebooks' stored outputs and the
# figures that the nbval run just saved in build/figures (ANALYSIS_SITE_EXECUTE=0): nbval has
# re-executed every notebook and compared it with those outputs the line before.
# ANALYSIS_AWLSIM_MEMO (analysis.plc.runner.sweep): a notebook and a test that execute the same
# program on the same targets share one awlsim run; emptied first, so it lasts one `make test`.
AWLSIM_MEMO := $(CURDIR)/build/awlsim-memo

# The IEC 61131-3 ST engine (analysis.plc.st_engine): the ST compiler and VM in pyplcopen's
# pinned source distribution (tools/st-engine/requirements.txt, hash-checked by pip), built once
# with Debian's g++ against tools/st-engine/st_run.cpp into the venv (about a minute). Rebuilt only
# when the pin or the driver changes; the binary reports the key of both (st_run --key). No
# download or compilation at test time. The second binary, analysis-st-machine
# (tools/st-engine/st_machine.cpp), runs a machine program cycle by cycle with simulated axes
# (analysis.plc.st_engine.run_machine, stl-run --dialect st); same sources, same key. The sdist's
# simulated axis is patched after unpacking (ST_PATCH: two upstream defects, velocity steps and
# the overrun-and-return of MC_Halt/MC_Stop, each explained in the patch's header).
ST_ENGINE := $(VENV)/bin/analysis-st-run
ST_MACHINE := $(VENV)/bin/analysis-st-machine
ST_PATCH := tools/st-engine/pyplcopen-0.21.0-motion.patch
ST_SOURCES := tools/st-engine/requirements.txt tools/st-engine/st_run.cpp tools/st-engine/st_machine.cpp \
  $(ST_PATCH)
KIN_ORACLE := $(VENV)/bin/analysis-kin-oracle

st-engine: $(ST_ENGINE) $(KIN_ORACLE)

# make test, make report and make notebooks build the engine where g++ is (CI: .ci/run installs
# it); without g++ the ST engine tests are skipped, saying why (analysis.plc.st_engine), and
# notebook 09, which plays a machine run of the engine, fails naming make st-engine.
st-engine-if-gxx: | $(STAMP)
	@if command -v g++ >/dev/null; then $(MAKE) --no-print-directory st-engine; \
	else echo "make: no g++ on PATH: the IEC 61131-3 ST engine is not built; its tests are skipped and notebook 09's machine run fails, naming make st-engine (Debian: apt-get install g++)"; fi

$(ST_ENGINE): $(ST_SOURCES) | $(STAMP)
	@command -v g++ >/dev/null || { echo "need g++ to build the ST engine (Debian: apt-get install g++)"; exit 2; }
	rm -rf build/st-engine && mkdir -p build/st-engine
	$(PY) -m pip download --quiet --no-deps --no-binary :all: --require-hashes \
	  -r tools/st-engine/requirements.txt -d build/st-engine
	tar -xzf build/st-engine/pyplcopen-0.21.0.tar.gz -C build/st-engine pyplcopen-0.21.0/core pyplcopen-0.21.0/LICENSE
	git apply --directory=build/st-engine -p1 $(ST_PATCH)
	g++ -std=c++17 -O2 -ffp-contract=off -fno-fast-math \
	  -DST_RUN_KEY='"'$$(cat $(ST_SOURCES) | sha256sum | cut -c1-16)'"' \
	  -Ibuild/st-engine/pyplcopen-0.21.0/core tools/st-engine/st_run.cpp -o $@.tmp
	g++ -std=c++17 -O2 -ffp-contract=off -fno-fast-math \
	  -DST_RUN_KEY='"'$$(cat $(ST_SOURCES) | sha256sum | cut -c1-16)'"' \
	  -Ibuild/st-engine/pyplcopen-0.21.0/core tools/st-engine/st_machine.cpp -o $(ST_MACHINE).tmp
	mv $(ST_MACHINE).tmp $(ST_MACHINE)
	mv $@.tmp $@

# pyplcopen's own kinematics (core/kin of the same sdist) as an oracle of the derived closed
# forms (analysis.kinematics.derive.plcopen_oracle): tools/st-engine/kin_oracle.cpp, built beside
# the engine from the sources it unpacked.
$(KIN_ORACLE): tools/st-engine/kin_oracle.cpp $(ST_ENGINE)
	g++ -std=c++17 -O2 -ffp-contract=off -fno-fast-math \
	  -Ibuild/st-engine/pyplcopen-0.21.0/core tools/st-engine/kin_oracle.cpp -o $@.tmp
	mv $@.tmp $@

test: $(STAMP) st-engine-if-gxx
	rm -rf $(AWLSIM_MEMO)
	ANALYSIS_AWLSIM_MEMO=$(AWLSIM_MEMO) MPLBACKEND=Agg $(PY) -m pytest -n 2 --dist loadscope --no-loadscope-reorder \
	  -p tests.nbval_kernel --nbval-kernel-preload $(NB_PRELOAD) --nbval-kernel-env MPLBACKEND=$(NB_BACKEND) \
	  --nbval --nbval-sanitize-with tests/nbval_sanitize.cfg --nbval-cell-timeout 300 notebooks \
	  --doctest-modules tests src --ignore=tests/browser
	ANALYSIS_SITE_EXECUTE=0 MPLBACKEND=Agg $(PY) -m pytest tests/browser

# The developer loop (about 27 s): the unit tests without those marked slow (the awlsim sweeps,
# the subprocess sessions, the site build; tests/conftest.py), stopping at the first failure.
test-fast: $(STAMP) st-engine-if-gxx
	HYPOTHESIS_PROFILE=$${HYPOTHESIS_PROFILE:-fast} MPLBACKEND=Agg $(PY) -m pytest -n 2 --dist worksteal -x -m "not slow" -p no:nbval tests --ignore=tests/browser

# The browser tests against build/report as `make report` left it (no rebuild).
test-browser: $(STAMP)
	ANALYSIS_SITE_DIR=build/report MPLBACKEND=Agg $(PY) -m pytest tests/browser

# Executes every notebook (progress: notebook i/n, seconds; two at a time) and builds the site with
# Sphinx. Cached (analysis/app/report_cache.py, jupyter-cache in build/report-cache): a notebook
# whose code and inputs (src/analysis, data/, the lock) are unchanged is not executed again, and
# when nothing changed since the last build the site is left as it is.
report: $(STAMP) st-engine-if-gxx
	MPLBACKEND=$(NB_BACKEND) $(PY) -m analysis report --out build/report

# The bench extra (numexpr, EAIK and what EAIK needs) is pinned in requirements-bench.lock
# and installed only here: none of it is a runtime dependency.
BENCH_STAMP := $(VENV)/.bench-installed

$(BENCH_STAMP): $(STAMP) requirements-bench.lock
	$(PY) -m pip install --quiet --no-deps -r requirements-bench.lock
	@touch $(BENCH_STAMP)

# benchmarks/report_build.py: make report as a whole process, cold (empty cache), warm (nothing
# changed) and with one notebook changed, into a scratch folder (build/bench-report.json).
# benchmarks/explorer_redraw.py: the explorer's change -> pose on screen in Chromium, the view's
# in-place redraw against Plotly.update in the same browser (build/bench-explorer.json).
# benchmarks/explorer_latency.py: typed value -> pose on screen, JupyterLab's explorer (a real
# server and kernel) and the static page, median and p90, quiet and under one CPU-bound
# process per core started by the bench (build/bench-latency.json; issue 31: Lab within 50 ms).
bench: $(BENCH_STAMP) $(ST_ENGINE)
	$(PY) benchmarks/run.py --out build/bench.json
	$(PY) benchmarks/report_build.py --out build/bench-report.json
	$(PY) benchmarks/explorer_redraw.py --out build/bench-explorer.json
	$(PY) benchmarks/explorer_latency.py --out build/bench-latency.json

# JupyterLab on copies of the notebooks in build/lab/ (analysis/app/lab.py): the stored ones are
# nbval's references, which Lab's autosave would change (the explorer moved, widget state);
# --allow-root when run as root. LAB_ARGS: more options (e.g. LAB_ARGS=--no-browser).
lab: $(STAMP)
	MPLBACKEND=$(NB_BACKEND) $(PY) -m analysis.app.lab $(LAB_ARGS)

# Re-executes notebooks in place (all, or NB="notebooks/03_table4.ipynb ...") and stores their
# outputs, the reference nbval compares against: commit them with the change that moved them.
notebooks: $(STAMP) st-engine-if-gxx
	MPLBACKEND=$(NB_BACKEND) $(PY) tests/refresh_notebooks.py $(NB)

lint: $(STAMP)
	$(VENV)/bin/ruff check src tests benchmarks

clean:
	rm -rf build .pytest_cache .hypothesis
