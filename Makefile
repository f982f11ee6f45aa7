# asymslip -- the user's entry points.  `make` sets up .venv if needed, regenerates the formulas
# and prints the demo; `make test` runs every test.  Both create the environment on first use.

PYTHON ?= python3
VENV   := .venv
PY     := $(VENV)/bin/python
STAMP  := $(VENV)/.installed-stamp
EXTRAS := derive,dev,plot,bench,dask,special,parquet,fe,docs

.DEFAULT_GOAL := all
.PHONY: all env demo generate check-generated check-wheel verify test lint test-languages toolchains bench \
        figures error-map check-error-map report docs docs-tools test-docs \
        stress-error-map check-stress-error-map nucleation-figure \
        accuracy clean help

all: generate demo ## set up the environment, regenerate the formulas, print the demo

help: ## list the targets
	@grep -E '^[a-z-]+:.*## ' $(MAKEFILE_LIST) | sed 's/:.*## /\t/' | expand -t 20

# Reinstall only when the project metadata changed; the editable install sees code edits.
$(STAMP): pyproject.toml
	@test -x $(PY) || $(PYTHON) -m venv $(VENV)
	$(PY) -m pip install --quiet --disable-pip-version-check -e '.[$(EXTRAS)]'
	@rm -rf asymslip.egg-info  # a build by-product; the install keeps its own metadata
	@touch $(STAMP)

env: $(STAMP) ## create .venv and install asymslip with its extras

generate: $(STAMP) ## run the derivations once; write generated/{asymslip_gen,c,fortran,matlab,report}
	$(PY) -m asymslip.codegen generate

check-generated: $(STAMP) ## regenerate every tree under two hash seeds and diff; check the figures' data
	$(PY) -m asymslip.codegen check
	$(PY) -m asymslip figure fig5 --check generated/figures
	$(PY) -m asymslip figure error-map --check generated/report
	$(PY) -m asymslip.stress.error_map --check --data generated/report

verify: $(STAMP) ## run every derivation, one line per paper equation
	$(PY) -m asymslip.codegen verify

demo: $(STAMP) ## the paper's Fig. 5 example: a1, a2, b and the slip-zone width
	$(PY) -m asymslip slip-zone --law hertz --R 1 --E-star 1 --mu 0.1 --P1 100 --Q1 0 --P2 105 --Q2 1

test: $(STAMP) lint ## the type checker, the formatter and linter, then the test suite (pytest -W error)
	$(PY) -m pytest

lint: $(STAMP) ## mypy over src/ (strict; pyproject.toml), ruff format --check and ruff check
	$(VENV)/bin/mypy
	$(VENV)/bin/ruff format --check src tests derivations docs
	$(VENV)/bin/ruff check src tests derivations docs

figures: $(STAMP) error-map ## write Fig. 5 (generated/figures/fig5.png, .csv) and the error map
	$(PY) -m asymslip figure fig5 --out generated/figures

# The solver over the whole map takes one to two minutes; the report summarises the CSV, so it
# is rewritten too (running every derivation, about 20 s).
error-map: $(STAMP) ## solver vs every estimate: generated/report/error_map.csv, figures/error_map.png
	$(PY) -m asymslip figure error-map --out generated/figures --data generated/report
	$(PY) -m asymslip.codegen report

check-error-map: $(STAMP) ## recompute a few rows of the error map and compare (a few seconds)
	$(PY) -m asymslip figure error-map --check generated/report

# The stress error map runs the solver on 60 cycles (a few minutes); the report summarises it
# (EA-7 of derivations/stress_edge_asymptote.py), so it is rewritten too.
stress-error-map: $(STAMP) ## asymptotic stress vs solver and exact field near the edges (CSV, PNG)
	$(PY) -m asymslip.stress.error_map --data generated/report --out generated/figures
	$(PY) -m asymslip.codegen report

check-stress-error-map: $(STAMP) ## recompute two cycles of the stress error map and compare
	$(PY) -m asymslip.stress.error_map --check --data generated/report

nucleation-figure: $(STAMP) ## the blade-root-like nucleation figure (generated/figures)
	$(PY) -m asymslip.nucleation.blade_root --out generated/figures

report: $(STAMP) ## write generated/report/derivation.md from the derivation records
	$(PY) -m asymslip.codegen report

check-wheel: ## build sdist and wheel, install the wheel with no extras, run the README example
	.ci/check-wheel

toolchains: ## install gfortran, Octave and CalculiX where missing (Debian, as root; quiet, idempotent)
	@.ci/install-toolchains

test-languages: $(STAMP) toolchains ## compile the C and Fortran, run the MATLAB files, compare with NumPy
	ASYMSLIP_REQUIRE_TOOLCHAINS=1 $(PY) -m pytest tests/emit

bench: $(STAMP) ## issue 10's targets vs the strongest baselines (BENCH_ARGS="--quick", "--markdown F")
	$(PY) -m tests.benchmarks.run_benchmarks $(BENCH_ARGS)

# The site is built offline with warnings as errors (nitpicky cross-references; --keep-going
# reports every warning before failing).  The gallery runs docs/examples/*.py; the API pages,
# the derivation pages and the generated-language pages are written from the sources at build
# time (docs/_ext), so new modules, commands and examples appear without editing the docs.
DOCS_OUT := docs/_build/html
docs: $(STAMP) ## build the documentation site into docs/_build/html (offline, warnings as errors)
	@rm -rf $(DOCS_OUT)  # no page of an earlier build survives (the link check reads them all)
	$(PY) -m sphinx -b html -W --keep-going -n -q -d docs/_build/doctrees docs $(DOCS_OUT)
	@echo "docs: open $(DOCS_OUT)/index.html"

docs-tools: ## install Chromium for the documentation's browser test (Debian, as root; idempotent)
	@.ci/install-docs-tools

test-docs: docs docs-tools ## build the site, then its checks: links, offline, API coverage, browser
	ASYMSLIP_REQUIRE_DOCS=1 $(PY) -m pytest tests/docs

accuracy: $(STAMP) ## the long accuracy run against 50-digit mpmath
	$(PY) -m tests.accuracy.harness --samples 2000

clean: ## remove the virtual environment and caches
	rm -rf $(VENV) .pytest_cache .ruff_cache .hypothesis build src/*.egg-info docs/_build \
	    docs/tutorials docs/reference/api docs/theory/derivations
